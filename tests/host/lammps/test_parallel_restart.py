#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""MPI and restart behaviour of pair tdem/gran + fix tdem/wall/gran (settling bed scene, 12000 steps).

1. -np 2 (processors 2 1 1, atoms and their pair and wall histories migrate between the ranks
   while the bed settles): the tdem run equals the stock gran/hooke/history run on the same two
   ranks bit for bit (same decomposition, same summation order) -- a test of the history
   migration against the stock implementation; and its statistics match the -np 1 run. The
   -np 1 and -np 2 trajectories differ by round-off that grows chaotically, so only
   bulk statistics are compared: mean height and top of the settled bed within 2 % (one
   particle diameter is ~20 % of the mean height; 2 % is ~ 1/10 of a diameter), same number of
   atoms, kinetic energy after settling below 10 % of the initial kinetic energy in both.
2. restart: 6000 steps + write_restart, then read_restart (pair style and coefficients come
   from the restart file; the wall fixes are defined again and get their per-atom history back)
   + M = 300 steps must equal one input that does `run 6000` then `run 300`. (Every LAMMPS
   `run` starts with a set-up force evaluation using full-step velocities, where a running
   velocity-Verlet step uses half-step velocities; with velocity-dependent contact forces a
   run boundary therefore changes the trajectory slightly, for the stock styles as well, so
   the reference must have the same run boundary. The difference to a single `run 6300` is
   printed for information.) LAMMPS builds new neighbour lists after read_restart, so forces
   may be summed in a different order (1-ulp differences that the chaotic flow amplifies over
   thousands of steps); over 300 steps the runs must agree to 1e-10 relative. A control run that loses the wall history (the wall fixes get new IDs)
   must differ by more than 1e-6, which shows the check can fail.
3. The laws with per-contact history added later (power_law: xi_max, ...; extended_linear: v0, k,
   gamma; extended_hertz: v0, alpha), each in pair tdem/gran and fix tdem/wall/gran:
   a. restart in the middle of a collision: a head-on pair and a sphere hitting the floor, both
      unloading at the restart (checked: contact forces on, normal velocities separating);
      write_restart / read_restart / run M equals run N + run M within 1e-10 relative; a control
      that loses the pair and wall history (styles defined anew) changes the rebound by > 1e-3.
   b. -np 2 (processors 2 1 1) = -np 1 within 1e-10 relative for that scene, in which one atom of
      the pair and the wall-sliding sphere cross the processor boundary during their contacts
      (their histories migrate mid-contact), newton off and on.
   c. -np 2 = -np 1 for a small bed (175 spheres from a data file, so the atom IDs do not depend
      on the processor grid; random-free velocities) falling on the floor, 3000 steps of dense
      collisions, pair and wall histories of all three laws, newton off and on: max relative
      difference <= 1e-8 (forces are summed in a different order on two ranks, so the runs
      differ by round-off that the collisions amplify: ~1e-11 after 3000 steps, 1e-2 after 8000).
   (Observation: stock gran/hooke/history itself is not restart-exact in LAMMPS 29Sep2021:
   its read_restart_settings leaves limit_damping uninitialised.)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.parallel_restart")
N = 12000

# ---------------------------------------------------------------- 1. -np 2
wd = lc.workdir("np")
lc.run(args["tdem"], lc.scene(lc.tdem_interaction(), N, "dump.np1"), wd, "in.np1")
_, out2 = lc.run(args["tdem"], lc.scene(lc.tdem_interaction(), N, "dump.np2", processors="processors 2 1 1"),
                 wd, "in.np2", np_=2, mpirun=args["mpirun"])
ref_exe, ref_inter = lc.stock_reference(args)  # stock walls, or tdem walls where they are not classic
_, outs2 = lc.run(ref_exe, lc.scene(ref_inter, N, "dump.stock2", processors="processors 2 1 1"),
                  wd, "in.stock2", np_=2, mpirun=args["mpirun"])
cols, a1 = lc.read_dump(os.path.join(wd, "dump.np1"))
_, a2 = lc.read_dump(os.path.join(wd, "dump.np2"))
_, s2 = lc.read_dump(os.path.join(wd, "dump.stock2"))
chk.check("2 by 1 by 1 MPI processor grid" in out2, "np2: ran on a 2x1x1 grid")
per, worst = lc.rel_diff(a2[:, 1:], s2[:, 1:])
print("np2 tdem vs np2 stock: max relative difference %.3g (%d differing values)" % (worst, int((a2 != s2).sum())))
chk.check(worst <= 1e-8, "np2: tdem equals stock gran/hooke/history on 2 ranks (max rel diff %.3g)" % worst)
chk.check(lc.thermo_blocks(out2) == lc.thermo_blocks(outs2), "np2: thermo identical to stock on 2 ranks")
z = cols.index("z")
m1, m2 = a1[:, z].mean(), a2[:, z].mean()
t1, t2 = np.percentile(a1[:, z], 99), np.percentile(a2[:, z], 99)
print("np1 vs np2: mean z %.6f vs %.6f (%.2e), 99th percentile z %.6f vs %.6f (%.2e); trajectories differ: %s"
      % (m1, m2, m2 / m1 - 1, t1, t2, t2 / t1 - 1, bool((a1 != a2).any())))
chk.check(a1.shape == a2.shape, "np1 vs np2: same number of atoms (%d)" % a2.shape[0])
chk.check(abs(m2 / m1 - 1) < 0.02, "np1 vs np2: mean height within 2 %")
chk.check(abs(t2 / t1 - 1) < 0.02, "np1 vs np2: bed top within 2 %")
v = [cols.index(c) for c in ("vx", "vy", "vz")]
ke1, ke2 = (a1[:, v] ** 2).sum(), (a2[:, v] ** 2).sum()
ke0 = 2592 * 3 * (0.05 ** 2) / 12  # initial: uniform in +-0.025 m/s per component
chk.check(ke1 < 0.1 * ke0 and ke2 < 0.1 * ke0, "np1, np2: bed settled (sum v^2 %.3g, %.3g vs initial %.3g)" % (ke1, ke2, ke0))

# ---------------------------------------------------------------- 2. restart
NR, M = 6000, 300
EVERY = "neigh_modify    delay 0"
wd = lc.workdir("restart")
text = lc.scene(lc.tdem_interaction(), "%d\nrun             %d" % (NR, M), "dump.full")
lc.run(args["tdem"], text, wd, "in.full")
lc.run(args["tdem"], lc.scene(lc.tdem_interaction(), NR + M, "dump.single"), wd, "in.single")
text1 = lc.scene(lc.tdem_interaction(), NR, "dump.half")
text1 += "write_restart   bed.restart\n"
lc.run(args["tdem"], text1, wd, "in.part1")

walls = "\n".join(l for l in lc.tdem_interaction().splitlines() if l.startswith("fix"))
PART2 = """
read_restart    bed.restart
comm_modify     vel yes
neighbor        0.001 bin
{every}
{walls}
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
compute         rke all erotate/sphere
thermo_style    custom step atoms ke c_rke
thermo_modify   format float %.15g
thermo          1000
run             {n}
write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""
_, outr = lc.run(args["tdem"], PART2.format(every=EVERY, walls=walls, n=M, dump="dump.restarted"), wd, "in.part2")
walls_new = walls.replace("fix w", "fix new_w")
lc.run(args["tdem"], PART2.format(every=EVERY, walls=walls_new, n=M, dump="dump.lost"), wd, "in.part2lost")
cols, full = lc.read_dump(os.path.join(wd, "dump.full"))
_, rest = lc.read_dump(os.path.join(wd, "dump.restarted"))
_, lost = lc.read_dump(os.path.join(wd, "dump.lost"))
_, single = lc.read_dump(os.path.join(wd, "dump.single"))
print("information: run 6000 + run 300 vs a single run 6300: max relative difference %.3g"
      % lc.rel_diff(full[:, 1:], single[:, 1:])[1])
per, worst = lc.rel_diff(rest[:, 1:], full[:, 1:])
_, worst_lost = lc.rel_diff(lost[:, 1:], full[:, 1:])
print("restart: max relative difference %.3g (%d differing values); control without wall history: %.3g"
      % (worst, int((rest != full).sum()), worst_lost))
chk.check(worst <= 1e-10, "restart: 6000 + write/read_restart + 300 steps equal run 6000 + run 300 (max rel diff %.3g)" % worst)
chk.check(worst_lost > 1e-6, "restart control: losing the wall history changes the result (%.3g)" % worst_lost)

# ---------------------------------------------------------------- 3. laws with history
TSL = "tangential cundall_strack 0.8 0.3"
RS = 0.005
MS = 0.01
# law, its wall contact time at 1 m/s (scene design: where to restart), time step
HLAWS = [("power_law", "normal power_law 1e7 1.5 2.915e7 " + TSL, 6.9e-4, 1e-6),
         ("extended_linear", "normal extended_linear e_fit rational 1 1 0.2 tc_fit power 1e-3 0.2 v_max 20 "
          + TSL + " limit_force yes", 1.0e-3, 1.4e-6),
         ("extended_hertz", "normal extended_hertz 1e9 0.3 e_fit power 0.1 0.1 " + TSL, 4.6e-4, 6e-7),
         # no normal history: the restart carries its coefficients (EPS N GAMMA by the law's name);
         # the lost-history control does not apply. Elastic: wall t_c 1.19e-3, pair 2.02e-3 (d = 2R);
         # 1.5e-3 puts the restart (at 0.7 of it) where both contacts unload
         ("continuous_potential", "normal continuous_potential 2e-4 36 0 " + TSL, 1.5e-3, 1e-6)]
NO_NORMAL_HISTORY = ("continuous_potential",)
HHEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          {newton}
comm_modify     vel yes
{processors}
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 box
"""
HTAIL = """
neighbor        0.001 bin
neigh_modify    delay 0 every 1 check yes
fix             nve all nve/sphere
timestep        {dt!r}
"""
HREPORT = "".join('print "RES %d $(x[%d]:%%.17g) $(z[%d]:%%.17g) $(vx[%d]:%%.17g) $(vz[%d]:%%.17g)"\n'
                  % (k, k, k, k, k) for k in (1, 2, 3))
HSTATE = ('print "STATE $(fx[1]:%.17g) $(fz[3]:%.17g) $(vx[2]-vx[1]:%.17g) $(vz[3]:%.17g)"\n')


def hatoms(dt):
    # pair along x: relative speed 1, drift -5 m/s (atom 2 crosses x = 0 in contact); atom 3
    # hits the floor at 1 m/s while sliding at +5 m/s across x = 0; both touch at step 20
    gap = 20 * dt
    specs = [(-0.0025 - RS, 0.05, -4.5, 0.0), (-0.0025 + RS + gap, 0.05, -5.5, 0.0),
             (-0.0025 - gap * 5.0, RS + gap, 5.0, -1.0)]
    out = ["create_atoms 1 single %r 0 %r units box" % (x, z) for x, z, _, _ in specs]
    for k, (x, z, vx, vz) in enumerate(specs, 1):
        out.append("set atom %d diameter %r\nset atom %d mass %r\nset atom %d vx %r vz %r"
                   % (k, 2 * RS, k, MS, k, vx, vz))
    return "\n".join(out)


def hresults(out, key="RES"):
    vals = []
    for line in out.splitlines():
        if line.startswith(key + " "):
            vals += [float(x) for x in line.split()[1 if key == "STATE" else 2:]]
    return vals


def hworst(a, b):
    assert len(a) == len(b) and a, (a, b)
    return max(abs(x - y) / max(abs(x), abs(y), 1e-300) for x, y in zip(a, b))


for name, law, tcw, dt in HLAWS:
    inter = ("pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL\n"
             % (law, law))
    n1 = 20 + int(0.7 * tcw / dt)
    n2 = int(0.8 * tcw / dt) + 100
    wd = lc.workdir("hist_" + name)
    base = HHEAD.format(newton="off", processors="") + hatoms(dt) + "\n" + inter + HTAIL.format(dt=dt)
    _, ref = lc.run(args["tdem"], base + "run %d\nrun %d\n" % (n1, n2) + HREPORT, wd, "in.ref")
    _, first = lc.run(args["tdem"], base + "run %d\n" % n1 + HSTATE + "write_restart h.restart\n", wd, "in.first")
    fx1, fz3, vrel, vz3 = hresults(first, "STATE")
    chk.check(fx1 < 0 and fz3 > 0 and vrel > 0 and vz3 > 0,
              "%s: restart point is inside both collisions, unloading (pair force %.3g N, relative "
              "velocity %.3g m/s; wall force %.3g N, vz %.3g m/s)" % (name, fx1, vrel, fz3, vz3))
    second = ("atom_modify map array\nread_restart h.restart\nneighbor 0.001 bin\n"
              "neigh_modify delay 0 every 1 check yes\ncomm_modify vel yes\n"
              "fix floor all tdem/wall/gran %s zplane 0 NULL\nfix nve all nve/sphere\ntimestep %r\nrun %d\n"
              % (law, dt, n2) + HREPORT)
    _, rs = lc.run(args["tdem"], second, wd, "in.second")
    lost = second.replace("fix floor all", "pair_style none\npair_style tdem/gran\npair_coeff * * %s\nfix floor2 all" % law)
    _, ls = lc.run(args["tdem"], lost, wd, "in.lost")
    r_ref, r_rs, r_ls = hresults(ref), hresults(rs), hresults(ls)
    w = hworst(r_ref, r_rs)
    print("%s: restart mid-collision max rel diff %.3g; history lost: pair vx %.6f vs %.6f, wall vz %.6f vs %.6f"
          % (name, w, r_ls[2], r_ref[2], r_ls[11], r_ref[11]))
    chk.check(w <= 1e-10, "%s: restart mid-collision equals run N + run M (max rel diff %.3g)" % (name, w))
    if name not in NO_NORMAL_HISTORY:
        chk.check(abs(r_ls[2] - r_ref[2]) > 1e-3 and abs(r_ls[11] - r_ref[11]) > 1e-3,
                  "%s: control: losing the pair and wall history changes the rebound" % name)
    for newton in ("off", "on"):
        outs = []
        for np_ in (1, 2):
            text = (HHEAD.format(newton=newton, processors="processors 2 1 1" if np_ == 2 else "") +
                    hatoms(dt) + "\n" + inter + HTAIL.format(dt=dt) + "run %d\n" % (n1 + n2) + HREPORT)
            _, out = lc.run(args["tdem"], text, wd, "in.np%d" % np_, np_=np_, mpirun=args["mpirun"])
            outs.append(hresults(out))
        w = hworst(outs[0], outs[1])
        crossed = outs[1][4] < 0 < outs[1][8]
        print("%s, newton %s: -np 2 vs -np 1 max rel diff %.3g (atom 2 x %.4f, atom 3 x %.4f at the end)"
              % (name, newton, w, outs[1][4], outs[1][8]))
        chk.check(crossed and w <= 1e-10,
                  "%s, newton %s: -np 2 equals -np 1 with atoms crossing ranks mid-contact (max rel diff %.3g)"
                  % (name, newton, w))

# small bed, -np 1 vs -np 2
BED = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          {newton}
comm_modify     vel yes
{processors}
read_data       bed.data
neighbor        0.001 bin
neigh_modify    delay 0
pair_style      tdem/gran
pair_coeff      * * {law}
fix             w0 all tdem/wall/gran {law} xplane 0 0.03
fix             w1 all tdem/wall/gran {law} yplane 0 0.03
fix             w2 all tdem/wall/gran {law} zplane 0 0.06
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
compute         nc all contact/atom
compute         ncs all reduce sum c_nc
thermo_style    custom step ke c_ncs
thermo          500
run             {n}
write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""
BED_LAWS = [("power_law", "normal power_law 1e5 1.5 2.915e5 " + TSL),
            ("extended_linear", "normal extended_linear e_fit rational 1 1 0.2 tc_fit constant 2e-3 "
             + TSL + " limit_force yes"),
            ("extended_hertz", "normal extended_hertz 1e6 0.3 e_fit power 0.1 0.1 " + TSL),
            ("continuous_potential", "normal continuous_potential 1e-7 36 0.002 " + TSL)]


def bed_data(path):
    lc.small_bed_data(path)


wd = lc.workdir("bed")
bed_data(os.path.join(wd, "bed.data"))
for name, law in BED_LAWS:
    for newton in ("off", "on"):
        res, contacts = [], []
        for np_ in (1, 2):
            text = BED.format(newton=newton, processors="processors 2 1 1" if np_ == 2 else "", law=law,
                              n=3000, dump="dump.np%d" % np_)
            _, out = lc.run(args["tdem"], text, wd, "in.bed%d" % np_, np_=np_, mpirun=args["mpirun"])
            res.append(lc.read_dump(os.path.join(wd, "dump.np%d" % np_))[1])
            contacts.append(max(float(r.split()[2]) for r in lc.thermo_blocks(out)[1:]))
        _, w = lc.rel_diff(res[1][:, 1:], res[0][:, 1:])
        print("bed %s, newton %s: -np 2 vs -np 1 max rel diff %.3g (%d atoms, up to %d contacts)"
              % (name, newton, w, res[0].shape[0], contacts[0]))
        chk.check(res[0].shape == res[1].shape and contacts[0] >= 50 and w <= 1e-8,
                  "bed %s, newton %s: -np 2 equals -np 1 within 1e-8 (max rel diff %.3g)" % (name, newton, w))
chk.done()
