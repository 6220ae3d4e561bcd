#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""normal thornton in pair tdem/gran and fix tdem/wall/gran.

1. Restitution vs Thornton's closed form (physics_reference 2.2.4), re-implemented here:
     k~ = 4/3 E* sqrt(R*), xi_y = R* (pi p_y/(2 E*))^2, v_y^2 = 4 k~ xi_y^(5/2)/(5 m*),
     r = v_y/v0 < 1: e = [6 sqrt(3)/5 (1 - r^2/6)]^(1/2) [r/(r + 2 sqrt(6/5 - r^2/5))]^(1/4),
     v0 <= v_y: e = 1.
   Wall (E*, R* = R from sphere and wall materials) and head-on (two types, E* mixed from
   pair_coeff I I and J J). About 1000 steps per contact (dt from the elastic Hertz contact
   time); tolerance 2e-3 relative (the velocity-Verlet error at this resolution is ~1e-5).
2. Restart during unloading (xi_max, f_max in the pair and wall history): equals run N + run M
   within 1e-10; a control that loses the history differs. -np 2 (newton on) with both
   contacts crossing the processor boundary equals -np 1 within 1e-10.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.thornton")
STEPS = 1000
TOL = 2.0 / STEPS
RHO = 2500.0
R = 0.005
E1, NU1, E2, NU2 = 1.0e9, 0.3, 3.0e9, 0.25
PY = 2.0e7


def estar(e1, n1, e2, n2):
    return 1.0 / ((1 - n1 * n1) / e1 + (1 - n2 * n2) / e2)


def mass(r):
    return RHO * 4.0 / 3.0 * math.pi * r ** 3


def v_yield(es, reff, meff):
    k = 4.0 / 3.0 * es * math.sqrt(reff)
    xi_y = reff * (math.pi * PY / (2 * es)) ** 2
    return math.sqrt(4 * k * xi_y ** 2.5 / (5 * meff)), k


def e_thornton(r):
    if r >= 1:
        return 1.0
    return math.sqrt(6 * math.sqrt(3) / 5 * (1 - r * r / 6)) * (
        r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25


HEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          {newton}
comm_modify     vel yes
{processors}
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      2 box
{atoms}
set             group all density {rho}
neighbor        0.001 bin
neigh_modify    delay 0 every 1 check yes
{inter}
fix             nve all nve/sphere
timestep        {dt!r}
"""


def law(mat):
    return "normal thornton %s %r tangential cundall_strack 0.8 0.3" % (mat, PY)


MAT1 = "%r %r" % (E1, NU1)
MAT2 = "%r %r" % (E2, NU2)
PAIR = "pair_style tdem/gran\npair_coeff 1 1 %s\npair_coeff 2 2 %s" % (law(MAT1), law(MAT2))
WALL = "fix floor all tdem/wall/gran %s zplane 0 NULL" % law(MAT1 + " " + MAT2)

# ------------------------------------------------------------------ 1. restitution
for geom, ratio in (("wall", 0.5), ("wall", 0.2), ("wall", 2.0), ("head-on", 0.3)):
    wall = geom == "wall"
    if wall:
        es, reff, meff = estar(E1, NU1, E2, NU2), R, mass(R)
    else:
        es, reff, meff = estar(E1, NU1, E2, NU2), R / 2, mass(R) / 2
    vy, k = v_yield(es, reff, meff)
    v0 = float("%.6g" % (vy / ratio))
    r = vy / v0
    e_exp = e_thornton(r)
    tc_el = 2.94328 * (5 * meff * v0 * v0 / (4 * k)) ** 0.4 / v0
    dt = float("%.6g" % (tc_el / STEPS))
    gap = 20
    if wall:
        atoms = ("create_atoms 1 single 0 0 %r units box\nset atom 1 diameter %r\n"
                 "velocity all set 0 0 0\nset atom 1 vz %r" % (R + gap * dt * v0, 2 * R, -v0))
        inter = PAIR + "\n" + WALL
        vrel = "vz[1]"
    else:
        atoms = ("create_atoms 1 single 0 0 0.05 units box\ncreate_atoms 2 single 0 0 %r units box\n"
                 "set group all diameter %r\nvelocity all set 0 0 0\nset atom 1 vz %r\nset atom 2 vz %r"
                 % (0.05 + 2 * R + gap * dt * v0, 2 * R, v0 / 2, -v0 / 2))
        inter = PAIR
        vrel = "vz[2]-vz[1]"
    text = HEAD.format(newton="off", processors="", atoms=atoms, rho=RHO, inter=inter, dt=dt)
    text += "run %d\nprint \"RES $(%s:%%.17g)\"\n" % (gap + 3 * STEPS, vrel)
    wd = lc.workdir("th_%s_%g" % (geom, ratio))
    _, out = lc.run(args["tdem"], text, wd)
    vout = float(next(l for l in out.splitlines() if l.startswith("RES ")).split()[1])
    e_m = vout / v0
    de = e_m / e_exp - 1
    print("%s v0/v_y = %.2f: e %.6f (expected %.6f, rel err %+.2e)" % (geom, 1 / r, e_m, e_exp, de))
    chk.check(abs(de) <= TOL, "%s v0/v_y = %.2f: restitution within %.2g" % (geom, 1 / r, TOL))

# ------------------------------------------------------------------ 2. restart and -np 2
es = estar(E1, NU1, E2, NU2)
vy, k = v_yield(es, R / 2, mass(R) / 2)
V0 = float("%.4g" % (4 * vy))
tc_el = 2.94328 * (5 * mass(R) / 2 * V0 * V0 / (4 * k)) ** 0.4 / V0
DT = float("%.4g" % (tc_el / STEPS))
DRIFT = 2.0 * 0.005 / tc_el  # the contacts move 10 mm per contact time
GAP = 20 * DT * V0
ATOMS = ("create_atoms 1 single %r 0 0.05 units box\ncreate_atoms 2 single %r 0 0.05 units box\n"
         "create_atoms 1 single %r 0 %r units box\nset group all diameter %r\n"
         "velocity all set 0 0 0\nset atom 1 vx %r\nset atom 2 vx %r\nset atom 3 vx %r vz %r"
         % (-0.0025 - R, -0.0025 + R + GAP, -0.0025 - 20 * DT * DRIFT, R + GAP, 2 * R,
            -DRIFT + V0 / 2, -DRIFT - V0 / 2, DRIFT, -V0))
REPORT = "".join('print "RES $(x[%d]:%%.17g) $(z[%d]:%%.17g) $(vx[%d]:%%.17g) $(vz[%d]:%%.17g)"\n'
                 % (k, k, k, k) for k in (1, 2, 3))


def results(out):
    vals = []
    for line in out.splitlines():
        if line.startswith("RES "):
            vals += [float(x) for x in line.split()[1:]]
    return vals


def worst(a, b):
    assert len(a) == len(b) and a
    return max(abs(x - y) / max(abs(x), abs(y), 1e-300) for x, y in zip(a, b))


N1, N2 = 20 + 800, 1200  # both contacts unloading at N1 (loading ends after ~500 steps)
wd = lc.workdir("th_restart")
base = HEAD.format(newton="off", processors="", atoms=ATOMS, rho=RHO, inter=PAIR + "\n" + WALL, dt=DT)
_, ref = lc.run(args["tdem"], base + "run %d\nrun %d\n" % (N1, N2) + REPORT, wd, "in.ref")
lc.run(args["tdem"], base + "run %d\nwrite_restart th.restart\n" % N1, wd, "in.first")
second = ("atom_modify map array\nread_restart th.restart\nneighbor 0.001 bin\n"
          "neigh_modify delay 0 every 1 check yes\ncomm_modify vel yes\n%s\n"
          "fix nve all nve/sphere\ntimestep %r\nrun %d\n" % (WALL, DT, N2) + REPORT)
_, rs = lc.run(args["tdem"], second, wd, "in.second")
lost = second.replace("fix floor all", "pair_style none\n%s\nfix floor2 all" % PAIR)
_, ls = lc.run(args["tdem"], lost, wd, "in.lost")
r_ref, r_rs, r_ls = results(ref), results(rs), results(ls)
w = worst(r_ref, r_rs)
print("restart mid-collision: max rel diff %.3g; history lost: pair dvx %.3g, wall dvz %.3g"
      % (w, r_ls[2] - r_ref[2], r_ls[11] - r_ref[11]))
chk.check(w <= 1e-10, "restart mid-collision equals run N + run M (max rel diff %.3g)" % w)
chk.check(abs(r_ls[2] - r_ref[2]) > 1e-3 * V0 and abs(r_ls[11] - r_ref[11]) > 1e-3 * V0,
          "control: losing the pair and wall history changes the rebound")
e_pair = (r_ref[6] - r_ref[2]) / V0
e_wall = r_ref[11] / V0
print("scene: pair e %.5f (expected %.5f)" % (e_pair, e_thornton(0.25)))
print("scene: wall e %.5f (expected %.5f; v_y of the wall contact is 2 v_y of the pair)"
      % (e_wall, e_thornton(0.5)))
chk.check(abs(e_pair / e_thornton(0.25) - 1) < TOL and abs(e_wall / e_thornton(0.5) - 1) < TOL,
          "scene: pair and wall rebounds match the closed form")

if args.get("mpirun"):
    outs = []
    wd = lc.workdir("th_np2")
    for np_ in (1, 2):
        text = HEAD.format(newton="on", processors="processors 2 1 1" if np_ == 2 else "", atoms=ATOMS,
                           rho=RHO, inter=PAIR + "\n" + WALL, dt=DT) + "run %d\n" % (N1 + N2) + REPORT
        _, out = lc.run(args["tdem"], text, wd, "in.np%d" % np_, np_=np_, mpirun=args["mpirun"])
        outs.append(results(out))
    w = worst(outs[0], outs[1])
    print("newton on: -np 2 vs -np 1 max rel diff %.3g (x at the end: atom 2 %.4f, atom 3 %.4f)"
          % (w, outs[1][4], outs[1][8]))
    chk.check(w <= 1e-10, "-np 2 equals -np 1 (max rel diff %.3g)" % w)
chk.done()
