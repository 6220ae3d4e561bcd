#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Stability suite (issue 8), LAMMPS side: hard cases under tdem-lammps, tdem's laws and, where the
case makes sense, the stock law side by side. One case per ctest: `--case NAME`.

Every case asserts: no NaN/inf, no lost atoms (thermo `atoms` with `thermo_modify lost warn`), no
energy gain of a dissipative law without external work (kinetic + rotational + gravity potential
energy outside contacts, or with the elastic energy of a linear spring), results finite and within
their physical bound (0 <= e <= 1, Coulomb bound, no attraction where the law forbids it).
Expected values are closed forms (tests/host/stability_ref.py) or physical bounds.

Cases (see CASES at the end):
  dt_0p9_critical_linear_stable_0p5_no_energy_gain       velocity Verlet at 0.9 dt_c of the linear law
  stiff_200gpa_hertz_impacts_0p001_and_100_mps_bounded
  soft_1mpa_hertz_impacts_0p001_and_1_mps_bounded
  grazing_89deg_tangential_no_energy_gain_coulomb_bound
  mass_ratio_1_1000_head_on_momentum_and_e
  dense_bed_at_rest_1e5_steps_no_creep
  walton_braun_repeated_loading_no_gain_no_attraction
  thornton_repeated_loading_no_gain_no_attraction
  power_law_repeated_loading_no_gain_no_attraction
  extended_laws_v0_1e-4_and_v_max_e_in_0_1
  rank_crossing_in_contact_np2_equals_np1
  clump_8_simultaneous_contacts_no_energy_gain  cube8 / 2x4 plate flat on a wall (N = 4, 8 vs closed form),
                                                cube8 on a fixed bed (16 contacts), cube8 on cube8 (9)
  clump_pile_at_rest_no_creep                   40 tetra clumps settled, 3e4 steps at rest
  grate_stopped_bed_at_rest_pprime_zero         P' of a bed on a stopped grate: exact rest and settled
  grate_moving_bars_energy_bounded              E <= E0 + work of the bars, speeds bounded, outlet only
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import lmp_common as lc  # noqa: E402
import stability_ref as S  # noqa: E402

args = lc.parse_args(sys.argv)
CASE = args.get("case")
GC = args.get("grid-correction") == "on"
chk = lc.Checker("lammps.stability%s." % ("_gc" if GC else "") + str(CASE))

if GC:
    # --grid-correction on: every tdem law of the case with `grid_correction on` (issue 22: the
    # whole suite with the correction)
    _run = lc.run

    def _with_gc(line):
        w = line.split()
        if len(w) > 2 and w[0] == "pair_coeff" and "normal" in w:
            return line + " grid_correction on"
        if "tdem/wall/gran" in w and "normal" in w:
            for k, x in enumerate(w):
                if x in ("xplane", "yplane", "zplane", "zcylinder"):
                    return " ".join(w[:k] + ["grid_correction", "on"] + w[k:])
        return line

    GC_LINES = [0]

    def _run_gc(exe, text, *a, **kw):
        lines = [_with_gc(l) for l in text.split("\n")]
        GC_LINES[0] += sum(1 for l in lines if "grid_correction on" in l)
        return _run(exe, "\n".join(lines), *a, **kw)

    lc.run = _run_gc

COLS = "id type mass radius x y z vx vy vz fx fy fz omegax omegay omegaz"


def scene(atoms, inter, dt, nsteps, every=1, box=(-0.1, 0.1, -0.1, 0.1, -0.01, 0.1), ntypes=1,
          gravity=0.0, mobile=None, processors="", newton="off", skin=0.001, extra="",
          boundary="f f f", tail=""):
    """atoms: dicts with type x y z vx vy vz d rho [wx wy wz]; inter: pair style and wall lines.
    mobile: atom ids that are integrated (default all). Dumps every `every` steps to dump.stab."""
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary " + boundary,
             "newton " + newton, "comm_modify vel yes", processors,
             "region box block %r %r %r %r %r %r units box" % box, "create_box %d box" % ntypes]
    for a in atoms:
        lines.append("create_atoms %d single %r %r %r units box" % (a.get("type", 1), a["x"], a["y"], a["z"]))
    for k, a in enumerate(atoms, 1):
        lines.append("set atom %d diameter %r density %r" % (k, a["d"], a["rho"]))
        lines.append("set atom %d vx %r vy %r vz %r omega %r %r %r" % (
            k, a.get("vx", 0.0), a.get("vy", 0.0), a.get("vz", 0.0),
            a.get("wx", 0.0), a.get("wy", 0.0), a.get("wz", 0.0)))
    if mobile is None:
        lines.append("group mobile union all")
    else:
        lines.append("group mobile id " + " ".join(str(i) for i in mobile))
    lines += ["neighbor %r bin" % skin, "neigh_modify delay 0 every 1 check yes", inter]
    if gravity:
        lines.append("fix g mobile gravity %r vector 0 0 -1" % gravity)
    lines += ["fix nve mobile nve/sphere", "timestep %r" % dt, extra,
              "dump d all custom %d dump.stab %s" % (every, COLS),
              "dump_modify d sort id format float %.17g",
              "thermo_style custom step atoms ke", "thermo_modify lost warn format float %.17g",
              "thermo %d" % max(1, nsteps // 20), "run %d" % nsteps, tail]
    return "\n".join(lines) + "\n"


def read_frames(path, natoms):
    return S.read_frames(path, natoms, COLS.split())


def run_scene(tag, text, natoms, np_=1, name="in.stab", wd=None):
    wd = wd or lc.workdir(tag)
    _, out = lc.run(args["tdem"], text, wd, name, np_=np_, mpirun=args.get("mpirun") or "mpirun")
    steps, fr, bad = read_frames(os.path.join(wd, "dump.stab"), natoms)
    return steps, fr, bad, out


def atoms_in_thermo(out):
    counts = []
    for row in lc.thermo_blocks(out):
        s = row.split()
        if s[0] != "Step":
            counts.append(int(float(s[1])))
    return counts


def basic_checks(tag, fr, bad, out, natoms):
    """no NaN, no lost atoms (dump frames and thermo atoms column)."""
    finite = all(np.all(np.isfinite(v)) for v in fr.values())
    chk.check(finite, "%s: every position, velocity, force and spin is finite" % tag)
    counts = atoms_in_thermo(out)
    ok = bad == 0 and counts and all(c == natoms for c in counts) and "Lost atoms" not in out
    chk.check(ok, "%s: no lost atoms (thermo atoms %s, expected %d)" % (
        tag, sorted(set(counts)), natoms))


kinetic = S.kinetic


# ------------------------------------------------------------------------------------------
# time step at 0.9 of the critical value of velocity Verlet on the linear law
R5, RHO = 0.005, 2500.0
M5 = S.sphere_mass(2 * R5, RHO)
KN, GN = 1.0e4, 400.0   # stiffness [N/m], mass-proportional damping [1/s] (gamma = m* GN)


def case_dt_critical():
    """Linear law (k, gamma = m* GN), velocity Verlet. dt_c = 2/omega (sqrt(1 + zeta^2) - zeta)
    from k, gamma, m*, confirmed by the spectral radius of the step matrix (stability_ref).
    At 0.9 dt_c: a lasting contact (sphere resting on the floor under gravity) decays to the static
    overlap m g/k without energy gain; impacts stay finite and their e equals, phase by phase, an
    independent velocity-Verlet model of the same contact (the scheme itself gives e > 1 for some
    phases of the touch on the step grid at this step, in tdem and in the stock style alike).
    At 0.5 dt_c every phase has 0 <= e <= 1: no energy gain. At 1.1 dt_c (control) the lasting
    contact grows."""
    dtc_wall, om, zeta = S.dt_critical_verlet(KN, GN * M5, M5)
    dtc_pair, om2, zeta2 = S.dt_critical_verlet(KN, GN * M5 / 2, M5 / 2)
    print("dt_c (velocity Verlet, linear law): wall %.6e s (omega %.1f, zeta %.4f), pair %.6e s"
          % (dtc_wall, om, zeta, dtc_pair))
    for f, stable in ((0.5, True), (0.9, True), (1.1, False)):
        rho_w = S.spectral_radius(S.verlet_step_matrix(KN, GN * M5, M5, f * dtc_wall))
        rho_p = S.spectral_radius(S.verlet_step_matrix(KN, GN * M5 / 2, M5 / 2, f * dtc_pair))
        chk.check((max(rho_w, rho_p) < 1) == stable,
                  "closed form: step matrix spectral radius at %.1f dt_c: wall %.4f, pair %.4f (%s)"
                  % (f, rho_w, rho_p, "stable" if stable else "unstable"))
    laws = {
        "tdem lsd": "normal lsd stiffness %r %r tangential cundall_strack %r 0 0.5" % (KN, GN, KN / 2),
        "stock gran/hooke/history": None,
    }
    v0, nph = 0.5, 8
    box = (-0.1, 0.1, -0.1, 0.1, -0.01, 3.0)
    for lawname, law in laws.items():
        if law:
            inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL" % (law, law)
        else:
            arg = "%r %r %r 0 0.5 1" % (KN, KN / 2, GN)
            inter = ("pair_style gran/hooke/history %s\npair_coeff * *\n"
                     "fix floor all wall/gran hooke/history %s zplane 0 NULL" % (arg, arg))
        for frac in (0.9, 0.5, 1.1):
            # run 1 (dt = frac dt_c of the wall contact): wall impacts at 8 phases of the touch on
            # the step grid and a sphere resting on the floor under gravity (starts at touch, v = 0);
            # run 2 (dt = frac dt_c of the pair contact, m* = m/2): head-on pairs at 8 phases
            for geo in ("wall", "pair"):
                dt = frac * (dtc_wall if geo == "wall" else dtc_pair)
                meff = M5 if geo == "wall" else M5 / 2
                atoms = []
                for k in range(nph):
                    gap = (3 + (k + 0.5) / nph) * v0 * dt
                    if geo == "wall":
                        atoms.append(dict(x=-0.09 + 0.011 * k, y=-0.05, z=R5 + gap, vz=-v0, d=2 * R5, rho=RHO))
                    else:
                        yk = -0.08 + 0.02 * k
                        atoms.append(dict(x=-R5 - gap / 2, y=yk, z=0.05, vx=v0 / 2, d=2 * R5, rho=RHO))
                        atoms.append(dict(x=R5 + gap / 2, y=yk, z=0.05, vx=-v0 / 2, d=2 * R5, rho=RHO))
                if geo == "wall":
                    atoms.append(dict(x=0.0, y=0.05, z=R5, d=2 * R5, rho=RHO))   # resting
                n = len(atoms)
                extra = ("group rest id %d\nfix g rest gravity 9.81 vector 0 0 -1" % n) if geo == "wall" else ""
                nsteps = 1000 if geo == "wall" else 100
                text = scene(atoms, inter, dt, nsteps, every=1 if geo == "wall" else nsteps, box=box, extra=extra)
                tag = "%s %.1f dt_c %s" % (lawname, frac, geo)
                steps, fr, bad, out = run_scene("dtc", text, n)
                if frac < 1:
                    basic_checks(tag, fr, bad, out, n)
                if geo == "wall":
                    e = fr["vz"][-1, :nph] / v0
                    ke0 = 0.5 * M5 * v0 ** 2 * nph
                    ke1 = float(np.sum(kinetic(fr)[-1, :nph]))
                else:
                    vx = fr["vx"][-1]
                    e = (vx[1::2] - vx[0::2]) / v0
                    ke0 = 0.5 * M5 * (v0 / 2) ** 2 * 2 * nph
                    ke1 = float(np.sum(kinetic(fr)[-1]))
                model = np.array([S.verlet_impact_e(KN, GN * meff, meff, v0, dt, 3 + (k + 0.5) / nph) for k in range(nph)])
                dev = float(np.max(np.abs(e - model)))
                print("%s: e over %d phases: %s (independent Verlet model: %s, max |diff| %.2e); KE %.6e -> %.6e"
                      % (tag, nph, " ".join("%.4f" % x for x in e), " ".join("%.4f" % x for x in model), dev, ke0, ke1))
                if frac < 1:
                    chk.check(dev < 1e-9, "%s: impact e equals the independent velocity-Verlet model at every phase" % tag)
                if frac == 0.5:
                    chk.check(bool(np.all((e >= 0) & (e <= 1))) and ke1 <= ke0,
                              "%s: 0 <= e <= 1 at every phase, no kinetic energy gain (e %.4f..%.4f)" % (tag, e.min(), e.max()))
                if geo == "wall":
                    z = fr["z"][:, nph]
                    xi = np.maximum(R5 - z, 0.0)
                    etot = kinetic(fr)[:, nph] + M5 * 9.81 * z + 0.5 * KN * xi ** 2
                    amp = np.abs(xi - M5 * 9.81 / KN)
                    n4 = len(amp) // 4
                    a_first, a_last = amp[:n4].max(), amp[-n4:].max()
                    print("%s: resting sphere: amplitude first quarter %.3e m, last quarter %.3e m, energy %.9e -> %.9e J"
                          % (tag, a_first, a_last, etot[0], etot[-1]))
                    if frac < 1:
                        chk.check(a_last < 1e-6 * a_first,
                                  "%s: lasting contact decays (amplitude last/first quarter %.2e < 1e-6)" % (tag, a_last / a_first))
                        chk.check(etot[-1] <= etot[0] and abs(z[-1] - (R5 - M5 * 9.81 / KN)) < 1e-12,
                                  "%s: no energy gain, rests at the static overlap m g/k (%.9e vs %.9e m)"
                                  % (tag, R5 - z[-1], M5 * 9.81 / KN))
                    else:
                        chk.check(a_last > a_first or not np.all(np.isfinite(z)),
                                  "%s: control: beyond dt_c the lasting contact grows (the check can fail)" % tag)


# ------------------------------------------------------------------------------------------
def hertz_impacts(tag, young, rho, d, speeds, nu=0.3, e_tsuji=0.9, steps_per_contact=100):
    """Sphere-wall and head-on impacts with tdem hertz (undamped and Tsuji e) and stock
    pair granular hertz/material (Tsuji damping) at each speed; dt = t_c / steps_per_contact from
    the closed-form undamped Hertz contact time of the pair (the shorter one)."""
    m = S.sphere_mass(d, rho)
    R = d / 2
    es = S.estar(young, nu)
    kt_w = S.hertz_ktilde(es, R)          # wall of the same material, R* = R
    kt_p = S.hertz_ktilde(es, R / 2)      # pair, R* = R/2
    for v in speeds:
        tc_w = S.hertz_tc(m, kt_w, v)
        tc_p = S.hertz_tc(m / 2, kt_p, 2 * v)
        xw = S.hertz_ximax(m, kt_w, v)
        dt = min(tc_w, tc_p) / steps_per_contact
        print("%s v0 %g m/s: Hertz t_c wall %.4e s, pair %.4e s, xi_max/R wall %.3e; dt %.4e s"
              % (tag, v, tc_w, tc_p, xw / R, dt))
        nsteps = int(1.5 * max(tc_w, tc_p) / dt) + 20
        laws = [
            ("tdem hertz undamped", "normal hertz %r %r tangential cundall_strack 0.8 0.5" % (young, nu), 1.0),
            ("tdem hertz tsuji", "normal hertz %r %r damping tsuji %r tangential cundall_strack 0.8 0.5 limit_force yes"
             % (young, nu, e_tsuji), e_tsuji),
            ("stock granular hertz/material tsuji", None, None),
        ]
        for lawname, law, e_exp in laws:
            atoms = [dict(x=0.0, y=0.0, z=R + 5 * v * dt, vz=-v, d=d, rho=rho),
                     dict(x=-R - 5 * v * dt, y=0.0, z=0.5 * (0.1 + R), vx=v, d=d, rho=rho),
                     dict(x=R + 5 * v * dt, y=0.0, z=0.5 * (0.1 + R), vx=-v, d=d, rho=rho)]
            if law:
                inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL" % (law, law)
            else:
                g = "hertz/material %r %r %r tangential linear_nohistory 0 0.5 damping tsuji" % (young, e_tsuji, nu)
                inter = "pair_style granular\npair_coeff * * %s\nfix floor all wall/gran granular %s zplane 0 NULL" % (g, g)
            box = (-0.1, 0.1, -0.1, 0.1, -0.01, 0.1)
            text = scene(atoms, inter, dt, nsteps, every=nsteps, box=box, skin=max(2 * v * dt * 5, 1e-6))
            t = "%s %s v0 %g" % (tag, lawname, v)
            steps, fr, bad, out = run_scene("hz", text, 3)
            basic_checks(t, fr, bad, out, 3)
            e_w = fr["vz"][-1, 0] / v
            e_p = (fr["vx"][-1, 2] - fr["vx"][-1, 1]) / (2 * v)
            ke0 = 1.5 * m * v * v
            ke1 = float(np.sum(kinetic(fr)[-1]))
            print("%s: e wall %.6f, pair %.6f (expected %s), kinetic energy %.6e -> %.6e"
                  % (t, e_w, e_p, "%.3f" % e_exp if e_exp else "in [0, 1]", ke0, ke1))
            if e_exp == 1.0:
                # conservative law: energy kept to the time discretisation (100 steps per contact)
                chk.check(abs(ke1 / ke0 - 1) <= 2e-3, "%s: conservative law keeps the kinetic energy within 2e-3 (%.2e)"
                          % (t, ke1 / ke0 - 1))
            else:
                chk.check(0 <= e_w <= 1 and 0 <= e_p <= 1, "%s: 0 <= e <= 1 (wall and pair)" % t)
                chk.check(ke1 <= ke0, "%s: no kinetic energy gain (dissipative law)" % t)
            if e_exp:
                # velocity Verlet at 100 steps per contact: |de| ~ 1/100 for the damped law
                tol = 1e-3 if e_exp == 1.0 else 2e-2
                chk.check(abs(e_w - e_exp) <= tol and abs(e_p - e_exp) <= tol,
                          "%s: e within %.0e of the closed form %.2f" % (t, tol, e_exp))


def case_stiff():
    hertz_impacts("stiff E 200 GPa d 1 mm", 200e9, 7800.0, 1e-3, (0.001, 100.0))


def case_soft():
    # E = 1 MPa, d = 1 mm: at 100 m/s the Hertz overlap would be ~126 R (the sphere passes the
    # wall; outside any contact law), so the fast soft impact is at 1 m/s (xi_max/R ~ 0.2)
    m = S.sphere_mass(1e-3, 1000.0)
    x100 = S.hertz_ximax(m, S.hertz_ktilde(S.estar(1e6, 0.3), 5e-4), 100.0) / 5e-4
    print("soft: a 100 m/s impact would reach xi_max/R = %.1f (not a contact); using 1 m/s" % x100)
    hertz_impacts("soft E 1 MPa d 1 mm", 1e6, 1000.0, 1e-3, (0.001, 1.0))


# ------------------------------------------------------------------------------------------
def case_grazing():
    ang = math.radians(89.0)
    v = 1.0
    vn, vt = v * math.cos(ang), v * math.sin(ang)
    mu = 0.3
    laws = [
        ("tdem lsd + cundall_strack", "normal lsd restitution 0.8 1e-3 tangential cundall_strack 0.8 %r limit_force yes" % mu),
        ("tdem hertz tsuji + mindlin_deresiewicz",
         "normal hertz 1e7 0.3 damping tsuji 0.8 tangential mindlin_deresiewicz 1e7 0.3 %r limit_force yes" % mu),
        ("tdem walton_braun + walton_braun", "normal walton_braun 1e4 1.5625e4 tangential walton_braun 5000 0.8 %r" % mu),
        ("stock gran/hooke/history", None),
    ]
    tc = 1e-3
    dt = tc / 200
    for lawname, law in laws:
        atoms = [dict(x=-0.05, y=0.0, z=R5 + 5 * vn * dt, vx=vt, vz=-vn, d=2 * R5, rho=RHO),
                 # pair: sphere 3 approaches the resting sphere 2 (not integrated: infinite mass)
                 dict(x=0.0, y=0.05, z=0.05, d=2 * R5, rho=RHO),
                 dict(x=-0.02, y=0.05, z=0.05 + 2 * R5 + 5 * vn * dt, vx=vt, vz=-vn, d=2 * R5, rho=RHO)]
        if law:
            inter = ("pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL"
                     % (law, law))
        else:
            k = M5 * (math.pi / tc) ** 2
            arg = "%r %r %r 0 %r 1 limit_damping" % (k, k * 2 / 7, 2 * 0.0709 * math.sqrt(k / M5), mu)
            inter = ("pair_style gran/hooke/history %s\npair_coeff * *\n"
                     "fix floor all wall/gran hooke/history %s zplane 0 NULL" % (arg, arg))
        nsteps = int(0.04 / dt)
        # sphere 2 is frozen (fix freeze: m* = m of the partner, as for a wall)
        text = scene(atoms, inter, dt, nsteps, every=nsteps, mobile=[1, 3],
                     extra="group nomove id 2\nfix frz nomove freeze")
        tag = "89 deg %s" % lawname
        steps, fr, bad, out = run_scene("graze", text, 3)
        basic_checks(tag, fr, bad, out, 3)
        e_w = fr["vz"][-1, 0] / vn
        dvt = abs(fr["vx"][-1, 0] - vt)
        ke0 = 0.5 * M5 * v * v
        ke1 = float(kinetic(fr)[-1, 0])
        # pair: normal along the line of centres at contact; e from the relative normal velocity
        dx = np.array([fr["x"][-1, 2] - fr["x"][-1, 1], fr["z"][-1, 2] - fr["z"][-1, 1]])
        kp1 = float(kinetic(fr)[-1, 2])
        print("%s: wall e_n %.4f, |dv_t| %.4e (Coulomb bound %.4e), KE %.6e -> %.6e; pair KE %.6e -> %.6e"
              % (tag, e_w, dvt, S.coulomb_impulse_bound(mu, max(e_w, 0), vn), ke0, ke1, ke0, kp1))
        chk.check(0 <= e_w <= 1, "%s: wall 0 <= e_n <= 1" % tag)
        chk.check(dvt <= S.coulomb_impulse_bound(mu, e_w, vn) * (1 + 1e-6),
                  "%s: tangential velocity change within the Coulomb bound mu (1 + e) v_n" % tag)
        chk.check(ke1 <= ke0 and kp1 <= ke0, "%s: no kinetic energy gain (wall and pair, incl. rotation)" % tag)
        chk.check(np.linalg.norm(dx) > 2 * R5, "%s: the pair separated" % tag)


# ------------------------------------------------------------------------------------------
def case_mass_ratio():
    """d = 1 mm against d = 10 mm, same density: mass ratio 1:1000, head-on at 1 m/s."""
    d1, d2 = 1e-3, 1e-2
    m1, m2 = S.sphere_mass(d1, RHO), S.sphere_mass(d2, RHO)
    meff = m1 * m2 / (m1 + m2)
    v = 1.0
    tc = 1e-4
    dt = tc / 1000
    k_st = meff * (math.pi / tc) ** 2
    gn = 2 * 0.0709 * math.pi / tc / math.sqrt(1 - 0.0709 ** 2)
    e_stock = S.lsd_e_zero_overlap(k_st, gn * meff, meff)
    laws = [
        ("tdem lsd restitution 0.8", "normal lsd restitution 0.8 %r tangential cundall_strack 0.8 0.5" % tc, 0.8),
        ("tdem hertz tsuji 0.8", "normal hertz 1e8 0.3 damping tsuji 0.8 tangential cundall_strack 0.8 0.5 limit_force yes", 0.8),
        ("stock gran/hooke/history", None, e_stock),
    ]
    for lawname, law, e_exp in laws:
        atoms = [dict(x=-(d1 / 2) - 5 * v * dt, y=0.0, z=0.05, vx=v, d=d1, rho=RHO),
                 dict(x=d2 / 2, y=0.0, z=0.05, d=d2, rho=RHO)]
        inter = ("pair_style tdem/gran\npair_coeff * * %s" % law if law else
                 "pair_style gran/hooke/history %r %r %r 0 0.5 0\npair_coeff * *" % (k_st, k_st / 2, gn))
        es = S.estar(1e8, 0.3)
        tch = S.hertz_tc(meff, S.hertz_ktilde(es, d1 * d2 / 2 / (d1 + d2)), v)
        steps_n = int(3 * max(tc, tch) / dt) + 20
        text = scene(atoms, inter, dt, steps_n, every=steps_n, skin=5e-4)
        tag = "1:1000 %s" % lawname
        steps, fr, bad, out = run_scene("mass", text, 2)
        basic_checks(tag, fr, bad, out, 2)
        mass = fr["mass"][-1]
        p0 = m1 * v
        p1 = float(np.sum(mass * fr["vx"][-1]))
        e = (fr["vx"][-1, 1] - fr["vx"][-1, 0]) / v
        ke0, ke1 = 0.5 * m1 * v * v, float(np.sum(kinetic(fr)[-1]))
        print("%s: mass ratio %.1f, e %.6f (expected %.6f), momentum %.12e -> %.12e, KE %.6e -> %.6e"
              % (tag, m2 / m1, e, e_exp, p0, p1, ke0, ke1))
        chk.check(abs(p1 - p0) <= 1e-12 * p0, "%s: momentum conserved to round-off" % tag)
        chk.check(0 <= e <= 1 and abs(e - e_exp) <= 5e-3, "%s: e within 5e-3 of the closed form" % tag)
        chk.check(ke1 <= ke0, "%s: no kinetic energy gain" % tag)


# ------------------------------------------------------------------------------------------
BED_D, BED_N = 0.004, 7


def fcc_bed():
    """fcc packing of 172 spheres, d = 4 mm (stability_ref.fcc_points)."""
    return S.fcc_points(BED_D, BED_N)


def bed_energy(fr, kn, L):
    return S.bed_energy(fr, kn, L, BED_D)


def case_dense_bed():
    """An fcc packing (172 spheres) in a box with frictional walls under gravity, left at rest for
    1e5 steps: kinetic energy decays and stays near zero, the total energy (kinetic + gravity +
    elastic energy of the normal springs) never grows, no creep over the last 5e4 steps."""
    pts, L = fcc_bed()
    kn = 2000.0
    law = "normal lsd stiffness %r 50 tangential cundall_strack 600 25 0.5" % kn
    walls = "\n".join("fix w%d all tdem/wall/gran %s %s" % (k, law, w) for k, w in
                      enumerate(("xplane 0 %r" % L, "yplane 0 %r" % L, "zplane 0 NULL")))
    atoms = [dict(x=p[0], y=p[1], z=p[2], d=BED_D, rho=RHO) for p in pts]
    n = len(atoms)
    nsteps, every = 100000, 2000
    text = scene(atoms, "pair_style tdem/gran\npair_coeff * * %s\n%s" % (law, walls), 2e-5, nsteps,
                 every=every, box=(0, L, 0, L, 0, 0.1), gravity=9.81)
    steps, fr, bad, out = run_scene("bed", text, n)
    basic_checks("fcc bed", fr, bad, out, n)
    ke, pe, el = bed_energy(fr, kn, L)
    m = S.sphere_mass(BED_D, RHO)
    e_scale = n * m * 9.81 * BED_D            # weight x one diameter
    etot = ke + pe + el
    half = len(steps) // 2
    disp = np.sqrt((fr["x"][half:] - fr["x"][half]) ** 2 + (fr["y"][half:] - fr["y"][half]) ** 2 +
                   (fr["z"][half:] - fr["z"][half]) ** 2).max()
    # Creep bound: xi_g = m g BED_N / kn (~2.9e-6 m) is the scale of the elastic overlaps under the
    # bed's weight; creep (contacts slipping under load) moves spheres by a growing fraction of it.
    # What remains at rest is a decaying elastic oscillation (the lightly damped rocking modes of
    # the tangential springs). Allowed: 1e-2 xi_g over the last 5e4 steps, and the displacement
    # from the final state must shrink from the third to the last quarter (decay, not drift).
    xi_g = m * 9.81 * BED_N / kn
    dend = np.sqrt((fr["x"] - fr["x"][-1]) ** 2 + (fr["y"] - fr["y"][-1]) ** 2 +
                   (fr["z"] - fr["z"][-1]) ** 2).max(axis=1)
    q = len(steps) // 4
    d3, d4 = dend[2 * q:3 * q].max(), dend[3 * q:-1].max()
    print("fcc bed (%d spheres): KE max %.3e J, end %.3e J (scale N m g d %.3e J), max KE last half %.3e J; "
          "total energy (kinetic + gravity + normal springs) %.12e -> %.12e J, max %.12e J; "
          "max displacement over the last half %.3e m (bound %.3e m), from the final state: third quarter "
          "%.3e m, last quarter %.3e m" % (n, ke.max(), ke[-1], e_scale, ke[half:].max(), etot[0], etot[-1],
                                          etot.max(), disp, 1e-2 * xi_g, d3, d4))
    chk.check(ke[-1] < 1e-7 * ke.max() and ke[3 * q:].max() < ke[2 * q:3 * q].max(),
              "fcc bed: kinetic energy decays (end / max %.1e < 1e-7, last quarter below the third)" % (ke[-1] / ke.max()))
    chk.check(ke[half:].max() < 1e-8 * e_scale, "fcc bed: kinetic energy stays near zero over the last half (< 1e-8 N m g d)")
    chk.check(etot[1:].max() <= etot[0], "fcc bed: no energy gain over the initial state at any time")
    chk.check(disp < 1e-2 * xi_g and d4 < d3, "fcc bed: no creep (max displacement over the last half %.2e m < %.2e m, decaying)"
              % (disp, 1e-2 * xi_g))


# ------------------------------------------------------------------------------------------
HYST = {
    "walton_braun": ("normal walton_braun 1e4 1.5625e4 tangential cundall_strack 0.8 0.5", 0.8),
    "power_law": ("normal power_law 5e5 1.5 %r tangential cundall_strack 0.3 0.5" % (5e5 / 0.7 ** 3), 0.7),
    "thornton": ("normal thornton 1e7 0.3 3e5 tangential cundall_strack 0.8 0.5", None),
}


def case_hysteretic(name):
    """A sphere dropped onto the floor and one onto a fixed sphere (not integrated), bouncing
    until they rest, then a lasting contact: repeated loading/unloading cycles."""
    law, e_free = HYST[name]
    g = 9.81
    h = 0.001
    dt = 2e-6
    nsteps = 150000
    atoms = [dict(x=-0.03, y=0.0, z=R5 + h, d=2 * R5, rho=RHO),
             dict(x=0.03, y=0.0, z=R5, d=2 * R5, rho=RHO),
             dict(x=0.03, y=0.0, z=3 * R5 + h, d=2 * R5, rho=RHO)]
    inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL" % (law, law)
    text = scene(atoms, inter, dt, nsteps, every=2, gravity=g, mobile=[1, 3])
    steps, fr, bad, out = run_scene("hyst_" + name, text, 3)
    basic_checks(name, fr, bad, out, 3)
    es = S.estar(1e7, 0.3)
    for idx, tag, surf in ((0, "wall", R5), (2, "fixed sphere", 3 * R5)):
        z, vz, fz = fr["z"][:, idx], fr["vz"][:, idx], fr["fz"][:, idx]
        m = fr["mass"][0, idx]
        fc = fz + m * g                       # contact force = total force - gravity
        xi = surf - z if tag == "wall" else 2 * R5 - (z - fr["z"][:, 1])
        fmin = float(fc.min())
        chk.check(fmin >= -1e-9 * m * g, "%s %s: contact force never attractive (min %.3e N, weight %.3e N)"
                  % (name, tag, fmin, m * g))
        if name == "thornton":
            # wall: m* = m, R* = R; fixed (not integrated, finite mass) sphere: m* = m/2, R* = R/2
            meff, rstar = (m, R5) if tag == "wall" else (m / 2, R5 / 2)
            e_bound = lambda v, meff=meff, rstar=rstar: S.thornton_e(meff, rstar, es, 3e5, v)
        else:
            e_bound = lambda v: e_free
        S.bounce_checks(chk.check, name, tag, z, vz, fr["omegay"][:, idx], xi, m, R5, g, e_bound,
                        lasting_required=(name != "thornton"))


# ------------------------------------------------------------------------------------------
def case_extended():
    """extended_linear (rational e, power t_c) and extended_hertz (power e) at v0 = 1e-4 m/s
    (below the clamp v_min = 1e-3: the fits are used at v_min) and at the fits' v_max = 5 m/s."""
    c = dict(c0=0.9, c1=1.0, c2=0.5, t0=5e-4, t1=0.2)
    vmax = 5.0
    lin = ("normal extended_linear e_fit rational %r %r %r tc_fit power %r %r v_max %r "
           "tangential cundall_strack 0.3 0.5 limit_force yes" % (c["c0"], c["c1"], c["c2"], c["t0"], c["t1"], vmax))
    hz = ("normal extended_hertz 5e6 0.3 e_fit power 5e-4 0.15 v_max %r tangential cundall_strack 0.3 0.5 "
          "limit_force yes" % vmax)
    for lawname, law in (("extended_linear", lin), ("extended_hertz", hz)):
        for v in (1e-4, vmax):
            vc = min(max(v, 1e-3), vmax)
            if lawname == "extended_linear":
                e_exp = S.rational_fit(c["c0"], c["c1"], c["c2"], vc)
                tc = S.power_tc(c["t0"], c["t1"], vc)
            else:
                e_exp = S.power_efit(5e-4, 0.15, vc)
                tc = min(S.hertz_tc(M5, S.hertz_ktilde(S.estar(5e6, 0.3), R5), v),
                         S.hertz_tc(M5 / 2, S.hertz_ktilde(S.estar(5e6, 0.3), R5 / 2), 2 * v))
            dt = tc / 500
            atoms = [dict(x=0.0, y=0.0, z=R5 + 5 * v * dt, vz=-v, d=2 * R5, rho=RHO),
                     dict(x=-R5 - 5 * v * dt, y=0.0, z=0.05, vx=v, d=2 * R5, rho=RHO),
                     dict(x=R5 + 5 * v * dt, y=0.0, z=0.05, vx=-v, d=2 * R5, rho=RHO)]
            inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL" % (law, law)
            nsteps = 5 * 500 + 40
            text = scene(atoms, inter, dt, nsteps, every=nsteps, skin=max(10 * v * dt, 1e-6))
            tag = "%s v0 %g" % (lawname, v)
            steps, fr, bad, out = run_scene("ext", text, 3)
            basic_checks(tag, fr, bad, out, 3)
            e_w = fr["vz"][-1, 0] / v
            # pair: the relative velocity is 2 v (the fit is evaluated at 2 v, clamped)
            vcp = min(max(2 * v, 1e-3), vmax)
            e_pexp = (S.rational_fit(c["c0"], c["c1"], c["c2"], vcp) if lawname == "extended_linear"
                      else S.power_efit(5e-4, 0.15, vcp))
            e_p = (fr["vx"][-1, 2] - fr["vx"][-1, 1]) / (2 * v)
            print("%s: e wall %.6f (fit %.6f), pair %.6f (fit %.6f)" % (tag, e_w, e_exp, e_p, e_pexp))
            chk.check(0 <= e_w <= 1 and 0 <= e_p <= 1, "%s: e in [0, 1]" % tag)
            chk.check(abs(e_w - e_exp) < 5e-3 and abs(e_p - e_pexp) < 5e-3,
                      "%s: e equals the fit at the clamped v0 within 5e-3" % tag)


# ------------------------------------------------------------------------------------------
def case_rank_crossing():
    """Spheres in contact drift across the processor boundary x = 0 (processors 2 1 1): an oblique
    head-on pair with Thornton, one with Walton-Braun, one with power_law (all with Mindlin-Deresiewicz:
    normal and tangential history; one tangential law per pair style), and a sphere
    sliding and bouncing on the floor (Walton-Braun history in the wall fix); the result of
    -np 2 equals -np 1 to round-off."""
    dt = 2e-6
    drift = 5.0
    v = 0.5
    laws = {
        1: "normal thornton 1e7 0.3 3e5 tangential mindlin_deresiewicz 1e7 0.3 0.3",
        2: "normal walton_braun 1e4 1.5625e4 tangential mindlin_deresiewicz 1e7 0.3 0.3",
        3: "normal power_law 5e5 1.5 %r tangential mindlin_deresiewicz 1e7 0.3 0.3" % (5e5 / 0.7 ** 3),
    }
    atoms = []
    for t in (1, 2, 3):
        y = -0.06 + 0.03 * t
        # the pair touches at step 100; its right atom crosses x = 0 at step 300 (mid-contact)
        x0 = (drift + v) * 300 * dt - R5 - 100 * dt * v
        atoms.append(dict(type=t, x=x0 - R5 - 100 * dt * v, y=y, z=0.05, vx=-drift + v, vy=0.1, d=2 * R5, rho=RHO))
        atoms.append(dict(type=t, x=x0 + R5 + 100 * dt * v, y=y + 0.002, z=0.05, vx=-drift - v, d=2 * R5, rho=RHO))
    atoms.append(dict(type=2, x=-drift * 500 * dt, y=0.06, z=R5 + 100 * dt * v, vx=drift, vz=-v, d=2 * R5, rho=RHO))
    inter = ["pair_style tdem/gran"]
    for t in (1, 2, 3):
        for u in (1, 2, 3):
            if u >= t:
                inter.append("pair_coeff %d %d %s" % (t, u, laws[t] if t == u else laws[2]))
    inter.append("fix floor all tdem/wall/gran %s zplane 0 NULL" % laws[2])
    inter = "\n".join(inter)
    outs = {}
    nsteps = 2500
    for np_ in (1, 2):
        for newton in ("off", "on"):
            text = scene(atoms, inter, dt, nsteps, every=50, ntypes=3, newton=newton,
                         processors="processors 2 1 1" if np_ == 2 else "", box=(-0.1, 0.1, -0.1, 0.1, -0.01, 0.1))
            steps, fr, bad, out = run_scene("np%d_%s" % (np_, newton), text, 7, np_=np_)
            basic_checks("-np %d newton %s" % (np_, newton), fr, bad, out, 7)
            outs[np_, newton] = fr
    fr = outs[1, "off"]
    # the crossing happened during the contacts: x of the right atom of each pair changes sign
    # at a frame where the pair overlaps
    crossed = []
    for p in range(3):
        a, b = 2 * p, 2 * p + 1
        gapv = np.sqrt((fr["x"][:, b] - fr["x"][:, a]) ** 2 + (fr["y"][:, b] - fr["y"][:, a]) ** 2 +
                       (fr["z"][:, b] - fr["z"][:, a]) ** 2) - 2 * R5
        sgn = np.sign(fr["x"][:, b])
        k = np.where(sgn[:-1] != sgn[1:])[0]
        crossed.append(bool(len(k)) and gapv[k[0]] < 0 and gapv[k[0] + 1] < 0)
    sgn = np.sign(fr["x"][:, 6])
    k = np.where(sgn[:-1] != sgn[1:])[0]
    crossed.append(bool(len(k)) and fr["z"][k[0], 6] < R5 and fr["z"][k[0] + 1, 6] < R5)
    chk.check(all(crossed), "every pair and the wall contact cross x = 0 while in contact (%s)" % crossed)
    for newton in ("off", "on"):
        a, b = outs[1, newton], outs[2, newton]
        w = 0.0
        for c in ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz"):
            den = np.maximum(np.abs(a[c]).max(axis=0), 1e-300)
            w = max(w, float((np.abs(a[c] - b[c]) / den).max()))
        print("newton %s: -np 2 vs -np 1 max relative difference over all frames %.3g" % (newton, w))
        chk.check(w <= 1e-10, "newton %s: -np 2 equals -np 1 to round-off (%.3g <= 1e-10)" % (newton, w))
    ke = kinetic(fr).sum(axis=1)
    chk.check(ke[-1] <= ke[0], "no kinetic energy gain over the collisions (%.6e -> %.6e J)" % (ke[0], ke[-1]))


# ------------------------------------------------------------------------------------------
# clumps (issue 6 module `clump`): 8+ simultaneous contacts, a pile at rest
CL_R, CL_D, CL_RHO = 0.002, 0.0045, 2500.0
CL_E, CL_TC = 0.8, 1e-4

CLUMP_HEAD = """units si
atom_style sphere
atom_modify map array
boundary {bnd}
newton off
comm_modify vel yes
region box block {box} units box
create_box 1 box
fix pm all property/atom mol ghost yes
"""


def clump_data(path, bodies, fixed=(), box=(-0.05, 0.05, -0.05, 0.05, -0.01, 0.05)):
    """bodies: list of (points, v); fixed: sphere centres of immobile spheres (mol 0).
    Writes a data file with a Molecules section; returns the number of atoms."""
    rows, vel, mol = [], [], []
    for b, (pts, v) in enumerate(bodies, 1):
        for p in pts:
            rows.append(p)
            vel.append(v)
            mol.append(b)
    for p in fixed:
        rows.append(p)
        vel.append((0.0, 0.0, 0.0))
        mol.append(0)
    n = len(rows)
    L = ["stability clumps", "", "%d atoms" % n, "1 atom types", "",
         "%r %r xlo xhi" % box[0:2], "%r %r ylo yhi" % box[2:4], "%r %r zlo zhi" % box[4:6], "",
         "Atoms # sphere", ""]
    L += ["%d 1 %r %r %r %r %r" % (i + 1, 2 * CL_R, CL_RHO, p[0], p[1], p[2]) for i, p in enumerate(rows)]
    L += ["", "Velocities", ""] + ["%d %r %r %r 0 0 0" % ((i + 1,) + tuple(v)) for i, v in enumerate(vel)]
    L += ["", "Molecules", ""] + ["%d %d" % (i + 1, m) for i, m in enumerate(mol)]
    with open(path, "w") as f:
        f.write("\n".join(L) + "\n")
    return n






def template_file(path, pts):
    c = np.mean(pts, axis=0)
    with open(path, "w") as f:
        f.write("".join("sphere %.17g %.17g %.17g %.17g\n" % (tuple(p - c) + (CL_R,)) for p in pts))






def clump_run(tag, wd, pts_bodies, fixed, inter, dt, nsteps, nbody_rows, every=20, gravity=0.0,
              bnd="f f f", box=(-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), tmpl=None):
    natoms = clump_data(os.path.join(wd, "clump.data"), pts_bodies, fixed, box)
    template_file(os.path.join(wd, "tmpl.txt"), tmpl if tmpl is not None else pts_bodies[0][0])
    nb = sum(len(p) for p, _ in pts_bodies)
    text = CLUMP_HEAD.format(bnd=bnd, box=" ".join(repr(b) for b in box))
    text += "read_data clump.data add append fix pm NULL Molecules\n"
    text += "group body id 1:%d\n" % nb
    text += "neighbor 0.001 bin\nneigh_modify delay 0 every 1 check yes exclude molecule/intra body\n"
    text += inter + "\n"
    text += "fix c body tdem/clump template t file tmpl.txt density %r\n" % CL_RHO
    if gravity:
        text += "fix g body gravity %r vector 0 0 -1\n" % gravity
    text += "timestep %r\n" % dt
    cols = ["f_c", "f_c[8]", "f_c[9]"]
    for b in range(1, nbody_rows + 1):
        cols += ["f_c[%d][%d]" % (b, j) for j in range(2, 8)]
    text += "thermo_style custom step atoms %s\nthermo_modify lost warn format float %%.17g\n" % " ".join(cols)
    text += "thermo %d\n" % every
    text += "dump d all custom %d dump.stab %s\ndump_modify d sort id format float %%.17g\n" % (every, COLS)
    text += "run %d\n" % nsteps
    _, out = lc.run(args["tdem"], text, wd, "in." + tag)
    rows = np.array([[float(x) for x in r.split()] for r in lc.thermo_blocks(out) if r.split()[0] != "Step"])
    steps, fr, bad = read_frames(os.path.join(wd, "dump.stab"), natoms)
    basic_checks(tag, fr, bad, out, natoms)
    chk.check(bool(np.all(np.isfinite(rows))), "%s: every output of fix tdem/clump is finite" % tag)
    return rows, fr, natoms


def case_clump_contacts():
    """A cube8 clump (2 x 2 x 2 spheres) dropped flat onto a wall (4 spheres touch at once: the
    face of a 2x2x2 cube), a 2 x 4 plate clump dropped flat (8 contacts at once), a cube8 dropped
    onto a 3 x 3 bed of fixed spheres (each bottom sphere sits in a pocket of 4: 16 contacts at
    once) and a cube8 onto a free cube8 shifted by (d/2, d/2) (9 contacts between two bodies).
    lsd e = 0.8, t_c = 1e-4 s per contact (m* from the body masses), no gravity, no friction.
    Asserts: no NaN, no lost atoms, kinetic energy (translation + rotation, fix output) after <=
    before, e in [0, 1], sphere distances constant to 1e-12 relative, flat drops: e vs the
    N-contact closed form (physics_reference 6.4) within the step error bounded by an independent
    velocity-Verlet model of the N-fold spring-dashpot."""
    v0 = 1.0
    law = "normal lsd restitution %r %r tangential cundall_strack 0.8 0" % (CL_E, CL_TC)
    M8 = 8 * S.sphere_mass(2 * CL_R, CL_RHO)          # non-overlapping spheres: exact union
    # --- flat drops on a wall: N = 4 (cube8) and N = 8 (plate)
    for name, maker, n in (("cube8 flat on wall", S.cube8, 4), ("plate 2x4 flat on wall", S.plate8, 8)):
        wd = lc.workdir("clump_flat%d" % n)
        k, g = S.lsd_k_gamma(CL_E, CL_TC, M8)
        e_cf, t_n = S.lsd_n_contacts(CL_E, CL_TC, n)
        dt = t_n / 2000.0
        # the body starts exactly 20 steps before the first touch (zc chosen with dt = 2.5e-8)
        pts = maker((0.0, 0.0, (CL_R if maker is S.plate8 else CL_R + 0.5 * CL_D) + 20 * dt * v0), CL_D)
        nsteps = int(1.3 * t_n / dt) + 40
        inter = "pair_style tdem/gran\npair_coeff * * %s\nfix w body tdem/wall/gran %s zplane 0 NULL" % (law, law)
        rows, fr, natoms = clump_run(name.split()[0], wd, [(pts, (0, 0, -v0))], [], inter, dt, nsteps, 1, every=10)
        ke = rows[:, 2]
        vz = rows[:, 10]
        e_m = vz[-1] / v0
        e_v1 = S.verlet_impact_e(n * k, n * g, M8, v0, dt, 20)
        e_v2 = S.verlet_impact_e(n * k, n * g, M8, v0, 2 * dt, 10)
        tol = abs(e_v2 - e_cf) + abs(e_v1 - e_cf) + 1e-9
        print("%s: N = %d, e %.7f, closed form %.7f, Verlet model at dt %.7f (2 dt %.7f), bound %.2e; "
              "KE %.6e -> %.6e J" % (name, n, e_m, e_cf, e_v1, e_v2, tol, ke[0], ke[-1]))
        chk.check(abs(e_m - e_cf) <= tol, "%s: e %.7f = N = %d closed form %.7f within the step error bound %.2e"
                  % (name, e_m, n, e_cf, tol))
        chk.check(0 <= e_m <= 1 and ke[-1] <= ke[0] * (1 + 1e-12),
                  "%s: e in [0, 1] and kinetic energy after <= before" % name)
        w = S.rigid_worst(fr, [list(range(8))])
        chk.check(w <= 1e-12, "%s: clump rigid (sphere distances to %.2g relative <= 1e-12)" % (name, w))
    # --- cube8 onto a 3x3 bed of fixed spheres (16 contacts) and onto a free cube8 (9 contacts)
    bed = [(i * CL_D, j * CL_D, 0.0) for i in (-1, 0, 1) for j in (-1, 0, 1)]
    hz = math.sqrt((2 * CL_R) ** 2 - 0.5 * CL_D ** 2)   # vertical distance at touch of a pocket sphere
    dt = 2.5e-8
    pts = S.cube8((0.0, 0.0, hz + 0.5 * CL_D + 20 * dt * v0), CL_D)
    wd = lc.workdir("clump_bed")
    inter = "pair_style tdem/gran\npair_coeff * * %s" % law
    rows, fr, natoms = clump_run("bed", wd, [(pts, (0, 0, -v0))], bed, inter, dt, 6000, 1, every=10)
    P = np.stack([fr["x"], fr["y"], fr["z"]], axis=2)
    dmat = np.sqrt(((P[:, :8, None, :] - P[:, None, 8:, :]) ** 2).sum(axis=3))
    ncont = (dmat < 2 * CL_R).sum(axis=(1, 2))
    ke = rows[:, 2]
    e_m = rows[-1, 10] / v0
    print("cube8 on fixed bed: max simultaneous contacts %d, e %.6f, KE %.6e -> %.6e J, rot KE at end %.3e"
          % (ncont.max(), e_m, ke[0], ke[-1], rows[-1, 4]))
    chk.check(ncont.max() >= 16, "cube8 on fixed bed: 16 contacts at once (%d)" % ncont.max())
    chk.check(ncont[-1] == 0 and 0 <= e_m <= 1 and ke[-1] <= ke[0] * (1 + 1e-12),
              "cube8 on fixed bed: rebounds, e %.4f in [0, 1], kinetic energy after <= before" % e_m)
    w = S.rigid_worst(fr, [list(range(8))])
    chk.check(w <= 1e-12, "cube8 on fixed bed: clump rigid (%.2g <= 1e-12)" % w)
    # two free bodies: lower cube at rest, upper shifted by (d/2, d/2): its (+,+) bottom sphere sits in the
    # pocket of the 4 top spheres of the lower cube, 2 more each touch 2, one touches 1: 9 contacts
    low = S.cube8((0.0, 0.0, 0.0), CL_D)
    zt = 0.5 * CL_D + hz + 0.5 * CL_D + 20 * dt * v0
    up = S.cube8((-0.5 * CL_D, -0.5 * CL_D, zt), CL_D)
    wd = lc.workdir("clump_pair")
    rows, fr, natoms = clump_run("pair", wd, [(low, (0, 0, 0)), (up, (0, 0, -v0))], [], inter, dt, 8000, 2, every=10)
    P = np.stack([fr["x"], fr["y"], fr["z"]], axis=2)
    dmat = np.sqrt(((P[:, :8, None, :] - P[:, None, 8:, :]) ** 2).sum(axis=3))
    ncont = (dmat < 2 * CL_R).sum(axis=(1, 2))
    ke = rows[:, 2]
    vrel0 = -v0
    vrel1 = rows[-1, 16] - rows[-1, 10]      # body 2 vz - body 1 vz
    e_m = -vrel1 / vrel0
    print("cube8 on free cube8: max simultaneous contacts %d, e %.6f, KE %.6e -> %.6e J (rot %.3e)"
          % (ncont.max(), e_m, ke[0], ke[-1], rows[-1, 4]))
    chk.check(ncont.max() >= 8, "cube8 on cube8: 8+ contacts at once between two bodies (%d)" % ncont.max())
    chk.check(0 <= e_m <= 1 and ke[-1] <= ke[0] * (1 + 1e-12),
              "cube8 on cube8: e %.4f in [0, 1], kinetic energy after <= before" % e_m)
    w = S.rigid_worst(fr, [list(range(8)), list(range(8, 16))])
    chk.check(w <= 1e-12, "cube8 on cube8: both clumps rigid (%.2g <= 1e-12)" % w)


PILE = """units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
atom_modify map array
region box block 0 {L} 0 {L} 0 0.08 units box
create_box 1 box
fix pm all property/atom mol ghost yes
region ins block 0.0 {L} 0.0 {L} 0.003 0.05 units box
fix c all tdem/clump template tet shape tetra {r} {d} density 2500 insert {n} region ins seed 4711
neighbor 0.001 bin
neigh_modify delay 0 every 1 check yes exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution {e} {tc} tangential cundall_strack {kappa} {mu}
fix floor all tdem/wall/gran normal lsd restitution {e} {tc} tangential cundall_strack {kappa} {mu} zplane 0 NULL
fix g all gravity {g} vector 0 0 -1
timestep {dt}
variable pe equal mass(all)*{g}*xcm(all,z)
thermo_style custom step atoms f_c v_pe
thermo_modify format float %.17g lost warn
thermo 1000
run {nsettle}
thermo 100
dump d all custom 500 dump.pile id mol mass radius x y z vx vy vz
dump_modify d sort id format float %.17g
run {nrest}
"""


def pile_energy(fr, L, r, e, tc, g, kappa, mu):
    """per frame: gravity potential, elastic energy of the lsd normal springs (sphere pairs of
    different bodies: m* = M1 M2/(M1 + M2), floor: m* = M) and the bound sum (mu F_n)^2/(2 k_t)
    of the energy the Cundall-Strack springs (k_t = kappa k) can hold; periodic x, y."""
    M = {}
    mol = fr["mol"][0].astype(int)
    for b in set(mol):
        M[b] = float(fr["mass"][0][mol == b].sum())
    c = (math.pi ** 2 + math.log(e) ** 2) / tc ** 2           # k = m* c
    pe, el, wt = [], [], []
    for f in range(len(fr["x"])):
        p = np.stack([fr["x"][f], fr["y"][f], fr["z"][f]], axis=1)
        dv = p[:, None, :] - p[None, :, :]
        dv[:, :, :2] -= L * np.round(dv[:, :, :2] / L)
        dd = np.sqrt((dv ** 2).sum(axis=2))
        xi = np.triu(np.maximum(2 * r - dd, 0.0) * (mol[:, None] != mol[None, :]), 1)
        i, j = np.nonzero(xi)
        ms = np.array([M[mol[a]] * M[mol[b]] / (M[mol[a]] + M[mol[b]]) for a, b in zip(i, j)])
        kp = ms * c
        xw = np.maximum(r - p[:, 2], 0.0)
        kw = np.array([M[m] for m in mol]) * c
        el.append(0.5 * float(np.sum(kp * xi[i, j] ** 2) + np.sum(kw * xw ** 2)))
        wt.append(float(np.sum((mu * kp * xi[i, j]) ** 2 / (2 * kappa * kp)) + np.sum((mu * kw * xw) ** 2 / (2 * kappa * kw))))
        pe.append(float(np.sum(fr["mass"][f] * g * p[:, 2])))
    return np.array(pe), np.array(el), np.array(wt)


def case_clump_pile():
    """40 tetra clumps (4 overlapping spheres each) inserted at random, poured onto the floor of a
    box periodic in x and y (lsd e = 0.3, Cundall-Strack mu = 0.4, gravity), settled for 6e4 steps,
    then left for 3e4 more steps. Asserts: no NaN, no lost atoms; the kinetic energy (fix output:
    translation + rotation of the bodies) has decayed to < 1e-6 of its peak and stays below
    1e-9 m_tot g d (lifting the pile by 1e-9 of a sphere diameter) at rest; no creep (centre of mass
    height range < 0.1 M g/k, a tenth of the static overlap of one body on one floor contact, and its
    drift in the second half of the rest phase not larger than in the first); no energy gain: KE + gravity + elastic energy of the normal springs
    never rises by more than the energy the tangential springs can hold at the earlier frame,
    sum (mu F_n)^2/(2 k_t) (+ 1e-15 of the potential energy for round-off)."""
    p = dict(L=0.025, r=0.002, d=0.003, n=40, e=0.3, tc=1e-4, kappa=0.8, mu=0.4, g=9.81, dt=5e-6,
             nsettle=60000, nrest=30000)
    wd = lc.workdir("clump_pile")
    _, out = lc.run(args["tdem"], PILE.format(**p), wd, "in.pile")
    rows = [r.split() for r in lc.thermo_blocks(out) if r.split()[0] != "Step"]
    a = np.array(rows, dtype=float)
    natoms = 4 * p["n"]
    chk.check(bool(np.all(np.isfinite(a))) and bool(np.all(a[:, 1] == natoms)) and "Lost atoms" not in out,
              "pile: thermo finite, no lost atoms (%s, expected %d)" % (sorted(set(a[:, 1].astype(int))), natoms))
    cols = "id mol mass radius x y z vx vy vz".split()
    steps, fr, bad = S.read_frames(os.path.join(wd, "dump.pile"), natoms, cols)
    finite = all(np.all(np.isfinite(v)) for v in fr.values())
    chk.check(finite and bad == 0, "pile: every dumped value finite, every frame has %d atoms" % natoms)
    mt = float(fr["mass"][0].sum())
    rest = a[a[:, 0] >= p["nsettle"]]
    ke_peak = float(a[:, 2].max())
    ke_rest = float(rest[:, 2].max())
    scale = mt * p["g"] * 2 * p["r"]
    zc = rest[:, 3] / (mt * p["g"])
    creep = float(zc.max() - zc.min())
    print("pile: KE peak %.4e J, at the end of the settle %.4e J, max over the %d rest steps %.4e J "
          "(m g d = %.4e J); centre of mass height range %.3e m" % (ke_peak, rest[0, 2], p["nrest"], ke_rest,
                                                                  scale, creep))
    chk.check(rest[0, 2] <= 1e-6 * ke_peak, "pile: kinetic energy decayed to %.2e of its peak (<= 1e-6)"
              % (rest[0, 2] / ke_peak))
    chk.check(ke_rest <= 1e-9 * scale, "pile at rest: KE stays near zero (max %.3e <= 1e-9 m g d = %.3e J)"
              % (ke_rest, 1e-9 * scale))
    # creep scale: the static overlap of one body resting on one floor contact, xi_g = M g / k_wall
    mb = mt / p["n"]
    xi_g = mb * p["g"] / (mb * (math.pi ** 2 + math.log(p["e"]) ** 2) / p["tc"] ** 2)
    h = len(zc) // 2
    d1, d2 = abs(zc[h] - zc[0]), abs(zc[-1] - zc[h])
    print("pile at rest: com height drift first half %.3e m, second half %.3e m (xi_g = M g/k = %.3e m)" % (d1, d2, xi_g))
    chk.check(creep <= 0.1 * xi_g and d2 <= max(d1, 1e-3 * xi_g),
              "pile at rest: no creep (com height range %.3e m <= 0.1 M g/k = %.3e m; drift does not grow: %.2e, %.2e)"
              % (creep, 0.1 * xi_g, d1, d2))
    pe, el, wt = pile_energy(fr, p["L"], p["r"], p["e"], p["tc"], p["g"], p["kappa"], p["mu"])
    kemap = dict(zip(a[:, 0].astype(int), a[:, 2]))
    ke = np.array([kemap[s] for s in steps])
    E = ke + pe + el
    rise = np.diff(E)
    allow = wt[:-1] + 1e-15 * np.abs(pe[:-1])
    tot = E[-1] - E[0]
    print("pile at rest: E = KE + gravity + normal elastic %.12e -> %.12e J; largest rise between frames %.3e J "
          "(allowed: tangential spring energy bound %.3e J); elastic %.3e J" % (E[0], E[-1], rise.max(), allow.min(),
                                                                               el[0]))
    chk.check(bool(np.all(rise <= allow)) and tot <= allow[0],
              "pile at rest: no energy gain (largest rise %.3e J <= tangential spring bound, overall %.3e J)"
              % (rise.max(), tot))


# ------------------------------------------------------------------------------------------
# grate (issue 7 modules `grate`, `mixing`): stopped bed at rest, moving bars
GR_R, GR_RHO = 0.0025, 2500.0
GR_LAW = "normal lsd restitution 0.3 2e-4 tangential cundall_strack 0.8 0.4"
GR_E, GR_TC = 0.3, 2e-4

GRATE_HEAD = """units si
atom_style sphere
atom_modify map array
boundary f p f
newton off
comm_modify vel yes
read_data grate.data
neighbor 0.001 bin
neigh_modify delay 0 every 1 check yes
pair_style tdem/gran
pair_coeff * * {law}
fix gr all tdem/grate {law} {grate}
"""


def grate_lattice_data(path, nx, ny, nz, L0, ytot, zlo, zhi, lift=0.0, vx=0.0, x0=0.0):
    """simple cubic lattice of touching spheres (spacing exactly 2r) resting with zero overlap on a
    flat top face at z = 0 (first layer centre z = r + lift), y periodic with box length ny 2r."""
    rows = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                rows.append((x0 + GR_R + 2 * GR_R * i, -0.5 * ytot + GR_R + 2 * GR_R * j, GR_R + lift + 2 * GR_R * k))
    with open(path, "w") as f:
        f.write("grate lattice\n\n%d atoms\n1 atom types\n%r %r xlo xhi\n%r %r ylo yhi\n%r %r zlo zhi\n\n"
                "Atoms # sphere\n\n" % (len(rows), L0[0], L0[1], -0.5 * ytot, 0.5 * ytot, zlo, zhi))
        for n, (x, y, z) in enumerate(rows, 1):
            f.write("%d 1 %r %r %r %r %r\n" % (n, 2 * GR_R, GR_RHO, x, y, z))
        f.write("\nVelocities\n\n")
        for n in range(1, len(rows) + 1):
            f.write("%d %r 0 0 0 0 0\n" % (n, vx))
    return len(rows)


def case_grate_stopped():
    """Spheres on a STOPPED grate (3 rows, the middle one a 'moving' row with stroke 0), compute
    tdem/mixing/velocity.
    (a) exact rest, no gravity: a simple cubic lattice (2 layers, 24 x 8 spheres, y periodic) of
        touching spheres (spacing exactly 2r) on the bar tops with zero overlap, zero velocities,
        2000 steps. The only forces are those of overlaps of the order of the round-off of the
        positions, |xi| <= 4 eps |x|max (eps = 2^-52); with k of the lsd law they change a velocity
        by at most N dt k |xi|/m, and P' <= 2 sqrt(3) max|v| (each p_k <= 2 max|v_k|). Asserted:
        P' <= that bound at every sampled step (measured: exactly 0).
    (b) settled under gravity: the same lattice, g = 9.81, 2e4 steps (2000 contact damping times
        t_c/ln(1/e)): P' <= 1e-3 g/omega n_layers, a thousandth of the velocity scale of the static
        compression of the column (omega = sqrt(k/m)); no lost atoms, nothing moves along x by more
        than the static overlap."""
    grate = "rows 3 bar_length 0.04 bar_height 0.02 step_height 0 declination 0 width 0.04 stroke 0 period 0.2"
    m = S.sphere_mass(2 * GR_R, GR_RHO)
    k = m * (math.pi ** 2 + math.log(GR_E) ** 2) / GR_TC ** 2       # pair k uses m* = m/2: k/2 <= this
    omega = math.sqrt(k / m)
    dt = GR_TC / 40
    for tag, g, nsteps in (("exact_rest", 0.0, 2000), ("settled", 9.81, 20000)):
        wd = lc.workdir("grate_" + tag)
        n = grate_lattice_data(os.path.join(wd, "grate.data"), 24, 8, 2, (-0.01, 0.13), 0.04, -0.05, 0.05)
        text = GRATE_HEAD.format(law=GR_LAW, grate=grate)
        if g:
            text += "fix g all gravity %r vector 0 0 -1\n" % g
        text += "fix nve all nve/sphere\ntimestep %r\n" % dt
        text += "compute mix all tdem/mixing/velocity radius 0.011 bins x 0 0.12 3 periodic y\n"
        text += "compute vmax all reduce max vx vy vz\ncompute vmin all reduce min vx vy vz\n"
        text += ("thermo_style custom step atoms c_mix c_vmax[1] c_vmax[2] c_vmax[3] c_vmin[1] c_vmin[2] c_vmin[3] ke\n"
                 "thermo_modify lost warn format float %%.17g\nthermo %d\nrun %d\n" % (nsteps // 20, nsteps))
        text += "write_dump all custom dump.end id x y z vx vy vz modify sort id format float %.17g\n"
        _, out = lc.run(args["tdem"], text, wd, "in." + tag)
        a = np.array([r.split() for r in lc.thermo_blocks(out) if r.split()[0] != "Step"], dtype=float)
        chk.check(bool(np.all(np.isfinite(a))) and bool(np.all(a[:, 1] == n)) and "Lost atoms" not in out,
                  "%s: finite, no lost atoms (%d)" % (tag, n))
        pp = a[:, 2]
        vabs = np.abs(a[:, 3:9]).max()
        if not g:
            eps = 2.0 ** -52
            xi = 4 * eps * 0.13
            vb = nsteps * dt * k * xi / m * 6        # up to 6 neighbours
            pb = 2 * math.sqrt(3) * vb
            print("exact rest: P' max %.3e m/s (bound %.3e m/s from |xi| <= %.2e m), max |v| %.3e m/s"
                  % (pp.max(), pb, xi, vabs))
            chk.check(pp.max() <= pb and vabs <= vb,
                      "exact rest on the stopped grate: P' = 0 within round-off (%.3e <= %.3e m/s)" % (pp.max(), pb))
        else:
            pb = 1e-3 * g / omega * 2
            cols, end = lc.read_dump(os.path.join(wd, "dump.end"))
            x0 = np.array([GR_R + 2 * GR_R * i for _ in range(16) for i in range(24)])
            dx = float(np.abs(end[:, 1] - x0).max())
            xs = 2 * m * g / k
            print("settled: P' at the end %.3e m/s (bound 1e-3 n g/omega = %.3e m/s), max |v| %.3e m/s, "
                  "largest x displacement %.3e m (static overlap scale 2 m g/k = %.3e m)" % (pp[-1], pb, vabs, dx, xs))
            chk.check(pp[-1] <= pb, "settled bed on the stopped grate: P' %.3e <= %.3e m/s" % (pp[-1], pb))
            chk.check(dx <= xs, "settled bed: no sphere drifts along the grate (%.3e <= %.3e m)" % (dx, xs))


def case_grate_moving():
    """Spheres on a moving grate: 3 flat rows (step 5 mm, no gaps, all rows moving together in phase
    group 0, sinusoidal stroke 0.02 m at 5 Hz, slow outward stroke (forward_share 0.8) and quick return,
    which transports by stick-slip: bar speed <= U = pi stroke/(2 0.2 T)), a fixed inlet wall at
    x = stroke (row 0 always reaches under it), gravity, lsd e = 0.3 + Cundall-Strack; spheres that fall off the last row leave through the
    floor of the box (the outlet). Energy balance with the work of the bars (fix output: total force
    of the particles on the boxes and the stroke velocity, all boxes move with the same velocity):
      E(t) = sum 1/2 m v^2 + 1/5 m r^2 w^2 + m g (z - z_lo) <= E(0) + W(t),  W = -int F_box . v_bar dt
    (contacts only dissipate and start without overlap; atoms leaving carry E_i >= 0 away), so every
    particle's speed is bounded by |v_i| <= sqrt(2 (E(0) + W(t))/m_i). Asserted: no NaN, atoms are
    lost only through the outlet (last seen beyond the last row's heel, falling), E(t) <= E(0) + W(t)
    (+ 1 % of the integrated |power| for the rectangle rule of W, + 1e-12 E(0) round-off), every speed below its bound, and
    the brief's a-priori bound 1/2 m |v|^2 <= 1/2 m (U + sqrt(2 g H))^2 (H: start height above zlo)."""
    stroke, T, sf = 0.02, 0.2, 0.8
    U = math.pi * stroke / (2 * min(sf, 1 - sf) * T)   # sinusoidal: pi stroke/(2 d), d the shorter stroke
    L, rows, step = 0.03, 3, 0.005
    grate = ("rows %d bar_length %r bar_height 0.02 step_height %r declination 0 width 0.04 row_group 0 0 0 "
             "stroke %r period %r forward_share %r profile sinusoidal" % (rows, L, step, stroke, T, sf))
    dt = GR_TC / 40
    nsteps = 60000                                     # 1.5 s: 7.5 strokes
    wd = lc.workdir("grate_moving")
    zlo = -0.02                                       # outlet: the floor of the box, below the last top face
    n = grate_lattice_data(os.path.join(wd, "grate.data"), 12, 8, 2, (-0.01, 0.2), 0.04, zlo, 0.05, lift=1e-4,
                           x0=stroke)
    text = GRATE_HEAD.format(law=GR_LAW, grate=grate)
    # the inlet wall stands at x = stroke: row 0 (heel at u in [0, stroke]) always covers x >= stroke
    text += "fix inlet all tdem/wall/gran %s xplane %r NULL\n" % (GR_LAW, stroke)
    text += "fix g all gravity 9.81 vector 0 0 -1\nfix nve all nve/sphere\ntimestep %r\n" % dt
    text += ("thermo_style custom step atoms f_gr[1] f_gr[2] f_gr[3] f_gr[5]\n"
             "thermo_modify lost ignore format float %.17g\nthermo 1\n")
    text += "dump d all custom 100 dump.gm id mass radius x y z vx vy vz omegax omegay omegaz\n"
    text += "dump_modify d sort id format float %%.17g\nrun %d\n" % nsteps
    _, out = lc.run(args["tdem"], text, wd, "in.moving")
    a = np.array([r.split() for r in lc.thermo_blocks(out) if r.split()[0] != "Step"], dtype=float)
    chk.check(bool(np.all(np.isfinite(a))), "moving grate: thermo (atoms, bar forces, stroke velocity) finite")
    # frames with a varying atom count
    frames = {}
    with open(os.path.join(wd, "dump.gm")) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            st, m_ = int(lines[i + 1]), int(lines[i + 3])
            frames[st] = np.array(" ".join(lines[i + 9:i + 9 + m_]).split(), dtype=float).reshape(m_, 12)
            i += 9 + m_
        else:
            i += 1
    steps = sorted(frames)
    finite = all(np.all(np.isfinite(frames[s])) for s in steps)
    chk.check(finite, "moving grate: every dumped position, velocity and spin is finite")
    # work of the bars: power on the particles = -F_box . (u' e_x), rectangle rule on the per-step output
    pw = -a[:, 2] * a[:, 5]
    W = np.concatenate([[0.0], np.cumsum(pw[1:] * dt)])
    Wabs = np.concatenate([[0.0], np.cumsum(np.abs(pw[1:]) * dt)])
    wmap = dict(zip(a[:, 0].astype(int), zip(W, Wabs)))

    def energy(fr):
        m, r = fr[:, 1], fr[:, 2]
        v2 = (fr[:, 6:9] ** 2).sum(axis=1)
        w2 = (fr[:, 9:12] ** 2).sum(axis=1)
        return 0.5 * m * v2 + 0.2 * m * r * r * w2 + m * 9.81 * (fr[:, 5] - zlo)

    E0 = float(energy(frames[steps[0]]).sum())
    H = float(frames[steps[0]][:, 5].max() - zlo)
    vapriori = U + math.sqrt(2 * 9.81 * H)
    worst_e, worst_v, worst_a, vmax = -1e300, 0.0, 0.0, 0.0
    lost_ok, nlost = True, 0
    prev = frames[steps[0]]
    x_last_heel = (rows - 1) * L
    for s in steps:
        fr = frames[s]
        Wt, Wa = wmap[s]
        E = float(energy(fr).sum())
        if s != steps[0]:
            worst_e = max(worst_e, E - (E0 + Wt + 0.01 * Wa) - 1e-12 * E0)  # + round-off of the sums
        v = np.sqrt((fr[:, 6:9] ** 2).sum(axis=1))
        vmax = max(vmax, float(v.max()))
        worst_v = max(worst_v, float((v / np.sqrt(2 * (E0 + Wt + 0.01 * Wa) / fr[:, 1])).max()))
        worst_a = max(worst_a, float(v.max() / vapriori))
        gone = np.setdiff1d(prev[:, 0], fr[:, 0])
        for gid in gone:
            row = prev[prev[:, 0] == gid][0]
            nlost += 1
            if not (row[3] > x_last_heel and row[8] < 0):
                lost_ok = False
                print("atom %d lost at x %.4f z %.4f vz %.3f (not at the outlet)" % (gid, row[3], row[5], row[8]))
        prev = fr
    natoms_end = len(frames[steps[-1]])
    print("moving grate: U = %.4f m/s, %d of %d spheres left through the outlet, bars' work %.4e J "
          "(integrated |power| %.4e J), E(0) %.4e J; max speed %.4f m/s (a-priori U + sqrt(2 g H) = %.4f m/s); "
          "largest E - (E0 + W + 1 %% |W|) %.3e J; worst speed / energy bound %.3f"
          % (U, nlost, n, W[-1], Wabs[-1], E0, vmax, vapriori, worst_e, worst_v))
    chk.check(int(a[-1, 1]) == natoms_end and n - natoms_end == nlost,
              "moving grate: atom count consistent (%d left, thermo %d)" % (nlost, int(a[-1, 1])))
    chk.check(lost_ok, "moving grate: atoms are lost only through the outlet (%d, beyond x = %.3f, falling)"
              % (nlost, x_last_heel))
    chk.check(nlost > 0, "moving grate: the bars transport spheres to the outlet (%d left)" % nlost)
    chk.check(worst_e <= 0, "moving grate: E(t) <= E(0) + work of the bars at every frame (worst %.3e J)" % worst_e)
    chk.check(worst_v <= 1, "moving grate: every particle speed below sqrt(2 (E0 + W)/m) (worst ratio %.3f)" % worst_v)
    chk.check(worst_a <= 1, "moving grate: every speed below U + sqrt(2 g H) = %.3f m/s (max %.3f)"
              % (vapriori, vmax))


CASES = {
    "dt_0p9_critical_linear_stable_0p5_no_energy_gain": case_dt_critical,
    "stiff_200gpa_hertz_impacts_0p001_and_100_mps_bounded": case_stiff,
    "soft_1mpa_hertz_impacts_0p001_and_1_mps_bounded": case_soft,
    "grazing_89deg_tangential_no_energy_gain_coulomb_bound": case_grazing,
    "mass_ratio_1_1000_head_on_momentum_and_e": case_mass_ratio,
    "dense_bed_at_rest_1e5_steps_no_creep": case_dense_bed,
    "walton_braun_repeated_loading_no_gain_no_attraction": lambda: case_hysteretic("walton_braun"),
    "thornton_repeated_loading_no_gain_no_attraction": lambda: case_hysteretic("thornton"),
    "power_law_repeated_loading_no_gain_no_attraction": lambda: case_hysteretic("power_law"),
    "extended_laws_v0_1e-4_and_v_max_e_in_0_1": case_extended,
    "rank_crossing_in_contact_np2_equals_np1": case_rank_crossing,
    "clump_8_simultaneous_contacts_no_energy_gain": case_clump_contacts,
    "clump_pile_at_rest_no_creep": case_clump_pile,
    "grate_stopped_bed_at_rest_pprime_zero": case_grate_stopped,
    "grate_moving_bars_energy_bounded": case_grate_moving,
}

if __name__ == "__main__":
    if CASE == "list":
        print("\n".join(CASES))
        sys.exit(0)
    if CASE not in CASES:
        print("unknown --case %r; allowed: %s" % (CASE, ", ".join(CASES)))
        sys.exit(2)
    CASES[CASE]()
    if GC:
        chk.check(GC_LINES[0] > 0, "grid_correction on in %d law lines of the case's inputs" % GC_LINES[0])
    chk.done()
