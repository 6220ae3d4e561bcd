#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/timestep in LIGGGHTS (issue 8). Parts (--part NAME), as the LAMMPS test
(tests/host/lammps/test_timestep_advice.py):

  acceptance  head-on two-sphere impact, model tdem/lsd (parameters stiffness: kn, gamman per unit
              m*), nve/sphere; dt_c = 2/omega (sqrt(1+zeta^2) - zeta) computed here.
              * 1.1 dt_c with `check stop`: stopped at set-up, the error names dt and dt_c;
              * 1.1 dt_c, `check off`, the pair pressed together by opposite constant forces
                (equilibrium overlap 10 v0/omega): the oscillation grows until the spheres separate;
              * 0.5 dt_c (`check stop` lets it run): the pressed pair stays and calms down; the free
                impact gives e within 0.15 of the closed form and equals velocity Verlet
                re-implemented here to 1e-9.
  closed_forms the printed table against closed forms computed here: tdem/hertz with e = 1
              (undamped): k_max = 3/2 k~ sqrt(xi_max), xi_max = (5 m* v^2/(4 k~))^(2/5), dt_c = 2/omega,
              contact time 2.8683 (m*^2/(R* Y*^2 v))^(1/5), Rayleigh time; m*, R* of the lightest /
              smallest atoms (two sizes per type); stock hooke (k matched to Hertz at
              characteristicVelocity, gamma from e), hooke/stiffness (kn, m* gamman), hertz (damping
              2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(R*) m*) xi^(1/4) at the undamped xi_max); a tdem/lsd
              wall (m* = m); the scheme of fix tdem/integrate and of `scheme`.
  check_modes `check warn` warns, `check stop` stops with the numbers, `check off` stays silent.
  runtime     tdem/hertz (e = 1), check stop, dt = 0.45 dt_c(vmax): the first run passes; velocities
              raised by 100 between runs: the run-time check (every 10) stops at step <= first + 10.
  bad_input   every keyword with a bad value; an unsupported law gives a warning naming it.
  tdem_laws   the six laws advised from what their models publish (tdem_liggghts_advice.h):
              tdem/walton_braun, tdem/thornton, tdem/power_law, tdem/continuous_potential,
              tdem/extended_linear, tdem/extended_hertz, each between two equal spheres and on a
              wall (m* = m, R* = R, contact distance R): the printed k_max and dt_c equal the closed
              form of the stiffest tangent stiffness evaluated here (docs/timestep.md) to 1e-6.
  lsd_settings tdem/lsd with every property set present (kn, gamman, coefficientRestitution,
              contactTime): `parameters restitution` with `limitForce off` and `on` each give the
              advice of that setting only (k, gamma from (e, t_c) in that convention, computed
              here from the damped oscillator), `parameters stiffness` that of kn, m* gamman,
              `absolute_damping on` that of kn, gamman_abs; tdem/hertz `damping linear` with
              coefficientRestitution also present: the linear damper only. The table names the
              setting and lists no candidates.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import tdem_lig as T  # noqa: E402

PART = ["all"]


def extra(p):
    p.add_argument("--part", default="all")


args = T.parse_args(extra)
checks = T.Checks()
EXE = args.tdem
RHO = 2500.0
R = 0.005


def mass(r, rho=RHO):
    return rho * 4.0 / 3.0 * math.pi * r ** 3


def vv_critical(k, gamma, meff):
    w = math.sqrt(k / meff)
    z = gamma / (2.0 * math.sqrt(k * meff))
    return 2.0 / w * (math.sqrt(1.0 + z * z) - z), z, w


def close(a, b, tol):
    return a is not None and b is not None and abs(a - b) <= tol * abs(b)


HEAD = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
hard_particles yes
units si
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box {ntypes} box
neighbor 0.001 bin
neigh_modify delay 0
{props}
{interaction}
timestep {dt!r}
{atoms}
{integrate}
{tsfix}
"""

K = 1.0e4
E_REST = 0.8
MEFF = mass(R) / 2


def gamma_for(e, k, meff):
    ln = math.log(e)
    beta = -ln / math.sqrt(math.pi ** 2 + ln * ln)
    return 2.0 * beta * math.sqrt(k * meff)


G = gamma_for(E_REST, K, MEFF)
GN = G / MEFF  # gamman per unit effective mass
DTC, ZETA, OMEGA = vv_critical(K, G, MEFF)


def lsd_props(ntypes=1, kn=K, gn=GN):
    n2 = ntypes * ntypes
    return ("fix m_kn all property/global kn peratomtypepair %d %s\n"
            "fix m_kt all property/global kt peratomtypepair %d %s\n"
            "fix m_gn all property/global gamman peratomtypepair %d %s\n"
            "fix m_gt all property/global gammat peratomtypepair %d %s\n"
            "fix m_mu all property/global coefficientFriction peratomtypepair %d %s\n"
            % (ntypes, " ".join([repr(kn)] * n2), ntypes, " ".join(["1000.0"] * n2), ntypes,
               " ".join([repr(gn)] * n2), ntypes, " ".join(["0.0"] * n2), ntypes, " ".join(["0.5"] * n2)))


LSD_PAIR = "pair_style gran model tdem/lsd tangential tdem/cundall_strack\npair_coeff * *"


def two_spheres(gap=0.0005, v=0.5, r1=R, r2=R):
    z1, z2 = -(r1 + gap / 2), r2 + gap / 2
    return ("create_atoms 1 single 0 0 %r units box\ncreate_atoms 1 single 0 0 %r units box\n"
            "set atom 1 diameter %r density %r\nset atom 2 diameter %r density %r\n"
            "group g1 id 1\ngroup g2 id 2\n"
            "velocity g1 set 0 0 %r units box\nvelocity g2 set 0 0 %r units box\n"
            % (z1, z2, 2 * r1, RHO, 2 * r2, RHO, v / 2, -v / 2))


def script(props, inter, dt, atoms, tsfix, body, ntypes=1, integrate="fix integr all nve/sphere"):
    return HEAD.format(ntypes=ntypes, props=props, interaction=inter, dt=dt, atoms=atoms,
                       integrate=integrate, tsfix=tsfix) + body


_count = [0]


def run(text, name, check=False, np_=1):
    _count[0] += 1
    d = T.workdir(args, "timestep_%s_%d" % (name, _count[0]))
    r = T.run(EXE, text, d, name, np_=np_, mpirun=args.mpirun, check=check, timeout=300)
    return r.returncode, r.stdout + r.stderr


def table_rows(out):
    lines = out.splitlines()
    rows = {}
    for i, l in enumerate(lines):
        if l.startswith("#what"):
            cols = l.split()
            for m in lines[i + 1:]:
                s = m.split()
                if not s or not (s[0].startswith("pair_") or s[0].startswith("wall_")):
                    break
                if len(s) == len(cols):
                    rows[s[0]] = {c: (s[j] if j < 2 or s[j] in ("-", "ok", "warn", "stop") else float(s[j]))
                                  for j, c in enumerate(cols)}
    return rows


def thermo_rows(out):
    res = []
    for header, rows in T.thermo_blocks(out):
        res += [r.split() for r in rows]
    return res


# ------------------------------------------------------------------ acceptance
def vv_restitution(dt, gap, v):
    m = mass(R)
    z1, z2 = -(R + gap / 2), R + gap / 2
    v1, v2 = v / 2, -v / 2

    def force(z1, z2, v1, v2):
        xi = 2 * R - (z2 - z1)
        if xi <= 0.0:
            return 0.0
        return K * xi + MEFF * GN * (v1 - v2)

    f = force(z1, z2, v1, v2)
    touched = False
    for _ in range(200000):
        v1 -= 0.5 * dt * f / m
        v2 += 0.5 * dt * f / m
        z1 += dt * v1
        z2 += dt * v2
        f = force(z1, z2, v1, v2)
        v1 -= 0.5 * dt * f / m
        v2 += 0.5 * dt * f / m
        if f != 0.0:
            touched = True
        elif touched:
            break
    return (v2 - v1) / v


def impact(dt, tsfix, gap=0.0005, v=0.5, nsteps=None):
    nsteps = nsteps or int((gap / v + 4.0 * math.pi / OMEGA) / dt) + 5
    body = ("variable dv equal vz[2]-vz[1]\nthermo_style custom step v_dv\nthermo_modify format float %%.17g\n"
            "thermo %d\nrun %d\n" % (nsteps, nsteps))
    return run(script(lsd_props(), LSD_PAIR, dt, two_spheres(gap, v), tsfix, body), "impact")


def pressed(dt, tsfix, v0=0.1, nsteps=4000):
    m = mass(R)
    xi_eq = 10.0 * v0 / OMEGA
    F = K * xi_eq * MEFF / (m / 2)
    atoms = ("create_atoms 1 single 0 0 %r units box\ncreate_atoms 1 single 0 0 %r units box\n"
             "set group all diameter %r density %r\ngroup g1 id 1\ngroup g2 id 2\n"
             "velocity g1 set 0 0 %r units box\nvelocity g2 set 0 0 %r units box\n"
             "fix f1 g1 addforce 0 0 %r\nfix f2 g2 addforce 0 0 %r\n"
             % (-R, R, 2 * R, RHO, v0 / 2, -v0 / 2, F, -F))
    body = ("variable xi equal %r-(z[2]-z[1])\nthermo_style custom step v_xi\n"
            "thermo_modify format float %%.17g\nthermo 1\nrun %d\n" % (2 * R, nsteps))
    rc, out = run(script(lsd_props(), LSD_PAIR, dt, atoms, tsfix, body), "pressed")
    xs = [float(r[1]) for r in thermo_rows(out) if len(r) > 1 and re.match(r"^-?[0-9.eE+-]+$", r[1])]
    xs = [x if math.isfinite(x) else float("nan") for x in xs]
    if rc != 0:
        if "Lost atoms" not in out and "lost" not in out.lower():
            sys.stdout.write(out[-3000:])
            raise SystemExit("FAIL: pressed pair: unexpected failure")
        print("info: pressed pair at dt = %.6g: atoms lost after %d steps" % (dt, len(xs)))
        return -1.0, max(xs) if xs else math.inf, math.nan, xi_eq
    return min(xs[1:]), max(xs), xs[-1], xi_eq


def part_acceptance():
    print("tdem/lsd: k = %g N/m, gamman = %.6g 1/s, m* = %.6g kg, zeta = %.6g, dt_c(VV) = %.9g s"
          % (K, GN, MEFF, ZETA, DTC))
    rc, out = impact(1.1 * DTC, "fix ts all tdem/timestep check stop")
    m = re.search(r"critical step dt_c = ([0-9.eE+-]+) s", out)
    checks.check(rc != 0 and "tdem/timestep (check stop)" in out and m is not None and close(float(m.group(1)), DTC, 1e-7),
                 "1.1 dt_c, check stop: stopped at set-up, printed dt_c %s vs %.9g (rc %d)"
                 % (m.group(1) if m else "?", DTC, rc))
    mn, mx, fin, xeq = pressed(1.1 * DTC, "fix ts all tdem/timestep check off")
    checks.check(mn < 0.0 or mx > 3 * xeq or not math.isfinite(fin),
                 "1.1 dt_c, enduring contact: overlap left the well (min %.3g, max %.3g, xi_eq %.3g)" % (mn, mx, xeq))
    mn, mx, fin, xeq = pressed(0.5 * DTC, "fix ts all tdem/timestep check stop")
    checks.check(mn > 0.0 and mx < 2.5 * xeq and abs(fin - xeq) < 0.05 * xeq,
                 "0.5 dt_c, enduring contact: stays and decays (min %.3g, max %.3g, final %.4g, xi_eq %.4g)"
                 % (mn, mx, fin, xeq))
    e_closed = math.exp(-math.pi * ZETA / math.sqrt(1 - ZETA ** 2))
    for gap in (0.0005, 0.000537, 0.000571):
        dt = 0.5 * DTC
        rc, out = impact(dt, "fix ts all tdem/timestep check stop", gap=gap)
        rows = thermo_rows(out)
        e = float(rows[-1][1]) / 0.5 if rc == 0 and rows else math.nan
        e_vv = vv_restitution(dt, gap, 0.5)
        checks.check(math.isfinite(e) and abs(e - e_closed) < 0.15 and close(e, e_vv, 1e-9),
                     "0.5 dt_c, free impact (gap %g): e = %.9f, closed form %.6f, velocity Verlet here %.9f"
                     % (gap, e, e_closed, e_vv))


# ------------------------------------------------------------------ closed forms
def hertz_closed(ystar, meff, reff, v):
    kt = 4.0 / 3.0 * ystar * math.sqrt(reff)
    xi = (5 * meff * v * v / (4 * kt)) ** 0.4
    kmax = 1.5 * kt * math.sqrt(xi)
    tc = 2.8683 * (meff * meff / (reff * ystar * ystar * v)) ** 0.2
    return kmax, 2.0 / math.sqrt(kmax / meff), tc, xi


def rayleigh(E, nu, r, rho):
    Gs = E / (2 * (1 + nu))
    return math.pi * r * math.sqrt(rho / Gs) / (0.1631 * nu + 0.8766)


def mat_props(ntypes, E, nu, e, extra=""):
    n2 = ntypes * ntypes
    return ("fix m_E all property/global youngsModulus peratomtype %s\n"
            "fix m_nu all property/global poissonsRatio peratomtype %s\n"
            "fix m_e all property/global coefficientRestitution peratomtypepair %d %s\n"
            "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair %d %s\n"
            "fix m_mu all property/global coefficientFriction peratomtypepair %d %s\n%s"
            % (" ".join([repr(E)] * ntypes), " ".join([repr(nu)] * ntypes), ntypes, " ".join([repr(e)] * n2),
               ntypes, " ".join(["0.8"] * n2), ntypes, " ".join(["0.5"] * n2), extra))


def part_closed_forms():
    E, nu, v = 7e10, 0.25, 2.0
    ystar = E / (2 * (1 - nu * nu))
    r1a, r1b, r2a, r2b = 0.005, 0.004, 0.003, 0.0035
    atoms = "\n".join([
        "create_atoms 1 single -0.02 0 0 units box", "create_atoms 1 single 0.02 0 0 units box",
        "create_atoms 2 single 0 -0.02 0 units box", "create_atoms 2 single 0 0.02 0 units box",
        "set atom 1 diameter %r density %r" % (2 * r1a, RHO), "set atom 2 diameter %r density %r" % (2 * r1b, RHO),
        "set atom 3 diameter %r density %r" % (2 * r2a, RHO), "set atom 4 diameter %r density %r" % (2 * r2b, RHO)])
    m1, m2 = mass(r1b), mass(r2a)
    dt = 1e-7
    inter = ("pair_style gran model tdem/hertz tangential tdem/cundall_strack damping tsuji\npair_coeff * *\n"
             "fix w all wall/gran model tdem/hertz tangential tdem/cundall_strack primitive type 1 zplane -0.05 "
             "damping tsuji")
    rc, out = run(script(mat_props(2, E, nu, 1.0), inter, dt, atoms, "fix ts all tdem/timestep vmax %r" % v,
                         "run 0\n", ntypes=2), "cf_hertz")
    rows = table_rows(out)
    for (i, j, mi, mj, ri, rj) in ((1, 1, m1, m1, r1b, r1b), (1, 2, m1, m2, r1b, r2a), (2, 2, m2, m2, r2a, r2a)):
        meff, reff = mi * mj / (mi + mj), ri * rj / (ri + rj)
        kmax, dtc, tc, _ = hertz_closed(ystar, meff, reff, v)
        tr = min(rayleigh(E, nu, ri, RHO), rayleigh(E, nu, rj, RHO))
        row = rows.get("pair_%d_%d" % (i, j))
        ok = row is not None and close(row["m*"], meff, 1e-8) and close(row["R*"], reff, 1e-8) and \
            close(row["k_max"], kmax, 1e-7) and close(row["dt_critical"], dtc, 1e-7) and \
            close(row["t_contact"], tc, 2e-4) and close(row["T_Rayleigh"], tr, 1e-7)
        checks.check(ok, "tdem/hertz e=1 pair %d %d: m* %s/%.9g R* %s/%.9g k_max %s/%.9g dt_c %s/%.9g t_c %s/%.9g "
                     "T_R %s/%.9g" % (i, j, row and row["m*"], meff, row and row["R*"], reff, row and row["k_max"], kmax,
                                      row and row["dt_critical"], dtc, row and row["t_contact"], tc,
                                      row and row["T_Rayleigh"], tr))
    # the wall (same material, R* = R, m* = m)
    for t, m, r in ((1, m1, r1b), (2, m2, r2a)):
        kmax, dtc, tc, _ = hertz_closed(ystar, m, r, v)
        row = rows.get("wall_w_type_%d" % t)
        checks.check(row is not None and close(row["m*"], m, 1e-8) and close(row["R*"], r, 1e-8)
                     and close(row["dt_critical"], dtc, 1e-7),
                     "tdem/hertz wall type %d: m* %s/%.9g dt_c %s/%.9g"
                     % (t, row and row["m*"], m, row and row["dt_critical"], dtc))
    # stock hooke, hooke/stiffness, hertz between two equal spheres
    e, vc = 0.7, 1.5
    atoms = two_spheres()
    lne = math.log(e)
    for model in ("hooke", "hooke/stiffness", "hertz"):
        if model == "hooke/stiffness":
            props, expect = lsd_props(), vv_critical(K, MEFF * GN, MEFF)[0]
            what = "dt_c"
        elif model == "hooke":
            props = mat_props(1, E, nu, e, "fix m_vc all property/global characteristicVelocity scalar %r\n" % vc)
            sr = math.sqrt(R / 2)
            k = 16.0 / 15.0 * sr * ystar * (15.0 * MEFF * vc * vc / (16.0 * sr * ystar)) ** 0.2
            g = math.sqrt(4.0 * MEFF * k * lne * lne / (lne * lne + math.pi ** 2))
            expect = vv_critical(k, g, MEFF)[0]
            what = "dt_c"
        else:
            props = mat_props(1, E, nu, e)
            kmax, _, _, xi = hertz_closed(ystar, MEFF, R / 2, 1.0)
            beta = abs(lne) / math.sqrt(lne * lne + math.pi ** 2)
            c = 2 * math.sqrt(5.0 / 6.0) * beta * math.sqrt(2 * ystar * math.sqrt(R / 2) * MEFF) * xi ** 0.25
            expect = vv_critical(kmax, c, MEFF)[0]
            what = "dt_c (at the undamped xi_max, v = 1)"
        inter = "pair_style gran model %s tangential history\npair_coeff * *" % model
        rc, out = run(script(props, inter, 1e-7, atoms, "fix ts all tdem/timestep vmax 1", "run 0\n"), "stock")
        row = table_rows(out).get("pair_1_1")
        checks.check(row is not None and close(row["dt_critical"], expect, 1e-7),
                     "stock %s: %s %s vs %.9g" % (model, what, row and row["dt_critical"], expect))
    # the scheme: fix tdem/integrate gear5 and the keyword
    for integ, kw, name, wc in (("fix i all tdem/integrate scheme gear5", "", "gear5", 0.8545),
                                ("fix integr all nve/sphere", " scheme ab4", "ab4", 0.4138)):
        rc, out = run(script(lsd_props(), LSD_PAIR, 1e-6, two_spheres(), "fix ts all tdem/timestep" + kw, "run 0\n",
                             integrate=integ), "scheme")
        row = table_rows(out).get("pair_1_1")
        checks.check(("scheme %s" % name) in out and row is not None and close(row["dt_critical"], wc / OMEGA, 2e-4),
                     "scheme %s picked up: dt_c %s vs w_c/omega = %.6g" % (name, row and row["dt_critical"], wc / OMEGA))


# ------------------------------------------------------------------ check modes
def part_check_modes():
    for mode, frac, expect in (("warn", 0.7, "warn"), ("stop", 1.1, "stop"), ("off", 1.1, "off"),
                               ("warn", 1.1, "warn_unstable")):
        dt = frac * DTC
        rc, out = impact(dt, "fix ts all tdem/timestep check %s" % mode, nsteps=20)
        warn = [l for l in out.splitlines() if l.startswith("WARNING") and "tdem/timestep" in l]
        dt_s = "time step dt = %.9g s" % dt
        if expect == "warn":
            checks.check(rc == 0 and warn and dt_s in warn[0] and "0.7 x the critical step" in warn[0],
                         "check warn at 0.7 dt_c: runs, warns '%s'" % (warn[0][:160] if warn else ""))
        elif expect == "warn_unstable":
            checks.check(rc == 0 and warn and "integration is unstable" in warn[0],
                         "check warn at 1.1 dt_c: runs, warns '%s'" % (warn[0][:160] if warn else ""))
        elif expect == "stop":
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            checks.check(rc != 0 and err and dt_s in err[0] and "1.1 x the critical step dt_c = %.9g s" % DTC in err[0]
                         and "use dt <=" in err[0], "check stop at 1.1 dt_c: error '%s'" % (err[0][:200] if err else ""))
        else:
            checks.check(rc == 0 and not warn and "ERROR" not in out, "check off at 1.1 dt_c: silent, runs")


# ------------------------------------------------------------------ run-time check
def part_runtime():
    E, nu, v = 7e10, 0.3, 0.2
    ystar = E / (2 * (1 - nu * nu))
    kmax, dtc, tc, _ = hertz_closed(ystar, MEFF, R / 2, v)
    dt = 0.45 * dtc
    inter = "pair_style gran model tdem/hertz tangential tdem/cundall_strack damping tsuji\npair_coeff * *"
    for mode, nproc in (("stop", 1), ("warn", 1), ("stop", 2)):
        body = ("thermo_style custom step f_ts[1] f_ts[2] f_ts[3]\nthermo 10\nrun 100\n"
                "velocity g1 set 0 0 %r units box\nvelocity g2 set 0 0 %r units box\nrun 100\n" % (50 * v, -50 * v))
        rc, out = run(script(mat_props(1, E, nu, 1.0), inter, dt, two_spheres(gap=0.004, v=v),
                             "fix ts all tdem/timestep vmax %r check %s every 10" % (v, mode), body), "runtime",
                      np_=nproc)
        second = out[out.find("Loop time") + 1:]
        m = re.search(r"run-time check at step (\d+)", second)
        if mode == "stop":
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            fm = re.search(r"is ([0-9.]+) x the critical", err[0]) if err else None
            checks.check(rc != 0 and "Loop time" in out and m and 100 < int(m.group(1)) <= 110 and err
                         and "run-time check" in err[0] and fm and close(float(fm.group(1)), 0.45 * 100 ** 0.2, 1e-6),
                         "velocity x100 between runs, check stop, %d rank(s): stopped at step %s: %s"
                         % (nproc, m and m.group(1), err[0][:220] if err else "no error"))
        else:
            nwarn = second.count("run-time check at step")
            frac = [float(r[3]) for r in thermo_rows(out) if len(r) == 4]
            checks.check(rc == 0 and m and 100 < int(m.group(1)) <= 110 and nwarn == 1 and frac and max(frac) > 1.0
                         and frac[0] < 0.5,
                         "velocity x100 between runs, check warn: one warning at step %s, dt/dt_c %s -> %s"
                         % (m and m.group(1), frac and frac[0], frac and max(frac)))


# ------------------------------------------------------------------ bad input
def part_bad_input():
    cases = [
        ("unknown keyword", "foo 1", ["unknown keyword 'foo'", "vmax V, check off|warn|stop, every N"]),
        ("check value", "check maybe", ["keyword 'check' value 'maybe'", "off|warn|stop"]),
        ("vmax negative", "vmax -1", ["keyword 'vmax' value -1", "(0, inf)"]),
        ("every negative", "every -5", ["keyword 'every' value '-5'", "integer >= 0"]),
        ("fraction above 1", "fraction 2", ["keyword 'fraction' value 2", "(0, 1]"]),
        ("scheme unknown", "scheme rk4", ["keyword 'scheme' value 'rk4'", "velocity_verlet", "gear6"]),
        ("missing value", "check", ["keyword 'check' needs a value"]),
    ]
    for name, kw, expect in cases:
        rc, out = run(script(lsd_props(), LSD_PAIR, 1e-6, two_spheres(), "fix ts all tdem/timestep " + kw, "run 0\n"),
                      "bad")
        err = [l for l in out.splitlines() if l.startswith("ERROR")]
        checks.check(0 < rc < 128 and err and all(e in err[0] for e in expect),
                     "%s: %s" % (name, err[0][:200] if err else "no error, rc %d" % rc))
    # an unsupported law: a warning naming it, the run goes on
    props = mat_props(1, 7e10, 0.3, 0.7)
    inter = "pair_style gran model hertz/stiffness tangential history\npair_coeff * *"
    props += ("fix m_kn all property/global kn peratomtypepair 1 1e5\nfix m_kt all property/global kt peratomtypepair 1 1e5\n"
              "fix m_gn all property/global gamman peratomtypepair 1 10\nfix m_gt all property/global gammat peratomtypepair 1 0\n")
    rc, out = run(script(props, inter, 1e-6, two_spheres(), "fix ts all tdem/timestep", "run 0\n"), "unsupported")
    w = [l for l in out.splitlines() if l.startswith("WARNING") and "hertz/stiffness" in l and "not supported" in l]
    checks.check(rc == 0 and w, "unsupported law hertz/stiffness: warning '%s'" % (w[0][:160] if w else out[-300:]))

# ------------------------------------------------------------------ the six laws published by their models
VMAX = 2.0


def vv_dtc(k, c, meff):
    return vv_critical(k, c, meff)[0]


def pp(name, v, ntypes=1):
    return "fix m_%s all property/global %s peratomtypepair %d %s\n" % (name, name, ntypes,
                                                                       " ".join([repr(v)] * ntypes * ntypes))


COMMON = pp("tangentialStiffnessRatio", 0.3) + pp("coefficientFriction", 0.5)


def wall_of(model):
    return "fix w all wall/gran model %s tangential tdem/cundall_strack primitive type 1 zplane -0.05" % model


def law_case(name, model, settings, props, expect):
    """expect(meff, reff, dist) -> k_max, damping c; rows pair_1_1 (two equal spheres) and the wall."""
    inter = ("pair_style gran model %s tangential tdem/cundall_strack %s\npair_coeff * *\n%s %s"
             % (model, settings, wall_of(model), settings))
    rc, out = run(script(props + COMMON, inter, 1e-7, two_spheres(), "fix ts all tdem/timestep vmax %r" % VMAX,
                         "run 0\n"), name)
    rows = table_rows(out)
    m = mass(R)
    for row_name, meff, reff, dist in (("pair_1_1", MEFF, R / 2, 2 * R), ("wall_w_type_1", m, R, R)):
        k, c = expect(meff, reff, dist)
        dtc = vv_dtc(k, c, meff)
        row = rows.get(row_name)
        ok = (rc == 0 and row is not None and close(row["k_max"], k, 1e-6) and close(row["dt_critical"], dtc, 1e-6)
              and close(row["m*"], meff, 1e-9) and model in row["law"] and "candidates" not in out)
        checks.check(ok, "%s %s: k_max %s vs %.9g, dt_c %s vs %.9g (zeta here %.4g)"
                     % (model, row_name, row and row["k_max"], k, row and row["dt_critical"], dtc,
                        c / (2 * math.sqrt(k * meff))))
        if not ok and rc != 0:
            sys.stdout.write(out[-2000:])


def part_tdem_laws():
    v = VMAX
    # Walton-Braun: k_ul = k_u + s F_max, F_max = k_l xi_max, xi_max = v sqrt(m*/k_l); no damping
    kl, ku, s = 1.0e4, 5.0e4, 2000.0
    law_case("walton_braun", "tdem/walton_braun", "",
             pp("loadingStiffness", kl) + pp("unloadingStiffness", ku) + pp("unloadingStiffnessSlope", s),
             lambda meff, reff, d: (ku + s * kl * v * math.sqrt(meff / kl), 0.0))

    # Thornton: loading Hertz up to xi_y = R* (pi p_y / (2 E*))^2, then F = F_y + pi p_y R* (xi - xi_y),
    # F_y = 2/3 pi p_y R* xi_y; xi_max from the energy 1/2 m* v^2; k_max = 2 E* sqrt(R* xi_max)
    E, nu, py = 1.0e9, 0.3, 5.0e7
    ystar = E / (2 * (1 - nu * nu))

    def thornton(meff, reff, d):
        xy = reff * (math.pi * py / (2 * ystar)) ** 2
        fy = 2.0 / 3.0 * math.pi * py * reff * xy
        wy = 0.4 * fy * xy
        w = 0.5 * meff * v * v
        if w <= wy:
            xm = (15 * meff * v * v / (16 * ystar * math.sqrt(reff))) ** 0.4
        else:
            S = math.pi * py * reff
            u = (-fy + math.sqrt(fy * fy + 2 * S * (w - wy))) / S
            xm = xy + u
        print("info: thornton m* %.4g: yield overlap %.4g, xi_max %.4g (plastic: %s)" % (meff, xy, xm, w > wy))
        return 2 * ystar * math.sqrt(reff * xm), 0.0
    law_case("thornton", "tdem/thornton", "",
             "fix m_E all property/global youngsModulus peratomtype %r\n"
             "fix m_nu all property/global poissonsRatio peratomtype %r\n" % (E, nu) + pp("yieldPressure", py),
             thornton)

    # power law: xi_max = ((p+1) m* v^2 / (2 a_l))^(1/(p+1)), F_max = a_l xi_max^p,
    # unloading amplitude d = (F_max/a_ul)^(1/(p+q)); k = max(p F_max/xi_max, (p+q) F_max/d)
    al, p, aul, q = 2e5, 1.5, 2e7, 0.5

    def power(meff, reff, d):
        xm = ((p + 1) * meff * v * v / (2 * al)) ** (1 / (p + 1))
        fm = al * xm ** p
        dd = (fm / aul) ** (1 / (p + q))
        assert dd <= xm
        return max(p * fm / xm, (p + q) * fm / dd), 0.0
    law_case("power_law", "tdem/power_law", "",
             pp("loadingCoefficient", al) + pp("loadingExponent", p) + pp("unloadingCoefficient", aul) +
             pp("unloadingExponentIncrement", q), power)

    # continuous potential from touch (X = d): 1/2 m* v^2 = eps ((d/X_min)^n - 1),
    # k = (n+1) n eps d^n / X_min^(n+2), damping gamma
    eps, n, gam = 1e-3, 24.0, 0.05

    def potential(meff, reff, d):
        xmin = d * (1 + meff * v * v / (2 * eps)) ** (-1 / n)
        return (n + 1) * n * eps * d ** n / xmin ** (n + 2), gam
    for lf in ("off", "on"):
        law_case("continuous_potential", "tdem/continuous_potential", "limitForce %s" % lf,
                 pp("potentialEnergy", eps) + pp("potentialExponent", n) + pp("dampingCoefficient", gam), potential)

    # extended linear, e = c0 constant, t_c = c0 v^-c1 (falls with v0): the stiffest at v_max;
    # zero overlap: zeta = -ln e / sqrt(pi^2 + ln^2 e), omega0 = pi / (t_c sqrt(1 - zeta^2))
    e0, t0, t1 = 0.8, 5e-4, 0.2

    def ext_lin(meff, reff, d):
        le = math.log(e0)
        z = -le / math.sqrt(math.pi ** 2 + le * le)
        w0 = math.pi / (t0 * v ** (-t1) * math.sqrt(1 - z * z))
        k = meff * w0 * w0
        return k, 2 * z * math.sqrt(k * meff)
    law_case("extended_linear", "tdem/extended_linear", "restitutionFit constant contactTimeFit power limitForce off",
             pp("restitutionFitC0", e0) + pp("contactTimeFitC0", t0) + pp("contactTimeFitC1", t1), ext_lin)

    # extended Hertz, e = c0 constant: Tsuji alpha = sqrt(5) zeta(e) (zero overlap); at the undamped
    # xi_max = (5 m* v^2 / (4 k~))^(2/5): k = 3/2 k~ sqrt(xi_max), c = alpha sqrt(m* k~) xi_max^(1/4)
    E2, nu2, e2 = 5e7, 0.4, 0.7
    ystar2 = E2 / (2 * (1 - nu2 * nu2))

    def ext_hertz(meff, reff, d):
        kt = 4.0 / 3.0 * ystar2 * math.sqrt(reff)
        xm = (5 * meff * v * v / (4 * kt)) ** 0.4
        le = math.log(e2)
        alpha = -math.sqrt(5) * le / math.sqrt(le * le + math.pi ** 2)
        return 1.5 * kt * math.sqrt(xm), alpha * math.sqrt(meff * kt) * xm ** 0.25
    law_case("extended_hertz", "tdem/extended_hertz", "restitutionFit constant limitForce off",
             "fix m_E all property/global youngsModulus peratomtype %r\n"
             "fix m_nu all property/global poissonsRatio peratomtype %r\n" % (E2, nu2) + pp("restitutionFitC0", e2),
             ext_hertz)


# ------------------------------------------------------------------ tdem/lsd settings
def zero_force_e_tc(z, w0):
    """Damped linear oscillator whose contact ends when the force k x + c x' returns to zero
    (limitForce on): x = v/wd e^(-z w0 t) sin(wd t); x'' = 0 at wd t = pi - atan(2 z s / (1 - 2 z^2))
    (z < 1/sqrt 2); e = |x'(t_c)| / v."""
    s = math.sqrt(1 - z * z)
    wd = w0 * s
    ph = math.pi - math.atan2(2 * z * s, 1 - 2 * z * z)
    tc = ph / wd
    e = math.exp(-z * w0 * tc) * abs(wd * math.cos(ph) - z * w0 * math.sin(ph)) / wd
    return e, tc


def from_e_tc(e, tc, end, meff):
    """k, gamma of the linear law giving restitution e and contact time tc for m* in convention end."""
    if end == "zero_overlap":
        le = math.log(e)
        z = -le / math.sqrt(math.pi ** 2 + le * le)
        w0 = math.pi / (tc * math.sqrt(1 - z * z))
    else:
        lo, hi = 0.0, 1.0 / math.sqrt(2) - 1e-12  # e falls with z
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if zero_force_e_tc(mid, 1.0)[0] > e:
                lo = mid
            else:
                hi = mid
        z = 0.5 * (lo + hi)
        w0 = zero_force_e_tc(z, 1.0)[1] / tc  # t_c scales as 1/w0
    k = meff * w0 * w0
    return k, 2 * z * math.sqrt(k * meff)


def part_lsd_settings():
    e, tc = 0.6, 2e-4
    props = lsd_props() + pp("coefficientRestitution", e) + pp("contactTime", tc) + \
        pp("tangentialStiffnessRatio", 0.3)
    got = {}
    for settings, end, expect in (
            ("parameters restitution limitForce off", "zero_overlap", from_e_tc(e, tc, "zero_overlap", MEFF)),
            ("parameters restitution limitForce on", "zero_force", from_e_tc(e, tc, "zero_force", MEFF)),
            ("parameters stiffness limitForce on", "zero_force", (K, GN * MEFF))):
        inter = "pair_style gran model tdem/lsd tangential tdem/cundall_strack %s\npair_coeff * *" % settings
        rc, out = run(script(props, inter, 1e-7, two_spheres(), "fix ts all tdem/timestep vmax 1", "run 0\n"),
                      "lsd_settings")
        row = table_rows(out).get("pair_1_1")
        k, c = expect
        dtc = vv_dtc(k, c, MEFF)
        words = settings.split()
        named = row is not None and ("parameters_%s" % words[1]) in row["law"] and \
            ("limitForce_%s" % words[3]) in row["law"] and ("(%s)" % end.replace("_", "_")) in row["law"]
        ok = rc == 0 and named and close(row["k_max"], k, 1e-6) and close(row["dt_critical"], dtc, 1e-6) and \
            "candidates" not in out and "smallest dt_c of" not in out
        got[settings] = row and row["dt_critical"]
        checks.check(ok, "tdem/lsd %s: law %s, k_max %s vs %.9g, dt_c %s vs %.9g"
                     % (settings, row and row["law"], row and row["k_max"], k, row and row["dt_critical"], dtc))
    # absolute_damping on: gamma = gamman_abs (not m* gamman)
    ga = 0.9
    props_abs = props + pp("gamman_abs", ga) + pp("gammat_abs", 0.0)
    inter = ("pair_style gran model tdem/lsd tangential tdem/cundall_strack parameters stiffness absolute_damping on\n"
             "pair_coeff * *")
    rc, out = run(script(props_abs, inter, 1e-7, two_spheres(), "fix ts all tdem/timestep vmax 1", "run 0\n"),
                  "lsd_settings")
    row = table_rows(out).get("pair_1_1")
    dtc = vv_dtc(K, ga, MEFF)
    checks.check(rc == 0 and row is not None and "absolute_damping_on" in row["law"] and
                 close(row["dt_critical"], dtc, 1e-6) and close(row["zeta"], ga / (2 * math.sqrt(K * MEFF)), 1e-6),
                 "tdem/lsd absolute_damping on: dt_c %s vs %.9g (gamma = gamman_abs %g)" % (row and row["dt_critical"], dtc, ga))
    # tdem/hertz damping linear with coefficientRestitution present too: only the linear damper counts
    E, nu, c0 = 7e10, 0.3, 2.0
    kmax, _, _, _ = hertz_closed(E / (2 * (1 - nu * nu)), MEFF, R / 2, 1.0)
    dtc = vv_dtc(kmax, c0, MEFF)
    inter = "pair_style gran model tdem/hertz tangential tdem/cundall_strack damping linear\npair_coeff * *"
    rc, out = run(script(mat_props(1, E, nu, 0.5) + pp("dampingCoefficient", c0), inter, 1e-7, two_spheres(),
                         "fix ts all tdem/timestep vmax 1", "run 0\n"), "hertz_settings")
    row = table_rows(out).get("pair_1_1")
    checks.check(rc == 0 and row is not None and "damping_linear" in row["law"] and "candidates" not in out and
                 close(row["dt_critical"], dtc, 1e-6),
                 "tdem/hertz damping linear (e also given): dt_c %s vs %.9g (k_max 3/2 k~ sqrt(xi_max), c = %g)"
                 % (row and row["dt_critical"], dtc, c0))
    a, b = got.get("parameters restitution limitForce off"), got.get("parameters restitution limitForce on")
    checks.check(a and b and abs(a - b) > 1e-3 * a,
                 "limitForce off / on advise different steps (%s vs %s): no longer the smaller of both" % (a, b))



# ------------------------------------------------------------------ strong damping (issue 17)
def part_overdamped():
    """Velocity Verlet's critical step 2 (sqrt(1 + zeta^2) - zeta) / omega over the whole damping
    range; e = 1e-5 with limitForce on (zeta 158) was reported as "unstable at every step"."""
    import oscillator_ref as OR
    for z in (0.5, 2.0, 30.0, 158.0, 1e3, 1e4):
        gn = 2.0 * z * math.sqrt(K * MEFF) / MEFF
        rc, out = run(script(lsd_props(gn=gn), LSD_PAIR, 1e-9, two_spheres(), "fix ts all tdem/timestep vmax 1",
                             "run 0\n"), "overdamped")
        row = table_rows(out).get("pair_1_1")
        dtc = vv_dtc(K, gn * MEFF, MEFF)
        checks.check(rc == 0 and row is not None and close(row["dt_critical"], dtc, 1e-7),
                     "tdem/lsd stiffness zeta %g: dt_c %s vs closed form %.9g" % (z, row and row["dt_critical"], dtc))
    tc = 1e-4
    for e in (1e-5, 1e-3, 0.3):
        z = OR.zeta_for_zero_force_e(e)
        w = OR.zero_force_end(z)[1] / tc
        dtc = 2.0 / w * (math.sqrt(1.0 + z * z) - z)
        props = lsd_props() + pp("coefficientRestitution", e) + pp("contactTime", tc) + \
            pp("tangentialStiffnessRatio", 0.3)
        inter = ("pair_style gran model tdem/lsd tangential tdem/cundall_strack parameters restitution limitForce on\n"
                 "pair_coeff * *")
        rc, out = run(script(props, inter, 1e-9, two_spheres(), "fix ts all tdem/timestep vmax 1 check stop",
                             "run 10\n"), "overdamped")
        row = table_rows(out).get("pair_1_1")
        checks.check(rc == 0 and row is not None and close(row["zeta"], z, 1e-6) and close(row["dt_critical"], dtc, 1e-6)
                     and "unstable at every step" not in out,
                     "tdem/lsd restitution e %g limitForce on: zeta %s vs %.9g, dt_c %s vs %.9g (exit %d)"
                     % (e, row and row["zeta"], z, row and row["dt_critical"], dtc, rc))


PARTS = {"acceptance": part_acceptance, "closed_forms": part_closed_forms, "check_modes": part_check_modes,
         "runtime": part_runtime, "bad_input": part_bad_input, "tdem_laws": part_tdem_laws,
         "lsd_settings": part_lsd_settings, "overdamped": part_overdamped}
for name, f in PARTS.items():
    if args.part in ("all", name):
        f()
checks.done()
