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

Where the stock fix wall/gran is not the classic code (LAMMPS from mid-2023 on, see
lmp_common.classic_walls) the stock side of 1-3 is the stock pair style with fix tdem/wall/gran
walls, run by the tdem executable (bitwise, as before); and the walls are compared on their own:
5. 60 spheres that do not meet each other, with random velocities and spins, hit a floor that
   wiggles, two side walls that shear and a cylinder (stock: wall/gran hooke/history planes and
   wall/gran/region with a cylinder region; tdem: tdem/wall/gran planes and zcylinder) for
   30000 steps: positions, velocities and spins agree to 1e-9 relative (rounding order only).
   In the versions whose stock walls have the friction defect LAMMPS fixed in 2026 (PR 5007,
   lmp_common.stock_wall_friction_sound) this comparison runs with frictionless walls, and a
   grazing impact (76 degrees from the normal, mu 0.5) is printed: stock vs tdem energy left.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.equivalence")
NSTEPS = 12000

CLASSIC = lc.classic_walls(args)
print("LAMMPS %s: stock walls are %s" % (args["version"], "the classic code" if CLASSIC else
      "GranularModel sub-models (the stock side uses tdem walls; walls compared in part 5)"))
for limit in (False, True):
    tag = "limit" if limit else "plain"
    wd = lc.workdir("equiv_" + tag)
    ref_exe, ref_inter = lc.stock_reference(args, limit=limit)
    _, out_s = lc.run(ref_exe, lc.scene(ref_inter, NSTEPS, "dump.stock"), wd, "in.stock")
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
law = lc.tdem_law()
st = "pair_style gran/hooke/history %s\npair_coeff * *\n" % stock_arg + "\n".join(
    ("fix w%d all wall/gran hooke/history %s %s" % (k, stock_arg, w)) if CLASSIC else
    ("fix w%d all tdem/wall/gran %s %s" % (k, law, w)) for k, w in enumerate(WALLS_CYL))
td = "pair_style tdem/gran\npair_coeff * * %s\n" % law + "\n".join(
    "fix w%d all tdem/wall/gran %s %s" % (k, law, w) for k, w in enumerate(WALLS_CYL))
wd = lc.workdir("equiv_cyl")
_, out_s = lc.run(args["lmp"] if CLASSIC else args["tdem"], CYL.format(interaction=st, dump="dump.stock"),
                  wd, "in.stock")
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

# ---- the walls on their own, where the stock walls are the sub-model code
WALLS_ALONE = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 0 0.2 units box
create_box      1 box
region          cyl cylinder z 0 0 0.045 -1 1 side in units box
{atoms}
set             group all density 2500
neighbor        0.001 bin
neigh_modify    delay 0
{interaction}
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        1e-5
compute         rke all erotate/sphere
thermo_style    custom step ke c_rke
run             30000
write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""
if not CLASSIC:
    import random
    rng = random.Random(3)
    pts = []
    while len(pts) < 60:  # centres at least 12 mm apart: the spheres (< 10 mm) do not meet at first
        p = (rng.uniform(-0.03, 0.03), rng.uniform(-0.03, 0.03), rng.uniform(0.01, 0.15))
        if all(sum((a - b) ** 2 for a, b in zip(p, q)) > 0.012 ** 2 for q in pts):
            pts.append(p)
    lines = []
    for i, p in enumerate(pts):
        lines.append("create_atoms    1 single %r %r %r units box" % p)
        lines.append("set             atom %d diameter %r" % (i + 1, rng.uniform(0.006, 0.01)))
        lines.append("set             atom %d vx %r vy %r vz %r" % ((i + 1,) + tuple(rng.uniform(-0.5, 0.5) for _ in range(3))))
        lines.append("set             atom %d omega %r %r %r" % ((i + 1,) + tuple(rng.uniform(-50, 50) for _ in range(3))))
    atoms = "\n".join(lines)
    walls = ("zplane 0 NULL wiggle z 0.001 20", "xplane -0.04 0.04 shear y 0.05")
    sound = lc.stock_wall_friction_sound(args)
    if not sound:
        stock_arg = "2000 600 50 25 0.0 1"
        law = lc.tdem_law(mu=0.0)
        print("walls alone: LAMMPS %s has the stock-wall friction defect fixed in 2026 (PR 5007): "
              "compared without friction" % args["version"])
    # no pair interaction: every sphere meets only walls
    st = "pair_style zero 0.011\npair_coeff * *\n" + "\n".join(
        "fix w%d all wall/gran hooke/history %s %s" % (k, stock_arg, w) for k, w in enumerate(walls)) + \
        "\nfix wc all wall/gran/region hooke/history %s region cyl" % stock_arg
    td = "pair_style zero 0.011\npair_coeff * *\n" + "\n".join(
        "fix w%d all tdem/wall/gran %s %s" % (k, law, w) for k, w in enumerate(walls)) + \
        "\nfix wc all tdem/wall/gran %s zcylinder 0.045" % law
    wd = lc.workdir("equiv_walls")
    lc.run(args["lmp"], WALLS_ALONE.format(atoms=atoms, interaction=st, dump="dump.stock"), wd, "in.stock")
    lc.run(args["tdem"], WALLS_ALONE.format(atoms=atoms, interaction=td, dump="dump.tdem"), wd, "in.tdem")
    cols, a = lc.read_dump(os.path.join(wd, "dump.tdem"))
    _, b = lc.read_dump(os.path.join(wd, "dump.stock"))
    per, worst = lc.rel_diff(a[:, 1:], b[:, 1:])
    print("walls alone (stock sub-model walls vs tdem/wall/gran): max relative difference per column %s: %s"
          % (cols[1:], ["%.3g" % x for x in per]))
    r = (a[:, cols.index("x")] ** 2 + a[:, cols.index("y")] ** 2) ** 0.5
    chk.check(a.shape == b.shape and worst <= 1e-9,
              "walls alone: tdem/wall/gran equals stock wall/gran (+ region cylinder) to 1e-9 (max %.3g)" % worst)
    chk.check(r.max() < 0.045 and a[:, cols.index("z")].min() > 0, "walls alone: the walls hold the spheres")
    # a grazing frictional impact on a plane: the energy each wall leaves
    GRAZE = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
region          box block -0.5 0.5 -0.05 0.05 0 0.2 units box
create_box      1 box
create_atoms    1 single 0.0 0.0 0.0041 units box
set             atom 1 diameter 0.008
set             atom 1 vx %r vz %r
set             group all density 2500
pair_style      zero 0.011
pair_coeff      * *
{wall}
fix             nve all nve/sphere
timestep        1e-6
compute         r all erotate/sphere
variable        e equal 0.5*mass[1]*(vx[1]^2+vy[1]^2+vz[1]^2)+c_r
thermo_style    custom step v_e
thermo_modify   format float %%.15g
thermo          20000
run             20000
""" % (math.sin(math.radians(76)), -math.cos(math.radians(76)))
    ws = "fix w all wall/gran hooke/history 2000 600 50 25 0.5 1 zplane 0 NULL"
    wt = "fix w all tdem/wall/gran %s zplane 0 NULL" % lc.tdem_law()
    _, os_ = lc.run(args["lmp"], GRAZE.format(wall=ws), wd, "in.graze_stock")
    _, ot = lc.run(args["tdem"], GRAZE.format(wall=wt), wd, "in.graze_tdem")
    es = [float(r.split()[1]) for r in lc.thermo_blocks(os_)[1:]]
    et = [float(r.split()[1]) for r in lc.thermo_blocks(ot)[1:]]
    print("grazing impact (76 deg, mu 0.5): energy left, stock wall/gran %.6f, tdem/wall/gran %.6f"
          % (es[-1] / es[0], et[-1] / et[0]))
    chk.check(et[-1] < et[0], "grazing impact: tdem/wall/gran dissipates (%.6f of the energy left)" % (et[-1] / et[0]))
    if sound:
        chk.check(abs(es[-1] - et[-1]) <= 1e-9 * es[0],
                  "grazing impact: stock and tdem walls leave the same energy (%.9f, %.9f)" % (es[-1] / es[0], et[-1] / et[0]))
chk.done()
