# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/grate in LIGGGHTS (issue 7): the grate's bars are LIGGGHTS meshes moved by the fix and seen
by the stock fix wall/gran. Expected values are computed here independently of the code under test:

 kinematics  u_g(t), du_g/dt of every phase group (fix vector, printed with 17 digits) against this
             file's own implementation of the profiles of docs/grate.md §3 (sinusoidal with phases,
             trapezoidal with dwells, forward share and t_start, trapezoidal_accel), 1e-12 relative;
             the bar corners of the VTK XML files (.vtp, read with the VTK library) against this file's
             own grate geometry (docs/grate.md §1), 1e-9 relative, and the series bars.pvd (every file,
             in step order, at t = step*dt); the nodes and the element
             velocity "v" of the LIGGGHTS meshes themselves (dump mesh/vtk: nodes as %g, 6 digits).
 carried     a sphere resting on a moving bar: without rotation it follows the bar, x - x0 = u(t);
             with rotation it rolls without slip and its centre follows (2/7) u(t) (solid sphere on an
             accelerating surface: a = a_s I/(I + m R^2)); a sphere on a fixed bar does not move (< 1e-9 m).
 rebound     a sphere dropped (gravity off) on a fixed horizontal bar rebounds with the e of the law:
             tdem/lsd `parameters restitution` (e given) and stock hooke (e given, zero-overlap
             convention), to 1e-3.
 parallel    a bed of spheres on a moving grate, -np 2 against -np 1 after N steps (1e-8 m), and
             `write_restart` + `read_restart` continuing one run (np 2).
 bad         bad input ends with an error naming the keyword, the value and the allowed values.
 2d          frame xy, dimension 2, enforce2d: a disk is carried by a moving bar (no rotation), one
             on a fixed bar stays, and the VTK corners follow the xy mapping.
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

import tdem_lig as T
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import vtk_read as vr  # noqa: E402

PI = math.pi


# ----------------------------------------------------------------------------- reference kinematics
def unit_stroke(profile, ramp, s, d):
    """f, df/ds of a unit stroke of duration d at elapsed time s (docs/grate.md §3)."""
    if profile == "sinusoidal":
        w = PI / d
        return 0.5 * (1.0 - math.cos(w * s)), 0.5 * w * math.sin(w * s)
    if profile == "trapezoidal":
        return s / d, 1.0 / d
    # trapezoidal_accel: accelerate over ta, cruise, decelerate over ta
    ta = ramp * d
    vmax = 1.0 / (d - ta)
    acc = vmax / ta
    if s < ta:
        return 0.5 * acc * s * s, acc * s
    if s <= d - ta:
        return 0.5 * acc * ta * ta + vmax * (s - ta), vmax
    q = d - s
    return 1.0 - 0.5 * acc * q * q, acc * q


def motion(m, t, phase):
    """(u, v, distance of t to the nearest segment boundary) of a row of phase `phase`."""
    stroke = m["stroke"]
    if stroke == 0.0:
        return 0.0, 0.0, 1.0
    T_ = m["period"]
    tau = (t - m["t_start"]) / T_ - phase
    if tau < 0.0:
        return 0.0, 0.0, -tau * T_
    tau -= math.floor(tau)
    move = 1.0 - m["dwell_out"] - m["dwell_home"]
    bounds = [0.0, m["forward_share"] * move, m["forward_share"] * move + m["dwell_out"],
              m["forward_share"] * move + m["dwell_out"] + (1.0 - m["forward_share"]) * move, 1.0]
    dist = min(abs(tau - b) for b in bounds) * T_
    s = tau * T_
    d_f = (bounds[1] - bounds[0]) * T_
    d_r = (bounds[3] - bounds[2]) * T_
    if tau < bounds[1]:
        f, fd = unit_stroke(m["profile"], m["ramp"], s, d_f)
        return stroke * f, stroke * fd, dist
    if tau < bounds[2]:
        return stroke, 0.0, dist
    if tau < bounds[3]:
        f, fd = unit_stroke(m["profile"], m["ramp"], s - bounds[2] * T_, d_r)
        return stroke * (1.0 - f), -stroke * fd, dist
    return 0.0, 0.0, dist


MOTION_DEFAULTS = dict(profile="sinusoidal", stroke=0.0, period=1.0, t_start=0.0, dwell_out=0.0, dwell_home=0.0,
                       forward_share=0.5, ramp=0.25)
GEOM_DEFAULTS = dict(rows=6, bar_length=0.2, bar_height=0.05, step_height=0.0, overlap=0.0, declination=12.0,
                     width=0.2, side_walls=False, wall_height=0.3, wall_thickness=0.01, type="forward", frame="xyz",
                     origin=(0.0, 0.0, 0.0), row_group=None, group_phase=None)


def grate_args(g, m):
    """fix tdem/grate arguments of a geometry dict g and a motion dict m."""
    a = []
    for k in ("rows", "bar_length", "bar_height", "step_height", "overlap", "declination", "width", "wall_height",
              "wall_thickness"):
        a += [k, repr(g[k])]
    a += ["side_walls", "yes" if g["side_walls"] else "no", "type", g["type"], "frame", g["frame"],
          "origin"] + [repr(x) for x in g["origin"]]
    if g["row_group"] is not None:
        a += ["row_group"] + [str(x) for x in g["row_group"]]
    if g["group_phase"] is not None:
        a += ["group_phase"] + [repr(x) for x in g["group_phase"]]
    for k in ("profile", "stroke", "period", "t_start", "dwell_out", "dwell_home", "forward_share", "ramp"):
        a += [k, m[k] if k == "profile" else repr(m[k])]
    return " ".join(a)


def row_groups(g):
    return g["row_group"] if g["row_group"] is not None else [0 if i % 2 == 1 else -1 for i in range(g["rows"])]


def phases(g):
    ng = max(row_groups(g)) + 1
    return g["group_phase"] if g["group_phase"] is not None else [0.0] * ng


def to_global(g, p):
    o = g["origin"]
    if g["frame"] == "xyz":
        return np.array([o[0] + p[0], o[1] + p[1], o[2] + p[2]])
    return np.array([o[0] + p[0], o[1] + p[2], o[2] - p[1]])


def ref_corners(g, m, t):
    """Corners of every box (rows in order, then side walls), in the order of Grate::box_mesh:
    corner c has the sign of local axis k set if bit k of c is set; local axes (e_t, e_w, e_n)."""
    a = math.radians(g["declination"])
    e_t = np.array([math.cos(a), 0.0, -math.sin(a)])
    e_n = np.array([math.sin(a), 0.0, math.cos(a)])
    e_w = np.array([0.0, 1.0, 0.0])
    up = np.array([0.0, 0.0, 1.0])
    L, h, W, s = g["bar_length"], g["bar_height"], g["width"], g["step_height"]
    sign = 1.0 if g["type"] == "forward" else -1.0
    rg, ph = row_groups(g), phases(g)
    boxes_local = []
    for i in range(g["rows"]):
        heel = i * (L - g["overlap"]) * e_t - i * s * up
        c = heel + 0.5 * L * e_t - 0.5 * h * e_n
        boxes_local.append((c, (e_t, e_w, e_n), (0.5 * L, 0.5 * W, 0.5 * h), rg[i]))
    corners = []
    rest = []
    for (c, ax, half, grp) in boxes_local:
        u = motion(m, t, ph[grp])[0] if grp >= 0 else 0.0
        for cc in range(8):
            q0 = c.copy()
            for k in range(3):
                q0 = q0 + (half[k] if (cc >> k) & 1 else -half[k]) * ax[k]
            rest.append(q0)
            corners.append(to_global(g, q0 + u * sign * e_t))
    if g["side_walls"]:
        rest = np.array(rest)
        xmin, xmax = rest[:, 0].min(), rest[:, 0].max()
        umin, umax = rest[:, 2].min(), rest[:, 2].max()
        reach = m["stroke"] * math.cos(a)
        xmin -= reach
        xmax += reach
        umax += g["wall_height"]
        wt = g["wall_thickness"]
        for sgn in (-1, 1):
            c = np.array([0.5 * (xmin + xmax), sgn * (0.5 * W + 0.5 * wt), 0.5 * (umin + umax)])
            half = (0.5 * (xmax - xmin), 0.5 * wt, 0.5 * (umax - umin))
            for cc in range(8):
                q = c.copy()
                for k in range(3):
                    q[k] += half[k] if (cc >> k) & 1 else -half[k]
                corners.append(to_global(g, q))
    return np.array(corners)


def read_vtk_points(path):
    """the points of a .vtp of fix tdem/grate, read with the VTK library (tests/host/vtk_read.py)"""
    return vr.read_dataset(path)["points"]


def read_mesh_vtk(path):
    """LIGGGHTS dump mesh/vtk: points and the cell field v."""
    with open(path) as f:
        toks = f.read().split()
    i = toks.index("POINTS")
    n = int(toks[i + 1])
    pts = np.array([float(x) for x in toks[i + 3:i + 3 + 3 * n]]).reshape(n, 3)
    j = toks.index("v")
    ncell = int(toks[j + 2])
    v = np.array([float(x) for x in toks[j + 4:j + 4 + 3 * ncell]]).reshape(ncell, 3)
    return pts, v


def thermo_rows(log_text):
    rows = []
    for header, lines in T.thermo_blocks(log_text):
        for l in lines:
            rows.append([float(x) for x in l.split()])
    return np.array(rows)


# ----------------------------------------------------------------------------- scenes
R = 0.005
RHO = 2500.0
TC = 1.0e-3
PROPS = """
fix m_e  all property/global coefficientRestitution peratomtypepair 1 %.17g
fix m_tc all property/global contactTime peratomtypepair 1 %.17g
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
"""
LAW = "model tdem/lsd tangential tdem/cundall_strack"


def header(box, dim=3, boundary="f p f", e=0.5, tc=TC, dt=2e-5, props=None, law=LAW, settings="parameters restitution"):
    return """
atom_style granular
atom_modify map array sort 0 0.0
dimension %d
boundary %s
newton off
communicate single vel yes
units si
region box block %s units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s %s
pair_coeff * *
timestep %.17g
""" % (dim, boundary, box, props if props is not None else PROPS % (e, tc), law, settings, dt)


def walls(fixid, meshes, law=LAW, settings="parameters restitution"):
    return "fix walls all wall/gran %s mesh n_meshes %d meshes %s %s\n" % (law, len(meshes), " ".join(meshes), settings)


def dump(every, name="dump.out"):
    return ("dump d all custom %d %s id x y z vx vy vz omegax omegay omegaz\n"
            "dump_modify d sort id format \"%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g\"\n"
            % (every, name))


# ----------------------------------------------------------------------------- parts
def part_kinematics(args, checks):
    dt = 1e-4
    cases = [
        ("sine_phases_reverse_walls",
         dict(GEOM_DEFAULTS, rows=4, bar_length=0.1, bar_height=0.02, step_height=0.01, overlap=0.004,
              declination=12.0, width=0.1, side_walls=True, wall_height=0.05, type="reverse",
              row_group=[-1, 0, -1, 1], group_phase=[0.0, 0.25], origin=(0.01, 0.0, 0.1)),
         dict(MOTION_DEFAULTS, profile="sinusoidal", stroke=0.03, period=0.2), "f f f", "-0.07 0.07"),
        ("trapezoid_dwell_forward_periodic",
         dict(GEOM_DEFAULTS, rows=5, bar_length=0.1, bar_height=0.02, step_height=0.005, declination=8.0,
              width=0.1, row_group=[-1, 0, 1, 0, -1], group_phase=[0.1, 0.6], origin=(0.0, 0.0, 0.1)),
         dict(MOTION_DEFAULTS, profile="trapezoidal", stroke=0.025, period=0.15, t_start=0.013, dwell_out=0.1,
              dwell_home=0.2, forward_share=0.6), "f p f", "-0.05 0.05"),
        ("trapezoid_accel",
         dict(GEOM_DEFAULTS, rows=3, bar_length=0.1, bar_height=0.02, declination=20.0, width=0.1,
              origin=(0.0, 0.0, 0.1)),
         dict(MOTION_DEFAULTS, profile="trapezoidal_accel", stroke=0.02, period=0.12, ramp=0.3, forward_share=0.4,
              dwell_home=0.1), "f p f", "-0.05 0.05"),
    ]
    for name, g, m, bnd, ybox in cases:
        d = T.workdir(args, "grate_kin_" + name)
        ng = max(row_groups(g)) + 1
        thermo = " ".join("f_g[%d] f_g[%d]" % (2 + 2 * k, 3 + 2 * k) for k in range(ng))
        meshes = " ".join("g_moving%d" % k for k in range(ng))
        text = header("-0.2 0.8 %s -0.3 0.3" % ybox, boundary=bnd, dt=dt)
        text += "fix g all tdem/grate %s vtk 250 bars\n" % grate_args(g, m)
        text += "dump dm all mesh/vtk 250 mesh_*.vtk vel %s\n" % meshes
        text += "thermo_style custom step f_g[1] %s\nthermo_modify format float %%.17g\nthermo 37\nrun 3000\n" % thermo
        r = T.run(args.tdem, text, d, "kin", mpirun=args.mpirun)
        rows = thermo_rows(open(os.path.join(d, "log.kin")).read())
        vmax = {"sinusoidal": 0.5 * PI, "trapezoidal": 1.0, "trapezoidal_accel": 1.0 / (1 - m["ramp"])}[m["profile"]]
        move = 1 - m["dwell_out"] - m["dwell_home"]
        vscale = m["stroke"] * vmax / (min(m["forward_share"], 1 - m["forward_share"]) * move * m["period"])
        eu = ev = et = 0.0
        nsamp = 0
        ph = phases(g)
        for row in rows:
            step = int(row[0])
            t = step * dt
            et = max(et, abs(row[1] - t) / max(t, 1e-300))
            for k in range(ng):
                u, v, dist = motion(m, t, ph[k])
                if dist < 1e-9:
                    continue
                eu = max(eu, abs(row[2 + 2 * k] - u) / m["stroke"])
                ev = max(ev, abs(row[3 + 2 * k] - v) / vscale)
                nsamp += 1
        checks.check(len(rows) > 70 and nsamp > 70, "%s: %d thermo samples of u_g, v_g (%d used)" % (name, len(rows), nsamp))
        checks.check(et < 1e-14, "%s: grate time = step*dt (max rel %.2e)" % (name, et))
        checks.check(eu < 1e-12, "%s: u_g(t) vs reference profile, max |du|/stroke = %.2e < 1e-12" % (name, eu))
        checks.check(ev < 1e-12, "%s: du_g/dt vs reference, max |dv|/v_max = %.2e < 1e-12" % (name, ev))
        # VTK bar corners
        files = sorted(glob.glob(os.path.join(d, "bars_*.vtp")), key=lambda p: int(re.findall(r"_(\d+)\.vtp", p)[0]))
        checks.check(len(files) == 13, "%s: VTK written at setup and every 250 steps (%d files, expected 13)" % (name, len(files)))
        series = vr.read_pvd(os.path.join(d, "bars.pvd"))
        checks.check([os.path.abspath(f) for _, f in series] == [os.path.abspath(f) for f in files] and
                     all(abs(t - int(re.findall(r"_(\d+)\.vtp", f)[0]) * dt) <= 1e-15 for t, f in series),
                     "%s: bars.pvd lists the %d files in step order at t = step*dt" % (name, len(series)))
        ev_ = 0.0
        moved = 0.0
        for p in files:
            step = int(re.findall(r"_(\d+)\.vtp", p)[0])
            pts = read_vtk_points(p)
            ref = ref_corners(g, m, step * dt)
            if pts.shape != ref.shape:
                checks.check(False, "%s: VTK %s has %d points, expected %d" % (name, os.path.basename(p), len(pts), len(ref)))
                continue
            ev_ = max(ev_, float(np.abs(pts - ref).max()) / g["bar_length"])
            moved = max(moved, float(np.abs(ref - ref_corners(g, m, 0.0)).max()))
        checks.check(moved > 0.5 * m["stroke"] * math.cos(math.radians(g["declination"])),
                     "%s: the sampled corners move (max %.3g m)" % (name, moved))
        checks.check(ev_ < 1e-9, "%s: VTK bar corners vs reference geometry, max %.2e (rel. to bar length) < 1e-9" % (name, ev_))
        # the LIGGGHTS meshes themselves: nodes (6 digits) and element velocity v
        sign = 1.0 if g["type"] == "forward" else -1.0
        a = math.radians(g["declination"])
        sdir = sign * np.array([math.cos(a), 0.0, -math.sin(a)])
        en = ev2 = 0.0
        nm = 0
        mfiles = sorted(glob.glob(os.path.join(d, "mesh_*.vtk")))
        for p in mfiles:
            step = int(re.findall(r"_(\d+)\.vtk", p)[0])
            t = step * dt
            pts, vel = read_mesh_vtk(p)
            ref = ref_corners(g, m, t)
            rg = row_groups(g)
            moving_idx = [8 * i + c for i in range(g["rows"]) if rg[i] >= 0 for c in range(8)]
            refm = ref[moving_idx]
            dist = np.sqrt(((pts[:, None, :] - refm[None, :, :]) ** 2).sum(-1)).min(axis=1)
            en = max(en, float(dist.max()))
            speeds = [motion(m, t, ph[kk])[1] for kk in range(ng)]
            # every cell velocity is one of the groups' stroke velocities
            for vv in vel:
                err = min(float(np.abs(vv - s_ * sdir).max()) for s_ in speeds)
                ev2 = max(ev2, err / vscale)
            nm += 1
        checks.check(nm == 13, "%s: %d mesh dumps (expected 13)" % (name, nm))
        checks.check(en < 2e-6, "%s: LIGGGHTS mesh nodes at the kinematic positions, max distance %.2e m < 2e-6 (%%g output)" % (name, en))
        checks.check(ev2 < 1e-9, "%s: mesh element velocity v = du/dt * stroke direction, max rel %.2e < 1e-9" % (name, ev2))
    part_kinematics_clock(args, checks)


def part_kinematics_clock(args, checks):
    """The grate clock across runs: `run 500; timestep 2 dt; run 500` gives t = 500 dt + (n - 500) 2 dt."""
    dt = 1e-4
    g = dict(GEOM_DEFAULTS, rows=2, bar_length=0.1, bar_height=0.02, declination=0.0, width=0.1)
    m = dict(MOTION_DEFAULTS, stroke=0.02, period=0.07)
    d = T.workdir(args, "grate_kin_clock")
    text = header("-0.1 0.3 -0.05 0.05 -0.2 0.2", dt=dt)
    text += "fix g all tdem/grate %s\n" % grate_args(g, m)
    text += "thermo_style custom step f_g[1] f_g[2] f_g[3]\nthermo_modify format float %.17g\nthermo 100\n"
    text += "run 500\ntimestep %.17g\nrun 500\n" % (2 * dt)
    T.run(args.tdem, text, d, "clock", mpirun=args.mpirun)
    rows = thermo_rows(open(os.path.join(d, "log.clock")).read())
    err = 0.0
    for row in rows:
        n = int(row[0])
        t = n * dt if n <= 500 else 500 * dt + (n - 500) * 2 * dt
        u, v, _ = motion(m, t, 0.0)
        err = max(err, abs(row[1] - t) / t if t > 0 else abs(row[1]), abs(row[2] - u) / m["stroke"])
    checks.check(len(rows) >= 12 and rows[-1][0] == 1000 and err < 1e-12,
                 "clock: run 500 at dt, run 500 at 2 dt: grate time and u follow t = 500 dt + (n-500) 2 dt (max rel %.1e)" % err)


def bed_on_bars_3d(args, d, name, rotation, extra=""):
    g = dict(GEOM_DEFAULTS, rows=3, bar_length=0.1, bar_height=0.02, declination=0.0, width=0.1)
    m = dict(MOTION_DEFAULTS, stroke=0.02, period=0.5, t_start=0.1)
    text = header("-0.1 0.5 -0.05 0.05 -0.2 0.2")
    text += "fix g all tdem/grate %s\n" % grate_args(g, m)
    text += walls("walls", ["g_fixed", "g_moving0"])
    text += "create_atoms 1 single 0.15 0.0 %.17g units box\n" % (R + 1e-4)
    text += "create_atoms 1 single 0.05 0.0 %.17g units box\n" % (R + 1e-4)
    text += "set group all diameter %.17g density %.17g\n" % (2 * R, RHO)
    text += "fix grav all gravity 9.81 vector 0 0 -1\n"
    if rotation:
        text += "fix integr all nve/sphere\n"
    else:
        text += "fix integr all tdem/integrate scheme velocity_verlet rotation no\n"
    text += extra + dump(250) + "thermo 5000\nrun 30000\n"
    T.run(args.tdem, text, d, name, mpirun=args.mpirun)
    return T.read_dump(os.path.join(d, "dump.out")), m


def part_carried(args, checks):
    dt = 2e-5
    for rotation in (False, True):
        name = "carried_" + ("rolling" if rotation else "norotation")
        d = T.workdir(args, "grate_" + name)
        frames, m = bed_on_bars_3d(args, d, name, rotation)
        ratio = 2.0 / 7.0 if rotation else 1.0
        x0 = None
        err = 0.0
        umax = 0.0
        fixed_move = 0.0
        for step, cols, a in frames:
            t = step * dt
            ix = cols.index("x")
            if x0 is None and t >= m["t_start"] - 1e-12:
                x0 = (a[0, ix], a[1, ix])
            if x0 is None:
                continue
            u = motion(m, t, 0.0)[0]
            umax = max(umax, u)
            err = max(err, abs((a[0, ix] - x0[0]) - ratio * u))
            fixed_move = max(fixed_move, abs(a[1, ix] - x0[1]), abs(a[1, cols.index("y")]))
        tol = 5e-6
        checks.check(umax > 0.99 * m["stroke"], "%s: the bar made a full stroke (u_max %.4g)" % (name, umax))
        checks.check(err < tol, "%s: sphere on the moving bar follows %s u(t): max |x - x0 - %s u| = %.3e m < %.1e"
                     % (name, "2/7" if rotation else "", "2/7" if rotation else "", err, tol))
        checks.check(fixed_move < 1e-9, "%s: sphere on the fixed bar stays put: max |dx| = %.2e m < 1e-9" % (name, fixed_move))


def part_rebound(args, checks):
    v0 = 1.0
    mass = RHO * 4.0 / 3.0 * PI * R ** 3
    g = dict(GEOM_DEFAULTS, rows=2, bar_length=0.1, bar_height=0.02, declination=0.0, width=0.1,
             row_group=[-1, 0])
    m = dict(MOTION_DEFAULTS)
    # stock hooke: k_n from Young's modulus and the characteristic velocity (LIGGGHTS docs, sphere-wall:
    # R* = R, m* = m, Y* = Y / (2 (1 - nu^2)))
    Y, nu, vchar = 5e6, 0.3, 1.0
    ystar = Y / (2 * (1 - nu ** 2))
    kn = 16.0 / 15.0 * math.sqrt(R) * ystar * (15.0 * mass * vchar ** 2 / (16.0 * math.sqrt(R) * ystar)) ** 0.2
    tc_hooke = PI / math.sqrt(kn / mass)
    hooke_props = """
fix m_E  all property/global youngsModulus peratomtype %.17g
fix m_nu all property/global poissonsRatio peratomtype %.17g
fix m_e  all property/global coefficientRestitution peratomtypepair 1 %.17g
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
fix m_v  all property/global characteristicVelocity scalar %.17g
"""
    cases = [("tdem_lsd", 0.5, LAW, "parameters restitution", None, TC),
             ("stock_hooke", 0.7, "model hooke tangential history", "", hooke_props % (Y, nu, 0.7, vchar), tc_hooke)]
    for name, e, law, settings, props, tc in cases:
        d = T.workdir(args, "grate_rebound_" + name)
        dt = tc / 2000.0  # the realised e has a first-order error in dt from the contact start/end
        nsteps = int(3.0 * tc / dt) + int(2e-4 / v0 / dt)
        text = header("-0.1 0.3 -0.05 0.05 -0.2 0.2", e=e, dt=dt, props=props, law=law, settings=settings)
        text += "fix g all tdem/grate %s\n" % grate_args(g, m)
        text += walls("walls", ["g_fixed", "g_moving0"], law=law, settings=settings)
        text += "create_atoms 1 single 0.05 0.0 %.17g units box\n" % (R + 1e-4)
        text += "create_atoms 1 single 0.15 0.0 %.17g units box\n" % (R + 1e-4)
        text += "set group all diameter %.17g density %.17g\n" % (2 * R, RHO)
        text += "velocity all set 0 0 %.17g units box\n" % (-v0)
        text += "fix integr all nve/sphere\n" + dump(nsteps) + "thermo %d\nrun %d\n" % (nsteps, nsteps)
        T.run(args.tdem, text, d, name, mpirun=args.mpirun)
        frames = T.read_dump(os.path.join(d, "dump.out"))
        step, cols, a = frames[-1]
        for i, where in ((0, "fixed bar"), (1, "moving row (standing)")):
            e_meas = a[i, cols.index("vz")] / v0
            checks.check(abs(e_meas - e) < 1e-3, "rebound %s on the %s: e = %.6f, law e = %.3f (|diff| %.1e < 1e-3)"
                         % (name, where, e_meas, e, abs(e_meas - e)))
        # the same impact on the stock primitive plane z = 0 (the bars' top face): same trajectory
        prim = re.sub(r"fix g all tdem/grate[^\n]*\n", "", text)
        prim = re.sub(r"fix walls all wall/gran[^\n]*\n",
                      "fix walls all wall/gran %s primitive type 1 zplane 0.0 %s\n" % (law, settings), prim)
        os.rename(os.path.join(d, "dump.out"), os.path.join(d, "dump.mesh"))
        T.run(args.tdem, prim, d, name + "_plane", mpirun=args.mpirun)
        step2, cols2, b = T.read_dump(os.path.join(d, "dump.out"))[-1]
        diff = float(np.abs(a - b).max())
        checks.check(step2 == step and diff < 1e-12, "rebound %s: mesh bar vs stock primitive plane, max |diff| of the "
                     "final state = %.1e < 1e-12" % (name, diff))


def bed_scene(nsteps_run, restart_write=None, restart_read=None):
    g = dict(GEOM_DEFAULTS, rows=4, bar_length=0.08, bar_height=0.02, step_height=0.005, declination=10.0,
             width=0.06, row_group=[-1, 0, -1, 1], group_phase=[0.0, 0.5], origin=(0.0, 0.0, 0.0))
    m = dict(MOTION_DEFAULTS, stroke=0.015, period=0.1)
    fixes = "fix g all tdem/grate %s\n" % grate_args(g, m)
    fixes += walls("walls", ["g_fixed", "g_moving0", "g_moving1"])
    fixes += "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\n"
    if restart_read:
        text = """
atom_style granular
atom_modify map array sort 0 0.0
newton off
communicate single vel yes
read_restart %s
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s parameters restitution
pair_coeff * *
timestep 2e-5
""" % (restart_read, PROPS % (0.5, TC), LAW) + fixes
    else:
        text = header("-0.05 0.35 -0.03 0.03 -0.1 0.1") + fixes
        text += "lattice sc 0.012\nregion bed block 0.01 0.3 -0.03 0.03 0.02 0.045 units box\n"
        text += "create_atoms 1 region bed\nset group all diameter 0.01 density 2500\n"
        text += "velocity all set 0 0 -0.3 units box\n"
    text += dump(nsteps_run) + "thermo 500\n"
    text += "run %d\n" % nsteps_run
    if restart_write:
        text += "write_restart %s\n" % restart_write
    return text


def part_parallel(args, checks):
    n = 6000
    d = T.workdir(args, "grate_parallel")
    T.run(args.tdem, bed_scene(n), d, "np1", mpirun=args.mpirun)
    os.rename(os.path.join(d, "dump.out"), os.path.join(d, "dump.np1"))
    T.run(args.tdem, bed_scene(n), d, "np2", np_=2, mpirun=args.mpirun)
    os.rename(os.path.join(d, "dump.out"), os.path.join(d, "dump.np2"))
    d1 = T.read_dump(os.path.join(d, "dump.np1"))
    d2 = T.read_dump(os.path.join(d, "dump.np2"))
    # create_atoms numbers the lattice sites per rank: match the atoms by their initial position
    c0 = d1[0][1]
    p1 = d1[0][2][:, [c0.index("x"), c0.index("y"), c0.index("z")]]
    p2 = d2[0][2][:, [c0.index("x"), c0.index("y"), c0.index("z")]]
    order = [int(np.argmin(((p2 - q) ** 2).sum(axis=1))) for q in p1]
    f1 = d1[-1]
    f2 = (d2[-1][0], d2[-1][1], d2[-1][2][order])
    natoms = f1[2].shape[0]
    cols = f1[1]
    sel = [cols.index(c) for c in ("x", "y", "z")]
    vsel = [cols.index(c) for c in ("vx", "vy", "vz")]
    z0 = 0.02
    fell = float(np.max(f1[2][:, cols.index("z")]))
    checks.check(natoms > 50 and fell < 0.045, "parallel: %d spheres settled on the grate (max z %.4f)" % (natoms, fell))
    vxmax = float(np.abs(f1[2][:, cols.index("vx")]).max())
    checks.check(vxmax > 0.02, "parallel: the bars move the bed (max |vx| %.3f m/s)" % vxmax)
    dx = float(np.abs(f1[2][:, sel] - f2[2][:, sel]).max()) if f1[2].shape == f2[2].shape else 1.0
    checks.check(f1[0] == f2[0] == n and dx < 1e-8, "parallel: -np 2 vs -np 1 after %d steps: max |dx| = %.2e m < 1e-8" % (n, dx))
    # one run split in two (np 2): run n/2; run n/2  vs  run n
    split = bed_scene(n // 2).replace("run %d\n" % (n // 2), "run %d\nrun %d\n" % (n // 2, n // 2))
    T.run(args.tdem, split, d, "split", np_=2, mpirun=args.mpirun)
    f4 = T.read_dump(os.path.join(d, "dump.out"))[-1]
    f4 = (f4[0], f4[1], f4[2][order])
    ds = float(np.abs(f4[2][:, sel] - f2[2][:, sel]).max()) if f4[2].shape == f2[2].shape else 1.0
    checks.check(f4[0] == n and ds < 1e-8, "run %d; run %d vs run %d (np 2): max |dx| = %.2e m < 1e-8" % (n // 2, n // 2, n, ds))
    # restart (np 2): run n/2, write_restart, read_restart + the same fixes, run n/2  vs  one run of n
    half = n // 2
    T.run(args.tdem, bed_scene(half, restart_write="grate.restart"), d, "first", np_=2, mpirun=args.mpirun)
    T.run(args.tdem, bed_scene(half, restart_read="grate.restart"), d, "second", np_=2, mpirun=args.mpirun)
    f3 = T.read_dump(os.path.join(d, "dump.out"))[-1]
    f3 = (f3[0], f3[1], f3[2][order])
    dr = float(np.abs(f3[2][:, sel] - f2[2][:, sel]).max()) if f3[2].shape == f2[2].shape else 1.0
    dv = float(np.abs(f3[2][:, vsel] - f2[2][:, vsel]).max()) if f3[2].shape == f2[2].shape else 1.0
    drs = float(np.abs(f3[2] - f4[2]).max()) if f3[2].shape == f4[2].shape else 1.0
    checks.check(drs == 0.0, "restart = the same run split in two without restart: max |difference| %.1e (0 expected)" % drs)
    checks.check(f3[0] == n and dr < 1e-8, "restart: run %d + write/read_restart + run %d vs run %d (np 2): max |dx| = %.2e m < 1e-8, max |dv| = %.2e m/s"
                 % (half, half, n, dr, dv))


def part_bad(args, checks):
    d = T.workdir(args, "grate_bad")
    base = header("-0.1 0.5 -0.05 0.05 -0.2 0.2")
    good = "rows 3 bar_length 0.1 bar_height 0.02 width 0.1"
    cases = [
        ("unknown keyword", good + " colour red", ["colour", "allowed", "rows"]),
        ("bad profile", good + " profile square", ["profile", "square", "sinusoidal"]),
        ("declination range", good + " declination 95", ["declination", "95", "[0, 80]"]),
        ("negative stroke", good + " stroke -0.01", ["stroke", "-0.01", "[0, inf)"]),
        ("not a number", good + " period fast", ["period", "fast", "number"]),
        ("bad type", good + " type sideways", ["type", "sideways", "forward", "reverse"]),
        ("bad frame", good + " frame xz", ["frame", "xz", "xyz", "xy"]),
        ("frame xy in 3D", good + " frame xy", ["frame", "xy", "dimension 2"]),
        ("rows too many", good.replace("rows 3", "rows 100000000"), ["rows", "100000000", "[1, 1000]"]),
        ("row_group count", good + " row_group -1 0", ["row_group", "2", "one entry per row"]),
        ("phase range", good + " row_group -1 0 -1 group_phase 1.5", ["phase", "1.5", "[0, 1)"]),
        ("dwell sum", good + " stroke 0.01 dwell_out 0.6 dwell_home 0.5", ["dwell_out + dwell_home", "1.1", "[0, 1)"]),
        ("wall_type range", good + " wall_type 3", ["wall_type", "3", "[1, 1]"]),
        ("vtk N", good + " vtk 0 bars", ["vtk", "0", "[1, inf)"]),
        ("side_walls value", good + " side_walls maybe", ["side_walls", "maybe", "yes, no"]),
        ("frequency", good + " frequency 0", ["frequency", "0", "(0, inf)"]),
    ]
    for i, (what, fargs, needles) in enumerate(cases):
        text = base + "fix g all tdem/grate %s\nrun 1\n" % fargs
        r = T.run(args.tdem, text, d, "bad%d" % i, mpirun=args.mpirun, check=False)
        out = r.stdout + r.stderr
        line = next((l for l in out.splitlines() if "ERROR" in l), "")
        ok = r.returncode > 0 and all(n in line for n in needles)
        checks.check(ok, "bad input (%s): exit %d, message: %s" % (what, r.returncode, line.strip()[:200]))
    # touching bars (two per row, no gap): the faces they share are left out of the meshes (LIGGGHTS
    # refused the duplicate elements), and a sphere resting on the seam is held by the bars
    r_s = 0.005
    text = (base + "fix g all tdem/grate %s bar_thickness 0.05 bar_gap 0 declination 0\n" % good +
            "create_atoms 1 single 0.05 0 %r units box\nset group all diameter %r density 2500\n" % (r_s - 1e-5, 2 * r_s) +
            walls("g", ["g_fixed", "g_moving0"]) + "fix grav all gravity 9.81 vector 0 0 -1\nfix nve all nve/sphere\n"
            "variable z equal z[1]\nrun 2000\nprint \"ZFINAL ${z}\"\n")
    r = T.run(args.tdem, text, d, "seam", mpirun=args.mpirun, check=False)
    out = r.stdout + r.stderr
    zf = [float(l.split()[1]) for l in out.splitlines() if l.startswith("ZFINAL")]
    facets = {}
    for mesh in ("g_fixed", "g_moving0"):
        path = os.path.join(d, "tdem_grate_%s.stl" % mesh)
        facets[mesh] = open(path).read().count("facet normal") if os.path.exists(path) else -1
    # 12 triangles per bar, less 2 per periodic end face (2 per row) and 2 per side of a shared face
    # (2 per row): rows 0 and 2 fixed, row 1 moving
    want = {"g_fixed": 2 * (2 * 12 - 4 - 4), "g_moving0": 2 * 12 - 4 - 4}
    checks.check(r.returncode == 0 and facets == want and zf and r_s - 1e-4 < zf[0] < r_s,
                 "touching bars: exit %d, mesh faces %s (expected %s), sphere on the seam at z = %s (r = %g)"
                 % (r.returncode, facets, want, zf, r_s))


def part_2d(args, checks):
    dt = 2e-5
    g = dict(GEOM_DEFAULTS, rows=3, bar_length=0.1, bar_height=0.02, declination=0.0, width=0.1, frame="xy")
    m = dict(MOTION_DEFAULTS, stroke=0.02, period=0.5, t_start=0.1)
    d = T.workdir(args, "grate_2d")
    text = header("-0.1 0.5 -0.2 0.2 -0.05 0.05", dim=2, boundary="f f p")
    text += "fix g all tdem/grate %s vtk 2500 bars\n" % grate_args(g, m)
    text += walls("walls", ["g_fixed", "g_moving0"])
    text += "create_atoms 1 single 0.15 %.17g 0.0 units box\n" % (R + 1e-4)
    text += "create_atoms 1 single 0.05 %.17g 0.0 units box\n" % (R + 1e-4)
    text += "set group all diameter %.17g density %.17g\n" % (2 * R, RHO)
    text += "fix grav all gravity 9.81 vector 0 -1 0\n"
    text += "fix integr all tdem/integrate scheme velocity_verlet rotation no\nfix e2d all enforce2d\n"
    text += dump(250) + "thermo 5000\nrun 30000\n"
    T.run(args.tdem, text, d, "disk", mpirun=args.mpirun)
    frames = T.read_dump(os.path.join(d, "dump.out"))
    x0 = None
    err = umax = fixed_move = zmax = 0.0
    for step, cols, a in frames:
        t = step * dt
        ix = cols.index("x")
        zmax = max(zmax, float(np.abs(a[:, cols.index("z")]).max()))
        if x0 is None and t >= m["t_start"] - 1e-12:
            x0 = (a[0, ix], a[1, ix])
        if x0 is None:
            continue
        u = motion(m, t, 0.0)[0]
        umax = max(umax, u)
        err = max(err, abs((a[0, ix] - x0[0]) - u))
        fixed_move = max(fixed_move, abs(a[1, ix] - x0[1]))
    checks.check(umax > 0.99 * m["stroke"], "2d: the bar made a full stroke (u_max %.4g)" % umax)
    checks.check(err < 5e-6, "2d: disk on the moving bar follows u(t): max |x - x0 - u| = %.3e m < 5e-6" % err)
    checks.check(fixed_move < 1e-9, "2d: disk on the fixed bar stays put: max |dx| = %.2e m < 1e-9" % fixed_move)
    checks.check(zmax == 0.0, "2d: disks stay in the plane z = 0 (max |z| = %.1e)" % zmax)
    files = glob.glob(os.path.join(d, "bars_*.vtp"))
    ev_ = 0.0
    for p in files:
        step = int(re.findall(r"_(\d+)\.vtp", p)[0])
        pts = read_vtk_points(p)
        ref = ref_corners(g, m, step * dt)
        ev_ = max(ev_, float(np.abs(pts - ref).max()) / g["bar_length"]) if pts.shape == ref.shape else 1.0
    checks.check(len(files) == 13 and ev_ < 1e-9, "2d: %d VTK files, corners in the xy frame vs reference: max %.2e < 1e-9"
                 % (len(files), ev_))


PARTS = dict(kinematics=part_kinematics, carried=part_carried, rebound=part_rebound, parallel=part_parallel,
             bad=part_bad, **{"2d": part_2d})


def main():
    args = T.parse_args(lambda p: p.add_argument("--part", required=True, choices=sorted(PARTS)))
    checks = T.Checks()
    PARTS[args.part](args, checks)
    checks.done()


if __name__ == "__main__":
    main()
