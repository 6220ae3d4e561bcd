#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Parallel mixing evaluation (issue 20): cost of compute tdem/mixing/velocity and fix
tdem/mixing/depth per evaluation at 1 and 2 ranks on a bed of N particles, and memory per rank.

The bed: N = nx ny nz spheres (d = 10 mm, density 2500) on a jittered simple cubic lattice in a box
1.0 x 0.2 x 0.6 m (periodic x, y) for N = 10^5, ids shuffled, random velocities of fixed seed, as a
data file that both engines read. No forces (pair_style none, nothing moves): the runs time the
evaluation alone. Velocity: r_v = 25 mm (about 65 neighbours), 10 bins along x, periodic x y,
evaluated at every step by thermo output. Depth: column 25 mm, 10 bins, floor 0, a snapshot every
step. A baseline run without either gives the time of the steps themselves, subtracted.

Reported per engine and style:
- time per evaluation at 1 and 2 ranks (runs interleaved 1, 2, 2, 1 per round; the spread of a
  configuration's own runs is the A/A control) and the speedup;
- the machine's own capacity for two processes: two independent 1-rank runs of the velocity scene
  at the same time against one alone (this VM gives less than 2x for memory-heavy loops);
- instructions per rank of one evaluation (valgrind callgrind, LAMMPS 2022 build), 1 against 2
  ranks: the division of the work itself, free of the machine's noise;
- rows each rank holds (owned atoms + halo incl. periodic images, TDEM_MIXING_REPORT) and the
  peak resident memory per rank with the evaluation and without it (/usr/bin/time).

usage: bench/mixing_scaling.py [--build build] [--n 100000] [--evals 10] [--rounds 2] [--no-callgrind]
                               [--out bench/results/mixing_scaling.md]
"""
import argparse
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
T0 = time.time()
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", TDEM_MIXING_REPORT="1")


def say(msg, k=None, n=None, t_start=None):
    """A progress line; with k runs of n done since t_start also the estimated remaining time."""
    rem = ""
    if k and n and t_start is not None:
        rem = ", about %.0f s to go for this engine" % ((time.time() - t_start) / k * (n - k))
    print("[%5.0f s] %s%s" % (time.time() - T0, msg, rem), flush=True)


def bed(path, n):
    """Jittered lattice, nx : ny : nz = 5 : 1 : 2.5 (10^5 = 100 x 20 x 50), spacing 10 mm."""
    s = (n / 2.5 / 5.0) ** (1.0 / 3.0)
    nx, ny = int(round(5 * s)), int(round(s))
    nz = int(round(n / (nx * ny)))
    rng = np.random.default_rng(20261205)
    i, j, k = np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij")
    x = np.column_stack([i.ravel() + 0.5, j.ravel() + 0.5, k.ravel() + 0.5]) * 0.01
    x += rng.uniform(-0.001, 0.001, x.shape)
    ids = rng.permutation(len(x)) + 1
    v = np.column_stack([0.1 + 0.05 * rng.standard_normal(len(x)), 0.05 * rng.standard_normal(len(x)),
                         0.02 * rng.standard_normal(len(x))])
    box = (0.01 * nx, 0.01 * ny, 0.01 * nz * 1.2)
    with open(path, "w") as f:
        f.write("mixing bed\n\n%d atoms\n1 atom types\n\n0 %g xlo xhi\n0 %g ylo yhi\n0 %g zlo zhi\n\nAtoms\n\n"
                % (len(x), *box))
        for q in range(len(x)):
            f.write("%d 1 0.01 2500 %.9g %.9g %.9g\n" % (ids[q], *x[q]))
        f.write("\nVelocities\n\n")
        for q in range(len(x)):
            f.write("%d %.9g %.9g %.9g 0 0 0\n" % (ids[q], *v[q]))
    return len(x), box


STYLE = {
    "velocity": "compute m all tdem/mixing/velocity radius 0.025 bins x 0 {L} 10 periodic x y\n"
                "thermo_style custom step c_m\nthermo 1\n",
    "depth": "fix d all tdem/mixing/depth every 1 column 0.025 bins x 0 {L} 10 floor 0\n"
             "thermo_style custom step f_d\nthermo 1\n",
    "base": "thermo_style custom step\nthermo 1\n",
}


def scene(engine, style, box, evals):
    head = "units si\natom_style %s\nboundary p p f\natom_modify map array\n" % (
        "sphere" if engine == "lammps" else "granular")
    if engine == "liggghts":
        head += "atom_modify sort 0 0.0\ncommunicate single vel yes\n"
    return (head + "read_data bed.data\npair_style none\n" + STYLE[style].format(L=box[0])
            + "run %d\n" % evals)


def run(exe, wd, name, text, np_, wrap=()):
    with open(os.path.join(wd, name), "w") as f:
        f.write(text)
    cmd = list(wrap) + [exe, "-in", name, "-log", "log." + name, "-echo", "none"]
    if np_ > 1 or wrap:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    r = subprocess.run(cmd, cwd=wd, env=ENV, capture_output=True, text=True, errors="replace")
    log = open(os.path.join(wd, "log." + name), errors="replace").read()
    if r.returncode != 0:
        sys.stderr.write(log[-3000:] + r.stdout[-2000:] + r.stderr[-2000:])
        raise SystemExit("mixing_scaling.py: %s failed" % name)
    return log, r.stdout + r.stderr


def loop_time(log):
    return float(re.findall(r"Loop time of ([0-9.eE+-]+) on", log)[-1])


def held(out):
    rows = [tuple(int(w) for w in re.findall(r"owned (\d+) halo (\d+) group (\d+)", l)[0])
            for l in out.splitlines() if l.startswith("tdem mixing report:")]
    return rows


def maxrss(out):
    got = [int(x) / 1024.0 for x in re.findall(r"tdem-maxrss (\d+)", out)]  # MB per rank
    return got or [float("nan")]


def timing(exe, engine, wd, box, evals, rounds):
    res = {}
    t_phase, k, n = time.time(), 0, 3 * rounds * 4
    for style in ("base", "velocity", "depth"):
        for r in range(rounds):
            for np_ in (1, 2, 2, 1):
                say("%s %s on %d rank(s), round %d (run %d of %d)" % (engine, style, np_, r + 1, k + 1, n), k, n, t_phase)
                k += 1
                log, out = run(exe, wd, "in.%s%d" % (style, np_), scene(engine, style, box, evals), np_,
                               wrap=("/usr/bin/time", "-f", "tdem-maxrss %M"))
                res.setdefault((style, np_), []).append((loop_time(log), held(out), maxrss(out)))
    # the machine: two independent 1-rank runs of the velocity scene at once
    say("%s: two 1-rank velocity runs at the same time (machine capacity)" % engine)
    text = scene(engine, "velocity", box, evals)
    for k in (0, 1):
        with open(os.path.join(wd, "in.pair%d" % k), "w") as f:
            f.write(text)
    ps = [subprocess.Popen([exe, "-in", "in.pair%d" % k, "-log", "log.pair%d" % k, "-echo", "none"], cwd=wd, env=ENV,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for k in (0, 1)]
    for p in ps:
        p.wait()
    together = [loop_time(open(os.path.join(wd, "log.pair%d" % k)).read()) for k in (0, 1)]
    return res, together


def callgrind(exe, wd, box):
    """Instructions of one velocity evaluation and one depth snapshot per rank, at 1 and 2 ranks."""
    out = {}
    text = scene("lammps", "velocity", box, 0).replace("run 0\n", "") + STYLE["depth"].format(L=box[0]) + \
        "thermo_style custom step c_m f_d\nrun 0\n"
    for np_ in (1, 2):
        for fn, key in (("LAMMPS_NS::ComputeTDEMMixingVelocity::evaluate()", "velocity"),
                        ("LAMMPS_NS::FixTDEMMixingDepth::take_snapshot()", "depth")):
            say("callgrind: %s on %d rank(s)" % (key, np_))
            pre = os.path.join(wd, "cg.%s.%d" % (key, np_))
            run(exe, wd, "in.cg", text, np_, wrap=("valgrind", "--tool=callgrind", "--toggle-collect=" + fn,
                                                    "--callgrind-out-file=" + pre + ".%p"))
            irs = []
            for f in sorted(os.listdir(wd)):
                if f.startswith(os.path.basename(pre) + "."):
                    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", os.path.join(wd, f)],
                                         capture_output=True, text=True, errors="replace").stdout
                    num = lambda t: int(t.replace(",", ""))
                    total = num(re.search(r"^\s*([\d,]+) .*PROGRAM TOTALS", ann, re.M).group(1))
                    # time spent inside MPI calls (a rank that arrives first at a collective spins there)
                    mpi = sum(num(m.group(1)) for m in re.finditer(r"^\s*([\d,]+) \(.*\)\s+\?\?\?:PMPI_\w+", ann, re.M))
                    irs.append((total, total - mpi))
                    os.remove(os.path.join(wd, f))
            out[(key, np_)] = irs
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--n", type=int, default=100000)
    ap.add_argument("--evals", type=int, default=10)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--no-callgrind", action="store_true")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "mixing_scaling.md"))
    a = ap.parse_args()
    exes = {"lammps": os.path.join(a.build, "bin", "tdem-lammps"),
            "liggghts": os.path.join(a.build, "bin", "tdem-liggghts")}
    wd = tempfile.mkdtemp(prefix="tdem_mixbench_")
    n, box = bed(os.path.join(wd, "bed.data"), a.n)
    say("bed of %d particles in %s (%s)" % (n, box, wd))
    L = ["# Parallel mixing evaluation: 1 and 2 ranks on a bed of %d particles" % n, "",
         "`bench/mixing_scaling.py --n %d --evals %d --rounds %d`, %s, %s; load before: %s." % (
             a.n, a.evals, a.rounds, time.strftime("%Y-%m-%d"), platform.node() or "this machine",
             open("/proc/loadavg").read().split()[0]), "",
         "Time per evaluation = (loop time of the scene - loop time of the baseline scene) / evaluations;",
         "A/A = slowest / fastest run of the same configuration. Rows held = owned atoms + halo rows",
         "(other ranks' atoms and periodic images) in the last evaluation, largest rank. Peak RSS: the",
         "largest rank, with the evaluation minus without it (baseline run).", ""]
    for engine in ("lammps", "liggghts"):
        res, together = timing(exes[engine], engine, wd, box, a.evals, a.rounds)
        base = {p: np.mean([t for t, _, _ in res[("base", p)]]) for p in (1, 2)}
        rss0 = {p: np.nanmax([max(r) for _, _, r in res[("base", p)]]) for p in (1, 2)}
        L += ["## %s" % ("LAMMPS (Debian 12, 20220106)" if engine == "lammps" else "LIGGGHTS 3.8"), "",
              "| style | ranks | time / evaluation [s] | per atom and rank [us] | A/A | speedup 1 -> 2 | "
              "rows held (largest rank) | peak RSS added [MB] |", "|---|---|---|---|---|---|---|---|"]
        for style in ("velocity", "depth"):
            per = {}
            for p in (1, 2):
                ts = [(t - base[p]) / a.evals for t, _, _ in res[(style, p)]]
                per[p] = np.mean(ts)
                h = res[(style, p)][-1][1]
                most = max(o + m for o, m, g in h[-p:]) if h else -1
                rss = np.nanmax([max(r) for _, _, r in res[(style, p)]]) - rss0[p]
                L.append("| %s | %d | %.4f | %.2f | %.2f | %s | %d of %d | %.1f |" % (
                    style, p, per[p], per[p] * p / n * 1e6, max(ts) / min(ts),
                    "%.2f" % (per[1] / per[2]) if p == 2 else "", most, n, rss))
        alone = np.mean([t for t, _, _ in res[("velocity", 1)]])
        L += ["", "Machine: two independent 1-rank velocity runs at the same time took %.2f and %.2f s against "
              "%.2f s alone (mean): two such processes at once get %.2fx the throughput of one." % (
                  together[0], together[1], alone, 4 * alone / (together[0] + together[1])), ""]
        print("\n".join(L[-12:]), flush=True)
    if not a.no_callgrind:
        cg = callgrind(exes["lammps"], wd, box)
        L += ["## Instructions per rank (callgrind, LAMMPS, one evaluation)", "",
              "Outside MPI calls (in them a rank that arrives first at a collective spins and counts",
              "instructions; the totals with them in brackets).", "",
              "| style | 1 rank | 2 ranks (each) | largest rank / 1 rank |", "|---|---|---|---|"]
        for style in ("velocity", "depth"):
            one, two = cg[(style, 1)], cg[(style, 2)]
            L.append("| %s | %.3g (%.3g) | %s | %.3f |" % (
                style, one[0][1], one[0][0], " / ".join("%.3g (%.3g)" % (w, t) for t, w in two),
                max(w for _, w in two) / one[0][1]))
        L.append("")
    with open(a.out, "w") as f:
        f.write("\n".join(L) + "\n")
    say("wrote %s" % a.out)


if __name__ == "__main__":
    main()
