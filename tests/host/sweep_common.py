# SPDX-License-Identifier: GPL-2.0-or-later
"""The verdict of one case of the generated bad-input sweeps (tests/host/lammps/test_sweep.py,
tests/host/liggghts/test_sweep.py) and the parallel runner shared by both."""
import concurrent.futures

# What each replacement value must give for an argument of a class: "error", "accept" (a
# documented acceptance, docs/limits.md) or "huge" (accepted, or a clean host error such as lost
# atoms). Words, NaN and +-inf are errors for every class (ALWAYS).
CLASSES = {
    "pos": {"-1": "error", "0": "error", "1e300": "huge"},      # > 0, dimensional
    "nonneg": {"-1": "error", "0": "accept", "1e300": "huge"},  # >= 0, dimensional
    "e": {"-1": "error", "0": "error", "1e300": "error"},       # restitution (0, 1]
    "nu": {"-1": "error", "0": "accept", "1e300": "error"},     # Poisson ratio (-1, 0.5]
    "int0": {"-1": "error", "0": "accept", "0.5": "error", "1e300": "error"},  # an integer >= 0 (every)
    "int1": {"-1": "error", "0": "error", "0.5": "error", "1e300": "error"},   # an integer >= 1, capped
    "frac": {"-1": "error", "0": "error", "1e300": "error"},    # a fraction (0, 1]
    "open01": {"-1": "error", "0": "error", "1e300": "error"},  # (0, 1)
    "half": {"-1": "error", "0": "error", "1e300": "error"},    # (0, 0.5]
    "unit0": {"-1": "error", "0": "accept", "1e300": "error"},  # [0, 1)
    "deg80": {"-1": "error", "0": "accept", "1e300": "error"},  # an angle [0, 80] degrees
    "bounded0": {"-1": "error", "0": "accept", "1e300": "error"},  # [0, a length of the scene)
    "halfbox": {"-1": "error", "0": "error", "1e300": "error"},   # (0, half the periodic box]
    "colbox": {"-1": "error", "0": "error", "1e300": "error"},    # (0, the periodic box]
    "lohi_lo": {"-1": "accept", "0": "accept", "1e300": "error"},  # LO of LO < HI
    "lohi_hi": {"-1": "error", "0": "error", "1e300": "accept"},   # HI of LO < HI (LO = 0)
    "any": {"-1": "accept", "0": "accept", "1e300": "huge"},    # a position
    "anyfinite": {"-1": "accept", "0": "accept", "1e300": "huge"},  # a time or height
}
ALWAYS = {"abc": "error", "nan": "error", "inf": "error", "-inf": "error"}


def verdict(name, rc, out, expect, words, host_words=()):
    """expect: 'error' (an ERROR line naming one of `words`), 'accept' (exit 0 after a run), 'huge'
    (either, cleanly), 'host' (an ERROR naming `words` or containing one of `host_words`: the host's
    own parser). Returns [(ok, message)] and the counter to raise ('crash', 'silent', 'unnamed' or
    None)."""
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    tail = out.strip().splitlines()[-2:] if out.strip() else ["(no output)"]
    first = err[0][:170] if err else "no ERROR line; the output ends: " + " | ".join(l[:120] for l in tail)
    if rc < 0 or rc >= 128 or ("Signal" in out and not err):
        return [(False, "%s: crashed (exit %d)" % (name, rc))], "crash"
    if expect == "accept" or (expect == "huge" and rc == 0):
        return [(rc == 0 and "Loop time" in out, "%s: accepted as documented (exit %d%s)"
                 % (name, rc, ", " + err[0][:150] if err else ""))], None
    if rc == 0:
        return [(False, "%s: silently accepted (exit 0), expected an ERROR" % name)], "silent"
    named = bool(err) and any(w.lower() in err[0].lower() for w in words)
    if expect == "host":
        named = named or (bool(err) and any(h in err[0] for h in host_words))
    named = named or expect == "huge"
    return [(bool(err) and named, "%s: exit %d, %s" % (name, rc, first))], (None if named else "unnamed")


def run_all(n, execute, chk):
    """Runs execute(k) for k < n two at a time (two cores) and reports in case order. Returns the
    counts of cases, crashes, hangs, silent acceptances and unnamed errors."""
    counts = {"cases": 0, "crash": 0, "hang": 0, "silent": 0, "unnamed": 0}
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for results, counter in pool.map(execute, range(n)):
            counts["cases"] += 1
            if counter:
                counts[counter] += 1
            for ok, msg in results:
                chk.check(ok, msg)
    return counts


def finish(counts, chk, what="the argument"):
    print("sweep: %d cases, %d crashes, %d hangs, %d silent acceptances, %d errors not naming %s"
          % (counts["cases"], counts["crash"], counts["hang"], counts["silent"], counts["unnamed"], what))
    chk.check(counts["cases"] >= 150, "at least 150 cases (%d)" % counts["cases"])
    chk.check(counts["crash"] == 0 and counts["hang"] == 0 and counts["silent"] == 0,
              "0 crashes, 0 hangs, 0 silent acceptances")
