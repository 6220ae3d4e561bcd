#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Validation of fix tdem/clump (LAMMPS, issue 6). Writes results/ (table.md, *.png, *.json).

  study.py --lammps PATH/tdem-lammps [--mpirun mpirun] [--parts flat,tilted,rigid] [--quick]

flat    flat-face impacts of clumps with N = 1, 2, 4, 8 coplanar spheres on a wall (fix
        tdem/wall/gran lsd restitution e t_c, no gravity, no friction), several steps per contact:
        e and t_c against the closed form of N identical parallel contacts (computed here)
tilted  dimer and 4-sphere rod hitting the wall with one sphere at tilt angles 5..85 deg,
        frictionless and with friction: rebound velocity and spin at the end of the first contact
        against rigid-body impact theory (impulse at the contact point with the body's inverse
        mass matrix; Newton's restitution; computed here from the sphere geometry)
rigid   the same scenes with the stock fix rigid/small (RIGID package of the same LAMMPS):
        flat impacts, mass properties of overlapping spheres (double counting), Hertz flat impact
        (contact time depends on the body mass) and a small pour
Every expected value is computed in this script from closed forms (no numbers of the code under test).
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tests", "host"))
from clump_ref import hertz_wall_ode  # noqa: E402  (the RK4 reference of the LIGGGHTS hertz test)
RES = os.path.join(HERE, "results")

E, TC, R, RHO, V0 = 0.8, 1e-4, 0.002, 2500.0, 1.0
MS = 4.0 / 3.0 * math.pi * R ** 3 * RHO  # mass of one sphere


def args_of(argv):
    out = {"lammps": None, "mpirun": "mpirun", "parts": "flat,tilted,rigid", "quick": False}
    i = 1
    while i < len(argv):
        k = argv[i].lstrip("-")
        if k == "quick":
            out["quick"] = True
            i += 1
            continue
        out[k] = argv[i + 1]
        i += 2
    return out


def run(exe, text, cwd, name, np_=1, mpirun="mpirun"):
    with open(os.path.join(cwd, name), "w") as f:
        f.write(text)
    cmd = [exe, "-in", name, "-log", "log." + name, "-echo", "none", "-screen", "none"]
    if np_ > 1:
        cmd = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    t0 = time.time()
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(cwd, "log." + name)) as f:
        log = f.read()
    if p.returncode != 0:
        sys.stdout.write(log[-3000:] + p.stdout[-2000:])
        raise RuntimeError("%s failed (%d) in %s" % (" ".join(cmd), p.returncode, cwd))
    return log, time.time() - t0


def thermo(text):
    """numeric thermo rows of all runs (list of arrays, one per run)."""
    blocks, cur = [], None
    for line in text.splitlines():
        s = line.split()
        if s and s[0] == "Step":
            cur = []
            blocks.append(cur)
            continue
        if line.startswith("Loop time"):
            cur = None
            continue
        if cur is not None and s:
            try:
                cur.append([float(x) for x in s])
            except ValueError:
                pass
    return [np.array(b) for b in blocks]


# ------------------------------------------------------------------ closed forms
def lsd_beta(e):
    a = -math.log(e) / math.pi
    return a / math.sqrt(1 + a * a)


def closed_form_n(e, tc, n):
    """LSD (contact ends at zero overlap), parameters from (e, tc) with mass M; n parallel
    contacts (n may be any real > 0: n = M/m_loc for a single contact off the com line)."""
    beta = lsd_beta(e)
    w0 = math.pi / tc / math.sqrt(1 - beta * beta)
    bn, wn = math.sqrt(n) * beta, math.sqrt(n) * w0
    if bn >= 1:
        return 0.0, float("nan")
    return math.exp(-math.pi * bn / math.sqrt(1 - bn * bn)), math.pi / (wn * math.sqrt(1 - bn * bn))


def skew(a):
    return np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])


def inertia_spheres(pts, r, m):
    """mass, com, inertia tensor about the com of NON-overlapping spheres (parallel axes)."""
    pts = np.asarray(pts, float)
    M = m * len(pts)
    c = pts.mean(axis=0)
    I = np.zeros((3, 3))
    for p in pts - c:
        I += 0.4 * m * r * r * np.eye(3) + m * (p.dot(p) * np.eye(3) - np.outer(p, p))
    return M, c, I


def impact_theory(pts, r, m, v, w, e, mu=0.0):
    """Rigid-body impact of the lowest sphere on the plane z = 0 (normal +z): impulse at the
    contact point (below the sphere centre), Newton's restitution v_n' = -e v_n of the contact
    point; frictionless (impulse along n) or Coulomb (sticking impulse v_t' = 0 if it lies in the
    cone mu P_n, else sliding impulse P_n (n + mu d) along the sticking impulse's tangential
    direction d). Returns v', w', m_loc."""
    M, c, I = inertia_spheres(pts, r, m)
    low = np.asarray(pts, float)[np.argmin(np.asarray(pts)[:, 2])]
    rc = low - c + np.array([0, 0, -r])
    Ii = np.linalg.inv(I)
    K = np.eye(3) / M - skew(rc).dot(Ii).dot(skew(rc))
    n = np.array([0.0, 0.0, 1.0])
    vc = v + np.cross(w, rc)
    vn = vc.dot(n)
    m_loc = 1.0 / n.dot(K).dot(n)
    if mu == 0.0:
        P = -(1 + e) * vn * m_loc * n
    else:
        dv = -(1 + e) * vn * n - (vc - vn * n)
        P = np.linalg.solve(K, dv)
        pn = P.dot(n)
        pt = P - pn * n
        if np.linalg.norm(pt) > mu * pn:
            d = pt / np.linalg.norm(pt)
            pn = -(1 + e) * vn / n.dot(K).dot(n + mu * d)
            P = pn * (n + mu * d)
    return v + P / M, w + Ii.dot(np.cross(rc, P)), m_loc, M


def compliant_theory(pts, r, m, v0, e, tc, mu, kappa=0.8, nsub=20000):
    """Finite-duration reference with FIXED geometry (the body does not turn during the contact):
    the contact point below the lowest sphere carries the LSD law (k = M omega0^2, gamma =
    2 M beta omega0 from e, t_c with the body mass, attractive end allowed) and a Cundall-Strack
    tangential spring k_t = kappa k capped at mu |F_n| (no tangential dashpot); the body (M, I
    about y) moves in the x-z plane. Integrated here with symplectic Euler at t_c/nsub until the
    overlap returns to zero. Returns v', omega_y', t_c."""
    M, c, I = inertia_spheres(pts, r, m)
    low = np.asarray(pts, float)[np.argmin(np.asarray(pts)[:, 2])]
    rx, rz = (low - c)[0], (low - c)[2] - r
    Iyy = I[1, 1]
    beta = lsd_beta(e)
    w0 = math.pi / tc / math.sqrt(1 - beta * beta)
    k, g = M * w0 * w0, 2 * M * beta * w0
    kt = kappa * k
    h = tc / nsub
    vx, vz, w = 0.0, -v0, 0.0
    xi, s, t = 0.0, 0.0, 0.0
    while True:
        vcx, vcz = vx + w * rz, vz - w * rx
        fn = k * xi - g * vcz
        s += vcx * h
        ft = -kt * s
        if abs(ft) > mu * abs(fn):
            ft = math.copysign(mu * abs(fn), ft)
            s = -ft / kt
        vx += ft / M * h
        vz += fn / M * h
        w += (rz * ft - rx * fn) / Iyy * h
        xi -= (vz - w * rx) * h
        t += h
        if xi <= 0.0 and t > h:
            break
    return np.array([vx, 0.0, vz]), np.array([0.0, w, 0.0]), t


# ------------------------------------------------------------------ LAMMPS inputs
HEAD = """units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
atom_modify map array
region box block -0.05 0.05 -0.05 0.05 0 0.05
create_box 1 box
fix pm all property/atom mol ghost yes
read_data body.data add append fix pm NULL Molecules
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution {e} {tc} tangential cundall_strack 0.8 0
"""


def write_body(wd, pts, r, z0, v, rho=RHO, fname="body.data"):
    n = len(pts)
    lines = ["clump", "", "%d atoms" % n, "1 atom types", "", "-0.05 0.05 xlo xhi", "-0.05 0.05 ylo yhi",
             "0 0.05 zlo zhi", "", "Atoms # sphere", ""]
    for i, p in enumerate(pts):
        lines.append("%d 1 %.17g %.17g %.17g %.17g %.17g" % (i + 1, 2 * r, rho, p[0], p[1], p[2] + z0))
    lines += ["", "Velocities", ""] + ["%d %.17g %.17g %.17g 0 0 0" % (i + 1, v[0], v[1], v[2])
                                        for i in range(n)]
    lines += ["", "Molecules", ""] + ["%d 1" % (i + 1) for i in range(n)]
    with open(os.path.join(wd, fname), "w") as f:
        f.write("\n".join(lines) + "\n")


def write_template(wd, pts, r, fname="tpl.txt"):
    with open(os.path.join(wd, fname), "w") as f:
        f.write("".join("sphere %.17g %.17g %.17g %.17g\n" % (p[0], p[1], p[2], r) for p in pts))


def flat_pts(n, d):
    nx, ny = {1: (1, 1), 2: (2, 1), 4: (2, 2), 8: (4, 2)}[n]
    return [np.array([(i - 0.5 * (nx - 1)) * d, (j - 0.5 * (ny - 1)) * d, 0.0]) for j in range(ny) for i in range(nx)]


def integ_line(kind):
    if kind == "tdem":
        return "fix c all tdem/clump template t file tpl.txt density %g\n" % RHO
    return "comm_modify vel yes cutoff 0.03\nfix c all rigid/small molecule\n"


def contact_crossings(t, xi, dt):
    on = np.where(xi > 0)[0]
    if len(on) == 0:
        return float("nan"), float("nan")
    i0 = on[0]
    # end of the first contact interval
    i1 = i0
    while i1 + 1 < len(xi) and xi[i1 + 1] > 0:
        i1 += 1
    ts = t[i0 - 1] + (0 - xi[i0 - 1]) / (xi[i0] - xi[i0 - 1]) * dt if i0 > 0 else t[i0]
    te = t[i1] + (0 - xi[i1]) / (xi[i1 + 1] - xi[i1]) * dt if i1 + 1 < len(xi) else float("nan")
    return ts, te


def flat_run(exe, wd, n, spc, kind="tdem", law=None, d=0.0045, rho=RHO):
    """one flat impact; returns (e, t_c, steps in contact)."""
    pts = flat_pts(n, d)
    write_template(wd, pts, R)
    gap = 2e-6
    write_body(wd, pts, R, R + gap, (0, 0, -V0), rho=rho)
    e_ref, t_ref = closed_form_n(E, TC, n)
    dt = TC / spc
    law = law or "normal lsd restitution %g %g tangential cundall_strack 0.8 0" % (E, TC)
    tmax = t_ref if not math.isnan(t_ref) else TC
    if "hertz" in law:
        tmax = 8e-4  # Hertz E = 5e6: t_c about 5e-4 s here
    nsteps = int(math.ceil((gap / V0 + 1.6 * tmax) / dt)) + 5
    txt = (HEAD.format(e=E, tc=TC) + integ_line(kind) +
           "fix w all tdem/wall/gran %s zplane 0 NULL\n" % law +
           "variable zc equal xcm(all,z)\nvariable vz equal vcm(all,z)\n"
           "timestep %.17g\nthermo_style custom step v_zc v_vz\nthermo_modify format float %%.17g\n"
           "thermo 1\nrun %d\n" % (dt, nsteps))
    log, _ = run(exe, txt, wd, "in.flat_%s_%d_%d" % (kind, n, spc))
    rows = thermo(log)[-1]
    t = rows[:, 0] * dt
    xi = R - rows[:, 1]
    ts, te = contact_crossings(t, xi, dt)
    return rows[-1, 2] / V0, te - ts, (te - ts) / dt


def part_flat(exe, quick):
    wd = tempfile.mkdtemp(prefix="vclump_flat_")
    spcs = [10, 25, 100, 1000] if quick else [10, 25, 50, 100, 400, 2000]
    out = []
    for n in (1, 2, 4, 8):
        e_ref, t_ref = closed_form_n(E, TC, n)
        for spc in spcs:
            e_m, t_m, k = flat_run(exe, wd, n, spc)
            out.append(dict(n=n, spc=spc, steps_in_contact=k, e=e_m, tc=t_m, e_ref=e_ref, tc_ref=t_ref,
                            e_rel=(e_m - e_ref) / e_ref, tc_rel=(t_m - t_ref) / t_ref))
            print("flat N=%d dt=t_c/%d: e %.6f (closed %.6f) t_c %.5e (closed %.5e)" % (n, spc, e_m, e_ref, t_m, t_ref))
    return out


# ------------------------------------------------------------------ tilted
def tilted_pts(nsph, d, theta):
    """rod of nsph spheres along the x axis tilted by theta about y (first sphere lowest)."""
    L = d * (nsph - 1)
    u = np.array([math.cos(theta), 0.0, math.sin(theta)])
    return [(-0.5 * L + i * d) * u for i in range(nsph)]


def tilted_run(exe, wd, nsph, d, theta, mu, spc):
    pts = tilted_pts(nsph, d, theta)
    axis_pts = [np.array([(-0.5 * d * (nsph - 1) + i * d), 0.0, 0.0]) for i in range(nsph)]
    write_template(wd, axis_pts, R)
    gap = 2e-6
    zlow = min(p[2] for p in pts)
    write_body(wd, pts, R, R + gap - zlow, (0, 0, -V0))
    dt = TC / spc
    nsteps = int(math.ceil((gap / V0 + 2.5 * TC) / dt))
    law = "normal lsd restitution %g %g tangential cundall_strack 0.8 %g" % (E, TC, mu)
    zs = " ".join("v_z%d" % (i + 1) for i in range(nsph))
    txt = (HEAD.format(e=E, tc=TC) + integ_line("tdem") +
           "fix w all tdem/wall/gran %s zplane 0 NULL\n" % law +
           "".join("variable z%d equal z[%d]\n" % (i + 1, i + 1) for i in range(nsph)) +
           "timestep %.17g\n" % dt +
           "thermo_style custom step f_c[1][5] f_c[1][6] f_c[1][7] f_c[1][15] f_c[1][16] f_c[1][17] %s\n" % zs +
           "thermo_modify format float %%.17g\nthermo 1\nrun %d\n" % nsteps)
    log, _ = run(exe, txt, wd, "in.tilt_%d_%g_%g" % (nsph, theta, mu))
    rows = thermo(log)[-1]
    t = rows[:, 0] * dt
    xi1 = R - rows[:, 7]
    ts, te = contact_crossings(t, xi1, dt)
    # state right after the first sphere left the wall
    k = int(np.searchsorted(t, te)) + 1
    k = min(k, len(t) - 1)
    others = np.max(R - rows[:k + 1, 8:8 + nsph - 1]) if nsph > 1 else -1
    return dict(v=rows[k, 1:4], w=rows[k, 4:7], tc=te - ts, second=bool(others > 0),
                gap_other=float(-others))


def part_tilted(exe, quick):
    wd = tempfile.mkdtemp(prefix="vclump_tilt_")
    angles = [5, 15, 30, 45, 60, 75, 85] if not quick else [5, 30, 60, 85]
    out = []
    spc = 1000
    for shape, nsph, d in (("dimer", 2, 2 * R), ("rod4", 4, 2 * R)):
        for mu in (0.0, 0.5):
            for a in angles:
                th = math.radians(a)
                pts = tilted_pts(nsph, d, th)
                s = tilted_run(exe, wd, nsph, d, th, mu, spc)
                v, w = np.zeros(3), np.zeros(3)
                v0 = np.array([0, 0, -V0])
                vN, wN, m_loc, M = impact_theory(pts, R, MS, v0, w, E, mu)
                e_loc, t_loc = closed_form_n(E, TC, M / m_loc)
                vL, wL, _, _ = impact_theory(pts, R, MS, v0, w, e_loc, mu)
                vC, wC, tC = compliant_theory(pts, R, MS, V0, E, TC, mu)
                half = 0.5 * d * (nsph - 1)
                rec = dict(shape=shape, mu=mu, angle=a, m_loc_over_M=m_loc / M, e_loc=e_loc, tc_loc=t_loc,
                           tc=s["tc"], vx=s["v"][0], vz=s["v"][2], wy=s["w"][1],
                           vx_N=vN[0], vz_N=vN[2], wy_N=wN[1], vx_L=vL[0], vz_L=vL[2], wy_L=wL[1],
                           dev_N=float(max(np.max(np.abs(s["v"] - vN)), np.max(np.abs(s["w"] - wN)) * half) / V0),
                           dev_L=float(max(np.max(np.abs(s["v"] - vL)), np.max(np.abs(s["w"] - wL)) * half) / V0),
                           dev_C=float(max(np.max(np.abs(s["v"] - vC)), np.max(np.abs(s["w"] - wC)) * half) / V0),
                           vx_C=vC[0], vz_C=vC[2], wy_C=wC[1], tc_C=tC,
                           second=s["second"], gap_other=s["gap_other"])
                out.append(rec)
                print("%s mu=%g %2d deg: vz %.5f (Newton e %.5f, e_loc %.5f) vx %.5f (%.5f) wy %.3f (%.3f, %.3f) "
                      "dev %.2e / %.2e / compliant %.2e m_loc/M %.3f" % (shape, mu, a, s["v"][2], vN[2], vL[2], s["v"][0], vL[0],
                                                          s["w"][1], wN[1], wL[1], rec["dev_N"], rec["dev_L"],
                                                          rec["dev_C"], m_loc / M))
    # convergence in the time step at one angle
    conv = []
    for spc in (50, 200, 1000, 5000):
        th = math.radians(45)
        pts = tilted_pts(2, 2 * R, th)
        s = tilted_run(exe, wd, 2, 2 * R, th, 0.0, spc)
        vN, wN, m_loc, M = impact_theory(pts, R, MS, np.array([0, 0, -V0]), np.zeros(3), E)
        e_loc, _ = closed_form_n(E, TC, M / m_loc)
        vL, wL, _, _ = impact_theory(pts, R, MS, np.array([0, 0, -V0]), np.zeros(3), e_loc)
        conv.append(dict(spc=spc, dev_L=float(max(np.max(np.abs(s["v"] - vL)), np.max(np.abs(s["w"] - wL)) * R) / V0),
                         vz=float(s["v"][2]), wy=float(s["w"][1])))
    return out, conv


# ------------------------------------------------------------------ rigid/small
def mc_union(pts, r, rho, n=400000, seed=1):
    """Monte-Carlo mass, com and inertia of the union of equal spheres (independent of the core)."""
    pts = np.asarray(pts, float)
    lo, hi = pts.min(axis=0) - r, pts.max(axis=0) + r
    rng = np.random.default_rng(seed)
    acc = []
    for _ in range(10):
        x = lo + (hi - lo) * rng.random((n, 3))
        inside = np.zeros(n, bool)
        for p in pts:
            inside |= np.sum((x - p) ** 2, axis=1) <= r * r
        acc.append(x[inside])
    x = np.vstack(acc)
    vol = np.prod(hi - lo) * len(x) / (10 * n)
    M = rho * vol
    c = x.mean(axis=0)
    y = x - c
    I = M * (np.eye(3) * np.mean(np.sum(y * y, axis=1)) - (y.T.dot(y)) / len(y))
    return M, c, I


def tetra_pts(d):
    a = d / math.sqrt(8.0)
    return [np.array(p) * a for p in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1))]


def rigid_props(exe, wd, pts, r, rho_sphere, kind):
    """body mass and principal moments seen by the host fix (rigid/small: compute rigid/local;
    tdem/clump: rebuilt from L and omega is not needed - the per-sphere masses it sets are read)."""
    write_template(wd, pts, r)
    write_body(wd, pts, r, 0.01, (0, 0, 0), rho=rho_sphere)
    txt = HEAD.format(e=E, tc=TC) + integ_line(kind)
    if kind == "rigid":
        txt += ("compute rl all rigid/local c mass inertiax inertiay inertiaz\n"
                "dump dl all local 1 rl.dump c_rl[1] c_rl[2] c_rl[3] c_rl[4]\n")
    txt += "compute pma all property/atom mass\ncompute ms all reduce sum c_pma\nthermo_style custom step c_ms\nthermo_modify format float %.17g\nrun 0\n"
    log, _ = run(exe, txt, wd, "in.props_" + kind)
    msum = thermo(log)[-1][-1, 1]
    if kind == "tdem":
        import re
        m = re.search(r"principal inertia ([0-9.eE+-]+) ([0-9.eE+-]+) ([0-9.eE+-]+)", log)
        return msum, sorted(float(x) for x in m.groups()) if m else None
    if kind == "rigid":
        with open(os.path.join(wd, "rl.dump")) as f:
            lines = f.read().splitlines()
        k = [i for i, l in enumerate(lines) if l.startswith("ITEM: ENTRIES")][-1]
        vals = [float(x) for x in lines[k + 1].split()]
        return vals[0], sorted(vals[1:4])
    return msum, None


POUR = """units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
atom_modify map array
processors * * 1
region box block 0 0.03 0 0.03 0 0.12 units box
create_box 1 box
fix pm all property/atom mol ghost yes
{create}
neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
variable law string "normal hertz 5e6 0.3 damping tsuji 0.6 tangential cundall_strack 0.8 0.5 limit_force yes"
pair_style tdem/gran
pair_coeff * * ${{law}}
fix floor all tdem/wall/gran ${{law}} zplane 0 NULL
fix g all gravity 9.81 vector 0 0 -1
timestep 1e-5
variable zc equal xcm(all,z)
compute nc all contact/atom
compute snc all reduce sum c_nc
compute pma all property/atom mass\ncompute ms all reduce sum c_pma
compute kes all ke
thermo_style custom step c_kes v_zc c_snc c_ms
thermo_modify format float %.10g
thermo 250
run {steps}
"""


def part_rigid(exe, quick, mpirun):
    wd = tempfile.mkdtemp(prefix="vclump_rigid_")
    res = {}
    # 1. flat impacts (non-overlapping spheres: both fixes have the same mass properties)
    fl = []
    for n in (1, 2, 4, 8):
        e_ref, t_ref = closed_form_n(E, TC, n)
        row = dict(n=n, e_ref=e_ref, tc_ref=t_ref)
        for kind in ("tdem", "rigid"):
            if kind == "rigid" and n == 1:  # fix rigid/small: "One or more rigid bodies are a single particle"
                row["e_rigid"] = row["tc_rigid"] = float("nan")
                continue
            e_m, t_m, _ = flat_run(exe, wd, n, 2000, kind)
            row["e_" + kind], row["tc_" + kind] = e_m, t_m
        fl.append(row)
        print("rigid/small flat N=%d: e %.6f tdem %.6f closed %.6f" % (n, row["e_rigid"], row["e_tdem"], e_ref))
    res["flat"] = fl
    # 2. mass properties of overlapping spheres: tetra r = 2 mm, edge 3 mm; square4 spacing 3 mm
    props = []
    for name, pts in (("tetra (edge 3 mm)", tetra_pts(0.003)), ("square4 (spacing 3 mm)", flat_pts(4, 0.003)),
                      ("dimer touching (d = 2r)", flat_pts(2, 2 * R))):
        Mu, _, Iu = mc_union(pts, R, RHO)
        lu = sorted(np.linalg.eigvalsh(Iu))
        Mr, lr = rigid_props(exe, wd, pts, R, RHO, "rigid")
        Mt, lt = rigid_props(exe, wd, pts, R, RHO, "tdem")
        # rigid/small fed with the masses tdem/clump gives the spheres (share of the union mass)
        share = RHO * Mt / (len(pts) * MS)
        Mr2, lr2 = rigid_props(exe, wd, pts, R, share, "rigid")
        props.append(dict(shape=name, M_union=Mu, I_union=lu, M_tdem=Mt, I_tdem=lt, M_rigid=Mr, I_rigid=lr,
                          M_rigid_share=Mr2, I_rigid_share=lr2))
        print("props %s: union M %.4e I %s; tdem M %.4e; rigid/small M %.4e I %s; with share M %.4e I %s"
              % (name, Mu, lu, Mt, Mr, lr, Mr2, lr2))
    res["props"] = props
    # 3. Hertz flat impact of the overlapping square4: t_c ~ M^(2/5) (same N = 4 contacts)
    law = "normal hertz 5e6 0.3 damping tsuji 0.8 tangential cundall_strack 0.8 0"
    hz = {}
    for kind in ("tdem", "rigid"):
        e_m, t_m, _ = flat_run(exe, wd, 4, 400, kind, law=law, d=0.003)
        hz[kind] = dict(e=e_m, tc=t_m)
    pr = props[1]
    hz["tc_ratio"] = hz["rigid"]["tc"] / hz["tdem"]["tc"]
    hz["tc_ratio_expected"] = (pr["M_rigid"] / pr["M_tdem"]) ** 0.4
    res["hertz_square4"] = hz
    print("hertz square4: tc ratio rigid/tdem %.5f expected (M ratio)^0.4 %.5f" % (hz["tc_ratio"], hz["tc_ratio_expected"]))
    # 4. small pour: the same inserted tetra clumps with both fixes
    nclump = 60 if quick else 150
    steps = 4000 if quick else 8000
    create = ("region ins block 0 0.03 0 0.03 0.005 0.115 units box\n"
              "fix ins all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 "
              "insert %d region ins seed 4711 vel 0 0 -0.5\n" % nclump)
    run(exe, POUR.format(create=create, steps=0) + "write_data pour.data nocoeff\n", wd, "in.pour_make")
    pours = {}
    for key, integ, dens in (("tdem/clump", "fix c all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 bodies molecule", None),
                             ("rigid/small, sphere masses = union share", "comm_modify vel yes cutoff 0.01\nfix c all rigid/small molecule", None),
                             ("rigid/small, every sphere density 2500", "comm_modify vel yes cutoff 0.01\nfix c all rigid/small molecule", 2500)):
        create = "read_data pour.data add append fix pm NULL Molecules\n" + ("set group all density %g\n" % dens if dens else "") + integ
        log, wall = run(exe, POUR.format(create=create, steps=steps), wd, "in.pour_%d" % len(pours))
        rows = thermo(log)[-1]
        pours[key] = dict(t=(rows[:, 0] * 1e-5).tolist(), ke=rows[:, 1].tolist(), zc=rows[:, 2].tolist(),
                          contacts=rows[:, 3].tolist(), mass=float(rows[0, 4]), wall=wall)
        print("pour %s: mass %.5e final zc %.5f ke %.3e contacts %d" % (key, rows[0, 4], rows[-1, 2], rows[-1, 1], rows[-1, 3]))
    res["pour"] = dict(nclump=nclump, steps=steps, runs=pours)
    return res


# ------------------------------------------------------------------ output
def write_results(flat, tilt, conv, rig, quick):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(RES, exist_ok=True)
    md = ["# fix tdem/clump (LAMMPS): validation results", "",
          "Generated by `validation/clumps/run.sh`%s. Law: `normal lsd restitution %g %g` (contact ends at "
          "zero overlap, parameters derived with the body mass M), spheres r = %g m, density %g, v0 = %g m/s, "
          "no gravity." % (" (--quick)" if quick else "", E, TC, R, RHO, V0), ""]
    if flat:
        md += ["## a. Flat-face impacts, N spheres touching at once (no correction)", "",
               "Closed form of N identical parallel contacts (physics_reference 6.4): beta_N = sqrt(N) beta, "
               "omega_N = sqrt(N) omega0. `spc` = single-contact t_c / dt; `steps` = steps in the N-contact.", "",
               "| N | spc | steps | e | e closed | rel | t_c (s) | t_c closed | rel |", "|---|---|---|---|---|---|---|---|---|"]
        for r in flat:
            md.append("| %d | %d | %.1f | %.6f | %.6f | %.1e | %.5e | %.5e | %.1e |" % (
                r["n"], r["spc"], r["steps_in_contact"], r["e"], r["e_ref"], r["e_rel"], r["tc"], r["tc_ref"], r["tc_rel"]))
        md += ["", "With the multiple-contact correction in the core (the host styles' numbers: "
               "`correction_lammps.md`, `liggghts_correction.md`; "
               "`tests/unit/test_clumps.cpp`, `ClumpMultiContact.FlatFaceDropsMatchNContactClosedFormAndCorrection`, "
               "r = 1 mm, spacing 1.8 mm, dt = t_c/5000), printed by the unit test:", "", "```"]
        ut = os.path.join(HERE, "unit_clumps.txt")
        if os.path.exists(ut):
            md += [l.rstrip() for l in open(ut) if "[ clumps ]" in l]
        md += ["```", ""]
        fig, ax = plt.subplots(1, 2, figsize=(10, 4))
        for n in (1, 2, 4, 8):
            rr = [r for r in flat if r["n"] == n]
            ax[0].loglog([r["spc"] for r in rr], [max(abs(r["e_rel"]), 1e-8) for r in rr], "o-", label="N = %d" % n)
            ax[1].loglog([r["spc"] for r in rr], [max(abs(r["tc_rel"]), 1e-8) for r in rr], "o-", label="N = %d" % n)
        ax[0].set_title("|e - e_N| / e_N"); ax[1].set_title("|t_c - t_N| / t_N")
        for a in ax:
            a.set_xlabel("single-contact t_c / dt"); a.grid(True, which="both", alpha=0.3); a.legend()
        fig.tight_layout(); fig.savefig(os.path.join(RES, "flat_convergence.png"), dpi=110); plt.close(fig)
        fig, ax = plt.subplots(figsize=(5, 4))
        ns = np.linspace(1, 8, 50)
        ax.plot(ns, [closed_form_n(E, TC, x)[0] for x in ns], "k-", label="closed form e_N")
        ax.plot(ns, [closed_form_n(E, TC, x)[1] / TC for x in ns], "k--", label="closed form t_N / t_c")
        big = max(r["spc"] for r in flat)
        rr = [r for r in flat if r["spc"] == big]
        ax.plot([r["n"] for r in rr], [r["e"] for r in rr], "o", label="tdem/clump e")
        ax.plot([r["n"] for r in rr], [r["tc"] / TC for r in rr], "s", label="tdem/clump t_c / t_c1")
        ax.axhline(E, color="grey", lw=0.8); ax.set_xlabel("N spheres touching"); ax.legend(); ax.grid(alpha=0.3)
        fig.tight_layout(); fig.savefig(os.path.join(RES, "flat_e_tc.png"), dpi=110); plt.close(fig)
    if tilt:
        md += ["## b. Tilted impacts, one sphere touches first", "",
               "Rod of touching spheres (d = 2r; `dimer` 2, `rod4` 4 spheres) with its axis at `angle` to the wall, "
               "v0 straight down, no spin; the state at the end of the first sphere's contact (dt = t_c/1000) is "
               "compared with three references computed in `study.py`:", "",
               "* `Newton e`: rigid-body impact theory, impulse at the contact point with the inverse mass matrix "
               "K = 1/M - [r]x I^-1 [r]x, v_n' = -e v_n of the contact point with the nominal e = %g "
               "(frictionless: impulse along n; mu = 0.5: Coulomb impulse - sticking v_t' = 0 if inside the cone, "
               "else sliding);" % E,
               "* `e_loc`: the same with the restitution the LSD law (k, gamma derived with the body mass M) has "
               "for the local effective mass m_loc = 1/(n.K.n): the N-contact closed form with N = M/m_loc;",
               "* `compliant`: the finite contact with FIXED geometry - the contact point carries the LSD spring-"
               "dashpot and the Cundall-Strack spring k_t = 0.8 k capped at mu|F_n|, body (M, I_yy) integrated "
               "in the x-z plane at t_c/20000 (independent of the host code).", "",
               "`dev` = max(|v - v_ref|, |omega - omega_ref| L/2) / v0 (L/2: half the rod length).", "",
               "| shape | mu | angle | m_loc/M | e_loc | vz | vz Newton e | vz e_loc | vz compliant | vx | vx e_loc | "
               "vx compliant | omega_y | omega_y e_loc | omega_y compliant | dev Newton e | dev e_loc | dev compliant | "
               "t_c/t_c1 | t_c compliant/t_c1 | other sphere touched |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in tilt:
            md.append("| %s | %g | %d | %.4f | %.4f | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.2f | %.2f | %.2f "
                      "| %.1e | %.1e | %.1e | %.4f | %.4f | %s |" % (
                r["shape"], r["mu"], r["angle"], r["m_loc_over_M"], r["e_loc"], r["vz"], r["vz_N"], r["vz_L"],
                r["vz_C"], r["vx"], r["vx_L"], r["vx_C"], r["wy"], r["wy_L"], r["wy_C"], r["dev_N"], r["dev_L"],
                r["dev_C"], r["tc"] / TC, r["tc_C"] / TC,
                "yes" if r["second"] else "no (gap %.1e m)" % r["gap_other"]))
        md += ["", "Time-step convergence (dimer, 45 deg, frictionless), dev vs e_loc theory: " +
               ", ".join("t_c/%d: %.2e" % (c["spc"], c["dev_L"]) for c in conv) +
               " (vz: " + ", ".join("%.6f" % c["vz"] for c in conv) + "; omega_y: " +
               ", ".join("%.4f" % c["wy"] for c in conv) + ")", ""]
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        for shape in ("dimer", "rod4"):
            for mu, ls in ((0.0, "-"), (0.5, "--")):
                rr = [r for r in tilt if r["shape"] == shape and r["mu"] == mu]
                ax[0].semilogy([r["angle"] for r in rr], [max(r["dev_L"], 1e-9) for r in rr], "o" + ls,
                               label="%s mu=%g (e_loc)" % (shape, mu))
                ax[0].semilogy([r["angle"] for r in rr], [max(r["dev_N"], 1e-9) for r in rr], "x:",
                               label="%s mu=%g (Newton e)" % (shape, mu))
                ax[0].semilogy([r["angle"] for r in rr], [max(r["dev_C"], 1e-9) for r in rr], "s" + ls, mfc="none",
                               label="%s mu=%g (compliant)" % (shape, mu))
                ax[1].plot([r["angle"] for r in rr], [r["vz"] for r in rr], "o" + ls, label="%s mu=%g sim" % (shape, mu))
                ax[1].plot([r["angle"] for r in rr], [r["vz_C"] for r in rr], "k" + ls, lw=0.8)
        ax[0].set_xlabel("tilt angle (deg)"); ax[0].set_ylabel("deviation / v0"); ax[0].legend(fontsize=6)
        ax[1].set_xlabel("tilt angle (deg)"); ax[1].set_ylabel("v_z of the com after the contact (m/s)")
        ax[1].legend(fontsize=6); ax[1].set_title("lines: compliant fixed-geometry reference")
        for a in ax:
            a.grid(alpha=0.3)
        fig.tight_layout(); fig.savefig(os.path.join(RES, "tilted.png"), dpi=110); plt.close(fig)
    if rig:
        md += ["## c. Stock `fix rigid/small` (same tdem-lammps executable, RIGID package of LAMMPS 20220106)", "",
               "Flat impacts with the same spheres, the same `fix tdem/wall/gran` law (both fixes export the body "
               "mass, so m* = M), dt = t_c/2000 (N = 1: rigid/small refuses a body of one sphere, "
               "\"One or more rigid bodies are a single particle\"):", "",
               "| N | e tdem/clump | e rigid/small | e closed | t_c tdem/clump | t_c rigid/small | t_c closed |",
               "|---|---|---|---|---|---|---|"]
        for r in rig["flat"]:
            md.append("| %d | %.6f | %.6f | %.6f | %.5e | %.5e | %.5e |" % (r["n"], r["e_tdem"], r["e_rigid"], r["e_ref"],
                                                                          r["tc_tdem"], r["tc_rigid"], r["tc_ref"]))
        md += ["", "Mass properties (r = 2 mm, density 2500). `union`: Monte-Carlo integration of the sphere union "
               "in this script (4e6 points, ~1e-3); tdem/clump: sum of the masses it gives the spheres; "
               "rigid/small: `compute rigid/local` (mass, principal moments), with every sphere at density 2500 "
               "and with the spheres' masses set to tdem/clump's share of the union mass:", "",
               "| shape | M union | M tdem/clump | M rigid/small | I union (principal) | I tdem/clump (its log) | I rigid/small | "
               "M rigid/small (share) | I rigid/small (share) |", "|---|---|---|---|---|---|---|---|---|"]
        for p in rig["props"]:
            md.append("| %s | %.4e | %.4e | %.4e (x%.3f) | %s | %s | %s | %.4e | %s |" % (
                p["shape"], p["M_union"], p["M_tdem"], p["M_rigid"], p["M_rigid"] / p["M_union"],
                " ".join("%.3e" % x for x in p["I_union"]), " ".join("%.3e" % x for x in (p["I_tdem"] or [])),
                " ".join("%.3e" % x for x in p["I_rigid"]),
                p["M_rigid_share"], " ".join("%.3e" % x for x in p["I_rigid_share"])))
        hz = rig["hertz_square4"]
        md += ["", "Effect on a Hertz flat impact (square4 of overlapping spheres, `normal hertz 5e6 0.3 damping "
               "tsuji 0.8`, N = 4): e tdem/clump %.5f, rigid/small %.5f (Tsuji: e independent of the mass); t_c "
               "rigid/small / tdem/clump = %.5f, expected (M_rigid/M_union)^(2/5) = %.5f." % (
                   hz["tdem"]["e"], hz["rigid"]["e"], hz["tc_ratio"], hz["tc_ratio_expected"]), ""]
        po = rig["pour"]
        md += ["Pour: %d tetra clumps (r = 2 mm, edge 3 mm) inserted once by tdem/clump, written to a data file "
               "and read by each run; Hertz + Tsuji + Cundall-Strack, gravity, %d steps of 1e-5 s:" % (
                   po["nclump"], po["steps"]), "",
               "| integrator | total mass (kg) | final com height (m) | final sum 1/2 m v^2 of the spheres (J) | final contacts | wall (s) |",
               "|---|---|---|---|---|---|"]
        fig, ax = plt.subplots(1, 2, figsize=(10, 4))
        for k, r in po["runs"].items():
            md.append("| %s | %.5e | %.5f | %.3e | %d | %.1f |" % (k, r["mass"], r["zc"][-1], r["ke"][-1], r["contacts"][-1], r["wall"]))
            ax[0].semilogy(r["t"], np.maximum(r["ke"], 1e-12), label=k)
            ax[1].plot(r["t"], r["zc"], label=k)
        ax[0].set_ylabel("sum of 1/2 m v^2 of the spheres (J)"); ax[1].set_ylabel("com height (m)")
        for a in ax:
            a.set_xlabel("t (s)"); a.legend(fontsize=7); a.grid(alpha=0.3)
        fig.tight_layout(); fig.savefig(os.path.join(RES, "pour_rigid_small.png"), dpi=110); plt.close(fig)
        md.append("")
    with open(os.path.join(RES, "table.md"), "w") as f:
        f.write("\n".join(md) + "\n")


# ================================================================== LAMMPS: multiple-contact correction
# (section of the LAMMPS host; `study.py --lammps EXE --parts correction_lammps`; writes
# results/correction_lammps.md, .png, .json). fix tdem/clump ... correction none|count|overlap|local_mass,
# applied by pair tdem/gran and fix tdem/wall/gran. References computed here: closed_form_n (N-contact
# and single-contact LSD), m_loc of two disjoint spheres from the geometry.
LMP_CORR_MODES = ("none", "count", "overlap", "local_mass")


def lmp_corr_flat(exe, wd, n, spc, mode):
    """flat impact of N coplanar spheres with a correction mode: (e, t_c)."""
    pts = flat_pts(n, 0.0045)
    write_template(wd, pts, R)
    gap = 2e-6
    write_body(wd, pts, R, R + gap, (0, 0, -V0))
    dt = TC / spc
    nsteps = int(math.ceil((gap / V0 + 1.6 * TC) / dt)) + 5
    txt = (HEAD.format(e=E, tc=TC) + integ_line("tdem").rstrip("\n") + " correction %s\n" % mode +
           "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL\n"
           % (E, TC) + "variable zc equal xcm(all,z)\nvariable vz equal vcm(all,z)\n"
           "timestep %.17g\nthermo_style custom step v_zc v_vz\nthermo_modify format float %%.17g\n"
           "thermo 1\nrun %d\n" % (dt, nsteps))
    log, _ = run(exe, txt, wd, "in.cflat_%s_%d_%d" % (mode, n, spc))
    rows = thermo(log)[-1]
    t = rows[:, 0] * dt
    ts, te = contact_crossings(t, R - rows[:, 1], dt)
    return rows[-1, 2] / V0, te - ts


def lmp_corr_dimer(exe, wd, theta, mode, v0=0.1, spc=4000):
    """dimer of two disjoint spheres tilted by theta, frictionless, one sphere hits the wall:
    normal velocity of the contact point after / before (= that of the lower sphere), contact time."""
    d = 0.0045
    pts = tilted_pts(2, d, theta)
    write_template(wd, [np.array([-0.5 * d, 0.0, 0.0]), np.array([0.5 * d, 0.0, 0.0])], R)
    gap = 1e-7
    zlow = min(p[2] for p in pts)
    write_body(wd, pts, R, R + gap - zlow, (0, 0, -v0))
    dt = TC / spc
    nsteps = int(1.5 * TC / dt)
    txt = (HEAD.format(e=E, tc=TC) + integ_line("tdem").rstrip("\n") + " correction %s\n" % mode +
           "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL\n"
           % (E, TC) + "variable z1 equal z[1]\nvariable v1 equal vz[1]\n"
           "timestep %.17g\nthermo_style custom step v_z1 v_v1\nthermo_modify format float %%.17g\n"
           "thermo 1\nrun %d\n" % (dt, nsteps))
    log, _ = run(exe, txt, wd, "in.cdimer_%s_%g" % (mode, theta))
    rows = thermo(log)[-1]
    t = rows[:, 0] * dt
    ts, te = contact_crossings(t, R - rows[:, 1], dt)
    k = int(np.searchsorted(t, te))
    v_after = rows[k - 1, 2] + (rows[k, 2] - rows[k - 1, 2]) * (te - t[k - 1]) / dt
    m = MS
    M = 2 * m
    Iyy = 2 * (0.4 * m * R * R + m * (0.5 * d) ** 2)
    m_loc = 1.0 / (1.0 / M + (0.5 * d * math.cos(theta)) ** 2 / Iyy)
    return dict(e=v_after / v0, tc=te - ts, m_loc_over_M=m_loc / M)


def lmp_corr_row(exe, wd, theta, mode, n=4, spc=1000):
    """row of n spheres tilted by theta: largest step change of the wall force (without the first
    touch and the release) over the largest force."""
    d = 0.0045
    pts = tilted_pts(n, d, theta) if n > 1 else [np.zeros(3)]
    axis = [np.array([(-0.5 * d * (n - 1) + i * d), 0.0, 0.0]) for i in range(n)]
    write_template(wd, axis, R)
    zlow = min(p[2] for p in pts)
    write_body(wd, pts, R, R + 1e-6 - zlow, (0, 0, -V0))
    dt = TC / spc
    txt = (HEAD.format(e=E, tc=TC) + integ_line("tdem").rstrip("\n") + " correction %s\n" % mode +
           "fix w all tdem/wall/gran normal lsd restitution %g %g tangential cundall_strack 0.8 0 zplane 0 NULL\n"
           % (E, TC) + "variable fz equal fcm(all,z)\n"
           "timestep %.17g\nthermo_style custom step v_fz\nthermo_modify format float %%.17g\n"
           "thermo 1\nrun %d\n" % (dt, int(1.5 * spc)))
    log, _ = run(exe, txt, wd, "in.crow_%s_%d_%g" % (mode, n, theta))
    F = thermo(log)[-1][:, 1]
    dF = np.abs(np.diff(F))
    keep = (F[:-1] != 0.0) & (F[1:] != 0.0)
    return float(np.max(dF[keep]) / np.max(np.abs(F)))


def lmp_corr_study(exe, quick):
    wd = tempfile.mkdtemp(prefix="vclump_corr_lmp_")
    spcs = [25, 1000] if quick else [25, 100, 1000]
    flat = []
    for mode in LMP_CORR_MODES:
        for n in (1, 2, 4, 8):
            for spc in spcs:
                e_m, t_m = lmp_corr_flat(exe, wd, n, spc, mode)
                e1, t1 = closed_form_n(E, TC, 1)
                en, tn = closed_form_n(E, TC, n)
                flat.append(dict(mode=mode, n=n, spc=spc, e=e_m, tc=t_m, e_rel_1=(e_m - e1) / e1, tc_rel_1=(t_m - t1) / t1,
                                 e_rel_n=(e_m - en) / en, tc_rel_n=(t_m - tn) / tn))
                print("correction %s flat N=%d spc=%d: e %.6f t_c %.5e" % (mode, n, spc, e_m, t_m))
    dimer = []
    for deg in ((15, 45, 75) if quick else (10, 20, 30, 45, 60, 75, 85)):
        th = math.radians(deg)
        r0 = lmp_corr_dimer(exe, wd, th, "none")
        r1 = lmp_corr_dimer(exe, wd, th, "local_mass")
        e_pred, t_pred = closed_form_n(E, TC, 1.0 / r0["m_loc_over_M"])
        dimer.append(dict(deg=deg, m_loc_over_M=r0["m_loc_over_M"], e_none=r0["e"], tc_none=r0["tc"],
                          e_none_closed=e_pred, tc_none_closed=t_pred, e_local=r1["e"], tc_local=r1["tc"]))
        print("dimer %d deg: m_loc/M %.4f; none e %.5f (closed %.5f); local_mass e %.5f t_c %.5e"
              % (deg, r0["m_loc_over_M"], r0["e"], e_pred, r1["e"], r1["tc"]))
    one = lmp_corr_row(exe, wd, 0.0, "none", n=1)
    cont = []
    for mrad in ((2.0,) if quick else (1.0, 2.0, 5.0)):
        row = dict(mrad=mrad, single=one)
        for mode in ("none", "count", "overlap"):
            row[mode] = lmp_corr_row(exe, wd, mrad * 1e-3, mode)
        cont.append(row)
        print("row of 4, %g mrad: max step change / max force: one sphere %.4f, none %.4f, count %.4f, overlap %.4f"
              % (mrad, one, row["none"], row["count"], row["overlap"]))
    return dict(flat=flat, dimer=dimer, continuity=cont)


def lmp_corr_write(res, quick):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(RES, exist_ok=True)
    with open(os.path.join(RES, "correction_lammps.json"), "w") as f:
        json.dump(res, f, indent=1, default=float)
    md = ["# LAMMPS: multiple-contact correction of fix tdem/clump", "",
          "Generated by `study.py --parts correction_lammps`%s. Law `normal lsd restitution %g %g` (zero-overlap "
          "end, parameters derived with the body mass; per contact with m_loc for `local_mass`), spheres r = %g m, "
          "density %g, no gravity, no friction. References computed in study.py: closed_form_n." %
          (" --quick" if quick else "", E, TC, R, RHO), "",
          "## Flat-face impacts (v0 = %g m/s): relative error of e and t_c against the single-contact (N = 1) "
          "and the N-contact closed form" % V0, "",
          "| correction | N | spc | e | t_c (s) | e vs N=1 | t_c vs N=1 | e vs N-contact | t_c vs N-contact |",
          "|---|---|---|---|---|---|---|---|---|"]
    for r in res["flat"]:
        md.append("| %s | %d | %d | %.6f | %.5e | %.1e | %.1e | %.1e | %.1e |" % (
            r["mode"], r["n"], r["spc"], r["e"], r["tc"], r["e_rel_1"], r["tc_rel_1"], r["e_rel_n"], r["tc_rel_n"]))
    md += ["", "`count` and `overlap` give the single-contact e and t_c for every N (coplanar spheres: equal "
           "overlaps, so both are the same); `local_mass` alone does not remove the N-fold stiffness of a flat "
           "face (each contact's m_loc < M when the contact is off the com line, so it makes the face stiffer and "
           "more damped still, or equal for N = 1).", "",
           "## Tilted dimer, one sphere hits the wall (frictionless, v0 = 0.1 m/s, dt = t_c/4000)", "",
           "Contact-point restitution = normal velocity of the contact point after / before. Without correction "
           "the law (parameters with M) acts on the effective mass m_loc: closed form with N = M/m_loc.", "",
           "| tilt (deg) | m_loc/M | none: e | closed form | none: t_c (s) | closed form | local_mass: e | local_mass: t_c (s) |",
           "|---|---|---|---|---|---|---|---|"]
    for r in res["dimer"]:
        md.append("| %d | %.4f | %.5f | %.5f | %.5e | %.5e | %.5f | %.5e |" % (
            r["deg"], r["m_loc_over_M"], r["e_none"], r["e_none_closed"], r["tc_none"], r["tc_none_closed"],
            r["e_local"], r["tc_local"]))
    md += ["", "## Continuity: row of 4 spheres, slightly tilted, contacts close one after another (dt = t_c/1000)",
           "", "Largest step-to-step change of the wall force (without the first touch and the release) over the "
           "largest force.", "", "| tilt (mrad) | one sphere | none | count | overlap |", "|---|---|---|---|---|"]
    for r in res["continuity"]:
        md.append("| %g | %.4f | %.4f | %.4f | %.4f |" % (r["mrad"], r["single"], r["none"], r["count"], r["overlap"]))
    md += ["", "`none`: each new contact adds its damping force gamma v at once (a step of the law itself); `count`: "
           "the force drops by about F/N_c when a contact closes; `overlap`: of the order of one sphere's smooth change."]
    with open(os.path.join(RES, "correction_lammps.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    spc_max = max(r["spc"] for r in res["flat"])
    for mode in LMP_CORR_MODES:
        rr = [r for r in res["flat"] if r["mode"] == mode and r["spc"] == spc_max]
        ax[0].plot([r["n"] for r in rr], [r["e"] for r in rr], "o-", label=mode)
    ns = [1, 2, 4, 8]
    ax[0].plot(ns, [closed_form_n(E, TC, n)[0] for n in ns], "k--", label="N-contact closed form")
    ax[0].set_xlabel("N spheres on the wall"); ax[0].set_ylabel("e"); ax[0].legend(fontsize=7); ax[0].grid(alpha=0.3)
    ax[1].plot([r["deg"] for r in res["dimer"]], [r["e_none"] for r in res["dimer"]], "o-", label="none")
    ax[1].plot([r["deg"] for r in res["dimer"]], [r["e_none_closed"] for r in res["dimer"]], "k--",
               label="closed form, N = M/m_loc")
    ax[1].plot([r["deg"] for r in res["dimer"]], [r["e_local"] for r in res["dimer"]], "s-", label="local_mass")
    ax[1].axhline(E, color="grey", lw=0.8)
    ax[1].set_xlabel("dimer tilt (deg)"); ax[1].set_ylabel("contact-point e"); ax[1].legend(fontsize=7)
    ax[1].grid(alpha=0.3)
    fig.tight_layout(); fig.savefig(os.path.join(RES, "correction_lammps.png"), dpi=110); plt.close(fig)


def main():
    a = args_of(sys.argv)
    exe = a["lammps"]
    parts = a["parts"].split(",")
    if "correction_lammps" in parts:  # LAMMPS: multiple-contact correction (own result files)
        lmp_corr_write(lmp_corr_study(exe, a["quick"]), a["quick"])
        parts.remove("correction_lammps")
        if not parts:
            return
    flat = part_flat(exe, a["quick"]) if "flat" in parts else None
    tilt, conv = part_tilted(exe, a["quick"]) if "tilted" in parts else (None, None)
    rig = part_rigid(exe, a["quick"], a["mpirun"]) if "rigid" in parts else None
    os.makedirs(RES, exist_ok=True)
    with open(os.path.join(RES, "results.json"), "w") as f:
        json.dump(dict(flat=flat, tilted=tilt, tilted_convergence=conv, rigid=rig), f, indent=1, default=float)
    write_results(flat, tilt, conv, rig, a["quick"])
    print("results in", RES)


# ====================================================================== LIGGGHTS section (issue 6)
# The multiple-contact correction of fix tdem/clump in LIGGGHTS (docs/liggghts/fix_tdem_clump.md):
#   study.py --liggghts PATH/tdem-liggghts
# writes results/liggghts_correction.md, .json and .png. Self-contained (its own inputs and closed forms):
#   flat     rods of N = 1, 2, 4, 8 spheres flat on a tdem/lsd wall, per-contact k, gamma from the BODY mass for
#            (e, t_c): none -> the N-contact closed form, count and overlap -> the single contact
#   tilted   the same rod of 4 tilted by 0..4e-4 rad (contacts close one after another), e = 1: largest
#            step-to-step change of the body's normal force, count vs overlap
#   local    a dimer hitting the wall at 10..80 deg, frictionless, tdem/lsd parameters restitution: the
#            contact point's normal e with local_mass (= the law's e) and none (= closed form on m_loc)
#   stock    flat rods with the stock `model hertz tangential history`: the correction (through the surface
#            model tdem/clump, any model) against a one-contact ODE of LIGGGHTS's hertz law
# A correction needs `surface tdem/clump` in the pair style and the wall (added by lig_scene).
LIG_HEAD = """atom_style hybrid sphere molecular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
"""
LIG_R, LIG_RHO, LIG_DIST, LIG_E, LIG_TC, LIG_V = 0.005, 2500.0, 0.0125, 0.8, 1e-4, 1.0


def lig_rates(e, tc):
    lne = math.log(e)
    beta = -lne / math.sqrt(math.pi ** 2 + lne ** 2)
    w0 = math.pi / (tc * math.sqrt(1 - beta * beta))
    return w0 * w0, 2 * beta * w0


def lig_outcome(k, gamma, m):
    w0 = math.sqrt(k / m)
    beta = gamma / (2.0 * math.sqrt(k * m))
    return math.exp(-math.pi * beta / math.sqrt(1 - beta * beta)), math.pi / (w0 * math.sqrt(1 - beta * beta))


def lig_scene(n, dist, k, gamma, dt, steps, corr, tilt=0.0, restitution=None, hertz=None):
    r, gap = LIG_R, 2e-6
    shape = "single %g 0" % r if n == 1 else ("dimer %g %g" % (r, dist) if n == 2 else "rod %g %g %d" % (r, dist, n))
    zc = r + gap + 0.5 * (n - 1) * dist * math.sin(abs(tilt))
    L = [LIG_HEAD, "region b block -0.1 0.1 -0.05 0.05 -0.05 0.05 units box", "create_box 1 b",
         "neighbor 0.001 bin", "neigh_modify delay 0 exclude molecule all"]
    for i in range(n):
        s = (i - 0.5 * (n - 1)) * dist
        L.append("create_atoms 1 single %.17g 0 %.17g units box" % (s * math.cos(tilt), zc + s * math.sin(tilt)))
    L += ["set group all diameter %.17g density %.17g" % (2 * r, LIG_RHO), "set group all mol 1 vz %.17g" % -LIG_V]
    model = "tdem/lsd tangential no_history"
    if hertz:   # stock LIGGGHTS model hertz tangential history: (E, nu, e)
        model, law = "hertz tangential history", ""
        L += ["fix m_E all property/global youngsModulus peratomtype %.17g" % hertz[0],
              "fix m_nu all property/global poissonsRatio peratomtype %.17g" % hertz[1],
              "fix m_e all property/global coefficientRestitution peratomtypepair 1 %.17g" % hertz[2]]
    elif restitution:
        law = "parameters restitution"
        L += ["fix m_e all property/global coefficientRestitution peratomtypepair 1 %.17g" % restitution[0],
              "fix m_tc all property/global contactTime peratomtypepair 1 %.17g" % restitution[1],
              "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.0"]
    else:
        law = "parameters stiffness absolute_damping on"
        L += ["fix m_kn all property/global kn peratomtypepair 1 %.17g" % k,
              "fix m_kt all property/global kt peratomtypepair 1 %.17g" % k,
              "fix m_gn all property/global gamman_abs peratomtypepair 1 %.17g" % gamma,
              "fix m_gt all property/global gammat_abs peratomtypepair 1 0.0"]
    # the correction acts through the surface model tdem/clump of the pair style and the wall
    surf = " surface tdem/clump" if corr != "none" else ""
    L += ["fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0",
          "pair_style gran model %s%s %s" % (model, surf, law), "pair_coeff * *",
          "timestep %.17g" % dt,
          "fix c all tdem/clump template rod shape %s density %.17g correction %s" % (shape, LIG_RHO, corr),
          "fix w all wall/gran model %s%s primitive type 1 zplane 0.0 %s" % (model, surf, law),
          "dump d all custom 1 dump.lig id z vz fz", "dump_modify d format \"%d %.17g %.17g %.17g\"",
          "thermo_style custom step f_c[1][4] f_c[1][7]", "thermo_modify format float %.17g", "thermo 1",
          "run %d" % steps]
    return "\n".join(L) + "\n"


def lig_run(exe, text):
    wd = tempfile.mkdtemp(prefix="tdem_lig_corr_")
    with open(os.path.join(wd, "in.lig"), "w") as f:
        f.write(text)
    p = subprocess.run([exe, "-in", "in.lig", "-log", "log.lig", "-echo", "none", "-screen", "none"], cwd=wd,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise SystemExit("study.py: tdem-liggghts failed in %s:\n%s" % (wd, p.stdout[-2000:]))
    frames, cur = [], None
    with open(os.path.join(wd, "dump.lig")) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1]); n = int(lines[i + 3]); i += 9
            a = np.array([[float(x) for x in lines[i + j].split()] for j in range(n)])
            frames.append((step, a[np.argsort(a[:, 0])])); i += n
        else:
            i += 1
    return frames


def lig_flat(exe):
    kpm, gpm = lig_rates(LIG_E, LIG_TC)
    rows = []
    for n in (1, 2, 4, 8):
        M = n * 4.0 / 3.0 * math.pi * LIG_R ** 3 * LIG_RHO
        k, g = M * kpm, M * gpm
        for corr in ("none", "count", "overlap"):
            e_ref, t_ref = lig_outcome(n * k, n * g, M) if corr == "none" else lig_outcome(k, g, M)
            dt = LIG_TC / 4000.0
            fr = lig_run(exe, lig_scene(n, LIG_DIST, k, g, dt, int((2e-6 + 1.6 * LIG_TC) / dt), corr))
            t = np.array([s for s, _ in fr]) * dt
            xi = LIG_R - np.array([a[:, 1].min() for _, a in fr])
            vz = np.array([a[:, 2].mean() for _, a in fr])
            ins = np.where(xi > 0)[0]
            a0, b0 = ins[0], ins[-1]
            tin = t[a0 - 1] + (t[a0] - t[a0 - 1]) * (-xi[a0 - 1]) / (xi[a0] - xi[a0 - 1])
            tout = t[b0] + (t[b0 + 1] - t[b0]) * (-xi[b0]) / (xi[b0 + 1] - xi[b0])
            rows.append(dict(n=n, corr=corr, e=vz[-1] / LIG_V, tc=tout - tin, e_ref=e_ref, tc_ref=t_ref))
    return rows


def lig_tilted(exe):
    n = 4
    M = n * 4.0 / 3.0 * math.pi * LIG_R ** 3 * LIG_RHO
    k = M * lig_rates(1.0, LIG_TC)[0]
    dt = LIG_TC / 4000.0
    rows, series = [], {}
    for tilt in (0.0, 1e-4, 2e-4, 4e-4):
        for corr in ("count", "overlap"):
            fr = lig_run(exe, lig_scene(n, LIG_DIST, k, 0.0, dt, int((2e-6 + 2.2 * LIG_TC) / dt), corr, tilt=tilt))
            F = np.array([a[:, 3].sum() for _, a in fr])
            t = np.array([s for s, _ in fr]) * dt
            rows.append(dict(tilt=tilt, corr=corr, djump=float(np.abs(np.diff(F)).max()), fmax=float(F.max()),
                             e=float(np.mean(fr[-1][1][:, 2]) / LIG_V), bound=k * LIG_V * dt))
            if tilt == 2e-4:
                series[corr] = (t, F)
    return rows, series


def lig_local(exe):
    dist, tc = 2.5 * LIG_R, 2e-5
    m = 4.0 / 3.0 * math.pi * LIG_R ** 3 * LIG_RHO
    I_perp = 2 * (0.4 * m * LIG_R ** 2 + m * (0.5 * dist) ** 2)
    kpm, gpm = lig_rates(LIG_E, tc)
    rows = []
    for deg in (10, 30, 50, 70, 80):
        th = math.radians(deg)
        arm = 0.5 * dist * math.cos(th)
        mloc = 1.0 / (1.0 / (2 * m) + arm * arm / I_perp)
        e_none_ref = lig_outcome(m * kpm, m * gpm, mloc)[0]
        out = {}
        dt = tc / 4000.0
        for corr in ("local_mass", "none"):
            fr = lig_run(exe, lig_scene(2, dist, 0, 0, dt, int((2e-6 + 2.0 * tc) / dt), corr, tilt=th,
                                        restitution=(LIG_E, tc)))
            z = np.array([a[0, 1] for _, a in fr]); vz = np.array([a[0, 2] for _, a in fr])
            first = np.where(LIG_R - z > 0)[0][0]
            end = first + np.where(LIG_R - z[first:] <= 0)[0][0]   # first step after the first contact
            out[corr] = -vz[end] / vz[first - 1]
        rows.append(dict(deg=deg, mloc_over_msphere=mloc / m, e_local=out["local_mass"], e_none=out["none"],
                         e_none_ref=e_none_ref, e_law=LIG_E))
    return rows


def lig_stock(exe):
    """stock `model hertz tangential history` (+ surface tdem/clump), flat rods on the wall, e_in = 0.8."""
    E, nu, e_in = 5e7, 0.3, 0.8
    m = 4.0 / 3.0 * math.pi * LIG_R ** 3 * LIG_RHO
    rows = []
    for n in (1, 2, 4, 8):
        M = n * m
        tc1 = hertz_wall_ode(E, nu, LIG_R, 1.0 - 1e-12, M, m, LIG_V)[1]
        dt = tc1 / 4000.0
        for corr in ("none", "count", "overlap"):
            mass = m if corr == "none" else M
            e_ref, t_ref = hertz_wall_ode(E, nu, LIG_R, e_in, mass, m, LIG_V)
            fr = lig_run(exe, lig_scene(n, LIG_DIST, 0, 0, dt, int((2e-6 + 1.3 * tc1) / dt), corr, hertz=(E, nu, e_in)))
            t = np.array([s for s, _ in fr]) * dt
            xi = LIG_R - np.array([a[:, 1].min() for _, a in fr])
            vz = np.array([a[:, 2].mean() for _, a in fr])
            ins = np.where(xi > 0)[0]
            a0, b0 = ins[0], ins[-1]
            tin = t[a0 - 1] + (t[a0] - t[a0 - 1]) * (-xi[a0 - 1]) / (xi[a0] - xi[a0 - 1])
            tout = t[b0] + (t[b0 + 1] - t[b0]) * (-xi[b0]) / (xi[b0 + 1] - xi[b0])
            rows.append(dict(n=n, corr=corr, e=vz[-1] / LIG_V, tc=tout - tin, e_ref=e_ref, tc_ref=t_ref))
    return rows


def liggghts_correction_main(argv):
    a = args_of(argv)
    exe = os.path.abspath(a["liggghts"])
    flat = lig_flat(exe)
    tilted, series = lig_tilted(exe)
    local = lig_local(exe)
    stock = lig_stock(exe)
    os.makedirs(RES, exist_ok=True)
    with open(os.path.join(RES, "liggghts_correction.json"), "w") as f:
        json.dump(dict(flat=flat, tilted=tilted, local=local, stock=stock), f, indent=1, default=float)
    md = ["# LIGGGHTS fix tdem/clump: multiple-contact correction (study.py --liggghts)", "",
          "## Flat rods on a wall (tdem/lsd, k and gamma per contact from the body mass for e = 0.8, t_c = 1e-4 s)", "",
          "| N | correction | e | reference | t_c (s) | reference | rel. error e, t_c |", "|---|---|---|---|---|---|---|"]
    for r in flat:
        md.append("| %d | %s | %.6f | %.6f | %.6e | %.6e | %.1e, %.1e |" % (
            r["n"], r["corr"], r["e"], r["e_ref"], r["tc"], r["tc_ref"], r["e"] / r["e_ref"] - 1, r["tc"] / r["tc_ref"] - 1))
    md += ["", "Reference: none = N parallel contacts (N k, N gamma on M); count, overlap = one contact.", "",
           "## Tilted rod of 4 (e = 1): largest step-to-step change of the body's normal force", "",
           "| tilt (rad) | correction | max abs dF per step (N) | k v0 dt (N) | max F (N) | e of the com |",
           "|---|---|---|---|---|---|"]
    for r in tilted:
        md.append("| %g | %s | %.4g | %.4g | %.4g | %.5f |" % (r["tilt"], r["corr"], r["djump"], r["bound"], r["fmax"], r["e"]))
    md += ["", "k v0 dt: the change per step of one contact of stiffness k at the approach speed v0 (the flat rod: "
           "both modes give exactly that). count jumps by about F/(N_c + 1) when a contact closes; overlap stays "
           "within 1.3 k v0 dt. e of the com: vz after/before of the centre of mass only (the tilted rod leaves "
           "spinning, so < 1 without damping; count's jumps are not conservative and give slightly > 1)."]
    md += ["", "## Dimer (d = 2.5 r) at an angle, frictionless, tdem/lsd parameters restitution (e = 0.8, t_c = 2e-5 s)", "",
           "Contact-point normal restitution (the lower sphere's vz after/before).", "",
           "| angle (deg) | m_loc / m_sphere | local_mass | none | none, closed form on m_loc |", "|---|---|---|---|---|"]
    for r in local:
        md.append("| %d | %.4f | %.6f | %.6f | %.6f |" % (r["deg"], r["mloc_over_msphere"], r["e_local"], r["e_none"], r["e_none_ref"]))
    md += ["", "## Stock `model hertz tangential history` + `surface tdem/clump`: flat rods on the wall "
           "(E = 5e7 Pa, nu = 0.3, e_in = 0.8)", "",
           "The surface model scales the whole output of any model. Reference: one hertz contact with LIGGGHTS's "
           "damping on m* = the sphere mass (what LIGGGHTS passes for a clump sphere), integrated by RK4, moving "
           "the sphere mass (none: N contacts on N sphere masses) or the body mass (count, overlap).", "",
           "| N | correction | e | reference | t_c (s) | reference | rel. error e, t_c |", "|---|---|---|---|---|---|---|"]
    for r in stock:
        md.append("| %d | %s | %.6f | %.6f | %.6e | %.6e | %.1e, %.1e |" % (
            r["n"], r["corr"], r["e"], r["e_ref"], r["tc"], r["tc_ref"], r["e"] / r["e_ref"] - 1, r["tc"] / r["tc_ref"] - 1))
    md += ["", "With a damping derived from m* = the sphere share, count/overlap give the e of one contact whose "
           "damping belongs to the sphere mass acting on the body mass (not e_in); without correction a flat face of "
           "equal spheres already behaves as one sphere (e_in). t_c with count/overlap is that of one contact on the "
           "body mass."]
    with open(os.path.join(RES, "liggghts_correction.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        for c, (t, F) in series.items():
            ax.plot(t * 1e3, F, label="correction " + c)
        ax.set_xlabel("t (ms)"); ax.set_ylabel("normal force on the body (N)")
        ax.set_title("rod of 4 tilted by 2e-4 rad on a wall (e = 1)"); ax.legend(); ax.grid(alpha=0.3)
        fig.tight_layout(); fig.savefig(os.path.join(RES, "liggghts_correction_force.png"), dpi=110); plt.close(fig)
    except ImportError:
        pass
    print("results in", os.path.join(RES, "liggghts_correction.md"))


if __name__ == "__main__":
    if "--liggghts" in sys.argv:
        liggghts_correction_main(sys.argv)
    else:
        main()
