#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""tdem performance benchmark (issue 9): tdem's styles side by side with the stock styles of the
same physics, in LAMMPS and LIGGGHTS, on 1 and 2 MPI ranks, written as one Markdown table.

Scenes
  (a) chute  the LAMMPS benchmark bench/in.chute (32000 spheres of diameter 1 and density 1, frozen
             rough base, 26 degree chute, lj units, dt = 1e-4), data.chute from the Debian LAMMPS
             source package (fetched by tools/setup.sh). Linear law:
               LAMMPS    gran/hooke/history 2e5 NULL 50 NULL 0.5 0
                         vs pair tdem/gran normal lsd stiffness 2e5 50 tangential cundall_strack 2/7 kn 0 0.5
               LIGGGHTS  model hooke/stiffness tangential history (kn 2e5, kt 2/7 kn, gamman 50,
                         gammat 0, mu 0.5) vs model tdem/lsd tangential tdem/cundall_strack (same
                         properties)
  (b) bed    a dense settled bed of N spheres (default 100000; diameter 1, density 1, lj units,
             periodic in x and y on a frozen base layer, gravity 1): an fcc packing with 3 % gaps
             and random 1 % displacements, settled under gravity once with the stock Hertz style in LAMMPS (cached in
             BUILD/bench_cache/bed<N>.data; both engines read the same file). Hertz law:
               LAMMPS    gran/hertz/history 2e5 NULL 50 NULL 0.5 0 vs pair tdem/gran normal hertz
                         3e5 0 damping kuwabara_kono G (the same physics for mobile pairs, see
                         bench/lammps/bench_laws.sh) tangential cundall_strack 0.8 0.5
               LIGGGHTS  model hertz tangential history vs model tdem/hertz damping tsuji
                         tangential tdem/cundall_strack (E 3e5, nu 0.3, e 0.7, mu 0.5)
  (c) every scene on 1 and 2 ranks (mpirun -np 2): strong scaling (the bed with `processors * * 1`).
Each case runs WARM untimed steps and STEPS timed steps (`run STEPS pre no`) in its own process.
Method (robust against the load of a shared machine; bench/perf_method.md):
  * three arms per case: S = stock, T = tdem, C = the stock command again (the A/A control; off with
    --no-control);
  * REPEATS rounds; a round runs the arms in a palindromic order, S T C C T S, T C S S C T, C S T T S C
    in turn, so every arm has the same mean position in the round (a linear drift of the machine
    cancels) and every arm takes each pair of places once in three rounds;
  * per run two times of the timed loop: the wall clock (LAMMPS/LIGGGHTS "Loop time") and the CPU
    time of the engine process (rank 0: its on-CPU nanoseconds from /proc/PID/schedstat, read by a
    `shell` command just before and just after the timed run), which does not count the time the
    process waits for a core taken by another job;
  * per round the ratio tdem/stock = (t_S1 + t_S2) / (t_T1 + t_T2) (speed ratio, > 1: tdem faster) and
    the control stock/stock = (t_S1 + t_S2) / (t_C1 + t_C2); the table gives the median over the
    rounds, min-max and the interquartile range, and the pooled ratio (sum over all rounds); the
    control is the noise floor: a tdem/stock difference inside the control's spread is not resolved;
  * particle-steps per second: median over the runs of an arm; the 2-rank speedup from those medians.
  * --concurrent (1 rank only): instead, a round runs stock and tdem at the same time, one process on
    each core, then stock and control (the launch order alternating): the two runs of a pair see the
    same load during their loops, and the per-round ratio is t_S / t_T of the pair;
  * LAMMPS's and LIGGGHTS's section times (Pair, Neigh, Comm, Modify/Other) are reported as tdem/stock
    medians too, so a difference can be placed in the step.
Memory: the engine's "Per MPI rank memory allocation" (average, summed over ranks) per particle, and
the per-contact history of each style (doubles; from the style definitions).

usage: bench/perf.py [--build DIR] [--steps S] [--warm W] [--repeats R] [--natoms N] [--quick]
                     [--out FILE] [--engines lammps,liggghts] [--scenes chute,bed] [--ranks 1,2]
                     [--no-control] [--concurrent] [--metric cpu|wall] [--lammps-version V]
  --lammps-version: LAMMPS through build/bin/tdem-lammps-V (e.g. 4Jul2026) instead of tdem-lammps
  --quick: 200 steps, 1 round, a 20000-sphere bed (a smoke run, minutes)
  --metric: the time the main table's ratio uses (default cpu; both are always in the detail tables)
The tables go to stdout and to --out (default bench/results/perf.md; --out "" writes none).
"""
import argparse
import datetime
import glob
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
from progress import Progress  # noqa: E402
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe"]

KT = 200000.0 * 2.0 / 7.0
# hertz kuwabara_kono coefficient equal to gran/hertz/history's dashpot for two mobile spheres of
# diameter 1 and density 1: G = m* gamma_n sqrt(R*), m* = (pi/6)/2, R* = 1/4
GKK = 3.141592653589793 / 12.0 * 50.0 * 0.5

# per-contact history (doubles) of the styles compared here
HISTORY = {
    "gran/hooke/history": 3, "gran/hertz/history": 3,
    "tdem/gran lsd + cundall_strack": 3, "tdem/gran hertz + cundall_strack": 3,
    "hooke/stiffness + history": 3, "hertz + history": 3,
    "tdem/lsd + tdem/cundall_strack": 3, "tdem/hertz + tdem/cundall_strack": 3,
}

LMP_HEAD = """units lj
atom_style sphere
boundary p p fs
newton off
comm_modify vel yes
"""
LIG_HEAD = """units lj
atom_style granular
atom_modify map array
boundary p p fs
newton off
communicate single vel yes
"""


def lig_props(kind):
    if kind == "linear":
        return "\n".join([
            "fix m1 all property/global kn peratomtypepair 2 200000.0 200000.0 200000.0 200000.0",
            "fix m2 all property/global kt peratomtypepair 2 %r %r %r %r" % (KT, KT, KT, KT),
            "fix m3 all property/global gamman peratomtypepair 2 50.0 50.0 50.0 50.0",
            "fix m4 all property/global gammat peratomtypepair 2 0.0 0.0 0.0 0.0",
            "fix m5 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5"])
    return "\n".join([
        "fix m1 all property/global youngsModulus peratomtype 3e5 3e5",
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3",
        "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.7 0.7 0.7 0.7",
        "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5",
        "fix m5 all property/global tangentialStiffnessRatio peratomtypepair 2 %r %r %r %r"
        % (2 / 7, 2 / 7, 2 / 7, 2 / 7)])


# (scene, engine) -> list of (style label, interaction lines); the first is the stock style
def styles(scene, engine):
    if engine == "lammps":
        if scene == "chute":
            return [("gran/hooke/history", "pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *"),
                    ("tdem/gran lsd + cundall_strack",
                     "pair_style tdem/gran\npair_coeff * * normal lsd stiffness 200000.0 50.0 "
                     "tangential cundall_strack %r 0.0 0.5" % KT)]
        return [("gran/hertz/history", "pair_style gran/hertz/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *"),
                ("tdem/gran hertz + cundall_strack",
                 "pair_style tdem/gran\npair_coeff * * normal hertz 3e5 0 damping kuwabara_kono %r "
                 "tangential cundall_strack 0.8 0.5" % GKK)]
    if scene == "chute":
        p = lig_props("linear")
        return [("hooke/stiffness + history", p + "\npair_style gran model hooke/stiffness tangential history\npair_coeff * *"),
                ("tdem/lsd + tdem/cundall_strack",
                 p + "\npair_style gran model tdem/lsd tangential tdem/cundall_strack\npair_coeff * *")]
    p = lig_props("hertz")
    return [("hertz + history", p + "\npair_style gran model hertz tangential history\npair_coeff * *"),
            ("tdem/hertz + tdem/cundall_strack",
             p + "\npair_style gran model tdem/hertz tangential tdem/cundall_strack damping tsuji\npair_coeff * *")]


def scene_input(scene, engine, inter, steps, warm, data, mark=None):
    """The input of one case; with mark, `shell ./mark.sh FILE` writes the engine's CPU time to
    mark.0 before and mark.1 after the timed run. The timed run skips its setup (`pre no`); the
    `run 0` after it only prints the memory in use after the timed run."""
    head = LMP_HEAD if engine == "lammps" else LIG_HEAD
    if scene == "chute":
        grav = "fix 1 all gravity 1.0 chute 26.0"
    else:
        grav = "fix 1 all gravity 1.0 vector 0.0 0.0 -1.0"
    thermo_fmt = "thermo_modify norm no format float %.15g" + ("" if engine == "lammps" else " lost ignore")
    # the bed is lower than its box: split it across the ranks in x and y only
    procs = "processors * * 1\n" if scene == "bed" else ""
    before = f"shell ./mark.sh {mark}.0\n" if mark else ""
    after = f"shell ./mark.sh {mark}.1\n" if mark else ""
    return f"""{head}{procs}read_data {data}
{inter}
neighbor 0.1 bin
neigh_modify every 1 delay 0
timestep 0.0001
group bottom type 2
group active subtract all bottom
neigh_modify exclude group bottom bottom
{grav}
fix 2 bottom freeze
fix 3 active nve/sphere
compute nc all contact/atom
compute snc all reduce sum c_nc
thermo_style custom step atoms ke c_snc
{thermo_fmt}
thermo {max(steps, 1)}
run {warm}
{before}run {steps} pre no
{after}run 0 post no
"""


def lammps_source():
    """The LAMMPS source tree whose bench/data.chute the chute scenes read (TDEM_LAMMPS_SOURCE, else the
    tree tools/setup.sh unpacks into /var/cache/tdem); "" if none."""
    return os.environ.get("TDEM_LAMMPS_SOURCE") or (glob.glob("/var/cache/tdem/debian-lammps-*") +
                                                    glob.glob("/opt/tdem-deps/lammps-*") + [""])[0]


def make_bed(lmp, natoms, path, log):
    """A dense bed of about natoms spheres: an fcc packing with 3 % gaps between neighbours and random
    displacements of 1 % of a diameter, on a frozen base layer, settled under gravity (LAMMPS, stock
    Hertz) until it rests (each sphere in contact with its neighbours)."""
    a = 1.03 * 2 ** 0.5                      # fcc cell: nearest-neighbour distance 1.03
    nx = max(4, int(round((natoms / (4.0 * 28)) ** 0.5)))   # about 28 cells high
    layers = max(2, -(-natoms // (4 * nx * nx)))
    lx = nx * a
    top = 1.2 + layers * a
    rho = 4.0 / a ** 3                       # lj units: the lattice takes the reduced density
    inp = f"""units lj
atom_style sphere
boundary p p fm
newton off
comm_modify vel yes
region box block 0 {lx} 0 {lx} 0 {top + 2}
create_box 2 box
lattice sc 1.0 origin 0.5 0.5 0.5
region base block 0 {lx} 0 {lx} 0 0.9 units box
create_atoms 2 region base
lattice fcc {rho} origin 0.25 0.25 0.25
region pour block 0 {lx} 0 {lx} 1.2 {top} units box
create_atoms 1 region pour
set group all diameter 1.0
set group all density 1.0
group base type 2
group pour type 1
displace_atoms pour random 0.01 0.01 0.01 4928459 units box
pair_style gran/hertz/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
neighbor 0.2 bin
neigh_modify every 1 delay 0 exclude group base base
fix 1 all gravity 1.0 vector 0.0 0.0 -1.0
fix 2 base freeze
fix 3 pour nve/sphere
timestep 0.0002
thermo 1000
thermo_style custom step atoms ke
run 6000
timestep 0.0001
run 1000
write_data {os.path.basename(path)}
"""
    d = os.path.dirname(path)
    with open(os.path.join(d, "in.settle"), "w") as f:
        f.write(inp)
    subprocess.run(MPIRUN + ["-np", "2", lmp, "-in", "in.settle", "-log", "log.settle", "-echo", "none",
                             "-screen", "none"], cwd=d, check=True)
    ke = None
    for line in open(os.path.join(d, "log.settle")):
        m = re.match(r"\s*(\d+)\s+(\d+)\s+(\S+)\s*$", line)
        if m:
            ke = float(m.group(3))
    n = int(open(path).read().split(" atoms")[0].split()[-1])
    print(f"  settled bed: {n} spheres (incl. base), final kinetic energy {ke:.4g}", file=log)


LOOP = re.compile(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms")
MEM = re.compile(r"Per MPI rank memory allocation \(min/avg/max\) = (\S+) \| (\S+) \| (\S+) Mbytes"
                 r"|Memory usage per processor = (\S+) Mbytes")
# section times of the last run: LAMMPS "Pair    | min | avg | max | ..." (avg), LIGGGHTS "Pair  time (%) = t (p)"
SECT_LMP = re.compile(r"^(Pair|Neigh|Comm|Output|Modify|Other)\s*\|\s*(\S*)\s*\|\s*(\S+)\s*\|", re.M)
SECT_LIG = re.compile(r"^(Pair|Neigh|Comm|Outpt|Modify|Other)\s+time \(%\) = (\S+)", re.M)
SECTIONS = ("Pair", "Neigh", "Comm", "Modify", "Other")

# On-CPU time [ns] of the engine process (the nearest ancestor named tdem-*; LAMMPS and LIGGGHTS run
# `shell` on rank 0 only) from /proc/PID/schedstat (first field: time spent on a CPU), or, on a kernel
# without it, from utime + stime of /proc/PID/stat (clock ticks).
MARK_SH = """#!/bin/sh
p=$PPID
while [ "$p" -gt 1 ]; do
  case "$(cat /proc/$p/comm)" in tdem-*)
    if [ -r /proc/$p/schedstat ]; then read t w n < /proc/$p/schedstat; echo "$t" > "$1"
    else awk -v hz="$(getconf CLK_TCK)" '{printf "%.0f\\n", ($14 + $15) * 1e9 / hz}' /proc/$p/stat > "$1"; fi
    exit 0;;
  esac
  p=$(awk '{print $4}' /proc/$p/stat)
done
echo nan > "$1"
"""


def run_case(exe, np_, workdir, name, text):
    return finish_case(start_case(exe, np_, workdir, name, text), workdir, name)


def run_pair(exe, np_, workdir, cases):
    """Run two cases [(name, text), (name, text)] at the same time (--concurrent): both see the same
    load of the machine during their loops."""
    procs = [start_case(exe, np_, workdir, n, t) for n, t in cases]
    return [finish_case(p, workdir, n) for p, (n, t) in zip(procs, cases)]


def start_case(exe, np_, workdir, name, text):
    inp = os.path.join(workdir, "in." + name)
    with open(inp, "w") as f:
        f.write(text)
    for k in (0, 1):
        try:
            os.remove(os.path.join(workdir, f"cpu.{name}.{k}"))
        except OSError:
            pass
    cmd = ([exe] if np_ == 1 else MPIRUN + ["-np", str(np_), exe]) + ["-in", inp, "-log", "log." + name,
                                                                       "-echo", "none", "-screen", "none"]
    return subprocess.Popen(cmd, cwd=workdir)


def finish_case(proc, workdir, name):
    if proc.wait() != 0:
        sys.exit(f"perf.py: case {name} failed (exit {proc.returncode}); see {workdir}/log.{name}")
    log = open(os.path.join(workdir, "log." + name)).read()
    loops = [m for m in LOOP.finditer(log) if int(m.group(3)) > 0] or list(LOOP.finditer(log))
    mems = MEM.findall(log)
    t, procs, steps, atoms = loops[-1].groups()
    # the thermo lines up to the end of the timed run (the `run 0` after it repeats the last step)
    thermo = [l for l in log[:loops[-1].start()].splitlines() if re.match(r"\s*\d+\s+\d+\s+\S+\s+\S+\s*$", l)]
    contacts = float(thermo[-1].split()[3]) / float(atoms) if thermo else float("nan")
    mem = float(mems[-1][1] or mems[-1][3]) * int(procs) if mems else float("nan")
    last = log[loops[-1].start():]
    nxt = LOOP.search(last, 1)
    last = last[:nxt.start()] if nxt else last
    sect = {}
    for m in SECT_LMP.finditer(last):
        sect[m.group(1)] = float(m.group(3))
    for m in SECT_LIG.finditer(last):
        sect[m.group(1)] = float(m.group(2))
    if "Modify" not in sect and "Other" in sect:      # LIGGGHTS counts the fixes in Other
        sect["Modify"] = sect["Other"]
    try:
        c0, c1 = (float(open(os.path.join(workdir, f"cpu.{name}.{k}")).read()) for k in (0, 1))
        cpu = (c1 - c0) * 1e-9
    except (OSError, ValueError):
        cpu = float("nan")
    work = int(steps) * int(atoms)
    return {"wall": float(t), "cpu": cpu, "pss": work / float(t), "pss_cpu": work / cpu if cpu == cpu and cpu > 0 else float("nan"),
            "atoms": int(atoms), "contacts": contacts, "mem_per_particle": mem * 1048576.0 / int(atoms),
            "sections": sect, "thermo": " ".join(thermo[-1].split()) if thermo else ""}


# palindromic orders of the arms S (stock), T (tdem), C (stock again: the A/A control), one per round in turn
ORDERS3 = (("S", "T", "C"), ("T", "C", "S"), ("C", "S", "T"))
ORDERS2 = (("S", "T"), ("T", "S"))


def round_order(r, control, concurrent=False):
    if concurrent:      # pairs run at the same time, the launch order alternating
        pairs = [("S", "T"), ("S", "C")] if control else [("S", "T")]
        return [p if (r + k) % 2 == 0 else tuple(reversed(p)) for k, p in enumerate(pairs)]
    half = (ORDERS3 if control else ORDERS2)[r % (3 if control else 2)]
    return list(half) + list(reversed(half))


def spread(vals):
    """median, min, max, first and third quartile of a list (NaN-free)"""
    v = sorted(vals)
    if not v:
        return {"med": float("nan"), "min": float("nan"), "max": float("nan"), "q1": float("nan"), "q3": float("nan"), "n": 0}
    q = statistics.quantiles(v, n=4, method="inclusive") if len(v) > 1 else [v[0], v[0], v[0]]
    return {"med": statistics.median(v), "min": v[0], "max": v[-1], "q1": q[0], "q3": q[2], "n": len(v)}


def fmt_spread(st):
    if not st["n"]:
        return ""
    if st["n"] == 1:
        return f"{st['med']:.3f}"
    return f"{st['med']:.3f} [{st['min']:.3f}-{st['max']:.3f}; IQR {st['q1']:.3f}-{st['q3']:.3f}]"


def case_stats(runs, rounds, control):
    """runs[(round, arm)] = list of run results. Per-round ratios (speed of X / speed of S) for the wall
    clock and the CPU time, and of the section times; their spreads; the pooled ratios."""
    out = {"rounds": [], "pooled": {}}
    arms = ["T", "C"] if control else ["T"]
    tot = {(a, m): 0.0 for a in ["S"] + arms for m in ("wall", "cpu")}
    tot.update({("S" + a, m): 0.0 for a in arms for m in ("wall", "cpu")})

    def ref(r, a):      # the stock runs that arm a is compared with (--concurrent: its partner)
        return runs.get((r, "S" + a)) or runs[(r, "S")]
    for r in range(rounds):
        row = {}
        for m in ("wall", "cpu"):
            for a in arms:
                ts = sum(x[m] for x in ref(r, a))
                ta = sum(x[m] for x in runs[(r, a)])
                tot[("S" + a, m)] += ts
                tot[(a, m)] += ta
                row[(a, m)] = ts / ta if ta > 0 else float("nan")
        for sec in SECTIONS:
            for a in arms:
                ss = sum(x["sections"].get(sec, float("nan")) for x in ref(r, a))
                sa = sum(x["sections"].get(sec, float("nan")) for x in runs[(r, a)])
                row[(a, sec)] = sa / ss if ss > 0 else float("nan")     # time ratio: < 1 tdem spends less
        out["rounds"].append(row)
    for a in arms:
        for m in ("wall", "cpu") + SECTIONS:
            out[(a, m)] = spread([row[(a, m)] for row in out["rounds"] if row[(a, m)] == row[(a, m)]])
        for m in ("wall", "cpu"):
            out["pooled"][(a, m)] = tot[("S" + a, m)] / tot[(a, m)] if tot[(a, m)] > 0 else float("nan")
            # best-of estimator: noise only adds time, so the shortest run of an arm is its least disturbed one
            best = {b: min((x[m] for (r, arm), xs in runs.items() if arm == b for x in xs), default=float("nan"))
                    for b in ("S", a)}
            out["best"] = out.get("best", {})
            out["best"][(a, m)] = best["S"] / best[a] if best[a] > 0 else float("nan")
    return out


def machine_line(args):
    cpu = ""
    try:
        cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")][0]
    except Exception:
        pass
    mem_gb = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 1e9
    osname = ""
    try:
        osname = [l.split("=", 1)[1].strip().strip('"') for l in open("/etc/os-release") if l.startswith("PRETTY_NAME")][0]
    except Exception:
        pass
    load = ""
    try:
        load = " ".join(open("/proc/loadavg").read().split()[:3])
    except Exception:
        pass
    ctl = "with the A/A control" if args.control else "without control"
    if args.concurrent:
        ctl += ", stock and tdem (stock and control) run at the same time (--concurrent)"
    return (f"Measured {datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC on {cpu}, {os.cpu_count()} cores, "
            f"{mem_gb:.0f} GB, {osname}, kernel {platform.release()}; load average at the end {load}; "
            f"{args.steps} timed steps after {args.warm} untimed; {args.repeats} round(s) in palindromic order "
            f"{ctl}; main table: median over the rounds of the per-round ratio of {args.metric.upper()} time "
            f"(speed ratio, > 1: tdem faster) [min-max; interquartile range].")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--warm", type=int, default=100)
    ap.add_argument("--repeats", "--rounds", dest="repeats", type=int, default=3,
                    help="rounds (each runs every arm twice)")
    ap.add_argument("--natoms", type=int, default=100000)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=os.path.join(HERE, "results", "perf.md"))
    ap.add_argument("--engines", default="lammps,liggghts")
    ap.add_argument("--scenes", default="chute,bed")
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--no-control", dest="control", action="store_false",
                    help="skip the A/A control arm (stock run again)")
    ap.add_argument("--concurrent", action="store_true",
                    help="run stock and tdem (and stock and control) at the same time, one on each core (1 rank only)")
    ap.add_argument("--metric", default="cpu", help="cpu or wall: the time behind the main table's ratio")
    ap.add_argument("--lammps-version", default="",
                    help="run LAMMPS through build/bin/tdem-lammps-VERSION (e.g. 4Jul2026, a TDEM_LAMMPS_EXTRA "
                         "version) instead of tdem-lammps; both arms run in that executable")
    args = ap.parse_args()
    if args.quick:
        args.steps, args.repeats, args.natoms, args.warm = 200, 1, 20000, 20
    engines = [e for e in args.engines.split(",") if e]
    scenes = [s for s in args.scenes.split(",") if s]
    for e in engines:
        if e not in ("lammps", "liggghts"):
            sys.exit(f"perf.py: --engines: unknown engine '{e}' (allowed: lammps, liggghts)")
    for sc in scenes:
        if sc not in ("chute", "bed"):
            sys.exit(f"perf.py: --scenes: unknown scene '{sc}' (allowed: chute, bed)")
    try:
        ranks = [int(x) for x in args.ranks.split(",") if x]
    except ValueError:
        ranks = []
    if not ranks or any(n < 1 for n in ranks):
        sys.exit(f"perf.py: --ranks: '{args.ranks}' is not a list of positive rank counts (allowed: e.g. 1 or 1,2)")
    if args.metric not in ("cpu", "wall"):
        sys.exit(f"perf.py: --metric: unknown value '{args.metric}' (allowed: cpu, wall)")
    if args.concurrent and ranks != [1]:
        sys.exit(f"perf.py: --concurrent: --ranks {args.ranks} (allowed: --ranks 1; two cases at once fill both cores)")
    if args.repeats < 1:
        sys.exit(f"perf.py: --repeats: {args.repeats} (allowed: >= 1)")
    build = os.path.abspath(args.build)
    lmp_exe = "tdem-lammps" + ("-" + args.lammps_version if args.lammps_version else "")
    exes = {"lammps": os.path.join(build, "bin", lmp_exe), "liggghts": os.path.join(build, "bin", "tdem-liggghts")}
    for e in engines:
        if not os.access(exes[e], os.X_OK):
            sys.exit(f"no {exes[e]} (build first)")
    src = lammps_source()
    chute = os.path.join(src, "bench", "data.chute")
    work = tempfile.mkdtemp(prefix="tdem_perf.")
    log = sys.stderr
    try:
        with open(os.path.join(work, "mark.sh"), "w") as f:
            f.write(MARK_SH)
        os.chmod(os.path.join(work, "mark.sh"), 0o755)
        data = {}
        if "chute" in scenes:
            if not os.path.isfile(chute):
                sys.exit(f"no data.chute under {src}/bench (set TDEM_LAMMPS_SOURCE)")
            shutil.copy(chute, os.path.join(work, "data.chute"))
            data["chute"] = "data.chute"
        if "bed" in scenes:
            cache = os.path.join(build, "bench_cache")
            os.makedirs(cache, exist_ok=True)
            bed = os.path.join(cache, f"bed{args.natoms}.data")
            if not os.path.isfile(bed):
                print(f"settling a bed of {args.natoms} spheres (once; cached in {bed}) ...", file=log)
                make_bed(exes["lammps"], args.natoms, bed, log)
            shutil.copy(bed, os.path.join(work, "bed.data"))
            data["bed"] = "bed.data"
        cases = [(sc, en, np_) for sc in scenes for en in engines for np_ in ranks]
        runs = {c: {} for c in cases}

        def stage(r, c):
            return f"round {r + 1} {c[0]} {c[1]} np {c[2]}"
        # expected cost of a stage: particles x steps, a 2-rank run about 1.8 times faster
        prog = Progress({stage(r, c): (args.natoms if c[0] == "bed" else 32000) / (1.0 if c[2] == 1 else 1.8)
                         for r in range(args.repeats) for c in cases}, stream=log)
        for r in range(args.repeats):
            for c in cases:
                sc, en, np_ = c
                sts = dict(zip(("S", "T"), styles(sc, en)))
                sts["C"] = sts["S"]
                if args.concurrent:
                    for k, pair in enumerate(round_order(r, args.control, True)):
                        todo = []
                        for j, arm in enumerate(pair):
                            name = re.sub(r"[^A-Za-z0-9]+", "_", f"{sc}_{en}_{np_}_{arm}_{k}_{j}")
                            todo.append((name, scene_input(sc, en, sts[arm][1], args.steps, args.warm, data[sc],
                                                           mark="cpu." + name)))
                        res = dict(zip(pair, run_pair(exes[en], np_, work, todo)))
                        other = next(a for a in pair if a != "S")
                        runs[c].setdefault((r, "S"), []).append(res["S"])
                        runs[c][(r, "S" + other)] = [res["S"]]
                        runs[c][(r, other)] = [res[other]]
                        for arm in pair:
                            print(f"  round {r + 1} {sc:5s} {en:8s} np {np_} {arm} (with {'+'.join(pair)}) "
                                  f"{sts[arm][0]:34s} {res[arm]['pss']:.4g} particle-steps/s "
                                  f"(loop {res[arm]['wall']:.3f} s wall, {res[arm]['cpu']:.3f} s CPU)", file=log)
                    prog.done(stage(r, c))
                    continue
                for k, arm in enumerate(round_order(r, args.control)):
                    label, inter = sts[arm]
                    name = re.sub(r"[^A-Za-z0-9]+", "_", f"{sc}_{en}_{np_}_{arm}_{k}")
                    res = run_case(exes[en], np_, work, name,
                                   scene_input(sc, en, inter, args.steps, args.warm, data[sc], mark="cpu." + name))
                    runs[c].setdefault((r, arm), []).append(res)
                    print(f"  round {r + 1} {sc:5s} {en:8s} np {np_} {arm} {label:34s} {res['pss']:.4g} particle-steps/s "
                          f"(loop {res['wall']:.3f} s wall, {res['cpu']:.3f} s CPU)", file=log)
                prog.done(stage(r, c))
        # ---------------------------------------------------------------- tables
        stats = {c: case_stats(runs[c], args.repeats, args.control) for c in cases}

        def med(c, arm, key):
            return statistics.median([x[key] for (r, a), xs in runs[c].items() if a == arm for x in xs])

        def one(c, arm, key):
            return next(x[key] for (r, a), xs in runs[c].items() if a == arm for x in xs)

        m = args.metric
        lines = [machine_line(args), ""]
        lines.append("| scene | engine | ranks | stock style | tdem style | stock particle-steps/s | tdem particle-steps/s | "
                     f"tdem / stock ({m} time) | A/A control stock / stock ({m} time) | 2-rank speedup stock, tdem | "
                     "contacts/particle | memory/particle stock, tdem [bytes] | history/contact stock, tdem [doubles] |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for c in cases:
            sc, en, np_ = c
            (sl, _), (tl, _) = styles(sc, en)
            st = stats[c]
            sp = ""
            if np_ != 1 and (sc, en, 1) in runs:
                c1 = (sc, en, 1)
                sp = f"{med(c, 'S', 'pss') / med(c1, 'S', 'pss'):.2f}, {med(c, 'T', 'pss') / med(c1, 'T', 'pss'):.2f}"
            atoms = one(c, "S", "atoms")
            scene_name = f"(a) in.chute, {atoms}" if sc == "chute" else f"(b) settled bed, {atoms}"
            ctl = fmt_spread(st[("C", m)]) if args.control else ""
            lines.append(f"| {scene_name} | {en} | {np_} | `{sl}` | `{tl}` | {med(c, 'S', 'pss'):.4g} | {med(c, 'T', 'pss'):.4g} | "
                         f"{fmt_spread(st[('T', m)])} | {ctl} | {sp} | {one(c, 'S', 'contacts'):.2f} | "
                         f"{one(c, 'S', 'mem_per_particle'):.0f}, {one(c, 'T', 'mem_per_particle'):.0f} | {HISTORY[sl]}, {HISTORY[tl]} |")
        lines += ["", "Both times: the median of the per-round ratios [min-max; IQR], the pooled ratio (sum of the stock "
                  "times / sum of the tdem times over all rounds) and the best-of ratio (shortest stock run / shortest "
                  "tdem run), each also for the A/A control; "
                  "section times of the engines' timing breakdown (wall clock, median over the rounds of tdem/stock "
                  "time, < 1: tdem spends less).", ""]
        lines.append("| scene | engine | ranks | tdem/stock wall: median [min-max] | pooled | best | A/A wall | pooled, best | "
                     "tdem/stock CPU: median [min-max] | pooled | best | A/A CPU | pooled, best | "
                     "Pair time tdem/stock | Neigh | Comm | Modify (LIGGGHTS: Other) |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for c in cases:
            sc, en, np_ = c
            st = stats[c]
            ctl_w = fmt_spread(st[("C", "wall")]) if args.control else ""
            ctl_c = fmt_spread(st[("C", "cpu")]) if args.control else ""
            pb = {m_: (f"{st['pooled'][('C', m_)]:.3f}, {st['best'][('C', m_)]:.3f}" if args.control else "") for m_ in ("wall", "cpu")}
            lines.append(f"| {sc} | {en} | {np_} | {fmt_spread(st[('T', 'wall')])} | {st['pooled'][('T', 'wall')]:.3f} | "
                         f"{st['best'][('T', 'wall')]:.3f} | {ctl_w} | {pb['wall']} | "
                         f"{fmt_spread(st[('T', 'cpu')])} | {st['pooled'][('T', 'cpu')]:.3f} | {st['best'][('T', 'cpu')]:.3f} | "
                         f"{ctl_c} | {pb['cpu']} | "
                         + " | ".join(f"{st[('T', sec)]['med']:.3f}" for sec in ("Pair", "Neigh", "Comm", "Modify")) + " |")
        lines += ["", "Per-round ratios (speed tdem/stock and of the A/A control, from the CPU time and from the wall clock):", ""]
        lines.append("| scene | engine | ranks | round | order | tdem/stock CPU | tdem/stock wall | A/A CPU | A/A wall |")
        lines.append("|---|---|---|---|---|---|---|---|---|")
        for c in cases:
            sc, en, np_ = c
            for r, row in enumerate(stats[c]["rounds"]):
                a_c = f"{row[('C', 'cpu')]:.3f}" if args.control else ""
                a_w = f"{row[('C', 'wall')]:.3f}" if args.control else ""
                lines.append(f"| {sc} | {en} | {np_} | {r + 1} | {' '.join('+'.join(p) if args.concurrent else p for p in round_order(r, args.control, args.concurrent))} | "
                             f"{row[('T', 'cpu')]:.3f} | {row[('T', 'wall')]:.3f} | {a_c} | {a_w} |")
        same = []
        for c in cases:
            th = {arm: {x["thermo"] for (r, a), xs in runs[c].items() if a == arm for x in xs} for arm in ("S", "T")}
            same.append(f"{c[0]}/{c[1]}/{c[2]}: " + ("tdem = stock" if th["S"] == th["T"] and len(th["S"]) == 1
                                                   else "stock " + "; ".join(sorted(th["S"])) + " / tdem " + "; ".join(sorted(th["T"]))))
        lines += ["", "Thermo after the timed run (step atoms ke contacts): " + " | ".join(same)]
        text = "\n".join(lines) + "\n"
        print(text)
        if args.out:
            os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
            with open(args.out, "w") as f:
                f.write(text)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
