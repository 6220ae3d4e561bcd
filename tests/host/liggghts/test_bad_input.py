# SPDX-License-Identifier: GPL-2.0-or-later
"""Bad input to the tdem LIGGGHTS styles must end with a LIGGGHTS error (error->all / error->one:
exit status 1, never a signal) whose message names the keyword, the value and what is allowed.
Every case asserts the exit status and the message text."""
import re

import tdem_lig as T

GOOD_REST = {
    "coefficientRestitution": "peratomtypepair 2 0.8 0.8 0.8 0.8",
    "contactTime": "peratomtypepair 2 1e-4 1e-4 1e-4 1e-4",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
GOOD_STIFF = {
    "kn": "peratomtypepair 2 1e4 1e4 1e4 1e4",
    "kt": "peratomtypepair 2 3e3 3e3 3e3 3e3",
    "gamman": "peratomtypepair 2 10 10 10 10",
    "gammat": "peratomtypepair 2 1 1 1 1",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}

GOOD_MAT = {
    "youngsModulus": "peratomtype 5e6 5e6",
    "poissonsRatio": "peratomtype 0.3 0.3",
    "characteristicVelocity": "scalar 1.0",
    "coefficientRestitution": "peratomtypepair 2 0.8 0.8 0.8 0.8",
    "tangentialStiffnessRatio": "peratomtypepair 2 1 1 1 1",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}


def props(base, **changes):
    p = dict(base)
    for k, v in changes.items():
        if v is None:
            p.pop(k, None)
        else:
            p[k] = v
    return "\n".join("fix p_%s all property/global %s %s" % (k, k, v) for k, v in p.items())


def scene(pair_args, properties, wall_args=None):
    wall = ""
    if wall_args is not None:
        wall = "fix w all wall/gran %s\n" % wall_args
    return """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.05 units box
create_box 2 box
neighbor 0.002 bin
%s
pair_style gran %s
pair_coeff * *
timestep 1e-6
create_atoms 1 single 0 0 0.01 units box
create_atoms 2 single 0 0 0.02 units box
set group all diameter 0.005 density 2500
%s
fix integr all nve/sphere
run 10
""" % (properties, pair_args, wall)


LSD = "model tdem/lsd tangential tdem/cundall_strack"
LSD_REST = LSD + " parameters restitution"

CASES = [
    # name, pair_style args, properties, wall args or None, regexes the error line must match
    ("unknown normal model", "model tdem/lsdx tangential history", props(GOOD_STIFF), None,
     [r"keyword 'model'", r"unknown normal model 'tdem/lsdx'", r"allowed: .*hooke/stiffness.*tdem/lsd"]),
    ("unknown tangential model", "model tdem/lsd tangential tdem/cundall", props(GOOD_STIFF), None,
     [r"keyword 'tangential'", r"'tdem/cundall'", r"allowed: .*tdem/cundall_strack"]),
    ("unknown model in wall/gran", LSD, props(GOOD_STIFF),
     "model tdem/lsd tangential bogus primitive type 1 zplane 0.0",
     [r"keyword 'tangential'", r"'bogus'", r"allowed: .*history"]),
    ("combination not compiled", LSD + " cohesion sjkr", props(GOOD_STIFF), None,
     [r"'model tdem/lsd tangential tdem/cundall_strack cohesion sjkr rolling_friction off surface default'",
      r"not compiled", r"compiled tdem combinations"]),
    ("parameters value", LSD + " parameters elastic", props(GOOD_STIFF), None,
     [r"model tdem/lsd", r"keyword 'parameters'", r"'elastic'", r"allowed values: stiffness \| restitution \| material"]),
    ("limitForce value", LSD + " limitForce yes", props(GOOD_STIFF), None,
     [r"keyword 'limitForce'", r"'yes'", r"allowed values: off \| on"]),
    ("slip_rule value", LSD + " slip_rule dashpot", props(GOOD_STIFF), None,
     [r"tangential tdem/cundall_strack", r"keyword 'slip_rule'", r"'dashpot'",
      r"allowed values: spring \| spring_dashpot"]),
    ("absolute_damping with restitution", LSD_REST + " absolute_damping on", props(GOOD_REST), None,
     [r"absolute_damping on", r"parameters restitution", r"allowed with parameters stiffness"]),
    ("missing contactTime", LSD_REST, props(GOOD_REST, contactTime=None), None,
     [r"contactTime"]),
    ("missing tangentialStiffnessRatio", LSD_REST, props(GOOD_REST, tangentialStiffnessRatio=None), None,
     [r"tangentialStiffnessRatio"]),
    ("restitution > 1", LSD_REST, props(GOOD_REST, coefficientRestitution="peratomtypepair 2 0.8 1.2 1.2 0.8"),
     None, [r"coefficientRestitution", r"1\.2", r"types 1 2", r"\(0, 1\]"]),
    ("restitution = 0", LSD_REST, props(GOOD_REST, coefficientRestitution="peratomtypepair 2 0.8 0.8 0.8 0"),
     None, [r"coefficientRestitution", r"value 0 ", r"types 2 2", r"\(0, 1\]"]),
    ("contactTime = 0", LSD_REST, props(GOOD_REST, contactTime="peratomtypepair 2 0 1e-4 1e-4 1e-4"), None,
     [r"contactTime", r"value 0 ", r"types 1 1", r"> 0"]),
    ("contactTime < 0", LSD_REST, props(GOOD_REST, contactTime="peratomtypepair 2 1e-4 1e-4 1e-4 -1e-4"), None,
     [r"contactTime", r"-0\.0001", r"types 2 2", r"> 0"]),
    ("contactTime < 0 via wall", LSD, props(GOOD_REST, contactTime="peratomtypepair 2 1e-4 1e-4 1e-4 -1e-4") +
     "\n" + props(GOOD_STIFF), LSD + " primitive type 1 zplane 0.0 parameters restitution",
     [r"contactTime", r"-0\.0001", r"> 0"]),
    ("tangentialStiffnessRatio < 0", LSD_REST,
     props(GOOD_REST, tangentialStiffnessRatio="peratomtypepair 2 0.3 -0.3 -0.3 0.3"), None,
     [r"tangentialStiffnessRatio", r"-0\.3", r">= 0"]),
    ("negative kn", LSD, props(GOOD_STIFF, kn="peratomtypepair 2 1e4 -5e3 -5e3 1e4"), None,
     [r"model tdem/lsd", r"kn", r"-5000", r"types 1 2", r"> 0"]),
    ("zero kn", LSD, props(GOOD_STIFF, kn="peratomtypepair 2 1e4 1e4 1e4 0"), None,
     [r"kn", r"value 0 ", r"> 0"]),
    ("negative gamman", LSD, props(GOOD_STIFF, gamman="peratomtypepair 2 10 10 10 -1"), None,
     [r"gamman", r"-1", r">= 0"]),
    ("missing kn", LSD, props(GOOD_STIFF, kn=None), None, [r"\bkn\b"]),
    ("spring_dashpot with kt = 0", LSD, props(GOOD_STIFF, kt="peratomtypepair 2 0 0 0 0"),
     LSD + " primitive type 1 zplane 0.008 slip_rule spring_dashpot",
     [r"slip_rule spring_dashpot", r"kt > 0", r"kt = 0", r"types 1 1"]),
    ("material mode without characteristicVelocity", LSD + " parameters material",
     props(GOOD_MAT, characteristicVelocity=None), None, [r"characteristicVelocity"]),
    ("material mode characteristicVelocity <= 0", LSD + " parameters material",
     props(GOOD_MAT, characteristicVelocity="scalar -2"), None,
     [r"characteristicVelocity", r">= 1e-2"]),  # LIGGGHTS's own range check of the property
    ("material mode restitution > 1", LSD + " parameters material",
     props(GOOD_MAT, coefficientRestitution="peratomtypepair 2 0.8 0.8 0.8 1.5"), None,
     [r"coefficientRestitution", r"1\.5", r"types 2 2", r"\(0, 1\]"]),
    ("absolute_damping with material", LSD + " parameters material absolute_damping on", props(GOOD_MAT), None,
     [r"absolute_damping on", r"parameters material", r"allowed with parameters stiffness"]),
    ("negative friction", LSD, props(GOOD_STIFF, coefficientFriction="peratomtypepair 2 0.5 -0.5 -0.5 0.5"),
     None, [r"tangential tdem/cundall_strack", r"coefficientFriction", r"-0\.5", r">= 0"]),
]

GOOD_HERTZ = {
    "youngsModulus": "peratomtype 5e6 5e6",
    "poissonsRatio": "peratomtype 0.3 0.3",
    "coefficientRestitution": "peratomtypepair 2 0.8 0.8 0.8 0.8",
    "dampingCoefficient": "peratomtypepair 2 0.1 0.1 0.1 0.1",
    "dampingExponent": "peratomtypepair 2 0.25 0.25 0.25 0.25",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
GOOD_WB = {
    "loadingStiffness": "peratomtypepair 2 1e4 1e4 1e4 1e4",
    "unloadingStiffness": "peratomtypepair 2 2e4 2e4 2e4 2e4",
    "unloadingStiffnessSlope": "peratomtypepair 2 0 0 0 0",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
GOOD_LU = {
    "loadingStiffness": "peratomtypepair 2 1e4 1e4 1e4 1e4",
    "unloadingStiffnessMax": "peratomtypepair 2 5e4 5e4 5e4 5e4",
    "plasticityDepth": "peratomtypepair 2 0.1 0.1 0.1 0.1",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
LU = "model tdem/luding tangential tdem/cundall_strack"
GOOD_TH = {
    "youngsModulus": "peratomtype 5e6 5e6",
    "poissonsRatio": "peratomtype 0.3 0.3",
    "yieldPressure": "peratomtypepair 2 6e5 6e5 6e5 6e5",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
GOOD_CP = {
    "potentialEnergy": "peratomtypepair 2 2e-4 2e-4 2e-4 2e-4",
    "potentialExponent": "peratomtypepair 2 36 36 36 36",
    "dampingCoefficient": "peratomtypepair 2 0 0 0 0",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
CP = "model tdem/continuous_potential tangential tdem/cundall_strack"
HERTZ = "model tdem/hertz tangential tdem/cundall_strack"
WB = "model tdem/walton_braun tangential tdem/cundall_strack"
TH = "model tdem/thornton tangential tdem/cundall_strack"

CASES += [
    ("tdem/hertz damping value", HERTZ + " damping viscous", props(GOOD_HERTZ), None,
     [r"model tdem/hertz", r"keyword 'damping'", r"'viscous'",
      r"allowed values: linear \| kuwabara_kono \| tsuji \| general"]),
    ("tdem/hertz limitForce value", HERTZ + " limitForce 1", props(GOOD_HERTZ), None,
     [r"keyword 'limitForce'", r"'1'", r"allowed values: off \| on"]),
    ("tdem/hertz not compiled with cohesion", HERTZ + " cohesion sjkr", props(GOOD_HERTZ), None,
     [r"'model tdem/hertz tangential tdem/cundall_strack cohesion sjkr", r"not compiled"]),
    ("tdem/hertz tsuji without coefficientRestitution", HERTZ + " damping tsuji",
     props(GOOD_HERTZ, coefficientRestitution=None), None, [r"coefficientRestitution", r"model tdem/hertz"]),
    ("tdem/hertz tsuji restitution > 1", HERTZ, props(GOOD_HERTZ, coefficientRestitution="peratomtypepair 2 0.8 1.1 1.1 0.8"),
     None, [r"model tdem/hertz", r"coefficientRestitution", r"1\.1", r"types 1 2", r"\(0, 1\]"]),
    ("tdem/hertz linear without dampingCoefficient", HERTZ + " damping linear",
     props(GOOD_HERTZ, dampingCoefficient=None), None, [r"dampingCoefficient", r"model tdem/hertz"]),
    ("tdem/hertz negative dampingCoefficient", HERTZ + " damping kuwabara_kono",
     props(GOOD_HERTZ, dampingCoefficient="peratomtypepair 2 0.1 0.1 0.1 -2"), None,
     [r"model tdem/hertz", r"dampingCoefficient", r"-2", r"types 2 2", r">= 0"]),
    ("tdem/hertz general without dampingExponent", HERTZ + " damping general",
     props(GOOD_HERTZ, dampingExponent=None), None, [r"dampingExponent", r"model tdem/hertz"]),
    ("tdem/hertz negative dampingExponent via wall", HERTZ,
     props(GOOD_HERTZ, dampingExponent="peratomtypepair 2 -0.5 0.25 0.25 0.25"),
     HERTZ + " primitive type 1 zplane 0.0 damping general",
     [r"model tdem/hertz", r"dampingExponent", r"-0\.5", r"types 1 1", r">= 0"]),
    ("tdem/hertz negative tangentialStiffnessRatio", HERTZ,
     props(GOOD_HERTZ, tangentialStiffnessRatio="peratomtypepair 2 0.3 0.3 0.3 -1"), None,
     [r"tangentialStiffnessRatio", r"-1", r">= 0"]),
    ("tdem/walton_braun unloadingStiffness < loadingStiffness", WB,
     props(GOOD_WB, unloadingStiffness="peratomtypepair 2 2e4 5e3 5e3 2e4"), None,
     [r"model tdem/walton_braun", r"unloadingStiffness", r"5000", r"types 1 2", r">= loadingStiffness \(10000\)"]),
    # tdem/luding (docs/adding_a_law.md): the messages of a law added as a unit
    ("tdem/luding unloadingStiffnessMax < loadingStiffness", LU,
     props(GOOD_LU, unloadingStiffnessMax="peratomtypepair 2 5e4 5e3 5e3 5e4"), None,
     [r"model tdem/luding", r"unloadingStiffnessMax", r"5000", r"types 1 2", r">= loadingStiffness \(10000\)"]),
    ("tdem/luding unloadingStiffnessMax = loadingStiffness", LU,
     props(GOOD_LU, unloadingStiffnessMax="peratomtypepair 2 1e4 1e4 1e4 1e4"), None,
     [r"model tdem/luding", r"atom types 1 1", r"k2_max"]),
    ("tdem/luding plasticityDepth = 0", LU, props(GOOD_LU, plasticityDepth="peratomtypepair 2 0.1 0 0 0.1"), None,
     [r"model tdem/luding", r"plasticityDepth", r"value 0 ", r"types 1 2", r"> 0"]),
    ("tdem/luding missing plasticityDepth", LU, props(GOOD_LU, plasticityDepth=None), None, [r"plasticityDepth"]),
    ("tdem/walton_braun loadingStiffness = 0", WB,
     props(GOOD_WB, loadingStiffness="peratomtypepair 2 1e4 1e4 1e4 0"), None,
     [r"model tdem/walton_braun", r"loadingStiffness", r"value 0 ", r"types 2 2", r"> 0"]),
    ("tdem/walton_braun negative slope", WB,
     props(GOOD_WB, unloadingStiffnessSlope="peratomtypepair 2 0 -3 -3 0"), None,
     [r"unloadingStiffnessSlope", r"-3", r"types 1 2", r">= 0"]),
    ("tdem/walton_braun missing unloadingStiffnessSlope", WB, props(GOOD_WB, unloadingStiffnessSlope=None),
     None, [r"unloadingStiffnessSlope"]),
    ("tdem/walton_braun unknown setting", WB + " damping tsuji", props(GOOD_WB), None, [r"damping"]),
    ("tdem/thornton yieldPressure <= 0", TH, props(GOOD_TH, yieldPressure="peratomtypepair 2 6e5 -1e5 -1e5 6e5"),
     None, [r"model tdem/thornton", r"yieldPressure", r"-100000", r"types 1 2", r"> 0"]),
    ("tdem/thornton missing yieldPressure", TH, props(GOOD_TH, yieldPressure=None), None, [r"yieldPressure"]),
    ("tdem/continuous_potential potentialExponent <= 0", CP,
     props(GOOD_CP, potentialExponent="peratomtypepair 2 36 0 0 36"), None,
     [r"model tdem/continuous_potential", r"potentialExponent", r"value 0 ", r"types 1 2", r"> 0"]),
    ("tdem/continuous_potential missing potentialEnergy", CP, props(GOOD_CP, potentialEnergy=None), None,
     [r"potentialEnergy"]),
    ("tdem/continuous_potential limitForce value", CP + " limitForce maybe", props(GOOD_CP), None,
     [r"model tdem/continuous_potential", r"keyword 'limitForce'", r"'maybe'", r"allowed values: off \| on"]),
    ("tdem/thornton yieldPressure = 0 via wall", TH, props(GOOD_TH, yieldPressure="peratomtypepair 2 0 0 0 0"),
     TH + " primitive type 1 zplane 0.0", [r"yieldPressure", r"value 0 ", r"> 0"]),
]

GOOD_PL = {
    "loadingCoefficient": "peratomtypepair 2 5e5 5e5 5e5 5e5",
    "loadingExponent": "peratomtypepair 2 1.5 1.5 1.5 1.5",
    "unloadingCoefficient": "peratomtypepair 2 2e6 2e6 2e6 2e6",
    "unloadingExponentIncrement": "peratomtypepair 2 0 0 0 0",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
GOOD_EL = {
    "restitutionFitC0": "peratomtypepair 2 0.9 0.9 0.9 0.9",
    "restitutionFitC1": "peratomtypepair 2 1 1 1 1",
    "restitutionFitC2": "peratomtypepair 2 0.5 0.5 0.5 0.5",
    "contactTimeFitC0": "peratomtypepair 2 5e-4 5e-4 5e-4 5e-4",
    "contactTimeFitC1": "peratomtypepair 2 0.2 0.2 0.2 0.2",
    "tangentialStiffnessRatio": "peratomtypepair 2 0.3 0.3 0.3 0.3",
    "coefficientFriction": "peratomtypepair 2 0.5 0.5 0.5 0.5",
}
GOOD_EH = dict(GOOD_EL, youngsModulus="peratomtype 5e6 5e6", poissonsRatio="peratomtype 0.3 0.3")
PL = "model tdem/power_law tangential tdem/cundall_strack"
EL = "model tdem/extended_linear tangential tdem/cundall_strack"
EH = "model tdem/extended_hertz tangential tdem/cundall_strack"

CASES += [
    ("tdem/power_law loadingExponent = 0", PL, props(GOOD_PL, loadingExponent="peratomtypepair 2 1.5 0 0 1.5"), None,
     [r"model tdem/power_law", r"loadingExponent", r"value 0 ", r"types 1 2", r"> 0"]),
    ("tdem/power_law loadingCoefficient < 0", PL,
     props(GOOD_PL, loadingCoefficient="peratomtypepair 2 5e5 5e5 5e5 -1"), None,
     [r"model tdem/power_law", r"loadingCoefficient", r"-1", r"types 2 2", r"> 0"]),
    ("tdem/power_law negative unloadingExponentIncrement via wall", PL,
     props(GOOD_PL, unloadingExponentIncrement="peratomtypepair 2 -0.5 0 0 0"), PL + " primitive type 1 zplane 0.0",
     [r"model tdem/power_law", r"unloadingExponentIncrement", r"-0\.5", r"types 1 1", r">= 0"]),
    ("tdem/power_law missing unloadingCoefficient", PL, props(GOOD_PL, unloadingCoefficient=None), None,
     [r"unloadingCoefficient"]),
    ("tdem/power_law has no limitForce", PL + " limitForce on", props(GOOD_PL), None, [r"limitForce"]),
    ("tdem/extended_linear restitutionFit value", EL + " restitutionFit linear", props(GOOD_EL), None,
     [r"model tdem/extended_linear", r"keyword 'restitutionFit'", r"'linear'",
      r"allowed values: constant \| rational \| power"]),
    ("tdem/extended_linear contactTimeFit rational", EL + " contactTimeFit rational", props(GOOD_EL), None,
     [r"model tdem/extended_linear", r"keyword 'contactTimeFit'", r"'rational'", r"allowed values: constant \| power"]),
    ("tdem/extended_linear limitForce value", EL + " limitForce true", props(GOOD_EL), None,
     [r"model tdem/extended_linear", r"keyword 'limitForce'", r"'true'", r"allowed values: off \| on"]),
    ("tdem/extended_linear rational without restitutionFitC2", EL, props(GOOD_EL, restitutionFitC2=None), None,
     [r"restitutionFitC2"]),
    ("tdem/extended_linear power tc fit without contactTimeFitC1", EL + " contactTimeFit power",
     props(GOOD_EL, contactTimeFitC1=None), None, [r"contactTimeFitC1"]),
    ("tdem/extended_linear rational C0 <= 0", EL, props(GOOD_EL, restitutionFitC0="peratomtypepair 2 0.9 -0.9 -0.9 0.9"),
     None, [r"model tdem/extended_linear", r"types 1 2", r"restitutionFitC0", r"-0\.9", r"\(0, inf\)"]),
    ("tdem/extended_linear rational C1 < 0", EL, props(GOOD_EL, restitutionFitC1="peratomtypepair 2 1 1 1 -2"),
     None, [r"types 2 2", r"restitutionFitC1", r"-2", r"\[0, inf\)"]),
    ("tdem/extended_linear constant e > 1", EL + " restitutionFit constant",
     props(GOOD_EL, restitutionFitC0="peratomtypepair 2 0.9 0.9 0.9 1.5"), None,
     [r"restitutionFitC0", r"restitutionFit constant", r"1\.5", r"types 2 2", r"\(0, 1\]"]),
    ("tdem/extended_linear constant contact time <= 0", EL + " contactTimeFit constant",
     props(GOOD_EL, contactTimeFitC0="peratomtypepair 2 0 5e-4 5e-4 5e-4"), None,
     [r"contactTimeFitC0", r"= 0 ", r"types 1 1", r"\(0, inf\)"]),
    ("tdem/extended_linear power C0 <= 0 via wall", EL,
     props(GOOD_EL, contactTimeFitC0="peratomtypepair 2 -5e-4 5e-4 5e-4 5e-4"), EL + " primitive type 1 zplane 0.0",
     [r"model tdem/extended_linear", r"contactTimeFitC0", r"-0\.0005", r"\(0, inf\)"]),
    ("tdem/extended_linear impactVelocityMin <= 0", EL,
     props(GOOD_EL, impactVelocityMin="scalar -1"), None, [r"impactVelocityMin", r"-1", r"> 0"]),
    ("tdem/extended_linear impactVelocityMax < impactVelocityMin", EL,
     props(GOOD_EL, impactVelocityMin="scalar 2", impactVelocityMax="scalar 1"), None,
     [r"model tdem/extended_linear", r"impactVelocityMax = 1 ", r"\[impactVelocityMin, inf\)"]),
    ("tdem/extended_hertz restitutionFit value", EH + " restitutionFit cubic", props(GOOD_EH), None,
     [r"model tdem/extended_hertz", r"keyword 'restitutionFit'", r"'cubic'",
      r"allowed values: constant \| rational \| power"]),
    ("tdem/extended_hertz has no contactTimeFit", EH + " contactTimeFit power", props(GOOD_EH), None,
     [r"contactTimeFit"]),
    ("tdem/extended_hertz power exponent < 0", EH + " restitutionFit power",
     props(GOOD_EH, restitutionFitC1="peratomtypepair 2 0.2 -0.2 -0.2 0.2"), None,
     [r"model tdem/extended_hertz", r"types 1 2", r"restitutionFitC1", r"-0\.2", r"\[0, inf\)"]),
    ("tdem/extended_hertz missing youngsModulus", EH, props(GOOD_EH, youngsModulus=None), None,
     [r"youngsModulus"]),
    ("tdem/extended_hertz negative tangentialStiffnessRatio", EH,
     props(GOOD_EH, tangentialStiffnessRatio="peratomtypepair 2 0.3 0.3 0.3 -1"), None,
     [r"model tdem/extended_hertz", r"tangentialStiffnessRatio", r"-1", r">= 0"]),
]

# ---------------------------------------------------------------- issue-4 tangential laws
GOOD_T = dict(GOOD_REST)
GOOD_T.update({"tangentialDampingRatio": "peratomtypepair 2 0.5 0.5 0.5 0.5",
               "youngsModulus": "peratomtype 5e6 5e6", "poissonsRatio": "peratomtype 0.3 0.3"})
LS = "model tdem/lsd tangential tdem/linear_spring parameters restitution"
MD = "model tdem/lsd tangential tdem/mindlin_deresiewicz parameters restitution"
CASES += [
    ("tangential tdem/linear_spring frictionLimit value", LS + " frictionLimit positive", props(GOOD_T), None,
     [r"tangential tdem/linear_spring", r"keyword 'frictionLimit'", r"'positive'",
      r"allowed values: absolute \| positive_normal"]),
    ("tangential tdem/mindlin_no_slip slipReset value",
     "model tdem/hertz tangential tdem/mindlin_no_slip slipReset dashpot", props(GOOD_T), None,
     [r"tangential tdem/mindlin_no_slip", r"keyword 'slipReset'", r"'dashpot'",
      r"allowed values: spring_only \| spring_and_dashpot"]),
    ("tangential tdem/walton_braun has no slipReset", "model tdem/lsd tangential tdem/walton_braun "
     "parameters restitution slipReset spring_only", props(GOOD_T), None, [r"slipReset"]),
    ("tangential tdem/haff_werner negative tangentialDampingRatio",
     "model tdem/lsd tangential tdem/haff_werner parameters restitution",
     props(GOOD_T, tangentialDampingRatio="peratomtypepair 2 0.5 -0.5 -0.5 0.5"), None,
     [r"tangential tdem/haff_werner", r"tangentialDampingRatio", r"-0\.5", r"types 1 2", r">= 0"]),
    ("tangential tdem/linear_spring missing tangentialDampingRatio", LS,
     props(GOOD_T, tangentialDampingRatio=None), None, [r"tangentialDampingRatio"]),
    ("tangential tdem/di_renzo negative friction via wall", "model tdem/hertz tangential tdem/di_renzo",
     props(GOOD_T, coefficientFriction="peratomtypepair 2 -0.5 0.5 0.5 0.5"),
     "model tdem/hertz tangential tdem/di_renzo primitive type 1 zplane 0.0",
     [r"tangential tdem/di_renzo", r"coefficientFriction", r"-0\.5", r"types 1 1", r">= 0"]),
    ("tangential tdem/mindlin_deresiewicz missing youngsModulus", MD, props(GOOD_T, youngsModulus=None), None,
     [r"youngsModulus"]),
    ("tangential tdem/mindlin_deresiewicz poissonsRatio out of range", MD,
     props(GOOD_T, poissonsRatio="peratomtype 0.3 0.7"), None, [r"poissonsRatio|Poisson"]),
    ("tangential tdem/mindlin_no_slip not compiled with tdem/continuous_potential",
     "model tdem/continuous_potential tangential tdem/mindlin_no_slip", props(GOOD_T), None,
     [r"'model tdem/continuous_potential tangential tdem/mindlin_no_slip", r"not compiled", r"compiled tdem combinations"]),
    ("unknown tangential model lists the new laws", "model tdem/lsd tangential tdem/mindlin", props(GOOD_T), None,
     [r"keyword 'tangential'", r"'tdem/mindlin'", r"allowed: .*tdem/haff_werner.*tdem/mindlin_deresiewicz.*tdem/di_renzo"]),
]


def main():
    args = T.parse_args(lambda p: p.add_argument("--only", default=None, help="run the cases whose name contains this"))
    checks = T.Checks()
    d = T.workdir(args, "tdem_lig_bad_input")
    for i, (name, pair_args, properties, wall_args, patterns) in enumerate(CASES):
        if args.only and args.only not in name:
            continue
        r = T.run(args.tdem, scene(pair_args, properties, wall_args), d, "bad%d" % i, check=False, timeout=60)
        out = r.stdout + r.stderr
        err = [l for l in out.splitlines() if "ERROR" in l]
        line = err[0] if err else ""
        checks.check(r.returncode > 0, "%s: exit status %d (> 0, not a signal)" % (name, r.returncode))
        missing = [p for p in patterns if not re.search(p, line)]
        checks.check(bool(err) and not missing, "%s: message %r%s" % (
            name, line, (" lacks " + ", ".join(missing)) if missing else ""))
    checks.done()


if __name__ == "__main__":
    main()
