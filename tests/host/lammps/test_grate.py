#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/grate (LAMMPS module 'grate', issue 7). Parts (--part NAME), one ctest each:

kinematics  Bar geometry and motion vs an independent Python model of docs/grate.md (section 1-3,
            re-implemented here from the formulas, not from the C++): every VTK file written by
            `vtk N prefix` (at set-up and every N steps) is read back and the 8 corners of every
            box (bars and side walls) and its velocity are compared with the model at t = step*dt.
            The files are VTK XML polydata (.vtp, binary doubles) read with the VTK library
            (python3-vtk9, tests/host/vtk_read.py); tolerance 1e-12 relative. The series bars.pvd
            lists every file at t = step*dt, as does the TimeValue of each file. The displacement u and velocity of every phase group, output
            as f_ID[4..] with %.17g, must match the model to 1e-12 (relative to the stroke and to
            the largest speed). Cases: reverse-acting, declined, stepped, roof-tile overlap, bars
            with lateral gaps, side walls, trapezoidal profile with dwells, forward share 0.4, two
            phase groups, t_start > 0; forward-acting sinusoidal; 2D frame xy, trapezoidal_accel.
            A change of `timestep` between runs continues the grate time (150 dt1 + 150 dt2).
carry       Gravity -z, declination 0. A non-rotating sphere (fix nve) resting on a moving row of
            a forward grate (sinusoidal stroke, peak acceleration 1.6 m/s^2 < mu g) follows the bar
            displacement u(t) within 1e-5 m (elastic tangential spring m a/k_t ~ 2e-7 m, and the lag
            of the half-step velocities of velocity Verlet, v dt/2 ~ 1.3e-6 m); a freely
            rolling sphere (nve/sphere) on the same row moves by (2/7) u(t) (rolling without slip
            on an accelerating plate, I = 2/5 m r^2) within 2 % of the stroke; a sphere on a fixed
            row does not move horizontally (drift < 1e-9 m). A second fix instance (reverse grate,
            declination 10 deg, acceleration-limited trapezoid: a linear trapezoid has velocity
            jumps, at which any sphere slips) carries a non-rotating sphere along -e_t by u(t).
impact      Gravity off, mu = 0. Normal lsd stiffness KN GAMMAN (mass damping, limit_force no):
            e = exp(-pi b/sqrt(1-b^2)), t_c = pi/(w0 sqrt(1-b^2)), b = GAMMAN/(2 w0), w0 = sqrt(KN/m).
            (a) head-on on the top face, (b) exactly above the joint of two coplanar rows (one
            contact, not two: a double contact would shorten t_c by 1/sqrt(2)), (c) oblique impact
            on the top edge of a bar end, along the edge normal at 45 deg (rebound along the same
            normal, normal speed ratio e, tangential speed unchanged). e to 1e-3, t_c (counted in
            steps with a non-zero bar force) to 0.5 %, dt = t_c/1000. Control: the two rows as two
            separate fixes give two contacts above the joint: t_c of doubled k and gamma
            (w0 sqrt(2), beta sqrt(2); 0.72 t_c), so (b) can fail.
parallel    Spheres sitting in the lateral gaps between bars (each touching two boxes; one gap
            across the periodic y boundary), on bar tops, and a touching pair, on a stepped grate
            whose moving row carries spheres across the processor boundary (processors 2 1 1).
            -np 2 equals -np 1 (max relative difference <= 1e-10); a write_restart/read_restart in
            the middle of the stroke (spheres touching two boxes, checked with the Python model)
            continues like run N + run M (<= 1e-10: not bitwise, the moving row pushes spheres
            into pair contacts, whose forces are summed in the order of the neighbour lists that
            read_restart rebuilds); a control that loses the histories (new fix ID, t_start
            shifted so that the bars continue their motion) differs by > 1e-9 m.
bad_input   Bad values name the keyword, the value and the allowed values; more contacts than
            max_contacts stops with an error naming max_contacts.
scene       input_scripts/lammps/grate_forward_3d.in, 2000 steps on 2 ranks: runs, writes VTK and dump.
twod        dimension 2, frame xy (up +y), disks, fix enforce2d: a non-rotating disk on a moving
            row follows u(t) within 1e-5 m, a rolling disk (nve/sphere disc, I = 1/2 m r^2) moves
            by u(t)/3 within 2 % of the stroke, the grate force is in the xy plane.
"""
import glob
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import vtk_read as vr  # noqa: E402

args = lc.parse_args(sys.argv)
PART = args.get("part", "kinematics")
chk = lc.Checker("lammps.grate." + PART)
LAW_CS = "normal lsd restitution 0.5 1e-3 tangential cundall_strack 0.8 0.5"


# ------------------------------------------------------------------ independent model
def motion(t, m, phase):
    """u, du/dt of a moving row (docs/grate.md section 3)."""
    if m["stroke"] == 0.0:
        return 0.0, 0.0
    T = m["period"]
    tau = (t - m["t_start"]) / T - phase
    if tau < 0:
        return 0.0, 0.0
    tau -= math.floor(tau)
    move = 1.0 - m["dwell_out"] - m["dwell_home"]
    d_out = m["forward_share"] * move * T
    d_back = (1.0 - m["forward_share"]) * move * T
    s = tau * T

    def unit(x, d):  # f(x), df/dt
        if m["profile"] == "sinusoidal":
            return 0.5 * (1 - math.cos(math.pi * x)), 0.5 * math.pi / d * math.sin(math.pi * x)
        if m["profile"] == "trapezoidal_accel":  # velocity trapezoid: ramps of ramp*d, cruise vmax
            ra = m["ramp"]
            vmax = 1.0 / (1.0 - ra)  # in units of 1/d (area 1 under the velocity)
            if x < ra:
                return 0.5 * vmax / ra * x * x, vmax / ra * x / d
            if x <= 1 - ra:
                return 0.5 * vmax * ra + vmax * (x - ra), vmax / d
            return 1 - 0.5 * vmax / ra * (1 - x) ** 2, vmax / ra * (1 - x) / d
        return x, 1.0 / d

    if s < d_out:
        f, fd = unit(s / d_out, d_out)
        return m["stroke"] * f, m["stroke"] * fd
    s -= d_out
    if s < m["dwell_out"] * T:
        return m["stroke"], 0.0
    s -= m["dwell_out"] * T
    if s < d_back:
        f, fd = unit(s / d_back, d_back)
        return m["stroke"] * (1 - f), -m["stroke"] * fd
    return 0.0, 0.0


MOTION_DEFAULT = dict(profile="sinusoidal", stroke=0.0, period=1.0, t_start=0.0, dwell_out=0.0,
                      dwell_home=0.0, forward_share=0.5, ramp=0.25)
GRATE_DEFAULT = dict(rows=6, bar_length=0.2, bar_height=0.05, bar_thickness=0.0, bar_gap=0.0,
                     step_height=0.0, overlap=0.0, declination=12.0, width=0.2, side_walls=False,
                     wall_height=0.3, wall_thickness=0.01, type="forward", frame="xyz",
                     origin=(0.0, 0.0, 0.0), row_group=None, group_phase=None)


class Model:
    """Boxes of the grate (docs/grate.md sections 1-2): list of (centre, axes, half, velocity)."""

    def __init__(self, g, m):
        self.g = dict(GRATE_DEFAULT, **g)
        self.m = dict(MOTION_DEFAULT, **m)
        g = self.g
        a = math.radians(g["declination"])
        self.et = np.array([math.cos(a), 0, -math.sin(a)])
        self.en = np.array([math.sin(a), 0, math.cos(a)])
        self.ew = np.array([0.0, 1, 0])
        rg = g["row_group"] or [0 if i % 2 else -1 for i in range(g["rows"])]
        self.rg = rg
        ng = max(rg) + 1
        self.phase = g["group_phase"] or [0.0] * ng
        self.sign = 1.0 if g["type"] == "forward" else -1.0

    def glob_dir(self, v):
        return v.copy() if self.g["frame"] == "xyz" else np.array([v[0], v[2], -v[1]])

    def glob_pt(self, v):
        return np.array(self.g["origin"], float) + self.glob_dir(v)

    def boxes(self, t):
        g = self.g
        W = g["width"]
        th, nb = g["bar_thickness"], 1
        if g["frame"] == "xy" or th <= 0 or th >= W:
            th = W
        else:
            nb = max(1, int(math.floor((W + g["bar_gap"]) / (th + g["bar_gap"]) + 1e-12)))
        span = nb * th + (nb - 1) * g["bar_gap"]
        pitch = g["bar_length"] - g["overlap"]
        out, local = [], []
        for i in range(g["rows"]):
            heel = i * pitch * self.et - i * g["step_height"] * np.array([0, 0, 1.0])
            c = heel + 0.5 * g["bar_length"] * self.et - 0.5 * g["bar_height"] * self.en
            u, v = (0.0, 0.0) if self.rg[i] < 0 else motion(t, self.m, self.phase[self.rg[i]])
            for k in range(nb):
                cl = c + (-0.5 * span + 0.5 * th + k * (th + g["bar_gap"])) * self.ew
                half = np.array([0.5 * g["bar_length"], 0.5 * th, 0.5 * g["bar_height"]])
                local.append((cl, half))
                out.append((self.glob_pt(cl + u * self.sign * self.et),
                            [self.glob_dir(e) for e in (self.et, self.ew, self.en)], half,
                            self.glob_dir(v * self.sign * self.et)))
        if g["side_walls"]:
            pts = np.vstack([corners((cl, (self.et, self.ew, self.en), half, None)) for cl, half in local])
            reach = self.m["stroke"] * math.cos(math.radians(g["declination"]))
            xmin, xmax = pts[:, 0].min() - reach, pts[:, 0].max() + reach
            umin, umax = pts[:, 2].min(), pts[:, 2].max() + g["wall_height"]
            for s in (-1, 1):
                cl = np.array([0.5 * (xmin + xmax), s * 0.5 * (W + g["wall_thickness"]), 0.5 * (umin + umax)])
                half = np.array([0.5 * (xmax - xmin), 0.5 * g["wall_thickness"], 0.5 * (umax - umin)])
                out.append((self.glob_pt(cl), [self.glob_dir(e) for e in np.eye(3)], half, np.zeros(3)))
        return out


def corners(box):
    c, ax, half, _ = box
    # corner c: sign of axis k is + if bit k of c is set (the point order of the VTK writer)
    return np.array([c + sum((1 if (cc >> k) & 1 else -1) * half[k] * ax[k] for k in range(3))
                     for cc in range(8)])


def read_vtp(path):
    """points, per-triangle box index and velocity, and the time of a .vtp (read with VTK)."""
    d = vr.read_dataset(path)
    return d["points"], d["cell"]["box"].astype(int), d["cell"]["velocity"], d["time"]


def grate_args(g, m):
    out = []
    for key, val in list(g.items()) + list(m.items()):
        if isinstance(val, bool):
            out.append("%s %s" % (key, "yes" if val else "no"))
        elif isinstance(val, (list, tuple)):
            out.append("%s %s" % (key, " ".join(repr(v) for v in val)))
        else:
            out.append("%s %s" % (key, val))
    return " ".join(out)


HEAD3 = """
units           si
atom_style      sphere
atom_modify     map array
dimension       {dim}
boundary        f {yb} {zb}
newton          off
comm_modify     vel yes
{processors}
region          box block {box} units box
create_box      1 box
"""


# ------------------------------------------------------------------ 1. kinematics
def part_kinematics():
    dt = 1e-3
    cases = [
        ("reverse_trap", 3, dict(rows=5, bar_length=0.1, bar_height=0.03, bar_thickness=0.03, bar_gap=0.01,
                                 step_height=0.02, overlap=0.01, declination=20.0, width=0.1, side_walls=True,
                                 wall_height=0.1, wall_thickness=0.005, type="reverse",
                                 origin=(0.01, 0.0, 0.2), row_group=[-1, 0, -1, 1, 0], group_phase=[0.0, 0.3]),
         dict(profile="trapezoidal", stroke=0.03, period=0.2, t_start=0.05, dwell_out=0.1, dwell_home=0.2,
              forward_share=0.4), "-0.1 0.7 -0.07 0.07 -0.2 0.5", 7),
        ("forward_sine", 3, dict(rows=4, bar_length=0.12, bar_height=0.04, step_height=0.01, declination=12.0,
                                 width=0.08, origin=(0.0, 0.0, 0.1)),
         dict(profile="sinusoidal", stroke=0.02, period=0.15), "-0.1 0.6 -0.04 0.04 -0.2 0.3", 5),
        ("xy_2d", 2, dict(rows=3, bar_length=0.1, bar_height=0.02, step_height=0.01, declination=8.0, width=0.01,
                          frame="xy", origin=(0.0, 0.1, 0.0), row_group=[0, -1, 1], group_phase=[0.25, 0.5]),
         dict(profile="trapezoidal_accel", stroke=0.015, period=0.1, dwell_home=0.3, ramp=0.3),
         "-0.1 0.5 -0.1 0.3 -0.01 0.01", 3),
    ]
    for name, dim, g, m, box, every in cases:
        wd = lc.workdir("kin_" + name)
        model = Model(g, m)
        ng = len(model.phase)
        text = HEAD3.format(dim=dim, yb="p" if dim == 3 and not g.get("side_walls") else "f",
                            zb="f" if dim == 3 else "p", processors="", box=box)
        if dim == 3 and not g.get("side_walls"):
            ylo, yhi = [float(w) for w in box.split()[2:4]]
            assert abs((yhi - ylo) - g["width"]) < 1e-12
        text += "create_atoms 1 single -0.09 0.0 0.0 units box\nset atom 1 diameter 0.001 density 1000\n"
        text += "fix gr all tdem/grate %s %s vtk %d bars\n" % (LAW_CS, grate_args(g, m), every)
        text += "fix nve all nve/sphere\ntimestep %r\n" % dt
        text += "thermo_style custom step %s\nthermo_modify format float %%.17g\nthermo 1\nrun 400\n" % " ".join(
            "f_gr[%d]" % (4 + k) for k in range(2 * ng))
        _, out = lc.run(args["tdem"], text, wd, "in.kin")
        files = sorted(glob.glob(os.path.join(wd, "bars_*.vtp")))
        steps = sorted(int(re.search(r"_(\d+)\.vtp$", f).group(1)) for f in files)
        chk.check(steps == list(range(0, 401, every)),
                  "%s: VTK files at set-up and every %d steps (%d files)" % (name, every, len(steps)))
        # the series lists every file once, in step order, at its time step*dt
        series = vr.read_pvd(os.path.join(wd, "bars.pvd"))
        chk.check([os.path.basename(f) for _, f in series] == ["bars_%d.vtp" % k for k in steps] and
                  all(abs(t - k * dt) <= 1e-15 for (t, _), k in zip(series, steps)),
                  "%s: bars.pvd lists the %d files at t = step*dt" % (name, len(series)))
        worst_p = worst_v = worst_t = 0.0
        tol_p = 1e-12  # binary doubles: round-off of the geometry only
        for step in steps:
            pts, tbox, tvel, tfile = read_vtp(os.path.join(wd, "bars_%d.vtp" % step))
            worst_t = max(worst_t, abs(tfile - step * dt))
            boxes = model.boxes(step * dt)
            ref = np.vstack([corners(b) for b in boxes])
            if pts.shape != ref.shape:
                chk.check(False, "%s step %d: %d VTK points, model has %d" % (name, step, len(pts), len(ref)))
                break
            scale = max(1.0, np.abs(ref).max())
            worst_p = max(worst_p, np.abs(pts - ref).max() / scale)
            vref = np.array([boxes[b][3] for b in tbox])
            vs = max(np.abs(vref).max(), 1e-30)
            worst_v = max(worst_v, np.abs(tvel - vref).max() / vs if np.abs(vref).max() > 0 else np.abs(tvel).max())
        print("%s: corners max rel. difference %.3g (tolerance %.1g), velocities %.3g, TimeValue %.3g"
              % (name, worst_p, tol_p, worst_v, worst_t))
        chk.check(worst_t <= 1e-15, "%s: the TimeValue of every file is step*dt" % name)
        chk.check(worst_p <= tol_p, "%s: bar corners equal the model at all %d VTK steps" % (name, len(steps)))
        chk.check(worst_v <= tol_p, "%s: bar velocities equal the model" % name)
        # u, v of every phase group at every step, full precision
        rows = [r.split() for r in lc.thermo_blocks(out)[1:]]
        vmax = max(abs(motion(k * 1e-4, model.m, 0.0)[1]) for k in range(int(model.m["period"] / 1e-4) + 1))
        wu = wv = 0.0
        for r in rows:
            t = int(r[0]) * dt
            for gi in range(ng):
                u, v = motion(t, model.m, model.phase[gi])
                wu = max(wu, abs(float(r[1 + 2 * gi]) - u) / model.m["stroke"])
                wv = max(wv, abs(float(r[2 + 2 * gi]) - v) / vmax)
        print("%s: %d steps x %d groups: u max rel. diff %.3g, v max rel. diff %.3g" % (name, len(rows), ng, wu, wv))
        chk.check(len(rows) == 401 and wu <= 1e-12 and wv <= 1e-12,
                  "%s: displacement and velocity of every group equal the profile to 1e-12" % name)

    # a change of the time step between runs: the grate time continues, t = 150 dt1 + 150 dt2
    wd = lc.workdir("kin_dt")
    name, dim, g, m, box, every = cases[1]
    model = Model(g, m)
    text = HEAD3.format(dim=3, yb="p", zb="f", processors="", box=box)
    text += "create_atoms 1 single -0.09 0.0 0.0 units box\nset atom 1 diameter 0.001 density 1000\n"
    text += "fix gr all tdem/grate %s %s\nfix nve all nve/sphere\n" % (LAW_CS, grate_args(g, m))
    text += "thermo_style custom step f_gr[4] f_gr[5]\nthermo_modify format float %.17g\nthermo 150\n"
    text += "timestep 1e-3\nrun 150\ntimestep 4e-4\nrun 150\n"
    _, out = lc.run(args["tdem"], text, wd, "in.dt")
    last = [float(w) for w in lc.thermo_blocks(out)[-1].split()]
    u, v = motion(150 * 1e-3 + 150 * 4e-4, model.m, 0.0)
    print("time step changed between runs: u = %.17g (model %.17g), v = %.17g (model %.17g)" % (last[1], u, last[2], v))
    chk.check(int(last[0]) == 300 and abs(last[1] - u) <= 1e-12 * m["stroke"] and abs(last[2] - v) <= 1e-9 * abs(v),
              "a change of the time step between runs continues the grate time")


# ------------------------------------------------------------------ 2. carry
def part_carry():
    r, dt, nsteps = 0.005, 2e-5, 40000
    law = "normal lsd restitution 0.3 1e-3 tangential cundall_strack 0.8 0.5"
    gf = dict(rows=2, bar_length=0.2, bar_height=0.05, declination=0.0, width=0.1, row_group=[-1, 0])
    mf = dict(profile="sinusoidal", stroke=0.02, period=0.5, t_start=0.1)
    gr = dict(rows=2, bar_length=0.2, bar_height=0.05, declination=10.0, width=0.1, type="reverse",
              origin=(0.5, 0.0, 0.0), row_group=[-1, 0])
    mr = dict(profile="trapezoidal_accel", stroke=0.01, period=0.6, t_start=0.1, dwell_home=0.25, ramp=0.25)
    a_max = mf["stroke"] * 0.5 * (2 * math.pi / mf["period"]) ** 2
    print("forward grate: peak bar acceleration %.3g m/s^2 vs mu g = %.3g" % (a_max, 0.5 * 9.81))
    mdl_r = Model(gr, mr)
    a = math.radians(10.0)
    # sphere positions: A fixed row, B non-rotating on the moving row, C rolling on it, D reverse
    atoms = {1: (0.1, 0.0, r), 2: (0.25, -0.02, r), 3: (0.32, 0.02, r)}
    s4 = 0.3
    x4 = 0.5 + s4 * math.cos(a) + r * math.sin(a)
    z4 = -s4 * math.sin(a) + r * math.cos(a)
    atoms[4] = (x4, 0.0, z4)
    text = HEAD3.format(dim=3, yb="p", zb="f", processors="", box="-0.1 1.0 -0.05 0.05 -0.3 0.3")
    for k, (x, y, z) in sorted(atoms.items()):
        text += "create_atoms 1 single %r %r %r units box\n" % (x, y, z - 1e-5)
    text += "set group all diameter %r density 2500\n" % (2 * r)
    text += "group fwd id 1 2 3\ngroup rev id 4\ngroup norot id 2 4\ngroup rot id 1 3\n"
    text += "fix gf fwd tdem/grate %s %s\n" % (law, grate_args(gf, mf))
    text += "fix gr rev tdem/grate %s %s\n" % (law, grate_args(gr, mr))
    text += "fix grav all gravity 9.81 vector 0 0 -1\nfix n1 norot nve\nfix n2 rot nve/sphere\n"
    text += "timestep %r\n" % dt
    text += "".join("variable x%d equal x[%d]\nvariable y%d equal y[%d]\nvariable z%d equal z[%d]\n"
                    % (k, k, k, k, k, k) for k in atoms)
    text += "thermo_style custom step %s\nthermo_modify format float %%.17g\nthermo 500\nrun %d\n" % (
        " ".join("v_x%d v_y%d v_z%d" % (k, k, k) for k in sorted(atoms)), nsteps)
    wd = lc.workdir("carry")
    _, out = lc.run(args["tdem"], text, wd, "in.carry")
    rows = np.array([[float(w) for w in l.split()] for l in lc.thermo_blocks(out)[1:]])
    t = rows[:, 0] * dt
    P = lambda k, c: rows[:, 1 + 3 * (sorted(atoms).index(k)) + c]
    i0 = np.searchsorted(t, 0.1)  # motion starts at t_start = 0.1 s: positions there are the rest state
    uf = np.array([motion(tt, dict(MOTION_DEFAULT, **mf), 0.0)[0] for tt in t])
    ur = np.array([motion(tt, dict(MOTION_DEFAULT, **mr), 0.0)[0] for tt in t])
    dA = max(np.abs(P(1, 0) - P(1, 0)[0]).max(), np.abs(P(1, 1) - P(1, 1)[0]).max())
    print("A (fixed row): horizontal drift %.3g m" % dA)
    chk.check(dA < 1e-9, "a sphere on a fixed row stays put (drift %.3g m < 1e-9 m)" % dA)
    eB = np.abs(P(2, 0)[i0:] - P(2, 0)[i0] - uf[i0:]).max()
    print("B (non-rotating, moving row): max |x - x0 - u| = %.3g m (stroke %.3g m, max u %.3g)"
          % (eB, mf["stroke"], uf.max()))
    chk.check(uf.max() > 0.019 and eB < 1e-5, "a non-rotating sphere on a moving row is carried with it "
              "(|x - x0 - u| = %.3g m < 1e-5 m)" % eB)
    eC = np.abs(P(3, 0)[i0:] - P(3, 0)[i0] - 2.0 / 7.0 * uf[i0:]).max()
    print("C (rolling, moving row): max |x - x0 - 2/7 u| = %.3g m = %.2f %% of the stroke; max x - x0 = %.3g"
          % (eC, 100 * eC / mf["stroke"], (P(3, 0) - P(3, 0)[i0]).max()))
    chk.check(eC < 0.02 * mf["stroke"], "a rolling sphere moves by 2/7 of the bar displacement (within 2 %% of the "
              "stroke: %.2f %%)" % (100 * eC / mf["stroke"]))
    d = mdl_r.sign * mdl_r.et
    eDx = np.abs(P(4, 0)[i0:] - P(4, 0)[i0] - d[0] * ur[i0:]).max()
    eDz = np.abs(P(4, 2)[i0:] - P(4, 2)[i0] - d[2] * ur[i0:]).max()
    print("D (reverse grate, 10 deg, non-rotating): max |dx - u e_x| = %.3g, |dz - u e_z| = %.3g m" % (eDx, eDz))
    chk.check(ur.max() > 0.0099 and max(eDx, eDz) < 1e-5,
              "reverse grate: a sphere is carried up-slope along -e_t (%.3g m)" % max(eDx, eDz))


# ------------------------------------------------------------------ 3. impact
def part_impact():
    r, rho, kn = 0.005, 2500.0, 1e5
    m = rho * 4 / 3 * math.pi * r ** 3
    w0 = math.sqrt(kn / m)
    b = 0.2
    gn = 2 * b * w0  # GAMMAN (mass mode: gamma = m GAMMAN), beta = GAMMAN/(2 w0)
    e_ref = math.exp(-math.pi * b / math.sqrt(1 - b * b))
    tc_ref = math.pi / (w0 * math.sqrt(1 - b * b))
    dt = tc_ref / 1000
    law = "normal lsd stiffness %r %r tangential cundall_strack %r 0 0" % (kn, gn, 0.8 * kn)
    g = dict(rows=2, bar_length=0.1, bar_height=0.03, declination=0.0, width=0.1, row_group=[-1, -1])
    s2 = math.sqrt(0.5)
    cases = [("top face", (0.05, 0.0, r + 0.5e-3), (0.0, 0.0, -1.0), (0, 0, 1)),
             ("joint of two rows", (0.1, 0.0, r + 0.5e-3), (0.0, 0.0, -1.0), (0, 0, 1)),
             ("bar edge at 45 deg", (0.2 + s2 * (r + 0.5e-3), 0.0, s2 * (r + 0.5e-3)), (-s2 * 1.0, 0.3, -s2 * 1.0),
              (s2, 0, s2))]
    print("lsd: m = %.4g kg, beta = %.2f: e = %.6f, t_c = %.6g s (closed forms)" % (m, b, e_ref, tc_ref))
    # control: the two rows as two separate fixes, so that the sphere above the joint has two
    # contacts (one per fix): the contact time must then be t_c/sqrt(2), which the check detects
    cases.append(("control: joint of two separate one-row grates", cases[1][1], cases[1][2], cases[1][3]))
    for name, x, v, n in cases:
        wd = lc.workdir("impact")
        text = HEAD3.format(dim=3, yb="p", zb="f", processors="", box="-0.05 0.3 -0.05 0.05 -0.1 0.1")
        text += "create_atoms 1 single %r %r %r units box\nset atom 1 diameter %r density %r\n" % (x + (2 * r, rho))
        text += "velocity all set %r %r %r\n" % v
        if name.startswith("control"):
            g1 = dict(g, rows=1, row_group=[-1])
            text += "fix gr all tdem/grate %s %s\n" % (law, grate_args(g1, {}))
            text += "fix gr2 all tdem/grate %s %s origin 0.1 0 0\n" % (law, grate_args(g1, {}))
            text += "fix nve all nve/sphere\ntimestep %r\n" % dt
            text += "variable fm equal sqrt(f_gr[1]^2+f_gr[2]^2+f_gr[3]^2)+sqrt(f_gr2[1]^2+f_gr2[2]^2+f_gr2[3]^2)\n"
        else:
            text += "fix gr all tdem/grate %s %s\nfix nve all nve/sphere\ntimestep %r\n" % (law, grate_args(g, {}), dt)
            text += "variable fm equal sqrt(f_gr[1]^2+f_gr[2]^2+f_gr[3]^2)\n"
        text += "variable vx equal vx[1]\nvariable vy equal vy[1]\nvariable vz equal vz[1]\n"
        text += "thermo_style custom step v_fm v_vx v_vy v_vz\nthermo_modify format float %.17g\nthermo 1\n"
        text += "run %d\n" % int(2.5 * tc_ref / dt + 0.5e-3 / dt)
        _, out = lc.run(args["tdem"], text, wd, "in.impact")
        rows = np.array([[float(w) for w in l.split()] for l in lc.thermo_blocks(out)[1:]])
        ncon = int((rows[:, 1] > 0).sum())
        vin, vout = np.array(v), rows[-1, 2:5]
        n = np.array(n)
        e = -np.dot(vout, n) / np.dot(vin, n)
        vt_in, vt_out = vin - np.dot(vin, n) * n, vout - np.dot(vout, n) * n
        print("%s: e = %.6f (rel. error %.2e), t_c = %d steps = %.6g s (rel. error %.2e), tangential change %.2e"
              % (name, e, e / e_ref - 1, ncon, ncon * dt, ncon * dt / tc_ref - 1, np.abs(vt_out - vt_in).max()))
        if name.startswith("control"):
            b2 = math.sqrt(2) * b  # doubled k and gamma: w0 -> sqrt(2) w0, beta -> sqrt(2) beta
            tc2 = math.pi / (math.sqrt(2) * w0 * math.sqrt(1 - b2 * b2))
            chk.check(abs(ncon * dt / tc2 - 1) < 5e-3 and abs(ncon * dt / tc_ref - 1) > 0.2,
                      "%s: two contacts, t_c = %.4g s as for doubled k and gamma (closed form %.4g s): the "
                      "joint check can fail" % (name, ncon * dt, tc2))
            continue
        chk.check(abs(e / e_ref - 1) < 1e-3, "%s: restitution equals the closed form to 1e-3" % name)
        chk.check(abs(ncon * dt / tc_ref - 1) < 5e-3, "%s: contact time equals the closed form to 0.5 %%" % name)
        chk.check(np.abs(vt_out - vt_in).max() < 1e-9 and np.all(np.isfinite(rows)),
                  "%s: tangential velocity unchanged (mu = 0), finite" % name)


# ------------------------------------------------------------------ 4. parallel and restart
PAR_G = dict(rows=4, bar_length=0.1, bar_height=0.03, bar_thickness=0.012, bar_gap=0.006, step_height=0.01,
             declination=0.0, width=0.054, row_group=[-1, 0, -1, 0])
PAR_M = dict(profile="sinusoidal", stroke=0.03, period=0.4, t_start=0.05)
PAR_LAW = "normal lsd restitution 0.3 1e-3 tangential cundall_strack 0.8 0.4"


def par_data(path):
    r = 0.005
    rows = []
    sink = math.sqrt(r * r - 0.003 ** 2)  # centre above the top in a gap of 6 mm
    for i in range(4):
        top = -0.01 * i
        xs = [0.02, 0.05, 0.08] + ([0.097] if i == 1 else [])
        for x in xs:
            x += 0.1 * i
            for y in (-0.009, 0.009, 0.0269):
                rows.append((x, y, top + sink + 2e-5))
        rows.append((0.1 * i + 0.035, 0.018, top + r + 2e-5))      # on a bar top
    rows.append((0.265, -0.018, -0.02 + r + 2e-5))                   # touching pair on row 2
    rows.append((0.265 + 2 * r - 1e-5, -0.018, -0.02 + r + 2e-5))
    with open(path, "w") as f:
        f.write("grate spheres\n\n%d atoms\n1 atom types\n-0.05 0.45 xlo xhi\n-0.027 0.027 ylo yhi\n"
                "-0.1 0.1 zlo zhi\n\nAtoms # sphere\n\n" % len(rows))
        for k, (x, y, z) in enumerate(rows, 1):
            f.write("%d 1 %r 2500 %r %r %r\n" % (k, 2 * r, x, y, z))
    return len(rows)


PAR_HEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f p f
newton          {newton}
comm_modify     vel yes
{processors}
read_data       spheres.data
"""
PAR_BODY = """
neighbor        0.002 bin
neigh_modify    delay 0
pair_style      tdem/gran
pair_coeff      * * {law}
fix             {fid} all tdem/grate {law} {grate}
fix             grav all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
"""
DUMP = "write_dump all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g\n"


def part_parallel():
    wd = lc.workdir("parallel")
    n = par_data(os.path.join(wd, "spheres.data"))
    body = PAR_BODY.format(law=PAR_LAW, grate=grate_args(PAR_G, PAR_M), fid="gr")
    N1, N2 = 10000, 4000
    for newton in ("off", "on"):
        res = {}
        for np_ in (1, 2):
            text = PAR_HEAD.format(newton=newton, processors="processors 2 1 1" if np_ == 2 else "") + body
            text += "run %d\n" % (N1 + N2) + DUMP.format(dump="dump.np%d" % np_)
            _, out = lc.run(args["tdem"], text, wd, "in.np%d" % np_, np_=np_, mpirun=args["mpirun"])
            res[np_] = lc.read_dump(os.path.join(wd, "dump.np%d" % np_))[1]
            if np_ == 2:
                chk.check("2 by 1 by 1 MPI processor grid" in out, "newton %s: ran on 2 ranks" % newton)
        worst = lc.rel_diff(res[2][:, 1:], res[1][:, 1:])[1]
        crossed = int(((res[1][:, 1] > 0.2) & (res[1][:, 1] < 0.24) & (np.abs(res[1][:, 3] + 0.01 - 0.004) < 0.002)).sum())
        print("newton %s: -np 2 vs -np 1: max rel. difference %.3g (%d differing values); atoms of row 1 "
              "now beyond x = 0.2: %d" % (newton, worst, int((res[2] != res[1]).sum()), crossed))
        chk.check(res[1].shape[0] == n and worst <= 1e-10, "newton %s: -np 2 equals -np 1 (%.3g)" % (newton, worst))
    chk.check(crossed >= 3, "spheres carried by the moving row crossed the processor boundary x = 0.2 (%d)" % crossed)

    # restart in the middle of a stroke
    head = PAR_HEAD.format(newton="off", processors="")
    lc.run(args["tdem"], head + body + "run %d\nrun %d\n" % (N1, N2) + DUMP.format(dump="dump.ref"), wd, "in.ref")
    lc.run(args["tdem"], head + body + "run %d\n" % N1 + DUMP.format(dump="dump.half") + "write_restart g.restart\n",
           wd, "in.first")
    second = "read_restart g.restart\ncomm_modify vel yes\n" + body.replace("pair_style      tdem/gran\npair_coeff      * * %s\n" % PAR_LAW, "")
    second += "run %d\n" % N2 + DUMP.format(dump="dump.rest")
    lc.run(args["tdem"], second, wd, "in.second")
    # control: a new fix ID loses the contact histories; t_start shifted so that the bars continue
    lost = second.replace("fix             gr ", "fix             gr2 ").replace("dump.rest", "dump.lost")
    lost = lost.replace("t_start %r" % PAR_M["t_start"], "t_start %r" % (PAR_M["t_start"] - N1 * 2e-5))
    assert lost.count("t_start") == 1 and "gr2" in lost
    lc.run(args["tdem"], lost, wd, "in.lost")
    cols, half = lc.read_dump(os.path.join(wd, "dump.half"))
    model = Model(PAR_G, PAR_M)
    boxes = model.boxes(N1 * 2e-5)
    two = 0
    for row in half:
        p = row[1:4]
        touching = 0
        for c, ax, hh, _ in boxes:
            d = p - c
            d[1] -= 0.054 * round(d[1] / 0.054)
            q = sum(max(-h, min(h, np.dot(d, e))) * e for e, h in zip(ax, hh))
            if np.linalg.norm(d - q) < 0.005:
                touching += 1
        two += touching >= 2
    u, v = motion(N1 * 2e-5, dict(MOTION_DEFAULT, **PAR_M), 0.0)
    print("restart at t = %.3f s: bar displacement %.4g m, velocity %.3g m/s; %d spheres touch two boxes"
          % (N1 * 2e-5, u, v, two))
    chk.check(two >= 8 and abs(v) > 0.1, "at the restart the bars move and %d spheres touch two boxes" % two)
    _, ref = lc.read_dump(os.path.join(wd, "dump.ref"))
    _, rest = lc.read_dump(os.path.join(wd, "dump.rest"))
    _, lost = lc.read_dump(os.path.join(wd, "dump.lost"))
    worst = lc.rel_diff(rest[:, 1:], ref[:, 1:])[1]
    dpos = lost[:, 1:4] - ref[:, 1:4]
    dpos[:, 1] -= 0.054 * np.round(dpos[:, 1] / 0.054)  # periodic width: minimum image
    dlost = np.abs(dpos).max()
    print("restart: max rel. difference %.3g (%d differing values); control without history: max |dx| %.3g m"
          % (worst, int((rest != ref).sum()), dlost))
    chk.check(worst <= 1e-10, "write_restart + read_restart + run M equals run N + run M (%.3g)" % worst)
    chk.check(dlost > 1e-9, "control: losing the contact histories changes the result (%.3g m)" % dlost)


# ------------------------------------------------------------------ 5. bad input
def part_bad_input():
    wd = lc.workdir("bad")
    par_data(os.path.join(wd, "spheres.data"))
    base = PAR_HEAD.format(newton="off", processors="")
    cases = [
        ("declination 95", ["declination", "95", "[0, 80]"]),
        ("type sideways", ["type", "sideways", "forward, reverse"]),
        ("profile square", ["profile", "square", "sinusoidal"]),
        ("rows 0", ["rows", "0", "[1, 1000]"]),
        ("rows 100000000", ["rows", "100000000", "[1, 1000]"]),
        ("overlap 0.2", ["overlap", "0.2", "[0, bar_length)"]),
        ("row_group -1 0 -1", ["row_group", "3", "one entry per row"]),
        ("group_phase 1.5", ["group_phase", "1.5", "[0, 1)"]),
        ("row_group -1 1 -1 1 group_phase 0.5", ["group_phase", "1", "one value per phase group"]),
        ("stroke -0.1", ["stroke", "-0.1", "[0, inf)"]),
        ("frequency 0", ["frequency", "0", "(0, inf)"]),
        ("dwell_out 0.6 dwell_home 0.5", ["dwell_out + dwell_home", "1.1", "[0, 1)"]),
        ("max_contacts 0", ["max_contacts", "0", "[1, 64]"]),
        ("vtk 0 bars", ["vtk", "0", "[1, inf)"]),
        ("bar_length abc", ["bar_length", "abc", "not a finite number"]),
        ("foo 1", ["unknown keyword", "foo", "bar_length"]),
        ("side_walls maybe", ["side_walls", "maybe", "no, yes"]),
        ("frame xy", ["'frame' = 'xy'", "needs 'dimension 2'"]),  # in 3D, with side walls (added below)
    ]
    for extra, words in cases:
        g = dict(PAR_G)
        if extra == "frame xy":
            g["side_walls"] = True
        text = base + PAR_BODY.format(law=PAR_LAW, grate=grate_args(g, PAR_M) + " " + extra, fid="gr") + "run 10\n"
        rc, out = lc.run(args["tdem"], text, wd, "in.bad", check=False)
        err = [l for l in out.splitlines() if l.startswith("ERROR")]
        msg = err[0] if err else "(no error)"
        ok = rc != 0 and bool(err) and all(w in msg for w in words)
        chk.check(ok, "'%s' -> %s" % (extra, msg))
    # more contacts than max_contacts: spheres in gaps touch two boxes
    text = base + PAR_BODY.format(law=PAR_LAW, grate=grate_args(PAR_G, PAR_M) + " max_contacts 1", fid="gr")
    rc, out = lc.run(args["tdem"], text + "run 2000\n", wd, "in.max", check=False)
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    msg = err[0] if err else "(no error)"
    chk.check(rc != 0 and "max_contacts = 1" in msg and "touches 2 boxes" in msg, "max_contacts 1 exceeded -> %s" % msg)
    # 2D requires frame xy
    text = HEAD3.format(dim=2, yb="f", zb="p", processors="", box="-0.1 0.5 -0.1 0.3 -0.01 0.01")
    text += "create_atoms 1 single 0.1 0.1 0 units box\nfix gr all tdem/grate %s frame xyz width 0.01\nrun 1\n" % PAR_LAW
    rc, out = lc.run(args["tdem"], text, wd, "in.2d", check=False)
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    msg = err[0] if err else "(no error)"
    chk.check(rc != 0 and "frame" in msg and "xyz" in msg and "allowed: xy" in msg, "frame xyz in 2D -> %s" % msg)
    # 3D refuses frame xy (it was accepted, and the bed then fell along -z past the bars: "Lost atoms")
    g = dict(PAR_G)
    g["side_walls"] = False
    text = base + PAR_BODY.format(law=PAR_LAW, grate=grate_args(g, PAR_M) + " frame xy", fid="gr") + "run 10\n"
    rc, out = lc.run(args["tdem"], text, wd, "in.xy3d", check=False)
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    msg = err[0] if err else "(no error)"
    chk.check(rc != 0 and "'frame' = 'xy'" in msg and "needs 'dimension 2'" in msg and "allowed in 3D: frame xyz" in msg
              and "Lost atoms" not in out, "frame xy in 3D -> %s" % msg)


# ------------------------------------------------------------------ 6. 2D
def part_twod():
    r, dt, nsteps = 0.005, 2e-5, 30000
    law = "normal lsd restitution 0.3 1e-3 tangential cundall_strack 0.8 0.5"
    g = dict(rows=2, bar_length=0.2, bar_height=0.05, declination=0.0, width=0.01, frame="xy", row_group=[-1, 0],
             origin=(0.0, 0.1, 0.0))
    mo = dict(profile="trapezoidal", stroke=0.02, period=0.4, t_start=0.05, dwell_out=0.1, dwell_home=0.1)
    mo["profile"] = "sinusoidal"
    text = HEAD3.format(dim=2, yb="f", zb="p", processors="", box="-0.1 0.5 -0.1 0.3 -0.01 0.01")
    for k, x in ((1, 0.25), (2, 0.33)):
        text += "create_atoms 1 single %r %r 0 units box\n" % (x, 0.1 + r - 1e-5)
    text += "set group all diameter %r density 2500\n" % (2 * r)
    text += "group norot id 1\ngroup rot id 2\n"
    text += "fix gr all tdem/grate %s %s\n" % (law, grate_args(g, mo))
    text += "fix grav all gravity 9.81 vector 0 -1 0\nfix n1 norot nve\nfix n2 rot nve/sphere disc\n"
    text += "fix e2 all enforce2d\ntimestep %r\n" % dt
    text += "variable x1 equal x[1]\nvariable x2 equal x[2]\nvariable y1 equal y[1]\n"
    text += "thermo_style custom step v_x1 v_x2 v_y1 f_gr[1] f_gr[2] f_gr[3]\nthermo_modify format float %.17g\n"
    text += "thermo 500\nrun %d\n" % nsteps
    wd = lc.workdir("twod")
    _, out = lc.run(args["tdem"], text, wd, "in.twod")
    rows = np.array([[float(w) for w in l.split()] for l in lc.thermo_blocks(out)[1:]])
    t = rows[:, 0] * dt
    i0 = np.searchsorted(t, 0.05)
    u = np.array([motion(tt, dict(MOTION_DEFAULT, **mo), 0.0)[0] for tt in t])
    e1 = np.abs(rows[i0:, 1] - rows[i0, 1] - u[i0:]).max()
    e2 = np.abs(rows[i0:, 2] - rows[i0, 2] - u[i0:] / 3.0).max()
    print("2D: non-rotating disk |x - x0 - u| = %.3g m; rolling disk |x - x0 - u/3| = %.3g m (%.2f %% of the stroke); "
          "max |F_z| on the bars %.3g N, max F_y %.3g N" % (e1, e2, 100 * e2 / mo["stroke"], np.abs(rows[:, 6]).max(),
                                                          np.abs(rows[:, 5]).max()))
    chk.check(u.max() > 0.019 and e1 < 1e-5, "2D: a disk on a moving bar is carried with it (%.3g m)" % e1)
    chk.check(e2 < 0.02 * mo["stroke"], "2D: a rolling disk moves by u/3 (within 2 %% of the stroke)")
    chk.check(np.abs(rows[:, 6]).max() == 0.0 and rows[-1, 5] < 0, "2D: bar forces in the xy plane, disks press down")


# ------------------------------------------------------------------ 7. the example scene
def part_scene():
    """input_scripts/lammps/grate_forward_3d.in on 2 ranks, shortened to 2000 steps: runs, writes the
    VTK files (set-up, step 2000) and the dump, the bed presses on the bars."""
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts", "lammps",
                       "grate_forward_3d.in")
    wd = lc.workdir("scene")
    with open(src) as f:
        text = f.read()
    _, out = lc.run(args["tdem"], text, wd, "in.scene", np_=2, mpirun=args["mpirun"], extra=["-var", "steps", "2000"])
    rows = [r.split() for r in lc.thermo_blocks(out)]
    hdr = rows[0]
    last = dict(zip(hdr, rows[-1]))
    vtk = sorted(os.path.basename(f) for f in glob.glob(os.path.join(wd, "grate_bars_*.vtp")))
    print("scene: %s atoms at step %s, force on the bars (%s, %s) N; VTK files %s"
          % (last["Atoms"], last["Step"], last["f_grate[1]"], last["f_grate[3]"], vtk))
    chk.check(vtk == ["grate_bars_0.vtp", "grate_bars_2000.vtp"], "scene: VTK of the bars at set-up and step 2000")
    chk.check(os.path.exists(os.path.join(wd, "grate_bed.dump")), "scene: particle dump written")
    chk.check(int(last["Atoms"]) > 600 and float(last["f_grate[3]"]) < 0, "scene: the bed lies on the grate")


{"scene": part_scene, "kinematics": part_kinematics, "carry": part_carry, "impact": part_impact, "parallel": part_parallel,
 "bad_input": part_bad_input, "twod": part_twod}[PART]()
chk.done()
