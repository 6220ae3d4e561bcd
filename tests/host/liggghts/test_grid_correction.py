# SPDX-License-Identifier: GPL-2.0-or-later
"""`grid_correction on` of the tdem normal laws in pair gran and fix wall/gran (issue 22;
src/contact/grid_correction.h, src/pair_styles/liggghts/tdem_liggghts_grid.h).

Parts (--part, all by default):

harness   A sphere hits the floor (wall/gran primitive zplane) from a gap with the correction on,
          `fix tdem/integrate scheme S`, no gravity: e (and for the oblique impact e_t and the
          spin) equal `tdem-collide ... --scheme S --gap GAP --grid-correction on` (the same rules
          on the single-collision harness), for tdem/lsd (both ends), tdem/hertz damping tsuji,
          tdem/walton_braun and tdem/lsd + tdem/cundall_strack at 25 degrees; velocity_verlet and
          velocity_verlet_ab2; 4 phases of the touch each, at 25.37 steps per contact. Two spheres
          head-on (pair gran, equal masses) equal the harness with m* and the closing speed, and a
          mesh floor (wall/gran mesh) gives the primitive wall's oblique impacts bitwise. With
          velocity_verlet_ab2 the lsd |de| against the closed form, mean of the phases, is <= 1e-3
          with the correction and > 3e-3 without it (first order: the control).
unchanged Columns at rest (9 columns of 4 spheres at their static overlaps on the floor, gravity,
          3000 steps): their contacts exist from the set-up and persist, so the run with the
          correction equals the one without bitwise.
mpi       A bed of spheres falling onto the floor (dense collisions, side walls) with the
          correction on: -np 2 equals -np 1 to 1e-8 relative after 4000 steps (0.2 s), and
          `run; write_restart` / `read_restart; run` on 2 ranks equals the uninterrupted run to
          1e-10; the run without the correction differs (control).
fast_end  Fast impacts (tdem/lsd, velocity_verlet_ab2, 3 m/s at the step of 25.37 steps per contact at
          1 m/s: the approach speed times the step is 2.4 % of the radius, the gap at the first step
          apart up to 1.9 %): with the default contact distance factor (1.01) the warning that an end
          lies beyond the contact distance is printed; with neigh_modify contact_distance_factor
          1.05 it is not, and e equals the harness for 4 phases of the touch. The 1 m/s impacts
          (gap per step 0.8 %) print no warning.
bad_input grid_correction without a value or with a wrong one: ERROR naming the keyword and the
          allowed values; with a stock normal model (hertz): ERROR.
"""
import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np

import tdem_lig as T

HEAD = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
"""
R, MASS, K, GAMMA, V0 = 0.005, 1.25e-3, 1.2e4, 0.55, 1.0
KT, MU = 0.3 * K, 0.3
E_YOUNG, NU = 1.0e7, 0.3
LSD_PROPS = """
fix m_kn all property/global kn peratomtypepair 1 %r
fix m_kt all property/global kt peratomtypepair 1 %r
fix m_gn all property/global gamman_abs peratomtypepair 1 %r
fix m_gt all property/global gammat_abs peratomtypepair 1 0.0
fix m_mu all property/global coefficientFriction peratomtypepair 1 %r
""" % (K, KT, GAMMA, MU)
LSD = "model tdem/lsd tangential tdem/cundall_strack|absolute_damping on"
LSD_H = ["--law", "lsd", "--k", repr(K), "--gamma", repr(GAMMA)]
MAT_PROPS = """
fix m_E  all property/global youngsModulus peratomtype %r
fix m_nu all property/global poissonsRatio peratomtype %r
fix m_mu all property/global coefficientFriction peratomtypepair 1 %r
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.3
""" % (E_YOUNG, NU, MU)
KL = 1.0e4
# (name, model, properties, harness options, angle [deg])
CASES = [
    ("lsd zero_overlap", LSD, LSD_PROPS, LSD_H, 0.0),
    ("lsd zero_force", LSD + " limitForce on", LSD_PROPS, LSD_H + ["--end", "zero_force"], 0.0),
    ("hertz tsuji", "model tdem/hertz tangential tdem/cundall_strack|damping tsuji",
     MAT_PROPS + "fix m_e all property/global coefficientRestitution peratomtypepair 1 0.8\n",
     ["--law", "hertz", "--E", repr(E_YOUNG), "--nu", repr(NU), "--damping", "tsuji", "--e", "0.8"], 0.0),
    ("walton_braun", "model tdem/walton_braun tangential tdem/cundall_strack|",
     MAT_PROPS + "fix m_kl all property/global loadingStiffness peratomtypepair 1 %r\n"
     "fix m_ku all property/global unloadingStiffness peratomtypepair 1 %r\n"
     "fix m_s all property/global unloadingStiffnessSlope peratomtypepair 1 0.0\n" % (KL, KL / 0.49),
     ["--law", "walton_braun", "--kl", repr(KL), "--kul", repr(KL / 0.49), "--s", "0"], 0.0),
    ("lsd 25 deg + cundall_strack", LSD, LSD_PROPS,
     LSD_H + ["--tangential", "cundall_strack", "--kt", repr(KT), "--mu", repr(MU), "--lever-arm", "contact_point"],
     25.0),
]
SCHEMES = ("velocity_verlet", "velocity_verlet_ab2")
PHASES = 4
SPC = 25.37


def wall_line(name, model, where):
    """`fix NAME all wall/gran` for model "MODEL|SETTINGS": the model, then the wall, then the settings."""
    m, _, settings = model.partition("|")
    return "fix %s all wall/gran %s primitive type 1 %s %s" % (name, m, where, settings)


def pair_line(model):
    return "pair_style gran " + model.replace("|", " ")


def collide(args, checks, cmd):
    r = subprocess.run([args.collide] + cmd, capture_output=True, text=True)
    if r.returncode != 0:
        checks.check(False, "tdem-collide %s failed: %s" % (" ".join(cmd), (r.stderr or r.stdout)[-300:]))
        return None
    return json.loads(r.stdout)


def wall_impacts(model, props, dt, impacts, nsteps, gc=True):
    """One sphere per (scheme, gap, vn, vt); returns the input text."""
    on = " grid_correction on" if gc else ""
    lines = []
    for k, (scheme, gap, vn, vt) in enumerate(impacts):
        lines.append("create_atoms 1 single %r 0.0 %r units box" % (0.03 * k, R + gap))
        lines.append("group g%d id %d" % (k, k + 1))
        lines.append("set group g%d vz %r vx %r" % (k, -vn, vt))
        lines.append("fix i%d g%d tdem/integrate scheme %s" % (k, k, scheme))
    return HEAD + """
region box block -0.01 %r -0.02 0.02 -0.001 0.05 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
%s
%s
pair_coeff * *
timestep %r
%s
set group all diameter %r density 2500
set group all mass %r
%s
compute om all property/atom omegay
dump d all custom %d dump.h id z vx vz c_om fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
run %d
""" % (0.03 * len(impacts), props, pair_line(model) + on, dt, "\n".join(lines), 2 * R, MASS,
       wall_line("wz", model, "zplane 0.0") + on, nsteps, nsteps)


def part_harness(args, checks):
    if not args.collide:
        checks.check(False, "harness: --collide (tdem-collide) not given")
        return
    body = ["--m1", repr(MASS), "--R1", repr(R), "--wall", "--v0", repr(V0)]
    errs = {}
    for name, model, props, hopts, angle in CASES:
        base = collide(args, checks, hopts + body)
        if base is None:
            continue
        dt = float("%.6g" % (base["contact_time"] / SPC))
        th = math.radians(angle)
        vn, vt = V0 * math.cos(th), V0 * math.sin(th)
        impacts = [(s, (3 + (k + 0.5) / PHASES) * vn * dt, vn, vt) for s in SCHEMES for k in range(PHASES)]
        nsteps = int(4 + 1.6 * SPC + 40)
        d = T.workdir(args, "tdem_lig_gc_" + name.replace(" ", "_"))
        T.run(args.tdem, wall_impacts(model, props, dt, impacts, nsteps), d, "h")
        st, cols, a = T.read_dump(os.path.join(d, "dump.h"))[-1]
        for k, (scheme, gap, _, _) in enumerate(impacts):
            z, vx, vz, om, fz = (a[k, cols.index(c)] for c in ("z", "vx", "vz", "c_om", "fz"))
            ended = z > R and fz == 0.0 and vz > 0
            cmd = hopts + body + ["--scheme", scheme, "--dt", repr(dt), "--gap", repr(gap), "--grid-correction", "on"]
            if angle:
                cmd += ["--angle", repr(angle)]
            h = collide(args, checks, cmd)
            if h is None:
                continue
            e_host = vz / vn
            dev = abs(e_host - h["e"])
            msg = "%s, %s, phase %d: e host %.12f harness %.12f" % (name, scheme, k % PHASES, e_host, h["e"])
            if angle:
                dev = max(dev, abs(vx / vt - h["e_t"]), abs(-om - h["spin_after"]) * R / V0)
                msg += ", e_t %.12f / %.12f, spin %.9g / %.9g" % (vx / vt, h["e_t"], -om, h["spin_after"])
            checks.check(ended and dev <= 1e-9, msg + " (difference %.2g <= 1e-9)%s" % (dev, "" if ended else
                                                                                        " CONTACT NOT OVER"))
            if angle == 0.0 and name.startswith("lsd") and scheme == "velocity_verlet_ab2":
                errs.setdefault(name, []).append(abs(e_host - base["closed_form"]["e"]))
    # the same oblique impacts on a mesh floor (fix mesh/surface, two triangles at z = 0): the
    # mesh wall's contact history and surfacesClose give the primitive wall's result bitwise
    name, model, props, hopts, angle = CASES[-1]
    base = collide(args, checks, hopts + body)
    if base is not None:
        dt = float("%.6g" % (base["contact_time"] / SPC))
        th = math.radians(angle)
        vn, vt = V0 * math.cos(th), V0 * math.sin(th)
        impacts = [("velocity_verlet_ab2", (3 + (k + 0.5) / PHASES) * vn * dt, vn, vt) for k in range(PHASES)]
        nsteps = int(4 + 1.6 * SPC + 40)
        finals = {}
        for kind in ("primitive", "mesh"):
            text = wall_impacts(model, props, dt, impacts, nsteps)
            if kind == "mesh":
                text = text.replace(wall_line("wz", model, "zplane 0.0"),
                                    "fix cad all mesh/surface file floor.stl type 1\n" +
                                    wall_line("wz", model, "X").replace("primitive type 1 X", "mesh n_meshes 1 meshes cad"))
            d = T.workdir(args, "tdem_lig_gc_floor_" + kind)
            with open(os.path.join(d, "floor.stl"), "w") as f:
                f.write("solid floor\n" + "".join(
                    "facet normal 0 0 1\nouter loop\n%sendloop\nendfacet\n" % "".join("vertex %r %r 0\n" % p for p in tri)
                    for tri in (((-0.005, -0.015), (0.115, -0.015), (0.115, 0.015)),
                                ((-0.005, -0.015), (0.115, 0.015), (-0.005, 0.015)))) + "endsolid floor\n")
            T.run(args.tdem, text, d, "h")
            finals[kind] = T.read_dump(os.path.join(d, "dump.h"))[-1][2]
        a, b = finals["primitive"], finals["mesh"]
        checks.check(a.shape == b.shape and np.array_equal(a, b), "%s, velocity_verlet_ab2, 4 phases: mesh floor = "
                     "primitive zplane bitwise (e %.12f ... %.12f)" % (name, b[0, 3] / vn, b[-1, 3] / vn))
    for name, v in errs.items():
        checks.check(np.mean(v) <= 1e-3, "%s, velocity_verlet_ab2 with the correction: mean |de| over the phases "
                     "%.2e <= 1e-3 (%.2f steps per contact)" % (name, np.mean(v), SPC))
    # control: the same lsd impacts without the correction are first order
    base = collide(args, checks, LSD_H + body)
    if base is None:
        return
    dt = float("%.6g" % (base["contact_time"] / SPC))
    impacts = [("velocity_verlet_ab2", (3 + (k + 0.5) / PHASES) * V0 * dt, V0, 0.0) for k in range(PHASES)]
    d = T.workdir(args, "tdem_lig_gc_off")
    T.run(args.tdem, wall_impacts(LSD, LSD_PROPS, dt, impacts, int(4 + 1.6 * SPC + 40), gc=False), d, "h")
    st, cols, a = T.read_dump(os.path.join(d, "dump.h"))[-1]
    off = [abs(a[k, cols.index("vz")] / V0 - base["closed_form"]["e"]) for k in range(PHASES)]
    checks.check(np.mean(off) > 3e-3, "control: lsd without the correction, mean |de| %.2e > 3e-3" % np.mean(off))
    # two spheres head-on (pair gran): the harness with m* = m/2 and the closing speed 2 v
    v = 0.5 * V0
    pb = collide(args, checks, LSD_H + ["--m1", repr(0.5 * MASS), "--R1", repr(R), "--wall", "--v0", repr(V0)])
    if pb is None:
        return
    dt = float("%.6g" % (pb["contact_time"] / SPC))
    for scheme in SCHEMES:
        for k in range(2):
            gap = (3 + (k + 0.25) / 2) * V0 * dt
            text = HEAD + """
region box block -0.03 0.03 -0.02 0.02 -0.02 0.02 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
%s
%s grid_correction on
pair_coeff * *
timestep %r
create_atoms 1 single %r 0 0 units box
create_atoms 1 single %r 0 0 units box
set group all diameter %r density 2500
set group all mass %r
set atom 1 vx %r
set atom 2 vx %r
fix i all tdem/integrate scheme %s
dump d all custom %d dump.p id x vx
dump_modify d sort id format "%%d %%.17g %%.17g"
thermo 1000000
run %d
""" % (LSD_PROPS, pair_line(LSD), dt, -R - gap / 2, R + gap / 2, 2 * R, MASS, v, -v, scheme, 100, 100)
            d = T.workdir(args, "tdem_lig_gc_pair")
            T.run(args.tdem, text, d, "p")
            st, cols, a = T.read_dump(os.path.join(d, "dump.p"))[-1]
            e_host = (a[1, cols.index("vx")] - a[0, cols.index("vx")]) / V0
            h = collide(args, checks, LSD_H + ["--m1", repr(0.5 * MASS), "--R1", repr(R), "--wall", "--v0", repr(V0),
                                               "--scheme", scheme, "--dt", repr(dt), "--gap", repr(gap),
                                               "--grid-correction", "on"])
            if h is not None:
                checks.check(abs(e_host - h["e"]) <= 1e-9, "pair head-on, %s, phase %d: e host %.12f harness %.12f"
                             % (scheme, k, e_host, h["e"]))


def columns(gc, steps=3000):
    g = 9.81
    ov = MASS * g / K  # the static overlap per sphere above a contact
    lines = []
    for c in range(9):
        z = R - ov * 4
        for s in range(4):
            lines.append("create_atoms 1 single %r 0 %r units box" % (0.02 * c, z))
            z += 2 * R - ov * (3 - s)
    on = " grid_correction on" if gc else ""
    model = LSD
    return HEAD + """
region box block -0.01 0.18 -0.01 0.01 -0.001 0.06 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
%s
%s
pair_coeff * *
timestep 2e-5
%s
set group all diameter %r density 2500
set group all mass %r
%s
fix gr all gravity %r vector 0 0 -1
fix i all tdem/integrate scheme velocity_verlet
dump d all custom %d dump.c id x z vx vz fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
run %d
""" % (LSD_PROPS, pair_line(model) + on, "\n".join(lines), 2 * R, MASS, wall_line("wz", model, "zplane 0.0") + on,
       g, steps, steps)


def part_unchanged(args, checks):
    res = {}
    for gc in (False, True):
        d = T.workdir(args, "tdem_lig_gc_unchanged_%d" % gc)
        T.run(args.tdem, columns(gc), d, "c")
        res[gc] = T.read_dump(os.path.join(d, "dump.c"))[-1][2]
    a, b = res[False], res[True]
    moved = np.max(np.abs(a[:, 4])) if len(a) else 0.0
    checks.check(len(a) == 36 and np.array_equal(a, b),
                 "columns at rest, 3000 steps: with the correction = without, bitwise (max |vz| %.2e, max |diff| %.2e)"
                 % (moved, np.max(np.abs(a - b)) if a.shape == b.shape else float("nan")))


def walls(on):
    return "\n".join(wall_line(n, LSD, w) + on for n, w in (("wz", "zplane 0.0"), ("wx1", "xplane -0.045"),
                                                              ("wx2", "xplane 0.045"), ("wy1", "yplane -0.028"),
                                                              ("wy2", "yplane 0.028")))


def bed(gc, steps, tail=""):
    on = " grid_correction on" if gc else ""
    atoms = []
    for i in range(8):
        for j in range(5):
            for k in range(5):
                atoms.append("create_atoms 1 single %r %r %r units box" %
                             (-0.036 + 0.0102 * i + 0.0007 * (j % 2), -0.02 + 0.0102 * j, 0.01 + 0.0103 * k + 0.0005 * i))
    return HEAD + """
processors * 1 1
region box block -0.05 0.05 -0.03 0.03 -0.001 0.1 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
%s
%s
pair_coeff * *
timestep 5e-5
%s
set group all diameter %r density 2500
set group all mass %r
%s
fix gr all gravity 9.81 vector 0 0 -1
fix i all tdem/integrate scheme velocity_verlet_ab2
dump d all custom %d dump.b id x y z vx vy vz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
%s
""" % (LSD_PROPS, pair_line(LSD) + on, "\n".join(atoms), 2 * R, MASS, walls(on), steps, tail)


def part_mpi(args, checks):
    n = 4000
    finals = {}
    for tag, gc, np_ in (("np1", True, 1), ("np2", True, 2), ("off", False, 1)):
        d = T.workdir(args, "tdem_lig_gc_mpi_" + tag)
        T.run(args.tdem, bed(gc, n, "run %d" % n), d, "b", np_=np_, mpirun=args.mpirun)
        finals[tag] = T.read_dump(os.path.join(d, "dump.b"))[-1]
    a = finals["np1"][2]
    b = finals["np2"][2]
    scale = np.maximum(np.max(np.abs(a[:, 1:]), axis=0), 1e-300)
    dev = np.max(np.abs(a[:, 1:] - b[:, 1:]) / scale) if a.shape == b.shape else float("inf")
    hit = np.max(a[:, 3]) < 0.05  # the top layer (from z = 0.06) has fallen into the bed
    checks.check(hit and dev <= 1e-8, "bed of %d spheres, %d steps: -np 2 = -np 1 within %.2g (<= 1e-8); "
                 "the bed reached the floor: %s" % (len(a), n, dev, hit))
    c = finals["off"][2]
    dctl = np.max(np.abs(a[:, 1:] - c[:, 1:]) / scale)
    checks.check(dctl > 1e-6, "control: the run without the correction differs by %.2g (> 1e-6)" % dctl)
    # restart in the middle, on 2 ranks
    d = T.workdir(args, "tdem_lig_gc_mpi_restart")
    T.run(args.tdem, bed(True, n, "run %d\nwrite_restart r.restart" % (n // 2)), d, "b1", np_=2, mpirun=args.mpirun)
    text = HEAD + """
processors * 1 1
read_restart r.restart
neighbor 0.001 bin
neigh_modify delay 0
%s
%s grid_correction on
pair_coeff * *
timestep 5e-5
%s
fix gr all gravity 9.81 vector 0 0 -1
fix i all tdem/integrate scheme velocity_verlet_ab2
dump d all custom %d dump.b id x y z vx vy vz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
run %d
""" % (LSD_PROPS, pair_line(LSD), walls(" grid_correction on"), n - n // 2, n - n // 2)
    text = text.replace("atom_style granular\natom_modify map array\nboundary f f f\n", "")
    T.run(args.tdem, text, d, "b2", np_=2, mpirun=args.mpirun)
    r = T.read_dump(os.path.join(d, "dump.b"))[-1][2]
    dev = np.max(np.abs(a[:, 1:] - r[:, 1:]) / scale) if a.shape == r.shape else float("inf")
    checks.check(dev <= 1e-8, "write_restart at step %d / read_restart on 2 ranks = uninterrupted -np 1 within %.2g "
                 "(<= 1e-8)" % (n // 2, dev))


UNSEEN = "gap beyond the contact distance"


def part_fast_end(args, checks):
    if not args.collide:
        checks.check(False, "fast_end: --collide (tdem-collide) not given")
        return
    base = collide(args, checks, LSD_H + ["--m1", repr(MASS), "--R1", repr(R), "--wall", "--v0", repr(V0)])
    if base is None:
        return
    dt = float("%.6g" % (base["contact_time"] / SPC))
    nsteps = int(4 + 1.6 * SPC + 40)
    for v, factor, warn in ((V0, None, False), (3.0 * V0, None, True), (3.0 * V0, 1.05, False)):
        impacts = [("velocity_verlet_ab2", (3 + (k + 0.5) / PHASES) * v * dt, v, 0.0) for k in range(PHASES)]
        text = wall_impacts(LSD, LSD_PROPS, dt, impacts, nsteps)
        if factor:
            text = text.replace("neigh_modify delay 0", "neigh_modify delay 0 contact_distance_factor %r" % factor)
        d = T.workdir(args, "tdem_lig_gc_fast")
        r = T.run(args.tdem, text, d, "h")
        out = r.stdout + r.stderr
        what = "v0 %g m/s (v0 dt / R = %.3f), contact distance factor %s" % (v, v * dt / R, factor or "1.01 (default)")
        checks.check((UNSEEN in out) == warn, "%s: the unseen-end warning %s" % (what, "printed" if UNSEEN in out
                                                                                  else "not printed"))
        if not factor:
            continue
        a = T.read_dump(os.path.join(d, "dump.h"))[-1][2]
        cols = T.read_dump(os.path.join(d, "dump.h"))[-1][1]
        for k, (scheme, gap, _, _) in enumerate(impacts):
            h = collide(args, checks, LSD_H + ["--m1", repr(MASS), "--R1", repr(R), "--wall", "--v0", repr(v),
                                               "--scheme", scheme, "--dt", repr(dt), "--gap", repr(gap),
                                               "--grid-correction", "on"])
            if h is not None:
                e_host = a[k, cols.index("vz")] / v
                checks.check(abs(e_host - h["e"]) <= 1e-9, "%s, phase %d: e host %.12f harness %.12f"
                             % (what, k, e_host, h["e"]))


def part_bad_input(args, checks):
    d = T.workdir(args, "tdem_lig_gc_bad")
    base = HEAD + """
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box 1 box
%s
pair_style gran %s
pair_coeff * *
run 0
"""
    lsd = LSD.replace("|", " ")
    for tail, want in ((lsd + " grid_correction", "grid_correction"), (lsd + " grid_correction maybe", "grid_correction"),
                       ("model hertz tangential history grid_correction on", "grid_correction")):
        r = T.run(args.tdem, base % (LSD_PROPS, tail), d, "bad", check=False)
        out = r.stdout + r.stderr
        err = [l for l in out.splitlines() if "ERROR" in l]
        checks.check(r.returncode != 0 and err and want in err[0] and "Segmentation" not in out,
                     "pair_style gran %s: %s" % (tail, err[0].strip() if err else "NO ERROR (rc %d)" % r.returncode))


def main():
    args = T.parse_args(lambda p: (p.add_argument("--collide"), p.add_argument("--part", default="all")))
    checks = T.Checks()
    parts = {"harness": part_harness, "unchanged": part_unchanged, "mpi": part_mpi, "fast_end": part_fast_end,
             "bad_input": part_bad_input}
    for name, f in parts.items():
        if args.part in ("all", name):
            f(args, checks)
    checks.done()


if __name__ == "__main__":
    main()
