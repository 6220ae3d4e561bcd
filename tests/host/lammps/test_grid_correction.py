#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""`grid_correction on` of pair tdem/gran and fix tdem/wall/gran (issue 22; src/contact/grid_correction.h,
src/pair_styles/lammps/grid_host.h).

Run with --part P (one ctest each):
  harness   1. A sphere hits a wall (fix tdem/wall/gran) from a gap, `fix tdem/integrate scheme S`,
               with the correction on: e (and e_t, the spin of an oblique impact) equal
               `tdem-collide ... --scheme S --gap GAP --grid-correction on` (the same code on the
               single-collision harness) within 1e-9, for lsd (both ends), hertz + tsuji,
               walton_braun head-on and lsd + cundall_strack at 25 degrees, velocity_verlet and
               velocity_verlet_ab2, 4 phases of the touch each, at 25.37 steps per contact.
               Two spheres head-on (pair tdem/gran, equal masses) equal the harness with m* and the
               closing speed. With velocity_verlet_ab2 the lsd |de| against the closed form is
               <= 1e-3 (mean of the phases) with the correction and > 3e-3 without.
  unchanged 2. Columns at rest (9 columns of 4 spheres, every contact at its static overlap, on the
               floor, gravity; 3000 steps): its contacts exist from the set-up and persist, so the run
               with the correction equals the one without it bitwise. A restart file whose contacts
               carry another history size than the new pair_coeff (grid_correction switched on):
               ERROR. A head-on impact with a neighbour-list rebuild at every step has the corrected e
               of the default schedule bitwise (a contact ending at a rebuild keeps its history).
  mpi       3. A falling bed (175 spheres, dense collisions, walls) with the correction on:
               -np 2 with write_restart / read_restart in the middle equals -np 1 uninterrupted to
               1e-8 relative (the tolerance of test_parallel_restart.py; the restart file keeps
               `grid_correction on`); the uncorrected run differs (control).
  bad_input 4. grid_correction without a value or with a wrong one: ERROR naming it and the
               allowed values.
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
PART = args.get("part", "harness")
chk = lc.Checker("lammps.grid_correction_" + PART)

K, GAMMA, MASS, RAD, V0 = 1e5, 4.48097, 0.01, 0.01, 1.0

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
velocity        all set {vx!r} 0 {vz!r}
fix             floor all tdem/wall/gran {law} grid_correction on zplane 0 NULL
fix             i all tdem/integrate scheme {scheme}
timestep        {dt!r}
variable        z equal z[1]
variable        vx equal vx[1]
variable        vz equal vz[1]
compute         oma all property/atom omegay
compute         om all reduce sum c_oma
variable        wy equal c_om
thermo_style    custom step v_z v_vx v_vz v_wy
thermo_modify   format float %.17g
thermo          1
run             {n}
"""

PAIR = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
comm_modify     vel yes
region          box block -0.1 0.1 -0.05 0.05 -0.05 0.05 units box
create_box      1 box
create_atoms    1 single {xa!r} 0 0 units box
create_atoms    1 single {xb!r} 0 0 units box
set             group all diameter {d!r}
set             group all mass {m!r}
velocity        all set 0 0 0
set             atom 1 vx {v!r}
set             atom 2 vx {mv!r}
neighbor        0.005 bin
pair_style      tdem/gran
pair_coeff      * * {law} grid_correction on
fix             i all tdem/integrate scheme {scheme}
timestep        {dt!r}
variable        dx equal x[2]-x[1]
variable        dv equal vx[2]-vx[1]
thermo_style    custom step v_dx v_dv
thermo_modify   format float %.17g
thermo          1
run             {n}
"""


def collide(cmd):
    q = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if q.returncode != 0:
        chk.check(False, "%s failed: %s" % (" ".join(cmd), q.stdout[-400:]))
        return None
    return json.loads(q.stdout)


def rows_of(out):
    return [[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]]


def after_contact(ov, rows, k):
    """The row 10 steps after the first whole step without overlap (ov[i] <= 0) after contact."""
    ins = [i for i, o in enumerate(ov) if o > 0]
    if not ins:
        return None
    iend = next((i for i in range(ins[0], len(ov)) if ov[i] <= 0), None)
    if iend is None or iend + 10 >= len(rows):
        return None
    return rows[iend + 10]


# (name, LAMMPS law line, tdem-collide law options, angle [deg])
LAWS = [
    ("lsd zero_overlap", "normal lsd stiffness %r %r tangential cundall_strack 3e4 0 0.3 damping absolute "
     "limit_force no" % (K, GAMMA), ["--law", "lsd", "--k", repr(K), "--gamma", repr(GAMMA)], 0.0),
    ("lsd zero_force", "normal lsd stiffness %r %r tangential cundall_strack 3e4 0 0.3 damping absolute "
     "limit_force yes" % (K, GAMMA), ["--law", "lsd", "--k", repr(K), "--gamma", repr(GAMMA), "--end", "zero_force"],
     0.0),
    ("hertz tsuji", "normal hertz 2e8 0.3 damping tsuji 0.8 tangential cundall_strack 0.8 0",
     ["--law", "hertz", "--params", "2e8 0.3 damping tsuji 0.8"], 0.0),
    ("walton_braun", "normal walton_braun 1e5 1.5625e5 tangential cundall_strack 0.8 0",
     ["--law", "walton_braun", "--params", "1e5 1.5625e5"], 0.0),
    ("lsd 25 deg + cundall_strack", "normal lsd stiffness %r %r tangential cundall_strack 3e4 0 0.3 damping absolute "
     "limit_force no" % (K, GAMMA),
     ["--law", "lsd", "--k", repr(K), "--gamma", repr(GAMMA), "--tangential", "cundall_strack", "--kt", "3e4",
      "--mu", "0.3"], 25.0),
]


def part_harness():
    coll = args.get("collide")
    if not coll:
        chk.check(False, "harness: tdem-collide not given (--collide PATH)")
        return
    wd = lc.workdir("gc_harness")
    bodies = ["--m1", repr(MASS), "--R1", repr(RAD), "--wall"]
    errs = {}
    for name, law, copts, angle in LAWS:
        base = collide([coll] + copts + bodies + ["--v0", repr(V0)])
        if base is None:
            continue
        tc = base["contact_time"]
        dt = float("%.6g" % (tc / 25.37))
        th = math.radians(angle)
        vn, vt = V0 * math.cos(th), V0 * math.sin(th)
        for scheme in ("velocity_verlet", "velocity_verlet_ab2"):
            for k in range(4):
                gap = (3 + (k + 0.5) / 4) * vn * dt
                n = 4 + int(1.6 * 25.37) + 40
                text = WALL.format(z0=RAD + gap, d=2 * RAD, m=MASS, vx=vt, vz=-vn, law=law, scheme=scheme, dt=dt,
                                   n=n)
                _, out = lc.run(args["tdem"], text, wd, "in.wall")
                rows = rows_of(out)
                row = after_contact([RAD - r[1] for r in rows], rows, k)
                if row is None:
                    chk.check(False, "harness %s %s: no contact or run too short" % (name, scheme))
                    continue
                cmd = [coll] + copts + bodies + ["--v0", repr(V0), "--scheme", scheme, "--dt", repr(dt), "--gap",
                                                 repr(gap), "--grid-correction", "on"]
                if angle:
                    cmd += ["--angle", repr(angle)]
                h = collide(cmd)
                if h is None:
                    continue
                e_host = row[3] / vn
                d = abs(e_host - h["e"])
                msg = "%s, %s, phase %d: e host %.12f harness %.12f" % (name, scheme, k, e_host, h["e"])
                if angle:
                    et_host = row[2] / vt
                    spin_host = -row[4]
                    d = max(d, abs(et_host - h["e_t"]), abs(spin_host - h["spin_after"]) * RAD / V0)
                    msg += ", e_t %.12f / %.12f, spin %.9g / %.9g" % (et_host, h["e_t"], spin_host,
                                                                     h["spin_after"])
                chk.check(d <= 1e-9, msg + " (difference %.2g <= 1e-9)" % d)
                if angle == 0.0 and name.startswith("lsd"):
                    errs.setdefault((name, scheme), []).append(abs(e_host - base["closed_form"]["e"]))
    for (name, scheme), v in errs.items():
        if scheme == "velocity_verlet_ab2":
            chk.check(np.mean(v) <= 1e-3, "%s, %s with the correction: mean |de| over the phases %.2e <= 1e-3 "
                      "(25.37 steps per contact)" % (name, scheme, np.mean(v)))
    # the same impact without the correction (stock-equal path): the error is first order
    name, law, copts, _ = LAWS[0]
    base = collide([coll] + copts + bodies + ["--v0", repr(V0)])
    dt = float("%.6g" % (base["contact_time"] / 25.37))
    off = []
    for k in range(4):
        gap = (3 + (k + 0.5) / 4) * V0 * dt
        text = WALL.format(z0=RAD + gap, d=2 * RAD, m=MASS, vx=0.0, vz=-V0, law=law, scheme="velocity_verlet_ab2",
                           dt=dt, n=100).replace(" grid_correction on", "")
        _, out = lc.run(args["tdem"], text, wd, "in.off")
        rows = rows_of(out)
        row = after_contact([RAD - r[1] for r in rows], rows, k)
        off.append(abs(row[3] / V0 - base["closed_form"]["e"]))
    chk.check(np.mean(off) > 3e-3, "the same without the correction: mean |de| %.2e > 3e-3" % np.mean(off))
    # two spheres head-on: the harness with m* = m/2 and the closing speed 2 v
    for scheme in ("velocity_verlet", "velocity_verlet_ab2"):
        for k in range(2):
            m_eff = MASS / 2
            tc = math.pi / math.sqrt(K / m_eff - (GAMMA / (2 * m_eff)) ** 2)
            dt = float("%.6g" % (tc / 25.37))
            gap = (3 + (k + 0.5) / 2) * 2 * V0 * dt
            law = ("normal lsd stiffness %r %r tangential cundall_strack 3e4 0 0.3 damping absolute limit_force no"
                   % (K, GAMMA))
            text = PAIR.format(xa=-RAD - gap / 2, xb=RAD + gap / 2, d=2 * RAD, m=MASS, v=V0, mv=-V0, law=law,
                               scheme=scheme, dt=dt, n=100)
            _, out = lc.run(args["tdem"], text, wd, "in.pair")
            rows = rows_of(out)
            row = after_contact([2 * RAD - r[1] for r in rows], rows, k)
            h = collide([coll, "--law", "lsd", "--k", repr(K), "--gamma", repr(GAMMA), "--m1", repr(m_eff), "--R1",
                         repr(RAD), "--wall", "--v0", repr(2 * V0), "--scheme", scheme, "--dt", repr(dt), "--gap",
                         repr(gap), "--grid-correction", "on"])
            if row is None or h is None:
                chk.check(False, "pair %s: no result" % scheme)
                continue
            e_host = row[2] / (2 * V0)
            chk.check(abs(e_host - h["e"]) <= 1e-9, "pair head-on, %s, phase %d: e host %.12f harness (m*) %.12f"
                      % (scheme, k, e_host, h["e"]))


BED = """
units           si
atom_style      sphere
boundary        f f f
newton          off
comm_modify     vel yes
{read}
neighbor        0.001 bin
neigh_modify    delay 0
pair_style      tdem/gran
pair_coeff      * * {law}
fix             w0 all tdem/wall/gran {law} xplane 0 {xhi}
fix             w1 all tdem/wall/gran {law} yplane 0 0.03
fix             w2 all tdem/wall/gran {law} zplane 0 NULL
fix             g all gravity 9.81 vector {gvec}
fix             i all tdem/integrate scheme velocity_verlet_ab2
timestep        2e-5
thermo_style    custom step ke
thermo_modify   format float %.15g
thermo          500
{body}
"""
LAW = "normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5"


STACK = """
units           si
atom_style      sphere
boundary        f f f
newton          off
comm_modify     vel yes
region          box block 0 0.03 0 0.03 0 0.05 units box
create_box      1 box
{atoms}
set             group all diameter 0.005
set             group all density 2500
neighbor        0.001 bin
neigh_modify    delay 0
pair_style      tdem/gran
pair_coeff      * * {law}
fix             w2 all tdem/wall/gran {law} zplane 0 NULL
fix             g all gravity 9.81 vector 0 0 -1
fix             i all tdem/integrate scheme velocity_verlet_ab2
timestep        2e-5
compute         nc all contact/atom
compute         ncs all reduce sum c_nc
thermo_style    custom step ke c_ncs
thermo_modify   format float %.17g
thermo          1000
run             3000
write_dump      all custom dump.{tag} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""


# 9 columns of 4 spheres (d = 5 mm, 2500 kg/m^3), 10 mm apart, each contact pressed to its static
# overlap n m g / k (n the spheres it carries; k = 2000 N/m): the columns start at rest and stay
# there, so every contact exists from the set-up and none ends
def _columns():
    d, k = 0.005, 2000.0
    delta = 2500.0 * math.pi / 6.0 * d ** 3 * 9.81 / k
    zs, z = [], d / 2 - 4 * delta
    for n in (3, 2, 1, 0):
        zs.append(z)
        z += d - n * delta
    return "\n".join("create_atoms    1 single %r %r %r units box" % (0.005 + 0.01 * ix, 0.005 + 0.01 * iy, zz)
                     for ix in range(3) for iy in range(3) for zz in zs)


COLUMNS = _columns()


def part_unchanged():
    wd = lc.workdir("gc_unchanged")
    dumps, outs = {}, {}
    for tag, law in (("off", LAW), ("on", LAW + " grid_correction on")):
        _, outs[tag] = lc.run(args["tdem"], STACK.format(law=law, tag=tag, atoms=COLUMNS), wd, "in." + tag)
        dumps[tag] = lc.read_dump(os.path.join(wd, "dump." + tag))[1]
    nc = [float(r.split()[2]) for r in lc.thermo_blocks(outs["on"])[1:]]
    chk.check(len(nc) > 1 and min(nc) == max(nc) > 0,
              "9 columns of 4 spheres on the floor keep their contacts (%s)" % sorted(set(nc)))
    same = np.array_equal(dumps["on"], dumps["off"])
    chk.check(same, "its 3000 steps with the correction equal those without it bitwise (contacts that exist "
              "from the set-up are not corrected; largest difference %.2g)"
              % np.max(np.abs(dumps["on"] - dumps["off"])))
    # a restart whose contacts carry another history size than the new pair_coeff: ERROR
    text = STACK.format(law=LAW, tag="w", atoms=COLUMNS).replace("write_dump", "write_restart r.restart\nwrite_dump")
    lc.run(args["tdem"], text, wd, "in.wr")
    text = ("read_restart r.restart\nneighbor 0.001 bin\npair_coeff * * %s grid_correction on\n"
            "fix w2 all tdem/wall/gran %s zplane 0 NULL\nfix i all tdem/integrate scheme velocity_verlet\n"
            "timestep 2e-5\nrun 10\n" % (LAW, LAW))
    rc, out = lc.run(args["tdem"], text, wd, "in.rd", check=False)
    chk.check(rc != 0 and "ERROR" in out and "cannot take over the contacts of a restart file" in out,
              "switching grid_correction on at a restart: ERROR naming the history sizes")
    # a corrected contact that ends at a step that rebuilds the neighbour list keeps its history
    # (pair tdem/gran sets beyond_contact): a head-on impact with a rebuild at every step has the e of
    # the default rebuild schedule, bitwise (without it the end's impulse was lost: e 0.80405 against
    # 0.79945)
    es = {}
    for nm in ("delay 0 every 1 check yes", "delay 0 every 1 check no"):
        text = REBUILD.format(nm=nm)
        _, out = lc.run(args["tdem"], text, wd, "in.rebuild")
        es[nm] = float(lc.thermo_blocks(out)[-1].split()[1]) / -0.5
    vals = list(es.values())
    chk.check(vals[0] == vals[1] and abs(vals[0] - 0.8) < 2e-3,
              "a rebuild at every step leaves the corrected e unchanged (%.6f, %.6f)" % tuple(vals))


REBUILD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box      1 box
create_atoms    1 single 0 0 -0.0105 units box
create_atoms    1 single 0 0 0.0105 units box
set             group all diameter 0.02
set             group all density 2500
velocity        all set 0 0 0
set             atom 1 vz 0.5
set             atom 2 vz -0.5
neighbor        0.002 bin
neigh_modify    {nm}
pair_style      tdem/gran
pair_coeff      * * normal lsd restitution 0.8 1e-3 tangential cundall_strack 0.8 0.3 grid_correction on
fix             nve all nve/sphere
timestep        3.7e-5
variable        v1 equal vz[1]
thermo_style    custom step v_v1
thermo_modify   format float %.17g
thermo          100
run             100
"""


def part_mpi():
    wd = lc.workdir("gc_mpi")
    lc.small_bed_data(os.path.join(wd, "bed.data"), xhi=0.06, vz_shift=-0.3)
    law = LAW + " grid_correction on"
    n1, n2 = 1500, 1500
    dump = "write_dump all custom dump.{t} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g"
    common = dict(law=law, xhi=0.06, gvec="0.7071067811865476 0 -0.7071067811865476")
    ref = BED.format(read="read_data bed.data", body="run %d\nrun %d\n%s" % (n1, n2, dump.format(t="ref")), **common)
    lc.run(args["tdem"], ref, wd, "in.ref")
    part1 = BED.format(read="processors 2 1 1\nread_data bed.data",
                       body="run %d\nwrite_restart half.restart" % n1, **common)
    lc.run(args["tdem"], part1, wd, "in.p1", np_=2, mpirun=args["mpirun"])
    part2 = BED.format(read="processors 2 1 1\nread_restart half.restart",
                       body="run %d\n%s" % (n2, dump.format(t="np2")), **common).replace(
        "pair_coeff      * * " + law + "\n", "")
    _, out = lc.run(args["tdem"], part2, wd, "in.p2", np_=2, mpirun=args["mpirun"])
    a = lc.read_dump(os.path.join(wd, "dump.np2"))[1]
    b = lc.read_dump(os.path.join(wd, "dump.ref"))[1]
    d = lc.rel_diff(a[:, 1:], b[:, 1:])[1]
    chk.check(a.shape == b.shape and d <= 1e-8,
              "-np 2 with restart vs -np 1 uninterrupted, grid_correction on: max relative difference %.2g <= 1e-8" % d)
    # control: without the correction the end state differs
    refoff = BED.format(read="read_data bed.data", body="run %d\nrun %d\n%s" % (n1, n2, dump.format(t="off")),
                        **dict(common, law=LAW))
    lc.run(args["tdem"], refoff, wd, "in.off")
    c = lc.read_dump(os.path.join(wd, "dump.off"))[1]
    dc = lc.rel_diff(c[:, 1:], b[:, 1:])[1]
    chk.check(dc > 100 * 1e-8, "control: the uncorrected run differs (%.2g > 1e-6)" % dc)


BAD = """
units si
atom_style sphere
boundary f f f
region box block 0 0.1 0 0.1 0 0.1 units box
create_box 1 box
create_atoms 1 single 0.05 0.05 0.05 units box
set group all diameter 0.01
pair_style tdem/gran
pair_coeff * * normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5 {opt}
run 0
"""


def part_bad_input():
    wd = lc.workdir("gc_bad")
    for opt, want in (("grid_correction", "keyword 'grid_correction' needs a value; allowed: on, off"),
                      ("grid_correction maybe", "grid_correction 'maybe' is unknown; allowed: on, off")):
        rc, out = lc.run(args["tdem"], BAD.format(opt=opt), wd, "in.bad", check=False)
        chk.check(rc != 0 and "ERROR" in out and want in out, "'%s': ERROR with \"%s\"" % (opt, want))


{"harness": part_harness, "unchanged": part_unchanged, "mpi": part_mpi, "bad_input": part_bad_input}[PART]()
chk.done()
