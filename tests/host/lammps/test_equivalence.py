#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Equivalence of pair tdem/gran + fix tdem/wall/gran with the stock LAMMPS styles.

1. settling bed (2592 spheres, 6 walls, gravity, 20000 steps): stock gran/hooke/history +
   wall/gran hooke/history run by /usr/bin/lmp vs tdem/gran + tdem/wall/gran (normal lsd
   stiffness, damping mass) run by tdem-lammps. Positions, velocities and angular velocities
   (dump sorted by id, %.17g) must agree to 1e-8 relative; the thermo output must be equal.
2. the same with limit_damping (stock) vs limit_force yes (tdem).
   Also the run-time dispatch path: a second atom type without atoms gets a different law
   variant (restitution mode), so the pair style cannot use its compile-time specialisation;
   the result must still equal the stock run bit for bit.
3. wall motion and the cylinder wall: spheres in a zcylinder on a floor that wiggles along z,
   between two xplane walls that shear along y (stock wall/gran vs tdem/wall/gran): bitwise.
4. pair granular (hooke, damping mass_velocity, tangential linear_history): that style places
   the contact point at r_i - delta/2 for torques and rotates the tangential history with a
   magnitude-preserving projection, so many-body trajectories cannot agree; the comparison
   uses head-on collisions of sphere pairs (no tangential force, so only the normal law acts)
   along x, y and a diagonal with different masses: velocities after the impacts must agree
   to 1e-10 relative (different rounding order only).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.equivalence")
NSTEPS = 12000

for limit in (False, True):
    tag = "limit" if limit else "plain"
    wd = lc.workdir("equiv_" + tag)
    _, out_s = lc.run(args["lmp"], lc.scene(lc.stock_interaction(limit=limit), NSTEPS, "dump.stock"),
                      wd, "in.stock")
    _, out_t = lc.run(args["tdem"], lc.scene(lc.tdem_interaction(limit=limit), NSTEPS, "dump.tdem"),
                      wd, "in.tdem")
    cols, a = lc.read_dump(os.path.join(wd, "dump.tdem"))
    _, b = lc.read_dump(os.path.join(wd, "dump.stock"))
    chk.check(a.shape == b.shape and a.shape[0] == 2592, "%s: %d atoms in both dumps" % (tag, a.shape[0]))
    per, worst = lc.rel_diff(a[:, 1:], b[:, 1:])
    nbits = int((a != b).sum())
    print("%s: max relative difference per column %s: %s" % (tag, cols[1:], ["%.3g" % x for x in per]))
    print("%s: max relative difference %.3g, differing values %d of %d" % (tag, worst, nbits, a.size))
    chk.check(worst <= 1e-8, "%s: x, v, omega agree to 1e-8 relative (max %.3g)" % (tag, worst))
    ts, tt = lc.thermo_blocks(out_s), lc.thermo_blocks(out_t)
    chk.check(len(ts) > 5 and ts == tt, "%s: thermo output identical (%d lines)" % (tag, len(ts)))
    if not limit:
        wd2 = wd
        rt = lc.scene(lc.tdem_interaction(limit=False) +
                      "\npair_coeff 2 2 normal lsd restitution 0.5 1e-4 tangential cundall_strack 1 0.5",
                      NSTEPS, "dump.runtime").replace("create_box      1 box", "create_box      2 box")
        lc.run(args["tdem"], rt, wd, "in.runtime")
        _, c = lc.read_dump(os.path.join(wd, "dump.runtime"))
        _, w = lc.rel_diff(c[:, 1:], b[:, 1:])
        print("run-time dispatch: max relative difference %.3g" % w)
        chk.check(w <= 1e-8, "run-time dispatch (mixed law variants): equals stock (max %.3g)" % w)
    # the particles really moved and touched: the bed settled
    z = a[:, cols.index("z")]
    chk.check(z.max() < 0.045, "%s: bed settled below its initial top (max z %.4f)" % (tag, z.max()))

# ---- cylinder, wiggling floor, shearing side walls
CYL = """
units           si
atom_style      sphere
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 0 0.2 units box
create_box      1 box
lattice         sc 0.0052
region          fill cylinder z 0 0 0.03 0.003 0.06 units box
create_atoms    1 region fill
variable        d atom 0.0040+0.0008*random(0,1,4711)
set             group all diameter v_d
set             group all density 2500
velocity        all set 0 0 -0.1
neighbor        0.001 bin
neigh_modify    delay 0
{interaction}
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
thermo_style    custom step atoms ke
thermo_modify   format float %.15g
thermo          1000
compute         pl all pair/local dist force p1 p2 p3 p4 p5 p6 p7 p8 p9 p10
dump            pl all local 6000 {dump}.local c_pl[*]
dump_modify     pl format float %.17g
run             6000
write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""
WALLS_CYL = ("zcylinder 0.035", "zplane 0 NULL wiggle z 0.001 0.01", "xplane -0.025 0.025 shear y 0.05")
stock_arg = "2000 600 50 25 0.5 1"
st = "pair_style gran/hooke/history %s\npair_coeff * *\n" % stock_arg + "\n".join(
    "fix w%d all wall/gran hooke/history %s %s" % (k, stock_arg, w) for k, w in enumerate(WALLS_CYL))
law = lc.tdem_law()
td = "pair_style tdem/gran\npair_coeff * * %s\n" % law + "\n".join(
    "fix w%d all tdem/wall/gran %s %s" % (k, law, w) for k, w in enumerate(WALLS_CYL))
wd = lc.workdir("equiv_cyl")
_, out_s = lc.run(args["lmp"], CYL.format(interaction=st, dump="dump.stock"), wd, "in.stock")
_, out_t = lc.run(args["tdem"], CYL.format(interaction=td, dump="dump.tdem"), wd, "in.tdem")
cols, a = lc.read_dump(os.path.join(wd, "dump.tdem"))
_, b = lc.read_dump(os.path.join(wd, "dump.stock"))
_, worst = lc.rel_diff(a[:, 1:], b[:, 1:])
r = (a[:, cols.index("x")] ** 2 + a[:, cols.index("y")] ** 2) ** 0.5
print("cylinder/wiggle/shear: %d atoms, max relative difference %.3g, max radius %.4f" % (a.shape[0], worst, r.max()))
chk.check(a.shape == b.shape and worst <= 1e-8, "cylinder + wiggle + shear walls: equal to stock (max %.3g)" % worst)
chk.check(lc.thermo_blocks(out_s) == lc.thermo_blocks(out_t), "cylinder + wiggle + shear walls: thermo identical")
chk.check(r.max() < 0.035, "cylinder wall holds the spheres (max radius %.4f < 0.035)" % r.max())


def read_local(path):
    lines = open(path).read().splitlines()
    k = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ENTRIES"))
    import numpy as np
    return np.array([[float(x) for x in l.split()] for l in lines[k + 1:] if l.strip()])


la, lb = read_local(os.path.join(wd, "dump.tdem.local")), read_local(os.path.join(wd, "dump.stock.local"))
_, wl = lc.rel_diff(la, lb) if la.shape == lb.shape and la.size else (None, float("inf"))
print("compute pair/local (single()): %d pairs, max relative difference %.3g" % (len(la), wl))
chk.check(la.shape == lb.shape and len(la) > 20 and wl <= 1e-12,
          "pair tdem/gran single(): compute pair/local force and p1..p10 equal stock (max %.3g)" % wl)

# ---- pair granular, head-on collisions
HEADON = """
units           si
atom_style      sphere
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -1 1 -1 1 -1 1 units box
create_box      1 box
create_atoms    1 single -0.0030 0.3 0 units box
create_atoms    1 single  0.0030 0.3 0 units box
create_atoms    1 single  0.3 -0.0030 0 units box
create_atoms    1 single  0.3  0.0030 0 units box
create_atoms    1 single -0.3 -0.3021 -0.3021 units box
create_atoms    1 single -0.3 -0.2979 -0.2979 units box
set             atom 1 diameter 0.004
set             atom 2 diameter 0.006
set             atom 3 diameter 0.005
set             atom 4 diameter 0.005
set             atom 5 diameter 0.003
set             atom 6 diameter 0.0045
set             group all density 2500
velocity        all set 0 0 0
set             atom 1 vx 0.5
set             atom 2 vx -0.3
set             atom 3 vy 0.4
set             atom 4 vy -0.4
set             atom 5 vy 0.2
set             atom 5 vz 0.2
set             atom 6 vy -0.1
set             atom 6 vz -0.1
neighbor        0.002 bin
neigh_modify    delay 0
{interaction}
fix             nve all nve/sphere
timestep        1e-6
thermo          1000
run             6000
write_dump      all custom {dump} id x y z vx vy vz modify sort id format float %.17g
"""
wd = lc.workdir("equiv_granular")
gran = "pair_style granular\npair_coeff * * hooke 2000 50 tangential linear_history 600 0.5 0.5 damping mass_velocity"
lc.run(args["lmp"], HEADON.format(interaction=gran, dump="dump.gran"), wd, "in.gran")
lc.run(args["tdem"], HEADON.format(interaction=lc.tdem_interaction(walls=False), dump="dump.tdem"),
       wd, "in.tdem")
cols, a = lc.read_dump(os.path.join(wd, "dump.tdem"))
_, b = lc.read_dump(os.path.join(wd, "dump.gran"))
v = [cols.index(c) for c in ("vx", "vy", "vz")]
per, worst = lc.rel_diff(a[:, v], b[:, v])
print("granular head-on: max relative velocity difference %.3g" % worst)
# every pair collided and separated: the velocities changed sign
chk.check(a[0, v[0]] < 0 and a[1, v[0]] > 0 and a[2, v[1]] < 0 and a[3, v[1]] > 0 and a[4, v[1]] < 0,
          "granular head-on: all pairs rebounded")
chk.check(worst <= 1e-10, "granular head-on: velocities agree with pair granular to 1e-10 (max %.3g)" % worst)
chk.done()
