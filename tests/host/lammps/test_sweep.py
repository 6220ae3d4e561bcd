#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Generated bad-input sweep of the tdem LAMMPS styles (issue 17).

Every numeric argument of every law of pair tdem/gran (with fix tdem/wall/gran where the law has
a wall form), of fix tdem/timestep and of fix tdem/integrate is replaced in turn by a word, NaN,
+-inf, -1, 0 and 1e300; the value list of every law is cut short and given one number too many;
every keyword word option is given a wrong word and no value. Each case runs a two-sphere scene in
contact for 10 steps and must end in one of two ways:
  * an ERROR line naming the argument (or, for a cut or extended list, the law), exit status in
    1..127 (no signal), within the time limit; or
  * a documented acceptance (docs/limits.md): the value is allowed by the law (0 for a damping,
    friction or exponent, 1e300 for a dimensional constant, -1 where the range allows it). A
    huge dimensional constant may also end in LAMMPS's own ERROR (e.g. lost atoms): never a crash.
Counts: crashes, hangs and silent acceptances must all be 0."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import lmp_common as lc  # noqa: E402
import sweep_common as SC  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.sweep")

BASE = """units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block 0 0.1 0 0.1 0 0.1 units box
create_box 1 box
create_atoms 1 single 0.05 0.05 0.003 units box
create_atoms 1 single 0.05 0.05 0.0075 units box
set group all diameter 0.005
set group all density 2500
fix nve all nve/sphere
timestep 1e-7
{body}
run 10
"""

CLASSES, ALWAYS = SC.CLASSES, SC.ALWAYS

H = "2e8 0.3"  # hertz material
# (case name, template with {} for the swept slots, [(slot name in the message, class, good value)],
#  wall: the template is also a fix tdem/wall/gran law)
LAWS = [
    ("lsd stiffness", "normal lsd stiffness {} {} tangential cundall_strack {} {} {}",
     [("KN", "pos", "2000"), ("GAMMAN", "nonneg", "50"), ("KT", "pos", "600"), ("GAMMAT", "nonneg", "25"),
      ("MU", "nonneg", "0.5")]),
    ("lsd restitution", "normal lsd restitution {} {} tangential cundall_strack {} {}",
     [("E", "e", "0.6"), ("TC", "pos", "1e-4"), ("KAPPA", "pos", "0.8"), ("MU", "nonneg", "0.5")]),
    ("hertz", "normal hertz {} {} tangential cundall_strack 0.8 0.5", [("E", "pos", "2e8"), ("NU", "nu", "0.3")]),
    ("hertz two materials", "normal hertz 2e8 0.3 {} {} tangential cundall_strack 0.8 0.5",
     [("E2", "pos", "1e9"), ("NU2", "nu", "0.2")]),
    ("hertz linear", "normal hertz " + H + " damping linear {} tangential cundall_strack 0.8 0.5",
     [("GAMMA", "nonneg", "3")]),
    ("hertz kuwabara_kono", "normal hertz " + H + " damping kuwabara_kono {} tangential cundall_strack 0.8 0.5",
     [("GAMMA", "nonneg", "100")]),
    ("hertz tsuji", "normal hertz " + H + " damping tsuji {} tangential cundall_strack 0.8 0.5", [("E", "e", "0.7")]),
    ("hertz general", "normal hertz " + H + " damping general {} {} tangential cundall_strack 0.8 0.5",
     [("THETA", "nonneg", "0.5"), ("C", "nonneg", "100")]),
    ("walton_braun", "normal walton_braun {} {} {} tangential cundall_strack 0.8 0.5",
     [("KL", "pos", "1e5"), ("KUL", "pos", "2e5"), ("S", "nonneg", "0.1")]),
    ("thornton", "normal thornton {} {} {} tangential cundall_strack 0.8 0.5",
     [("E", "pos", "2e8"), ("NU", "nu", "0.3"), ("PY", "pos", "1e6")]),
    ("power_law", "normal power_law {} {} {} {} tangential cundall_strack 0.8 0.5",
     [("AL", "pos", "1e7"), ("P", "pos", "1.5"), ("AUL", "pos", "3e7"), ("Q", "nonneg", "0.2")]),
    ("extended_linear", "normal extended_linear e_fit constant {} tc_fit constant {} tangential cundall_strack 0.8 0.5",
     [("C0", "e", "0.7"), ("C0", "pos", "1e-4")]),
    ("extended_hertz", "normal extended_hertz " + H + " e_fit constant {} tangential cundall_strack 0.8 0.5",
     [("C0", "e", "0.6")]),
    ("haff_werner", "normal hertz " + H + " tangential haff_werner {} {}",
     [("GAMMAT", "nonneg", "20"), ("MU", "nonneg", "0.5")]),
    ("linear_spring", "normal hertz " + H + " tangential linear_spring {} {} {} {}",
     [("KT", "nonneg", "100"), ("KAPPA", "nonneg", "0.8"), ("GAMMAT", "nonneg", "0.1"), ("MU", "nonneg", "0.5")]),
    ("walton_braun tangential", "normal hertz " + H + " tangential walton_braun {} {} {}",
     [("KT", "nonneg", "100"), ("KAPPA", "nonneg", "0.5"), ("MU", "nonneg", "0.5")]),
    ("mindlin_deresiewicz", "normal hertz " + H + " tangential mindlin_deresiewicz {} {} {}",
     [("E", "pos", "2e8"), ("NU", "nu", "0.3"), ("MU", "nonneg", "0.5")]),
    ("mindlin_no_slip", "normal hertz " + H + " tangential mindlin_no_slip {} {} {} {}",
     [("E", "pos", "2e8"), ("NU", "nu", "0.3"), ("RATIO", "nonneg", "1"), ("MU", "nonneg", "0.5")]),
    ("di_renzo", "normal hertz " + H + " tangential di_renzo {} {} {}",
     [("E", "pos", "2e8"), ("NU", "nu", "0.3"), ("MU", "nonneg", "0.5")]),
    ("rolling", "normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.5 rolling sds {} {} {}",
     [("KR", "pos", "1000"), ("GAMMAR", "nonneg", "0"), ("MUR", "nonneg", "0.1")]),
]
# documented exceptions to the class table (docs/limits.md): the value is allowed by this law
ACCEPT = {
    ("linear_spring", "KT", "0"), ("linear_spring", "KAPPA", "0"),  # one of KT, KAPPA may be 0
    ("walton_braun tangential", "KT", "0"), ("walton_braun tangential", "KAPPA", "0"),
}
# laws whose last value is optional (walton_braun KL KUL [S], power_law AL P AUL [Q])
OPTIONAL_LAST = {"walton_braun", "power_law"}
# word options after a law: (template, keyword, bad value, allowed words in the message)
WORDS = [
    ("normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5 {}", "damping", "viscous", "mass"),
    ("normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.5 {}", "limit_force", "maybe", "yes"),
    ("normal hertz 2e8 0.3 tangential cundall_strack 0.8 0.5 {}", "slip", "sometimes", "spring"),
    ("normal hertz 2e8 0.3 tangential mindlin_deresiewicz 2e8 0.3 0.5 {}", "friction_limit", "never", "absolute"),
    ("normal hertz 2e8 0.3 damping {} tangential cundall_strack 0.8 0.5", None, "viscous", "linear"),
    ("normal extended_linear e_fit {} 0.7 tc_fit constant 1e-4 tangential cundall_strack 0.8 0.5", None, "cubic",
     "constant"),
]
FIXES = [
    # fix tdem/timestep options (with a good pair)
    ("timestep", "fix ts all tdem/timestep vmax {}", [("vmax", "pos", "1")]),
    ("timestep", "fix ts all tdem/timestep every {}", [("every", "int0", "10")]),
    ("timestep", "fix ts all tdem/timestep fraction {}", [("fraction", "frac", "0.5")]),
    ("wall zplane", "fix w all tdem/wall/gran normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5 "
                    "zplane {} 0.09", [("zplane lo", "any", "0")]),
    ("wall zcylinder", "fix w all tdem/wall/gran normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5 "
                       "zcylinder {}", [("zcylinder radius", "pos", "0.2")]),
    ("wall wiggle", "fix w all tdem/wall/gran normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5 "
                    "zplane 0 NULL wiggle z {} {}", [("amplitude", "any", "0.001"), ("period", "pos", "0.01")]),
]

PAIR_GOOD = "pair_style tdem/gran\npair_coeff * * normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5"

wd = lc.workdir("sweep")

CASES = []


def run_case(body, name, expect, words):
    CASES.append((body, name, expect, words))


def execute(k):
    body, name, expect, words = CASES[k]
    try:
        rc, out = lc.run(args["tdem"], BASE.format(body=body), wd, "in.sweep%03d" % k, check=False, timeout=60)
    except Exception as ex:  # subprocess.TimeoutExpired
        return [(False, "%s: no hang (%s)" % (name, type(ex).__name__))], "hang"
    return SC.verdict(name, rc, out, expect, words)


def mutations(cls):
    m = dict(ALWAYS)
    m.update(CLASSES[cls])
    return m


def sweep_template(case, template, slots, make_body, law_words):
    good = [g for _, _, g in slots]
    for k, (slot, cls, _) in enumerate(slots):
        for val, expect in mutations(cls).items():
            if (case, slot, val) in ACCEPT:
                expect = "accept"
            vals = list(good)
            vals[k] = val
            run_case(make_body(template.format(*vals)), "%s %s = %s" % (case, slot, val), expect, [slot] + law_words)
    # the value list cut short (the last value missing) and one number too many
    base = case.replace(" (wall)", "")
    cut = template.format(*(good[:-1] + [""]))
    optional = base in OPTIONAL_LAST
    run_case(make_body(cut), "%s: last value missing%s" % (case, " (optional: accepted)" if optional else ""),
             "accept" if optional else "error", law_words + ["needs", "expects", "values"])
    if optional:
        cut2 = template.format(*(good[:-2] + ["", ""]))
        run_case(make_body(cut2), "%s: last two values missing" % case, "error", law_words + ["needs", "values"])
    extra = template.format(*(good[:-1] + [good[-1] + " 7"]))
    run_case(make_body(extra), "%s: one value too many" % case, "error",
             law_words + ["needs", "expected", "unknown", "values", "third number", "keyword"])


def pair_body(law):
    return "pair_style tdem/gran\npair_coeff * * " + law


def wall_body(law):
    return PAIR_GOOD + "\nfix w all tdem/wall/gran " + law + " zplane 0 NULL"


for case, template, slots in LAWS:
    law_words = [case.split()[0]]
    sweep_template(case, template, slots, pair_body, law_words)
    if case in ("lsd stiffness", "hertz tsuji", "walton_braun", "rolling"):
        sweep_template(case + " (wall)", template, slots, wall_body, law_words)

for template, key, bad, allowed in WORDS:
    if key:
        run_case(pair_body(template.format(key + " " + bad)), "%s %s" % (key, bad), "error", [key, bad])
        run_case(pair_body(template.format(key)), "%s without a value" % key, "error", [key])
    else:
        run_case(pair_body(template.format(bad)), "word '%s'" % bad, "error", [bad, allowed])

for case, template, slots in FIXES:
    sweep_template(case, template, slots, lambda t: PAIR_GOOD + "\n" + t, [case.split()[0], "tdem/"])

SC.finish(SC.run_all(len(CASES), execute, chk), chk)
chk.done()
