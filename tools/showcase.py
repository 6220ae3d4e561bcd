#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""tdem showcase: the linear spring-dashpot + Cundall-Strack laws in LIGGGHTS and LAMMPS.

1. Accuracy. A sphere hits a wall head-on, in both engines, with tdem's law given by the
   coefficient of restitution e and the contact time t_c it should have, in both end-of-contact
   conventions. The realised e and t_c are measured from the trajectory and compared with the
   request. Next to it: stock LIGGGHTS `model hooke` with `limitForce on` (no attraction), which
   derives its damping with the attraction-allowed formula, against tdem's `parameters material`
   (the same stiffness rule, damping derived for the convention in use).
2. What accuracy costs in time: the integrator study (validation/integrators/run.sh: every scheme,
   phase-averaged errors of e and beta against the closed form vs steps per contact, cost per
   contact), its Pareto picture (build/showcase/pareto.png) and a three-line verdict, then the cost
   of every tdem normal law against the stock LAMMPS law it replaces, measured on the spot as
   interleaved ratios with an A/A control (bench/law_costs.py; build/showcase/law_costs.md).
3. A bed of spheres settles in a box, in each engine on 2 MPI ranks, with the tdem laws
   (input_scripts/liggghts/in.tdem_lsd_box, input_scripts/lammps/in.tdem_settle).
4. Moving grates (fix tdem/grate) on 2 MPI ranks: forward-acting 2D and 3D, reverse-acting 3D,
   with the mixing measures P' (compute tdem/mixing/velocity) and D, Q' (fix tdem/mixing/depth):
   the short version of validation/grate/run.sh; bar and particle VTK files for ParaView and the
   mixing plots in build/showcase/grate.
5. Rigid multi-sphere clumps (fix tdem/clump) on 2 MPI ranks: 2000 tetra-sphere and rod clumps
   inserted with random orientations and poured into a box (input_scripts/liggghts/clumps_pour.in);
   particle dumps for ParaView and the bodies as VTK series (tetra_bodies.pvd, rod_bodies.pvd, read
   back here with the VTK library) in build/showcase/clumps.

Writes build/showcase/impact.csv and impact.png and prints the tables.
Usage: python3 tools/showcase.py [BUILD_DIR]
"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(HERE, "tools"))
from progress import Progress  # noqa: E402
BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "build"))
LIG = os.path.join(BUILD, "bin", "tdem-liggghts")
LMP = os.path.join(BUILD, "bin", "tdem-lammps")
OUT = os.path.join(BUILD, "showcase")
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"]

R, RHO, V0, TC = 0.005, 2500.0, 1.0, 1.0e-3
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
STEPS_PER_CONTACT = 400
DT = TC / STEPS_PER_CONTACT
NSTEPS = 3 * STEPS_PER_CONTACT
GAP = 0.2 * V0 * TC  # free flight before the touch

LIG_IMPACT = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
{props}
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran {model} {settings}
pair_coeff * *
timestep {dt!r}
create_atoms 1 single 0.0 0.0 {z0!r} units box
set group all diameter {d!r} density {rho!r}
velocity all set 0.0 0.0 {v!r} units box
fix wz all wall/gran {model} primitive type 1 zplane 0.0 {settings}
fix integr all nve/sphere
dump d all custom 1 dump.impact id z vz fz
dump_modify d format "%d %.17g %.17g %.17g"
thermo {n}
run {n}
"""

LMP_IMPACT = """units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
create_atoms 1 single 0 0 {z0!r} units box
set atom 1 diameter {d!r} density {rho!r}
velocity all set 0 0 {v!r} units box
pair_style tdem/gran
pair_coeff * * {law}
fix wz all tdem/wall/gran {law} zplane 0 NULL
fix nve all nve/sphere
timestep {dt!r}
dump d all custom 1 dump.impact id z vz fz
dump_modify d format float %.17g
thermo {n}
run {n}
"""


def run(cmd, text, workdir, name):
    path = os.path.join(workdir, name)
    with open(path, "w") as f:
        f.write(text)
    t0 = time.time()
    r = subprocess.run(cmd + ["-in", name, "-log", "none"], cwd=workdir, capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:] + r.stderr[-3000:])
        raise SystemExit("showcase: %s failed on %s" % (cmd[-1], name))
    return r.stdout, time.time() - t0


def measure(workdir):
    """Realised e (final/initial normal velocity) and t_c (time with a non-zero wall force)."""
    vz, fz = [], []
    with open(os.path.join(workdir, "dump.impact")) as f:
        lines = f.read().split("ITEM: TIMESTEP")[1:]
    for block in lines:
        row = block.strip().splitlines()[-1].split()
        vz.append(float(row[2]))
        fz.append(float(row[3]))
    steps_in_contact = sum(1 for x in fz if x != 0.0)
    return vz[-1] / -vz[0], steps_in_contact * DT


def closed_form(k, gamma, meff, zero_force):
    """(e, t_c) of the linear spring-dashpot; zero force end also in the over-damped range."""
    w0, d = math.sqrt(k / meff), gamma / (2 * meff)
    if d >= w0:
        if not zero_force:
            return 0.0, math.inf
        s = math.sqrt(d * d - w0 * w0)
        tc = 2 * math.atanh(s / d) / s if s > 0 else 2 / d
        return math.exp(-d * tc), tc
    w = math.sqrt(w0 * w0 - d * d)
    if zero_force:
        tc = 2 * math.atan2(w, d) / w
        return math.exp(-d * tc), tc
    return math.exp(-math.pi * d / w), math.pi / w


def impacts(tmp):
    rows = []
    common = dict(dt=DT, z0=R + GAP, d=2 * R, rho=RHO, v=-V0, n=NSTEPS)
    for e in (0.9, 0.7, 0.5, 0.3, 0.1):
        for limit in (False, True):
            conv = "zero force" if limit else "zero overlap"
            # tdem, restitution mode, both hosts
            props = ("fix m_e all property/global coefficientRestitution peratomtypepair 1 %r\n"
                     "fix m_tc all property/global contactTime peratomtypepair 1 %r\n"
                     "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857" % (e, TC))
            w = tempfile.mkdtemp(dir=tmp)
            run([LIG], LIG_IMPACT.format(props=props, model="model tdem/lsd tangential tdem/cundall_strack",
                                         settings="parameters restitution limitForce " + ("on" if limit else "off"),
                                         **common), w, "in.impact")
            rows.append(("LIGGGHTS tdem/lsd restitution", conv, e, TC) + measure(w))
            w = tempfile.mkdtemp(dir=tmp)
            law = ("normal lsd restitution %r %r tangential cundall_strack 0.2857 0.5 limit_force %s"
                   % (e, TC, "yes" if limit else "no"))
            run([LMP], LMP_IMPACT.format(law=law, **common), w, "in.impact")
            rows.append(("LAMMPS tdem/gran restitution", conv, e, TC) + measure(w))
            # material data (Young's modulus, characteristic velocity) and e: stock hooke vs tdem
            Y = 2.0e7
            props = ("fix m_E all property/global youngsModulus peratomtype %r\n"
                     "fix m_nu all property/global poissonsRatio peratomtype 0.3\n"
                     "fix m_vc all property/global characteristicVelocity scalar 1.0\n"
                     "fix m_e all property/global coefficientRestitution peratomtypepair 1 %r\n"
                     "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 1.0" % (Y, e))
            ystar = Y / (2 * (1 - 0.3 ** 2))
            k = 16 / 15 * math.sqrt(R) * ystar * (15 * MASS / (16 * math.sqrt(R) * ystar)) ** 0.2
            for label, model, settings in (
                    ("LIGGGHTS stock hooke", "model hooke tangential history", ""),
                    ("LIGGGHTS tdem/lsd material", "model tdem/lsd tangential tdem/cundall_strack",
                     "parameters material")):
                w = tempfile.mkdtemp(dir=tmp)
                lf = "limitForce " + ("on" if limit else "off")
                run([LIG], LIG_IMPACT.format(props=props, model=model, settings=(settings + " " + lf).strip(),
                                             **common), w, "in.impact")
                er, tcr = measure(w)
                # the contact time the requested e should come with, for this stiffness
                lo, hi = 0.0, 20 * math.sqrt(k * MASS)  # e(gamma) decreases monotonically
                for _ in range(100):
                    mid = (lo + hi) / 2
                    lo, hi = (mid, hi) if closed_form(k, mid, MASS, limit)[0] > e else (lo, mid)
                rows.append((label, conv, e, closed_form(k, lo, MASS, limit)[1], er, tcr))
    return rows


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, conv in zip(axes, ("zero overlap", "zero force")):
        ax.plot([0, 1], [0, 1], color="0.7", lw=1, label="requested")
        for label, marker in (("LIGGGHTS tdem/lsd restitution", "o"), ("LAMMPS tdem/gran restitution", "x"),
                              ("LIGGGHTS tdem/lsd material", "s"), ("LIGGGHTS stock hooke", "^")):
            pts = [(r[2], r[4]) for r in rows if r[0] == label and r[1] == conv]
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, ls="none", mfc="none", label=label)
        ax.set_xlabel("requested coefficient of restitution e")
        ax.set_ylabel("realised e (sphere on a wall)")
        ax.set_title("contact ends at %s" % conv)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return True


def _is_number(x):
    try:
        float(x)
        return True
    except ValueError:
        return False


def render(*args):
    """Pictures through tools/render.py (VTK, off-screen under Xvfb); False when that cannot run."""
    xvfb = shutil.which("xvfb-run")
    if not xvfb:
        print("(no xvfb-run: pictures skipped; tools/setup.sh installs xvfb)")
        return False
    r = subprocess.run([xvfb, "-a", "-s", "-screen 0 1280x1024x24", sys.executable,
                        os.path.join(HERE, "tools", "render.py")] + [str(a) for a in args],
                       capture_output=True, text=True)
    sys.stdout.write("".join(l + "\n" for l in r.stdout.splitlines() if l.startswith("render.py")))
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-2000:] + r.stderr[-2000:])
        raise SystemExit("showcase: rendering %s failed" % " ".join(str(a) for a in args))
    return True


def settle(tmp):
    res = []
    for host, exe, script in (("LIGGGHTS", LIG, "input_scripts/liggghts/in.tdem_lsd_box"),
                              ("LAMMPS", LMP, "input_scripts/lammps/in.tdem_settle")):
        w = tempfile.mkdtemp(dir=tmp)
        text = open(os.path.join(HERE, script)).read()
        text += "\nwrite_dump all custom bed.dump id type x y z vx vy vz radius\n"
        with open(os.path.join(w, "in.scene"), "w") as f:
            f.write(text)
        t0 = time.time()
        r = subprocess.run(MPIRUN + [exe, "-in", "in.scene", "-log", "none"], cwd=w, capture_output=True, text=True)
        if r.returncode != 0:
            sys.stderr.write(r.stdout[-3000:] + r.stderr[-3000:])
            raise SystemExit("showcase: %s failed" % script)
        thermo = [l for l in r.stdout.splitlines() if l.split() and all(_is_number(x) for x in l.split())]
        res.append((host, script, thermo[0], thermo[-1], time.time() - t0))
        os.makedirs(os.path.join(OUT, "beds"), exist_ok=True)
        shutil.copy(os.path.join(w, "bed.dump"), os.path.join(OUT, "beds", host.lower() + ".dump"))
    return res


def clumps(n_per_kind=1000, steps=24000):
    """Pour 2 x n_per_kind clumps; returns (thermo first, thermo last, seconds, clumps, spheres,
    largest change of an intra-clump distance, highest sphere centre)."""
    w = os.path.join(OUT, "clumps")
    shutil.rmtree(w, ignore_errors=True)
    os.makedirs(w)
    text = open(os.path.join(HERE, "input_scripts", "liggghts", "clumps_pour.in")).read()
    marker = "# dump          d all custom 2000 dump.clumps id mol type x y z radius"
    if marker not in text:
        raise SystemExit("showcase: the dump line of clumps_pour.in moved")
    text = text.replace(marker, "dump            d all custom %d dump.clumps id mol type x y z radius\n"
                        "dump_modify     d format \"%%d %%d %%d %%.16g %%.16g %%.16g %%.16g\"" % (steps // 6))
    # the bodies as VTK files (fix tdem/clump ... vtk N prefix): a .pvd series per clump kind
    for kind, tail in (("tetra", "type 1 vel 0 0 -0.5"), ("rod", "type 2 vel 0 0 -0.5")):
        if tail not in text:
            raise SystemExit("showcase: the fix tdem/clump lines of clumps_pour.in moved")
        text = text.replace(tail, "%s vtk %d %s_bodies" % (tail, steps // 6, kind), 1)
    with open(os.path.join(w, "in.clumps"), "w") as f:
        f.write(text)
    t0 = time.time()
    r = subprocess.run(MPIRUN + [LIG, "-in", "in.clumps", "-log", "log.clumps", "-var", "n", str(n_per_kind),
                                 "-var", "steps", str(steps), "-var", "zhi", "0.36"], cwd=w, capture_output=True,
                       text=True, errors="replace")
    secs = time.time() - t0
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:] + r.stderr[-3000:])
        raise SystemExit("showcase: the clump pour failed")
    thermo = [l for l in r.stdout.splitlines() if l.split() and all(_is_number(x) for x in l.split())]
    frames = []
    with open(os.path.join(w, "dump.clumps")) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[k + 1])
            k += 7  # bounds header and ITEM: ATOMS line
            rows = sorted((tuple(float(v) for v in l.split()) for l in lines[k:k + n]), key=lambda a: a[0])
            frames.append(rows)
            k += n
        else:
            k += 1
    first, last = frames[0], frames[-1]

    def distances(rows):
        by_mol = {}
        for a in rows:
            by_mol.setdefault(int(a[1]), []).append(a[3:6])
        out = {}
        for m, ps in by_mol.items():
            out[m] = [math.dist(ps[i], ps[j]) for i in range(len(ps)) for j in range(i + 1, len(ps))]
        return out

    d0, d1 = distances(first), distances(last)
    worst = max(abs(a - b) for m in d0 for a, b in zip(d0[m], d1[m]))
    top = max(a[5] for a in last)
    # the VTK series of the bodies, read back with the VTK library
    sys.path.insert(0, os.path.join(HERE, "tests", "host"))
    import vtk_read
    for kind in ("tetra", "rod"):
        series = vtk_read.read_pvd(os.path.join(w, kind + "_bodies.pvd"))
        d = vtk_read.read_dataset(series[-1][1])
        print("  %s_bodies.pvd: %d files up to t = %.3g s; the last holds %d bodies, %d spheres" % (
            kind, len(series), series[-1][0], len(d["cells"]), d["npoints"]))
        if len(series) != 7 or len(d["cells"]) != n_per_kind:
            raise SystemExit("showcase: the VTK series %s_bodies.pvd is not complete" % kind)
    return thermo[0], thermo[-1], secs, len(d1), len(last), worst, top


def cheapest_rows(table_md):
    """{target: (cheapest, cost, velocity_verlet cost)} from the integrator study's table.md."""
    out, on = {}, False
    for line in open(table_md, encoding="utf-8"):
        if line.startswith("## Cheapest scheme"):
            on = True
            continue
        if on and line.startswith("## "):
            break
        cells = [c.strip().replace("\x00", "|") for c in line.replace("\\|", "\x00").strip().strip("|").split("|")]
        if on and len(cells) == 4 and cells[0] not in ("target", "---"):
            best = cells[1].split(" (")
            out[cells[0]] = (best[0], best[1].rstrip(")") if len(best) > 1 else "-", cells[3])
    return out


def accuracy_cost(steps, rounds):
    """The integrator study with its verdict, and the per-law cost table; returns the seconds."""
    t0 = time.time()
    res = os.path.join(HERE, "validation", "integrators", "results")
    r = subprocess.run(["sh", os.path.join(HERE, "validation", "integrators", "run.sh")], capture_output=True, text=True)
    sys.stdout.write(r.stdout)
    if r.returncode != 0:
        sys.stderr.write(r.stderr[-3000:])
        raise SystemExit("showcase: the integrator study failed")
    shutil.copy(os.path.join(res, "pareto.png"), os.path.join(OUT, "pareto.png"))
    shutil.copy(os.path.join(res, "table.md"), os.path.join(OUT, "integrators.md"))
    c = cheapest_rows(os.path.join(res, "table.md"))

    def row(key):
        return c.get(key, ("?", "?", "?"))
    e2, e3, e4, ei = (row("|Δe| ≤ 0.01, generic dt"), row("|Δe| ≤ 0.001, generic dt"),
                      row("|Δe| ≤ 0.0001, generic dt"), row("|Δe| ≤ 0.001, dt = t_c/N"))
    print("verdict (head-on LSD impact, e = 0.8, the step not a divisor of the contact time, as in every real run):")
    print("  |de| <= 1e-2:  %s at a cost of %s force evaluations per contact; velocity Verlet (= nve/sphere) %s:"
          " keep nve/sphere." % (e2[0], e2[1], e2[2]))
    print("  |de| <= 1e-3:  %s at %s, velocity Verlet %s: every scheme is first order here (the contact starts and"
          " ends between grid points), so higher order buys nothing; refine the step." % (e3[0], e3[1], e3[2]))
    print("  |de| <= 1e-4:  %s at a generic step; only with dt = t_c/N exactly does order pay (%s reaches 1e-3 at"
          " %s, velocity Verlet %s). The time-grid correction of issue 22 targets this." % (
              e4[0] if e4[0] != "none within N ≤ 320" else "no scheme within 320 steps per contact", ei[0], ei[1], ei[2]))
    print("picture: %s (error against cost per contact); full table: %s" % (os.path.join(OUT, "pareto.png"),
                                                                              os.path.join(OUT, "integrators.md")))
    print("\ncost of the tdem normal laws against the stock LAMMPS laws (bench/law_costs.py, chute of 32000 spheres):")
    r = subprocess.run([sys.executable, os.path.join(HERE, "bench", "law_costs.py"), "--build", BUILD, "--steps",
                        str(steps), "--rounds", str(rounds), "--out", os.path.join(OUT, "law_costs.md")])
    if r.returncode != 0:
        raise SystemExit("showcase: bench/law_costs.py failed")
    return time.time() - t0


def main():
    for exe in (LIG, LMP):
        if not os.access(exe, os.X_OK):
            raise SystemExit("showcase: %s not built (run tools/setup.sh)" % exe)
    os.makedirs(OUT, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="tdem_showcase_")
    # the steps and their expected seconds on 2 cores: a progress line after each, with the time to go
    prog = Progress({"step 1 (impacts)": 15, "step 2 (accuracy and cost)": 90, "step 3 (settling beds)": 40,
                     "step 4 (grates)": 70, "step 5 (clumps)": 50})
    try:
        print("== 1. Sphere on a wall, v0 = %g m/s, R = %g m, %d steps per contact ==" % (V0, R, STEPS_PER_CONTACT))
        rows = impacts(tmp)
        print("%-31s %-13s %6s %8s %8s %10s %10s %8s" % ("law", "contact end", "e req", "e real", "err e",
                                                         "t_c req", "t_c real", "err t_c"))
        for r in rows:
            print("%-31s %-13s %6.2f %8.4f %+8.1e %10.4e %10.4e %+8.1e"
                  % (r[0], r[1], r[2], r[4], r[4] / r[2] - 1, r[3], r[5], r[5] / r[3] - 1))
        with open(os.path.join(OUT, "impact.csv"), "w", newline="") as f:
            wr = csv.writer(f)
            wr.writerow(["law", "contact_end", "e_requested", "tc_expected", "e_realised", "tc_realised"])
            wr.writerows(rows)
        worst = max(abs(r[4] / r[2] - 1) for r in rows if "stock" not in r[0])
        stock = [r for r in rows if "stock" in r[0] and r[1] == "zero force"]
        print("\ntdem laws: largest |e error| %.1e (time-step error, 1/%d of a contact)." % (worst, STEPS_PER_CONTACT))
        print("stock hooke with limitForce on: requested e -> realised e: " +
              ", ".join("%.2f -> %.3f" % (r[2], r[4]) for r in stock))
        if plot(rows, os.path.join(OUT, "impact.png")):
            print("plot: %s" % os.path.join(OUT, "impact.png"))
        prog.done("step 1 (impacts)")
        print("\n== 2. What accuracy costs in time (validation/integrators/run.sh, bench/law_costs.py) ==")
        accuracy_cost(300, 3)
        prog.done("step 2 (accuracy and cost)")
        print("\n== 3. Settling beds with the tdem laws, mpirun -np 2 ==")
        for host, script, first, last, secs in settle(tmp):
            print("%-9s %-40s %5.1f s\n          first thermo: %s\n          last thermo:  %s"
                  % (host, script, secs, first.strip(), last.strip()))
            render("dump", os.path.join(OUT, "beds", host.lower() + ".dump"), os.path.join(OUT, "bed_%s.png" % host.lower()),
                   "--color", "height", "--title", "settled bed, %s (%s)" % (host, os.path.basename(script)))
        prog.done("step 3 (settling beds)")
        print("\n== 4. Moving grates with mixing analysis, mpirun -np 2 (validation/grate/run.sh --short) ==")
        grate = os.path.join(OUT, "grate")
        env = dict(os.environ, TDEM_LIGGGHTS=LIG, WORKDIR=grate, VTKOUT="0.05")  # bars every 0.05 s: frames
        t0 = time.time()
        r = subprocess.run(["sh", os.path.join(HERE, "validation", "grate", "run.sh"), "--short"], env=env,
                           capture_output=True, text=True)
        sys.stdout.write(r.stdout)
        if r.returncode != 0:
            sys.stderr.write(r.stderr[-3000:])
            raise SystemExit("showcase: the grate scenes failed")
        print("grate scenes: %.0f s; VTK files (bars and particles) and plots in %s" % (time.time() - t0, grate))
        render("grate", grate, "fwd3d", OUT, "--frames", "--title", "forward-acting grate, 3D (colour: depth D)")
        render("grate", grate, "fwd2d", OUT, "--title", "forward-acting grate, 2D (colour: depth D)")
        render("grate", grate, "rev3d", OUT, "--color", "speed", "--title", "reverse-acting grate, 3D (colour: speed)")
        prog.done("step 4 (grates)")
        print("\n== 5. Rigid clumps poured into a box, mpirun -np 2 (input_scripts/liggghts/clumps_pour.in) ==")
        first, last, secs, nbody, nsph, worst, top = clumps()
        if not worst < 1e-12:
            raise SystemExit("showcase: a clump did not stay rigid (a distance changed by %g m)" % worst)
        print("%d clumps (tetra-sphere and 3-sphere rods, %d spheres), %.0f s\n"
              "  thermo (step atoms KE_tetra KE_rods n_tetra n_rods) first: %s\n"
              "                                                        last:  %s\n"
              "  largest change of a distance inside a clump: %.1e m; highest sphere centre %.4f m; dumps in %s"
              % (nbody, nsph, secs, first.strip(), last.strip(), worst, top, os.path.join(OUT, "clumps")))
        render("dump", os.path.join(OUT, "clumps", "dump.clumps"), os.path.join(OUT, "clumps.png"), "--color", "body",
               "--title", "2000 clumps poured into a box (colour: body)")
        prog.done("step 5 (clumps)")
        print("\nOutput in %s; pictures: %s" % (OUT, ", ".join(sorted(f for f in os.listdir(OUT)
                                                                 if f.endswith((".png", ".gif"))))))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
