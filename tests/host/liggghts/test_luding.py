# SPDX-License-Identifier: GPL-2.0-or-later
"""model tdem/luding (the worked example of docs/adding_a_law.md) against LIGGGHTS's own
`model hooke/hysteresis` with its damping and cohesion off (coefficientRestitution 1, kn2kc 0):
the same law, so the stock engine gives the expected trajectories.

The stock model forms k1 = kn = 16/15 sqrt(R*) Y* (15 m* V^2 / (16 sqrt(R*) Y*))^(1/5) from
youngsModulus, poissonsRatio and characteristicVelocity V, k2_max = kn2kcMax kn and
xi_lim = k2_max/(k2_max - kn) phiF 2 R*, and passes k_t = kn to `tangential history`. The tdem
run gets loadingStiffness = that kn (computed here, per geometry: the wall impact has
m* = m, R* = R, the pair m/2, R/2), unloadingStiffnessMax = kn2kcMax kn, plasticityDepth = phiF
and tangentialStiffnessRatio 1, with the same `tangential history`.
Cases: an oblique sphere-wall impact (vz = -1, vx = 0.5 m/s: the tangential spring and its slip
take part) and a head-on pair impact (relative 2 m/s), each with phiF 0.3 (xi_max below xi_lim)
and 0.02 (beyond; checked from the largest overlap). After the impact the positions, velocities
and spins of both runs must agree within 1e-9 relative (k1 is formed in a different order, so the
runs differ by round-off); the rebound must differ from an undamped elastic rebound by > 1 %
(the plastic law is at work)."""
import math
import os

import numpy as np

import tdem_lig as T

args = T.parse_args()
R, RHO = 0.005, 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
E, NU, VC = 1.0e7, 0.3, 1.0
RATIO = 5.0
YSTAR = E / (2 * (1 - NU * NU))
failures = []


def kn_hooke(meff, reff):
    s = math.sqrt(reff)
    return 16.0 / 15.0 * s * YSTAR * (15.0 * meff * VC * VC / (16.0 * s * YSTAR)) ** 0.2


def scene(geometry, model, props, dt, steps):
    if geometry == "wall":
        atoms = "create_atoms 1 single 0.0 0.0 %.17g units box\n" % (R + 20 * dt)
        vel = "velocity all set 0.5 0.0 -1.0 units box\n"
        walls = "fix wz all wall/gran %s primitive type 1 zplane 0.0\n" % model
    else:
        gap = 10 * dt
        atoms = ("create_atoms 1 single %.17g 0.0 0.02 units box\n"
                 "create_atoms 1 single %.17g 0.0 0.02 units box\n") % (-(R + gap), R + gap)
        vel = ("group g1 id 1\ngroup g2 id 2\n"
               "velocity g1 set 1.0 0.0 0.0 units box\nvelocity g2 set -1.0 0.0 0.0 units box\n")
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
pair_style gran %s
pair_coeff * *
timestep %.17g
%s
set group all diameter %.17g density %.17g
%s
%s
fix integr all nve/sphere
thermo 1000
run %d
write_dump all custom dump.end id x y z vx vy vz omegax omegay omegaz modify sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
""" % (props, model, dt, atoms, 2 * R, RHO, vel, walls, steps)


def prop_text(p):
    out = []
    for name, (kind, v) in p.items():
        if kind == "scalar":
            out.append("fix %s all property/global %s scalar %.17g" % (name, name, v))
        elif kind == "peratomtype":
            out.append("fix %s all property/global %s peratomtype %.17g" % (name, name, v))
        else:
            out.append("fix %s all property/global %s peratomtypepair 1 %.17g" % (name, name, v))
    return "\n".join(out)


for geometry in ("wall", "pair"):
    meff, reff = (MASS, R) if geometry == "wall" else (MASS / 2, R / 2)
    k1 = kn_hooke(meff, reff)
    tc = math.pi * math.sqrt(meff / k1)
    dt = tc / 2000
    steps = int(3 * tc / dt) + 40
    v0 = 1.0 if geometry == "wall" else 2.0
    for phi in (0.3, 0.02):
        xl = RATIO / (RATIO - 1) * phi * 2 * reff
        a = v0 * math.sqrt(meff / k1)
        regime = "below" if a < xl else "beyond"
        common = {"youngsModulus": ("peratomtype", E), "poissonsRatio": ("peratomtype", NU),
                  "coefficientFriction": ("pair", 0.3)}
        stock = dict(common)
        stock.update({"coefficientRestitution": ("pair", 1.0), "characteristicVelocity": ("scalar", VC),
                      "coefficientMaxElasticStiffness": ("pair", RATIO), "coefficientAdhesionStiffness": ("pair", 0.0),
                      "coefficientPlasticityDepth": ("pair", phi)})
        tdem = dict(common)
        tdem.update({"loadingStiffness": ("pair", k1), "unloadingStiffnessMax": ("pair", RATIO * k1),
                     "plasticityDepth": ("pair", phi), "tangentialStiffnessRatio": ("pair", 1.0)})
        res = {}
        for tag, exe, model, props in (("stock", args.stock, "model hooke/hysteresis tangential history", stock),
                                       ("tdem", args.tdem, "model tdem/luding tangential history", tdem)):
            wd = T.workdir(args, "luding_%s_%s_%g" % (tag, geometry, phi))
            T.run(exe, scene(geometry, model, prop_text(props), dt, steps), wd, "impact")
            _, cols, d = T.read_dump(os.path.join(wd, "dump.end"))[-1]
            res[tag] = (cols, d)
        cols, ds = res["stock"]
        _, dtm = res["tdem"]
        w = T.max_rel_diff(dtm[:, 1:], ds[:, 1:], floor=1e-12)
        c = {k: i for i, k in enumerate(cols)}
        e = (ds[0, c["vz"]] / 1.0) if geometry == "wall" else (ds[1, c["vx"]] - ds[0, c["vx"]]) / 2.0
        print("%s, phiF %g (A/xi_lim = %.3f, %s the limit): stock e = %.6f; tdem vs stock max rel diff %.3g"
              % (geometry, phi, a / xl, regime, e, w))
        if regime != ("below" if phi == 0.3 else "beyond"):
            failures.append("%s phiF %g: the case is not %s the limit" % (geometry, phi, "below" if phi == 0.3 else "beyond"))
        if not w <= 1e-9:
            failures.append("%s phiF %g: tdem/luding differs from hooke/hysteresis by %.3g" % (geometry, phi, w))
        if not e < 0.99:
            failures.append("%s phiF %g: e = %.6f, the plastic law did not dissipate" % (geometry, phi, e))

if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    raise SystemExit(1)
print("PASS: tdem/luding equals LIGGGHTS's hooke/hysteresis (damping and cohesion off) in %d cases" % 4)
