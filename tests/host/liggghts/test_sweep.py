#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Generated bad-input sweep of the tdem LIGGGHTS models and fixes (issue 17).

Every per-type-pair (and per-type, scalar) property of every tdem normal law and setting, and of
the tdem tangential laws, is replaced in turn by a word, NaN, inf, -1, 0 and 1e300; every word
keyword of the models is given a wrong word; the options of fix tdem/timestep are swept like the
LAMMPS ones. Each case runs two touching spheres and a wall for 10 steps, with the output
unbuffered (stdbuf -o0 -e0) so that no message is lost, and must end in one of two ways:
  * an ERROR line naming the property or keyword, exit status 1..127 (no signal), in time. Words,
    NaN and inf in a fix property/global line are refused by LIGGGHTS's own number parser
    ("Expected floating point parameter"), which does not name the property: documented;
  * a documented acceptance (docs/limits.md): 0 for a damping, friction, slope or exponent
    increment; 1e300 for a dimensional constant (or a clean host error such as lost atoms).
Counts: crashes, hangs and silent acceptances must all be 0."""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import sweep_common as SC  # noqa: E402
import law_props as LP  # noqa: E402
import tdem_lig as T  # noqa: E402
import mpi_env  # noqa: E402

args = T.parse_args()
chk = T.Checks()
HOST_PARSER = "Expected floating point parameter"

CLASSES = SC.CLASSES

# property -> class (how the tdem models check it)
PROP_CLASS = {
    "kn": "pos", "kt": "nonneg", "gamman": "nonneg", "gammat": "nonneg", "gamman_abs": "nonneg",
    "gammat_abs": "nonneg", "coefficientRestitution": "e", "contactTime": "pos",
    "tangentialStiffnessRatio": "nonneg", "coefficientFriction": "nonneg", "tangentialDampingRatio": "nonneg",
    "dampingCoefficient": "nonneg", "dampingExponent": "nonneg", "loadingStiffness": "pos",
    "unloadingStiffness": "pos", "unloadingStiffnessSlope": "nonneg", "yieldPressure": "pos",
    "potentialEnergy": "pos", "potentialExponent": "pos", "loadingCoefficient": "pos", "loadingExponent": "pos",
    "unloadingCoefficient": "pos", "unloadingExponentIncrement": "nonneg", "restitutionFitC0": "e",
    "contactTimeFitC0": "pos", "characteristicVelocity": "pos",
    "rollingStiffness": "pos", "rollingDamping": "nonneg", "coefficientRollingFriction": "nonneg", "youngsModulus": "pos", "poissonsRatio": "nu",
}
CS = "tangential tdem/cundall_strack"
# (case, models, settings, the properties the law reads)
LAWS = [
    ("lsd stiffness", "model tdem/lsd " + CS, "parameters stiffness",
     ["kn", "kt", "gamman", "gammat", "coefficientFriction"]),
    ("lsd absolute", "model tdem/lsd " + CS, "parameters stiffness absolute_damping on", ["gamman_abs", "gammat_abs"]),
    ("lsd restitution", "model tdem/lsd " + CS, "parameters restitution",
     ["coefficientRestitution", "contactTime", "tangentialStiffnessRatio"]),
    ("lsd material", "model tdem/lsd " + CS, "parameters material",
     ["youngsModulus", "poissonsRatio", "characteristicVelocity", "coefficientRestitution"]),
    ("hertz tsuji", "model tdem/hertz " + CS, "damping tsuji", ["youngsModulus", "coefficientRestitution"]),
    ("hertz linear", "model tdem/hertz " + CS, "damping linear", ["dampingCoefficient"]),
    ("hertz general", "model tdem/hertz " + CS, "damping general", ["dampingCoefficient", "dampingExponent"]),
    ("walton_braun", "model tdem/walton_braun " + CS, "",
     ["loadingStiffness", "unloadingStiffness", "unloadingStiffnessSlope", "tangentialStiffnessRatio"]),
    ("thornton", "model tdem/thornton " + CS, "", ["yieldPressure", "youngsModulus"]),
    ("power_law", "model tdem/power_law " + CS, "",
     ["loadingCoefficient", "loadingExponent", "unloadingCoefficient", "unloadingExponentIncrement"]),
    ("continuous_potential", "model tdem/continuous_potential " + CS, "limitForce off",
     ["potentialEnergy", "potentialExponent", "dampingCoefficient"]),
    ("extended_linear", "model tdem/extended_linear " + CS, "restitutionFit constant contactTimeFit constant",
     ["restitutionFitC0", "contactTimeFitC0"]),
    ("extended_hertz", "model tdem/extended_hertz " + CS, "restitutionFit constant", ["restitutionFitC0"]),
    ("haff_werner", "model tdem/hertz tangential tdem/haff_werner", "damping tsuji",
     ["tangentialDampingRatio", "coefficientFriction"]),
    ("mindlin_deresiewicz", "model tdem/hertz tangential tdem/mindlin_deresiewicz", "damping tsuji",
     ["coefficientFriction", "poissonsRatio"]),
    ("rolling tdem/sds", "model tdem/lsd " + CS + " rolling_friction tdem/sds", "parameters restitution",
     ["rollingStiffness", "rollingDamping", "coefficientRollingFriction"]),
]
# documented exceptions: (case, property, value) -> expectation
EXCEPT = {
    # lsd material: LIGGGHTS forms Yeff from youngsModulus/poissonsRatio with its own checks
    ("mindlin_deresiewicz", "poissonsRatio", "-1"): "error",
}
WORDS = [  # (models, settings with a wrong word, keyword, wrong word)
    ("model tdem/lsd " + CS, "parameters elastic", "parameters", "elastic"),
    ("model tdem/lsd " + CS, "parameters restitution limitForce maybe", "limitForce", "maybe"),
    ("model tdem/lsd " + CS, "parameters restitution tangential_damping yes", "tangential_damping", "yes"),
    ("model tdem/lsd " + CS, "parameters stiffness absolute_damping 1", "absolute_damping", "1"),
    ("model tdem/hertz " + CS, "damping viscous", "damping", "viscous"),
    ("model tdem/extended_linear " + CS, "restitutionFit cubic", "restitutionFit", "cubic"),
    ("model tdem/extended_linear " + CS, "restitutionFit constant contactTimeFit rational", "contactTimeFit",
     "rational"),
    ("model tdem/lsd " + CS, "parameters restitution slip_rule never", "slip_rule", "never"),
    ("model tdem/hertz tangential tdem/linear_spring", "damping tsuji slipReset both", "slipReset", "both"),
    ("model tdem/hertz tangential tdem/mindlin_deresiewicz", "damping tsuji frictionLimit none", "frictionLimit",
     "none"),
]
FIXES = [  # fix tdem/timestep options: (keyword, class, good)
    ("vmax", "pos", "1"), ("every", "int0", "10"), ("fraction", "frac", "0.5"),
]


def properties(over=None):
    return LP.lines(1, over=over)


def scene(models, settings, over=None, extra=""):
    return """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.05 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
%s
pair_style gran %s %s
pair_coeff * *
timestep 1e-7
create_atoms 1 single 0 0 0.0026 units box
create_atoms 1 single 0 0 0.0075 units box
set group all diameter 0.005 density 2500
fix w all wall/gran %s primitive type 1 zplane 0.0 %s
fix integr all nve/sphere
%s
run 10
""" % (properties(over), models, settings, models, settings, extra)


CASES = []


def case(name, text, expect, words):
    CASES.append((name, text, expect, words))


for cname, models, settings, props in LAWS:
    for prop in props:
        cls = PROP_CLASS[prop]
        muts = {"abc": "host", "nan": "host", "inf": "host"}
        muts.update(CLASSES[cls])
        for val, expect in muts.items():
            expect = EXCEPT.get((cname, prop, val), expect)
            case("%s %s = %s" % (cname, prop, val), scene(models, settings, {prop: val}), expect, [prop])
for models, settings, key, bad in WORDS:
    case("%s %s %s" % (models.split()[1], key, bad), scene(models, settings), "error", [key, bad])
for key, cls, good in FIXES:
    muts = dict(SC.ALWAYS)
    muts.update(CLASSES[cls])
    for val, expect in muts.items():
        case("fix tdem/timestep %s %s" % (key, val),
             scene("model tdem/lsd " + CS, "parameters restitution", extra="fix ts all tdem/timestep %s %s" % (key, val)),
             expect, [key])
    case("fix tdem/timestep %s without a value" % key,
         scene("model tdem/lsd " + CS, "parameters restitution", extra="fix ts all tdem/timestep %s" % key), "error",
         [key])
for key, bad in (("check", "maybe"), ("scheme", "rk4")):
    case("fix tdem/timestep %s %s" % (key, bad),
         scene("model tdem/lsd " + CS, "parameters restitution", extra="fix ts all tdem/timestep %s %s" % (key, bad)),
         "error", [key, bad])

wd = T.workdir(args, "sweep")


def execute(k):
    name, text, expect, words = CASES[k]
    inp = os.path.join(wd, "in.sweep%03d" % k)
    with open(inp, "w") as f:
        f.write(text)
    cmd = ["stdbuf", "-o0", "-e0", args.tdem, "-in", inp, "-log", os.path.join(wd, "log.sweep%03d" % k),
           "-echo", "none"]
    try:
        r = mpi_env.run(cmd, cwd=wd, capture_output=True, text=True, errors="replace", timeout=60)
    except subprocess.TimeoutExpired:
        return [(False, "%s: no hang (timeout)" % name)], "hang"
    return SC.verdict(name, r.returncode, r.stdout + r.stderr, expect, words, (HOST_PARSER,))


SC.finish(SC.run_all(len(CASES), execute, chk), chk, "the property or keyword")
chk.done()
