#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/clump (LAMMPS, issue 6): rigid multi-sphere clumps. One part per ctest case
(--part NAME):

  nve_single   single-sphere clumps (one body per sphere) reproduce fix nve/sphere in a scene with
               sphere-sphere and wall contacts with friction (1000 steps, positions to round-off)
  free_body    torque-free asymmetric body (explicit inertia I = 1, 2, 3), 1e5 steps with the splitting
               scheme: L bitwise constant, energy error bounded; body-frame angular momentum at t = 20
               vs an independent RK4 integration of Euler's equations
  flat_impact  flat-face impacts of clumps with N = 1, 2, 4, 8 coplanar spheres on a wall (fix
               tdem/wall/gran lsd restitution e t_c, no gravity, no friction): e and t_c vs the closed
               form of N parallel contacts (k -> N k, gamma -> N gamma; physics_reference 6.4)
  mpi          a few dozen tetra clumps poured onto a floor: -np 1 and -np 2 agree
  restart      run N + write_restart + read_restart + run M equals run N + run M
  insert       N clumps inserted: no overlap (with each other and with existing atoms), inside
               the region, sphere distances of the template, uniformly random orientations; -np 2
               creates the same spheres
  bad_input    errors name the keyword, the value and what is allowed
  ranks        local bodies (issue 20): a tetra pour and a pour of long rods (6 spheres, longer than
               a sub-domain at 8 ranks; the fix raises the ghost cutoff) on -np 1, 2, 4 and 8
               (oversubscribed): positions, velocities, spins and the fix's scalar, vector and
               array output bitwise equal; bodies whose spheres lie on several ranks, in contact;
               the rods with their local bodies rebuilt at every step equal the default run

Multiple-contact correction (fix tdem/clump ... correction none|count|overlap|local_mass):
  corr_flat        flat-face impacts, N = 2, 4, 8 spheres on a wall and a N = 4 body-body impact,
                   with 'count' and with 'overlap': e and t_c of the single-contact closed form
                   (<= 1e-3); without correction the N-contact closed form
  corr_continuity  a tilted row of 4 spheres hits the wall, contacts close one after another:
                   with 'overlap' the largest step-to-step change of the wall force is of the
                   order of the smooth change (vs the single-sphere impact), with 'count' the
                   jumps at closing contacts (of order F/N) are detected
  corr_local_mass  a tilted frictionless dimer hits the wall (and, through the pair style, a frozen
                   sphere) with one sphere: with 'local_mass' the normal velocity of the contact
                   point after/before equals the law's e, with 'none' it does not (m_loc < M), as
                   the closed form of m_loc predicts
  corr_stock       the correction with bodies of the stock fix rigid/small (fix tdem/correction): flat
                   faces N = 2, 4, 8 on the wall and N = 4 body-body, the closed forms as corr_flat; bad input
  corr_wide        the contact tally exchanged with the neighbouring ranks only: 8 slabs, bodies on
                   every boundary, -np 8 = -np 1 bitwise, single-contact e, two neighbours per rank
  corr_stock_local local_mass with rigid/small bodies: the tilted dimer of corr_local_mass (wall and
                   pair), the law's e and t_c at the contact point; -np 2 with the body split equals -np 1
  vtk              `vtk N prefix`: the bodies of a tetra pour as .vtu files and a .pvd series, read back
                   with the VTK library (python3-vtk9): every N steps at t = step*dt; the cells equal
                   the fix's array at the same steps (id, centre, orientation, velocity, angular
                   momentum, omega: bitwise); the points are the dumped spheres (unwrapped) with the
                   template radius, 4 per body, edge 0.003 and centroid = centre; -np 2 writes the same
                   files as -np 1; a run continued from a restart file extends the series, with the
                   times of the uninterrupted run
  corr_mpi         pour of tetra clumps with 'overlap', 'count' and 'local_mass': -np 2 equals -np 1;
                   newton on equals newton off (pairs with a ghost partner counted once); restart
                   with 'overlap' continues identically; correction none is bitwise the default
"""
import math
import os
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import tally_report  # noqa: E402

args = lc.parse_args(sys.argv)
part = args.get("part", "all")
chk = lc.Checker("lammps.clump." + part)
TDEM = args["tdem"]
MPIRUN = args["mpirun"]

DUMP = ("write_dump all custom {out} id mol x y z vx vy vz omegax omegay omegaz radius mass "
        "modify sort id format float %.17g\n")

# ----------------------------------------------------------------------------- 1. nve/sphere
SINGLE = """
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block 0 0.03 0 0.03 0 0.03
create_box 1 box
fix pm all property/atom mol ghost yes
lattice sc 0.0041
region fill block 0.003 0.027 0.003 0.027 0.003 0.015 units box
create_atoms 1 region fill
set group all diameter 0.004
set group all density 2500
variable m atom id
set group all mol v_m
variable vx atom 1.0*(random(0,1,13)-0.5)
variable vy atom 1.0*(random(0,1,17)-0.5)
variable vz atom 1.0*(random(0,1,19)-0.5)
velocity all set v_vx v_vy v_vz
neighbor 0.001 bin
neigh_modify delay 0
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution 0.7 1e-4 tangential cundall_strack 0.8 0.4
fix w0 all tdem/wall/gran normal lsd restitution 0.7 1e-4 tangential cundall_strack 0.8 0.4 zplane 0 0.03
fix w1 all tdem/wall/gran normal lsd restitution 0.7 1e-4 tangential cundall_strack 0.8 0.4 xplane 0 0.03
fix g all gravity 9.81 vector 0 0 -1
{integ}
timestep 2e-6
compute nc all contact/atom
compute snc all reduce sum c_nc
thermo_style custom step ke c_snc
thermo 100
run 1000
""" + DUMP


def part_nve_single():
    wd = lc.workdir("clump_single")
    _, out_n = lc.run(TDEM, SINGLE.format(integ="fix nve all nve/sphere", out="d.nve"), wd, "in.nve")
    lc.run(TDEM, SINGLE.format(integ="fix c all tdem/clump template s shape single 0.002 0 density 2500",
                               out="d.clump"), wd, "in.clump")
    cols, a = lc.read_dump(os.path.join(wd, "d.nve"))
    _, b = lc.read_dump(os.path.join(wd, "d.clump"))
    contacts = max(float(r.split()[2]) for r in lc.thermo_blocks(out_n)[1:])
    chk.check(contacts >= 20, "the scene has contacts (largest count of sphere contacts %d)" % contacts)
    for name in ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz", "mass"):
        k = cols.index(name)
        d = np.max(np.abs(a[:, k] - b[:, k])) / max(np.max(np.abs(a[:, k])), 1e-300)
        tol = 1e-13 if name in ("x", "y", "z", "mass") else 1e-10
        chk.check(d <= tol, "single-sphere clump vs nve/sphere after 1000 steps: %s max rel diff %.3g (<= %g)"
                  % (name, d, tol))
    moved = np.max(np.abs(a[:, cols.index("omegax")]))
    chk.check(moved > 1.0, "spins were produced by the contacts (max |omega_x| %.3g rad/s)" % moved)


# ----------------------------------------------------------------------------- 2. free body
# An L of three spheres in the xy plane with the intended body's mass properties given
# explicitly: M = 1, com at the origin, I = diag(1, 2, 3) (principal axes = template axes).
L_TEMPLATE = """# an L-shape, explicit mass properties
sphere  0.0 0.0 0.0 0.1
sphere  0.5 0.0 0.0 0.1
sphere  0.0 0.5 0.0 0.1
mass 1.0
com 0 0 0
inertia 1 2 3 0 0 0
"""
FREE = """
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block -5 5 -5 5 -5 5
create_box 1 box
fix pm all property/atom mol ghost yes
read_data body.data add append fix pm NULL Molecules
neigh_modify exclude molecule/intra all
# one free body, no contacts: a skin of 2 m keeps the list from being rebuilt every step (the
# default of LAMMPS since 2023 is delay 0) over a million 0.1 m bins
neighbor 2.0 bin
pair_style tdem/gran
pair_coeff * * normal lsd stiffness 1e3 0 tangential cundall_strack 100 0 0.5
fix c all tdem/clump template L file L.txt rotation {scheme}
timestep 0.01
thermo_style custom step f_c f_c[5] f_c[6] f_c[7] f_c[1][8] f_c[1][9] f_c[1][10] f_c[1][11]
thermo_modify format float %.17g
thermo {every}
run {n}
"""


def write_body_data(path, spheres, w):
    """Data file of one body (molecule 1) at rest in translation, spinning with omega w about
    the origin (the com): v_i = w x r_i, omega_i = w."""
    lines = ["LAMMPS data file: one clump", "", "%d atoms" % len(spheres), "1 atom types", "",
             "-5 5 xlo xhi", "-5 5 ylo yhi", "-5 5 zlo zhi", "", "Atoms # sphere", ""]
    for i, (x, r) in enumerate(spheres):
        lines.append("%d 1 %.17g 1000 %.17g %.17g %.17g" % (i + 1, 2 * r, x[0], x[1], x[2]))
    lines += ["", "Velocities", ""]
    for i, (x, r) in enumerate(spheres):
        v = np.cross(w, x)
        lines.append("%d %.17g %.17g %.17g %.17g %.17g %.17g" % (i + 1, v[0], v[1], v[2], w[0], w[1], w[2]))
    lines += ["", "Molecules", ""] + ["%d 1" % (i + 1) for i in range(len(spheres))]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def euler_rk4(I, pi0, t_end, h):
    """Body-frame angular momentum of the torque-free body: dpi/dt = pi x (I^-1 pi)."""
    I = np.asarray(I, float)

    def f(p):
        return np.cross(p, p / I)
    p = np.array(pi0, float)
    for _ in range(int(round(t_end / h))):
        k1 = f(p)
        k2 = f(p + 0.5 * h * k1)
        k3 = f(p + 0.5 * h * k2)
        k4 = f(p + h * k3)
        p = p + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    return p


def quat_matrix(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def part_free_body():
    wd = lc.workdir("clump_free")
    with open(os.path.join(wd, "L.txt"), "w") as f:
        f.write(L_TEMPLATE)
    # the template spheres relative to the explicit com (origin), unrotated
    spheres = [(np.array([0.0, 0.0, 0.0]), 0.1), (np.array([0.5, 0.0, 0.0]), 0.1), (np.array([0.0, 0.5, 0.0]), 0.1)]
    w0 = np.array([0.2, 1.0, 0.3])  # near the intermediate axis: the body tumbles (Dzhanibekov)
    write_body_data(os.path.join(wd, "body.data"), spheres, w0)
    I = np.array([1.0, 2.0, 3.0])
    L0 = I * w0
    E0 = 0.5 * np.sum(I * w0 ** 2)
    res = {}
    for scheme in ("splitting", "richardson", "explicit"):
        _, out = lc.run(TDEM, FREE.format(scheme=scheme, every=1000, n=100000), wd, "in.free_" + scheme)
        rows = np.array([[float(x) for x in r.split()] for r in lc.thermo_blocks(out)[1:]])
        E = rows[:, 1]
        L = rows[:, 2:5]
        res[scheme] = (np.max(np.abs(E - E0)) / E0, np.max(np.abs(L - L[0])) / np.linalg.norm(L0),
                       abs(E[-1] - E0) / E0, rows)
        print("%-10s 1e5 steps h = 0.01: max |E - E0|/E0 = %.3g (at the end %.3g), max |L - L(0)|/|L0| = %.3g"
              % (scheme, res[scheme][0], res[scheme][2], res[scheme][1]))
    ds, dl, _, rows = res["splitting"]
    chk.check(dl == 0.0, "splitting: angular momentum (space frame) bitwise constant over 1e5 steps (%.3g)" % dl)
    chk.check(ds <= 1e-5, "splitting: energy error bounded, max |dE/E| = %.3g over 1e5 steps (<= 1e-5)" % ds)
    chk.check(np.max(np.abs(rows[0, 2:5] - L0)) / np.linalg.norm(L0) < 1e-14,
              "initial angular momentum from the sphere velocities = I w (%s vs %s)" % (rows[0, 2:5], L0))
    chk.check(abs(rows[0, 1] - E0) / E0 < 1e-12,
              "initial kinetic energy from the sphere velocities = 1/2 w.I.w (rel %.3g)" % (abs(rows[0, 1] - E0) / E0))
    chk.check(res["explicit"][2] > 10 * ds, "explicit rotation drifts more than splitting (%.3g vs %.3g)"
              % (res["explicit"][2], ds))
    # dynamics: body-frame angular momentum at t = 20 (2000 steps) vs RK4 of Euler's equations
    _, out = lc.run(TDEM, FREE.format(scheme="splitting", every=2000, n=2000), wd, "in.free_t20")
    row = np.array([float(x) for x in lc.thermo_blocks(out)[-1].split()])
    q = row[5:9]
    pi_lmp = quat_matrix(q).T.dot(row[2:5])
    pi_ref = euler_rk4(I, L0, 20.0, 1e-3)
    err = np.max(np.abs(pi_lmp - pi_ref)) / np.linalg.norm(L0)
    moved = np.max(np.abs(pi_ref - L0)) / np.linalg.norm(L0)
    print("t = 20: body-frame L (LAMMPS) %s, Euler RK4 %s" % (pi_lmp, pi_ref))
    chk.check(moved > 0.1, "the body tumbles (body-frame L changed by %.3g of |L|)" % moved)
    chk.check(err <= 2e-3, "body-frame angular momentum at t = 20 vs RK4 of Euler's equations: %.3g (<= 2e-3)" % err)


# ----------------------------------------------------------------------------- 3. flat impacts
IMPACT = """
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 0 0.05
create_box 1 box
fix pm all property/atom mol ghost yes
read_data body.data add append fix pm NULL Molecules
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution 0.8 1e-4 tangential cundall_strack 0.8 0
fix c all tdem/clump template flat file flat.txt density 2500
fix w all tdem/wall/gran normal lsd restitution {e} {tc} tangential cundall_strack 0.8 0 zplane 0 NULL
timestep {dt}
thermo_style custom step f_c[1][4] f_c[1][7]
thermo_modify format float %.17g
thermo 1
run {n}
"""


def flat_template(n, r, d):
    """n coplanar spheres (z = 0): 1, 2 (1x2), 4 (2x2), 8 (2x4)."""
    nx, ny = {1: (1, 1), 2: (2, 1), 4: (2, 2), 8: (4, 2)}[n]
    return [np.array([(i - 0.5 * (nx - 1)) * d, (j - 0.5 * (ny - 1)) * d, 0.0]) for j in range(ny) for i in range(nx)]


def closed_form_n(e, tc, n):
    """LSD, zero-overlap end: single contact (e, tc) with the body mass -> N parallel contacts."""
    a = -math.log(e) / math.pi          # beta / sqrt(1 - beta^2)
    beta = a / math.sqrt(1 + a * a)
    w0 = math.pi / tc / math.sqrt(1 - beta * beta)
    bn, wn = math.sqrt(n) * beta, math.sqrt(n) * w0
    return math.exp(-math.pi * bn / math.sqrt(1 - bn * bn)), math.pi / (wn * math.sqrt(1 - bn * bn))


def part_flat_impact():
    wd = lc.workdir("clump_flat")
    e, tc, r, d, v0 = 0.8, 1e-4, 0.002, 0.0045, 1.0
    dt = tc / 4000
    z0 = r + 2e-6  # 2 microseconds of free flight before the contact
    for n in (1, 2, 4, 8):
        pts = flat_template(n, r, d)
        with open(os.path.join(wd, "flat.txt"), "w") as f:
            f.write("".join("sphere %.17g %.17g %.17g %.17g\n" % (p[0], p[1], p[2], r) for p in pts))
        lines = ["one flat clump", "", "%d atoms" % n, "1 atom types", "", "-0.05 0.05 xlo xhi",
                 "-0.05 0.05 ylo yhi", "0 0.05 zlo zhi", "", "Atoms # sphere", ""]
        for i, p in enumerate(pts):
            lines.append("%d 1 %.17g 2500 %.17g %.17g %.17g" % (i + 1, 2 * r, p[0], p[1], p[2] + z0))
        lines += ["", "Velocities", ""] + ["%d 0 0 %.17g 0 0 0" % (i + 1, -v0) for i in range(n)]
        lines += ["", "Molecules", ""] + ["%d 1" % (i + 1) for i in range(n)]
        with open(os.path.join(wd, "body.data"), "w") as f:
            f.write("\n".join(lines) + "\n")
        e_ref, t_ref = closed_form_n(e, tc, n)
        nsteps = int((2e-6 + 1.3 * t_ref) / dt) + 200
        _, out = lc.run(TDEM, IMPACT.format(e=e, tc=tc, dt=dt, n=nsteps), wd, "in.flat%d" % n)
        rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
        t = rows[:, 0] * dt
        xi = r - rows[:, 1]  # overlap of every sphere (coplanar with the com)
        vz = rows[:, 2]
        on = np.where(xi > 0)[0]
        i0, i1 = on[0], on[-1]
        # linear interpolation of the zero crossings of the overlap
        ts = t[i0 - 1] + (0 - xi[i0 - 1]) / (xi[i0] - xi[i0 - 1]) * dt
        te = t[i1] + (0 - xi[i1]) / (xi[i1 + 1] - xi[i1]) * dt
        e_m = vz[-1] / v0
        t_m = te - ts
        print("N = %d: e %.6f (closed form %.6f), t_c %.6e s (closed form %.6e s)" % (n, e_m, e_ref, t_m, t_ref))
        chk.check(abs(e_m - e_ref) / e_ref <= 1e-3 and abs(t_m - t_ref) / t_ref <= 1e-3,
                  "N = %d flat-face impact: e rel err %.2g, t_c rel err %.2g vs the N-contact closed form (<= 1e-3)"
                  % (n, abs(e_m - e_ref) / e_ref, abs(t_m - t_ref) / t_ref))
        if n > 1:
            chk.check(abs(e_m - e) > 0.01, "N = %d differs from the single-contact e %.2f (%.4f)" % (n, e, e_m))


# ----------------------------------------------------------------------------- 4./5. pour
# the interactions of the pours (POUR, RANKS): lsd + Cundall-Strack between spheres and with the floor
POUR_LAWS = """neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4
fix floor all tdem/wall/gran normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4 zplane 0 NULL
fix g all gravity 9.81 vector 0 0 -1
timestep 5e-6
compute nc all contact/atom
"""
POUR = """
units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
atom_modify map array
region box block 0 0.025 0 0.025 0 0.08
create_box 1 box
fix pm all property/atom mol ghost yes
region ins block 0.0 0.025 0.0 0.025 0.003 0.05
fix c all tdem/clump template tet shape tetra 0.002 0.003 density 2500 insert 40 region ins seed 4711 vel 0 0 -1
""" + POUR_LAWS + """
compute snc all reduce sum c_nc
thermo_style custom step atoms f_c f_c[1] c_snc
thermo_modify format float %.15g
thermo 200
"""
POUR_RESTART = """
units si
atom_style sphere
atom_modify map array
newton off
read_restart pour.restart
fix pm all property/atom mol ghost yes
comm_modify vel yes
neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
fix c all tdem/clump template tet shape tetra 0.002 0.003 density 2500 insert 40 region ins seed 4711 vel 0 0 -1
fix floor all tdem/wall/gran normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4 zplane 0 NULL
fix g all gravity 9.81 vector 0 0 -1
timestep 5e-6
thermo_style custom step atoms f_c f_c[1]
thermo_modify format float %.15g
thermo 1000
run {m}
""" + DUMP


def body_rows(path):
    cols, a = lc.read_dump(path)
    return cols, a


def part_mpi():
    wd = lc.workdir("clump_mpi")
    text = POUR + "run 10000\n" + DUMP.format(out="d.np{np}")
    _, o1 = lc.run(TDEM, text.format(np=1), wd, "in.np1")
    _, o2 = lc.run(TDEM, text.format(np=2), wd, "in.np2", np_=2, mpirun=MPIRUN)
    cols, a = lc.read_dump(os.path.join(wd, "d.np1"))
    _, b = lc.read_dump(os.path.join(wd, "d.np2"))
    contacts = max(float(r.split()[4]) for r in lc.thermo_blocks(o1)[1:])
    chk.check(contacts >= 10, "the pour has contacts (largest sphere contact count %d)" % contacts)
    chk.check(a.shape == b.shape and a.shape[0] == 160, "160 spheres on 1 and on 2 ranks")
    per, worst = lc.rel_diff(b[:, 2:12], a[:, 2:12])
    print("np 1 vs np 2: max relative difference per column (x y z vx vy vz wx wy wz) %s" % per)
    chk.check(worst <= 1e-8, "-np 2 equals -np 1 after 10000 steps of pouring (max rel diff %.3g <= 1e-8)" % worst)
    # the clumps stayed rigid: distances inside each clump equal the tetra edge 0.003
    x = a[:, 2:5]
    dmax = 0.0
    for m in np.unique(a[:, 1]):
        p = x[a[:, 1] == m]
        for i in range(4):
            for j in range(i + 1, 4):
                dd = p[i] - p[j]
                dd[:2] -= 0.025 * np.round(dd[:2] / 0.025)  # periodic in x and y
                dmax = max(dmax, abs(np.linalg.norm(dd) - 0.003))
    chk.check(dmax <= 1e-12, "clumps stay rigid: sphere distances = edge to %.3g m" % dmax)
    fell = np.max(x[:, 2])
    chk.check(np.min(x[:, 2]) < 0.002 + 1e-6, "clumps touch the floor (lowest sphere at %.5f m)" % np.min(x[:, 2]))
    chk.check(fell < 0.05, "the clumps fell (highest sphere at %.4f m)" % fell)


def part_vtk():
    import vtk_read as vr
    every, nsteps, dt = 500, 2000, 5e-6
    # the fix's array (variable length: not for fix ave/time) as thermo columns, 40 bodies x 17
    cols = " ".join("f_c[%d][%d]" % (i, j) for i in range(1, 41) for j in range(1, 18))
    out = "thermo_style custom step %s\nthermo_modify format float %%.17g\nthermo %d\n" % (cols, every)
    text = POUR.replace("vel 0 0 -1\n", "vel 0 0 -1 vtk %d out/bodies\n" % every) + out
    res = {}
    for np_ in (1, 2):
        wd = lc.workdir("clump_vtk_np%d" % np_)
        os.makedirs(os.path.join(wd, "out"), exist_ok=True)
        _, o = lc.run(TDEM, text + "run %d\n" % nsteps + DUMP.format(out="d.end"), wd, "in.vtk", np_=np_,
                      mpirun=MPIRUN)
        series = vr.read_pvd(os.path.join(wd, "out", "bodies.pvd"))
        res[np_] = (wd, series, o)
    wd, series, o1 = res[1]
    steps = list(range(0, nsteps + 1, every))
    chk.check([os.path.basename(f) for _, f in series] == ["bodies_%d.vtu" % k for k in steps] and
              all(abs(t - k * dt) <= 1e-18 for (t, _), k in zip(series, steps)),
              "bodies.pvd lists %d files, every %d steps, at t = step*dt" % (len(series), every))
    # the fix's array at the same steps
    blocks = {}
    for r in lc.thermo_blocks(o1)[1:]:
        w = r.split()
        blocks[int(w[0])] = np.array([float(v) for v in w[1:]]).reshape(40, 17)
    worst_cell = 0.0
    names = [("id", [0]), ("centre", [1, 2, 3]), ("velocity", [4, 5, 6]), ("orientation", [7, 8, 9, 10]),
             ("angular_momentum", [11, 12, 13]), ("omega", [14, 15, 16])]
    compared = 0
    for (t, f), k in zip(series, steps):
        d = vr.read_dataset(f)
        chk.check(d["time"] == k * dt if k else d["time"] == 0.0, "step %d: TimeValue %.17g = step*dt" % (k, d["time"]))
        if k in blocks:
            a = blocks[k]
            for name, js in names:
                v = d["cell"][name].reshape(len(a), -1)
                worst_cell = max(worst_cell, float(np.abs(v - a[:, js]).max()))
            compared += 1
    chk.check(compared == len(steps) and worst_cell == 0.0,
              "the cells equal the fix's array at %d steps: max difference %.3g" % (compared, worst_cell))
    # the last file against the dumped spheres (periodic x, y: unwrapped by the minimum image)
    d = vr.read_dataset(series[-1][1])
    cols_, a = lc.read_dump(os.path.join(wd, "d.end"))
    x = d["points"]
    chk.check(len(d["cells"]) == 40 and all(len(c) == 4 for c in d["cells"]) and set(d["types"]) == {2},
              "40 poly-vertex cells of 4 points (%d cells)" % len(d["cells"]))
    chk.check(np.all(d["point"]["radius"] == 0.002), "point radius = template radius 0.002")
    worst_p = edge = cen = 0.0
    for c, mol in zip(d["cells"], d["cell"]["id"]):
        p = x[c]
        chk_mol = np.all(d["point"]["body"][c] == mol)
        if not chk_mol:
            chk.check(False, "body %d: point data 'body' names the cell's id" % mol)
        s = a[a[:, 1] == mol][:, 2:5]
        for q in p:
            dd = s - q
            dd[:, :2] -= 0.025 * np.round(dd[:, :2] / 0.025)
            worst_p = max(worst_p, float(np.min(np.linalg.norm(dd, axis=1))))
        for i in range(4):
            for j in range(i + 1, 4):
                edge = max(edge, abs(np.linalg.norm(p[i] - p[j]) - 0.003))
        cen = max(cen, float(np.abs(p.mean(axis=0) - d["cell"]["centre"][list(d["cell"]["id"]).index(mol)]).max()))
    print("last file: points vs dumped spheres %.3g m, edge error %.3g m, centroid vs centre %.3g m"
          % (worst_p, edge, cen))
    chk.check(worst_p <= 1e-15, "every point is a dumped sphere centre (%.3g m)" % worst_p)
    chk.check(edge <= 1e-15 and cen <= 1e-15, "rigid tetra of edge 0.003 around its centre")
    # -np 2 writes the same files
    s2 = res[2][1]
    same = len(s2) == len(series)
    for (t1, f1), (t2, f2) in zip(series, s2):
        d1, d2 = vr.read_dataset(f1), vr.read_dataset(f2)
        same = same and t1 == t2 and np.array_equal(d1["points"], d2["points"])
        for name, _ in names:
            same = same and np.array_equal(d1["cell"][name], d2["cell"][name])
    chk.check(same, "-np 2 writes the same %d files as -np 1 (bitwise)" % len(s2))
    # restart: run 1000 + write_restart, then read_restart + run 1000 in the same directory; the
    # reference is the writing process continuing after write_restart (as part restart)
    wd = lc.workdir("clump_vtk_restart")
    ref = lc.workdir("clump_vtk_restart_ref")
    for w in (wd, ref):
        os.makedirs(os.path.join(w, "out"), exist_ok=True)
    lc.run(TDEM, text + "run 1000\nwrite_restart pour.restart\n", wd, "in.a")
    lc.run(TDEM, text + "run 1000\nwrite_restart pour.restart\nrun 1000\n", ref, "in.a")
    series = vr.read_pvd(os.path.join(ref, "out", "bodies.pvd"))
    rtext = POUR_RESTART.replace("vel 0 0 -1\n", "vel 0 0 -1 vtk %d out/bodies\n" % every).format(m=1000, out="d.r")
    lc.run(TDEM, rtext, wd, "in.b")
    s3 = vr.read_pvd(os.path.join(wd, "out", "bodies.pvd"))
    ok = [os.path.basename(f) for _, f in s3] == ["bodies_%d.vtu" % k for k in steps]
    worst = 0.0
    for (t1, f1), (t3, f3) in zip(series, s3):
        d1, d3 = vr.read_dataset(f1), vr.read_dataset(f3)
        ok = ok and d3["time"] == t3
        worst = max(worst, lc.rel_diff(d3["cell"]["centre"], d1["cell"]["centre"])[1])
    # not bitwise: read_restart rebuilds the neighbour lists (part restart: 1e-10)
    chk.check(ok and worst <= 1e-10, "after read_restart the series continues: %d files, centres equal to the "
              "writing process's continued run to %.3g" % (len(s3), worst))
    # the fix keeps its own clock in the restart record: LAMMPS before 2022-05 (Debian 12's) restarts
    # its clock at 0 after read_restart (LAMMPS issue 3096)
    print("series after the restart: times %s" % [t for t, _ in s3])
    chk.check(all(abs(a - b) <= 1e-15 * b for (a, _), (b, _) in zip(s3, series)),
              "the times of the continued series are the uninterrupted run's")


def part_restart():
    wd = lc.workdir("clump_restart")
    # The reference is the process that wrote the restart file and went on: `run 6000; write_restart;
    # run 600`. Not `run 6000; run 600`: LAMMPS itself (stock gran/hooke/history + fix wall/gran with
    # nve/sphere, 2022 and 4Jul2026 alike) does not continue a granular pile identically across a
    # `run` boundary (measured on this pile: 2.5e-2 after one step; 1e-6 with reneighbouring every
    # step), so that comparison depends on the pile. (600 steps: later, the different order of the
    # atoms after read_restart changes the order of the per-atom sums at round-off level, and the
    # dense pile amplifies it.)
    first = POUR + "run 6000\nwrite_restart pour.restart\nrun 600\n" + DUMP.format(out="d.full")
    lc.run(TDEM, first, wd, "in.first", np_=2, mpirun=MPIRUN)
    _, out = lc.run(TDEM, POUR_RESTART.format(m=600, out="d.rest"), wd, "in.rest", np_=2, mpirun=MPIRUN)
    chk.check("'insert' is skipped" in out, "the restarted fix does not insert again")
    cols, a = lc.read_dump(os.path.join(wd, "d.full"))
    _, b = lc.read_dump(os.path.join(wd, "d.rest"))
    chk.check(a.shape == b.shape, "same spheres after the restart (%s vs %s)" % (a.shape, b.shape))
    per, worst = lc.rel_diff(b[:, 2:12], a[:, 2:12])
    print("restart: max relative difference per column %s (%d values differ)" % (per, int((a != b).sum())))
    chk.check(worst <= 1e-10, "read_restart + run 600 equals the writing process's run 600 after write_restart "
              "(%.3g <= 1e-10)" % worst)
    # control: the same restart with the contact history of the pair style dropped
    lost = POUR_RESTART.replace("fix floor all", "pair_style none\npair_style tdem/gran\npair_coeff * * normal "
                                "lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4\nfix floor all")
    lost = lost.format(m=600, out="d.lost")
    lc.run(TDEM, lost, wd, "in.lost", np_=2, mpirun=MPIRUN)
    _, c = lc.read_dump(os.path.join(wd, "d.lost"))
    _, worst_lost = lc.rel_diff(c[:, 2:12], a[:, 2:12])
    chk.check(worst_lost > 1e-6, "control: dropping the pair contact history changes the result (%.3g)" % worst_lost)
    # a restart file of the global-bodies version (every body in the fix's global record; tdem before
    # issue 20, commit 0fa3e78, at step 3000 of POUR on one rank: data/clump_global/pour_3000.restart):
    # its bodies reach their spheres at the set-up; read on 2 ranks and continued, it equals this
    # build's own run 3000 + write_restart + run 600
    legacy = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "clump_global", "pour_3000.restart")
    shutil.copy(legacy, os.path.join(wd, "legacy.restart"))
    own = POUR + "run 3000\nwrite_restart own.restart\nrun 600\n" + DUMP.format(out="d.own")
    lc.run(TDEM, own, wd, "in.own")
    _, out = lc.run(TDEM, POUR_RESTART.replace("pour.restart", "legacy.restart").format(m=600, out="d.legacy"), wd,
                    "in.legacy", np_=2, mpirun=MPIRUN)
    _, a = lc.read_dump(os.path.join(wd, "d.own"))
    _, b = lc.read_dump(os.path.join(wd, "d.legacy"))
    per, worst = lc.rel_diff(b[:, 2:12], a[:, 2:12])
    chk.check(a.shape == b.shape and worst <= 1e-10 and "'insert' is skipped" in out,
              "a restart file of the global-bodies version, read on 2 ranks + run 600, equals this build's own "
              "run 3000 + write_restart + run 600 (%.3g <= 1e-10)" % worst)


# ----------------------------------------------------------------------------- 6. insertion
INSERT = """
units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
region box block 0 0.05 0 0.05 0 0.05
create_box 2 box
fix pm all property/atom mol ghost yes
# existing atoms in the region: a coarse lattice of type 2 spheres
lattice sc 0.01
region old block 0.005 0.045 0.005 0.045 0.005 0.045 units box
create_atoms 2 region old
set type 2 diameter 0.003
set type 2 density 2500
group old type 2
region ins block 0.0 0.05 0.0 0.05 0.002 0.048 units box
fix c all tdem/clump template tet shape tetra 0.0015 0.0025 density 2500 insert {n} region ins seed 99 type 1 vel 0.1 0 0
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4
fix fr old freeze
timestep 1e-6
run 0
write_dump all custom d.ins{np} id mol type x y z vx vy vz radius mass modify sort id format float %.17g
"""


def part_insert():
    wd = lc.workdir("clump_insert")
    n = 300
    _, out = lc.run(TDEM, INSERT.format(n=n, np=1), wd, "in.ins1")
    lc.run(TDEM, INSERT.format(n=n, np=2), wd, "in.ins2", np_=2, mpirun=MPIRUN)
    cols, a = lc.read_dump(os.path.join(wd, "d.ins1"))
    _, b = lc.read_dump(os.path.join(wd, "d.ins2"))
    chk.check(a.shape == b.shape and np.array_equal(a, b), "-np 2 creates the same spheres as -np 1 (bitwise)")
    typ = a[:, cols.index("type")]
    new = a[typ == 1]
    old = a[typ == 2]
    x = new[:, 3:6]
    L = 0.05
    chk.check(new.shape[0] == 4 * n and len(np.unique(new[:, 1])) == n,
              "%d clumps of 4 spheres with distinct molecule IDs (%d spheres)" % (n, new.shape[0]))
    chk.check(np.all(new[:, cols.index("radius")] == 0.0015), "sphere radius from the template")
    # mass: tetra spheres d = 2.5 mm < 2 r = 3 mm overlap, so each sphere has 1/4 of the union mass,
    # less than a full sphere and more than 1/4 of... bounds from the geometry
    m = new[:, cols.index("mass")]
    msphere = 4.0 / 3.0 * math.pi * 0.0015 ** 3 * 2500
    chk.check(np.all(m < msphere) and np.all(m > 0.7 * msphere) and np.ptp(m) == 0,
              "sphere mass = 1/4 of the union mass: %.4g (a full sphere %.4g)" % (m[0], msphere))
    # inside the region (z: [0.002, 0.048] with the sphere extent; x, y periodic)
    zlo, zhi = np.min(x[:, 2] - 0.0015), np.max(x[:, 2] + 0.0015)
    chk.check(zlo >= 0.002 and zhi <= 0.048, "every sphere inside the region (z extent %.5f .. %.5f)" % (zlo, zhi))
    # no overlap: between clumps, and with the existing atoms (minimum image in x and y)
    allx = np.vstack([x, old[:, 3:6]])
    allr = np.concatenate([new[:, cols.index("radius")], old[:, cols.index("radius")]])
    mol = np.concatenate([new[:, 1], -1 - np.arange(old.shape[0])])
    worst = np.inf
    for i in range(x.shape[0]):
        d = allx - x[i]
        d[:, :2] -= L * np.round(d[:, :2] / L)
        dist = np.sqrt(np.sum(d * d, axis=1))
        other = mol != mol[i]
        gap = dist[other] - (allr[other] + allr[i])
        worst = min(worst, np.min(gap))
    chk.check(worst >= 0.0, "no overlap between clumps or with the %d existing atoms (smallest gap %.3g m)"
              % (old.shape[0], worst))
    # rigid template: the 6 distances in each clump equal the edge 0.0025
    dev = 0.0
    dirs = []
    for mm in np.unique(new[:, 1]):
        p = x[new[:, 1] == mm]
        for i in range(4):
            for j in range(i + 1, 4):
                dev = max(dev, abs(np.linalg.norm(p[i] - p[j]) - 0.0025))
        u = p[0] - p.mean(axis=0)
        dirs.append(u / np.linalg.norm(u))
    chk.check(dev <= 1e-15, "sphere distances of the template (edge) to %.3g m" % dev)
    dirs = np.array(dirs)
    mean = np.linalg.norm(dirs.mean(axis=0))
    zz = np.mean(dirs[:, 2] ** 2)
    xx = np.mean(dirs[:, 0] ** 2)
    print("orientation spread: |mean of a body axis| %.3f (uniform: ~%.3f), <u_z^2> %.3f, <u_x^2> %.3f (uniform 1/3)"
          % (mean, 1 / math.sqrt(n), zz, xx))
    chk.check(mean < 4 / math.sqrt(n) and abs(zz - 1 / 3) < 0.06 and abs(xx - 1 / 3) < 0.06,
              "random orientations: uniform on the sphere within 4 sigma")
    v = new[:, cols.index("vx")]
    chk.check(np.all(v == 0.1), "initial velocity from 'vel'")


# ----------------------------------------------------------------------------- 7. bad input
BAD_BASE = """
units si
atom_style sphere
boundary f f f
comm_modify vel yes
region box block 0 0.05 0 0.05 0 0.05
create_box 1 box
{pm}
region ins block 0.01 0.04 0.01 0.04 0.01 0.04
create_atoms 1 single 0.025 0.025 0.025
set group all diameter 0.004
set group all density 2500
{setmol}
pair_style tdem/gran
pair_coeff * * normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4
{fix}
timestep 1e-6
run 1
"""
PM = "fix pm all property/atom mol ghost yes"


def part_bad_input():
    wd = lc.workdir("clump_bad")
    with open(os.path.join(wd, "bad.txt"), "w") as f:
        f.write("sphere 0 0 0 0.002\ncolor red\n")
    with open(os.path.join(wd, "two.txt"), "w") as f:
        f.write("sphere 0 0 0 0.002\nsphere 0.005 0 0 0.002\n")
    cases = [
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500", "", "property/atom mol"),
        ("fix c all tdem/clump template s shape blob 0.002 0 density 2500", PM, "shape 'blob' is unknown; allowed"),
        ("fix c all tdem/clump template s shape single -0.002 0 density 2500", PM, "radius r = -0.002"),
        ("fix c all tdem/clump template s shape single 0.002 0", PM, "missing keyword 'density RHO'"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 rotation leapfrog", PM,
         "rotation 'leapfrog' is unknown; allowed: splitting, explicit, richardson"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 integration exact", PM,
         "integration 'exact' is unknown; allowed: columns, voxel, monte_carlo"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 resolution 2", PM,
         "'resolution': value '2' is not an integer in [4, 4096]"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 colour red", PM,
         "unknown keyword 'colour'; allowed"),
        ("fix c all tdem/clump shape single 0.002 0 density 2500", PM, "missing keyword 'template NAME'"),
        ("fix c all tdem/clump template s file bad.txt density 2500", PM, "unknown keyword 'color'"),
        ("fix c all tdem/clump template s file nothere.txt density 2500", PM, "cannot be opened"),
        ("fix c all tdem/clump template s file two.txt density 2500", PM, "molecule 1 has 1 spheres in group all"),
        ("fix c all tdem/clump template s shape single 0.003 0 density 2500", PM,
         "has radius 0.002 but sphere 1 of template s has radius 0.003"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 insert 10 region nowhere seed 1", PM,
         "insert region 'nowhere' does not exist"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 insert 10 region ins seed -3", PM,
         "'insert seed': value '-3' is not an integer"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 insert 100000 region ins seed 5", PM,
         "insert: placed only"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 bodies atoms", PM,
         "bodies 'atoms' is unknown; allowed: molecule"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 correction half", PM,
         "correction 'half' is unknown; allowed: none, count, overlap, local_mass"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 correction", PM,
         "keyword 'correction' needs a value (none, count, overlap, local_mass)"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500\nfix n all nve/sphere", PM,
         "also integrates clump spheres"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 vtk 0 b", PM,
         "'vtk': value '0' is not an integer in [1, 2147483647]"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 vtk 10", PM,
         "keyword 'vtk' needs N prefix"),
        ("fix c all tdem/clump template s shape single 0.002 0 density 2500 vtk 10 /nonexistent-dir/b", PM,
         "cannot write the VTK file '/nonexistent-dir/b_0.vtu': the directory '/nonexistent-dir' does not exist"),
    ]
    for fix, pm, expect in cases:
        rc, out = lc.run(TDEM, BAD_BASE.format(pm=pm, fix=fix, setmol="set group all mol 1" if pm else ""), wd, "in.bad", check=False, timeout=120)
        err = [l for l in out.splitlines() if "ERROR" in l]
        ok = rc != 0 and rc < 128 and err and expect in " ".join(err)
        chk.check(bool(ok), "%-60s -> %s" % (fix.replace("\n", " | ")[:60], err[0][:150] if err else "no error (rc %d)" % rc))
    rc, out = lc.run(TDEM, BAD_BASE.format(pm=PM, setmol="set group all mol 1", fix="fix c all tdem/clump template s shape single 0.002 0 "
                                           "density 2500"), wd, "in.good", check=False)
    chk.check(rc == 0, "control: the good input runs (rc %d)" % rc)
    # a clump of several spheres without 'neigh_modify exclude molecule/intra': a warning
    rc, out = lc.run(TDEM, BAD_BASE.format(pm=PM, setmol="", fix="fix c all tdem/clump template t shape tetra 0.002 "
                                           "0.003 density 2500 insert 2 region ins seed 3"), wd, "in.warn", check=False)
    warn = [l for l in out.splitlines() if "WARNING" in l and "tdem/clump" in l]
    chk.check(rc == 0 and warn and "neigh_modify exclude molecule/intra all" in warn[0],
              "missing intra-clump exclusion -> %s" % (warn[0][:140] if warn else "no warning (rc %d)" % rc))


# ----------------------------------------------------------------------------- 8. correction
def write_flat(wd, n, r, d, bodies):
    """Template flat.txt (n coplanar spheres) and body.data: bodies = [(z of the com, vz), ...]."""
    pts = flat_template(n, r, d)
    with open(os.path.join(wd, "flat.txt"), "w") as f:
        f.write("".join("sphere %.17g %.17g %.17g %.17g\n" % (p[0], p[1], p[2], r) for p in pts))
    lines = ["flat clumps", "", "%d atoms" % (n * len(bodies)), "1 atom types", "", "-0.05 0.05 xlo xhi",
             "-0.05 0.05 ylo yhi", "0 0.05 zlo zhi", "", "Atoms # sphere", ""]
    vel, mol = [], []
    k = 0
    for b, (z, vz) in enumerate(bodies):
        for p in pts:
            k += 1
            lines.append("%d 1 %.17g 2500 %.17g %.17g %.17g" % (k, 2 * r, p[0], p[1], p[2] + z))
            vel.append("%d 0 0 %.17g 0 0 0" % (k, vz))
            mol.append("%d %d" % (k, b + 1))
    lines += ["", "Velocities", ""] + vel + ["", "Molecules", ""] + mol
    with open(os.path.join(wd, "body.data"), "w") as f:
        f.write("\n".join(lines) + "\n")


CORR_IMPACT = """
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 0 0.05
create_box 1 box
fix pm all property/atom mol ghost yes
read_data body.data add append fix pm NULL Molecules
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution {e} {tc} tangential cundall_strack 0.8 0
fix c all tdem/clump template flat file flat.txt density 2500 {corr}
{wall}
timestep {dt}
variable fz equal fcm(all,z)
thermo_style custom step f_c[1][4] f_c[1][7] {more} v_fz
thermo_modify format float %.17g
thermo 1
run {n}
"""


def crossing(t, xi, dt):
    """Start and end time of the (first) positive stretch of xi, by linear interpolation."""
    on = np.where(xi > 0)[0]
    i0 = on[0]
    gaps = np.where(np.diff(on) > 1)[0]
    i1 = on[gaps[0]] if len(gaps) else on[-1]
    ts = t[i0 - 1] + (0 - xi[i0 - 1]) / (xi[i0] - xi[i0 - 1]) * dt
    te = t[i1] + (0 - xi[i1]) / (xi[i1 + 1] - xi[i1]) * dt
    return ts, te, i0, i1


def part_corr_flat():
    wd = lc.workdir("clump_corr_flat")
    e, tc, r, d, v0 = 0.8, 1e-4, 0.002, 0.0045, 1.0
    dt = tc / 4000
    z0 = r + 2e-6
    wall = "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL" % (e, tc)
    for corr in ("none", "count", "overlap"):
        for n in (2, 4, 8):
            write_flat(wd, n, r, d, [(z0, -v0)])
            e_n, t_n = closed_form_n(e, tc, n)
            e_ref, t_ref = (e_n, t_n) if corr == "none" else (e, tc)
            nsteps = int((2e-6 + 1.3 * max(t_ref, tc)) / dt) + 200
            _, out = lc.run(TDEM, CORR_IMPACT.format(e=0.5, tc=tc, corr="correction " + corr, wall=wall, dt=dt,
                                                    more="", n=nsteps), wd, "in.w%s%d" % (corr, n))
            rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
            t = rows[:, 0] * dt
            ts, te, _, _ = crossing(t, r - rows[:, 1], dt)
            e_m, t_m = rows[-1, 2] / v0, te - ts
            ee, et = abs(e_m - e_ref) / e_ref, abs(t_m - t_ref) / t_ref
            print("wall, correction %-7s N = %d: e %.6f t_c %.6e s; reference (%s) e %.6f t_c %.6e s: "
                  "rel err %.2g %.2g" % (corr, n, e_m, t_m, "N contacts" if corr == "none" else "single contact",
                                         e_ref, t_ref, ee, et))
            chk.check(ee <= 1e-3 and et <= 1e-3, "wall N = %d, correction %s: e, t_c vs the %s closed form: rel err "
                      "%.2g, %.2g (<= 1e-3)" % (n, corr, "N-contact" if corr == "none" else "single-contact", ee, et))
    # body-body: two N = 4 clumps face to face (pair tdem/gran), m* = M/2
    n = 4
    for corr in ("none", "count", "overlap"):
        za = 0.01
        write_flat(wd, n, r, d, [(za, 0.5 * v0), (za + 2 * r + 2e-6, -0.5 * v0)])
        e_n, t_n = closed_form_n(e, tc, n)
        e_ref, t_ref = (e_n, t_n) if corr == "none" else (e, tc)
        nsteps = int((1e-6 + 1.3 * max(t_ref, tc)) / dt) + 200
        _, out = lc.run(TDEM, CORR_IMPACT.format(e=e, tc=tc, corr="correction " + corr, wall="", dt=dt,
                                                more="f_c[2][4] f_c[2][7]", n=nsteps), wd, "in.b%s" % corr)
        rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
        t = rows[:, 0] * dt
        ts, te, _, _ = crossing(t, 2 * r - (rows[:, 3] - rows[:, 1]), dt)
        e_m, t_m = (rows[-1, 4] - rows[-1, 2]) / v0, te - ts
        ee, et = abs(e_m - e_ref) / e_ref, abs(t_m - t_ref) / t_ref
        print("body-body, correction %-7s N = 4: e %.6f t_c %.6e s; reference e %.6f t_c %.6e s: rel err %.2g %.2g"
              % (corr, e_m, t_m, e_ref, t_ref, ee, et))
        chk.check(ee <= 1e-3 and et <= 1e-3, "body-body N = 4, correction %s: e, t_c vs the %s closed form: rel err "
                  "%.2g, %.2g (<= 1e-3)" % (corr, "N-contact" if corr == "none" else "single-contact", ee, et))


def write_row(wd, n, r, d, zlow, theta, v0):
    """A row of n spheres along x (template row.txt), tilted by theta about y so that the sphere at
    -x is lowest (its centre at zlow), translating with vz = -v0."""
    xs = [(k - 0.5 * (n - 1)) * d for k in range(n)]
    with open(os.path.join(wd, "row.txt"), "w") as f:
        f.write("".join("sphere %.17g 0 0 %.17g\n" % (x, r) for x in xs))
    c, sn = math.cos(theta), math.sin(theta)
    zc = zlow + xs[-1] * sn
    lines = ["tilted row", "", "%d atoms" % n, "1 atom types", "", "-0.05 0.05 xlo xhi", "-0.05 0.05 ylo yhi",
             "0 0.05 zlo zhi", "", "Atoms # sphere", ""]
    for k, x in enumerate(xs):
        lines.append("%d 1 %.17g 2500 %.17g 0 %.17g" % (k + 1, 2 * r, x * c, zc + x * sn))
    lines += ["", "Velocities", ""] + ["%d 0 0 %.17g 0 0 0" % (k + 1, -v0) for k in range(n)]
    lines += ["", "Molecules", ""] + ["%d 1" % (k + 1) for k in range(n)]
    with open(os.path.join(wd, "body.data"), "w") as f:
        f.write("\n".join(lines) + "\n")


ROW = CORR_IMPACT.replace("template flat file flat.txt", "template row file row.txt")


def force_series(wd, name, corr, n, theta, e, tc, r, d, v0, dt, nsteps):
    write_row(wd, n, r, d, r + 1e-6, theta, v0)
    wall = ("fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL"
            % (e, tc))
    _, out = lc.run(TDEM, ROW.format(e=e, tc=tc, corr="correction " + corr, wall=wall, dt=dt, more="", n=nsteps),
                    wd, "in." + name)
    rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
    return rows[:, -1]


def jumps(F):
    """Largest |F[k+1] - F[k]| over the contact, without the first touch (F from 0: the law's own
    damping step gamma v0, the same with one sphere) and the last step (back to 0)."""
    dF = np.abs(np.diff(F))
    keep = (F[:-1] != 0.0) & (F[1:] != 0.0)
    return np.max(dF[keep]), np.max(np.abs(F))


def part_corr_continuity():
    wd = lc.workdir("clump_corr_cont")
    e, tc, r, d, v0 = 0.8, 1e-4, 0.002, 0.0045, 1.0
    dt = tc / 1000
    nsteps = 1500
    theta = 0.002  # the spheres touch 9 um apart in height: they close during the first half
    j1, f1 = jumps(force_series(wd, "one", "none", 1, 0.0, e, tc, r, d, v0, dt, nsteps))
    smooth = j1 / f1
    print("single sphere: max step change %.4g N of max force %.4g N (%.4f)" % (j1, f1, smooth))
    res = {}
    for corr in ("none", "count", "overlap"):
        F = force_series(wd, corr, corr, 4, theta, e, tc, r, d, v0, dt, nsteps)
        jm, fm = jumps(F)
        res[corr] = jm / fm
        print("row of 4, theta %.3g, correction %-7s: max step change %.4g N of max force %.4g N (%.4f, %.1f x the "
              "single sphere)" % (theta, corr, jm, fm, jm / fm, jm / fm / smooth))
    chk.check(res["overlap"] <= 3 * smooth, "overlap: the largest step change of the wall force is %.3g of its maximum, "
              "<= 3 x that of one sphere (%.3g)" % (res["overlap"], smooth))
    chk.check(res["count"] >= 0.1 and res["count"] >= 10 * smooth,
              "count: a contact closing makes the force jump (%.3g of its maximum; F/N with N = 2..4 expected, "
              ">= 0.1 and >= 10 x the single sphere %.3g)" % (res["count"], smooth))


def lsd_e(e, tc, mass_ratio):
    """Restitution of the LSD law derived from (e, tc) with mass M, acting on a mass m with
    M/m = mass_ratio (zero-overlap end): beta -> beta sqrt(M/m)."""
    a = -math.log(e) / math.pi
    beta = a / math.sqrt(1 + a * a) * math.sqrt(mass_ratio)
    return math.exp(-math.pi * beta / math.sqrt(1 - beta * beta))


LOCAL = ROW.replace("create_box 1 box", "atom_modify map array\ncreate_box 1 box").replace(
    "variable fz equal fcm(all,z)", "variable fz equal vz[1]")


def add_frozen_ball(wd, r, d, theta):
    """Adds to body.data of write_row (a dimer tilted by theta) atom 3: a free sphere of radius 2r at z = 0
    right below the lower sphere (frozen by the input)."""
    x1 = -0.5 * d * math.cos(theta)
    with open(os.path.join(wd, "body.data")) as f:
        text = f.read()
    text = text.replace("2 atoms", "3 atoms").replace(
        "\n\nVelocities\n\n", "\n3 1 %.17g 2500 %.17g 0 0\n\nVelocities\n\n" % (4 * r, x1)).replace(
        "\n\nMolecules\n\n", "\n3 0 0 0 0 0 0\n\nMolecules\n\n") + "3 0\n"
    with open(os.path.join(wd, "body.data"), "w") as f:
        f.write(text)


def part_corr_local_mass():
    wd = lc.workdir("clump_corr_local")
    e, tc, r, d, v0, rho = 0.8, 1e-4, 0.002, 0.0045, 0.1, 2500.0
    dt = tc / 4000
    theta = math.radians(30.0)
    # independent m_loc: two disjoint spheres of mass m at +-d/2 on the body x axis; contact point
    # below sphere 1, n = z: (r x n).I^-1 (r x n) = (d/2 cos theta)^2 / I_yy
    m = 4.0 / 3.0 * math.pi * r ** 3 * rho
    M = 2 * m
    Iyy = 2 * (0.4 * m * r * r + m * (0.5 * d) ** 2)
    m_loc = 1.0 / (1.0 / M + (0.5 * d * math.cos(theta)) ** 2 / Iyy)
    e_none = lsd_e(e, tc, M / m_loc)
    wall = "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL" % (e, tc)
    res = {}
    for corr in ("none", "local_mass"):
        write_row(wd, 2, r, d, r + 1e-7, theta, v0)
        nsteps = int(1.5 * tc / dt)
        _, out = lc.run(TDEM, LOCAL.format(e=e, tc=tc, corr="correction " + corr, wall=wall, dt=dt, more="",
                                           n=nsteps), wd, "in." + corr)
        rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
        t = rows[:, 0] * dt
        vz1 = rows[:, -1]
        # overlap of sphere 1 from the body: z1 = z_com - d/2 sin(theta') ~ integrate vz1 instead
        z1 = (r + 1e-7) + np.concatenate([[0.0], np.cumsum(0.5 * (vz1[1:] + vz1[:-1]) * dt)])
        ts, te, i0, i1 = crossing(t, r - z1, dt)
        v_after = vz1[i1] + (vz1[i1 + 1] - vz1[i1]) * (te - t[i1]) / dt
        res[corr] = v_after / v0
        res[corr + "_t"] = te - ts
        print("tilted dimer (30 deg), correction %-10s: contact-point e %.6f, contact %.4e s (law e %.3f; closed form "
              "with m_loc/M = %.4f and the body mass: %.6f)" % (corr, res[corr], te - ts, e, m_loc / M, e_none))
    # the same through pair tdem/gran: the lower sphere lands on a frozen free sphere (radius 2r)
    # right below it (a frozen side adds 0 to the inverse mass, as a wall)
    for corr in ("none", "local_mass"):
        write_row(wd, 2, r, d, 3 * r + 1e-7, theta, v0)
        add_frozen_ball(wd, r, d, theta)
        inp = LOCAL.replace("fix c all", "group body molecule 1\ngroup ball id 3\nfix fr ball freeze\nfix c body")
        nsteps = int(1.5 * tc / dt)
        _, out = lc.run(TDEM, inp.format(e=e, tc=tc, corr="correction " + corr, wall="", dt=dt, more="", n=nsteps),
                        wd, "in.pair_" + corr)
        rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
        t = rows[:, 0] * dt
        vz1 = rows[:, -1]
        z1 = (3 * r + 1e-7) + np.concatenate([[0.0], np.cumsum(0.5 * (vz1[1:] + vz1[:-1]) * dt)])
        ts, te, i0, i1 = crossing(t, 3 * r - z1, dt)
        res["pair_" + corr] = (vz1[i1] + (vz1[i1 + 1] - vz1[i1]) * (te - t[i1]) / dt) / v0
        res["pair_" + corr + "_t"] = te - ts
        print("tilted dimer on a frozen sphere (pair), correction %-10s: contact-point e %.6f, contact %.4e s"
              % (corr, res["pair_" + corr], te - ts))
    ep = abs(res["pair_local_mass"] - e) / e
    tp = abs(res["pair_local_mass_t"] - tc) / tc
    chk.check(ep <= 2e-3 and tp <= 2e-3, "pair, local_mass: contact-point e %.6f = the law's e, contact time rel err "
              "%.2g (rel err of e %.2g; <= 2e-3)" % (res["pair_local_mass"], tp, ep))
    epn = abs(res["pair_none"] - e_none) / e_none
    chk.check(epn <= 5e-3, "pair, none: contact-point e %.6f = the m_loc closed form %.6f (rel err %.2g <= 5e-3)"
              % (res["pair_none"], e_none, epn))
    el = abs(res["local_mass"] - e) / e
    tl = abs(res["local_mass_t"] - tc) / tc
    chk.check(el <= 2e-3 and tl <= 2e-3, "local_mass: contact-point e %.6f = the law's e %.2f, contact time %.6g s = "
              "t_c %g s (rel err %.2g, %.2g <= 2e-3)" % (res["local_mass"], e, res["local_mass_t"], tc, el, tl))
    en = abs(res["none"] - e_none) / e_none
    chk.check(en <= 5e-3 and abs(res["none"] - e) / e > 0.02,
              "none: contact-point e %.6f differs from the law's e (%.2f) as the m_loc closed form predicts (%.6f, "
              "rel err %.2g <= 5e-3)" % (res["none"], e, e_none, en))


def part_corr_mpi():
    wd = lc.workdir("clump_corr_mpi")
    steps = 6000
    base = POUR + "run %d\n" % steps + DUMP
    # correction none is today's behaviour, bitwise
    lc.run(TDEM, base.format(out="d.default"), wd, "in.default")
    lc.run(TDEM, base.replace("vel 0 0 -1", "vel 0 0 -1 correction none").format(out="d.none"), wd, "in.none")
    _, a0 = lc.read_dump(os.path.join(wd, "d.default"))
    _, b0 = lc.read_dump(os.path.join(wd, "d.none"))
    chk.check(np.array_equal(a0, b0), "correction none equals no correction keyword (bitwise)")
    for corr in ("overlap", "count", "local_mass"):
        # split x or y over the ranks: bodies straddle the rank boundary, their contacts are tallied
        # on both ranks
        text = base.replace("vel 0 0 -1", "vel 0 0 -1 correction " + corr).replace(
            "boundary p p f", "boundary p p f\nprocessors * * 1")
        _, o1 = lc.run(TDEM, text.format(out="d.np1"), wd, "in.%s1" % corr)
        lc.run(TDEM, text.format(out="d.np2"), wd, "in.%s2" % corr, np_=2, mpirun=MPIRUN)
        _, a = lc.read_dump(os.path.join(wd, "d.np1"))
        _, b = lc.read_dump(os.path.join(wd, "d.np2"))
        contacts = max(float(r.split()[4]) for r in lc.thermo_blocks(o1)[1:])
        per, worst = lc.rel_diff(b[:, 2:12], a[:, 2:12])
        _, vs_none = lc.rel_diff(a[:, 2:12], a0[:, 2:12])
        print("correction %-10s: -np 2 vs -np 1 max rel diff %.3g (per column %s); vs no correction %.3g; "
              "largest contact count %d" % (corr, worst, per, vs_none, contacts))
        chk.check(a.shape == b.shape and worst <= 1e-12,
                  "correction %s: -np 2 equals -np 1 after %d steps of pouring (%.3g <= 1e-12)" % (corr, steps, worst))
        chk.check(vs_none > 1e-6, "correction %s changes the pour (%.3g vs no correction)" % (corr, vs_none))
    # newton off counts a pair with a ghost partner once (the copy on the other rank or periodic
    # image is removed from the tally): the same as newton on up to round-off (the order of the
    # force sums differs; after ~5000 steps the pile amplifies it, with or without correction)
    for corr in ("overlap", "count"):
        text = (POUR + "run 3000\n" + DUMP).replace("vel 0 0 -1", "vel 0 0 -1 correction " + corr)
        lc.run(TDEM, text.format(out="d.off"), wd, "in.off_" + corr)
        lc.run(TDEM, text.replace("newton off", "newton on").format(out="d.on"), wd, "in.on_" + corr, np_=2,
               mpirun=MPIRUN)
        _, a = lc.read_dump(os.path.join(wd, "d.off"))
        _, b = lc.read_dump(os.path.join(wd, "d.on"))
        _, worst = lc.rel_diff(b[:, 2:12], a[:, 2:12])
        chk.check(worst <= 1e-8, "correction %s: newton on (-np 2) equals newton off (-np 1) after 3000 steps to "
                  "round-off (%.3g <= 1e-8)" % (corr, worst))
    # restart with a correction: read_restart + run M equals the writing process's run M (2 ranks;
    # the reference as in part_restart)
    pour = POUR.replace("vel 0 0 -1", "vel 0 0 -1 correction overlap")
    rest = POUR_RESTART.replace("vel 0 0 -1", "vel 0 0 -1 correction overlap")
    lc.run(TDEM, pour + "run 6000\nwrite_restart pour.restart\nrun 600\n" + DUMP.format(out="d.full"), wd, "in.first",
           np_=2, mpirun=MPIRUN)
    lc.run(TDEM, rest.format(m=600, out="d.rest"), wd, "in.rest", np_=2, mpirun=MPIRUN)
    _, a = lc.read_dump(os.path.join(wd, "d.full"))
    _, b = lc.read_dump(os.path.join(wd, "d.rest"))
    per, worst = lc.rel_diff(b[:, 2:12], a[:, 2:12])
    print("restart with correction overlap: max rel diff per column %s" % per)
    chk.check(a.shape == b.shape and worst <= 1e-10,
              "correction overlap: read_restart + run 600 equals the writing process's run 600 (%.3g <= 1e-10)"
              % worst)


# ----------------------------------------------------------------------------- local bodies
RANKS = """
units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
atom_modify map array
{procs}
region box block 0 0.025 0 0.025 0 0.08
create_box 1 box
fix pm all property/atom mol ghost yes
region ins block 0.0 0.025 0.0 0.025 0.003 0.045
fix c all tdem/clump template t shape {shape} density 2500 insert {n} region ins seed 4711 vel 0 0 -1 \
    correction {corr}
""" + POUR_LAWS + """thermo_style custom step atoms f_c f_c[1] f_c[2] f_c[3] f_c[4] f_c[5] f_c[6] f_c[7] f_c[8] f_c[9] f_c[1][2] f_c[{last}][16]
thermo_modify format float %.17g
thermo 500
dump d all custom {steps} d.np{np} id mol x y z vx vy vz omegax omegay omegaz c_nc proc
dump_modify d sort id format float %.17g
run {steps}
"""
PROCS = {1: "", 2: "processors 2 1 1", 4: "processors 2 2 1", 8: "processors 2 2 2"}


def part_ranks():
    wd = lc.workdir("clump_ranks")
    scenes = [("tetra", "tetra 0.002 0.003", 40, 4, "none", 10000),
              ("rods", "rod 0.0015 0.0025 6", 24, 6, "overlap", 10000)]
    for name, shape, n, nsph, corr, steps in scenes:
        ref = None
        for np_ in (1, 2, 4, 8):
            text = RANKS.format(procs=PROCS[np_], shape=shape, n=n, corr=corr, last=n, steps=steps, np=np_)
            _, out = lc.run(TDEM, text, wd, "in.%s%d" % (name, np_), np_=np_, mpirun=MPIRUN, timeout=900)
            os.replace(os.path.join(wd, "d.np%d" % np_), os.path.join(wd, "d.%s%d" % (name, np_)))
            cols, a = lc.read_dump(os.path.join(wd, "d.%s%d" % (name, np_)))
            thermo = lc.thermo_blocks(out)
            if ref is None:
                ref = (a, thermo, out)
                chk.check(a.shape[0] == n * nsph, "%s: %d spheres" % (name, n * nsph))
                if name == "rods":
                    chk.check("ghost cutoff set to 0.0125" in out,
                              "rods: the fix raises the ghost cutoff to the rod's length 0.0125 (log line)")
                continue
            same_atoms = a.shape == ref[0].shape and np.array_equal(a[:, :12], ref[0][:, :12])
            same_thermo = thermo == ref[1]
            # bodies whose spheres are owned by different ranks, in contact, at the end
            split = split_contact = 0
            for m in np.unique(a[:, 1]):
                rows = a[a[:, 1] == m]
                if len(np.unique(rows[:, cols.index("proc")])) > 1:
                    split += 1
                    split_contact += int(np.any(rows[:, cols.index("c_nc")] > 0))
            print("%s -np %d: %d bodies split over ranks at the end, %d of them in contact" % (name, np_, split, split_contact))
            if not same_atoms:
                per, worst = lc.rel_diff(a[:, 2:11], ref[0][:, 2:11])
                print("  differs from -np 1: max rel diff per column %s" % per)
            chk.check(same_atoms, "%s: -np %d equals -np 1 bitwise after %d steps (x, v, omega of %d spheres)"
                      % (name, np_, steps, n * nsph))
            chk.check(same_thermo, "%s: -np %d: thermo of f_c (scalar, vector, array elements) bitwise equal to -np 1"
                      % (name, np_))
            chk.check(split_contact > 0, "%s: -np %d: bodies with spheres on several ranks and in contact (%d)"
                      % (name, np_, split_contact))
        chk.check(np.max(ref[0][:, cols.index("c_nc")]) > 0, "%s: contacts at the end" % name)
    # the bodies survive the rebuilds of the local bodies unchanged: rods re-mapped at every step
    # (each step an exchange) equal the default run (6000 steps: falling and the first contacts;
    # later the pile amplifies the changed order of the pair sums)
    runs = []
    for tag, extra in (("a", ""), ("b", "neigh_modify every 1 delay 0 check no\n")):
        text = RANKS.format(procs="", shape="rod 0.0015 0.0025 6", n=24, corr="none", last=24, steps=6000, np=tag)
        lc.run(TDEM, text.replace("timestep 5e-6\n", "timestep 5e-6\n" + extra), wd, "in.rebuild" + tag)
        runs.append(lc.read_dump(os.path.join(wd, "d.np" + tag))[1])
    per, worst = lc.rel_diff(runs[1][:, 2:11], runs[0][:, 2:11])
    chk.check(worst <= 1e-9 and np.sum(runs[0][:, 11]) > 0,
              "rods rebuilt at every step equal the default run after 6000 steps with contacts (%.3g <= 1e-9)" % worst)


# a row of impacts along a long box, split into 8 slabs (corr_wide)
WIDE = """
units si
atom_style sphere
boundary p f f
newton off
comm_modify vel yes
{procs}
region box block 0 0.8 -0.05 0.05 0 0.1
create_box 1 box
fix pm all property/atom mol ghost yes
read_data body.data add append fix pm NULL Molecules
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution {e} {tc} tangential cundall_strack 0.8 0
fix c all tdem/clump template flat file flat.txt density 2500 correction overlap
fix w all tdem/wall/gran normal lsd restitution {e} {tc} tangential cundall_strack 0.8 0 zplane 0 NULL
timestep {dt}
thermo_style custom step atoms
thermo_modify format float %.17g
thermo 100
run {n}
write_dump all custom d.wide id mol x y z vx vy vz modify sort id format float %.17g
"""


def part_corr_wide():
    """The contact tally's exchange with the neighbouring ranks only (contact_tally_mpi.h): 7 flat N = 4
    bodies dropping on the wall and 7 pairs of N = 4 bodies hitting each other, centred on the 7
    inner boundaries of 8 slabs along a long box (every body split over two ranks), correction
    overlap. -np 8 (processors 8 1 1) equals -np 1 bitwise; every wall body leaves with the single-
    contact e, every pair with the body-body single-contact e; each rank merges with its two
    neighbouring slabs only (TDEM_TALLY_REPORT)."""
    wd = lc.workdir("clump_corr_wide")
    e, tc, r, d, v0 = 0.8, 1e-4, 0.002, 0.0045, 1.0
    dt = tc / 2000
    n = 4
    pts = flat_template(n, r, d)
    with open(os.path.join(wd, "flat.txt"), "w") as f:
        f.write("".join("sphere %.17g %.17g %.17g %.17g\n" % (p[0], p[1], p[2], r) for p in pts))
    # body k: (x, y, z of the com, vz); wall bodies at y = -0.03, pairs at y = +0.03 (lower one rising)
    bodies = []
    for k in range(1, 8):
        bodies.append((0.1 * k, -0.03, r + 2e-6, -v0, "wall"))
        bodies.append((0.1 * k, 0.03, 0.05, 0.5 * v0, "low"))
        bodies.append((0.1 * k, 0.03, 0.05 + 2 * r + 2e-6, -0.5 * v0, "up"))
    lines = ["wide", "", "%d atoms" % (n * len(bodies)), "1 atom types", "", "0 0.8 xlo xhi", "-0.05 0.05 ylo yhi",
             "0 0.1 zlo zhi", "", "Atoms # sphere", ""]
    vel, mol, k = [], [], 0
    for b, (x, y, z, vz, _) in enumerate(bodies):
        for p in pts:
            k += 1
            lines.append("%d 1 %.17g 2500 %.17g %.17g %.17g" % (k, 2 * r, x + p[0], y + p[1], z + p[2]))
            vel.append("%d 0 0 %.17g 0 0 0" % (k, vz))
            mol.append("%d %d" % (k, b + 1))
    with open(os.path.join(wd, "body.data"), "w") as f:
        f.write("\n".join(lines + ["", "Velocities", ""] + vel + ["", "Molecules", ""] + mol) + "\n")
    nsteps = int(1.4 * tc / dt)
    res = {}
    for np_ in (1, 8):
        text = WIDE.format(procs="processors 8 1 1" if np_ == 8 else "", e=e, tc=tc, dt=dt, n=nsteps)
        os.environ["TDEM_TALLY_REPORT"] = "1"
        try:
            _, out = lc.run(TDEM, text, wd, "in.np%d" % np_, np_=np_, mpirun=MPIRUN)
        finally:
            del os.environ["TDEM_TALLY_REPORT"]
        cols, a = lc.read_dump(os.path.join(wd, "d.wide"))
        res[np_] = (a, out)
    a1, a8 = res[1][0], res[8][0]
    chk.check(a1.shape == a8.shape and np.array_equal(a1, a8),
              "-np 8 (every body split over two slabs) equals -np 1 bitwise after %d steps (%d spheres)"
              % (nsteps, a1.shape[0]))
    vz = {int(m): a1[a1[:, 1] == m, 7].mean() for m in np.unique(a1[:, 1])}
    e_wall = [vz[3 * j + 1] / v0 for j in range(7)]
    e_pair = [(vz[3 * j + 3] - vz[3 * j + 2]) / v0 for j in range(7)]
    print("wall bodies: e %s; body pairs: e %s" % (np.array2string(np.array(e_wall), precision=6),
                                                   np.array2string(np.array(e_pair), precision=6)))
    worst = max(abs(x - e) / e for x in e_wall + e_pair)
    chk.check(worst <= 1e-3, "every wall body and every body pair leaves with the single-contact e (rel err %.2g "
              "<= 1e-3; without the correction N = 4 contacts give %.4f)" % (worst, closed_form_n(e, tc, n)[0]))
    ok, what = tally_report.slab_neighbours(res[8][1], 8)
    chk.check(ok, "-np 8: each rank exchanges its tally with its two neighbouring slabs only (%s)" % what)


# ----------------------------------------------------------------------------- 9. correction, stock bodies
# the impact of CORR_IMPACT with the bodies of fix rigid/small (and its atom map and ghost cutoff)
CORR_STOCK = (CORR_IMPACT.replace("atom_style sphere\n", "atom_style sphere\natom_modify map array\n")
              .replace("comm_modify vel yes\n", "comm_modify vel yes cutoff 0.03\n")
              .replace("fix c all tdem/clump template flat file flat.txt density 2500 {corr}\n",
                       "fix rb all rigid/small molecule\n{corr}\n")
              .replace("variable fz equal fcm(all,z)\nthermo_style custom step f_c[1][4] f_c[1][7] {more} v_fz\n",
                       "group b1 molecule 1\ngroup b2 molecule 2\nvariable z1 equal xcm(b1,z)\n"
                       "variable v1 equal vcm(b1,z)\nvariable z2 equal xcm(b2,z)\nvariable v2 equal vcm(b2,z)\n"
                       "thermo_style custom step v_z1 v_v1 {more}\n"))



def part_corr_stock():
    """The correction with bodies of the stock fix rigid/small (fix tdem/correction, issue 20): flat-face
    impacts N = 2, 4, 8 on the wall and N = 4 body-body give the single-contact e and t_c with count and
    overlap, the N-contact closed form without the correction; bad input."""
    wd = lc.workdir("clump_corr_stock")
    e, tc, r, d, v0 = 0.8, 1e-4, 0.002, 0.0045, 1.0
    dt = tc / 4000
    z0 = r + 2e-6
    wall = "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL" % (e, tc)
    for corr in ("none", "count", "overlap"):
        line = "" if corr == "none" else "fix corr all tdem/correction %s bodies rb" % corr
        for n in (2, 4, 8):
            write_flat(wd, n, r, d, [(z0, -v0)])
            e_n, t_n = closed_form_n(e, tc, n)
            e_ref, t_ref = (e_n, t_n) if corr == "none" else (e, tc)
            nsteps = int((2e-6 + 1.3 * max(t_ref, tc)) / dt) + 200
            _, out = lc.run(TDEM, CORR_STOCK.format(e=0.5, tc=tc, corr=line, wall=wall, dt=dt, more="", n=nsteps),
                            wd, "in.s%s%d" % (corr, n))
            rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
            t = rows[:, 0] * dt
            ts, te, _, _ = crossing(t, r - rows[:, 1], dt)
            e_m, t_m = rows[-1, 2] / v0, te - ts
            ee, et = abs(e_m - e_ref) / e_ref, abs(t_m - t_ref) / t_ref
            print("rigid/small, wall, correction %-7s N = %d: e %.6f t_c %.6e s; reference e %.6f t_c %.6e s: "
                  "rel err %.2g %.2g" % (corr, n, e_m, t_m, e_ref, t_ref, ee, et))
            chk.check(ee <= 1e-3 and et <= 1e-3, "rigid/small, wall N = %d, correction %s: e, t_c vs the %s closed "
                      "form: rel err %.2g, %.2g (<= 1e-3)" % (n, corr, "N-contact" if corr == "none" else
                                                              "single-contact", ee, et))
    n = 4
    for corr in ("none", "overlap"):
        line = "" if corr == "none" else "fix corr all tdem/correction %s bodies rb" % corr
        za = 0.01
        write_flat(wd, n, r, d, [(za, 0.5 * v0), (za + 2 * r + 2e-6, -0.5 * v0)])
        e_n, t_n = closed_form_n(e, tc, n)
        e_ref, t_ref = (e_n, t_n) if corr == "none" else (e, tc)
        nsteps = int((1e-6 + 1.3 * max(t_ref, tc)) / dt) + 200
        _, out = lc.run(TDEM, CORR_STOCK.format(e=e, tc=tc, corr=line, wall="", dt=dt, more="v_z2 v_v2", n=nsteps),
                        wd, "in.sb%s" % corr)
        rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
        t = rows[:, 0] * dt
        ts, te, _, _ = crossing(t, 2 * r - (rows[:, 3] - rows[:, 1]), dt)
        e_m, t_m = (rows[-1, 4] - rows[-1, 2]) / v0, te - ts
        ee, et = abs(e_m - e_ref) / e_ref, abs(t_m - t_ref) / t_ref
        print("rigid/small, body-body, correction %-7s N = 4: e %.6f t_c %.6e s; reference e %.6f t_c %.6e s: "
              "rel err %.2g %.2g" % (corr, e_m, t_m, e_ref, t_ref, ee, et))
        chk.check(ee <= 1e-3 and et <= 1e-3, "rigid/small, body-body N = 4, correction %s: e, t_c vs the %s closed "
                  "form: rel err %.2g, %.2g (<= 1e-3)" % (corr, "N-contact" if corr == "none" else "single-contact",
                                                         ee, et))
    # -np 2 (the body split over the ranks at x = 0): the same impact
    write_flat(wd, 8, r, d, [(z0, -v0)])
    nsteps = int((2e-6 + 1.3 * tc) / dt) + 200
    outs = []
    for np_ in (1, 2):
        text = CORR_STOCK.format(e=0.5, tc=tc, corr="fix corr all tdem/correction overlap bodies rb", wall=wall, dt=dt,
                                 more="", n=nsteps)
        _, out = lc.run(TDEM, ("processors 2 1 1\n" if np_ == 2 else "") + text, wd, "in.snp%d" % np_, np_=np_,
                        mpirun=MPIRUN)
        outs.append(np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]]))
    # (LAMMPS's xcm() and vcm() sum over the ranks in their order: round-off differs already at step 0)
    per, worst = lc.rel_diff(outs[1][:, 1:], outs[0][:, 1:])
    chk.check(outs[0].shape == outs[1].shape and worst <= 1e-12,
              "rigid/small, wall N = 8, correction overlap: -np 2 equals -np 1 (com z and v_z at every step to "
              "%.2g <= 1e-12, the round-off of xcm/vcm)" % worst)
    # bad input names what is wrong
    write_flat(wd, 2, r, d, [(z0, -v0)])
    cases = [("fix corr all tdem/correction half bodies rb",
              "correction 'half' is unknown; allowed: count, overlap, local_mass"),
             ("fix corr all tdem/correction overlap bodies nosuch", "fix nosuch does not exist"),
             ("fix corr all tdem/correction overlap bodies w", "exports no rigid bodies"),
             ("fix corr all tdem/correction overlap", "expected 3 arguments")]
    rigid = CORR_STOCK.replace("rigid/small molecule", "rigid molecule")
    for text, line, expect in [(CORR_STOCK, l, x) for l, x in cases] + [
            (rigid, "fix corr all tdem/correction local_mass bodies rb", "only the rigid/small styles export")]:
        rc, out = lc.run(TDEM, text.format(e=e, tc=tc, corr=line, wall=wall, dt=dt, more="", n=10), wd,
                         "in.sbad", check=False, timeout=120)
        err = [l for l in out.splitlines() if "ERROR" in l]
        chk.check(rc != 0 and rc < 128 and err and expect in " ".join(err),
                  "%-50s -> %s" % (line[:50], err[0][:140] if err else "no error (rc %d)" % rc))


# the tilted dimer of corr_local_mass with the bodies of fix rigid/small
STOCK_LOCAL = (LOCAL.replace("comm_modify vel yes\n", "comm_modify vel yes cutoff 0.03\n")
               .replace("fix c all tdem/clump template row file row.txt density 2500 {corr}\n",
                        "fix rb all rigid/small molecule\n{corr}\n")
               .replace("thermo_style custom step f_c[1][4] f_c[1][7] {more} v_fz\n",
                        "thermo_style custom step {more} v_fz\n"))


def part_corr_stock_local():
    """correction local_mass with the bodies of the stock fix rigid/small (fix tdem/correction): the
    tilted dimer of corr_local_mass on the wall and on a frozen sphere gives the law's e and t_c at the
    contact point, none the m_loc closed form; -np 2 with the dimer split over the ranks equals -np 1."""
    wd = lc.workdir("clump_corr_stock_local")
    e, tc, r, d, v0 = 0.8, 1e-4, 0.002, 0.0045, 0.1
    dt = tc / 4000
    theta = math.radians(30.0)
    m = 4.0 / 3.0 * math.pi * r ** 3 * 2500.0
    M = 2 * m
    Iyy = 2 * (0.4 * m * r * r + m * (0.5 * d) ** 2)  # rigid/small: extended spheres add 2/5 m r^2
    m_loc = 1.0 / (1.0 / M + (0.5 * d * math.cos(theta)) ** 2 / Iyy)
    e_none = lsd_e(e, tc, M / m_loc)
    wall = "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL" % (e, tc)
    nsteps = int(1.5 * tc / dt)

    def impact(name, z_low, text, np_=1):
        _, out = lc.run(TDEM, text, wd, "in." + name, np_=np_, mpirun=MPIRUN)
        rows = np.array([[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]])
        t = rows[:, 0] * dt
        vz1 = rows[:, -1]
        z1 = (z_low + 1e-7) + np.concatenate([[0.0], np.cumsum(0.5 * (vz1[1:] + vz1[:-1]) * dt)])
        ts, te, _, i1 = crossing(t, z_low - z1, dt)
        return (vz1[i1] + (vz1[i1 + 1] - vz1[i1]) * (te - t[i1]) / dt) / v0, te - ts, rows

    res = {}
    for corr in ("none", "local_mass"):
        line = "" if corr == "none" else "fix corr all tdem/correction local_mass bodies rb"
        write_row(wd, 2, r, d, r + 1e-7, theta, v0)
        res[corr] = impact("w" + corr, r, STOCK_LOCAL.format(e=e, tc=tc, corr=line, wall=wall, dt=dt, more="",
                                                             n=nsteps))
        print("rigid/small, tilted dimer (30 deg) on the wall, correction %-10s: contact-point e %.6f, contact %.4e s "
              "(law e %.2f; m_loc closed form with the body mass %.6f)" % (corr, res[corr][0], res[corr][1], e, e_none))
        # the same through pair tdem/gran on a frozen sphere of radius 2r right below the lower sphere
        write_row(wd, 2, r, d, 3 * r + 1e-7, theta, v0)
        add_frozen_ball(wd, r, d, theta)
        inp = STOCK_LOCAL.replace("fix rb all", "group body molecule 1\ngroup ball id 3\nfix fr ball freeze\n"
                                                "fix rb body")
        res["p" + corr] = impact("p" + corr, 3 * r, inp.format(e=e, tc=tc, corr=line, wall="", dt=dt, more="",
                                                                  n=nsteps))
        print("rigid/small, tilted dimer on a frozen sphere (pair), correction %-10s: contact-point e %.6f, contact "
              "%.4e s" % (corr, res["p" + corr][0], res["p" + corr][1]))
    for k, what in (("local_mass", "wall"), ("plocal_mass", "pair")):
        ee, et = abs(res[k][0] - e) / e, abs(res[k][1] - tc) / tc
        chk.check(ee <= 2e-3 and et <= 2e-3, "rigid/small, %s, local_mass: contact-point e %.6f, contact time %.6g s "
                  "= the law's e %.2f and t_c %g s (rel err %.2g, %.2g <= 2e-3)" % (what, res[k][0], res[k][1], e, tc,
                                                                                    ee, et))
    for k, what in (("none", "wall"), ("pnone", "pair")):
        en = abs(res[k][0] - e_none) / e_none
        chk.check(en <= 5e-3, "rigid/small, %s, none: contact-point e %.6f = the m_loc closed form %.6f (rel err %.2g "
                  "<= 5e-3)" % (what, res[k][0], e_none, en))
    # -np 2, the dimer split over the ranks at x = 0 (one sphere on each): the same impact
    write_row(wd, 2, r, d, r + 1e-7, theta, v0)
    line = "fix corr all tdem/correction local_mass bodies rb"
    runs = []
    for np_ in (1, 2):
        text = ("processors 2 1 1\n" if np_ == 2 else "") + STOCK_LOCAL.format(
            e=e, tc=tc, corr=line, wall=wall, dt=dt, more="", n=nsteps)
        runs.append(impact("np%d" % np_, r, text, np_))
    per, worst = lc.rel_diff(runs[1][2][:, 1:], runs[0][2][:, 1:])
    chk.check(runs[0][2].shape == runs[1][2].shape and worst <= 1e-12 and abs(runs[1][0] - e) / e <= 2e-3,
              "rigid/small, local_mass, -np 2 (body split at x = 0): v_z of sphere 1 at every step equals -np 1 to "
              "%.2g (<= 1e-12), contact-point e %.6f" % (worst, runs[1][0]))


PARTS = {"vtk": part_vtk, "nve_single": part_nve_single, "free_body": part_free_body, "flat_impact": part_flat_impact,
         "mpi": part_mpi, "restart": part_restart, "insert": part_insert, "bad_input": part_bad_input,
         "corr_flat": part_corr_flat, "corr_continuity": part_corr_continuity,
         "corr_local_mass": part_corr_local_mass, "corr_mpi": part_corr_mpi,
         "ranks": part_ranks, "corr_stock": part_corr_stock,
         "corr_stock_local": part_corr_stock_local, "corr_wide": part_corr_wide}
if part == "all":
    for f in PARTS.values():
        f()
else:
    PARTS[part]()
chk.done()
