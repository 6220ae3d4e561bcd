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


def ms_scene(n, k, gamma, dt, steps, correction, proc="", across=False):
    """One multisphere rod of n spheres along x, inserted at most 0.1 mm above touching (insert/pack's
    own placement), falling at CORR_V."""
    r, rho, dist, v0 = CORR_R, CORR_RHO, CORR_DIST, CORR_V
    m = 4.0 / 3.0 * math.pi * r ** 3 * rho
    mass = n * m
    xs = [(i - 0.5 * (n - 1)) * dist for i in range(n)]
    i_axis = n * 0.4 * m * r * r                      # exact inertia of the rod about its centre
    i_across = i_axis + m * sum(x * x for x in xs)
    spheres = " ".join("%.17g 0 0 %.17g" % ((i - 0.5 * (n - 1)) * dist, r) for i in range(n))
    surf = " surface tdem/clump" if correction not in ("none", None) else ""
    law = "parameters stiffness absolute_damping on"
    zc = r + 2e-6
    lines = ["atom_style sphere", "atom_modify map array sort 0 0", "boundary f f f", "newton off",
             "communicate single vel yes", "units si", proc,
             "region b block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box", "create_box 1 b",
             "neighbor 0.001 bin", "neigh_modify delay 0",
             "fix m_kn all property/global kn peratomtypepair 1 %.17g" % k,
             "fix m_kt all property/global kt peratomtypepair 1 %.17g" % k,
             "fix m_gn all property/global gamman_abs peratomtypepair 1 %.17g" % gamma,
             "fix m_gt all property/global gammat_abs peratomtypepair 1 0.0",
             "fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0",
             "pair_style gran model tdem/lsd tangential no_history%s %s" % (surf, law), "pair_coeff * *",
             "timestep %.17g" % dt,
             "fix w all wall/gran model tdem/lsd tangential no_history%s primitive type 1 zplane 0.0 %s" % (surf, law),
             "fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant %.17g nspheres %d "
             "ntry 1000000 spheres %s type 1 mass %.17g inertia_tensor %.17g 0 0 %.17g 0 %.17g use_density"
             % (rho, n, spheres, mass, i_axis, i_across, i_across),
             "fix pdd all particledistribution/discrete 32452843 1 pts 1.0",
             "region ins block %s -0.001 0.001 %.17g %.17g units box" % (
                 "0.03 0.031" if across else "0.005 0.007", zc + (4e-4 if across else 0.0),
                 zc + (5e-4 if across else 1e-4)),
             "fix ins all insert/pack seed 49979687 distributiontemplate pdd vel constant %g 0 %.17g "
             "orientation template insert_every once overlapcheck yes region ins particles_in_region 1 "
             "ntry_mc 1000" % (-40.0 if across else 0.0, -v0),
             "fix ms all multisphere"]
    if correction not in ("none", None):
        lines.append("fix corr all tdem/correction %s bodies ms" % correction)
    # lowest centre, mean velocity of the spheres (= the body's: no rotation) - variable group
    # functions are refused with fix multisphere
    lines += ["compute p all property/atom z vz x", "compute zmin all reduce min c_p[1]",
              "compute vz all reduce ave c_p[2]", "compute xmin all reduce min c_p[3]",
              "compute xmax all reduce max c_p[3]", "thermo_style custom step atoms c_zmin c_vz c_xmin c_xmax", "thermo_modify format float %.17g", "thermo 1",
              "run %d" % steps]
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


BAD = [
    ("fix corr all tdem/correction local_mass bodies ms", ["local_mass", "count, overlap"]),
    ("fix corr all tdem/correction many bodies ms", ["'many'", "count, overlap"]),
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
        p.add_argument("--part", required=True, choices=["flat", "bad"])
    args = T.parse_args(extra)
    checks = T.Checks()
    globals()["part_" + args.part](args, checks)
    checks.done()


if __name__ == "__main__":
    main()
