#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Effect-selective cost (issue 8): the same settled bed run with only the effects a scene selects.

Per engine one bed of spheres (two sizes, one atom type each) is settled once under gravity in a box
with frictional walls and written to a data file; every variant reads that file and runs
STEPS steps under `valgrind --tool=callgrind`, instructions collected inside Verlet::run only (the
set-up of the run is not counted). From `callgrind_annotate --inclusive=yes` the script takes the
instructions (Ir) of the whole run loop, of the pair compute, of the fixes (Modify::*) and of the
neighbour-list builds, divided by particles x steps.

Variants (LAMMPS / LIGGGHTS):
  normal        normal law only: pair tdem/gran lsd stiffness + tangential haff_werner 0 0 (the pair
                always has a tangential law; Haff-Werner with gamma_t = mu = 0 keeps no tangential
                memory and gives zero force) / model tdem/lsd tangential off
  normal_mu0    (LAMMPS) the other zero-friction choice: cundall_strack KT 0 0 (mu = 0: the spring is
                evaluated and truncated to zero; the single-law compile-time path)
  tangential    + Cundall-Strack (lsd stiffness + cundall_strack)
  rolling       + rolling resistance (LIGGGHTS: rolling_friction epsd2 with tdem/lsd; LAMMPS: none)
  clumps        + clumps: the same spheres as one-sphere clumps of fix tdem/clump instead of
                nve/sphere (LAMMPS; LIGGGHTS only if the fix is compiled in)
  grate_standing, grate_moving
                + grate: the flat floor replaced by fix tdem/grate (5 rows of flat bars, odd rows
                moving with 4 mm stroke at 5 Hz, or standing)
  stock_normal, stock_tangential
                the stock law of equal physics (LAMMPS gran/hooke with xmu = 0 and gran/hooke/history;
                LIGGGHTS hooke/stiffness tangential off and tangential history)
With --off BUILD the normal-only variant (and the tangential one) also run with the executables of a
build whose modules are compiled out: the claim is that their pair-loop Ir agree within 0.5 %.

usage: effects.py BUILD [--off BUILD_OFF] [--steps N] [--settle N] [--engines lammps,liggghts]
                  [--out FILE] [--keep]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "tools"))
from progress import Progress  # noqa: E402

# ----------------------------------------------------------------------------------- LAMMPS
# box with 1 cm margins around the walls (so that the grate's bars fit inside it)
LMP_HEAD = """units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
"""
LMP_KN, LMP_GN, LMP_KT, LMP_GT, LMP_MU = 2000.0, 50.0, 600.0, 25.0, 0.5
LMP_LAW_N = "normal lsd stiffness %g %g tangential haff_werner 0 0" % (LMP_KN, LMP_GN)
LMP_LAW_N0 = "normal lsd stiffness %g %g tangential cundall_strack %g 0 0" % (LMP_KN, LMP_GN, LMP_KT)
LMP_LAW_T = "normal lsd stiffness %g %g tangential cundall_strack %g %g %g" % (LMP_KN, LMP_GN, LMP_KT, LMP_GT, LMP_MU)
LMP_STOCK_N = "hooke %g 0 %g 0 0 1" % (LMP_KN, LMP_GN)
LMP_STOCK_T = "hooke/history %g %g %g %g %g 1" % (LMP_KN, LMP_KT, LMP_GN, LMP_GT, LMP_MU)
LMP_R1, LMP_R2, LMP_RHO = 0.0020, 0.0024, 2500.0
GRATE_GEOM = ("rows 5 bar_length 0.022 bar_height 0.01 declination 0 width 0.11 type forward "
              "row_group -1 0 -1 0 -1 profile sinusoidal frequency 5")


def lmp_settle(settle):
    return LMP_HEAD + f"""region box block -0.01 0.11 -0.01 0.11 -0.02 0.2 units box
create_box 2 box
lattice sc 0.0052
region fill block 0.003 0.097 0.003 0.097 0.003 0.060 units box
create_atoms 1 region fill
set type 1 type/fraction 2 0.5 4711
set type 1 diameter {2 * LMP_R1}
set type 2 diameter {2 * LMP_R2}
set group all density {LMP_RHO}
variable vx atom 0.05*(random(0,1,13)-0.5)
variable vy atom 0.05*(random(0,1,17)-0.5)
variable vz atom 0.05*(random(0,1,19)-0.5)
velocity all set v_vx v_vy v_vz
neighbor 0.001 bin
neigh_modify delay 0
pair_style tdem/gran
pair_coeff * * {LMP_LAW_T}
fix w0 all tdem/wall/gran {LMP_LAW_T} xplane 0 0.1
fix w1 all tdem/wall/gran {LMP_LAW_T} yplane 0 0.1
fix w2 all tdem/wall/gran {LMP_LAW_T} zplane 0 NULL
fix g all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep 2e-5
thermo 1000
run {settle}
write_data bed.data nocoeff
"""


def lmp_variant(name, steps):
    """input of one LAMMPS variant, or None if it does not exist"""
    stock = name.startswith("stock_")
    law = LMP_LAW_T
    if name in ("normal", "normal_off"):
        law = LMP_LAW_N
    if name == "normal_mu0":
        law = LMP_LAW_N0
    clumps = name == "clumps"
    lines = [LMP_HEAD]
    if clumps:
        lines.append("fix mol all property/atom mol ghost yes")
    lines.append("read_data bed.data")
    lines.append("neighbor 0.001 bin\nneigh_modify delay 0")
    if stock:
        sl = LMP_STOCK_N if name == "stock_normal" else LMP_STOCK_T
        lines.append(f"pair_style gran/{sl}\npair_coeff * *")
        wall = f"wall/gran {sl}"
        lines += [f"fix w0 all {wall} xplane 0 0.1", f"fix w1 all {wall} yplane 0 0.1",
                  f"fix w2 all {wall} zplane 0 NULL"]
    else:
        lines.append(f"pair_style tdem/gran\npair_coeff * * {law}")
        lines += [f"fix w0 all tdem/wall/gran {law} xplane 0 0.1", f"fix w1 all tdem/wall/gran {law} yplane 0 0.1"]
        if name.startswith("grate"):
            stroke = "0.004" if name == "grate_moving" else "0"
            lines.append(f"fix w2 all tdem/grate {law} {GRATE_GEOM} origin -0.005 0.05 0 stroke {stroke}")
        else:
            lines.append(f"fix w2 all tdem/wall/gran {law} zplane 0 NULL")
    lines.append("fix g all gravity 9.81 vector 0 0 -1")
    if clumps:
        # one body per sphere: molecule ID = atom ID; one template per sphere size (atom type)
        lines += ["variable m atom id", "set group all mol v_m",
                  "group t1 type 1", "group t2 type 2",
                  "neigh_modify exclude molecule/intra all",
                  f"fix c1 t1 tdem/clump template small shape single {LMP_R1} 0 density {LMP_RHO} bodies molecule",
                  f"fix c2 t2 tdem/clump template large shape single {LMP_R2} 0 density {LMP_RHO} bodies molecule"]
    else:
        lines.append("fix nve all nve/sphere")
    lines += ["timestep 2e-5", "thermo_style custom step atoms ke", "thermo_modify norm no",
              f"thermo {steps}", f"run {steps}"]
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------------- LIGGGHTS
LIG_HEAD = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
"""
LIG_PROPS = """fix m_kn all property/global kn peratomtypepair 2 6000 6000 6000 6000
fix m_kt all property/global kt peratomtypepair 2 1800 1800 1800 1800
fix m_gn all property/global gamman peratomtypepair 2 300 300 300 300
fix m_gt all property/global gammat peratomtypepair 2 120 120 120 120
fix m_mu all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m_rmu all property/global coefficientRollingFriction peratomtypepair 2 0.1 0.1 0.1 0.1
"""
LIG_MODELS = {
    "normal": "model tdem/lsd tangential off",
    "normal_off": "model tdem/lsd tangential off",
    "tangential": "model tdem/lsd tangential tdem/cundall_strack",
    "tangential_off": "model tdem/lsd tangential tdem/cundall_strack",
    "rolling": "model tdem/lsd tangential tdem/cundall_strack rolling_friction epsd2",
    "clumps": "model tdem/lsd tangential tdem/cundall_strack",
    "grate_standing": "model tdem/lsd tangential tdem/cundall_strack",
    "grate_moving": "model tdem/lsd tangential tdem/cundall_strack",
    "stock_normal": "model hooke/stiffness tangential off",
    "stock_tangential": "model hooke/stiffness tangential history",
}


def lig_walls(model, floor=True):
    out = [f"fix w0 all wall/gran {model} primitive type 1 xplane -0.05",
           f"fix w1 all wall/gran {model} primitive type 1 xplane 0.05",
           f"fix w2 all wall/gran {model} primitive type 1 yplane -0.05",
           f"fix w3 all wall/gran {model} primitive type 1 yplane 0.05"]
    if floor:
        out.append(f"fix w4 all wall/gran {model} primitive type 1 zplane 0.0")
    return "\n".join(out)


def lig_settle(settle, natoms):
    model = LIG_MODELS["tangential"]
    return LIG_HEAD + f"""region box block -0.06 0.06 -0.06 0.06 -0.02 0.20 units box
create_box 2 box
neighbor 0.0015 bin
neigh_modify delay 0
{LIG_PROPS}pair_style gran {model}
pair_coeff * *
timestep 0.00002
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
{lig_walls(model)}
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0025
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2000 radius constant 0.0020
fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.048 0.048 -0.048 0.048 0.002 0.12 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel uniform -0.3 0.3 -0.3 0.3 -0.6 0.0 omega constant 0 0 0 &
    region ins particles_in_region {natoms}
fix integr all nve/sphere
thermo_style custom step atoms ke
thermo 5000
thermo_modify lost ignore norm no
run 1
unfix ins
run {settle}
write_data bed.data
"""


def lig_molecular_data(src, dst):
    """bed.data (atom_style granular: id type diameter density x y z ...) -> the same bed for
    atom_style hybrid sphere molecular (id type x y z diameter density molecule ...), molecule = id"""
    out, section = [], None
    for line in open(src):
        w = line.split()
        if w and w[0] in ("Atoms", "Velocities"):
            section = w[0]
            out.append("Atoms # hybrid\n" if section == "Atoms" else line)
            continue
        if section == "Atoms" and len(w) >= 7:
            out.append(" ".join([w[0], w[1], w[4], w[5], w[6], w[2], w[3], w[0]] + w[7:]) + "\n")
            continue
        out.append(line)
    with open(dst, "w") as f:
        f.writelines(out)


def lig_variant(name, steps):
    model = LIG_MODELS[name]
    if name == "clumps":
        # every sphere a one-sphere body of fix tdem/clump (molecule = atom id); the radii and
        # densities of the two sphere templates of lig_settle
        lines = [LIG_HEAD.replace("atom_style granular", "atom_style hybrid sphere molecular"),
                 "read_data bed_mol.data", "neighbor 0.0015 bin", "neigh_modify delay 0", LIG_PROPS,
                 f"pair_style gran {model}", "pair_coeff * *", "timestep 0.00002",
                 "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0", lig_walls(model),
                 "group t1 type 1", "group t2 type 2",
                 "fix c1 t1 tdem/clump template big shape single 0.0025 0 density 2500 bodies molecule",
                 "fix c2 t2 tdem/clump template small shape single 0.0020 0 density 2000 bodies molecule",
                 "thermo_style custom step atoms ke", "thermo_modify lost ignore norm no",
                 f"thermo {steps}", f"run {steps}"]
        return "\n".join(lines) + "\n"
    lines = [LIG_HEAD, "read_data bed.data", "neighbor 0.0015 bin", "neigh_modify delay 0", LIG_PROPS,
             f"pair_style gran {model}", "pair_coeff * *", "timestep 0.00002",
             "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0"]
    if name.startswith("grate"):
        stroke = "0.004" if name == "grate_moving" else "0"
        lines.append(lig_walls(model, floor=False))
        lines.append(f"fix g all tdem/grate {GRATE_GEOM} origin -0.055 0 0 stroke {stroke}")
        lines.append(f"fix wg all wall/gran {model} mesh n_meshes 2 meshes g_fixed g_moving0")
    else:
        lines.append(lig_walls(model))
    lines.append("fix integr all nve/sphere")
    lines += ["thermo_style custom step atoms ke", "thermo_modify lost ignore norm no",
              f"thermo {steps}", f"run {steps}"]
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------------------ measuring
VARIANTS = ["normal", "normal_mu0", "tangential", "rolling", "clumps", "grate_standing", "grate_moving",
            "stock_normal", "stock_tangential"]


def run(cmd, cwd, log):
    with open(log, "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        tail = open(log).read()[-1500:]
        raise RuntimeError(f"{' '.join(cmd)} failed in {cwd} (rc {r.returncode}):\n{tail}")


def natoms_of(log):
    m = re.findall(r"for \d+ steps with (\d+) atoms", open(log).read())
    return int(m[-1]) if m else None


def annotate(cgout):
    """inclusive Ir per function name (callgrind_annotate --inclusive=yes)"""
    txt = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", cgout],
                         capture_output=True, text=True, check=True).stdout
    total = None
    incl = {}
    for line in txt.splitlines():
        m = re.match(r"^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?(\S.*?)\s+\[", line)
        if m is None:
            m2 = re.match(r"^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?PROGRAM TOTALS", line)
            if m2:
                total = int(m2.group(1).replace(",", ""))
            continue
        ir = int(m.group(1).replace(",", ""))
        fn = m.group(2)
        fn = fn.split(":", 1)[1] if ":" in fn and not fn.startswith("LAMMPS") and "::" not in fn.split(":", 1)[0] else fn
        incl[fn] = max(ir, incl.get(fn, 0))
    return total, incl


def sum_matching(incl, pattern):
    rx = re.compile(pattern)
    return sum(v for k, v in incl.items() if rx.search(k))


def measure(engine, exe, wd, name, text, steps):
    inp = os.path.join(wd, f"in.{name}")
    with open(inp, "w") as f:
        f.write(text)
    cgout = os.path.join(wd, f"cg.{name}")
    t0 = time.time()
    run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={cgout}", "--collect-atstart=no",
         "--toggle-collect=LAMMPS_NS::Verlet::run*", exe, "-in", f"in.{name}", "-log", f"log.{name}",
         "-echo", "none", "-screen", "/dev/null"], wd, os.path.join(wd, f"vg.{name}"))
    t_cg = time.time() - t0
    total, incl = annotate(cgout)
    n = natoms_of(os.path.join(wd, f"log.{name}"))
    pair = sum_matching(incl, r"^LAMMPS_NS::Pair\w*::compute\(int, ?int\)")
    modify = sum_matching(incl, r"^LAMMPS_NS::Modify::\w+\(")
    neigh = sum_matching(incl, r"^LAMMPS_NS::Neighbor::(decide|build)\(")
    return {"engine": engine, "name": name, "atoms": n, "steps": steps, "total": total, "pair": pair,
            "modify": modify, "neigh": neigh, "cg_seconds": t_cg}


def timed(exe, wd, name, steps):
    """one plain run (wall clock): Loop time per particle-step in ns"""
    txt = open(os.path.join(wd, f"in.{name}")).read().replace(f"run {steps}\n", f"run {steps * 10}\n")
    with open(os.path.join(wd, f"in.t.{name}"), "w") as f:
        f.write(txt)
    run([exe, "-in", f"in.t.{name}", "-log", f"log.t.{name}", "-echo", "none", "-screen", "/dev/null"], wd,
        os.path.join(wd, f"out.t.{name}"))
    log = open(os.path.join(wd, f"log.t.{name}")).read()
    m = re.findall(r"Loop time of ([0-9.eE+-]+) on", log)
    n = natoms_of(os.path.join(wd, f"log.t.{name}"))
    return float(m[-1]) / (n * steps * 10) * 1e9


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--off", default=None, help="build dir with the modules compiled out")
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--settle", type=int, default=8000)
    ap.add_argument("--natoms", type=int, default=3000, help="LIGGGHTS bed size")
    ap.add_argument("--engines", default="lammps,liggghts")
    ap.add_argument("--wallclock", action="store_true", help="also one plain run of 10x steps per variant")
    ap.add_argument("--out", default=None)
    ap.add_argument("--keep", action="store_true")
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    off = os.path.abspath(a.off) if a.off else None
    engines = a.engines.split(",")
    root = tempfile.mkdtemp(prefix="tdem_effects_")
    rows = []
    notes = []
    try:
        for engine in engines:
            exe = os.path.join(build, "bin", "tdem-" + engine)
            if not os.access(exe, os.X_OK):
                sys.exit(f"effects.py: {exe} not found (build the tdem-{engine} target)")
            wd = os.path.join(root, engine)
            os.makedirs(wd)
            settle = lmp_settle(a.settle) if engine == "lammps" else lig_settle(a.settle, a.natoms)
            with open(os.path.join(wd, "in.settle"), "w") as f:
                f.write(settle)
            t0 = time.time()
            run([exe, "-in", "in.settle", "-log", "log.settle", "-echo", "none", "-screen", "/dev/null"], wd,
                os.path.join(wd, "out.settle"))
            if engine == "liggghts":
                lig_molecular_data(os.path.join(wd, "bed.data"), os.path.join(wd, "bed_mol.data"))
            print(f"[{engine}] settled bed: {natoms_of(os.path.join(wd, 'log.settle'))} spheres, "
                  f"{a.settle} steps, {time.time() - t0:.0f} s", flush=True)
            todo = []
            for v in VARIANTS:
                if engine == "lammps":
                    if v == "rolling":
                        notes.append("LAMMPS: rolling sds of pair tdem/gran not measured in this bench")
                        continue
                    todo.append((v, exe, lmp_variant(v, a.steps)))
                else:
                    if v == "normal_mu0":
                        continue
                    text = lig_variant(v, a.steps)
                    todo.append((v, exe, text))
            if off:
                exe_off = os.path.join(off, "bin", "tdem-" + engine)
                for v in ("normal", "tangential"):
                    text = lmp_variant(v, a.steps) if engine == "lammps" else lig_variant(v, a.steps)
                    todo.append((v + "_off", exe_off, text))
            prog = Progress(n=len(todo), label=f"[{engine}] variants")
            for v, e, text in todo:
                r = measure(engine, e, wd, v, text, a.steps)
                if a.wallclock:
                    r["ns"] = timed(e, wd, v, a.steps)
                rows.append(r)
                print(f"[{engine}] {v}: {r['atoms']} atoms, Ir/particle-step total {r['total'] / (r['atoms'] * a.steps):.1f}"
                      f" pair {r['pair'] / (r['atoms'] * a.steps):.1f} fixes {r['modify'] / (r['atoms'] * a.steps):.1f}"
                      f" ({r['cg_seconds']:.0f} s)", flush=True)
                prog.done(f"[{engine}] {v}")
    finally:
        if a.keep:
            print("kept", root)
        else:
            shutil.rmtree(root, ignore_errors=True)
    if not report(rows, notes, a, build, off):
        sys.exit("effects.py: a compiled-in module changed the pair-loop instructions by more than 0.5 %")


NOTES = """## Variants

Same bed in every variant of an engine (written once by a settling run, read with `read_data`), the
walls (`fix tdem/wall/gran` planes / LIGGGHTS `wall/gran primitive`) and gravity with the law of the
variant, `fix nve/sphere` unless said otherwise.

| variant | LAMMPS (`pair tdem/gran`, `fix tdem/wall/gran`) | LIGGGHTS (`pair gran`, `fix wall/gran`) |
|---|---|---|
| normal | `normal lsd stiffness 2000 50 tangential haff_werner 0 0` (the pair always has a tangential law; Haff-Werner with gamma_t = mu = 0 keeps no memory and gives zero force) | `model tdem/lsd tangential off` |
| normal_mu0 | `tangential cundall_strack 600 0 0` (mu = 0; the spring is evaluated and truncated to zero) | - |
| tangential | `tangential cundall_strack 600 25 0.5` | `model tdem/lsd tangential tdem/cundall_strack` |
| rolling | not measured (pair tdem/gran `rolling sds`) | + `rolling_friction epsd2` (compiled for tdem/lsd + tdem/cundall_strack, `src/pair_styles/liggghts/combos.h`) |
| clumps | tangential + every sphere a one-sphere body of `fix tdem/clump` (`shape single`, one fix per sphere size, `bodies molecule`, default `rotation splitting`) instead of `nve/sphere` | the same (`atom_style hybrid sphere molecular`, the bed converted with molecule = atom id) |
| grate_standing / grate_moving | tangential, the floor replaced by `fix tdem/grate` (5 flat rows of 22 mm, rows 1 and 3 moving: stroke 0 / 4 mm at 5 Hz) | same grate as LIGGGHTS meshes + `fix wall/gran ... mesh` |
| stock_normal | `pair gran/hooke 2000 0 50 0 0 1` (xmu = 0: no tangential force) | `model hooke/stiffness tangential off` |
| stock_tangential | `pair gran/hooke/history 2000 600 50 25 0.5 1` | `model hooke/stiffness tangential history` |
| *_off | the same input run by the build with every module compiled out | same |

## Why an effect that is not selected costs nothing

- LIGGGHTS: every (normal, tangential, cohesion, rolling, surface) combination is its own compile-time
  instantiation `ContactModel<GranStyle<N, T, C, R, S>>` (`src/pair_styles/liggghts/register_combo.h`,
  `register_combo<N, T, C, R, S>()`), selected once from the hash of the `model ... tangential ...`
  keywords. `ContactModel::surfacesIntersect` calls `cohesionModel`, `tangentialModel`, `rollingModel`
  of the instantiation; for `COHESION_OFF`, `TANGENTIAL_OFF`, `ROLLING_OFF` these are empty inline
  functions (LIGGGHTS `cohesion_model_base.h`, `tangential_model_base.h`, `rolling_model_base.h`), so the
  contact loop of `tdem/lsd tangential off` contains no tangential or rolling code and no test for it.
- LAMMPS: `PairTDEMGran::eval<M, E, S, TL>` is instantiated per (normal law M, end E, slip S,
  tangential law TL) and picked once per `compute()` by `tdem_lammps::dispatch`
  (`src/pair_styles/lammps/tdem_lammps_law.h`); inside the loop `evaluate_contact<M, E, S, TL>` and
  `if (TL != TLAW_CUNDALL_STRACK)` are resolved at compile time (E, S = -1 read end/slip options at run
  time on the paths of the non-default tangential laws). The only run-time tests in the loop that are not
  law parameters are the stock granular ones: `if (fix_rigid)` (body mass of a rigid/clump fix) and the
  freeze-group mask.
- Clumps and grate live in separate fixes (modules): the pair loop does not know them; a scene without
  them runs no code of theirs (the *_off rows: the same pair-loop instructions with the modules compiled out).
"""

# the variant each one extends by one effect
BASE = {"normal_mu0": "normal", "tangential": "normal", "rolling": "tangential", "clumps": "tangential",
        "grate_standing": "tangential", "grate_moving": "grate_standing", "stock_tangential": "stock_normal",
        "normal_off": "normal", "tangential_off": "tangential"}


def report(rows, notes, a, build, off):
    out = []
    ok = True
    p = out.append
    p("# Effect-selective cost (bench/effects.sh)")
    p("")
    p(f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; build `{build}`"
      + (f", modules-off build `{off}`" if off else "") + f"; {a.steps} steps per variant under callgrind "
      "(instructions Ir inside `Verlet::run`, set-up excluded), 1 rank. Ir per particle-step: whole run loop; "
      "pair = the pair style's `compute`; fixes = `Modify::*` (integrator, walls, gravity, clump, grate); "
      "neigh = neighbour-list decisions and builds."
      + (f" Wall clock: `Loop time` of one plain run of {10 * a.steps} steps per variant on the shared, loaded "
         "2-core machine (noisy, +-10 % between invocations; the instruction counts are the figure to trust)."
         if a.wallclock else ""))
    p("")
    for engine in ("lammps", "liggghts"):
        er = {r["name"]: r for r in rows if r["engine"] == engine}
        if not er:
            continue
        ref = er.get("normal")
        p(f"## {'LAMMPS' if engine == 'lammps' else 'LIGGGHTS'}")
        p("")
        p("| variant | atoms | Ir/particle-step total | ratio to normal only | ratio to the variant without the effect "
          "| pair | pair ratio to normal only | fixes | neigh |" + (" wall clock ns/particle-step |" if a.wallclock else ""))
        p("|---|---|---|---|---|---|---|---|---|" + ("---|" if a.wallclock else ""))
        for name, r in er.items():
            ps = r["atoms"] * r["steps"]
            base = BASE.get(name)
            inc = f"{r['total'] / er[base]['total']:.3f} (vs {base})" if base in er else ""
            p(f"| {name} | {r['atoms']} | {r['total'] / ps:.1f} | {r['total'] / ref['total']:.3f} | {inc} | "
              f"{r['pair'] / ps:.1f} | {r['pair'] / ref['pair']:.3f} | {r['modify'] / ps:.1f} | {r['neigh'] / ps:.1f} |"
              + (f" {r['ns']:.1f} |" if a.wallclock else ""))
        p("")
        for mine, stock in (("normal", "stock_normal"), ("tangential", "stock_tangential")):
            if mine in er and stock in er:
                p(f"- pair-loop Ir {mine} / {stock}: {er[mine]['pair'] / er[stock]['pair']:.4f}")
        for v in ("normal", "tangential"):
            if v in er and v + "_off" in er:
                d_pair = er[v]["pair"] / er[v + "_off"]["pair"] - 1
                d_tot = er[v]["total"] / er[v + "_off"]["total"] - 1
                ok = ok and abs(d_pair) <= 0.005
                p(f"- {v}: modules compiled in vs compiled out: pair-loop Ir {er[v]['pair']} vs {er[v + '_off']['pair']} "
                  f"({100 * d_pair:+.4f} %), whole run loop {er[v]['total']} vs {er[v + '_off']['total']} "
                  f"({100 * d_tot:+.4f} %): {'within' if abs(d_pair) <= 0.005 else 'NOT within'} 0.5 %")
        p("")
    for n in sorted(set(notes)):
        p(f"- {n}")
    p("")
    p(NOTES)
    text = "\n".join(out) + "\n"
    print(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text)
    return ok


if __name__ == "__main__":
    main()
