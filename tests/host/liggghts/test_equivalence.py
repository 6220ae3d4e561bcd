# SPDX-License-Identifier: GPL-2.0-or-later
"""Equivalence with the stock LIGGGHTS models: a settling bed of 2400 spheres (two types) in a
box of six primitive walls (fix wall/gran; one case adds a V-shaped mesh floor) is run with a stock model under the stock
`liggghts` and with the tdem model configured identically under `tdem-liggghts`. Positions,
velocities and angular velocities at the end must agree to a relative 1e-8 (the adapters feed
the kernels the same operands in the same order, so the expected difference is exactly 0; the
number of bitwise-different values is printed)."""
import os

import numpy as np

import scenes as S
import tdem_lig as T

TOL = 1e-8

STIFF_ABS_PROPS = S.STIFFNESS_PROPS.replace("gamman peratomtypepair 2 300 280 280 260",
                                            "gamman_abs peratomtypepair 2 0.03 0.028 0.028 0.026") \
                                   .replace("gammat peratomtypepair 2 120 110 110 100",
                                            "gammat_abs peratomtypepair 2 0.012 0.011 0.011 0.010")

# model hooke has kt = kn: tangentialStiffnessRatio 1
MATERIAL_PROPS = S.HOOKE_PROPS + """
fix m_kap all property/global tangentialStiffnessRatio peratomtypepair 2 1 1 1 1
"""

ROLL_PROPS = S.STIFFNESS_PROPS + """
fix m_rmu all property/global coefficientRollingFriction peratomtypepair 2 0.1 0.12 0.12 0.15
"""

CASES = [
    # name, stock model args, tdem model args, properties
    ("lsd_vs_hooke_stiffness",
     "model hooke/stiffness tangential history",
     "model tdem/lsd tangential tdem/cundall_strack", S.STIFFNESS_PROPS),
    ("lsd_vs_hooke_stiffness_limitForce",
     "model hooke/stiffness tangential history limitForce on",
     "model tdem/lsd tangential tdem/cundall_strack limitForce on", S.STIFFNESS_PROPS),
    ("lsd_vs_hooke_stiffness_absdamp_notdamp",
     "model hooke/stiffness tangential history absolute_damping on tangential_damping off",
     "model tdem/lsd tangential tdem/cundall_strack absolute_damping on tangential_damping off",
     STIFF_ABS_PROPS),
    ("hooke_cundall_strack_vs_hooke_history",
     "model hooke tangential history",
     "model hooke tangential tdem/cundall_strack", S.HOOKE_PROPS),
    ("lsd_material_vs_hooke",
     "model hooke tangential history",
     "model tdem/lsd tangential tdem/cundall_strack parameters material", MATERIAL_PROPS),
    ("hertz_cundall_strack_vs_hertz_history",
     "model hertz tangential history",
     "model hertz tangential tdem/cundall_strack", S.HOOKE_PROPS),
    ("lsd_cdt_vs_hooke_stiffness_cdt",
     "model hooke/stiffness tangential history rolling_friction cdt",
     "model tdem/lsd tangential tdem/cundall_strack rolling_friction cdt", ROLL_PROPS),
    ("lsd_epsd2_vs_hooke_stiffness_epsd2",
     "model hooke/stiffness tangential history rolling_friction epsd2",
     "model tdem/lsd tangential tdem/cundall_strack rolling_friction epsd2", ROLL_PROPS),
    ("lsd_vs_hooke_stiffness_mesh_floor",
     "model hooke/stiffness tangential history",
     "model tdem/lsd tangential tdem/cundall_strack", S.STIFFNESS_PROPS, dict(mesh_floor=True)),
    ("lsd_history_vs_hooke_stiffness_history",
     "model hooke/stiffness tangential history",
     "model tdem/lsd tangential history", S.STIFFNESS_PROPS),
]


def main():
    args = T.parse_args(lambda p: p.add_argument("--steps", type=int, default=8000))
    checks = T.Checks()
    stock_ends = {}
    for case in CASES:
        name, stock_model, tdem_model, props = case[:4]
        opts = case[4] if len(case) > 4 else {}
        d = T.workdir(args, "tdem_lig_equiv_" + name)
        res = {}
        for tag, exe, model in (("stock", args.stock, stock_model), ("tdem", args.tdem, tdem_model)):
            sub = os.path.join(d, tag)
            os.makedirs(sub)
            if opts.get("mesh_floor"):
                S.write_v_floor_stl(os.path.join(sub, "floor.stl"))
            T.run(exe, S.settling(model, props, steps=args.steps, **opts), sub, tag)
            res[tag] = T.read_dump(os.path.join(sub, "dump.settle"))
        (s0, cols, a), (s1, _, b) = res["stock"][-1], res["tdem"][-1]
        stock_ends[name] = a
        checks.check(s0 == s1 == args.steps and a.shape == b.shape and a.shape[0] == 2400,
                     "%s: both runs reach step %d with 2400 atoms" % (name, args.steps))
        if a.shape != b.shape:
            continue
        checks.check(np.array_equal(a[:, cols.index("id")], b[:, cols.index("id")]), name + ": same ids")
        for group in (("x", "y", "z"), ("vx", "vy", "vz"), ("omegax", "omegay", "omegaz")):
            idx = [cols.index(c) for c in group]
            rel = T.max_rel_diff(a[:, idx], b[:, idx])
            nbit = int(np.count_nonzero(a[:, idx] != b[:, idx]))
            checks.check(rel <= TOL, "%s: %s max relative difference %.3e (<= %g), %d of %d values differ bitwise"
                         % (name, "/".join(group), rel, TOL, nbit, a[:, idx].size))
        # the scene must exercise contacts: without them the spheres would be in free fall
        # (> 1 m/s after 0.16 s); in the bed they have come almost to rest
        v = np.linalg.norm(a[:, [cols.index(c) for c in ("vx", "vy", "vz")]], axis=1)
        checks.check(float(v.mean()) < 0.25, name + ": bed formed (mean speed %.3g m/s < 0.25)" % v.mean())
        if opts.get("mesh_floor"):
            # the mesh floor carries the bed: every sphere stays above it (its lowest point is
            # z = 2 mm, the smallest radius 2 mm), none reaches the primitive plane z = 0
            zmin = float(a[:, cols.index("z")].min())
            checks.check(zmin > 0.0036, name + ": bed rests on the mesh floor (min z %.4g m > 0.0036)" % zmin)
    # negative control: the comparison is sensitive -- two stock runs that differ only in
    # limitForce must not pass the same tolerance
    a, b = stock_ends[CASES[0][0]], stock_ends[CASES[1][0]]
    rel = T.max_rel_diff(a[:, 2:5], b[:, 2:5])
    checks.check(rel > TOL, "control: stock limitForce off vs on differ by %.3e in positions (> %g)" % (rel, TOL))
    checks.done()


if __name__ == "__main__":
    main()
