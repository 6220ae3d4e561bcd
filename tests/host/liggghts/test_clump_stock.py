#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/correction in LIGGGHTS (issue 20): the multiple-contact correction for the bodies of the
stock fix multisphere. Expected values are closed forms, independent of the code under test:

 flat   rods of N = 2, 4, 8 spheres (r = 5 mm, 12.5 mm apart, one stock particletemplate/multisphere
        body of the exact mass N m, orientation template: lying flat) dropped at 1 m/s on a wall/gran
        plane, tdem/lsd with per-contact k and gamma derived for ONE contact on the body mass for
        e = 0.8, t_c = 1e-4 s (physics_reference 6.4), no gravity, no friction. With `fix tdem/correction
        count|overlap bodies MS`: the single-contact e and t_c to 1e-3. Without it (and without
        `surface tdem/clump`): the N-contact closed form (N k, N gamma) - the correction is what
        changes the result. The N = 4 rod also on -np 2 (processors 2 1 1), sliding frictionless along x
        so that it lies across the two sub-domains when it hits: the same e and t_c.
 local  correction local_mass: a multisphere dimer tilted by 30 degrees hits the wall with one sphere; the
        contact point's e is the law's with it and the m_loc closed form without it; -np 2 (the dimer
        across the sub-domains) gives the same e.
 bad    bad input ends with an error naming the argument and what is allowed.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tdem_lig as T  # noqa: E402
from test_clump import CORR_R, CORR_RHO, CORR_DIST, CORR_E, CORR_T, CORR_V  # noqa: E402
from test_clump import lsd_rates, lsd_outcome, crossing_times  # noqa: E402


def ms_scene(n, k, gamma, dt, steps, correction, proc="", across=False, dist=CORR_DIST, tilt=0.0, restitution=None,
             dump=None, slide=None):
    """One multisphere rod of n spheres along x, inserted at most 0.1 mm above touching (insert/pack's
    own placement), falling at CORR_V; tilt: rotated about y by tilt (rad), the sphere at +x lowest;
    restitution = (e1, t1): the law by `parameters restitution` (k, gamma = m* times rates); slide =
    (x_lo, x_hi, dz_lo, dz_hi, vx): insertion box in x and height above touching, and the x velocity
    (across: (0.03, 0.031, 4e-4, 5e-4, -40))."""
    r, rho, v0 = CORR_R, CORR_RHO, CORR_V
    m = 4.0 / 3.0 * math.pi * r ** 3 * rho
    mass = n * m
    xs = [(i - 0.5 * (n - 1)) * dist for i in range(n)]
    i_axis = n * 0.4 * m * r * r                      # exact inertia of the rod about its centre
    i_across = i_axis + m * sum(x * x for x in xs)
    spheres = " ".join("%.17g 0 0 %.17g" % ((i - 0.5 * (n - 1)) * dist, r) for i in range(n))
    surf = " surface tdem/clump" if correction not in ("none", None) else ""
    law = "parameters stiffness absolute_damping on"
    props = ["fix m_kn all property/global kn peratomtypepair 1 %.17g" % k,
             "fix m_kt all property/global kt peratomtypepair 1 %.17g" % k,
             "fix m_gn all property/global gamman_abs peratomtypepair 1 %.17g" % gamma,
             "fix m_gt all property/global gammat_abs peratomtypepair 1 0.0"]
    if restitution:
        law = "parameters restitution"
        props = ["fix m_e all property/global coefficientRestitution peratomtypepair 1 %.17g" % restitution[0],
                 "fix m_tc all property/global contactTime peratomtypepair 1 %.17g" % restitution[1],
                 "fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.0"]
    zc = r + 2e-6 + 0.5 * (n - 1) * dist * math.sin(tilt)
    if slide is None:
        slide = (0.03, 0.031, 4e-4, 5e-4, -40.0) if across else (0.005, 0.007, 0.0, 1e-4, 0.0)
    quat = "template" if tilt == 0.0 else "constant %.17g 0 %.17g 0" % (math.cos(0.5 * tilt), math.sin(0.5 * tilt))
    lines = ["atom_style sphere", "atom_modify map array sort 0 0", "boundary f f f", "newton off",
             "communicate single vel yes", "units si", proc,
             "region b block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box", "create_box 1 b",
             "neighbor 0.001 bin", "neigh_modify delay 0",
             ] + props + ["fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0",
             "pair_style gran model tdem/lsd tangential no_history%s %s" % (surf, law), "pair_coeff * *",
             "timestep %.17g" % dt,
             "fix w all wall/gran model tdem/lsd tangential no_history%s primitive type 1 zplane 0.0 %s" % (surf, law),
             "fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant %.17g nspheres %d "
             "ntry 1000000 spheres %s type 1 mass %.17g inertia_tensor %.17g 0 0 %.17g 0 %.17g use_density"
             % (rho, n, spheres, mass, i_axis, i_across, i_across),
             "fix pdd all particledistribution/discrete 32452843 1 pts 1.0",
             "region ins block %.17g %.17g -0.001 0.001 %.17g %.17g units box" % (
                 slide[0], slide[1], zc + slide[2], zc + slide[3]),
             "fix ins all insert/pack seed 49979687 distributiontemplate pdd vel constant %.17g 0 %.17g "
             "orientation %s insert_every once overlapcheck yes region ins particles_in_region 1 "
             "ntry_mc 1000" % (slide[4], -v0, quat),
             "fix ms all multisphere"]
    if correction not in ("none", None):
        lines.append("fix corr all tdem/correction %s bodies ms" % correction)
    # lowest centre, mean velocity of the spheres (= the body's: no rotation) - variable group
    # functions are refused with fix multisphere
    lines += ["compute p all property/atom z vz x", "compute zmin all reduce min c_p[1]",
              "compute vz all reduce ave c_p[2]", "compute xmin all reduce min c_p[3]",
              "compute xmax all reduce max c_p[3]", "thermo_style custom step atoms c_zmin c_vz c_xmin c_xmax",
              "thermo_modify format float %.17g", "thermo 1"]
    if dump:
        lines += ["dump d all custom 1 %s id x z vz" % dump, "dump_modify d format \"%d %.17g %.17g %.17g\""]
    lines += ["run %d" % steps]
    return "\n".join(lines) + "\n"


def impact(args, d, name, n, corr, np_=1):
    """(e, t_c, e_ref, t_ref) of the rod of n spheres with correction corr (none: N contacts)."""
    M = n * 4.0 / 3.0 * math.pi * CORR_R ** 3 * CORR_RHO
    kpm, gpm = lsd_rates(CORR_E, CORR_T)
    k, gamma = M * kpm, M * gpm
    e_ref, t_ref = lsd_outcome(k, gamma, M) if corr != "none" else lsd_outcome(n * k, n * gamma, M)
    dt = CORR_T / 4000.0
    # on 2 ranks the body is inserted inside one sub-domain (insert/pack places a body only within one)
    # and slides frictionless at 40 m/s along x, so that it lies across x = 0 when it hits the wall
    steps = int(((5.02e-4 if np_ == 2 else 1.02e-4) / CORR_V + 1.6 * CORR_T) / dt)
    proc = "processors 2 1 1" if np_ == 2 else ""
    T.run(args.tdem, ms_scene(n, k, gamma, dt, steps, corr, proc, across=np_ == 2), d, name, np_=np_,
          mpirun=args.mpirun)
    blocks = T.thermo_blocks(open(os.path.join(d, "log." + name)).read())
    rows = np.array([[float(x) for x in s.split()] for s in blocks[-1][1]])
    rows = rows[rows[:, 1] == n]  # steps after the insertion
    ct = crossing_times(rows[:, 0] * dt, CORR_R - rows[:, 2])
    if ct is None:
        return None
    touch = rows[np.argmax(CORR_R - rows[:, 2] > 0)]  # the first step in contact
    return rows[-1, 3] / CORR_V, ct[1] - ct[0], e_ref, t_ref, (touch[4], touch[5])


def part_flat(args, checks):
    d = T.workdir(args, "tdem_lig_clump_stock_flat")
    cases = [(n, c, 1) for c in ("count", "overlap") for n in (2, 4, 8)] + [(4, "none", 1), (4, "count", 2),
                                                                           (4, "overlap", 2)]
    for n, corr, np_ in cases:
        name = "ms%d_%s_np%d" % (n, corr, np_)
        got = impact(args, d, name, n, corr, np_)
        if got is None:
            checks.check(False, "%s: no contact" % name)
            continue
        e, tc, e_ref, t_ref, span = got
        if np_ == 2:
            checks.check(span[0] < 0.0 < span[1],
                         "%s: the body lies across the two sub-domains when it hits (sphere centres x = %.4f .. "
                         "%.4f m)" % (name, span[0], span[1]))
        err_e, err_t = e / e_ref - 1, tc / t_ref - 1
        what = "single-contact" if corr != "none" else "N-contact"
        print("multisphere N=%d, correction %s, -np %d: e = %.6f (%.6f, %.1e), t_c = %.6e s (%.6e, %.1e)"
              % (n, corr, np_, e, e_ref, err_e, tc, t_ref, err_t))
        checks.check(abs(err_e) < 1e-3 and abs(err_t) < 1e-3,
                     "fix multisphere rod N=%d, %s, -np %d: e, t_c = the %s closed form (%.1e, %.1e < 1e-3)"
                     % (n, "tdem/correction " + corr if corr != "none" else "no correction", np_, what, err_e, err_t))


def dimer_impact(args, d, name, corr, np_=1):
    """The contact-point e of the tilted multisphere dimer (the lower sphere's vz after / before) and
    the sphere centres' x at the first step in contact."""
    dt = 2e-5 / 4000.0
    # on 2 ranks inserted in one sub-domain (x > 0), sliding frictionless to x = 0 during the fall
    # (insert/pack keeps the bounding sphere, 10.4 mm, inside the sub-domain; the centre at the touch is
    # within +-3.9 mm of x = 0, the spheres +-4.7 mm from it)
    slide = (0.011, 0.015, 1.5e-4, 2e-4, -0.013 / 1.75e-4) if np_ == 2 else (0.005, 0.007, 0.0, 1e-4, 0.0)
    steps = int(((2.02e-4 if np_ == 2 else 1.02e-4) / CORR_V + 1.5 * 2e-5) / dt)
    text = ms_scene(2, 0, 0, dt, steps, corr, "processors 2 1 1" if np_ == 2 else "", dist=2.5 * CORR_R,
                    tilt=math.radians(30.0), restitution=(CORR_E, 2e-5), dump="dump." + name, slide=slide)
    T.run(args.tdem, text, d, name, np_=np_, mpirun=args.mpirun)
    fr = [f for f in T.read_dump(os.path.join(d, "dump." + name)) if len(f[2]) == 2]
    low = int(np.argmin(fr[0][2][:, 2]))
    z = np.array([f[2][low, 2] for f in fr])
    vz = np.array([f[2][low, 3] for f in fr])
    ztop = np.array([f[2][1 - low, 2] for f in fr])
    ins = np.where(CORR_R - z > 0)[0]
    if len(ins) == 0 or ins[-1] + 1 >= len(z) or np.any(np.diff(ins) > 1):
        return None
    return -vz[ins[-1] + 1] / vz[ins[0] - 1], (CORR_R - ztop).max(), fr[ins[0]][2][:, 1], vz


def part_local(args, checks):
    """local_mass with the bodies of fix multisphere: a dimer (spheres 2.5 r apart) tilted by 30 degrees,
    frictionless, (e, t_c) law (k, gamma = m* rates), hits the wall with one sphere off the centre-of-
    mass line. The normal velocity of the contact point after/before = the law's e to 1e-3 with
    `fix tdem/correction local_mass` (m* = m_loc, the closed form of two spheres); without it the
    closed form of the rates on the body mass acting on m_loc. On -np 2 the dimer slides across x = 0
    (one sphere on each sub-domain at the impact): the same e."""
    from test_clump import dimer_local_mass
    d = T.workdir(args, "tdem_lig_clump_stock_local")
    mloc, msph = dimer_local_mass(CORR_R, 2.5 * CORR_R, CORR_RHO, math.radians(30.0))
    kpm, gpm = lsd_rates(CORR_E, 2e-5)
    e_none, _ = lsd_outcome(2 * msph * kpm, 2 * msph * gpm, mloc)
    out = {}
    for corr, np_ in (("local_mass", 1), ("none", 1), ("local_mass", 2)):
        name = "dim_%s_np%d" % (corr, np_)
        got = dimer_impact(args, d, name, corr, np_)
        checks.check(got is not None, "%s: one complete contact of the lower sphere" % name)
        if got is None:
            return
        out[name] = got
        print("multisphere dimer at 30 deg, correction %s, -np %d: contact-point e %.6f (law %.2f; closed form "
              "without the correction %.6f), sphere x at the touch %s" % (corr, np_, got[0], CORR_E, e_none,
                                                                         np.array2string(got[2], precision=4)))
    for name, g in out.items():
        checks.check(g[1] < 0, "%s: the upper sphere never touched" % name)
    e_loc = out["dim_local_mass_np1"][0]
    checks.check(abs(e_loc / CORR_E - 1) < 1e-3,
                 "local_mass: contact-point e %.6f = the law's e (%.1e < 1e-3)" % (e_loc, e_loc / CORR_E - 1))
    e_no = out["dim_none_np1"][0]
    checks.check(abs(e_no / e_none - 1) < 2e-3 and abs(e_no - CORR_E) > 5e-3,
                 "no correction: e %.5f = closed form with m* = body mass on m_loc (%.5f), not %.2f"
                 % (e_no, e_none, CORR_E))
    g2 = out["dim_local_mass_np2"]
    # (another scene: inserted elsewhere, the touch falls elsewhere in the time grid)
    checks.check(g2[2].min() < 0.0 < g2[2].max() and abs(g2[0] / e_loc - 1) < 1e-6,
                 "local_mass, -np 2, the dimer across the sub-domains at the touch (x = %.4f, %.4f): e %.9f = -np 1 "
                 "(%.1e < 1e-6)" % (g2[2][0], g2[2][1], g2[0], g2[0] / e_loc - 1))


BAD = [
    ("fix corr all tdem/correction many bodies ms", ["'many'", "count, overlap, local_mass"]),
    ("fix corr all tdem/correction count ms", ["expected 3 arguments", "bodies"]),
    ("fix corr all tdem/correction count bodies nofix", ["fix nofix does not exist"]),
    ("fix corr all tdem/correction count bodies w", ["is not a fix multisphere"]),
]


def part_bad(args, checks):
    d = T.workdir(args, "tdem_lig_clump_stock_bad")
    M = 4 * 4.0 / 3.0 * math.pi * CORR_R ** 3 * CORR_RHO
    kpm, gpm = lsd_rates(CORR_E, CORR_T)
    base = ms_scene(4, M * kpm, M * gpm, CORR_T / 4000.0, 10, "count")
    for k, (line, want) in enumerate(BAD):
        text = base.replace("fix corr all tdem/correction count bodies ms", line)
        r = T.run(args.tdem, text, d, "bad%d" % k, check=False)
        out = r.stdout + r.stderr
        ok = r.returncode != 0 and "ERROR" in out and all(w in out for w in want)
        checks.check(ok, "'%s' stops with an error naming %s" % (line, ", ".join(want)))
    # the correction acts through surface tdem/clump: a wall without it is an error
    text = base.replace("no_history surface tdem/clump primitive", "no_history primitive")
    r = T.run(args.tdem, text, d, "nosurf", check=False)
    out = r.stdout + r.stderr
    checks.check(r.returncode != 0 and "has no 'surface tdem/clump'" in out,
                 "a wall/gran fix without surface tdem/clump is an error naming it")


def main():
    def extra(p):
        p.add_argument("--part", required=True, choices=["flat", "local", "bad"])
    args = T.parse_args(extra)
    checks = T.Checks()
    globals()["part_" + args.part](args, checks)
    checks.done()


if __name__ == "__main__":
    main()
