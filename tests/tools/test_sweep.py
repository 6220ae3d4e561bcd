#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Generated bad-input sweep of the two tools (issue 17): tdem-collide and tdem-fit.

Every numeric option of every law, body, oblique and integration form of tdem-collide, every
numeric option of tdem-fit and every value of its data file (header keys and columns) is replaced in
turn by a word, NaN, +-inf, -1, 0, 1e300 and, for integers, 0.5; every option is given without its
value at the end of the line; every word option is given a wrong word; an unknown option is added.
Each case must end in one of two ways:
  * exit status 2 with a line '<tool>: error: ...' naming the option (or the data key or column);
  * a documented acceptance (docs/limits.md, docs/tools/tdem-collide.md, docs/tools/tdem-fit.md): exit 0 with its JSON, or
    for tdem-collide exit 1 with "ended": false (the contact did not end).
Never a signal, never more than 30 s. Counts: crashes, hangs and silent acceptances must be 0."""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "host"))
import sweep_common as SC  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--collide", required=True)
ap.add_argument("--fit", required=True)
ap.add_argument("--tmp", default=".")
args = ap.parse_args()
os.makedirs(args.tmp, exist_ok=True)

CLASSES = dict(SC.CLASSES)
CLASSES.update({
    "deg90": {"-1": "error", "0": "accept", "1e300": "error"},      # impact angle [0, 90)
    "beta": {"-1": "accept", "0": "accept", "1e300": "error"},      # beta0 [-1, 1]
    "steps": {"-1": "error", "0": "error", "0.5": "error", "1e300": "error"},  # integer in a range
})

# tdem-collide: (case, command line with {} slots, [(option, class, good)])
B = "--m1 0.01 --v0 1 --wall"
HERTZ = "--law hertz --E 1e9 --nu 0.3 --R1 0.01 --rho 2500 --v0 1 --wall"
OBL = "--law lsd --k 1e5 --m1 0.01 --R1 0.005 --v0 1 --wall --angle 30"
COLLIDE = [
    ("lsd k", "--law lsd --k {} --gamma {} --m1 {} --v0 {} --wall",
     [("--k", "pos", "1e5"), ("--gamma", "nonneg", "1"), ("--m1", "pos", "0.01"), ("--v0", "pos", "1")]),
    ("lsd e tc", "--law lsd --e {} --tc {} " + B, [("--e", "e", "0.7"), ("--tc", "pos", "1e-4")]),
    ("lsd pair", "--law lsd --k 1e5 --m1 {} --m2 {} --v0 1", [("--m1", "pos", "0.01"), ("--m2", "pos", "0.02")]),
    ("lsd density", "--law lsd --k 1e5 --rho {} --R1 {} --rho2 {} --R2 {} --v0 1",
     [("--rho", "pos", "2500"), ("--R1", "pos", "0.005"), ("--rho2", "pos", "7800"), ("--R2", "pos", "0.004")]),
    ("lsd dt", "--law lsd --k 1e5 " + B + " --dt {}", [("--dt", "pos", "1e-6")]),
    ("lsd steps", "--law lsd --k 1e5 " + B + " --steps {}", [("--steps", "steps", "100")]),
    ("hertz material", "--law hertz --E {} --nu {} --E2 {} --nu2 {} --R1 {} --rho 2500 --v0 1 --wall "
     "--damping tsuji --e {}",
     [("--E", "pos", "1e9"), ("--nu", "nu", "0.3"), ("--E2", "pos", "2e9"), ("--nu2", "nu", "0.2"),
      ("--R1", "pos", "0.01"), ("--e", "e", "0.8")]),
    ("hertz k", "--law hertz --k {} " + B, [("--k", "pos", "1e8")]),
    ("hertz Estar", "--law hertz --Estar {} --R1 0.01 " + B, [("--Estar", "pos", "1e9")]),
    ("hertz tc", "--law hertz --tc {} --R1 0.01 " + B, [("--tc", "pos", "1e-4")]),
    ("hertz linear", HERTZ + " --damping linear --gamma {}", [("--gamma", "nonneg", "1")]),
    ("hertz kuwabara_kono", HERTZ + " --damping kuwabara_kono --A {}", [("--A", "nonneg", "1e-6")]),
    ("hertz tsuji alpha", HERTZ + " --damping tsuji --alpha {}", [("--alpha", "nonneg", "0.2")]),
    ("hertz general", HERTZ + " --damping general --gamma {} --theta {}",
     [("--gamma", "nonneg", "10"), ("--theta", "nonneg", "0.5")]),
    ("hertz linear e", HERTZ + " --damping linear --e {}", [("--e", "e_lt1", "0.8")]),
    ("walton_braun", "--law walton_braun --kl {} --kul {} --s {} " + B,
     [("--kl", "pos", "1e5"), ("--kul", "pos", "2e5"), ("--s", "nonneg", "10")]),
    ("walton_braun e", "--law walton_braun --e {} --kl {} " + B, [("--e", "e", "0.7"), ("--kl", "pos", "1e5")]),
    ("thornton", "--law thornton --Estar {} --R1 {} --py {} --m1 0.01 --v0 1 --wall",
     [("--Estar", "pos", "1e9"), ("--R1", "pos", "0.01"), ("--py", "pos", "1e7")]),
    ("thornton vy", "--law thornton --Estar 1e9 --R1 0.01 --vy {} " + B, [("--vy", "pos", "0.1")]),
    ("thornton e", "--law thornton --Estar 1e9 --R1 0.01 --e {} " + B, [("--e", "e_lt1", "0.7")]),
    ("continuous_potential", "--law continuous_potential --eps {} --n {} --d {} --gamma {} " + B,
     [("--eps", "pos", "1e-3"), ("--n", "pos", "36"), ("--d", "pos", "0.01"), ("--gamma", "nonneg", "0")]),
    ("continuous_potential x", "--law continuous_potential --x-min {} --x-cut {} --R1 0.005 " + B,
     [("--x-min", "pos", "0.0049"), ("--x-cut", "pos", "0.006")]),
    ("power_law", "--law power_law --al {} --p {} --aul {} --q {} " + B,
     [("--al", "pos", "1e8"), ("--p", "pos", "1.5"), ("--aul", "pos", "1e9"), ("--q", "nonneg", "0.2")]),
    ("extended_linear", "--law extended_linear --e-fit constant --e-coef {} --tc-fit constant --tc-coef {} "
     "--v-min {} --v-max {} --e-min {} " + B,
     [("--e-coef", "e", "0.7"), ("--tc-coef", "pos", "1e-4"), ("--v-min", "pos", "1e-3"), ("--v-max", "pos", "1e3"),
      ("--e-min", "e", "1e-3")]),
    ("extended_hertz", HERTZ.replace("--law hertz", "--law extended_hertz") + " --e-fit power --e-coef 0.1,{}",
     [("--e-coef", "nonneg", "0.1")]),
    ("oblique", OBL + " --spin {} --tangential cundall_strack --mu {} --kt {} --gammat {}",
     [("--spin", "any", "10"), ("--mu", "nonneg", "0.5"), ("--kt", "pos", "3e4"), ("--gammat", "nonneg", "0.1")]),
    ("oblique angle", OBL.replace("--angle 30", "--angle {}") + " --tangential cundall_strack --mu 0.5 --kappa {}",
     [("--angle", "deg90", "30"), ("--kappa", "pos", "0.8")]),
    ("oblique mindlin", OBL + " --tangential mindlin_no_slip --mu 0.5 --gstar {} --eta-ratio {}",
     [("--gstar", "pos", "1e9"), ("--eta-ratio", "nonneg", "1")]),
    ("oblique beta", OBL + " --tangential cundall_strack --mu 0.5 --kt 3e4 --beta0 {} --psi-kappa {}",
     [("--beta0", "beta", "0.5"), ("--psi-kappa", "pos", "0.8")]),
    ("scheme", "--law lsd --k 1e5 --m1 0.01 --R1 0.005 --v0 1 --wall --scheme velocity_verlet --steps {} "
     "--gap {} --phases {}", [("--steps", "steps", "100"), ("--gap", "nonneg", "0"), ("--phases", "steps", "4")]),
]
# documented acceptances beyond the class table: (case, option, value) -> expectation
EXCEPT = {
    ("hertz material", "--E2", "inf"): "accept",  # a rigid wall (docs/tools/tdem-collide.md)
    ("continuous_potential x", "--x-cut", "inf"): "accept",  # no cut-off (the default)
    ("lsd steps", "--steps", "1e300"): "error",
}
CLASSES["e_lt1"] = {"-1": "error", "0": "error", "1e300": "error"}  # a restitution < 1 (root search)
COLLIDE_WORDS = [  # (case, line with {} for the option, option, a good word)
    ("law", "{} --k 1e5 " + B, "--law", "lsd"),
    ("damping", HERTZ + " {}", "--damping", "none"),
    ("end", "--law lsd --k 1e5 " + B + " {}", "--end", "zero_force"),
    ("tangential", OBL.replace("--law lsd", "--law lsd") + " {} --mu 0.5 --kt 3e4", "--tangential", "cundall_strack"),
    ("friction-limit", OBL + " --tangential cundall_strack --mu 0.5 --kt 3e4 {}", "--friction-limit", "absolute"),
    ("slip-reset", OBL + " --tangential linear_spring --mu 0.5 --kt 3e4 {}", "--slip-reset", "spring_only"),
    ("lever-arm", OBL + " --tangential cundall_strack --mu 0.5 --kt 3e4 {}", "--lever-arm", "contact_point"),
    ("scheme", "--law lsd --k 1e5 --m1 0.01 --R1 0.005 --v0 1 --wall {}", "--scheme", "gear5"),
    ("e-fit", "--law extended_linear {} --e-coef 0.7 --tc-fit constant --tc-coef 1e-4 " + B, "--e-fit", "constant"),
    ("tc-fit", "--law extended_linear --e-fit constant --e-coef 0.7 {} --tc-coef 1e-4 " + B, "--tc-fit", "constant"),
    ("curve", "--law lsd --k 1e5 " + B + " {}", "--curve", "curve.csv"),
]

# tdem-fit: a data file with {} slots and the options
DATA = """# material: sweep
# configuration: {}
# R1: {}
# rho: {}
# E: {}
# nu: {}
# E2: {}
# nu2: {}
v0,e,e_err,tc
{},{},{},{}
1.0,0.80,0.01,9.0e-5
2.0,0.78,0.01,8.0e-5
4.0,0.75,0.01,7.0e-5
"""
DATA_SLOTS = [("configuration", "word", "wall"), ("R1", "pos", "0.005"), ("rho", "pos", "2500"), ("E", "pos", "1e9"),
              ("nu", "nu", "0.3"), ("E2", "pos", "2e9"), ("nu2", "nu", "0.3"), ("v0", "pos", "0.5"), ("e", "e", "0.82"),
              ("e_err", "pos", "0.01"), ("tc", "pos", "1e-4")]
FIT_EXCEPT = {
    ("data", "E2", "inf"): "accept",  # a rigid wall
    ("data", "e_err", "0"): "error",
}
FIT_OPTIONS = [  # (option, class, good)
    ("--steps", "steps", "200"), ("--w-e", "nonneg", "1"), ("--w-tc", "nonneg", "1"), ("--w-fmax", "nonneg", "1"),
    ("--curve", "int0", "5"), ("--kappa", "pos", "0.8"), ("--mu", "nonneg", "0.5"),
]
FIT_WORDS = [("--law", "lsd"), ("--end", "zero_overlap"), ("--weights", "relative"), ("--table", "off"),
             ("--json", "out.json")]

CASES = []  # (tool, argv list, stdin data or None, name, expect, words)


def mutations(cls):
    m = dict(SC.ALWAYS)
    if cls != "word":
        m.update(CLASSES[cls])
    return m


def fill(template, vals):
    return template.format(*vals)


for case, line, slots in COLLIDE:
    good = [g for _, _, g in slots]
    for k, (opt, cls, _) in enumerate(slots):
        for val, expect in mutations(cls).items():
            vals = list(good)
            vals[k] = val
            CASES.append(("collide", fill(line, vals).split(), None, "collide %s: %s %s" % (case, opt, val),
                          EXCEPT.get((case, opt, val), expect), [opt]))
    # the option without its value, at the end of the line
    for k, (opt, _, _) in enumerate(slots):
        words = fill(line, good).split()
        i = words.index(opt) if opt in words else -1
        if i >= 0:
            rest = words[:i] + words[i + 2:] + [opt]
            CASES.append(("collide", rest, None, "collide %s: %s without a value" % (case, opt), "error", [opt]))
    CASES.append(("collide", fill(line, good).split() + ["--colour", "red"], None,
                  "collide %s: unknown option --colour" % case, "error", ["--colour"]))
for case, line, opt, good in COLLIDE_WORDS:
    bad = "/nonexistent/dir/curve.csv" if opt == "--curve" else "sideways"
    CASES.append(("collide", line.format(opt + " " + bad).split(), None, "collide %s %s" % (opt, bad),
                  "error" if opt != "--curve" else "error1", [opt, bad]))
    CASES.append(("collide", (line.format("") + " " + opt).split(), None, "collide %s without a value" % opt,
                  "error", [opt]))
    CASES.append(("collide", line.format(opt + " " + good).split(), None, "collide %s %s (good)" % (opt, good),
                  "accept", [opt]))

dgood = [g for _, _, g in DATA_SLOTS]
for k, (key, cls, _) in enumerate(DATA_SLOTS):
    muts = mutations(cls) if cls != "word" else {"sideways": "error", "": "error"}
    for val, expect in muts.items():
        vals = list(dgood)
        vals[k] = val
        law = "hertz_tsuji" if key in ("E", "nu", "E2", "nu2", "R1") else "lsd"
        CASES.append(("fit", ["-", "--law", law, "--quiet"], DATA.format(*vals), "fit data: %s = %s" % (key, val),
                      FIT_EXCEPT.get(("data", key, val), expect), [key]))
for opt, cls, good in FIT_OPTIONS:
    for val, expect in mutations(cls).items():
        CASES.append(("fit", ["-", "--law", "lsd", "--quiet", opt, val], DATA.format(*dgood),
                      "fit %s %s" % (opt, val), expect, [opt]))
    CASES.append(("fit", ["-", "--law", "lsd", "--quiet", opt], DATA.format(*dgood), "fit %s without a value" % opt,
                  "error", [opt]))
for opt, good in FIT_WORDS:
    bad = "/nonexistent/dir/out.json" if opt == "--json" else "sideways"
    CASES.append(("fit", ["-", "--quiet", opt, bad] + ([] if opt == "--law" else ["--law", "lsd"]),
                  DATA.format(*dgood), "fit %s %s" % (opt, bad), "error1" if opt == "--json" else "error", [opt, bad]))
    CASES.append(("fit", ["-", "--quiet", "--law", "lsd", opt], DATA.format(*dgood), "fit %s without a value" % opt,
                  "error", [opt]))
    CASES.append(("fit", ["-", "--quiet", opt, good] + ([] if opt == "--law" else ["--law", "lsd"]),
                  DATA.format(*dgood), "fit %s %s (good)" % (opt, good), "accept", [opt]))
CASES.append(("fit", ["-", "--quiet", "--law", "lsd", "--colour", "red"], DATA.format(*dgood),
              "fit unknown option --colour", "error", ["--colour"]))
CASES.append(("fit", ["-", "--quiet", "--law", "lsd"], DATA.format(*dgood).replace("# E2:", "# E_2:"),
              "fit data: misspelt key E_2", "warn", ["'E_2'", "'E2'"]))
CASES.append(("fit", ["-", "--quiet", "--law", "lsd"], DATA.format(*dgood).replace("# rho:", "# rho: 2500\n# rh0:"),
              "fit data: misspelt key rh0", "warn", ["'rh0'", "'rho'"]))
CASES.append(("fit", ["-", "--quiet", "--law", "lsd"], DATA.format(*dgood).replace("v0,e,e_err,tc", "v0,e,colour,tc"),
              "fit data: unknown column", "error", ["colour"]))
CASES.append(("fit", ["-", "--quiet", "--law", "lsd"], DATA.format(*dgood).replace("# rho:", "# density:"),
              "fit data: rho under another name", "error", ["rho"]))


def verdict(name, tool, rc, stdout, out, expect, words):
    if expect == "warn":  # a run with a warning line naming the words
        warn = [l for l in out.splitlines() if ": warning:" in l]
        ok = rc == 0 and bool(warn) and all(w in warn[0] for w in words)
        return (ok, "%s: exit %d, %s" % (name, rc, warn[0][:170] if warn else "no warning")), None
    """The tools' contract: exit 2 and '<tool>: error: ...' naming the option for bad input; exit 1
    for an output file that cannot be written ('error1') or a contact that did not end."""
    errs = [l for l in out.splitlines() if ": error:" in l]
    first = errs[0][:170] if errs else "no error line"
    if rc < 0 or rc >= 128:
        return (False, "%s: crashed (exit %d)" % (name, rc)), "crash"
    ended_false = False
    if tool == "collide" and rc == 1:
        try:
            ended_false = json.loads(stdout).get("ended") is False
        except ValueError:
            ended_false = False
    if expect == "accept" or (expect == "huge" and (rc == 0 or ended_false)):
        return (rc == 0 or ended_false, "%s: accepted as documented (exit %d%s)"
                % (name, rc, ", " + first if errs else "")), None
    if rc == 0:
        return (False, "%s: silently accepted (exit 0), expected an error" % name), "silent"
    want_rc = 1 if expect == "error1" else 2
    named = bool(errs) and any(w.lower() in errs[0].lower() for w in words)
    named = named or (expect == "huge" and bool(errs))
    ok = named and (rc == want_rc or expect == "huge")
    return (ok, "%s: exit %d, %s" % (name, rc, first)), (None if named else "unnamed")


def execute(k):
    tool, argv, stdin, name, expect, words = CASES[k]
    exe = args.collide if tool == "collide" else args.fit
    d = os.path.join(args.tmp, "sweep")
    os.makedirs(d, exist_ok=True)
    try:
        r = subprocess.run([exe] + argv, input=stdin, capture_output=True, text=True, errors="replace", timeout=30,
                           cwd=d)
    except subprocess.TimeoutExpired:
        return (False, "%s: no hang (timeout)" % name), "hang"
    return verdict(name, tool, r.returncode, r.stdout, r.stdout + r.stderr, expect, words)


counts = {"cases": 0, "crash": 0, "hang": 0, "silent": 0, "unnamed": 0}
failed = 0
with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
    for (ok, msg), counter in pool.map(execute, range(len(CASES))):
        counts["cases"] += 1
        if counter:
            counts[counter] += 1
        print(("PASS " if ok else "FAIL ") + msg, flush=True)
        failed += not ok
ncol = sum(1 for c in CASES if c[0] == "collide")
print("sweep: %d cases (tdem-collide %d, tdem-fit %d), %d crashes, %d hangs, %d silent acceptances, %d errors not "
      "naming the option" % (counts["cases"], ncol, counts["cases"] - ncol, counts["crash"], counts["hang"],
                             counts["silent"], counts["unnamed"]))
ok = counts["crash"] == counts["hang"] == counts["silent"] == 0 and ncol >= 150 and counts["cases"] - ncol >= 100
print(("PASS " if ok else "FAIL ") + "0 crashes, 0 hangs, 0 silent acceptances; at least 150 + 100 cases")
failed += not ok
print("%d check(s) failed" % failed if failed else "all checks passed")
sys.exit(1 if failed else 0)
