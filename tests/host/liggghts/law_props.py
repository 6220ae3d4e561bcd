# SPDX-License-Identifier: GPL-2.0-or-later
"""One consistent set of fix property/global values that every tdem LIGGGHTS law and setting can
read (test_robustness.py, test_sweep.py): per type pair, per type and scalar, for type pair 1-1."""

PAIR = {
    "kn": 1e4, "kt": 3e3, "gamman": 10.0, "gammat": 1.0, "gamman_abs": 1e-3, "gammat_abs": 1e-4,
    "coefficientRestitution": 0.8, "contactTime": 1e-4, "tangentialStiffnessRatio": 0.3,
    "coefficientFriction": 0.5, "tangentialDampingRatio": 0.1,
    "dampingCoefficient": 0.3, "dampingExponent": 0.25,
    "loadingStiffness": 1e4, "unloadingStiffness": 5e4, "unloadingStiffnessSlope": 2000.0,
    "yieldPressure": 5e5,
    "potentialEnergy": 1e-3, "potentialExponent": 24.0,
    "loadingCoefficient": 2e5, "loadingExponent": 1.5, "unloadingCoefficient": 2e7,
    "unloadingExponentIncrement": 0.5,
    "restitutionFitC0": 0.8, "restitutionFitC1": 1.0, "restitutionFitC2": 0.1,
    "contactTimeFitC0": 5e-4, "contactTimeFitC1": 0.2,
    "rollingStiffness": 1e3, "rollingDamping": 1.0, "coefficientRollingFriction": 0.1,
}
TYPE = {"youngsModulus": 5e6, "poissonsRatio": 0.3}
SCALAR = {"characteristicVelocity": 1.0}


def lines(ntypes=1, pair_value=None, type_value=None, over=None):
    """fix property/global lines for ntypes types. pair_value(name, v, i, j) / type_value(name, v, t)
    give the value of a pair or type entry (default: v everywhere); over: name -> text that replaces
    every entry of that property (the sweep's mutations)."""
    over = over or {}
    out = []
    for k, v in PAIR.items():
        vals = [over.get(k) or repr(pair_value(k, v, i, j) if pair_value else v)
                for i in range(ntypes) for j in range(ntypes)]
        out.append("fix p_%s all property/global %s peratomtypepair %d %s" % (k, k, ntypes, " ".join(vals)))
    for k, v in TYPE.items():
        vals = [over.get(k) or repr(type_value(k, v, t) if type_value else v) for t in range(ntypes)]
        out.append("fix p_%s all property/global %s peratomtype %s" % (k, k, " ".join(vals)))
    for k, v in SCALAR.items():
        out.append("fix p_%s all property/global %s scalar %s" % (k, k, over.get(k) or repr(v)))
    return "\n".join(out)
