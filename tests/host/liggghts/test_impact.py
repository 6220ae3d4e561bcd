# SPDX-License-Identifier: GPL-2.0-or-later
"""Single normal impacts under tdem-liggghts, gravity off: a sphere onto a primitive plane wall
(fix wall/gran zplane) and a head-on impact of two equal spheres (pair gran), with
`model tdem/lsd`, both end-of-contact conventions (limitForce off / on).

 * parameters restitution: the measured coefficient of restitution and contact time must equal
   the (e, t_c) given in the input (the laws' closed forms are exact for a linear
   spring-dashpot; only the time discretisation differs).
 * parameters stiffness: the measured e and t_c must equal the closed forms, evaluated here
   independently from k, gamma and m*:
     zero_overlap: t_c = pi/omega,                 e = exp(-pi beta / sqrt(1 - beta^2))
     zero_force:   t_c = 2 atan2(omega, delta)/omega, e = exp(-delta t_c)
   with omega0^2 = k/m*, delta = gamma/(2 m*), omega^2 = omega0^2 - delta^2, beta = delta/omega0.
Time step: t_c/400; entry and exit times are interpolated between steps. Tolerance 2e-3
relative (the velocity-Verlet error is O((omega dt)^2) ~ 6e-5, the interpolation error is a
small fraction of a step, 1/400 = 2.5e-3)."""
import math
import os

import numpy as np

import tdem_lig as T

R = 0.005
RHO = 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
TC = 1.0e-3
DT = TC / 400.0
V0 = 1.0
TOL = 2e-3


def scene(geometry, settings, props):
    if geometry == "wall":
        atoms = "create_atoms 1 single 0.0 0.0 %.17g units box\n" % (R + 0.0004)
        vel = "velocity all set 0.0 0.0 %.17g units box\n" % (-V0)
        walls = ("fix wz all wall/gran model tdem/lsd tangential tdem/cundall_strack primitive type 1 "
                 "zplane 0.0 %s\n" % settings)
    else:
        atoms = ("create_atoms 1 single %.17g 0.0 0.02 units box\n"
                 "create_atoms 1 single %.17g 0.0 0.02 units box\n") % (-(R + 0.0002), R + 0.0002)
        vel = ("group g1 id 1\ngroup g2 id 2\n"
               "velocity g1 set %.17g 0.0 0.0 units box\nvelocity g2 set %.17g 0.0 0.0 units box\n") % (V0, -V0)
        walls = ""
    return """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran model tdem/lsd tangential tdem/cundall_strack %s
pair_coeff * *
timestep %.17g
%s
set group all diameter %.17g density %.17g
%s
%s
fix integr all nve/sphere
dump d all custom 1 dump.impact id x y z vx vy vz fx fy fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000
run 1000
""" % (props, settings, DT, atoms, 2 * R, RHO, vel, walls)


def measure(frames, geometry, zero_force):
    """(e, t_c) from the per-step dump."""
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
            f.append(a[1, c["fx"]])  # force on the right sphere, > 0 when pushed apart
        t.append(step * DT)
    t, xi, rate, f = map(np.array, (t, xi, rate, f))
    n_in = int(np.argmax(xi > 0))                     # first step in contact
    t_in = t[n_in - 1] + DT * (-xi[n_in - 1]) / (xi[n_in] - xi[n_in - 1])
    if zero_force:
        m = n_in + int(np.argmax(f[n_in:] == 0.0)) - 1  # last step with a (positive) force
        t_out = t[m] + DT * f[m] / (f[m - 1] - f[m])
    else:
        m = n_in + int(np.argmax(xi[n_in:] <= 0)) - 1   # last step with overlap
        t_out = t[m] + DT * xi[m] / (xi[m] - xi[m + 1])
    e = -rate[-1] / rate[0]
    return e, t_out - t_in, len(t)


def closed_form(k, gamma, meff, zero_force):
    w0 = math.sqrt(k / meff)
    delta = gamma / (2 * meff)
    beta = delta / w0
    w = w0 * math.sqrt(1 - beta * beta)
    if zero_force:
        tc = 2 * math.atan2(w, delta) / w
        return math.exp(-delta * tc), tc
    return math.exp(-math.pi * beta / math.sqrt(1 - beta * beta)), math.pi / w


def main():
    args = T.parse_args()
    checks = T.Checks()
    E = 0.7
    rest_props = """
fix m_e  all property/global coefficientRestitution peratomtypepair 1 %.17g
fix m_tc all property/global contactTime peratomtypepair 1 %.17g
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
""" % (E, TC)
    # stiffness mode: gamman is per unit m*; choose k so that t_c is near TC for the wall case
    KN, GN = MASS * (math.pi / TC) ** 2, 600.0
    stiff_props = """
fix m_kn all property/global kn peratomtypepair 1 %.17g
fix m_kt all property/global kt peratomtypepair 1 %.17g
fix m_gn all property/global gamman peratomtypepair 1 %.17g
fix m_gt all property/global gammat peratomtypepair 1 0.0
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
""" % (KN, KN * 0.2857, GN)
    # material mode (configured like model hooke): k from Y*, R*, m* and the characteristic
    # velocity; Y* is chosen so that the wall contact has the stiffness KN of stiffness mode.
    NU, VC = 0.3, 1.0
    Y = (KN ** 5 / ((16.0 / 15.0) ** 4 * R ** 2 * MASS * VC * VC)) ** 0.25
    mat_props = """
fix m_E  all property/global youngsModulus peratomtype %.17g
fix m_nu all property/global poissonsRatio peratomtype %.17g
fix m_vc all property/global characteristicVelocity scalar %.17g
fix m_e  all property/global coefficientRestitution peratomtypepair 1 %.17g
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
""" % (2.0 * (1.0 - NU * NU) * Y, NU, VC, E)
    rows = []
    for geometry in ("wall", "pair"):
        meff = MASS if geometry == "wall" else MASS / 2
        reff = R if geometry == "wall" else R / 2
        for limit in ("off", "on"):
            zf = limit == "on"
            name = "%s_material_limitForce_%s" % (geometry, limit)
            k = 16.0 / 15.0 * math.sqrt(reff) * Y * (15.0 * meff * VC * VC / (16.0 * math.sqrt(reff) * Y)) ** 0.2
            lo, hi = 0.0, 2.0 * math.sqrt(k * meff)   # damping giving e = E, by bisection
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if closed_form(k, mid, meff, zf)[0] > E:
                    lo = mid
                else:
                    hi = mid
            e_ref, tc_ref = closed_form(k, 0.5 * (lo + hi), meff, zf)
            d = T.workdir(args, "tdem_lig_impact_" + name)
            T.run(args.tdem, scene(geometry, "parameters material limitForce " + limit, mat_props), d, name)
            e, tc, n = measure(T.read_dump(os.path.join(d, "dump.impact")), geometry, zf)
            err_e, err_tc = e / e_ref - 1, tc / tc_ref - 1
            rows.append((name, e_ref, e, err_e, tc_ref, tc, err_tc))
            checks.check(abs(e_ref / E - 1) < 1e-9, name + ": the derived damping gives e = %.6f" % E)
            checks.check(abs(err_e) < TOL, "%s: e = %.6f, target %.6f, rel. error %.2e (< %g)"
                         % (name, e, e_ref, err_e, TOL))
            checks.check(abs(err_tc) < TOL, "%s: t_c = %.6e s, closed form %.6e s, rel. error %.2e (< %g)"
                         % (name, tc, tc_ref, err_tc, TOL))
    for geometry in ("wall", "pair"):
        meff = MASS if geometry == "wall" else MASS / 2
        for limit in ("off", "on"):
            zf = limit == "on"
            for mode in ("restitution", "stiffness"):
                settings = "parameters %s limitForce %s" % (mode, limit)
                props = rest_props if mode == "restitution" else stiff_props
                if mode == "restitution":
                    e_ref, tc_ref = E, TC
                else:
                    e_ref, tc_ref = closed_form(KN, GN * meff, meff, zf)
                name = "%s_%s_limitForce_%s" % (geometry, mode, limit)
                d = T.workdir(args, "tdem_lig_impact_" + name)
                T.run(args.tdem, scene(geometry, settings, props), d, name)
                frames = T.read_dump(os.path.join(d, "dump.impact"))
                e, tc, n = measure(frames, geometry, zf)
                err_e, err_tc = e / e_ref - 1, tc / tc_ref - 1
                rows.append((name, e_ref, e, err_e, tc_ref, tc, err_tc))
                checks.check(n == 1001, name + ": 1001 dumped steps")
                checks.check(abs(err_e) < TOL, "%s: e = %.6f, closed form %.6f, rel. error %.2e (< %g)"
                             % (name, e, e_ref, err_e, TOL))
                checks.check(abs(err_tc) < TOL, "%s: t_c = %.6e s, closed form %.6e s, rel. error %.2e (< %g)"
                             % (name, tc, tc_ref, err_tc, TOL))
    print("\n%-40s %9s %9s %10s %11s %11s %10s" % ("case", "e_ref", "e", "err_e", "tc_ref", "tc", "err_tc"))
    for r in rows:
        print("%-40s %9.6f %9.6f %10.2e %11.5e %11.5e %10.2e" % r)
    checks.done()


if __name__ == "__main__":
    main()
