#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/integrate (src/integrators/lammps): the schemes of src/integrators/schemes.h in LAMMPS.

Run with --part P (one ctest each):
  nve       1. `scheme velocity_verlet` reproduces `fix nve/sphere`: 392 spheres under gravity
               on a floor and side walls (pair tdem/gran + fix tdem/wall/gran, lsd + Cundall-Strack),
               3000 steps with collisions and sliding/rolling contacts: max relative difference of x,
               v, omega <= 1e-10 (the update is the same, but the kernel multiplies h/2 by F/m where
               nve/sphere multiplies (h/2)/m by F: the rounding differs by <= 1 ulp per step).
               Also: free flight under gravity for every scheme against the closed forms
               (exact for every scheme except the Euler variants, whose O(h) position error is
               known in closed form; leapfrog and position_verlet show the velocity half a step back).
  restart   2. multi-step history through MPI and restart, for ab4, ab5, gear5, gear6, beeman, abm4,
               taylor3, position_verlet: a bed of 175 spheres falls on the floor under gravity tilted
               by 45 degrees towards +x (dense collisions; the bed, 26 mm wide in a 60 mm box,
               slides and rolls across x = 0.03, the processor boundary of `processors 2 1 1`, while in contact). Reference: -np 1, `run N` + `run M` in one input. Compared:
               a. -np 1 with write_restart after N, read_restart, run M;
               b. -np 2 with write_restart after N, read_restart (on 2 ranks), run M.
               Tolerance: the three runs perform the same arithmetic per atom, but the contact forces
               are summed in a different order on two ranks and after read_restart (new neighbour
               lists), and dense granular flow amplifies 1-ulp differences (measured here for stock
               fix nve/sphere in the same scene, printed as "round-off scale"); the tolerance is
               1e-8 relative, as in test_parallel_restart.py. A control that loses the history at
               the restart (the fix defined with another ID: every atom re-started from its
               acceleration alone) must differ by more than 100 times the tolerance.
  harness   3. a sphere hits a wall head-on (fix tdem/wall/gran normal lsd, absolute damping, no
               gravity, start at a gap above the wall) for every scheme at ~20 and ~80 steps per
               contact; e = v_after / v0, read 10 steps after the first whole step without overlap,
               equals `tdem-collide --law lsd --wall --scheme NAME --dt DT --gap GAP` within 1e-9;
               and the error against the closed-form LSD restitution exp(-beta pi / omega) is
               smaller at 80 than at 20 steps per contact for the schemes of order >= 1.
  bad_input 4. unknown scheme, missing scheme, scheme without a value, bad rotation value, unknown
               keyword, atom_style atomic: LAMMPS ERROR naming the keyword, the value and the allowed
               values.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
PART = args.get("part", "all")
chk = lc.Checker("lammps.integrate_" + PART)

SCHEMES = ["euler", "symplectic_euler", "taylor2", "taylor3", "leapfrog", "position_verlet",
           "velocity_verlet", "velocity_verlet_sync", "beeman", "ab2", "ab3", "ab4", "ab5", "abm4",
           "gear4", "gear5", "gear6", "velocity_verlet_ab2"]
DUMP = ("write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz "
        "modify sort id format float %.17g\n")


def worst(a, b):
    return lc.rel_diff(a[:, 1:], b[:, 1:])[1]


# ---------------------------------------------------------------- 1. velocity_verlet = nve/sphere
NVE_SCENE = """
units           si
atom_style      sphere
boundary        f f f
newton          off
comm_modify     vel yes
region          box block 0 0.04 0 0.04 0 0.08 units box
create_box      1 box
lattice         sc 0.0052
region          fill block 0.003 0.037 0.003 0.037 0.003 0.045 units box
create_atoms    1 region fill
variable        d atom 0.0040+0.0008*random(0,1,4711)
set             group all diameter v_d
set             group all density 2500
variable        vx atom 0.4*(random(0,1,13)-0.5)
variable        vy atom 0.4*(random(0,1,17)-0.5)
variable        vz atom 0.4*(random(0,1,19)-0.5)-0.3
velocity        all set v_vx v_vy v_vz
neighbor        0.001 bin
neigh_modify    delay 0
pair_style      tdem/gran
pair_coeff      * * {law}
fix             w0 all tdem/wall/gran {law} xplane 0 0.04
fix             w1 all tdem/wall/gran {law} yplane 0 0.04
fix             w2 all tdem/wall/gran {law} zplane 0 NULL
fix             g all gravity 9.81 vector 0 0 -1
{integrate}
timestep        2e-5
compute         nc all contact/atom
compute         ncs all reduce sum c_nc
compute         rke all erotate/sphere
thermo_style    custom step ke c_rke c_ncs
thermo_modify   format float %.15g
thermo          500
run             {n}
"""
LAW = "normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5"

FREE = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
region          box block -1 1 -1 1 -1 1 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
set             group all diameter 0.01
set             group all density 2500
velocity        all set 0.1 0.2 0.3
fix             g all gravity 9.81 vector 0 0 -1
fix             i all tdem/integrate scheme {scheme}
timestep        {h!r}
run             {n}
print           "R $(x[1]:%.17g) $(z[1]:%.17g) $(vx[1]:%.17g) $(vz[1]:%.17g)"
"""

DEPOSIT = """
units           si
atom_style      sphere
boundary        f f f
region          box block -2 2 -2 2 -2 2 units box
create_box      1 box
region          slab block -1 1 -1 1 0.9999999999 1.0000000001 units box
fix             dep all deposit 9 1 7 4711 region slab vz -0.1 -0.1 units box
fix             g all gravity 9.81 vector 0 0 -1
fix             i all tdem/integrate scheme {scheme}
timestep        {h!r}
run             70
write_dump      all custom dump.deposit id x y z vx vy vz modify sort id format float %.17g
"""


def part_nve():
    wd = lc.workdir("nve")
    n = 3000
    runs = {}
    for tag, integ in (("nve", "fix             nve all nve/sphere"),
                       ("vv", "fix             nve all tdem/integrate scheme velocity_verlet"),
                       ("vvnorot", "fix             nve all tdem/integrate scheme velocity_verlet rotation no")):
        text = NVE_SCENE.format(law=LAW, integrate=integ, n=n) + DUMP.format(dump="dump." + tag)
        _, out = lc.run(args["tdem"], text, wd, "in." + tag)
        runs[tag] = (lc.read_dump(os.path.join(wd, "dump." + tag)), out)
    (cols, ref), out_ref = runs["nve"]
    (_, vv), _ = runs["vv"]
    (_, nr), _ = runs["vvnorot"]
    contacts = max(float(r.split()[3]) for r in lc.thermo_blocks(out_ref) if not r.startswith("Step"))
    per, w = lc.rel_diff(vv[:, 1:], ref[:, 1:])
    nbits = int((vv != ref).sum())
    print("velocity_verlet vs nve/sphere: %d atoms, %d steps, up to %d contacts; max relative "
          "difference x %.3g, v %.3g, omega %.3g; %s"
          % (ref.shape[0], n, contacts, per[0:3].max(), per[3:6].max(), per[6:9].max(),
             "bitwise identical" if nbits == 0 else "%d of %d values differ (not bitwise)" % (nbits, ref.size)))
    chk.check(ref.shape[0] > 300 and contacts >= 100, "nve: scene has %d atoms and up to %d contacts"
              % (ref.shape[0], contacts))
    chk.check(w <= 1e-10, "nve: tdem/integrate velocity_verlet reproduces nve/sphere (max rel diff %.3g <= 1e-10)" % w)
    om = [cols.index(c) for c in ("omegax", "omegay", "omegaz")]
    chk.check(np.abs(ref[:, om]).max() > 1.0 and np.all(nr[:, om] == 0.0),
              "nve: rotation no leaves omega untouched (0), rotation yes spins (max |omega| %.3g)"
              % np.abs(ref[:, om]).max())

    # free flight under gravity: closed forms
    h, nst, g = 1e-4, 100, 9.81
    t = nst * h
    v0z, z_exact, vz_exact = 0.3, 0.3 * t - 0.5 * g * t * t, 0.3 - g * t
    for s in SCHEMES:
        _, out = lc.run(args["tdem"], FREE.format(scheme=s, h=h, n=nst), wd, "in.free")
        x, z, vx, vz = [float(v) for v in [l for l in out.splitlines() if l.startswith("R ")][0].split()[1:]]
        z_ref, vz_ref = z_exact, vz_exact
        if s == "euler":
            z_ref = v0z * t - g * h * h * nst * (nst - 1) / 2
        elif s == "symplectic_euler":
            z_ref = v0z * t - g * h * h * nst * (nst + 1) / 2
        if s in ("leapfrog", "position_verlet"):
            vz_ref = v0z - g * (t - 0.5 * h)  # the half-step (backward-difference) velocity
        err = max(abs(z - z_ref) / 0.1, abs(vz - vz_ref) / 1.0, abs(x - 0.1 * t) / 0.1, abs(vx - 0.1))
        chk.check(err <= 1e-12, "free flight %s: x, z, vx, vz equal the closed form (max rel err %.2g)" % (s, err))

    # a change of the time step between runs re-starts the history (multi-step schemes would
    # otherwise use velocities of the old step: wrong even in free flight), with a warning
    for s in ("ab4", "abm4", "gear5", "position_verlet", "leapfrog"):
        text = FREE.format(scheme=s, h=h, n=50).replace("print ", "timestep %r\nrun 50\nprint " % (2 * h))
        _, out = lc.run(args["tdem"], text, wd, "in.dt")
        x, z, vx, vz = [float(v) for v in [l for l in out.splitlines() if l.startswith("R ")][0].split()[1:]]
        t = 50 * h + 50 * 2 * h
        vz_ref = v0z - g * t if s not in ("position_verlet", "leapfrog") else v0z - g * (t - h)
        err = max(abs(z - (v0z * t - 0.5 * g * t * t)) / 0.1, abs(vz - vz_ref))
        warned = "time step changed from 0.0001 to 0.0002" in out
        chk.check(err <= 1e-12 and warned, "timestep change between runs, %s: warning in the log (%s), "
                  "history re-started: free flight exact (max rel err %.2g)" % (s, warned, err))

    # atoms that appear during a run (fix deposit, one every 7 steps at z = 1 with vz = -0.1):
    # started in final_integrate after their first force; each follows the closed form from its
    # insertion step (n_i steps of free flight, n_i read from vz)
    for s in ("ab4", "abm4", "gear5", "taylor3", "beeman"):
        text = DEPOSIT.format(scheme=s, h=h)
        _, out = lc.run(args["tdem"], text, wd, "in.deposit")
        cols, d = lc.read_dump(os.path.join(wd, "dump.deposit"))
        iz, ivz = cols.index("z"), cols.index("vz")
        worst_err, nmin, nmax = 0.0, 10 ** 9, 0
        for row in d:
            n_i = (row[ivz] + 0.1) / (-g * h)
            k = round(n_i)
            t = k * h
            nmin, nmax = min(nmin, k), max(nmax, k)
            worst_err = max(worst_err, abs(n_i - k) * g * h, abs(row[iz] - (1.0 - 0.1 * t - 0.5 * g * t * t)))
        chk.check(d.shape[0] >= 8 and worst_err <= 1e-9,
                  "fix deposit, %s: %d atoms inserted during the run (%d .. %d steps of flight) follow the "
                  "closed form (max err %.2g)" % (s, d.shape[0], nmin, nmax, worst_err))


# ---------------------------------------------------------------- 2. MPI + restart
BED_HEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
{processors}
"""
BED_REST = """
neighbor        0.001 bin
neigh_modify    delay 0
pair_style      tdem/gran
pair_coeff      * * {law}
fix             w0 all tdem/wall/gran {law} xplane 0 0.06
fix             w1 all tdem/wall/gran {law} yplane 0 0.03
fix             w2 all tdem/wall/gran {law} zplane 0 0.06
fix             g all gravity 9.81 vector 1 0 -1
{integrate}
timestep        2e-5
compute         nc all contact/atom
compute         ncs all reduce sum c_nc
thermo_style    custom step ke c_ncs
thermo          500
"""
BED_DUMP = ("write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz c_nc "
            "modify sort id format float %.17g\n")
BED_LAW = "normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5"
CORRECTORS = {"beeman", "velocity_verlet_sync", "abm4", "gear4", "gear5", "gear6", "velocity_verlet_ab2"}
RESTART_SCHEMES = ["ab4", "ab5", "gear5", "gear6", "beeman", "abm4", "taylor3", "position_verlet"]


def bed_data(path):
    """The bed of test_parallel_restart.py in a box twice as long, falling at 0.3 m/s."""
    lc.small_bed_data(path, xhi=0.06, vz_shift=-0.3)


def part_restart():
    wd = lc.workdir("restart")
    bed_data(os.path.join(wd, "bed.data"))
    N, M = 1500, 1500
    TOL = 1e-8
    schemes = args.get("schemes", ",".join(RESTART_SCHEMES)).split(",")

    def proc(np_):
        return "processors 2 1 1" if np_ == 2 else ""

    def integ(s, fid="nve"):
        return ("fix             %s all nve/sphere" % fid if s == "nve_sphere"
                else "fix             %s all tdem/integrate scheme %s" % (fid, s))

    def dump(tag, s):
        extra = "" if s == "nve_sphere" else " f_nve[*]"
        return BED_DUMP.format(dump="dump." + tag).replace(" c_nc ", " c_nc%s " % extra)

    def full(s, np_, tag):
        text = (BED_HEAD.format(processors=proc(np_)) + "read_data bed.data\n"
                + BED_REST.format(law=BED_LAW, integrate=integ(s)) + "run %d\n" % N
                + dump("mid." + tag, s) + "run %d\n" % M + dump(tag, s))
        _, out = lc.run(args["tdem"], text, wd, "in." + tag, np_=np_, mpirun=args["mpirun"])
        return lc.read_dump(os.path.join(wd, "dump." + tag))[1], out

    def uninterrupted(s, tag):
        text = (BED_HEAD.format(processors="") + "read_data bed.data\n"
                + BED_REST.format(law=BED_LAW, integrate=integ(s)) + "run %d\n" % (N + M) + dump(tag, s))
        lc.run(args["tdem"], text, wd, "in." + tag, np_=1, mpirun=args["mpirun"])
        return lc.read_dump(os.path.join(wd, "dump." + tag))[1]

    def write(s, np_, tag):
        text = (BED_HEAD.format(processors=proc(np_)) + "read_data bed.data\n"
                + BED_REST.format(law=BED_LAW, integrate=integ(s)) + "run %d\n" % N
                + "write_restart   bed.%s.restart\n" % tag)
        lc.run(args["tdem"], text, wd, "in.%s.w" % tag, np_=np_, mpirun=args["mpirun"])

    def read(s, np_, tag, rtag, n, fid="nve"):
        # units, atom style, pair style and coefficients come from the restart file
        rest = BED_REST.format(law=BED_LAW, integrate=integ(s, fid)).replace(
            "pair_style      tdem/gran\npair_coeff      * * %s\n" % BED_LAW, "")
        text = ("boundary f f f\nnewton off\ncomm_modify vel yes\n%s\natom_modify map array\n"
                "read_restart bed.%s.restart\n" % (proc(np_), tag) + rest + "run %d\n" % n
                + dump(rtag, s if fid == "nve" else "nve_sphere"))
        _, out = lc.run(args["tdem"], text, wd, "in.%s.r" % rtag, np_=np_, mpirun=args["mpirun"])
        return lc.read_dump(os.path.join(wd, "dump." + rtag))[1], out

    # round-off scale of the scene and migration: stock nve/sphere, -np 1 vs -np 2
    r1, _ = full("nve_sphere", 1, "stock1")
    r2, out2 = full("nve_sphere", 2, "stock2")
    scale = worst(r2, r1)
    chk.check("2 by 1 by 1 MPI processor grid" in out2, "restart: -np 2 runs on a 2x1x1 grid")
    mid = lc.read_dump(os.path.join(wd, "dump.mid.stock1"))[1]
    cols = lc.read_dump(os.path.join(wd, "dump.stock1"))[0]
    ix, inc = cols.index("x"), cols.index("c_nc")
    crossed = int(np.sum(((mid[:, ix] - 0.03) * (r1[:, ix] - 0.03) < 0) & (r1[:, inc] > 0)))
    right = int(np.sum(r1[:, ix] > 0.03))  # all atoms start at x < 0.029
    print("round-off scale: stock nve/sphere -np 2 vs -np 1 after %d steps: max rel diff %.3g; "
          "%d atoms moved to rank 2 (x > 0.03), %d of them crossed in the second half and are in contact "
          "at the end" % (N + M, scale, right, crossed))
    chk.check(right >= 5 and crossed >= 1, "restart: atoms migrate between the ranks while in contact")
    for s in schemes:
        ref, out = full(s, 1, s + ".ref")                  # -np 1, run N + run M
        cref, midref = lc.read_dump(os.path.join(wd, "dump.mid.%s.ref" % s))
        p2, out2 = full(s, 2, s + ".np2")                  # -np 2, run N + run M
        one = uninterrupted(s, s + ".one")                 # -np 1, run N+M
        write(s, 1, s + ".w1")
        a, _ = read(s, 1, s + ".w1", s + ".r1", M)         # -np 1 restart
        write(s, 2, s + ".w2")
        st, _ = read(s, 2, s + ".w2", s + ".st2", 0)       # state read back on 2 ranks
        b2, outb = read(s, 2, s + ".w2", s + ".r2", M)     # -np 2 restart, 2 ranks
        b1, _ = read(s, 1, s + ".w2", s + ".r21", M)       # same file, 1 rank
        lost, _ = read(s, 1, s + ".w1", s + ".lost", M, fid="other")
        nh = len([c for c in cref if c.startswith("f_nve[")])
        w_state = worst(st, midref)
        w_np2, w_r1, w_r2, w_lost = worst(p2, ref), worst(a, ref), worst(b2, b1), lc.rel_diff(lost[:, 1:10], a[:, 1:10])[1]
        w_info = worst(b2, ref)
        contacts = max(float(r.split()[2]) for r in lc.thermo_blocks(out) if not r.startswith("Step"))
        print("%-16s (%d history columns incl. flag, up to %d contacts): -np 2 run %.3g; -np 1 restart %.3g;"
              " 2-rank restart file read back on 2 ranks: state incl. history %.3g, run %d on 2 vs 1 ranks %.3g;"
              " control without history %.3g; information: 2-rank restart vs uninterrupted -np 1 %.3g"
              % (s, nh, contacts, w_np2, w_r1, w_state, M, w_r2, w_lost, w_info))
        chk.check(nh >= 1 and w_state == 0.0,
                  "%s: write_restart on 2 ranks + read_restart on 2 ranks returns x, v, omega and the "
                  "history of every atom bit for bit" % s)
        w_one = worst(one[:, :10], ref[:, :10])
        print("%-16s run N + run M vs run N+M: max rel diff %.3g" % (s, w_one))
        if s in CORRECTORS:
            # LAMMPS evaluates the set-up force at the corrected positions, which re-decides which
            # contacts touch (a contact the corrector moved apart loses its tangential history):
            # information only, see docs/lammps.md
            print("%-16s (corrector) run N + run M vs run N+M: %.3g (information)" % (s, w_one))
        else:
            chk.check(w_one <= TOL, "%s: run N + run M equals one run N+M (the last force of a run is kept "
                      "for the next; max rel diff %.3g)" % (s, w_one))
        chk.check(w_np2 <= TOL, "%s: -np 2 (history migrating with the atoms) equals -np 1 (max rel diff %.3g)" % (s, w_np2))
        chk.check(w_r1 <= TOL, "%s: -np 1 write/read_restart equals run N + run M (max rel diff %.3g)" % (s, w_r1))
        chk.check(w_r2 <= TOL, "%s: a 2-rank restart continued on 2 ranks equals it continued on 1 rank "
                  "(max rel diff %.3g)" % (s, w_r2))
        chk.check(w_lost > 100 * TOL, "%s: control: losing the history changes the result (%.3g)" % (s, w_lost))
        chk.check("2 by 1 by 1" in outb and "WARNING" not in outb,
                  "%s: -np 2 restart ran on 2 ranks without warnings" % s)


# ---------------------------------------------------------------- 3. host vs harness
K, GAMMA, MASS, RAD, V0 = 1e5, 4.0, 0.01, 0.005, 1.0
WALL = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 box
create_atoms    1 single 0 0 {z0!r} units box
set             group all diameter {d!r}
set             group all mass {m!r}
velocity        all set 0 0 {vz!r}
fix             floor all tdem/wall/gran normal lsd stiffness {k!r} {g!r} tangential cundall_strack 3e4 0 0.3 damping absolute limit_force no zplane 0 NULL
fix             i all tdem/integrate scheme {scheme}
timestep        {dt!r}
variable        z equal z[1]
variable        vz equal vz[1]
thermo_style    custom step v_z v_vz
thermo_modify   format float %.17g
thermo          1
run             {n}
"""


def lsd_closed_form():
    beta = GAMMA / (2 * MASS)
    w = math.sqrt(K / MASS - beta * beta)
    return math.exp(-beta * math.pi / w), math.pi / w


def part_harness():
    coll = args.get("collide")
    if not coll:
        chk.check(False, "harness: tdem-collide not given (--collide PATH)")
        return
    p = subprocess.run([coll, "--help"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if "--scheme" not in p.stdout:
        chk.check(False, "harness: tdem-collide has no --scheme option yet (needs the harness schemes)")
        return
    wd = lc.workdir("harness")
    e_cf, tc = lsd_closed_form()
    print("closed form: e = %.12f, t_c = %.6g s" % (e_cf, tc))
    errs = {}
    for s in SCHEMES:
        for spc in (20, 80):
            dt = float("%.6g" % (tc / spc))
            gap = 3.37 * dt * V0  # touch between steps 3 and 4
            n = 4 + int(1.6 * spc) + 40
            text = WALL.format(z0=RAD + gap, d=2 * RAD, m=MASS, vz=-V0, k=K, g=GAMMA, scheme=s, dt=dt, n=n)
            _, out = lc.run(args["tdem"], text, wd, "in.wall")
            rows = [[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]]
            ov = [RAD - r[1] for r in rows]
            ins = [i for i, o in enumerate(ov) if o > 0]
            if not ins:
                chk.check(False, "harness %s %d: no contact" % (s, spc))
                continue
            iend = next(i for i in range(ins[0], len(ov)) if ov[i] <= 0)
            if iend + 10 >= len(rows):
                chk.check(False, "harness %s %d: run too short" % (s, spc))
                continue
            e_host = rows[iend + 10][2] / V0
            drift = max(abs(rows[j][2] / V0 - e_host) for j in range(iend + 10, len(rows)))
            cmd = [coll, "--law", "lsd", "--k", "%r" % K, "--gamma", "%r" % GAMMA, "--m1", "%r" % MASS,
                   "--R1", "%r" % RAD, "--wall", "--v0", "%r" % V0, "--scheme", s, "--dt", "%r" % dt,
                   "--gap", "%r" % gap]
            q = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            if q.returncode != 0:
                chk.check(False, "harness %s: %s failed: %s" % (s, " ".join(cmd), q.stdout[-500:]))
                continue
            e_h = json.loads(q.stdout)["e"]
            errs[(s, spc)] = abs(e_host - e_cf)
            print("%-20s %2d steps/contact: e host %.12f, harness %.12f, |de| %.2g; closed form err %.3g;"
                  " host e drift after +10 steps %.2g" % (s, spc, e_host, e_h, abs(e_host - e_h),
                                                          abs(e_host - e_cf), drift))
            chk.check(abs(e_host - e_h) <= 1e-9, "harness %s, %d steps/contact: |e_host - e_harness| = %.2g <= 1e-9"
                      % (s, spc, abs(e_host - e_h)))
    for s in SCHEMES:
        if (s, 20) in errs and (s, 80) in errs:
            chk.check(errs[(s, 80)] < errs[(s, 20)],
                      "harness %s: error vs closed form falls with more steps per contact (%.3g -> %.3g)"
                      % (s, errs[(s, 20)], errs[(s, 80)]))


# ---------------------------------------------------------------- 4. bad input
BAD = """
units si
atom_style {style}
boundary f f f
region box block 0 0.1 0 0.1 0 0.1 units box
create_box 1 box
create_atoms 1 single 0.05 0.05 0.05 units box
{setup}
timestep 1e-6
{fix}
run 10
"""
ALLOWED = "allowed: " + ", ".join(SCHEMES)


def part_bad_input():
    wd = lc.workdir("bad")
    sph = "set group all diameter 0.005\nset group all density 2500"
    cases = [
        ("good input (control)", "sphere", sph, "fix i all tdem/integrate scheme gear5 rotation no", None),
        ("unknown scheme", "sphere", sph, "fix i all tdem/integrate scheme rk4",
         ["fix i tdem/integrate: scheme 'rk4' is unknown", ALLOWED]),
        ("missing scheme", "sphere", sph, "fix i all tdem/integrate rotation yes",
         ["fix i tdem/integrate: missing keyword 'scheme NAME'", "allowed NAME: " + ", ".join(SCHEMES)]),
        ("scheme without value", "sphere", sph, "fix i all tdem/integrate scheme",
         ["fix i tdem/integrate: keyword scheme needs a value", ALLOWED]),
        ("bad rotation", "sphere", sph, "fix i all tdem/integrate scheme ab4 rotation maybe",
         ["fix i tdem/integrate: rotation 'maybe' is unknown; allowed: yes, no"]),
        ("unknown keyword", "sphere", sph, "fix i all tdem/integrate scheme ab4 order 4",
         ["fix i tdem/integrate: unexpected argument 'order'", "allowed: scheme NAME, rotation yes|no"]),
        ("atom_style atomic", "atomic", "mass 1 1.0", "fix i all tdem/integrate scheme ab4",
         ["fix i tdem/integrate requires atom_style sphere", "'atomic'"]),
    ]
    for name, style, setup, fix, expect in cases:
        rc, out = lc.run(args["tdem"], BAD.format(style=style, setup=setup, fix=fix), wd, "in.bad", check=False)
        if expect is None:
            chk.check(rc == 0 and "ERROR" not in out, "bad_input: %s runs" % name)
            continue
        ok = 0 < rc < 128 and "ERROR" in out and all(e in out for e in expect)
        if not ok:
            print("\n".join(l for l in out.splitlines() if "ERROR" in l))
        chk.check(ok, "bad_input: %s -> clear error (exit %d)" % (name, rc))


parts = {"nve": part_nve, "restart": part_restart, "harness": part_harness, "bad_input": part_bad_input}
for key, fn in parts.items():
    if PART in (key, "all"):
        fn()
chk.done()
