# SPDX-License-Identifier: GPL-2.0-or-later
"""Normal impacts with the non-linear / hysteretic tdem laws under tdem-liggghts, gravity off:
a sphere onto a primitive zplane wall (fix wall/gran) and a head-on impact of two equal spheres
(pair gran; relative velocity 2 v0, m* = m/2, R* = R/2). Expected values are closed forms
re-implemented here (physics_reference.md 2.2.3, 2.2.4, 8.2-8.4), never tdem output:

  model tdem/hertz, no damping:   xi_max = (5 m* v^2 / (4 k~))^(2/5), k~ = 4/3 Y* sqrt(R*),
                                  t_c = 2.94328 xi_max / v (constant 4/5 sqrt(pi) G(2/5)/G(9/10)), e = 1
  model tdem/hertz damping tsuji: e = the coefficientRestitution given, both limitForce conventions
  model tdem/hertz damping linear / kuwabara_kono / general: e and t_c from an independent RK4
                                  integration of m* xi'' = -(k~ xi^1.5 + c xi^Theta xi') (zero overlap end)
  model tdem/walton_braun:        e = sqrt(k_l / k_ul), t_c = pi/2 (sqrt(m*/k_l) + sqrt(m*/k_ul)),
                                  k_ul = k_u + s k_l xi_max, xi_max = v sqrt(m*/k_l)
  model tdem/thornton:            e(v_y/v) of Thornton (1997), v_y^2 = 4 k~ xi_y^(5/2)/(5 m*),
                                  xi_y = R* (pi p_y / (2 Y*))^2

Time step: >= 1000 steps per contact. Entry/exit times are interpolated between steps.
Tolerances: e and t_c to 2e-3 relative. The velocity-Verlet error of LIGGGHTS is first order in
dt for velocity-dependent (damped) forces (~1/1000) and at the kinks of the hysteretic laws; the
interpolation error is a fraction of a step (1e-3).

Also: restart in the middle of a hysteretic collision (write_restart / read_restart) must give
the same rebound as `run N` + `run M` in one process, and the head-on collision across the
processor boundary under -np 2 must give the e of -np 1."""
import math
import os

import numpy as np

import tdem_lig as T

R = 0.005
RHO = 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
V0 = 1.0
YOUNG, NU = 1.0e7, 0.3
YEFF = 1.0 / (2.0 * (1.0 - NU * NU) / YOUNG)   # LIGGGHTS's Yeff for two equal materials
TOL = 2e-3
C_HERTZ = 0.8 * math.sqrt(math.pi) * math.gamma(0.4) / math.gamma(0.9)


def geometry_quantities(geometry):
    if geometry == "wall":
        return MASS, R, V0
    return MASS / 2, R / 2, 2 * V0


def hertz_k(reff):
    return 4.0 / 3.0 * YEFF * math.sqrt(reff)


def hertz_tc(meff, reff, v):
    k = hertz_k(reff)
    return C_HERTZ * (5 * meff * v * v / (4 * k)) ** 0.4 / v


def scene(geometry, model, props, dt, steps, processors="", tail=None, rho=RHO, gap=0.0004):
    if geometry == "wall":
        atoms = "create_atoms 1 single 0.0 0.0 %.17g units box\n" % (R + gap)
        vel = "velocity all set 0.0 0.0 %.17g units box\n" % (-V0)
        # fix wall/gran: model and tangential first, the wall, then the model settings
        words = model.split()
        walls = "fix wz all wall/gran %s primitive type 1 zplane 0.0 %s\n" % (" ".join(words[:4]), " ".join(words[4:]))
    else:
        atoms = ("create_atoms 1 single %.17g 0.0 0.02 units box\n"
                 "create_atoms 1 single %.17g 0.0 0.02 units box\n") % (-(R + 0.0002), R + 0.0002)
        vel = ("group g1 id 1\ngroup g2 id 2\n"
               "velocity g1 set %.17g 0.0 0.0 units box\nvelocity g2 set %.17g 0.0 0.0 units box\n") % (V0, -V0)
        walls = ""
    text = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
%s
region box block -0.05 0.05 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %.17g
%s
set group all diameter %.17g density %.17g
%s
%s
fix integr all nve/sphere
dump d all custom 1 dump.impact id x y z vx vy vz fx fy fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 100000
""" % (processors, props, model, dt, atoms, 2 * R, rho, vel, walls)
    return text + (tail if tail is not None else "run %d\n" % steps)


def series(frames, geometry):
    t, xi, rate, f = [], [], [], []
    for step, cols, a in frames:
        c = {k: i for i, k in enumerate(cols)}
        if geometry == "wall":
            xi.append(R - a[0, c["z"]])
            rate.append(-a[0, c["vz"]])
            f.append(a[0, c["fz"]])
        else:
            xi.append(2 * R - (a[1, c["x"]] - a[0, c["x"]]))
            rate.append(a[0, c["vx"]] - a[1, c["vx"]])
            f.append(a[1, c["fx"]])
        t.append(step)
    return map(np.array, (t, xi, rate, f))


def measure(frames, geometry, dt, end_by_force):
    """(e, t_c): t_c ends where the force reaches 0 (end_by_force) or the overlap reaches 0."""
    t, xi, rate, f = series(frames, geometry)
    t = t * dt
    n_in = int(np.argmax(xi > 0))
    t_in = t[n_in - 1] + dt * (-xi[n_in - 1]) / (xi[n_in] - xi[n_in - 1])
    if end_by_force:
        m = n_in + int(np.argmax(f[n_in:] <= 0.0)) - 1   # last step with a positive force
        # the force is clipped at 0, so extrapolate the last force slope to its zero
        t_out = t[m] + dt * f[m] / (f[m - 1] - f[m])
    else:
        m = n_in + int(np.argmax(xi[n_in:] <= 0)) - 1
        t_out = t[m] + dt * xi[m] / (xi[m] - xi[m + 1])
    return -rate[-1] / rate[0], t_out - t_in


def rk4_general(meff, force, v, h):
    """Independent RK4 of m* xi'' = -force(xi, xi'), xi(0) = 0, xi'(0) = v, until xi < 0.
    Returns (e, t_c, xi_max)."""
    def acc(x, u):
        return -force(x, u) / meff

    x, u, t, xmax = 0.0, v, 0.0, 0.0
    while True:
        k1x, k1u = u, acc(x, u)
        k2x, k2u = u + 0.5 * h * k1u, acc(x + 0.5 * h * k1x, u + 0.5 * h * k1u)
        k3x, k3u = u + 0.5 * h * k2u, acc(x + 0.5 * h * k2x, u + 0.5 * h * k2u)
        k4x, k4u = u + h * k3u, acc(x + h * k3x, u + h * k3u)
        xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        un = u + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        if xn < 0 and t > 0:
            s = x / (x - xn)
            return -(u + s * (un - u)) / v, t + s * h, xmax
        x, u, t = xn, un, t + h
        xmax = max(xmax, x)


def rk4_reference(meff, k, c, theta, v, n=40000):
    """Independent RK4 of m* xi'' = -(k xi^1.5 + c xi^theta xi'), xi(0)=0, xi'(0)=v, until xi < 0
    (zero-overlap end). Returns (e, t_c)."""
    tc_el = C_HERTZ * (5 * meff * v * v / (4 * k)) ** 0.4 / v
    h = 2.0 * tc_el / n

    def acc(x, u):
        xp = max(x, 0.0)
        return -(k * xp ** 1.5 + c * (xp ** theta if theta > 0 else 1.0) * u) / meff

    x, u, t = 0.0, v, 0.0
    while True:
        k1x, k1u = u, acc(x, u)
        k2x, k2u = u + 0.5 * h * k1u, acc(x + 0.5 * h * k1x, u + 0.5 * h * k1u)
        k3x, k3u = u + 0.5 * h * k2u, acc(x + 0.5 * h * k2x, u + 0.5 * h * k2u)
        k4x, k4u = u + h * k3u, acc(x + h * k3x, u + h * k3u)
        xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        un = u + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        if xn < 0 and t > 0:
            s = x / (x - xn)
            return -(u + s * (un - u)) / v, t + s * h
        x, u, t = xn, un, t + h


def thornton_e(meff, reff, py, v):
    """Thornton (1997) closed form, re-derived: xi_y from the yield pressure, v_y from the elastic
    energy stored up to xi_y, then e(r = v_y / v)."""
    k = hertz_k(reff)
    xi_y = reff * (math.pi * py / (2 * YEFF)) ** 2
    vy = math.sqrt(4.0 * k * xi_y ** 2.5 / (5.0 * meff))
    r = vy / v
    if r >= 1:
        return 1.0, vy
    return (math.sqrt(6 * math.sqrt(3) / 5 * (1 - r * r / 6)) *
            (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25), vy


MAT = """
fix m_E  all property/global youngsModulus peratomtype %.17g
fix m_nu all property/global poissonsRatio peratomtype %.17g
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
""" % (YOUNG, NU)


def pp(name, value):
    return "fix m_%s all property/global %s peratomtypepair 1 %.17g\n" % (name, name, value)


KL, E_WB = 1.0e4, 0.7
PY = 6.0e5


def main():
    args = T.parse_args()
    checks = T.Checks()
    rows = []

    def case(name, geometry, model, props, e_ref, tc_ref, end_by_force, tc_hint):
        dt = tc_hint / 1000.0
        d = T.workdir(args, "tdem_lig_nl_" + name)
        steps = int(2.0 * tc_hint / dt) + int(0.0004 / (V0 * dt)) + 50
        T.run(args.tdem, scene(geometry, model, props, dt, steps), d, name)
        e, tc = measure(T.read_dump(os.path.join(d, "dump.impact")), geometry, dt, end_by_force)
        err_e = e / e_ref - 1
        checks.check(abs(err_e) < TOL, "%s: e = %.6f, reference %.6f, rel. error %.2e (< %g)" % (name, e, e_ref, err_e, TOL))
        err_tc = float("nan")
        if tc_ref is not None:
            err_tc = tc / tc_ref - 1
            checks.check(abs(err_tc) < TOL, "%s: t_c = %.6e s, reference %.6e s, rel. error %.2e (< %g)"
                         % (name, tc, tc_ref, err_tc, TOL))
        rows.append((name, e_ref, e, err_e, tc_ref or float("nan"), tc, err_tc))

    for geometry in ("wall", "pair"):
        meff, reff, v = geometry_quantities(geometry)
        k = hertz_k(reff)
        tc_el = hertz_tc(meff, reff, v)
        # Hertz, elastic
        case("hertz_elastic_" + geometry, geometry, "model tdem/hertz tangential tdem/cundall_strack damping linear",
             MAT + pp("dampingCoefficient", 0.0), 1.0, tc_el, False, tc_el)
        # Hertz + Tsuji, both conventions
        for limit in ("off", "on"):
            case("hertz_tsuji_limitForce_%s_%s" % (limit, geometry), geometry,
                 "model tdem/hertz tangential tdem/cundall_strack damping tsuji limitForce " + limit,
                 MAT + pp("coefficientRestitution", 0.6), 0.6, None, limit == "on", tc_el)
        # Hertz + linear / Kuwabara-Kono / general damping against the independent RK4
        c_lin = 0.5 * math.sqrt(meff * k * math.sqrt(1e-4))          # some kg/s
        for dname, c, theta, extra in (("linear", c_lin, 0.0, ""),
                                       ("kuwabara_kono", 0.3 * math.sqrt(meff * k) / 0.01 ** 0.25, 0.5, ""),
                                       ("general", 0.4 * math.sqrt(meff * k), 0.25, pp("dampingExponent", 0.25))):
            e_ref, tc_ref = rk4_reference(meff, k, c, theta, v)
            case("hertz_%s_%s" % (dname, geometry), geometry,
                 "model tdem/hertz tangential tdem/cundall_strack damping " + dname,
                 MAT + pp("dampingCoefficient", c) + extra, e_ref, tc_ref, False, tc_el)
        # Walton-Braun: constant k_ul and force-dependent k_ul
        for wname, ku, s in (("constant", KL / E_WB ** 2, 0.0), ("slope", KL, 1.0 / 3.6e-4)):
            xi_max = v * math.sqrt(meff / KL)
            kul = ku + s * KL * xi_max
            props = (pp("loadingStiffness", KL) + pp("unloadingStiffness", ku) + pp("unloadingStiffnessSlope", s) +
                     pp("tangentialStiffnessRatio", 0.2857) + pp("coefficientFriction", 0.5))
            tc = 0.5 * math.pi * (math.sqrt(meff / KL) + math.sqrt(meff / kul))
            case("walton_braun_%s_%s" % (wname, geometry), geometry,
                 "model tdem/walton_braun tangential tdem/cundall_strack", props,
                 math.sqrt(KL / kul), tc, True, tc)
        # Thornton
        e_th, vy = thornton_e(meff, reff, PY, v)
        checks.check(0.05 < vy / v < 0.5, "thornton_%s: v_y/v0 = %.3f, well inside the plastic range" % (geometry, vy / v))
        case("thornton_" + geometry, geometry, "model tdem/thornton tangential tdem/cundall_strack",
             MAT + pp("yieldPressure", PY), e_th, None, True, tc_el)

    # ---- continuous potential (cut at touch): F = n eps d^n / X^(n+1) + gamma xi_dot, X = d - xi
    #      elastic: e = 1, xi_max = d (1 - (1 + m* v^2 / (2 eps))^(-1/n)); damped: RK4 reference
    # (damped: a softer potential, so that the dashpot makes the force attractive at the end with
    # limitForce off, i.e. gamma v_out > n eps / d, and limitForce on makes a difference)
    N_CP = 36.0
    for geometry in ("wall", "pair"):
        meff, reff, v = geometry_quantities(geometry)
        dd = R if geometry == "wall" else 2 * R
        for gamma, limit, EPS_CP in ((0.0, "off", 2.0e-4), (0.1, "off", 1.0e-5), (0.1, "on", 1.0e-5)):
            def f_cp(x, u, gamma=gamma, dd=dd, clip=(limit == "on"), EPS_CP=EPS_CP):
                f = N_CP * EPS_CP * dd ** N_CP / (dd - x) ** (N_CP + 1) + gamma * u
                return max(f, 0.0) if clip else f
            xi_el = dd * (1 - (1 + meff * v * v / (2 * EPS_CP)) ** (-1 / N_CP))
            e_ref, tc_ref, xmax_ref = rk4_general(meff, f_cp, v, xi_el / v / 20000)
            name = "continuous_potential_%s_%s" % ("elastic" if gamma == 0 else "damped_limitForce_" + limit, geometry)
            props = (pp("potentialEnergy", EPS_CP) + pp("potentialExponent", N_CP) + pp("dampingCoefficient", gamma) +
                     pp("tangentialStiffnessRatio", 0.3) + pp("coefficientFriction", 0.5))
            if gamma == 0:
                checks.check(abs(e_ref - 1) < 1e-9 and abs(xmax_ref / xi_el - 1) < 1e-6,
                             name + ": RK4 reference reproduces e = 1 and the closed-form xi_max %.6e" % xi_el)
            dt = tc_ref / 2000.0
            d = T.workdir(args, "tdem_lig_nl_" + name)
            steps = int(0.0004 / (v * dt) * (2 if geometry == "pair" else 1)) + 2600
            T.run(args.tdem, scene(geometry, "model tdem/continuous_potential tangential tdem/cundall_strack "
                                   "limitForce " + limit, props,
                                   dt, steps), d, name)
            frames = T.read_dump(os.path.join(d, "dump.impact"))
            e, tc = measure(frames, geometry, dt, False)
            xmax = float(list(series(frames, geometry))[1].max())
            err_e, err_tc = e / e_ref - 1, tc / tc_ref - 1
            checks.check(abs(err_e) < TOL, "%s: e = %.6f, reference %.6f, rel. error %.2e (< %g)" % (name, e, e_ref, err_e, TOL))
            checks.check(abs(err_tc) < TOL, "%s: t_c = %.6e s, reference %.6e s, rel. error %.2e (< %g)"
                         % (name, tc, tc_ref, err_tc, TOL))
            if gamma == 0:
                err_x = xmax / xi_el - 1
                checks.check(abs(err_x) < TOL, "%s: xi_max = %.6e m, closed form %.6e m, rel. error %.2e (< %g)"
                             % (name, xmax, xi_el, err_x, TOL))
            rows.append((name, e_ref, e, err_e, tc_ref, tc, err_tc))

    # ---- numbers of physics_reference.md 8.2 (steel sphere on steel, v0 = 1: t_c = 3.4555e-5 s, e = 1)
    #      and 8.3 (Walton-Braun k_l = 1e5, k_ul = 1.5625e5, m = 0.01 kg: e = 0.8, t_c = 8.94113e-4 s)
    for name, model, props, rho, e_ref, tc_ref in (
            ("ref82_hertz_steel_wall", "model tdem/hertz tangential tdem/cundall_strack damping linear",
             "hard_particles yes\nfix m_E all property/global youngsModulus peratomtype 210e9\n"
             "fix m_nu all property/global poissonsRatio peratomtype 0.3\n" +
             pp("dampingCoefficient", 0.0) + pp("tangentialStiffnessRatio", 0.3) + pp("coefficientFriction", 0.5),
             7850.0, 1.0, 3.4555e-5),
            ("ref83_walton_braun_wall", "model tdem/walton_braun tangential tdem/cundall_strack",
             pp("loadingStiffness", 1e5) + pp("unloadingStiffness", 1.5625e5) + pp("unloadingStiffnessSlope", 0.0) +
             pp("tangentialStiffnessRatio", 0.3) + pp("coefficientFriction", 0.5),
             0.01 / (4.0 / 3.0 * math.pi * R ** 3), 0.8, 8.94113e-4)):
        dt = tc_ref / 1000.0
        d = T.workdir(args, "tdem_lig_nl_" + name)
        T.run(args.tdem, scene("wall", model, props, dt, 2300, rho=rho, gap=200 * dt * V0), d, name)
        e, tc = measure(T.read_dump(os.path.join(d, "dump.impact")), "wall", dt, name.startswith("ref83"))
        err_e, err_tc = e / e_ref - 1, tc / tc_ref - 1
        checks.check(abs(err_e) < TOL, "%s: e = %.6f, physics_reference %.6f, rel. error %.2e (< %g)" % (name, e, e_ref, err_e, TOL))
        checks.check(abs(err_tc) < TOL, "%s: t_c = %.6e s, physics_reference %.6e s, rel. error %.2e (< %g)"
                     % (name, tc, tc_ref, err_tc, TOL))
        rows.append((name, e_ref, e, err_e, tc_ref, tc, err_tc))

    # ---- the other compiled tangential laws (tangential history, off) give the same normal impact
    meff, reff, v = geometry_quantities("wall")
    for tang in ("history", "off"):
        case("hertz_tsuji_tangential_%s_wall" % tang, "wall",
             "model tdem/hertz tangential %s damping tsuji" % tang, MAT + pp("coefficientRestitution", 0.6),
             0.6, None, False, hertz_tc(meff, reff, v))
        case("walton_braun_tangential_%s_wall" % tang, "wall", "model tdem/walton_braun tangential " + tang,
             pp("loadingStiffness", KL) + pp("unloadingStiffness", KL / E_WB ** 2) + pp("unloadingStiffnessSlope", 0.0) +
             pp("tangentialStiffnessRatio", 0.2857) + pp("coefficientFriction", 0.5), E_WB,
             0.5 * math.pi * (math.sqrt(meff / KL) + math.sqrt(meff * E_WB ** 2 / KL)), True, 1e-3)
        case("thornton_tangential_%s_wall" % tang, "wall", "model tdem/thornton tangential " + tang,
             MAT + pp("yieldPressure", PY), thornton_e(meff, reff, PY, v)[0], None, True, hertz_tc(meff, reff, v))

    # ---- restart in the middle of a hysteretic collision, and -np 2 across the boundary
    for model, props, tc in (("model tdem/walton_braun tangential tdem/cundall_strack",
                              pp("loadingStiffness", KL) + pp("unloadingStiffness", KL / E_WB ** 2) +
                              pp("unloadingStiffnessSlope", 0.0) + pp("tangentialStiffnessRatio", 0.2857) +
                              pp("coefficientFriction", 0.5), 1e-3),
                             ("model tdem/thornton tangential tdem/cundall_strack", MAT + pp("yieldPressure", PY),
                              hertz_tc(MASS / 2, R / 2, 2 * V0))):
        law = model.split()[1].split("/")[1]
        dt = tc / 1000.0
        n_touch = int(0.0004 / (2 * V0 * dt))
        n1 = n_touch + 550          # past the maximum overlap: on the unloading branch (checked)
        n2 = 2000
        base = scene("pair", model, props, dt, 0, tail="")
        d1 = T.workdir(args, "tdem_lig_nl_restart_one_" + law)
        T.run(args.tdem, base + "run %d\nwrite_restart r.restart\nrun %d\n" % (n1, n2), d1, "one")
        d2 = T.workdir(args, "tdem_lig_nl_restart_two_" + law)
        T.run(args.tdem, """
atom_style granular
atom_modify map array
newton off
communicate single vel yes
units si
read_restart ../%s/r.restart
timestep %.17g
neighbor 0.002 bin
neigh_modify delay 0
%s
fix integr all nve/sphere
dump d all custom 1 dump.impact id x y z vx vy vz fx fy fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
run %d
""" % (os.path.basename(d1), dt, props, n2), d2, "two")
        a = T.read_dump(os.path.join(d1, "dump.impact"))[-1]
        b = T.read_dump(os.path.join(d2, "dump.impact"))[-1]
        fr1 = T.read_dump(os.path.join(d1, "dump.impact"))
        _, xi1, _, f1 = series(fr1, "pair")
        mid = [i for i, (st, _, _) in enumerate(fr1) if st == n1][0]
        checks.check(xi1[mid] > 0 and f1[mid] > 0 and xi1[mid] < xi1.max(),
                     "restart %s: written during the contact, on the unloading branch (xi = %.3e < xi_max = %.3e)"
                     % (law, xi1[mid], xi1.max()))
        rel = T.max_rel_diff(a[2], b[2])
        ca = {k: i for i, k in enumerate(a[1])}
        e_a = (a[2][1, ca["vx"]] - a[2][0, ca["vx"]]) / (2 * V0)
        e_b = (b[2][1, ca["vx"]] - b[2][0, ca["vx"]]) / (2 * V0)
        checks.check(a[0] == b[0] and rel <= 1e-12,
                     "restart %s: step %d/%d, e = %.9f (run N + run M) vs %.9f (read_restart), max rel. diff %.2e (<= 1e-12)"
                     % (law, a[0], b[0], e_a, e_b, rel))
        # -np 2: the contact point is at x = 0, the processor boundary of `processors 2 1 1`
        e_np = []
        for npr in (1, 2):
            d = T.workdir(args, "tdem_lig_nl_np%d_%s" % (npr, law))
            T.run(args.tdem, scene("pair", model, props, dt, 0, processors="processors 2 1 1" if npr == 2 else "",
                                   tail="run %d\n" % (n1 + n2)),
                  d, "np", np_=npr, mpirun=args.mpirun)
            e_np.append(measure(T.read_dump(os.path.join(d, "dump.impact")), "pair", dt, True)[0])
        checks.check(abs(e_np[1] / e_np[0] - 1) < 1e-10,
                     "-np 2 %s: e = %.12f vs -np 1 e = %.12f (rel. diff %.1e < 1e-10)"
                     % (law, e_np[1], e_np[0], abs(e_np[1] / e_np[0] - 1)))

    print("\n%-40s %9s %9s %10s %11s %11s %10s" % ("case", "e_ref", "e", "err_e", "tc_ref", "tc", "err_tc"))
    for r in rows:
        print("%-40s %9.6f %9.6f %10.2e %11.5e %11.5e %10.2e" % r)
    checks.done()


if __name__ == "__main__":
    main()
