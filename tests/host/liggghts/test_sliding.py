# SPDX-License-Identifier: GPL-2.0-or-later
"""Sliding-to-rolling of a sphere on a plane wall (fix wall/gran primitive zplane, gravity on),
`tangential tdem/cundall_strack` with both slip rules. Closed form for a solid sphere with
Coulomb friction mu, started with speed v0 and no spin:
  sliding:  v(t) = v0 - mu g t,  omega(t) = 5 mu g t / (2 R)   for t < t_s = 2 v0 / (7 mu g)
  rolling:  v = 5/7 v0, omega = v / R afterwards.
Asserts (relative to v0): v at t_s/2 within 1e-2, final v within 1e-2 of 5/7 v0, and final
rolling without slip |v - omega R| < 1e-2 v0. The tangential spring (stiffness of the order of
the normal one) makes the stick phase oscillate with amplitude ~ mu g / omega_t ~ 1e-4 m/s,
well inside the tolerance; the sliding phase is exact up to the time step."""
import math
import os

import numpy as np

import tdem_lig as T

R, RHO, G, MU, V0 = 0.005, 2500.0, 9.81, 0.3, 0.5
T_SLIDE = 2 * V0 / (7 * MU * G)
DT = 4e-6
STEPS = int(round(2.2 * T_SLIDE / DT / 100)) * 100


def scene(model):
    return """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.1 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
neighbor 0.002 bin
fix m_e  all property/global coefficientRestitution peratomtypepair 1 0.5
fix m_tc all property/global contactTime peratomtypepair 1 2e-4
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857
fix m_kn all property/global kn peratomtypepair 1 2e3
fix m_kt all property/global kt peratomtypepair 1 6e2
fix m_gn all property/global gamman peratomtypepair 1 200
fix m_gt all property/global gammat peratomtypepair 1 100
fix m_mu all property/global coefficientFriction peratomtypepair 1 %.17g
pair_style gran model tdem/lsd tangential tdem/cundall_strack
pair_coeff * *
timestep %.17g
create_atoms 1 single -0.04 0.0 %.17g units box
set group all diameter %.17g density %.17g
velocity all set %.17g 0.0 0.0 units box
fix gravi all gravity %.17g vector 0.0 0.0 -1.0
fix wz all wall/gran model tdem/lsd tangential tdem/cundall_strack primitive type 1 zplane 0.0 %s
fix integr all nve/sphere
dump d all custom 100 dump.slide id x z vx vz omegay
dump_modify d format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 10000
run %d
""" % (MU, DT, R, 2 * R, RHO, V0, G, model, STEPS)


def main():
    args = T.parse_args()
    checks = T.Checks()
    cases = [("restitution_spring", "parameters restitution slip_rule spring"),
             ("stiffness_spring", "parameters stiffness slip_rule spring"),
             ("stiffness_spring_dashpot", "parameters stiffness slip_rule spring_dashpot")]
    for name, settings in cases:
        d = T.workdir(args, "tdem_lig_slide_" + name)
        T.run(args.tdem, scene(settings), d, name)
        frames = T.read_dump(os.path.join(d, "dump.slide"))
        t = np.array([f[0] * DT for f in frames])
        c = {k: i for i, k in enumerate(frames[0][1])}
        vx = np.array([f[2][0, c["vx"]] for f in frames])
        wy = np.array([f[2][0, c["omegay"]] for f in frames])
        k = int(np.argmin(abs(t - T_SLIDE / 2)))
        v_mid_ref = V0 - MU * G * t[k]
        checks.check(abs(vx[k] - v_mid_ref) < 1e-2 * V0, "%s: sliding, v(%.4f s) = %.5f m/s, closed form %.5f"
                     % (name, t[k], vx[k], v_mid_ref))
        checks.check(abs(vx[-1] - 5.0 / 7.0 * V0) < 1e-2 * V0, "%s: rolling, final v = %.5f m/s, closed form 5/7 v0 = %.5f"
                     % (name, vx[-1], 5.0 / 7.0 * V0))
        checks.check(abs(vx[-1] - wy[-1] * R) < 1e-2 * V0, "%s: no slip at the end, v - omega R = %.2e m/s"
                     % (name, vx[-1] - wy[-1] * R))
    checks.done()


if __name__ == "__main__":
    main()
