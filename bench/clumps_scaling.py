#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Local clump bodies (issue 20): fix tdem/clump against the stock body fixes at 1 and 2 ranks.

LAMMPS: N tetra clumps (4 spheres r = 2 mm at the corners of a tetrahedron of edge 3 mm, density
2500) are inserted by fix tdem/clump into a box whose edges grow with N^(1/3) (0.06 x 0.06 x 0.15 m
for 1000; periodic x, y), settle for SETTLE steps on 2 ranks and are written with write_data. Every
timed run reads that file (the same clumps) with the same interactions (pair tdem/gran + fix
tdem/wall/gran: Hertz E = 5e6, Tsuji e = 0.6, Cundall-Strack mu = 0.5, gravity, dt = 1e-5 s) and
integrates the bodies with `fix tdem/clump ... bodies molecule` or the stock `fix rigid/small
molecule`; 100 untimed + STEPS timed steps.
LIGGGHTS: the same shapes and box, stock hertz + history; fix tdem/clump (insert) against the
stock fix multisphere (particletemplate/multisphere + insert/pack): each inserts its own clumps, so
the scenes agree statistically; SETTLE steps, then STEPS timed steps in the same process.

LAMMPS runs are interleaved over the fixes and the rank counts (per round: tdem and stock at 1 rank,
both at 2 ranks, both at 2 ranks, both at 1 rank, in mirrored order; --rounds rounds), LIGGGHTS runs
per rank count (tdem, stock, stock, tdem, repeated --rounds times): the runs of each fix are reported
separately, the ratio of a fix's slowest to fastest run is the A/A control
(how much the machine's noise alone moves a result), and ratio and speedup use the means; the median
over the rounds of each round's ratio and speedup (from runs close in time) is given as well. Reported from LAMMPS's and LIGGGHTS's own output:
loop time, the time per section (Pair, Neigh, Comm, Modify, Other), memory per rank; the memory
per body is the difference of the per-rank memory with the body fix and with fix nve/sphere on the
same spheres, divided by the bodies per rank (LAMMPS).
With --big N (default 0: off): N clumps inserted and run for 100 steps with fix tdem/clump on 2
ranks in LAMMPS: time per step and memory per rank.

usage: bench/clumps_scaling.py [--build build] [--n 10000] [--settle 20000] [--steps 2000]
                               [--lig-settle 4000] [--big 0] [--out bench/results/clumps_scaling.md]
"""
import argparse
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
T0 = time.time()


def say(msg, k=None, n=None, t_start=None):
    """A progress line; with k runs of n done since t_start also the estimated remaining time."""
    rem = ""
    if k and n and t_start is not None:
        rem = ", about %.0f s to go in this phase" % ((time.time() - t_start) / k * (n - k))
    print("[%5.0f s] %s%s" % (time.time() - T0, msg, rem), flush=True)


def run(cmd, cwd, name, text, np_=1):
    with open(os.path.join(cwd, name), "w") as f:
        f.write(text)
    # LIGGGHTS's insert/pack writes to the screen (crashes with -screen none): its output is discarded
    full = cmd + ["-in", name, "-log", "log." + name, "-echo", "none"]
    if "liggghts" not in cmd[0]:
        full += ["-screen", "none"]
    if np_ > 1:
        full = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + full
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    r = subprocess.run(full, cwd=cwd, env=env, capture_output=True, text=True, errors="replace")
    log = open(os.path.join(cwd, "log." + name), errors="replace").read()
    if r.returncode != 0:
        sys.stderr.write(log[-3000:] + r.stdout[-2000:] + r.stderr[-2000:])
        raise SystemExit("clumps_scaling.py: %s failed" % name)
    return log


def last_run(log):
    """Loop time, sections (s), memory per rank (MB, avg) and atoms of the last run in a log."""
    loops = list(re.finditer(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", log))
    m = loops[-1]
    tail = log[m.end():]
    sec = {}
    for name in ("Pair", "Neigh", "Comm", "Modify", "Other"):
        s = re.search(r"^%s\s*\|([^\n]*)" % name, tail, re.M)  # LAMMPS: min | avg | max | ...
        if s:
            sec[name] = float([x.strip() for x in s.group(1).split("|")][1])
        s = re.search(r"^%s\s+time \(%%\) = ([0-9.eE+-]+)" % name, tail, re.M)  # LIGGGHTS (Modify is in Other)
        if s:
            sec[name] = float(s.group(1))
    mems = re.findall(r"Per MPI rank memory allocation \(min/avg/max\) = ([0-9.eE+-]+) \| ([0-9.eE+-]+)", log[:m.start()])
    mems = [x[1] for x in mems] or re.findall(r"Memory usage per processor = ([0-9.eE+-]+) Mbytes", log[:m.start()])
    mem = float(mems[-1]) if mems else float("nan")
    return {"loop": float(m.group(1)), "np": int(m.group(2)), "steps": int(m.group(3)), "atoms": int(m.group(4)),
            "sec": sec, "mem": mem}


def box(n):
    s = (n / 1000.0) ** (1.0 / 3.0)
    return 0.06 * s, 0.15 * s


LAW = "normal hertz 5e6 0.3 damping tsuji 0.6 tangential cundall_strack 0.8 0.5 limit_force yes"


def lmp_head(n):
    L, H = box(n)
    return """units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
atom_modify map array
processors * * 1
region box block 0 {L} 0 {L} 0 {H} units box
create_box 1 box
fix pm all property/atom mol ghost yes
""".format(L=L, H=H)


def lmp_inter():
    return """neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * {law}
fix floor all tdem/wall/gran {law} zplane 0 NULL
fix g all gravity 9.81 vector 0 0 -1
timestep 1e-5
""".format(law=LAW)


def lammps(exe, wd, n, settle, steps, rounds):
    L, H = box(n)
    text = (lmp_head(n) + "region ins block 0 {L} 0 {L} 0.005 {h} units box\n"
            "fix c all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 insert {n} region ins "
            "seed 20261205 vel 0 0 -0.5\n".format(L=L, h=H - 0.005, n=n)
            + lmp_inter() + "thermo 1000\nrun {s}\nwrite_data settle.data nocoeff\n".format(s=settle))
    say("LAMMPS: inserting %d clumps and settling them for %d steps on 2 ranks" % (n, settle))
    run([exe], wd, "in.settle", text, 2)
    fixes = {"tdem": "fix c all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 bodies molecule\n",
             "stock": "fix c all rigid/small molecule\n",
             "none": "fix c all nve/sphere\n"}
    res = {}
    # one round: tdem and stock at 1 and 2 ranks in the order A1 B1 A2 B2 B2 A2 B1 A1, so that a slow
    # phase of the machine touches both fixes and both rank counts of the round alike
    order = [("tdem", 1), ("stock", 1), ("tdem", 2), ("stock", 2), ("stock", 2), ("tdem", 2), ("stock", 1), ("tdem", 1)]
    t_phase = time.time()
    for k, (what, np_) in enumerate(order * rounds + [("none", 1), ("none", 2)]):
        text = (lmp_head(n) + "read_data settle.data add append fix pm NULL Molecules\n" + fixes[what]
                + lmp_inter() + "thermo_style custom step atoms\nthermo {s}\nrun 100\nrun {s}\n".format(s=steps))
        say("LAMMPS: %s on %d rank(s), %d steps (run %d of %d)" % (what, np_, steps, k + 1, 8 * rounds + 2),
            k, 8 * rounds + 2, t_phase)
        res.setdefault((what, np_), []).append(last_run(run([exe], wd, "in.%s%d_%d" % (what, np_, k), text, np_)))
    return res


def liggghts(exe, wd, n, settle, steps, rounds):
    L, H = box(n)
    a = 0.003 / 8 ** 0.5
    head = """atom_style {style}
atom_modify map array
boundary p p f
newton off
communicate single vel yes
units si
processors * * 1
region reg block 0 {L} 0 {L} 0 {H} units box
create_box 1 reg
neighbor 0.001 bin
fix m1 all property/global youngsModulus peratomtype 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.6
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix zwall all wall/gran model hertz tangential history primitive type 1 zplane 0.0
region ins block {lo} {Li} {lo} {Li} 0.005 {Hi} units box
"""
    tdem = (head.format(style="hybrid sphere molecular", L=L, H=H, lo=0.0, Li=L, Hi=H - 0.005)
            + "neigh_modify delay 0 exclude molecule all\n"
            "fix c all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 insert %d region ins "
            "seed 20261205 vel 0 0 -0.5\n" % n)
    stock = (head.format(style="granular", L=L, H=H, lo=0.002, Li=L - 0.002, Hi=H - 0.005) + "neigh_modify delay 0\n"
             "fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 4 "
             "ntry 1000000 spheres {a} {a} {a} 0.002 {a} -{a} -{a} 0.002 -{a} {a} -{a} 0.002 -{a} -{a} {a} 0.002 "
             "type 1\nfix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0\n"
             "fix ins all insert/pack seed 32452867 distributiontemplate pdd1 vel constant 0. 0. -0.5 "
             "insert_every once overlapcheck yes all_in yes particles_in_region {n} region ins\n"
             "fix ms all multisphere\n".format(a=a, n=n))
    tail = "thermo 1000\nrun {s}\nrun {t}\n".format(s=settle, t=steps)
    res = {}
    t_phase = time.time()
    for np_ in (1, 2):
        for k, what in enumerate(("tdem", "stock", "stock", "tdem") * rounds):
            done = (np_ - 1) * 4 * rounds + k
            say("LIGGGHTS: %s on %d rank(s), %d + %d steps (run %d of %d)" % (what, np_, settle, steps, done + 1, 8 * rounds),
                done, 8 * rounds, t_phase)
            grid = "" if np_ == 1 else "processors 2 1 1\n"
            text = (tdem if what == "tdem" else stock).replace("processors * * 1\n", grid or "processors * * 1\n") + tail
            res.setdefault((what, np_), []).append(last_run(run([exe], wd, "in.l%s%d_%d" % (what, np_, k), text, np_)))
    return res


def big(exe, wd, n):
    L, H = box(n)
    text = (lmp_head(n) + "region ins block 0 {L} 0 {L} 0.005 {h} units box\n"
            "fix c all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 insert {n} region ins "
            "seed 20261205 vel 0 0 -0.5\n".format(L=L, h=H - 0.005, n=n)
            + lmp_inter() + "thermo 50\nrun 100\n")
    say("LAMMPS: %d clumps (%d spheres) inserted and run for 100 steps on 2 ranks" % (n, 4 * n))
    t = time.time()
    r = last_run(run([exe], wd, "in.big", text, 2))
    r["wall"] = time.time() - t
    rss = None
    return r


def table(res, title, stock_name):
    rows = ["| ranks | fix | loop time per run (s) | A/A (slowest / fastest) | Pair | Neigh | Comm | Modify | Other | "
            "memory per rank (MB) | tdem/stock speed |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    mean = {}
    for (what, np_), runs in sorted(res.items(), key=lambda kv: (kv[0][1], kv[0][0])):
        if what == "none":
            continue
        loops = [r["loop"] for r in runs]
        mean[(what, np_)] = sum(loops) / len(loops)
        sec = {k: sum(r["sec"].get(k, 0.0) for r in runs) / len(runs) for k in ("Pair", "Neigh", "Comm", "Modify", "Other")}
        ratio = ""
        if what == "tdem" and ("stock", np_) in res:
            st = sum(r["loop"] for r in res[("stock", np_)]) / len(res[("stock", np_)])
            ratio = "**%.3f**" % (st / mean[(what, np_)])
        rows.append("| %d | %s | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f | %s |" % (
            np_, "`tdem/clump`" if what == "tdem" else stock_name, " / ".join("%.3f" % x for x in loops),
            max(loops) / min(loops), sec["Pair"], sec["Neigh"], sec["Comm"], sec["Modify"], sec["Other"],
            runs[0]["mem"], ratio))
    speed, fastest, paired = [], [], []
    for what in ("tdem", "stock"):
        if (what, 1) in mean and (what, 2) in mean:
            name = "tdem/clump" if what == "tdem" else stock_name.strip("`")
            speed.append("%s %.2f" % (name, mean[(what, 1)] / mean[(what, 2)]))
            best = [min(r["loop"] for r in res[(what, np_)]) for np_ in (1, 2)]
            fastest.append("%s %.2f" % (name, best[0] / best[1]))
    # ABBA blocks (tdem, stock, stock, tdem): the runs of a block are close in time, so a slow phase of
    # the machine touches both fixes; the median over the blocks of stock / tdem
    for np_ in (1, 2):
        t, st = res.get(("tdem", np_), []), res.get(("stock", np_), [])
        blocks = sorted((st[2 * j]["loop"] + st[2 * j + 1]["loop"]) / (t[2 * j]["loop"] + t[2 * j + 1]["loop"])
                        for j in range(min(len(t), len(st)) // 2))
        if blocks:
            med = blocks[len(blocks) // 2] if len(blocks) % 2 else 0.5 * (blocks[len(blocks) // 2 - 1] +
                                                                          blocks[len(blocks) // 2])
            paired.append("%d rank%s: median **%.3f** (blocks %s)" % (np_, "s" if np_ > 1 else "", med,
                                                                        " / ".join("%.3f" % b for b in blocks)))
            best_ratio = min(r["loop"] for r in st) / min(r["loop"] for r in t)
            paired[-1] += ", fastest runs %.3f" % best_ratio
    # speedup per round (its two runs at 1 rank / its two at 2 ranks; rounds interleave the rank counts
    # only where they are run in one order: LAMMPS)
    per_round = []
    for what in ("tdem", "stock"):
        a, b = res.get((what, 1), []), res.get((what, 2), [])
        sp = sorted((a[2 * j]["loop"] + a[2 * j + 1]["loop"]) / (b[2 * j]["loop"] + b[2 * j + 1]["loop"])
                    for j in range(min(len(a), len(b)) // 2))
        if sp:
            med = sp[len(sp) // 2] if len(sp) % 2 else 0.5 * (sp[len(sp) // 2 - 1] + sp[len(sp) // 2])
            per_round.append("%s median **%.2f** (%s)" % ("tdem/clump" if what == "tdem" else stock_name.strip("`"),
                                                          med, " / ".join("%.2f" % x for x in sp)))
    return ["## " + title, ""] + rows + [
        "", "Speedup 1 -> 2 ranks (loop time ratio of the means): " + ", ".join(speed) +
        "; of the fastest runs: " + ", ".join(fastest) + "; per round: " + "; ".join(per_round), "",
        "tdem/stock speed per ABBA block (stock / tdem loop time of the block's two runs each): " + "; ".join(paired),
        ""]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--n", type=int, default=10000)
    ap.add_argument("--settle", type=int, default=20000)
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--lig-settle", type=int, default=4000)
    ap.add_argument("--lig-steps", type=int, default=1000)
    ap.add_argument("--rounds", type=int, default=2, help="ABBA blocks per rank count")
    ap.add_argument("--big", type=int, default=0)
    ap.add_argument("--skip", default="", help="comma list of parts to skip: lammps, liggghts")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "clumps_scaling.md"))
    a = ap.parse_args()
    bindir = os.path.join(os.path.abspath(a.build), "bin")
    wd = tempfile.mkdtemp(prefix="tdem_clumps_scaling_")
    load0 = open("/proc/loadavg").read().split()[:3]
    out = ["# Clumps at 1 and 2 ranks: fix tdem/clump (local bodies) against the stock body fixes", "",
           "Generated by `bench/clumps_scaling.py` on %s, %s, %d cores, load average %s before." % (
               time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), platform.processor() or platform.machine(),
               os.cpu_count(), " ".join(load0)), ""]
    L, H = box(a.n)
    skip = a.skip.split(",")
    if "lammps" not in skip:
        res = lammps(os.path.join(bindir, "tdem-lammps"), wd, a.n, a.settle, a.steps, a.rounds)
        out += table(res, "LAMMPS: %d tetra clumps (%d spheres), box %.3f x %.3f x %.3f m, settled %d steps, %d timed "
                     "steps, stock = fix rigid/small" % (a.n, 4 * a.n, L, L, H, a.settle, a.steps), "`rigid/small`")
        for np_ in (1, 2):
            m_t = res[("tdem", np_)][0]["mem"]
            m_s = res[("stock", np_)][0]["mem"]
            m_0 = res[("none", np_)][0]["mem"]
            per_rank_bodies = a.n / np_
            out.append("Memory per body (%d rank%s; per-rank memory with the body fix minus with nve/sphere, / bodies "
                       "per rank): tdem/clump %.0f bytes, rigid/small %.0f bytes (per rank: %.1f / %.1f / %.1f MB "
                       "with tdem/clump / rigid/small / nve/sphere)." % (
                           np_, "s" if np_ > 1 else "", (m_t - m_0) * 1048576 / per_rank_bodies,
                           (m_s - m_0) * 1048576 / per_rank_bodies, m_t, m_s, m_0))
        out.append("")
    if "liggghts" not in skip:
        res = liggghts(os.path.join(bindir, "tdem-liggghts"), wd, a.n, a.lig_settle, a.lig_steps, a.rounds)
        out += table(res, "LIGGGHTS: %d tetra clumps, same box, %d settling + %d timed steps in one process, "
                     "stock = fix multisphere (its own insertion: the same scene statistically)"
                     % (a.n, a.lig_settle, a.lig_steps), "`multisphere`")
    if a.big:
        r = big(os.path.join(bindir, "tdem-lammps"), wd, a.big)
        out += ["## %d clumps on 2 ranks (LAMMPS, fix tdem/clump)" % a.big, "",
                "%d spheres; 100 steps: loop time %.2f s (%.1f ms per step); memory per rank %.1f MB (LAMMPS's "
                "accounting); whole process including insertion %.0f s." % (
                    4 * a.big, r["loop"], 1e3 * r["loop"] / 100, r["mem"], r["wall"]), ""]
    load1 = open("/proc/loadavg").read().split()[:3]
    out.append("Load average after: %s. Work directory: %s." % (" ".join(load1), wd))
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    main()
