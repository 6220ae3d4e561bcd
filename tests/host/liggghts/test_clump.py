# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/clump in LIGGGHTS (issue 6): rigid multi-sphere clumps. Expected values are independent of
the code under test:

 vtk         `vtk N prefix`: the bodies of the tetra pour as .vtu files in a .pvd series, read back with the
             VTK library: every N steps at t = step*dt, cells equal to the fix's array (bitwise), points =
             the dumped spheres with the template radius, -np 2 = -np 1 bitwise, continued after a restart.
 nve         one-sphere clumps (bodies from molecules) in a scene with sphere-sphere and wall contacts
             (stock hertz + history, gravity) against the stock fix nve/sphere in the same scene over
             1000 steps: positions and velocities to round-off (1e-10 relative).
 torquefree  a free asymmetric body (template file with explicit inertia (1, 2, 3), three spheres)
             spinning near the unstable middle axis, 1e5 steps, splitting scheme: angular momentum
             unchanged (1e-12), kinetic energy bounded (|dE/E| < 1e-5); the explicit scheme drifts
             by more (shows that the measure can fail).
 flatface    rods of N = 1, 2, 4, 8 spheres lying flat, dropped on a fix wall/gran plane (tdem/lsd,
             parameters stiffness, absolute damping, per contact k and gamma derived from the BODY mass
             for e = 0.8, t_c = 1e-4 s, no gravity, no friction): e and t_c of the body against the
             closed form of N parallel contacts (physics_reference 6.4: Nk, N gamma), 1e-3; with
             parameters restitution (m* = the sphere's mass share M/N) the single-contact e and t_c.
 parallel    40 tetra clumps inserted and poured onto a floor (tdem/hertz + tdem/cundall_strack):
             -np 2 against -np 1, sphere positions and velocities after 10000 steps (1e-8; bitwise
             in fact), with clumps split over the ranks and spinning from contacts.
 restart     the same scene: run 7000 + write_restart, read_restart + run 3000 against one run of 10000
             steps (bitwise).
 insert      300 rod clumps inserted: no two spheres of different clumps overlap, every sphere inside
             the region, every clump a rigid copy of the template, axes uniform; 300 asymmetric L clumps:
             rotations (Kabsch from the spheres) uniform (<R> = 0, <q q^T> = I/4 within 4 sigma); the
             -np 2 insertion identical to -np 1; too many clumps: a clear error.
 bad         bad input ends with an error naming the keyword, the value and the allowed values.
 periodic    a rod in free flight with spin across periodic boundaries: unwrapped positions = the rigid
             motion (1e-8 m), -np 2 (crossing the ranks) = -np 1 bitwise.
 examples    input_scripts/liggghts/clumps_*.in, shortened, run (clumps_pour.in on 2 ranks).
"""
import math
import os
import shutil
import sys

import numpy as np

import tdem_lig as T

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from clump_ref import hertz_wall_ode  # noqa: E402
import tally_report  # noqa: E402

HEAD = """atom_style hybrid sphere molecular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
"""


def props_hertz(E=5e6):
    return """fix m1 all property/global youngsModulus peratomtype %g
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
""" % E


# ----------------------------------------------------------------------------- (1) nve/sphere
def part_nve(args, checks):
    r, rho = 0.005, 2500.0
    rng = np.random.RandomState(3)
    lines = [HEAD, "region b block 0 0.05 0 0.05 0 0.1 units box", "create_box 1 b",
             "neighbor 0.002 bin", "neigh_modify delay 0 exclude molecule all"]
    n = 0
    for iz in range(4):
        for iy in range(2):
            for ix in range(2):
                n += 1
                x = 0.015 + 0.02 * ix + rng.uniform(-0.002, 0.002)
                y = 0.015 + 0.02 * iy + rng.uniform(-0.002, 0.002)
                z = 0.006 + 0.0105 * iz
                lines.append("create_atoms 1 single %.6f %.6f %.6f units box" % (x, y, z))
    lines.append("set group all diameter %g density %g" % (2 * r, rho))
    for i in range(1, n + 1):
        lines.append("set atom %d mol %d" % (i, i))
        lines.append("set atom %d vx %g vy %g vz %g omegax %g" % (i, rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                                                                rng.uniform(-0.5, 0.0), rng.uniform(-20, 20)))
    lines += [props_hertz(), "pair_style gran model hertz tangential history", "pair_coeff * *",
              "timestep 1e-5", "fix gr all gravity 9.81 vector 0 0 -1",
              "fix wz all wall/gran model hertz tangential history primitive type 1 zplane 0.0",
              "fix wx all wall/gran model hertz tangential history primitive type 1 xplane 0.0",
              "fix wy all wall/gran model hertz tangential history primitive type 1 yplane 0.0", "INTEGRATOR",
              "dump d all custom 1000 dump.nve id x y z vx vy vz omegax omegay omegaz",
              "dump_modify d format \"%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\"",
              "run 1000"]
    base = "\n".join(lines) + "\n"
    d = T.workdir(args, "tdem_lig_clump_nve")
    T.run(args.stock, base.replace("INTEGRATOR", "fix i all nve/sphere"), d, "stock")
    os.rename(os.path.join(d, "dump.nve"), os.path.join(d, "dump.stock"))
    T.run(args.tdem, base.replace("INTEGRATOR", "fix i all tdem/clump template s shape single %g 0 density %g"
                                  % (r, rho)), d, "clump")
    a = T.read_dump(os.path.join(d, "dump.stock"))[-1][2]
    b = T.read_dump(os.path.join(d, "dump.nve"))[-1][2]
    moved = np.abs(a[:, 1:4] - T.read_dump(os.path.join(d, "dump.stock"))[0][2][:, 1:4]).max()
    checks.check(moved > 1e-3, "nve: the spheres moved (%.3g m) and collided" % moved)
    dx = np.abs(a[:, 1:4] - b[:, 1:4]).max() / np.abs(a[:, 1:4]).max()
    dv = np.abs(a[:, 4:7] - b[:, 4:7]).max() / np.abs(a[:, 4:7]).max()
    dw = np.abs(a[:, 7:10] - b[:, 7:10]).max() / np.abs(a[:, 7:10]).max()
    print("nve: max relative difference to nve/sphere after 1000 steps: x %.2e, v %.2e, omega %.2e" % (dx, dv, dw))
    checks.check(dx < 1e-10 and dv < 1e-10 and dw < 1e-10,
                 "nve: one-sphere clumps = fix nve/sphere to round-off (x %.1e, v %.1e, omega %.1e < 1e-10)"
                 % (dx, dv, dw))
    # contacts happened: only they give the spheres spin about y and z (initial spin about x only)
    wyz = np.abs(a[:, 8:10]).max()
    checks.check(wyz > 1.0, "nve: contacts made the spheres spin about y, z (max %.3g rad/s)" % wyz)


# ----------------------------------------------------------------------------- (2) torque-free body
def torquefree_run(args, d, scheme, steps, h):
    # three spheres (an L), explicit mass properties: I = diag(1, 2, 3) about the com at 0
    with open(os.path.join(d, "L.txt"), "w") as f:
        f.write("sphere 0.3 0 0 0.1\nsphere 0 0 0 0.1\nsphere 0 0.3 0 0.1\n"
                "mass 10\ncom 0.1 0.1 0\ninertia 1 2 3 0 0 0\n")
    # rigid motion with omega mostly about the middle axis (y) plus a small perturbation
    w = np.array([0.05, 2.0, 0.05])
    com = np.array([0.1, 0.1, 0.0])
    lines = [HEAD, "region b block -2 2 -2 2 -2 2 units box", "create_box 1 b",
             "neighbor 0.01 bin", "neigh_modify delay 0 exclude molecule all"]
    pos = [(0.3, 0, 0), (0, 0, 0), (0, 0.3, 0)]
    for i, p in enumerate(pos):
        lines.append("create_atoms 1 single %.17g %.17g %.17g units box" % p)
    lines.append("set group all diameter 0.2 density 1000")
    for i, p in enumerate(pos):
        v = np.cross(w, np.array(p) - com)
        lines.append("set atom %d mol 1 vx %.17g vy %.17g vz %.17g omegax %.17g omegay %.17g omegaz %.17g"
                     % (i + 1, v[0], v[1], v[2], w[0], w[1], w[2]))
    lines += [props_hertz(), "pair_style gran model hertz tangential history", "pair_coeff * *",
              "timestep %.17g" % h,
              "fix c all tdem/clump template L file L.txt rotation %s" % scheme,
              "thermo_style custom step f_c f_c[5] f_c[6] f_c[7]",
              "thermo_modify format float %.17g", "thermo %d" % (steps // 200), "run %d" % steps]
    T.run(args.tdem, "\n".join(lines) + "\n", d, "free_" + scheme)
    log = open(os.path.join(d, "log.free_" + scheme)).read()
    rows = np.array([[float(x) for x in r.split()] for r in T.thermo_blocks(log)[-1][1]])
    E, L = rows[:, 1], rows[:, 2:5]
    dE = np.abs(E / E[0] - 1).max()
    dL = np.abs(L - L[0]).max() / np.linalg.norm(L[0])
    return dE, dL, E[0], L[0]


def part_torquefree(args, checks):
    d = T.workdir(args, "tdem_lig_clump_free")
    h, steps = 1e-3, 100000
    dE, dL, E0, L0 = torquefree_run(args, d, "splitting", steps, h)
    # the initial state from the spheres: L = I w (body axes = template axes here)
    checks.check(np.allclose(L0, [0.05, 4.0, 0.15], rtol=1e-12, atol=1e-13),
                 "torquefree: L from the sphere velocities = I w = (0.05, 4, 0.15): %s" % L0)
    E_ref = 0.5 * (1 * 0.05 ** 2 + 2 * 2.0 ** 2 + 3 * 0.05 ** 2)
    checks.check(abs(E0 / E_ref - 1) < 1e-12, "torquefree: E0 = %.15g (closed form %.15g)" % (E0, E_ref))
    print("torquefree: splitting, h = %g, %d steps: max |dE/E| = %.3e, max |dL|/|L| = %.3e" % (h, steps, dE, dL))
    checks.check(dL < 1e-12, "torquefree: splitting conserves L (%.1e < 1e-12)" % dL)
    checks.check(dE < 1e-5, "torquefree: splitting energy error bounded (%.2e < 1e-5)" % dE)
    dEx, dLx, _, _ = torquefree_run(args, d, "explicit", steps, h)
    print("torquefree: explicit: max |dE/E| = %.3e, max |dL|/|L| = %.3e" % (dEx, dLx))
    checks.check(dEx > 10 * dE, "torquefree: the explicit scheme drifts more (%.2e > 10 x %.2e)" % (dEx, dE))


# ----------------------------------------------------------------------------- (3) flat-face impacts
def nc_closed_form(k, gamma, M, n):
    """e and t_c of N identical parallel LSD contacts (zero-overlap end) on a body of mass M."""
    w0 = math.sqrt(n * k / M)
    beta = n * gamma / (2.0 * math.sqrt(n * k * M))
    return math.exp(-math.pi * beta / math.sqrt(1 - beta * beta)), math.pi / (w0 * math.sqrt(1 - beta * beta))


def flat_measure(d, name, dt, r, v0):
    rows = np.array([[float(x) for x in s.split()] for s in
                     T.thermo_blocks(open(os.path.join(d, "log." + name)).read())[-1][1]])
    t = rows[:, 0] * dt
    xi = r - rows[:, 1]   # overlap of every sphere with the wall
    ins = np.where(xi > 0)[0]
    if len(ins) == 0:
        return None
    a, b = ins[0], ins[-1]
    t_in = t[a - 1] + (t[a] - t[a - 1]) * (0 - xi[a - 1]) / (xi[a] - xi[a - 1])
    t_out = t[b] + (t[b + 1] - t[b]) * (0 - xi[b]) / (xi[b + 1] - xi[b])
    return rows[-1, 2] / v0, t_out - t_in, np.abs(rows[:, 4:7]).max()


def part_flatface(args, checks):
    r, rho, dist, e1, t1, v0 = 0.005, 2500.0, 0.0125, 0.8, 1e-4, 1.0
    d = T.workdir(args, "tdem_lig_clump_flat")
    for n in (1, 2, 4, 8):
        M = n * 4.0 / 3.0 * math.pi * r ** 3 * rho
        lne = math.log(e1)
        beta = -lne / math.sqrt(math.pi ** 2 + lne ** 2)
        w0 = math.pi / (t1 * math.sqrt(1 - beta * beta))
        k = M * w0 * w0
        gamma = 2 * beta * math.sqrt(k * M)
        e_ref, tc_ref = nc_closed_form(k, gamma, M, n)
        dt = tc_ref / 4000.0
        gap = 2e-6
        shape = "single %g 0" % r if n == 1 else "rod %g %g %d" % (r, dist, n)
        lines = [HEAD, "region b block -0.1 0.1 -0.05 0.05 -0.01 0.05 units box", "create_box 1 b",
                 "neighbor 0.001 bin", "neigh_modify delay 0 exclude molecule all"]
        for i in range(n):
            lines.append("create_atoms 1 single %.17g 0 %.17g units box" % ((i - 0.5 * (n - 1)) * dist, r + gap))
        lines.append("set group all diameter %.17g density %.17g" % (2 * r, rho))
        lines.append("set group all mol 1 vz %.17g" % -v0)
        lines += ["fix m_kn all property/global kn peratomtypepair 1 %.17g" % k,
                  "fix m_kt all property/global kt peratomtypepair 1 %.17g" % k,
                  "fix m_gn all property/global gamman_abs peratomtypepair 1 %.17g" % gamma,
                  "fix m_gt all property/global gammat_abs peratomtypepair 1 0.0",
                  "fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0",
                  "pair_style gran model tdem/lsd tangential no_history parameters stiffness absolute_damping on",
                  "pair_coeff * *", "timestep %.17g" % dt,
                  "fix c all tdem/clump template rod shape %s density %.17g" % (shape, rho),
                  "fix w all wall/gran model tdem/lsd tangential no_history primitive type 1 zplane 0.0 "
                  "parameters stiffness absolute_damping on",
                  "thermo_style custom step f_c[1][4] f_c[1][7] f_c[1][2] f_c[1][15] f_c[1][16] f_c[1][17]",
                  "thermo_modify format float %.17g", "thermo 1",
                  "run %d" % int((2 * gap / v0 + 1.6 * tc_ref) / dt)]
        name = "flat%d" % n
        T.run(args.tdem, "\n".join(lines) + "\n", d, name)
        res = flat_measure(d, name, dt, r, v0)
        if res is None:
            checks.check(False, "flatface N=%d: no contact" % n)
            continue
        e, tc, spin = res
        err_e, err_t = e / e_ref - 1, tc / tc_ref - 1
        print("flatface N=%d: M = %.6g kg, e = %.6f (N-contact closed form %.6f, %.1e), t_c = %.6e s (%.6e, %.1e), "
              "|omega| max %.1e" % (n, M, e, e_ref, err_e, tc, tc_ref, err_t, spin))
        checks.check(abs(err_e) < 1e-3 and abs(err_t) < 1e-3,
                     "flatface N=%d: e and t_c = closed form of N contacts (%.1e, %.1e < 1e-3)" % (n, err_e, err_t))
        if n > 1:
            checks.check(abs(e - e1) > 0.01, "flatface N=%d: e %.4f differs from the single-contact %.2f" % (n, e, e1))
        # the same with `parameters restitution` (e, t_c per contact, k = m* w0^2 with m* = the SPHERE
        # mass M/N that LIGGGHTS passes): N contacts of k(M/N) on M act like one contact of k(M), so e1
        # and t1 come back (the 'count' correction by accident of the sphere masses)
        text = "\n".join(lines)
        for key in ("m_kn", "m_kt", "m_gn", "m_gt"):
            text = "\n".join(l for l in text.splitlines() if not l.startswith("fix %s " % key))
        text = text.replace("parameters stiffness absolute_damping on", "parameters restitution")
        text = text.replace("fix m_mu all", "fix m_e all property/global coefficientRestitution peratomtypepair 1 %.17g\n"
                            "fix m_tc all property/global contactTime peratomtypepair 1 %.17g\n"
                            "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.0\n"
                            "fix m_mu all" % (e1, t1))
        text = text.replace("timestep %.17g" % dt, "timestep %.17g" % (t1 / 4000.0))
        text = text.replace("run %d" % int((2 * gap / v0 + 1.6 * tc_ref) / dt), "run %d" % int((2 * gap / v0 + 1.6 * t1) / (t1 / 4000.0)))
        T.run(args.tdem, text + "\n", d, name + "_rest")
        res = flat_measure(d, name + "_rest", t1 / 4000.0, r, v0)
        e, tc = res[0], res[1]
        print("flatface N=%d, parameters restitution (m* = sphere mass): e = %.6f, t_c = %.6e s" % (n, e, tc))
        checks.check(abs(e / e1 - 1) < 1e-3 and abs(tc / t1 - 1) < 1e-3,
                     "flatface N=%d, parameters restitution: e and t_c of one contact (%.1e, %.1e < 1e-3)"
                     % (n, e / e1 - 1, tc / t1 - 1))


# ----------------------------------------------------------------------------- (4, 5) pour
def pour_scene(steps_a, steps_b=None, restart=None, read=None, nclump=40, correction=None,
               shape="tetra 0.003 0.0045"):
    """A box with 40 tetra clumps poured onto the floor. steps_b: a second run after write_restart."""
    lines = [HEAD]
    # the correction acts through the surface model tdem/clump (docs/liggghts/fix_tdem_clump.md)
    surf = " surface tdem/clump" if correction and correction != "none" else ""
    if read:
        lines = ["read_restart %s" % read, "newton off", "communicate single vel yes"]
    else:
        lines += ["region b block 0 0.06 0 0.06 0 0.12 units box", "create_box 1 b"]
    lines += ["neighbor 0.002 bin", "neigh_modify delay 0 exclude molecule all",
              "fix m1 all property/global youngsModulus peratomtype 5e6",
              "fix m2 all property/global poissonsRatio peratomtype 0.3",
              "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.6",
              "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5",
              "fix m5 all property/global tangentialStiffnessRatio peratomtypepair 1 0.82",
              "pair_style gran model tdem/hertz tangential tdem/cundall_strack%s limitForce on" % surf, "pair_coeff * *",
              "timestep 5e-6",
              "region ins block 0.005 0.055 0.005 0.055 0.01 0.11 units box",
              "fix c all tdem/clump template t shape %s density 2500 insert %d region ins seed 7 "
              "vel 0 0 -0.5%s" % (shape, nclump, " correction " + correction if correction else ""),
              "fix gr all gravity 9.81 vector 0 0 -1"]
    for i, (dim, pos) in enumerate([("z", 0.0), ("x", 0.0), ("x", 0.06), ("y", 0.0), ("y", 0.06)]):
        lines.append("fix w%d all wall/gran model tdem/hertz tangential tdem/cundall_strack%s primitive type 1 %splane %g "
                     "limitForce on" % (i, surf, dim, pos))
    lines += ["dump d all custom 1000 dump.pour id mol x y z vx vy vz omegax omegay omegaz",
              "dump_modify d format \"%d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\"",
              "thermo_style custom step atoms f_c f_c[1] f_c[2] f_c[3] f_c[4] f_c[5] f_c[6] f_c[7] f_c[8] f_c[9] "
              "f_c[1][2] f_c[%d][16]" % nclump, "thermo_modify format float %.17g", "thermo 1000",
              "run %d" % steps_a]
    if restart:
        lines.append("write_restart %s" % restart)
    return "\n".join(lines) + "\n"


def last_frame(d):
    return T.read_dump(os.path.join(d, "dump.pour"))[-1]


NPOUR = 10000


def part_parallel(args, checks):
    d1 = T.workdir(args, "tdem_lig_clump_par1")
    d2 = T.workdir(args, "tdem_lig_clump_par2")
    T.run(args.tdem, pour_scene(NPOUR), d1, "pour")
    T.run(args.tdem, "processors 2 1 1\n" + pour_scene(NPOUR), d2, "pour", np_=2, mpirun=args.mpirun)
    s1, c, a = last_frame(d1)
    s2, _, b = last_frame(d2)
    checks.check(s1 == s2 == NPOUR and a.shape == b.shape == (160, 11), "parallel: 160 spheres at step %d on 1 and 2 ranks" % NPOUR)
    a0 = T.read_dump(os.path.join(d1, "dump.pour"))[0][2]
    fell = (a0[:, 4] - a[:, 4]).max()
    checks.check(fell > 0.01, "parallel: the clumps fell %.3g m" % fell)
    dx = np.abs(a[:, 2:5] - b[:, 2:5]).max()
    dv = np.abs(a[:, 5:8] - b[:, 5:8]).max() / max(np.abs(a[:, 5:8]).max(), 1e-30)
    print("parallel: -np 2 vs -np 1 after %d steps:" % NPOUR, " max |dx| = %.2e m, max |dv|/|v|max = %.2e" % (dx, dv))
    checks.check(dx < 1e-8 and dv < 1e-8, "parallel: -np 2 = -np 1 (dx %.1e m, dv %.1e < 1e-8)" % (dx, dv))
    # spheres of one clump straddle the rank boundary (x = 0.03) at some point: at least at the end?
    straddle = 0
    for m in np.unique(a[:, 1]):
        xs = a[a[:, 1] == m, 2]
        if xs.min() < 0.03 < xs.max():
            straddle += 1
    print("parallel: %d clumps have spheres on both ranks at the end" % straddle)
    checks.check(straddle > 0, "parallel: some clumps have spheres on both ranks (%d)" % straddle)
    spun = len(np.unique(a[np.linalg.norm(a[:, 8:11], axis=1) > 1e-3, 1]))
    checks.check(spun >= 10, "parallel: contacts made %d of 40 clumps spin (>= 10)" % spun)


def part_restart(args, checks):
    d = T.workdir(args, "tdem_lig_clump_restart")
    half = 7 * NPOUR // 10
    T.run(args.tdem, pour_scene(NPOUR), d, "one")
    os.rename(os.path.join(d, "dump.pour"), os.path.join(d, "dump.one"))
    T.run(args.tdem, pour_scene(half, restart="mid.restart"), d, "first")
    os.rename(os.path.join(d, "dump.pour"), os.path.join(d, "dump.first"))
    T.run(args.tdem, pour_scene(NPOUR - half, read="mid.restart"), d, "second")
    a = T.read_dump(os.path.join(d, "dump.one"))[-1]
    b = T.read_dump(os.path.join(d, "dump.pour"))[-1]
    mid = T.read_dump(os.path.join(d, "dump.first"))[-1][2]
    checks.check(a[0] == NPOUR and b[0] == NPOUR, "restart: both at step %d (%d, %d)" % (NPOUR, a[0], b[0]))
    spun = len(np.unique(mid[np.linalg.norm(mid[:, 8:11], axis=1) > 1e-3, 1]))
    checks.check(spun >= 5, "restart: at the restart, %d clumps spin (contacts before and across the restart)" % spun)
    log2 = open(os.path.join(d, "log.second")).read()
    checks.check("bodies read from the restart file" in log2 and "inserted" not in log2,
                 "restart: bodies from the restart file, no second insertion")
    diff = np.abs(a[2][:, 2:] - b[2][:, 2:]).max()
    print("restart: largest difference of x, v, omega after %d + %d steps vs %d: %.3e" % (half, NPOUR - half, NPOUR, diff))
    checks.check(diff == 0.0, "restart: continues identically (bitwise: %.1e)" % diff)
    # a restart file of the global-bodies version (every body in the fix's global record; tdem before
    # issue 20, commit 0fa3e78, at step 7000 of this pour on one rank: data/clump_global/pour_7000.restart),
    # read on 2 ranks: the bodies reach their spheres at the set-up and the run continues identically
    legacy = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "clump_global", "pour_7000.restart")
    shutil.copy(legacy, os.path.join(d, "legacy.restart"))
    T.run(args.tdem, "processors 2 1 1\n" + pour_scene(NPOUR - half, read="legacy.restart"), d, "legacy", np_=2,
          mpirun=args.mpirun)
    c = T.read_dump(os.path.join(d, "dump.pour"))[-1]
    diff = np.abs(a[2][:, 2:] - c[2][:, 2:]).max() if c[2].shape == a[2].shape else float("inf")
    checks.check(half == 7000 and c[0] == NPOUR and diff == 0.0,
                 "restart: a file of the global-bodies version, read on 2 ranks, continues identically (%.1e)" % diff)


# ----------------------------------------------------------------------------- (6) insertion
def insert_scene(n):
    return "\n".join([HEAD, "region b block 0 0.1 0 0.1 0 0.1 units box", "create_box 1 b",
                      "neighbor 0.002 bin", "neigh_modify delay 0 exclude molecule all",
                      props_hertz(), "pair_style gran model hertz tangential history", "pair_coeff * *",
                      "timestep 1e-6",
                      "create_atoms 1 single 0.05 0.05 0.05 units box",
                      "set atom 1 diameter 0.02 density 2500",
                      "group old id 1",
                      "group new subtract all old",
                      "region ins block 0.01 0.09 0.01 0.09 0.01 0.09 units box",
                      "fix c new tdem/clump template rod shape rod 0.003 0.005 3 density 2500 insert %d region ins "
                      "seed 12345" % n,
                      "fix f old freeze",
                      "dump d all custom 1 dump.ins id mol radius x y z",
                      "dump_modify d format \"%d %d %.17g %.17g %.17g %.17g\"",
                      "variable q0 equal f_c[1][8]",
                      "thermo_style custom step atoms f_c[1]",
                      "run 0"]) + "\n"


def part_insert(args, checks):
    n = 300
    d = T.workdir(args, "tdem_lig_clump_insert")
    T.run(args.tdem, insert_scene(n), d, "ins")
    fr = T.read_dump(os.path.join(d, "dump.ins"))[0][2]
    checks.check(fr.shape[0] == 3 * n + 1, "insert: %d spheres (3 per clump + 1 existing)" % fr.shape[0])
    mol, rad, X = fr[:, 1], fr[:, 2], fr[:, 3:6]
    # overlaps between spheres of different clumps (and with the existing sphere, molecule 0)
    D = np.linalg.norm(X[:, None, :] - X[None, :, :], axis=2)
    S = rad[:, None] + rad[None, :]
    other = mol[:, None] != mol[None, :]
    gap = (D - S)[other].min()
    checks.check(gap >= -1e-15, "insert: no overlap between clumps or with the existing sphere (min gap %.3e m)" % gap)
    lo, hi = 0.01, 0.09
    clump = mol > 0
    inside = np.all(X[clump] - rad[clump, None] >= lo - 1e-15) and np.all(X[clump] + rad[clump, None] <= hi + 1e-15)
    checks.check(inside, "insert: every sphere inside the region")
    # rigid copies: the three spheres of a clump on a line, 0.005 apart, ids in order
    axes = []
    ok = True
    for m in np.unique(mol[clump]):
        P = X[mol == m]
        if P.shape[0] != 3:
            ok = False
            break
        d01, d12 = np.linalg.norm(P[1] - P[0]), np.linalg.norm(P[2] - P[1])
        ok = ok and abs(d01 - 0.005) < 1e-12 and abs(d12 - 0.005) < 1e-12 and np.linalg.norm(P[2] - 2 * P[1] + P[0]) < 1e-12
        axes.append((P[2] - P[0]) / np.linalg.norm(P[2] - P[0]))
    checks.check(ok and len(axes) == n, "insert: %d clumps, each a rigid copy of the rod template" % len(axes))
    A = np.array(axes)
    # uniform axis directions on the sphere: <a> = 0 and <a a^T> = I/3 (within 4 sigma)
    mean = np.abs(A.mean(axis=0)).max()
    cov = np.abs(A.T @ A / n - np.eye(3) / 3).max()
    print("insert: rod axes: |mean| max %.3f (4 sigma %.3f), |<aa>-I/3| max %.3f (4 sigma %.3f)"
          % (mean, 4 / math.sqrt(3 * n), cov, 4 * math.sqrt(4.0 / 45.0 / n)))
    checks.check(mean < 4 / math.sqrt(3 * n), "insert: mean rod axis ~ 0 (uniform orientations)")
    checks.check(cov < 4 * math.sqrt(4.0 / 45.0 / n), "insert: second moment of the axes ~ I/3 (uniform orientations)")
    # full orientations: an asymmetric L of three spheres, the rotation of every clump from its
    # spheres (Kabsch), then <R> = 0 and <q q^T> = I/4 of uniformly distributed rotations
    dl = T.workdir(args, "tdem_lig_clump_insertL")
    tpl = np.array([[0.0, 0.0, 0.0], [0.006, 0.0, 0.0], [0.0, 0.004, 0.0]])
    with open(os.path.join(dl, "L.txt"), "w") as f:
        f.write("".join("sphere %g %g %g 0.0015\n" % tuple(p) for p in tpl))
    text = insert_scene(n).replace("template rod shape rod 0.003 0.005 3 density 2500",
                                   "template L file L.txt density 2500")
    T.run(args.tdem, text, dl, "insL")
    frL = T.read_dump(os.path.join(dl, "dump.ins"))[0][2]
    Rs, qs, fit = [], [], 0.0
    a0 = tpl - tpl.mean(axis=0)
    for m in np.unique(frL[frL[:, 1] > 0, 1]):
        P = frL[frL[:, 1] == m][:, 3:6]
        b0 = P - P.mean(axis=0)
        U, S, Vt = np.linalg.svd(a0.T @ b0)
        D = np.diag([1.0, 1.0, np.sign(np.linalg.det(Vt.T @ U.T))])
        R = Vt.T @ D @ U.T
        Rs.append(R)
        fit = max(fit, np.abs(a0 @ R.T - b0).max())
        w = math.sqrt(max(0.0, 1 + np.trace(R))) / 2
        qv = np.array([w, 0, 0, 0.0])
        if w > 1e-6:
            qv[1:] = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / (4 * w)
        else:   # 180 degrees: axis from R + I
            ax = np.linalg.eigh(R + np.eye(3))[1][:, -1]
            qv[1:] = ax
        qs.append(qv / np.linalg.norm(qv))
    Rs, qs = np.array(Rs), np.array(qs)
    meanR = np.abs(Rs.mean(axis=0)).max()
    qq = np.abs(qs.T @ qs / len(qs) - np.eye(4) / 4).max()
    sig_R, sig_q = 1 / math.sqrt(3 * len(Rs)), 0.25 / math.sqrt(len(qs))  # sd of q_i^2: 1/4
    print("insert: %d L clumps: |<R>| max %.3f (4 sigma %.3f), |<q q^T> - I/4| max %.3f (4 sigma %.3f), fit %.1e m"
          % (len(Rs), meanR, 4 * sig_R, qq, 4 * sig_q, fit))
    checks.check(len(Rs) == n and fit < 1e-12, "insert: %d L clumps, rigid copies of the template" % len(Rs))
    checks.check(meanR < 4 * sig_R, "insert: mean rotation matrix ~ 0 (uniform orientations)")
    checks.check(qq < 4 * sig_q, "insert: quaternion second moment ~ I/4 (uniform orientations)")
    # the same on 2 ranks
    d2 = T.workdir(args, "tdem_lig_clump_insert2")
    T.run(args.tdem, "processors 2 1 1\n" + insert_scene(n), d2, "ins", np_=2, mpirun=args.mpirun)
    fr2 = T.read_dump(os.path.join(d2, "dump.ins"))[0][2]
    checks.check(fr2.shape == fr.shape and np.array_equal(fr2, fr), "insert: -np 2 inserts exactly the same clumps")
    # too many: a clear error
    d3 = T.workdir(args, "tdem_lig_clump_insert3")
    r = T.run(args.tdem, insert_scene(100000), d3, "toomany", check=False)
    out = r.stdout + r.stderr
    checks.check(r.returncode != 0 and "placed only" in out and "insert" in out,
                 "insert: too many clumps end with an error naming 'insert' and the count placed")


# ----------------------------------------------------------------------------- (7) bad input
def part_bad(args, checks):
    d = T.workdir(args, "tdem_lig_clump_bad")
    base = "\n".join([HEAD, "region b block 0 0.1 0 0.1 0 0.1 units box", "create_box 1 b",
                      "neigh_modify delay 0", "region ins block 0.01 0.09 0.01 0.09 0.01 0.09 units box",
                      "create_atoms 1 single 0.05 0.05 0.05 units box",
                      "create_atoms 1 single 0.06 0.05 0.05 units box",
                      "set group all diameter 0.004 density 2500 mol 1",
                      props_hertz(), "pair_style gran model hertz tangential history", "pair_coeff * *",
                      "timestep 1e-6"]) + "\n"
    cases = [
        ("shape", "fix c all tdem/clump template t shape cube 0.002 0.004 density 1", ["'shape'", "'cube'", "tetra"]),
        ("rotation", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1 rotation verlet",
         ["'rotation'", "'verlet'", "splitting, explicit, richardson"]),
        ("integration", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1 integration grid",
         ["'integration'", "'grid'", "columns, voxel, monte_carlo"]),
        ("density", "fix c all tdem/clump template t shape dimer 0.002 0.01 density -3",
         ["'density'", "-3", "(0, inf)"]),
        ("nodensity", "fix c all tdem/clump template t shape dimer 0.002 0.01", ["density RHO"]),
        ("resolution", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1 resolution 2",
         ["'resolution'", "'2'", "[4, 4096]"]),
        ("keyword", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1 colour red",
         ["'colour'", "allowed: template"]),
        ("file", "fix c all tdem/clump template t file nofile.txt density 1", ["nofile.txt", "cannot be opened"]),
        ("region", "fix c all tdem/clump template t shape dimer 0.002 0.005 density 1 insert 3 region nowhere seed 1",
         ["'insert'", "region 'nowhere'"]),
        ("radius", "fix c all tdem/clump template t shape dimer 0.003 0.01 density 1",
         ["radius 0.002", "radius 0.003"]),
        ("count", "fix c all tdem/clump template t shape rod 0.002 0.01 3 density 1",
         ["molecule 1 has 2 spheres", "has 3"]),
        ("exclude", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1\nrun 1",
         ["neigh_modify exclude molecule"]),
        ("correction", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1 correction many",
         ["'correction'", "'many'", "none, count, overlap, local_mass"]),
        ("vtk", "fix c all tdem/clump template t shape dimer 0.002 0.01 density 1 vtk 0 b",
         ["'vtk'", "'0'", "[1, 2147483647]"]),
        ("vtkdir", "neigh_modify exclude molecule all\nfix c all tdem/clump template t shape dimer 0.002 0.01 density 1 "
         "vtk 10 /nonexistent-dir/b\nrun 1", ["/nonexistent-dir/b_0.vtu", "does not exist"]),
        ("twice", "neigh_modify exclude molecule all\nfix c all tdem/clump template t shape dimer 0.002 0.01 density 1"
         "\nfix n all nve/sphere\nrun 1", ["fix n (nve/sphere) also integrates clump spheres"]),
    ]
    for name, text, needles in cases:
        r = T.run(args.tdem, base + text + "\n", d, name, check=False)
        out = r.stdout + r.stderr
        ok = r.returncode != 0 and all(s in out for s in needles)
        msg = [l for l in out.splitlines() if "ERROR" in l]
        checks.check(ok, "bad %s: error names %s%s" % (name, needles, "" if ok else ": " + (msg[0] if msg else out[-300:])))
    # no molecule IDs: atom_style sphere
    text = base.replace("atom_style hybrid sphere molecular", "atom_style sphere").replace(" mol 1", "")
    r = T.run(args.tdem, text + "fix c all tdem/clump template t shape single 0.002 0 density 1\n", d, "nomol", check=False)
    out = r.stdout + r.stderr
    checks.check(r.returncode != 0 and "molecule IDs" in out and "hybrid sphere molecular" in out,
                 "bad nomol: atom_style sphere is refused with the style to use")


# ----------------------------------------------------------------------------- periodic
def periodic_scene():
    lines = [HEAD.replace("boundary f f f", "boundary p p f"), "region b block 0 0.03 0 0.03 0 0.03 units box",
             "create_box 1 b", "neighbor 0.001 bin", "neigh_modify delay 0 exclude molecule all"]
    for k in range(3):
        lines.append("create_atoms 1 single %.17g 0.015 0.015 units box" % (0.003 + 0.005 * k))
    lines.append("set group all diameter 0.004 density 2500 mol 1")
    w, v = PERIODIC_W, PERIODIC_V
    for k in range(3):
        rx = 0.005 * (k - 1)
        lines.append("set atom %d vx %.17g vy %.17g vz 0 omegaz %.17g" % (k + 1, v[0], v[1] + w * rx, w))
    lines += [props_hertz(), "pair_style gran model hertz tangential history", "pair_coeff * *",
              "timestep 1e-5", "fix c all tdem/clump template rod shape rod 0.002 0.005 3 density 2500",
              "dump d all custom 20000 dump.per id x y z xu yu zu",
              "dump_modify d format \"%d %.17g %.17g %.17g %.17g %.17g %.17g\"", "run 20000"]
    return "\n".join(lines) + "\n"


PERIODIC_W, PERIODIC_V = 30.0, (0.5, 0.2)


def part_periodic(args, checks):
    d1 = T.workdir(args, "tdem_lig_clump_per1")
    d2 = T.workdir(args, "tdem_lig_clump_per2")
    T.run(args.tdem, periodic_scene(), d1, "per")
    T.run(args.tdem, "processors 2 1 1\n" + periodic_scene(), d2, "per", np_=2, mpirun=args.mpirun)
    a = T.read_dump(os.path.join(d1, "dump.per"))[-1][2]
    b = T.read_dump(os.path.join(d2, "dump.per"))[-1][2]
    t = 0.2
    com = np.array([0.008 + PERIODIC_V[0] * t, 0.015 + PERIODIC_V[1] * t, 0.015])
    phi = PERIODIC_W * t
    ref = np.array([com + 0.005 * (k - 1) * np.array([math.cos(phi), math.sin(phi), 0.0]) for k in range(3)])
    err = np.abs(a[:, 4:7] - ref).max()
    print("periodic: rod moved %.3f m in x (%.1f box lengths), turned %.1f rad; unwrapped positions vs rigid "
          "motion: %.2e m" % (PERIODIC_V[0] * t, PERIODIC_V[0] * t / 0.03, phi, err))
    checks.check(err < 1e-8, "periodic: unwrapped sphere positions = free rigid motion across x and y boundaries "
                 "(%.1e m < 1e-8)" % err)
    inside = np.all(a[:, 1:3] >= 0.0) and np.all(a[:, 1:3] < 0.03)
    checks.check(inside, "periodic: wrapped positions inside the box")
    checks.check(np.array_equal(a, b), "periodic: -np 2 (the rod crossing the ranks) = -np 1 bitwise")


# ----------------------------------------------------------------------------- examples
def part_examples(args, checks):
    """The example inputs of input_scripts/liggghts, shortened: they run and keep their clumps."""
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts", "liggghts")
    d = T.workdir(args, "tdem_lig_clump_examples")
    for f in ("clumps_vs_multisphere.in", "clumps_vs_multisphere_tdem.inc", "clumps_vs_multisphere_stock.inc"):
        with open(os.path.join(src, f)) as fi, open(os.path.join(d, f), "w") as fo:
            fo.write(fi.read())
    text = open(os.path.join(src, "clumps_pour.in")).read()
    text = "variable n index 60\nvariable steps index 2000\n" + text
    r = T.run(args.tdem, text, d, "pour", np_=2, mpirun=args.mpirun, check=False)
    rows = [l.split() for l in T.thermo_blocks(r.stdout)[-1][1]] if T.thermo_blocks(r.stdout) else []
    checks.check(r.returncode == 0 and rows and rows[-1][:2] == ["2000", "420"] and rows[-1][4:6] == ["60", "60"],
                 "clumps_pour.in (-np 2, 60 + 60 clumps, 2000 steps) runs and keeps its 120 bodies")
    for stock in (0, 1):
        text = open(os.path.join(d, "clumps_vs_multisphere.in")).read()
        text = "variable stock index %d\nvariable n index 50\nvariable steps index 1000\n" % stock + text
        r = T.run(args.tdem, text, d, "vs%d" % stock, check=False)
        rows = [l.split() for l in T.thermo_blocks(r.stdout)[-1][1]] if T.thermo_blocks(r.stdout) else []
        checks.check(r.returncode == 0 and rows and rows[-1][:2] == ["1000", "200"],
                     "clumps_vs_multisphere.in -var stock %d: 50 tetra clumps (200 spheres) at step 1000" % stock)


# ----------------------------------------------------------------------------- multiple-contact correction
def lsd_rates(e1, t1):
    """zero-overlap LSD: k/m and gamma/m of one contact for (e1, t1) (closed form, physics_reference 6.4)."""
    lne = math.log(e1)
    beta = -lne / math.sqrt(math.pi ** 2 + lne ** 2)
    w0 = math.pi / (t1 * math.sqrt(1 - beta * beta))
    return w0 * w0, 2 * beta * w0


def lsd_outcome(k, gamma, m):
    """e and t_c of one zero-overlap LSD contact of k, gamma on mass m."""
    w0 = math.sqrt(k / m)
    beta = gamma / (2.0 * math.sqrt(k * m))
    return math.exp(-math.pi * beta / math.sqrt(1 - beta * beta)), math.pi / (w0 * math.sqrt(1 - beta * beta))


def corr_scene(n, r, dist, rho, v0, k, gamma, dt, steps, correction, tilt=0.0, gap=2e-6, bodies=1,
               restitution=None, dump=None, surface=None, hertz=None):
    """Rods of n spheres (n = 1: one sphere) dropped at v0 on a tdem/lsd zplane (bodies = 1), or a rod
    dropped flat onto an equal resting rod (bodies = 2, no wall). Per-contact k, gamma (absolute), no
    friction, no gravity; tilt: rotation of the rod about y (rad). restitution = (e1, t1): the law by
    `parameters restitution` instead (k, gamma = m* times rates)."""
    shape = "single %g 0" % r if n == 1 else ("dimer %g %g" % (r, dist) if n == 2 else "rod %g %g %d" % (r, dist, n))
    # the correction acts through the surface model tdem/clump; surface = True / False forces it on / off
    surf = " surface tdem/clump" if (correction != "none" if surface is None else surface) else ""
    lines = [HEAD, "region b block -0.1 0.1 -0.05 0.05 -0.05 0.05 units box", "create_box 1 b",
             "neighbor 0.001 bin", "neigh_modify delay 0 exclude molecule all"]
    zc = r + gap + 0.5 * (n - 1) * dist * math.sin(abs(tilt))
    for i in range(n):
        s = (i - 0.5 * (n - 1)) * dist
        lines.append("create_atoms 1 single %.17g 0 %.17g units box" % (s * math.cos(tilt), zc + s * math.sin(tilt)))
    if bodies == 2:
        for i in range(n):
            lines.append("create_atoms 1 single %.17g 0 %.17g units box" % ((i - 0.5 * (n - 1)) * dist, -r))
    lines.append("set group all diameter %.17g density %.17g" % (2 * r, rho))
    lines.append("set group all mol 1 vz %.17g" % -v0)
    if bodies == 2:
        lines.append("group lower id %d:%d" % (n + 1, 2 * n))
        lines.append("set group lower mol 2 vz 0")
    model = "tdem/lsd tangential no_history"
    if hertz:
        # stock LIGGGHTS `model hertz tangential history` (E, nu, e per type); k and gamma unused
        E, nu, eh = hertz
        model, law = "hertz tangential history", ""
        lines += ["fix m_E all property/global youngsModulus peratomtype %.17g" % E,
                  "fix m_nu all property/global poissonsRatio peratomtype %.17g" % nu,
                  "fix m_e all property/global coefficientRestitution peratomtypepair 1 %.17g" % eh]
    elif restitution:
        e1, t1 = restitution
        law = "parameters restitution"
        lines += ["fix m_e all property/global coefficientRestitution peratomtypepair 1 %.17g" % e1,
                  "fix m_tc all property/global contactTime peratomtypepair 1 %.17g" % t1,
                  "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.0"]
    else:
        law = "parameters stiffness absolute_damping on"
        lines += ["fix m_kn all property/global kn peratomtypepair 1 %.17g" % k,
                  "fix m_kt all property/global kt peratomtypepair 1 %.17g" % k,
                  "fix m_gn all property/global gamman_abs peratomtypepair 1 %.17g" % gamma,
                  "fix m_gt all property/global gammat_abs peratomtypepair 1 0.0"]
    lines += ["fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0",
              "pair_style gran model %s%s %s" % (model, surf, law),
              "pair_coeff * *", "timestep %.17g" % dt,
              "fix c all tdem/clump template rod shape %s density %.17g correction %s" % (shape, rho, correction)]
    if bodies == 1:
        lines.append("fix w all wall/gran model %s%s primitive type 1 zplane 0.0 %s" % (model, surf, law))
        lines.append("thermo_style custom step f_c[1][4] f_c[1][7] f_c[1][2] f_c[1][15] f_c[1][16] f_c[1][17]")
    else:
        lines.append("thermo_style custom step f_c[1][4] f_c[1][7] f_c[2][4] f_c[2][7]")
    if dump:
        lines += ["dump d all custom 1 %s id z vz fz" % dump, "dump_modify d format \"%d %.17g %.17g %.17g\""]
    lines += ["thermo_modify format float %.17g", "thermo 1", "run %d" % steps]
    return "\n".join(lines) + "\n"


def thermo_rows(d, name):
    return np.array([[float(x) for x in s.split()] for s in T.thermo_blocks(open(os.path.join(d, "log." + name)).read())[-1][1]])


def crossing_times(t, xi):
    ins = np.where(xi > 0)[0]
    if len(ins) == 0:
        return None
    a, b = ins[0], ins[-1]
    t_in = t[a - 1] + (t[a] - t[a - 1]) * (0 - xi[a - 1]) / (xi[a] - xi[a - 1])
    t_out = t[b] + (t[b + 1] - t[b]) * (0 - xi[b]) / (xi[b + 1] - xi[b])
    return t_in, t_out


CORR_R, CORR_RHO, CORR_DIST, CORR_E, CORR_T, CORR_V = 0.005, 2500.0, 0.0125, 0.8, 1e-4, 1.0


def part_corrflat(args, checks):
    """count / overlap: flat rods of N = 1, 2, 4, 8 on a wall and a flat rod on a rod (N = 4) with per-contact
    k, gamma derived for the single contact (body mass, resp. reduced mass of the two bodies) give the
    single-contact e and t_c (closed form) to 1e-3; without correction the N-contact closed form (shown
    by test flatface)."""
    r, rho, dist, e1, t1, v0 = CORR_R, CORR_RHO, CORR_DIST, CORR_E, CORR_T, CORR_V
    d = T.workdir(args, "tdem_lig_clump_corrflat")
    kpm, gpm = lsd_rates(e1, t1)
    cases = [(n, c, 1) for c in ("count", "overlap") for n in (1, 2, 4, 8)] + [(4, "count", 2), (4, "overlap", 2),
                                                                               (4, "none", 2)]
    for n, corr, bodies in cases:
        M = n * 4.0 / 3.0 * math.pi * r ** 3 * rho
        m = M if bodies == 1 else 0.5 * M
        k, gamma = m * kpm, m * gpm
        e_ref, tc_ref = lsd_outcome(k, gamma, m)     # = e1, t1
        if corr == "none":
            e_ref, tc_ref = lsd_outcome(n * k, n * gamma, m)
        dt = t1 / 4000.0
        steps = int((2e-6 / v0 + 1.6 * t1) / dt)
        name = "flat%d_%s_%d" % (n, corr, bodies)
        T.run(args.tdem, corr_scene(n, r, dist, rho, v0, k, gamma, dt, steps, corr, bodies=bodies), d, name)
        rows = thermo_rows(d, name)
        t = rows[:, 0] * dt
        if bodies == 1:
            xi, vrel = r - rows[:, 1], rows[:, 2]
        else:
            xi, vrel = 2 * r - (rows[:, 1] - rows[:, 3]), rows[:, 2] - rows[:, 4]
        ct = crossing_times(t, xi)
        if ct is None:
            checks.check(False, "corrflat %s: no contact" % name)
            continue
        e, tc = vrel[-1] / v0, ct[1] - ct[0]
        err_e, err_t = e / e_ref - 1, tc / tc_ref - 1
        what = "wall" if bodies == 1 else "rod on rod"
        print("corrflat N=%d %s, correction %s: e = %.6f (%.6f, %.1e), t_c = %.6e s (%.6e, %.1e)"
              % (n, what, corr, e, e_ref, err_e, tc, tc_ref, err_t))
        checks.check(abs(err_e) < 1e-3 and abs(err_t) < 1e-3,
                     "corrflat N=%d %s, correction %s: e, t_c = %s closed form (%.1e, %.1e < 1e-3)"
                     % (n, what, corr, "single-contact" if corr != "none" else "N-contact", err_e, err_t))


def force_series(d, dump, ids):
    fr = T.read_dump(os.path.join(d, dump))
    steps = np.array([f[0] for f in fr])
    F = np.array([f[2][np.isin(f[2][:, 0], ids), 3].sum() for f in fr])
    return steps, F


def part_corrcont(args, checks):
    """Continuity: a rod of 4 spheres, tilted by 2e-4 rad, dropped on the wall (no damping, e = 1): its
    contacts close one after another. The body's normal force F (sum of the spheres' fz, every step):
    with `overlap` the largest step-to-step change stays below 3 k v0 dt (a smooth overlap-driven change
    of one contact of stiffness k at the approach speed v0; derivation in docs/liggghts/fix_tdem_clump.md),
    with `count` F jumps by about F/(N_c + 1) when a contact closes (detected: > 10 k v0 dt)."""
    r, rho, dist, v0, t1 = CORR_R, CORR_RHO, CORR_DIST, CORR_V, CORR_T
    n = 4
    M = n * 4.0 / 3.0 * math.pi * r ** 3 * rho
    kpm, _ = lsd_rates(1.0, t1)
    k = M * kpm
    dt = t1 / 4000.0
    steps = int((2e-6 / v0 + 2.0 * t1) / dt)
    tilt = 2e-4
    d = T.workdir(args, "tdem_lig_clump_corrcont")
    res = {}
    for corr in ("overlap", "count"):
        name = "cont_" + corr
        T.run(args.tdem, corr_scene(n, r, dist, rho, v0, k, 0.0, dt, steps, corr, tilt=tilt, dump="dump." + corr), d, name)
        st, F = force_series(d, "dump." + corr, np.arange(1, n + 1))
        dF = np.abs(np.diff(F))
        res[corr] = (dF.max(), F.max())
    bound = k * v0 * dt
    print("corrcont: tilted rod N=4: max |dF| per step: overlap %.4g N, count %.4g N; k v0 dt = %.4g N; max F %.4g N"
          % (res["overlap"][0], res["count"][0], bound, res["overlap"][1]))
    checks.check(res["overlap"][1] > 100 * bound, "corrcont: the rod was loaded (F max %.3g N)" % res["overlap"][1])
    checks.check(res["overlap"][0] < 3 * bound, "corrcont: overlap: no jump (max |dF| %.3g < 3 k v0 dt = %.3g N)"
                 % (res["overlap"][0], 3 * bound))
    checks.check(res["count"][0] > 10 * bound, "corrcont: count: the jump at a closing contact is detected "
                 "(max |dF| %.3g > 10 k v0 dt = %.3g N)" % (res["count"][0], 10 * bound))


def dimer_local_mass(r, dist, rho, tilt):
    """m_loc of the lower sphere's contact with a z wall, and the sphere mass (closed form of two disjoint
    spheres: I_perp = 2 (2/5 m r^2 + m (d/2)^2))."""
    m = 4.0 / 3.0 * math.pi * r ** 3 * rho
    M = 2 * m
    I_perp = 2 * (0.4 * m * r * r + m * (0.5 * dist) ** 2)
    arm = 0.5 * dist * math.cos(tilt)
    return 1.0 / (1.0 / M + arm * arm / I_perp), m


def part_corrlocal(args, checks):
    """local_mass: a dimer tilted by 30 degrees, frictionless, (e, t_c) law (k, gamma = m* rates): one sphere
    hits the wall off the centre-of-mass line. The normal velocity of the contact point (= the lower
    sphere's vz: omega x n has no normal part) after/before = the law's e to 1e-3 with local_mass; with
    none (m* = the sphere mass) it is the closed form of the rates on m_loc instead, and differs."""
    r, rho, dist, e1, t1, v0 = CORR_R, CORR_RHO, 2.5 * CORR_R, CORR_E, 2e-5, CORR_V
    tilt = math.radians(30.0)
    mloc, msph = dimer_local_mass(r, dist, rho, tilt)
    kpm, gpm = lsd_rates(e1, t1)
    e_none, _ = lsd_outcome(msph * kpm, msph * gpm, mloc)
    d = T.workdir(args, "tdem_lig_clump_corrlocal")
    dt = t1 / 4000.0
    steps = int((2e-6 / v0 + 1.3 * t1) / dt)
    out = {}
    for corr in ("local_mass", "none"):
        name = "loc_" + corr
        text = corr_scene(2, r, dist, rho, v0, 0, 0, dt, steps, corr, tilt=tilt, restitution=(e1, t1),
                          dump="dump." + corr)
        T.run(args.tdem, text, d, name)
        fr = T.read_dump(os.path.join(d, "dump." + corr))
        z = np.array([f[2][0, 1] for f in fr])   # lower sphere (id 1, tilted down)
        vz = np.array([f[2][0, 2] for f in fr])
        z2 = np.array([f[2][1, 1] for f in fr])
        xi = r - z
        ins = np.where(xi > 0)[0]
        if len(ins) == 0 or ins[-1] + 1 >= len(z):
            checks.check(False, "corrlocal %s: no complete contact" % corr)
            continue
        out[corr] = (-vz[ins[-1] + 1] / vz[ins[0] - 1], (r - z2).max())
    if len(out) < 2:
        return
    print("corrlocal: dimer at 30 deg, m_loc/m_sphere = %.4f: contact-point e with local_mass %.6f (law %.2f, %.1e), "
          "with none %.6f (closed form on m_loc %.6f)" % (mloc / msph, out["local_mass"][0], e1,
                                                           out["local_mass"][0] / e1 - 1, out["none"][0], e_none))
    checks.check(out["local_mass"][1] < 0 and out["none"][1] < 0, "corrlocal: the upper sphere never touched")
    checks.check(abs(out["local_mass"][0] / e1 - 1) < 1e-3,
                 "corrlocal: local_mass: contact-point e = the law's e (%.1e < 1e-3)" % (out["local_mass"][0] / e1 - 1))
    checks.check(abs(out["none"][0] / e_none - 1) < 2e-3 and abs(out["none"][0] - e1) > 5e-3,
                 "corrlocal: none: e %.5f = closed form with m* = sphere mass on m_loc (%.5f), not %.2f"
                 % (out["none"][0], e_none, e1))


def part_corrwide(args, checks):
    """The contact tally exchanged with the neighbouring ranks only (contact_tally_mpi.h): 7 flat rods of
    N = 4 dropped on the wall, centred on the 7 inner boundaries of 8 slabs along a long box (every rod
    split over two ranks; slabs of 0.4 m, more than the reach 3 x the ghost cutoff of the 47.5 mm rods),
    correction overlap, k and gamma for one contact on the body mass. -np 8
    (processors 8 1 1) equals -np 1 bitwise, every rod leaves with the single-contact e, and each rank
    merges with its two neighbouring slabs only (TDEM_TALLY_REPORT)."""
    r, rho, dist, e1, t1, v0 = CORR_R, CORR_RHO, CORR_DIST, CORR_E, CORR_T, CORR_V
    n = 4
    M = n * 4.0 / 3.0 * math.pi * r ** 3 * rho
    kpm, gpm = lsd_rates(e1, t1)
    k, gamma = M * kpm, M * gpm
    e_ref, _ = lsd_outcome(k, gamma, M)
    dt = t1 / 2000.0
    steps = int((2e-6 / v0 + 1.4 * t1) / dt)
    d = T.workdir(args, "tdem_lig_clump_corrwide")
    lines = [HEAD.replace("boundary f f f", "boundary p f f"), "{procs}",
             "region b block 0 3.2 -0.05 0.05 -0.05 0.05 units box", "create_box 1 b",
             "neighbor 0.001 bin", "neigh_modify delay 0 exclude molecule all"]
    for b in range(1, 8):
        for i in range(n):
            lines.append("create_atoms 1 single %.17g 0 %.17g units box" % (0.4 * b + (i - 1.5) * dist, r + 2e-6))
    lines.append("set group all diameter %.17g density %.17g vz %.17g" % (2 * r, rho, -v0))
    for b in range(1, 8):
        lines.append("group g%d id %d:%d" % (b, n * (b - 1) + 1, n * b))
        lines.append("set group g%d mol %d" % (b, b))
    lines += ["fix m_kn all property/global kn peratomtypepair 1 %.17g" % k,
              "fix m_kt all property/global kt peratomtypepair 1 %.17g" % k,
              "fix m_gn all property/global gamman_abs peratomtypepair 1 %.17g" % gamma,
              "fix m_gt all property/global gammat_abs peratomtypepair 1 0.0",
              "fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0",
              "pair_style gran model tdem/lsd tangential no_history surface tdem/clump parameters stiffness "
              "absolute_damping on", "pair_coeff * *", "timestep %.17g" % dt,
              "fix c all tdem/clump template rod shape rod %g %g %d density %.17g correction overlap" % (r, dist, n, rho),
              "fix w all wall/gran model tdem/lsd tangential no_history surface tdem/clump primitive type 1 zplane "
              "0.0 parameters stiffness absolute_damping on",
              "thermo 100", "run %d" % steps,
              "dump d all custom 1 dump.wide id mol x y z vx vy vz", "dump_modify d sort id format \"%d %d %.17g "
              "%.17g %.17g %.17g %.17g %.17g\"", "run 0"]
    text = "\n".join(lines) + "\n"
    res = {}
    os.environ["TDEM_TALLY_REPORT"] = "1"
    try:
        for np_ in (1, 8):
            r_ = T.run(args.tdem, text.replace("{procs}", "processors 8 1 1" if np_ == 8 else ""), d, "wide%d" % np_,
                       np_=np_, mpirun=args.mpirun)
            res[np_] = (T.read_dump(os.path.join(d, "dump.wide"))[-1][2], r_.stdout)
    finally:
        del os.environ["TDEM_TALLY_REPORT"]
    a1, a8 = res[1][0], res[8][0]
    checks.check(a1.shape == a8.shape and np.array_equal(a1, a8),
                 "corrwide: -np 8 (every rod split over two slabs) equals -np 1 bitwise after %d steps" % steps)
    es = [a1[a1[:, 1] == b, 7].mean() / v0 for b in range(1, 8)]
    worst = max(abs(e / e_ref - 1) for e in es)
    print("corrwide: e of the 7 rods %s (single-contact closed form %.6f)" % (np.array2string(np.array(es), precision=6),
                                                                          e_ref))
    checks.check(worst < 1e-3, "corrwide: every rod leaves with the single-contact e (%.1e < 1e-3)" % worst)
    ok, what = tally_report.slab_neighbours(res[8][1], 8)
    checks.check(ok, "corrwide: -np 8: each rank exchanges its tally with its two neighbouring slabs only (%s)" % what)


def part_corrpar(args, checks):
    """-np 2 = -np 1 and restart = one run, with `correction overlap` (the pour scene: tetra clumps on each
    other and on the walls, contacts tallied over both ranks)."""
    corr = "overlap"
    n = CORR_NPOUR
    d1 = T.workdir(args, "tdem_lig_clump_corrpar1")
    d2 = T.workdir(args, "tdem_lig_clump_corrpar2")
    T.run(args.tdem, pour_scene(n, correction=corr), d1, "pour")
    T.run(args.tdem, "processors 2 1 1\n" + pour_scene(n, correction=corr), d2, "pour", np_=2, mpirun=args.mpirun)
    a = last_frame(d1)
    b = last_frame(d2)
    a0 = T.read_dump(os.path.join(d1, "dump.pour"))[0][2]
    fell = (a0[:, 4] - a[2][:, 4]).max()
    checks.check(a[0] == b[0] == n and fell > 0.01, "corrpar: both at step %d, the clumps fell %.3g m" % (n, fell))
    diff = np.abs(a[2] - b[2]).max()
    print("corrpar: correction %s, -np 2 vs -np 1 after %d steps: largest difference of x, v, omega %.3e" % (corr, n, diff))
    checks.check(diff == 0.0, "corrpar: -np 2 = -np 1 bitwise with correction %s (%.1e)" % (corr, diff))
    # the correction acted: the same run without it ends elsewhere
    d0 = T.workdir(args, "tdem_lig_clump_corrpar0")
    T.run(args.tdem, pour_scene(n), d0, "pour")
    c = last_frame(d0)
    dc = np.abs(a[2][:, 2:5] - c[2][:, 2:5]).max()
    checks.check(dc > 1e-6, "corrpar: the correction changed the run (positions differ from none by %.2e m)" % dc)
    # flat impacts with the contacts of one body pair on both ranks: a rod of 4 on the wall split at x = 0
    # (processors 2 1 1: each rank counts its 2 contacts, the merge gives 4), a rod on a rod split at z = 0
    # between them (processors 1 1 2: every contact has a ghost partner, counted on one rank only)
    r, rho, dist, e1, t1, v0 = CORR_R, CORR_RHO, CORR_DIST, CORR_E, CORR_T, CORR_V
    kpm, gpm = lsd_rates(e1, t1)
    for bodies, grid in ((1, "2 1 1"), (2, "1 1 2")):
        for c in ("count", "overlap"):
            M = 4 * 4.0 / 3.0 * math.pi * r ** 3 * rho
            m = M if bodies == 1 else 0.5 * M
            dt = t1 / 4000.0
            steps = int((2e-6 / v0 + 1.6 * t1) / dt)
            text = corr_scene(4, r, dist, rho, v0, m * kpm, m * gpm, dt, steps, c, bodies=bodies)
            name = "split%d_%s" % (bodies, c)
            T.run(args.tdem, text, d1, name)
            T.run(args.tdem, "processors %s\n" % grid + text, d2, name, np_=2, mpirun=args.mpirun)
            r1, r2 = thermo_rows(d1, name), thermo_rows(d2, name)
            t = r2[:, 0] * dt
            xi = r - r2[:, 1] if bodies == 1 else 2 * r - (r2[:, 1] - r2[:, 3])
            vrel = r2[:, 2] if bodies == 1 else r2[:, 2] - r2[:, 4]
            ct = crossing_times(t, xi)
            e, tc = vrel[-1] / v0, ct[1] - ct[0]
            what = "rod on wall split in x" if bodies == 1 else "rod on rod split in z"
            print("corrpar: %s, correction %s, -np 2: e = %.6f, t_c = %.6e s" % (what, c, e, tc))
            checks.check(abs(e / e1 - 1) < 1e-3 and abs(tc / t1 - 1) < 1e-3 and np.array_equal(r1, r2),
                         "corrpar: %s, %s, -np 2: single-contact e, t_c (%.1e, %.1e) and = -np 1 bitwise"
                         % (what, c, e / e1 - 1, tc / t1 - 1))
    half = 7 * n // 10
    d = T.workdir(args, "tdem_lig_clump_corrrestart")
    T.run(args.tdem, pour_scene(half, restart="mid.restart", correction=corr), d, "first")
    T.run(args.tdem, pour_scene(n - half, read="mid.restart", correction=corr), d, "second")
    e = T.read_dump(os.path.join(d, "dump.pour"))[-1]
    diff = np.abs(a[2] - e[2]).max()
    print("corrpar: restart %d + %d vs %d steps: largest difference %.3e" % (half, n - half, n, diff))
    checks.check(e[0] == n and diff == 0.0, "corrpar: restart continues identically with correction %s (%.1e)"
                 % (corr, diff))


def part_corrstock(args, checks):
    """The correction through `surface tdem/clump` scales the output of ANY model: stock `model hertz
    tangential history`, a rod of N = 4 spheres dropped flat on the wall (no gravity). Elastic (e = 1):
    with count / overlap e = 1 and t_c = the Hertz closed form of ONE contact on the BODY mass M,
    t_c = 2 (xi_max / v0) int_0^1 (1 - x^2.5)^-1/2 dx = (4/5) B(2/5, 1/2) xi_max / v0, xi_max = (5 M v0^2 /
    (4 K))^(2/5), to 1e-3; without correction the N-contact value (the law on the sphere mass, shorter by
    4^(2/5)). Damped (e = 0.8): the one-contact ODE (RK4) with LIGGGHTS's hertz damping on m* = the
    sphere mass that LIGGGHTS passes: count / overlap = one contact on M, none = one contact on m."""
    r, rho, dist, v0, E, nu = CORR_R, CORR_RHO, CORR_DIST, CORR_V, 5e7, 0.3
    n = 4
    m = 4.0 / 3.0 * math.pi * r ** 3 * rho
    M = n * m
    Y = E / (2.0 * (1.0 - nu * nu))
    K = 4.0 / 3.0 * Y * math.sqrt(r)
    beta_int = 0.4 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)   # int_0^1 (1 - x^2.5)^-1/2 dx

    def tc_closed(mass):
        return 2.0 * beta_int * (5.0 * mass * v0 * v0 / (4.0 * K)) ** 0.4 / v0

    d = T.workdir(args, "tdem_lig_clump_corrstock")
    dt = tc_closed(M) / 4000.0
    steps = int((2e-6 / v0 + 1.3 * tc_closed(M)) / dt)
    for e_in in (1.0, 0.8):
        for corr in ("count", "overlap", "none"):
            mass = m if corr == "none" else M
            if e_in == 1.0:
                e_ref, tc_ref, what = 1.0, tc_closed(mass), "Hertz closed form"
            else:
                e_ref, tc_ref = hertz_wall_ode(E, nu, r, e_in, mass, m, v0)
                what = "one-contact ODE"
            name = "stock_%s_%g" % (corr, e_in)
            T.run(args.tdem, corr_scene(n, r, dist, rho, v0, 0, 0, dt, steps, corr, hertz=(E, nu, e_in)), d, name)
            rows = thermo_rows(d, name)
            ct = crossing_times(rows[:, 0] * dt, r - rows[:, 1])
            if ct is None:
                checks.check(False, "corrstock %s: no contact" % name)
                continue
            e, tc = rows[-1, 2] / v0, ct[1] - ct[0]
            err_e, err_t = e / e_ref - 1, tc / tc_ref - 1
            print("corrstock hertz N=%d, e_in %g, correction %s: e = %.6f (%.6f, %.1e), t_c = %.6e s (%.6e, %.1e)"
                  % (n, e_in, corr, e, e_ref, err_e, tc, tc_ref, err_t))
            checks.check(abs(err_e) < 1e-3 and abs(err_t) < 1e-3,
                         "corrstock hertz e_in %g, correction %s: e, t_c = %s on %s mass (%.1e, %.1e < 1e-3)"
                         % (e_in, corr, what, "the sphere" if corr == "none" else "the body", err_e, err_t))
            if corr == "none":
                checks.check(abs(tc / tc_closed(M) - 1) > 0.1,
                             "corrstock: without correction t_c differs from the one-contact value on M (%.3f)"
                             % (tc / tc_closed(M)))


def part_corrsurf(args, checks):
    """`surface tdem/clump`: a correction without it on the pair style or on a wall/gran fix is an error
    naming what to add; with correction none it warns and acts as the default surface model (bitwise the
    same run as without the keyword); a combination that is not compiled is named."""
    r, rho, dist, e1, t1, v0 = CORR_R, CORR_RHO, CORR_DIST, CORR_E, CORR_T, CORR_V
    M = 4 * 4.0 / 3.0 * math.pi * r ** 3 * rho
    kpm, gpm = lsd_rates(e1, t1)
    dt = t1 / 4000.0
    steps = int((2e-6 / v0 + 1.6 * t1) / dt)
    d = T.workdir(args, "tdem_lig_clump_corrsurf")

    def scene(corr, surface):
        return corr_scene(4, r, dist, rho, v0, M * kpm, M * gpm, dt, steps, corr, surface=surface)

    def expect_error(name, text, needles):
        res = T.run(args.tdem, text, d, name, check=False)
        out = res.stdout + res.stderr
        ok = res.returncode != 0 and all(s in out for s in needles)
        msg = [l for l in out.splitlines() if "ERROR" in l]
        checks.check(ok, "corrsurf %s: error names %s%s" % (name, needles, "" if ok else ": " + (msg[0] if msg else out[-300:])))

    for corr in ("count", "local_mass"):
        expect_error("nopair_" + corr, scene(corr, False),
                     ["'correction %s'" % corr, "pair style 'gran'", "add 'surface tdem/clump'"])
    text = scene("overlap", True).replace("tangential no_history surface tdem/clump primitive",
                                          "tangential no_history primitive")
    expect_error("nowall", text, ["'correction overlap'", "fix w (wall/gran)", "add 'surface tdem/clump'"])
    expect_error("notcompiled", scene("count", True).replace("tangential no_history surface", "tangential tdem/haff_werner surface"),
                 ["not compiled into tdem-liggghts", "surface tdem/clump"])
    # correction none with the keyword: a warning, and the run of the default surface model
    res = T.run(args.tdem, scene("none", True), d, "none_surface")
    out = res.stdout + res.stderr
    checks.check("WARNING" in out and "surface tdem/clump: no fix tdem/clump with a correction" in out,
                 "corrsurf: correction none with surface tdem/clump warns")
    T.run(args.tdem, scene("none", False), d, "none_default")
    a, b = thermo_rows(d, "none_surface"), thermo_rows(d, "none_default")
    checks.check(a.shape == b.shape and np.array_equal(a, b) and len(a) > 100,
                 "corrsurf: correction none: surface tdem/clump = surface default bitwise (%d rows)" % len(a))


# ----------------------------------------------------------------------------- local bodies (issue 20)
def thermo_lines(path):
    rows, on = [], False
    for line in open(path).read().splitlines():
        w = line.split()
        if w and w[0] == "Step":
            on = True
            continue
        if on and w and w[0].isdigit():
            rows.append(line)
        elif on and line.startswith("Loop time"):
            on = False
    return rows


def part_ranks(args, checks):
    """Tetra clumps and long rods (6 spheres, longer than half a sub-domain at 8 ranks; the fix extends
    the ghost cutoff) poured on -np 1, 2, 4 and 8 (processors 2 1 1, 2 2 1, 2 2 2): positions,
    velocities, spins and the fix's output bitwise equal."""
    grids = {1: "", 2: "processors 2 1 1\n", 4: "processors 2 2 1\n", 8: "processors 2 2 2\n"}
    for name, shape, n, nsph, corr in (("tetra", "tetra 0.003 0.0045", 40, 4, None),
                                       ("rods", "rod 0.002 0.0035 6", 24, 6, "overlap")):
        ref = None
        for np_ in (1, 2, 4, 8):
            d = T.workdir(args, "tdem_lig_clump_ranks_%s%d" % (name, np_))
            T.run(args.tdem, grids[np_] + pour_scene(NPOUR, nclump=n, correction=corr, shape=shape), d, "pour",
                  np_=np_, mpirun=args.mpirun)
            step, _, a = last_frame(d)
            thermo = thermo_lines(os.path.join(d, "log.pour"))
            if ref is None:
                ref = (a, thermo)
                fell = (T.read_dump(os.path.join(d, "dump.pour"))[0][2][:, 4] - a[:, 4]).max()
                checks.check(step == NPOUR and a.shape[0] == n * nsph and fell > 0.01,
                             "ranks %s: %d spheres fell %.3g m in %d steps" % (name, n * nsph, fell, NPOUR))
                continue
            split = 0
            for m in np.unique(a[:, 1]):
                p = a[a[:, 1] == m, 2:5]
                for k, mid in ((0, 0.03), (1, 0.03), (2, 0.06)):
                    if (np_ >= 2 and k == 0) or (np_ >= 4 and k == 1) or (np_ >= 8 and k == 2):
                        if p[:, k].min() < mid < p[:, k].max():
                            split += 1
                            break
            checks.check(np.array_equal(a, ref[0]), "ranks %s: -np %d equals -np 1 bitwise after %d steps (%d spheres)"
                         % (name, np_, NPOUR, n * nsph))
            checks.check(len(thermo) > 5 and thermo == ref[1],
                         "ranks %s: -np %d: thermo of f_c (scalar, vector, array elements) bitwise equal to -np 1"
                         % (name, np_))
            checks.check(split > 0, "ranks %s: -np %d: %d bodies with spheres on several ranks at the end"
                         % (name, np_, split))


CORR_NPOUR = 10000


def part_vtk(args, checks):
    """`vtk N prefix`: .vtu files and the .pvd series of the bodies, read back with the VTK library."""
    import vtk_read as vr
    every, n, dt = 500, 2000, 5e-6
    cols = " ".join("f_c[%d][%d]" % (i, j) for i in range(1, 41) for j in range(1, 18))

    def scene(steps, **kw):
        t = pour_scene(steps, **kw).replace("vel 0 0 -0.5", "vel 0 0 -0.5 vtk %d out/bodies" % every)
        return t.replace("thermo 1000", "thermo_style custom step %s\nthermo_modify format float %%.17g\n"
                                        "thermo %d" % (cols, every))
    res = {}
    for np_ in (1, 2):
        d = T.workdir(args, "tdem_lig_clump_vtk%d" % np_)
        os.makedirs(os.path.join(d, "out"))
        r = T.run(args.tdem, ("processors 2 1 1\n" if np_ == 2 else "") + scene(n), d, "pour", np_=np_,
                  mpirun=args.mpirun)
        res[np_] = (d, vr.read_pvd(os.path.join(d, "out", "bodies.pvd")), r.stdout)
    d, series, out = res[1]
    steps = list(range(0, n + 1, every))
    checks.check([os.path.basename(f) for _, f in series] == ["bodies_%d.vtu" % k for k in steps] and
                 all(abs(t - k * dt) <= 1e-18 for (t, _), k in zip(series, steps)),
                 "vtk: bodies.pvd lists %d files, every %d steps, at t = step*dt" % (len(series), every))
    blocks = {}
    for header, rows in T.thermo_blocks(out):
        for r in rows:
            w = r.split()
            blocks[int(w[0])] = np.array([float(v) for v in w[1:]]).reshape(40, 17)
    names = [("id", [0]), ("centre", [1, 2, 3]), ("velocity", [4, 5, 6]), ("orientation", [7, 8, 9, 10]),
             ("angular_momentum", [11, 12, 13]), ("omega", [14, 15, 16])]
    worst, compared = 0.0, 0
    for (t, f), k in zip(series, steps):
        ds = vr.read_dataset(f)
        checks.check(ds["time"] == t, "vtk: step %d: TimeValue %.17g is the series' time" % (k, ds["time"]))
        if k in blocks:
            for name, js in names:
                worst = max(worst, float(np.abs(ds["cell"][name].reshape(40, -1) - blocks[k][:, js]).max()))
            compared += 1
    checks.check(compared == len(steps) and worst == 0.0,
                 "vtk: the cells equal the fix's array at %d steps (max difference %.3g)" % (compared, worst))
    ds = vr.read_dataset(series[-1][1])
    step, _, a = last_frame(d)
    worst_p = edge = 0.0
    for c, mol in zip(ds["cells"], ds["cell"]["id"]):
        p = ds["points"][c]
        s = a[a[:, 1] == mol][:, 2:5]
        worst_p = max(worst_p, max(float(np.min(np.linalg.norm(s - q, axis=1))) for q in p))
        edge = max(edge, max(abs(np.linalg.norm(p[i] - p[j]) - 0.0045) for i in range(4) for j in range(i + 1, 4)))
    print("vtk: last file (step %d): points vs dumped spheres %.3g m, tetra edge error %.3g m" % (step, worst_p, edge))
    checks.check(step == n and len(ds["cells"]) == 40 and set(ds["types"]) == {2} and
                 np.all(ds["point"]["radius"] == 0.003), "vtk: 40 poly-vertex cells of 4 spheres of radius 0.003")
    checks.check(worst_p == 0.0 and edge <= 1e-15, "vtk: every point is a dumped sphere centre; rigid tetra of edge 0.0045")
    same = len(res[2][1]) == len(series)
    for (t1, f1), (t2, f2) in zip(series, res[2][1]):
        d1, d2 = vr.read_dataset(f1), vr.read_dataset(f2)
        same = same and t1 == t2 and np.array_equal(d1["points"], d2["points"]) and all(
            np.array_equal(d1["cell"][nm], d2["cell"][nm]) for nm, _ in names)
    checks.check(same, "vtk: -np 2 writes the same %d files as -np 1 (bitwise)" % len(series))
    # restart: run 1000 + write_restart, read_restart + run 1000 in the same directory (bitwise: part restart)
    d = T.workdir(args, "tdem_lig_clump_vtk_restart")
    os.makedirs(os.path.join(d, "out"))
    T.run(args.tdem, scene(n // 2, restart="mid.restart"), d, "first")
    T.run(args.tdem, scene(n // 2, read="mid.restart"), d, "second")
    s3 = vr.read_pvd(os.path.join(d, "out", "bodies.pvd"))
    ok = [os.path.basename(f) for _, f in s3] == ["bodies_%d.vtu" % k for k in steps]
    for (t1, f1), (t3, f3) in zip(series, s3):
        d1, d3 = vr.read_dataset(f1), vr.read_dataset(f3)
        ok = ok and np.array_equal(d1["cell"]["centre"], d3["cell"]["centre"])
    print("vtk: series after the restart: times %s" % [t for t, _ in s3])
    checks.check(ok, "vtk: after read_restart the series continues: %d files, bodies equal to the one run" % len(s3))
    checks.check(all(abs(a_ - b_) <= 1e-15 * max(b_, 1e-300) for (a_, _), (b_, _) in zip(s3, series)),
                 "vtk: the times of the continued series are the one run's")


def main():
    def extra(p):
        p.add_argument("--part", required=True,
                       choices=["nve", "torquefree", "flatface", "parallel", "restart", "insert", "bad", "examples", "periodic", "ranks",
                                "corrflat", "corrcont", "corrlocal", "corrpar", "corrwide", "corrstock", "corrsurf", "vtk"])
    args = T.parse_args(extra)
    checks = T.Checks()
    globals()["part_" + args.part](args, checks)
    checks.done()


if __name__ == "__main__":
    main()
