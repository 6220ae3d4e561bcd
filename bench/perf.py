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
Each case runs WARM untimed steps and STEPS timed steps; REPEATS rounds, the order of the styles
reversed every other round; the best round is reported (particle-steps per second of LAMMPS/LIGGGHTS
loop time), with the ratio tdem/stock and the 2-rank speedup. Memory: the engine's "Per MPI rank
memory allocation" (average, summed over ranks) per particle, and the per-contact history of each
style (doubles; from the style definitions).

usage: bench/perf.py [--build DIR] [--steps S] [--repeats R] [--natoms N] [--quick] [--out FILE]
  --quick: 200 steps, 1 round, a 20000-sphere bed (a smoke run, minutes)
The table goes to stdout and to --out (default bench/results/perf.md).
"""
import argparse
import datetime
import glob
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
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


def scene_input(scene, engine, inter, steps, warm, data):
    head = LMP_HEAD if engine == "lammps" else LIG_HEAD
    if scene == "chute":
        grav = "fix 1 all gravity 1.0 chute 26.0"
    else:
        grav = "fix 1 all gravity 1.0 vector 0.0 0.0 -1.0"
    thermo_fmt = "thermo_modify norm no format float %.15g" + ("" if engine == "lammps" else " lost ignore")
    # the bed is lower than its box: split it across the ranks in x and y only
    procs = "processors * * 1\n" if scene == "bed" else ""
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
run {steps}
"""


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


def run_case(exe, np_, workdir, name, text):
    inp = os.path.join(workdir, "in." + name)
    with open(inp, "w") as f:
        f.write(text)
    cmd = ([exe] if np_ == 1 else MPIRUN + ["-np", str(np_), exe]) + ["-in", inp, "-log", "log." + name,
                                                                       "-echo", "none", "-screen", "none"]
    subprocess.run(cmd, cwd=workdir, check=True)
    log = open(os.path.join(workdir, "log." + name)).read()
    loops = LOOP.findall(log)
    mems = MEM.findall(log)
    t, procs, steps, atoms = loops[-1]
    thermo = [l for l in log.splitlines() if re.match(r"\s*\d+\s+\d+\s+\S+\s+\S+\s*$", l)]
    contacts = float(thermo[-1].split()[3]) / float(atoms) if thermo else float("nan")
    mem = float(mems[-1][1] or mems[-1][3]) * int(procs) if mems else float("nan")
    return {"pss": int(steps) * int(atoms) / float(t), "atoms": int(atoms), "contacts": contacts,
            "mem_per_particle": mem * 1048576.0 / int(atoms)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--warm", type=int, default=100)
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--natoms", type=int, default=100000)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=os.path.join(HERE, "results", "perf.md"))
    ap.add_argument("--engines", default="lammps,liggghts")
    ap.add_argument("--scenes", default="chute,bed")
    args = ap.parse_args()
    if args.quick:
        args.steps, args.repeats, args.natoms, args.warm = 200, 1, 20000, 20
    build = os.path.abspath(args.build)
    exes = {"lammps": os.path.join(build, "bin", "tdem-lammps"), "liggghts": os.path.join(build, "bin", "tdem-liggghts")}
    for e in args.engines.split(","):
        if not os.access(exes[e], os.X_OK):
            sys.exit(f"no {exes[e]} (build first)")
    src = os.environ.get("TDEM_LAMMPS_SOURCE") or (glob.glob("/var/cache/tdem/lammps-*") + glob.glob("/opt/tdem-deps/lammps-*") + [""])[0]
    chute = os.path.join(src, "bench", "data.chute")
    work = tempfile.mkdtemp(prefix="tdem_perf.")
    log = sys.stderr
    try:
        data = {}
        if "chute" in args.scenes:
            if not os.path.isfile(chute):
                sys.exit(f"no data.chute under {src}/bench (set TDEM_LAMMPS_SOURCE)")
            shutil.copy(chute, os.path.join(work, "data.chute"))
            data["chute"] = "data.chute"
        if "bed" in args.scenes:
            cache = os.path.join(build, "bench_cache")
            os.makedirs(cache, exist_ok=True)
            bed = os.path.join(cache, f"bed{args.natoms}.data")
            if not os.path.isfile(bed):
                print(f"settling a bed of {args.natoms} spheres (once; cached in {bed}) ...", file=log)
                make_bed(exes["lammps"], args.natoms, bed, log)
            shutil.copy(bed, os.path.join(work, "bed.data"))
            data["bed"] = "bed.data"
        results = {}
        cases = [(sc, en, np_) for sc in args.scenes.split(",") for en in args.engines.split(",") for np_ in (1, 2)]
        for r in range(args.repeats):
            for sc, en, np_ in cases:
                sts = styles(sc, en)
                order = sts if r % 2 == 0 else list(reversed(sts))
                for label, inter in order:
                    name = re.sub(r"[^A-Za-z0-9]+", "_", f"{sc}_{en}_{np_}_{label}")
                    res = run_case(exes[en], np_, work, name, scene_input(sc, en, inter, args.steps, args.warm, data[sc]))
                    key = (sc, en, np_, label)
                    print(f"  {sc:5s} {en:8s} np {np_} {label:34s} {res['pss']:.4g} particle-steps/s", file=log)
                    if key not in results or res["pss"] > results[key]["pss"]:
                        results[key] = res
        # ---------------------------------------------------------------- table
        lines = []
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
        lines.append(f"Measured {datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC on {cpu}, {os.cpu_count()} cores, "
                     f"{mem_gb:.0f} GB, {osname}, kernel {platform.release()}; {args.steps} timed steps after "
                     f"{args.warm} untimed, best of {args.repeats} round(s).")
        lines.append("")
        lines.append("| scene | engine | ranks | stock style | tdem style | stock particle-steps/s | tdem particle-steps/s | tdem / stock | 2-rank speedup stock, tdem | contacts/particle | memory/particle stock, tdem [bytes] | history/contact stock, tdem [doubles] |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for sc in args.scenes.split(","):
            for en in args.engines.split(","):
                (sl, _), (tl, _) = styles(sc, en)
                for np_ in (1, 2):
                    s, t = results[(sc, en, np_, sl)], results[(sc, en, np_, tl)]
                    sp = ""
                    if np_ == 2:
                        s1, t1 = results[(sc, en, 1, sl)], results[(sc, en, 1, tl)]
                        sp = f"{s['pss'] / s1['pss']:.2f}, {t['pss'] / t1['pss']:.2f}"
                    scene_name = f"(a) in.chute, {s['atoms']}" if sc == "chute" else f"(b) settled bed, {s['atoms']}"
                    lines.append(f"| {scene_name} | {en} | {np_} | `{sl}` | `{tl}` | {s['pss']:.4g} | {t['pss']:.4g} | "
                                 f"{t['pss'] / s['pss']:.3f} | {sp} | {s['contacts']:.2f} | "
                                 f"{s['mem_per_particle']:.0f}, {t['mem_per_particle']:.0f} | {HISTORY[sl]}, {HISTORY[tl]} |")
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
