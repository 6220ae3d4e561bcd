#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/timestep in LAMMPS (issue 8). Parts (--part NAME):

  acceptance  head-on two-sphere impact, linear law (lsd stiffness K GAMMA damping absolute), velocity
              Verlet (nve/sphere); dt_c = 2/omega (sqrt(1+zeta^2) - zeta) computed here.
              * 1.1 dt_c with `check stop`: the run is stopped at set-up (error names dt and dt_c);
              * 1.1 dt_c with `check off`, the two spheres pressed together by opposite constant forces
                (an enduring contact, equilibrium overlap 10 v0/omega): the oscillation grows until
                the spheres separate - the integration blows up (impossible for the damped physics);
              * 0.5 dt_c (`check stop` lets it run): the pressed pair stays in contact, the
                oscillation decays; the free impact gives e within 0.15 of the closed form
                exp(-pi zeta/sqrt(1-zeta^2)) (3.4 steps per contact, docs/timestep.md) and equals
                the restitution of velocity Verlet re-implemented here to 1e-9.
  closed_forms the printed table against closed forms computed here: linear dt_c; Hertz (undamped)
              k_max = 3/2 k~ sqrt(xi_max), xi_max = (5 m* v^2/(4 k~))^(2/5), dt_c = 2/omega, contact
              time 2.8683 (m*^2/(R* E*^2 v))^(1/5), Rayleigh time pi R sqrt(rho/G)/(0.1631 nu +
              0.8766); m*, R* of the lightest/smallest atoms of the type pair (two sizes per type),
              walls (m* = m, R* = R); stock gran/hooke/history and gran/hertz/history; the scheme
              of fix tdem/integrate (gear5: smaller dt_c) and of `scheme`.
  check_modes `check warn` warns, `check stop` stops with the numbers, `check off` stays silent.
  runtime     Hertz law, check stop, dt = 0.45 dt_c(vmax): a first run passes; velocities raised by
              100 between runs: the run-time check (every 10) stops the run at step <= first + 10
              (dt_c ~ v^-1/5: 0.45 * 100^(1/5) = 1.13 > 1); with check warn it warns once and runs on.
  bad_input   every keyword with a bad value: error naming the keyword, the value, the allowed values.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import lmp_common as lc  # noqa: E402
import oscillator_ref as OR  # noqa: E402

argv = list(sys.argv)
part = "all"
if "--part" in argv:
    k = argv.index("--part")
    part = argv[k + 1]
    del argv[k:k + 2]
args = lc.parse_args(argv)
chk = lc.Checker("lammps.timestep." + part)
EXE = args["tdem"]

RHO = 2500.0
R = 0.005


def mass(r, rho=RHO):
    return rho * 4.0 / 3.0 * math.pi * r ** 3


def vv_critical(k, gamma, meff):
    w = math.sqrt(k / meff)
    z = gamma / (2.0 * math.sqrt(k * meff))
    return 2.0 / w * (math.sqrt(1.0 + z * z) - z), z, w


HEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box      {ntypes} box
{atoms}
set             group all density {rho}
velocity        all set 0 0 0
{velocities}
neighbor        0.001 bin
neigh_modify    delay 0
{interaction}
{integrate}
{timestep_fix}
timestep        {dt!r}
"""


def two_spheres(gap=0.0005, r1=R, r2=R, v=0.5, ntypes=1, t2=1):
    z1 = -(r1 + gap / 2)
    z2 = r2 + gap / 2
    atoms = ("create_atoms 1 single 0 0 %r units box\ncreate_atoms %d single 0 0 %r units box\n"
             "set atom 1 diameter %r\nset atom 2 diameter %r" % (z1, t2, z2, 2 * r1, 2 * r2))
    vel = "set atom 1 vz %r\nset atom 2 vz %r" % (v / 2, -v / 2)
    return atoms, vel, ntypes


def script(atoms, vel, ntypes, interaction, dt, tsfix, integrate="fix nve all nve/sphere", body=""):
    return HEAD.format(ntypes=ntypes, atoms=atoms, rho=RHO, velocities=vel, interaction=interaction,
                       integrate=integrate, timestep_fix=tsfix, dt=dt) + body


def lsd_pair(k, g):
    return ("pair_style tdem/gran\npair_coeff * * normal lsd stiffness %r %r tangential cundall_strack "
            "1000 0 0.5 damping absolute" % (k, g))


def table_rows(out):
    """Rows of the printed table: {what: {column: value}}."""
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


def close(a, b, tol):
    return abs(a - b) <= tol * abs(b)


# ------------------------------------------------------------------ acceptance
K = 1.0e4
E_REST = 0.8
MEFF = mass(R) / 2


def gamma_for(e, k, meff):
    ln = math.log(e)
    beta = -ln / math.sqrt(math.pi ** 2 + ln * ln)
    return 2.0 * beta * math.sqrt(k * meff)


G = gamma_for(E_REST, K, MEFF)
DTC, ZETA, OMEGA = vv_critical(K, G, MEFF)


def vv_restitution(dt, gap, v):
    """Velocity Verlet (nve/sphere: half kick, drift, force, half kick) on the head-on pair with the
    lsd force k xi + gamma xi_dot (zero-overlap end), as LAMMPS steps it; returns e."""
    m = mass(R)
    z1, z2 = -(R + gap / 2), R + gap / 2
    v1, v2 = v / 2, -v / 2

    def force(z1, z2, v1, v2):
        xi = 2 * R - (z2 - z1)
        if xi <= 0.0:
            return 0.0
        return K * xi + G * (v1 - v2)   # on atom 2 (+z); atom 1 gets -F

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


def run_impact(dt, tsfix, gap=0.0005, v=0.5, nsteps=None, check=True):
    atoms, vel, nt = two_spheres(gap=gap, v=v)
    nsteps = nsteps or int((gap / v + 4.0 * math.pi / OMEGA) / dt) + 5
    body = ("variable dv equal vz[2]-vz[1]\nthermo_style custom step v_dv\nthermo_modify format float %.17g\n"
            "thermo {n}\nrun {n}\n").format(n=nsteps)
    d = lc.workdir("ts_acc")
    return lc.run(EXE, script(atoms, vel, nt, lsd_pair(K, G), dt, tsfix, body=body), d, check=check)


def last_thermo(out, col=1):
    rows = [r for r in lc.thermo_blocks(out) if not r.startswith("Step")]
    return float(rows[-1].split()[col])


def run_pressed(dt, tsfix, v0=0.1, nsteps=4000):
    """The pair pressed together by opposite forces F (xi_eq = F/k = 10 v0/omega), touching at start
    with approach velocity v0. Returns (min overlap after the first step, max overlap, final overlap)."""
    m = mass(R)
    xi_eq = 10.0 * v0 / OMEGA
    F = K * xi_eq * MEFF / (m / 2)  # relative acceleration 2F/m = k xi_eq / m*
    atoms = ("create_atoms 1 single 0 0 %r units box\ncreate_atoms 1 single 0 0 %r units box\n"
             "set group all diameter %r" % (-R, R, 2 * R))
    vel = "set atom 1 vz %r\nset atom 2 vz %r" % (v0 / 2, -v0 / 2)
    body = ("group a1 id 1\ngroup a2 id 2\nfix f1 a1 addforce 0 0 %r\nfix f2 a2 addforce 0 0 %r\n"
            "variable xi equal %r-(z[2]-z[1])\nthermo_style custom step v_xi\n"
            "thermo_modify format float %%.17g\nthermo 1\nrun %d\n" % (F, -F, 2 * R, nsteps))
    d = lc.workdir("ts_press")
    rc, out = lc.run(EXE, script(atoms, vel, 1, lsd_pair(K, G), dt, tsfix, body=body), d, check=False)
    xs = [float(r.split()[1]) for r in lc.thermo_blocks(out) if not r.startswith("Step")]
    if rc != 0:
        # the only allowed failure: the atoms flew out of the box
        if "Lost atoms" not in out:
            sys.stdout.write(out[-3000:])
            raise RuntimeError("pressed pair: unexpected failure")
        print("info: pressed pair at dt = %.6g: atoms lost at step %d" % (dt, len(xs)))
        return min(xs[1:] + [-1.0]), max(xs), math.nan, xi_eq
    return min(xs[1:]), max(xs), xs[-1], xi_eq


def part_acceptance():
    print("linear law: k = %g N/m, gamma = %.6g kg/s, m* = %.6g kg, zeta = %.6g, dt_c(VV) = %.9g s"
          % (K, G, MEFF, ZETA, DTC))
    # 1.1 dt_c, check stop: stopped at set-up
    rc, out = run_impact(1.1 * DTC, "fix ts all tdem/timestep check stop", check=False)
    m = re.search(r"critical step dt_c = ([0-9.eE+-]+) s", out)
    chk.check(rc != 0 and "ERROR" in out and "tdem/timestep (check stop)" in out and m is not None
              and close(float(m.group(1)), DTC, 1e-7),
              "1.1 dt_c, check stop: run stopped at set-up, printed dt_c %s vs %.9g (rc %d)"
              % (m.group(1) if m else "?", DTC, rc))
    # 1.1 dt_c, check off: the pressed pair blows apart
    mn, mx, fin, xeq = run_pressed(1.1 * DTC, "fix ts all tdem/timestep check off")
    chk.check(mn < 0.0 or mx > 3 * xeq or not math.isfinite(fin),
              "1.1 dt_c, enduring contact: overlap left the well (min %.3g, max %.3g, xi_eq %.3g)"
              % (mn, mx, xeq))
    # 0.5 dt_c: runs with check stop, the pressed pair stays and calms down
    mn, mx, fin, xeq = run_pressed(0.5 * DTC, "fix ts all tdem/timestep check stop")
    chk.check(mn > 0.0 and mx < 2.5 * xeq and abs(fin - xeq) < 0.05 * xeq,
              "0.5 dt_c, enduring contact: stays in contact and decays (min %.3g, max %.3g, final %.4g, "
              "xi_eq %.4g)" % (mn, mx, fin, xeq))
    e_closed = math.exp(-math.pi * ZETA / math.sqrt(1 - ZETA ** 2))
    for gap in (0.0005, 0.000537, 0.000571):
        dt = 0.5 * DTC
        rc, out = run_impact(dt, "fix ts all tdem/timestep check stop", gap=gap)
        e = last_thermo(out) / 0.5
        e_vv = vv_restitution(dt, gap, 0.5)
        chk.check(math.isfinite(e) and abs(e - e_closed) < 0.15 and close(e, e_vv, 1e-9),
                  "0.5 dt_c, free impact (gap %g): e = %.9f, closed form %.6f, velocity Verlet here %.9f"
                  % (gap, e, e_closed, e_vv))
    # for the record: the free impact at 1.1 dt_c without the check
    rc, out = run_impact(1.1 * DTC, "fix ts all tdem/timestep check off")
    print("info: free impact at 1.1 dt_c, check off: e = %.4f (any value: 1-2 steps per contact)"
          % (last_thermo(out) / 0.5))


# ------------------------------------------------------------------ closed forms
def hertz_closed(E, nu, meff, reff, v):
    estar = E / (2 * (1 - nu * nu))
    kt = 4.0 / 3.0 * estar * math.sqrt(reff)
    xi = (5 * meff * v * v / (4 * kt)) ** 0.4
    kmax = 1.5 * kt * math.sqrt(xi)
    tc = 2.8683 * (meff * meff / (reff * estar * estar * v)) ** 0.2
    return kmax, 2.0 / math.sqrt(kmax / meff), tc


def rayleigh(E, nu, r, rho):
    Gs = E / (2 * (1 + nu))
    return math.pi * r * math.sqrt(rho / Gs) / (0.1631 * nu + 0.8766)


def part_closed_forms():
    # two types, each with two sizes: the lightest of each type count
    r1a, r1b, r2a, r2b = 0.005, 0.004, 0.003, 0.0035
    atoms = "\n".join([
        "create_atoms 1 single -0.02 0 0 units box", "create_atoms 1 single 0.02 0 0 units box",
        "create_atoms 2 single 0 -0.02 0 units box", "create_atoms 2 single 0 0.02 0 units box",
        "set atom 1 diameter %r" % (2 * r1a), "set atom 2 diameter %r" % (2 * r1b),
        "set atom 3 diameter %r" % (2 * r2a), "set atom 4 diameter %r" % (2 * r2b)])
    m1, m2 = mass(r1b), mass(r2a)
    E, nu, v = 7e10, 0.25, 2.0
    dt = 1e-7
    body = "run 0\n"
    inter = ("pair_style tdem/gran\npair_coeff * * normal hertz %r %r tangential cundall_strack 0.8 0.5\n"
             "fix w all tdem/wall/gran normal lsd stiffness %r %r tangential cundall_strack 1000 0 0.5 "
             "damping absolute zplane -0.05 0.05" % (E, nu, K, G))
    d = lc.workdir("ts_cf")
    _, out = lc.run(EXE, script(atoms, "", 2, inter, dt, "fix ts all tdem/timestep vmax %r" % v, body=body), d)
    rows = table_rows(out)
    for (i, j, mi, mj, ri, rj) in ((1, 1, m1, m1, r1b, r1b), (1, 2, m1, m2, r1b, r2a), (2, 2, m2, m2, r2a, r2a)):
        meff, reff = mi * mj / (mi + mj), ri * rj / (ri + rj)
        kmax, dtc, tc = hertz_closed(E, nu, meff, reff, v)
        tr = min(rayleigh(E, nu, ri, RHO), rayleigh(E, nu, rj, RHO))
        row = rows.get("pair_%d_%d" % (i, j))
        ok = row is not None and close(row["m*"], meff, 1e-8) and close(row["R*"], reff, 1e-8) and \
            close(row["k_max"], kmax, 1e-7) and close(row["dt_critical"], dtc, 1e-7) and \
            close(row["t_contact"], tc, 2e-4) and close(row["T_Rayleigh"], tr, 1e-7) and \
            close(row["steps/contact"], tc / dt, 2e-4)
        chk.check(ok, "hertz pair %d %d: m* %s/%.9g R* %s/%.9g k_max %s/%.9g dt_c %s/%.9g t_c %s/%.9g T_R %s/%.9g"
                  % (i, j, row and row["m*"], meff, row and row["R*"], reff, row and row["k_max"], kmax,
                     row and row["dt_critical"], dtc, row and row["t_contact"], tc, row and row["T_Rayleigh"], tr))
    for t, m in ((1, m1), (2, m2)):
        dtc, z, w = vv_critical(K, G, m)
        row = rows.get("wall_w_type_%d" % t)
        chk.check(row is not None and close(row["m*"], m, 1e-8) and close(row["dt_critical"], dtc, 1e-7)
                  and close(row["dt/dt_c"], dt / dtc, 1e-7),
                  "linear wall, type %d: m* %s/%.9g dt_c %s/%.9g" % (t, row and row["m*"], m,
                                                                    row and row["dt_critical"], dtc))
    # stock gran/hooke/history (F = kn xi + m* gamman xi_dot) and gran/hertz/history
    atoms, vel, nt = two_spheres()
    kn, gn = 2e4, 30.0
    for style in ("gran/hooke/history", "gran/hertz/history"):
        inter = "pair_style %s %r NULL %r NULL 0.5 0\npair_coeff * *" % (style, kn, gn)
        _, out = lc.run(EXE, script(atoms, vel, nt, inter, 1e-6, "fix ts all tdem/timestep vmax 1", body="run 0\n"),
                        lc.workdir("ts_stock"))
        row = table_rows(out).get("pair_1_1")
        if style == "gran/hooke/history":
            dtc, z, w = vv_critical(kn, MEFF * gn, MEFF)
            ok = row is not None and close(row["dt_critical"], dtc, 1e-7) and close(row["zeta"], z, 1e-7)
            chk.check(ok, "stock %s: dt_c %s vs %.9g" % (style, row and row["dt_critical"], dtc))
        else:
            # F = sqrt(R* xi) kn xi: k~ = kn sqrt(R*); undamped bound on k_max at v = 1 m/s
            reff = R / 2
            kt = kn * math.sqrt(reff)
            xi = (5 * MEFF / (4 * kt)) ** 0.4
            kmax = 1.5 * kt * math.sqrt(xi)
            ok = row is not None and close(row["k_max"], kmax, 1e-7)
            chk.check(ok, "stock %s: k_max %s vs %.9g (k~ = kn sqrt(R*))" % (style, row and row["k_max"], kmax))
    # normal luding (docs/adding_a_law.md, a law added as a unit): its advice from the unit, against
    # its closed forms re-typed here: xi_max = v sqrt(m*/k1) below xi_lim, k_max = k2(xi_max)
    # = k1 + (k2max - k1) xi_max / xi_lim, dt_c = 2 / omega, t_c = pi/2 (sqrt(m*/k1) + sqrt(m*/k2))
    atoms, vel, nt = two_spheres()
    k1, k2m, phi, v = 1e4, 5e4, 0.1, 1.0
    meff, reff = mass(R) / 2, R / 2
    xl = k2m / (k2m - k1) * phi * 2 * reff
    xm = v * math.sqrt(meff / k1)
    k2 = k1 + (k2m - k1) * xm / xl
    tc = 0.5 * math.pi * (math.sqrt(meff / k1) + math.sqrt(meff / k2))
    inter = "pair_style tdem/gran\npair_coeff * * normal luding %r %r %r tangential cundall_strack 0.8 0.5" % (k1, k2m, phi)
    _, out = lc.run(EXE, script(atoms, vel, nt, inter, 1e-6, "fix ts all tdem/timestep vmax %r" % v, body="run 0\n"),
                    lc.workdir("ts_luding"))
    row = table_rows(out).get("pair_1_1")
    ok = row is not None and xm < xl and close(row["k_max"], k2, 1e-7) and \
        close(row["dt_critical"], 2.0 * math.sqrt(meff / k2), 1e-7) and close(row["t_contact"], tc, 1e-7)
    chk.check(ok, "luding pair: k_max %s/%.9g dt_c %s/%.9g t_c %s/%.9g"
              % (row and row["k_max"], k2, row and row["dt_critical"], 2.0 * math.sqrt(meff / k2),
                 row and row["t_contact"], tc))
    # normal continuous_potential from touch (X = d = R_i + R_j): 1/2 m* v^2 = eps ((d/X_min)^n - 1),
    # k_max = (n+1) n eps d^n / X_min^(n+2), damping gamma; zeta = gamma / (2 sqrt(k m*))
    eps, n, gam, v = 1e-3, 24.0, 0.05, 1.0
    meff, d = mass(R) / 2, 2 * R
    xmin = d * (1 + meff * v * v / (2 * eps)) ** (-1 / n)
    kmax = (n + 1) * n * eps * d ** n / xmin ** (n + 2)
    inter = ("pair_style tdem/gran\npair_coeff * * normal continuous_potential %r %r %r tangential cundall_strack 0.8 0.5"
             % (eps, n, gam))
    _, out = lc.run(EXE, script(atoms, vel, nt, inter, 1e-6, "fix ts all tdem/timestep vmax %r" % v, body="run 0\n"),
                    lc.workdir("ts_cpot"))
    row = table_rows(out).get("pair_1_1")
    ok = row is not None and close(row["k_max"], kmax, 1e-7) and close(row["zeta"], gam / (2 * math.sqrt(kmax * meff)), 1e-7)
    chk.check(ok, "continuous_potential pair: k_max %s/%.9g zeta %s/%.9g"
              % (row and row["k_max"], kmax, row and row["zeta"], gam / (2 * math.sqrt(kmax * meff))))
    # the scheme: fix tdem/integrate gear5 (read from the fix) and the keyword `scheme`
    # w_c at zeta = 0.0709 (e = 0.8), docs/timestep.md: gear5 0.8545, ab4 0.4138 (4 digits)
    for integ, kw, name, wc in (("fix i all tdem/integrate scheme gear5", "", "gear5", 0.8545),
                                ("fix nve all nve/sphere", " scheme ab4", "ab4", 0.4138)):
        _, out = lc.run(EXE, script(atoms, vel, nt, lsd_pair(K, G), 1e-6, "fix ts all tdem/timestep" + kw,
                                    integrate=integ, body="run 0\n"), lc.workdir("ts_scheme"))
        row = table_rows(out).get("pair_1_1")
        chk.check(("scheme %s" % name) in out and row is not None and close(row["dt_critical"], wc / OMEGA, 2e-4),
                  "scheme %s picked up (%s): dt_c %s vs w_c/omega = %.6g"
                  % (name, integ.split()[3] if not kw else "keyword", row and row["dt_critical"], wc / OMEGA))


# ------------------------------------------------------------------ check modes
def part_check_modes():
    for mode, frac, expect in (("warn", 0.7, "warn"), ("stop", 1.1, "stop"), ("off", 1.1, "off"),
                               ("warn", 1.1, "warn_unstable")):
        dt = frac * DTC
        rc, out = run_impact(dt, "fix ts all tdem/timestep check %s" % mode, nsteps=20, check=False)
        warn = [l for l in out.splitlines() if l.startswith("WARNING") and "tdem/timestep" in l]
        dt_s = "time step dt = %s s" % ("%.9g" % dt)
        if expect == "warn":
            chk.check(rc == 0 and warn and dt_s in warn[0] and "0.7 x the critical step" in warn[0],
                      "check warn at 0.7 dt_c: runs, warns '%s'" % (warn[0][:160] if warn else ""))
        elif expect == "warn_unstable":
            chk.check(rc == 0 and warn and "integration is unstable" in warn[0],
                      "check warn at 1.1 dt_c: runs, warns '%s'" % (warn[0][:160] if warn else ""))
        elif expect == "stop":
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            chk.check(rc != 0 and err and dt_s in err[0] and "1.1 x the critical step dt_c = %.9g s" % DTC in err[0]
                      and "use dt <=" in err[0],
                      "check stop at 1.1 dt_c: error '%s'" % (err[0][:200] if err else ""))
        else:
            chk.check(rc == 0 and not warn and "ERROR" not in out, "check off at 1.1 dt_c: silent, runs")


# ------------------------------------------------------------------ run-time check
def part_runtime():
    E, nu, v = 7e10, 0.3, 0.2
    meff, reff = MEFF, R / 2
    kmax, dtc, tc = hertz_closed(E, nu, meff, reff, v)
    dt = 0.45 * dtc
    atoms, vel, nt = two_spheres(gap=0.004, v=v)
    inter = "pair_style tdem/gran\npair_coeff * * normal hertz %r %r tangential cundall_strack 0.8 0.5" % (E, nu)
    for mode, nproc in (("stop", 1), ("warn", 1), ("stop", 2)):
        body = ("thermo_style custom step f_ts[1] f_ts[2] f_ts[3]\nthermo 10\nrun 100\n"
                "set atom 1 vz %r\nset atom 2 vz %r\nrun 100\n" % (50 * v, -50 * v))
        rc, out = lc.run(EXE, script(atoms, vel, nt, inter, dt, "fix ts all tdem/timestep vmax %r check %s every 10"
                                     % (v, mode), body=body), lc.workdir("ts_rt"), check=False, np_=nproc,
                         mpirun=args["mpirun"])
        second = out[out.find("Loop time") + 1:]
        m = re.search(r"run-time check at step (\d+)", second)
        first_ok = "Loop time" in out
        if mode == "stop":
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            chk.check(rc != 0 and first_ok and m and 100 < int(m.group(1)) <= 110 and err
                      and "run-time check" in err[0] and "the integration is unstable" in err[0]
                      and re.search(r"is ([0-9.]+) x the critical", err[0])
                      and close(float(re.search(r"is ([0-9.]+) x the critical", err[0]).group(1)),
                                0.45 * 100 ** 0.2, 1e-6),
                      "velocity x100 between runs, check stop, %d rank(s): stopped at step %s: %s"
                      % (nproc, m and m.group(1), err[0][:220] if err else "no error"))
        else:
            nwarn = second.count("run-time check at step")
            rows = [r.split() for r in lc.thermo_blocks(out) if not r.startswith("Step")]
            frac = [float(r[3]) for r in rows]
            chk.check(rc == 0 and m and 100 < int(m.group(1)) <= 110 and nwarn == 1 and max(frac) > 1.0
                      and frac[0] < 0.5,
                      "velocity x100 between runs, check warn: one warning at step %s, dt/dt_c %.3g -> %.3g"
                      % (m and m.group(1), frac[0], max(frac)))
        print("info: expected dt/dt_c after the raise: %.4f" % (0.45 * 100 ** 0.2))


# ------------------------------------------------------------------ bad input
def part_bad_input():
    cases = [
        ("unknown keyword", "foo 1", ["unknown keyword 'foo'", "vmax V, check off|warn|stop, every N"]),
        ("check value", "check maybe", ["keyword 'check' value 'maybe'", "off|warn|stop"]),
        ("vmax negative", "vmax -1", ["keyword 'vmax' value -1", "(0, inf)"]),
        ("vmax text", "vmax fast", ["keyword 'vmax' value 'fast' is not a number"]),
        ("every negative", "every -5", ["keyword 'every' value '-5'", "integer >= 0"]),
        ("fraction above 1", "fraction 2", ["keyword 'fraction' value 2", "(0, 1]"]),
        ("scheme unknown", "scheme rk4", ["keyword 'scheme' value 'rk4'", "velocity_verlet", "gear6"]),
        ("missing value", "check", ["keyword 'check' needs a value"]),
    ]
    atoms, vel, nt = two_spheres()
    for name, kw, expect in cases:
        rc, out = lc.run(EXE, script(atoms, vel, nt, lsd_pair(K, G), 1e-6, "fix ts all tdem/timestep " + kw,
                                     body="run 0\n"), lc.workdir("ts_bad"), check=False)
        err = [l for l in out.splitlines() if l.startswith("ERROR")]
        chk.check(0 < rc < 128 and err and all(e in err[0] for e in expect),
                  "%s: %s" % (name, err[0][:200] if err else "no error, rc %d" % rc))
    rc, out = lc.run(EXE, script(atoms, vel, nt, lsd_pair(K, G), 1e-6,
                                 "fix ts all tdem/timestep vmax 1 check stop every 5 fraction 0.4 scheme gear5",
                                 body="run 0\n"), lc.workdir("ts_good"), check=False)
    chk.check(rc == 0, "control: every keyword with a good value runs")


# ------------------------------------------------------------------ strong damping (issue 17)
def part_overdamped():
    """fix tdem/timestep over the whole damping range: velocity Verlet's critical step on the
    damped oscillator is 2 (sqrt(1 + zeta^2) - zeta) / omega (w_c ~ 1/zeta); it reported 0 ("unstable
    at every step") for zeta >~ 100 (e = 1e-5 with limit_force yes, issue 17)."""
    atoms, vel, nt = two_spheres()
    for z in (0.5, 2.0, 30.0, 158.0, 1e3, 1e4):
        g = 2.0 * z * math.sqrt(K * MEFF)
        _, out = lc.run(EXE, script(atoms, vel, nt, lsd_pair(K, g), 1e-9, "fix ts all tdem/timestep vmax 1",
                                    body="run 0\n"), lc.workdir("ts_od"))
        row = table_rows(out).get("pair_1_1")
        dtc, zz, w = vv_critical(K, g, MEFF)
        chk.check(row is not None and close(row["zeta"], z, 1e-9) and close(row["dt_critical"], dtc, 1e-7),
                  "lsd stiffness zeta %g: dt_c %s vs closed form %.9g" % (z, row and row["dt_critical"], dtc))
    # the reported case: restitution form, e = 1e-5 and 1e-3, zero-force end
    tc = 1e-4
    for e in (1e-5, 1e-3, 0.3):
        z = OR.zeta_for_zero_force_e(e)
        w = OR.zero_force_end(z)[1] / tc
        dtc = 2.0 / w * (math.sqrt(1.0 + z * z) - z)
        inter = ("pair_style tdem/gran\npair_coeff * * normal lsd restitution %r %r tangential cundall_strack 0.8 0.5 "
                 "limit_force yes" % (e, tc))
        rc, out = lc.run(EXE, script(atoms, vel, nt, inter, 1e-9, "fix ts all tdem/timestep vmax 1 check stop",
                                     body="run 10\n"), lc.workdir("ts_od"), check=False)
        row = table_rows(out).get("pair_1_1")
        chk.check(rc == 0 and row is not None and close(row["zeta"], z, 1e-6) and close(row["dt_critical"], dtc, 1e-6)
                  and "unstable at every step" not in out,
                  "lsd restitution e %g limit_force yes: zeta %s vs %.9g, dt_c %s vs %.9g (exit %d)"
                  % (e, row and row["zeta"], z, row and row["dt_critical"], dtc, rc))


PARTS = {"acceptance": part_acceptance, "closed_forms": part_closed_forms, "check_modes": part_check_modes,
         "runtime": part_runtime, "bad_input": part_bad_input, "overdamped": part_overdamped}
for name, f in PARTS.items():
    if part in ("all", name):
        f()
chk.done()
