#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Measured coefficient of restitution and contact time of the lsd law in LAMMPS vs the
closed forms (re-implemented here, independently of src/contact):

  omega0 = sqrt(k/m*), beta = gamma/(2 sqrt(k m*))
  limit_force no  (contact ends at zero overlap): tau = pi/sqrt(1-beta^2),
                                                  e = exp(-pi beta/sqrt(1-beta^2))
  limit_force yes (contact ends at zero force):   tau = 2 atan2(sqrt(1-beta^2), beta)/sqrt(1-beta^2),
                                                  e = exp(-beta tau)
  t_c = tau/omega0

Cases: a sphere hitting a zplane wall (fix tdem/wall/gran, m* = m) and a head-on impact of
two spheres of different size (pair tdem/gran, m* = m1 m2/(m1+m2)), gravity off, each with
  * normal lsd restitution E TC: expected e = E and t_c = TC (the style derives k, gamma);
  * normal lsd stiffness K G damping absolute: expected e, t_c from the closed forms above.
dt = t_c/400. The contact starts and ends between steps; the times are found by linear
interpolation of the overlap (or of k xi + gamma xi_dot for limit_force yes) between the
sampled steps, so the remaining error is of order (dt/t_c) for the force sampling of the
velocity-Verlet scheme. Tolerance: 2 dt/t_c = 0.5 % relative for e and t_c.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.restitution")
STEPS_PER_CONTACT = 400
TOL = 2.0 / STEPS_PER_CONTACT
RHO = 2500.0


def closed_form(beta, end):
    w = math.sqrt(1.0 - beta * beta)
    if end == "no":
        tau = math.pi / w
        e = math.exp(-math.pi * beta / w)
    else:
        tau = 2.0 * math.atan2(w, beta) / w
        e = math.exp(-beta * tau)
    return e, tau


def mass(r):
    return RHO * 4.0 / 3.0 * math.pi * r ** 3


TEMPLATE = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 box
{atoms}
set             group all density {rho}
velocity        all set 0 0 0
{velocities}
neighbor        0.001 bin
neigh_modify    delay 0
{interaction}
fix             nve all nve/sphere
timestep        {dt!r}
variable        z1 equal z[1]
variable        v1 equal vz[1]
variable        z2 equal {z2}
variable        v2 equal {v2}
thermo_style    custom step v_z1 v_v1 v_z2 v_v2
thermo_modify   format float %.17g
thermo          1
run             {nsteps}
"""


def measure(rows, dt, radsum, k, gamma, end, wall):
    """rows: (step, z1, v1, z2, v2). Returns (e, tc) with interpolated contact start/end."""
    t, xi, xid = [], [], []
    for s, z1, v1, z2, v2 in rows:
        if wall:  # sphere 1 above the wall z = 0: overlap R - z
            xi.append(radsum - z1)
            xid.append(-v1)
        else:  # sphere 2 above sphere 1 along z
            xi.append(radsum - (z2 - z1))
            xid.append(-(v2 - v1))
        t.append(s * dt)
    f = [k * a + gamma * b for a, b in zip(xi, xid)]
    # start: overlap crosses 0 upwards
    i0 = next(i for i in range(1, len(xi)) if xi[i] > 0 >= xi[i - 1])
    ts = t[i0 - 1] + dt * (0 - xi[i0 - 1]) / (xi[i0] - xi[i0 - 1])
    g = xi if end == "no" else f
    i1 = next(i for i in range(i0 + 1, len(g)) if g[i] <= 0 < g[i - 1])
    te = t[i1 - 1] + dt * g[i1 - 1] / (g[i1 - 1] - g[i1])
    vin = xid[0]
    vout = xid[-1]
    return -vout / vin, te - ts


cases = []
for geom in ("wall", "pair"):
    for end in ("no", "yes"):
        for mode in ("restitution", "stiffness"):
            cases.append((geom, end, mode))

r1, r2 = 0.005, 0.004
for geom, end, mode in cases:
    wall = geom == "wall"
    meff = mass(r1) if wall else mass(r1) * mass(r2) / (mass(r1) + mass(r2))
    radsum = r1 if wall else r1 + r2
    if mode == "restitution":
        e_in, tc_in = 0.6, 1.0e-4
        law = "normal lsd restitution %r %r tangential cundall_strack 0.8 0.3 limit_force %s" % (
            e_in, tc_in, end)
        # k, gamma for locating the zero-force end (from the same closed forms)
        # beta from e by bisection on the closed form
        lo, hi = 0.0, 0.999999
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if closed_form(mid, end)[0] > e_in:
                lo = mid
            else:
                hi = mid
        beta = 0.5 * (lo + hi)
        w0 = closed_form(beta, end)[1] / tc_in
        k, gamma = meff * w0 * w0, meff * 2 * beta * w0
        e_exp, tc_exp = e_in, tc_in
    else:
        k, beta_t = 1.0e4, 0.2
        gamma = 2 * beta_t * math.sqrt(k * meff) * 1.1  # a round-ish absolute value
        gamma = float("%.6g" % gamma)
        law = ("normal lsd stiffness %r %r tangential cundall_strack %r 0 0.3 damping absolute "
               "limit_force %s" % (k, gamma, 0.8 * k, end))
        beta = gamma / (2 * math.sqrt(k * meff))
        e_exp, tau = closed_form(beta, end)
        tc_exp = tau / math.sqrt(k / meff)
    dt = float("%.6g" % (tc_exp / STEPS_PER_CONTACT))
    v0 = 0.5
    gap_steps = 20
    if wall:
        atoms = "create_atoms 1 single 0 0 %r units box\nset atom 1 diameter %r" % (
            r1 + gap_steps * dt * v0, 2 * r1)
        vel = "set atom 1 vz %r" % (-v0)
        inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL" % (law, law)
        z2, v2 = "0", "0"
    else:
        zc = 0.05
        atoms = ("create_atoms 1 single 0 0 %r units box\ncreate_atoms 1 single 0 0 %r units box\n"
                 "set atom 1 diameter %r\nset atom 2 diameter %r" % (
                     zc, zc + r1 + r2 + gap_steps * dt * v0, 2 * r1, 2 * r2))
        vel = "set atom 1 vz %r\nset atom 2 vz %r" % (v0 / 2, -v0 / 2)
        inter = "pair_style tdem/gran\npair_coeff * * %s" % law
        z2, v2 = "z[2]", "vz[2]"
    nsteps = gap_steps + int(1.5 * STEPS_PER_CONTACT) + 40
    text = TEMPLATE.format(atoms=atoms, rho=RHO, velocities=vel, interaction=inter, dt=dt,
                           z2=z2, v2=v2, nsteps=nsteps)
    wd = lc.workdir("rest_%s_%s_%s" % (geom, end, mode))
    _, out = lc.run(args["tdem"], text, wd)
    rows = [tuple(float(x) for x in l.split()) for l in lc.thermo_blocks(out)[1:]]
    e_m, tc_m = measure(rows, dt, radsum, k, gamma, end, wall)
    de, dtc = e_m / e_exp - 1, tc_m / tc_exp - 1
    tag = "%s limit_force %s %s" % (geom, end, mode)
    print("%s: e %.6f (expected %.6f, rel err %+.2e), t_c %.6e (expected %.6e, rel err %+.2e)"
          % (tag, e_m, e_exp, de, tc_m, tc_exp, dtc))
    chk.check(abs(de) <= TOL, "%s: restitution within %.2g" % (tag, TOL))
    chk.check(abs(dtc) <= TOL, "%s: contact time within %.2g" % (tag, TOL))
chk.done()
