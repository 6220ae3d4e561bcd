# SPDX-License-Identifier: GPL-2.0-or-later
"""The generated bad-input cases of tdem's fixes and computes (issue 17), shared by the two engines'
sweeps (tests/host/lammps/test_sweep_fixes.py, tests/host/liggghts/test_sweep_fixes.py).

A style is written as one command line with a '{}' for every numeric value, and the list of those
values: (name used in the messages, class of sweep_common.CLASSES, a good value). From it come:
  * every value replaced in turn by the mutations of its class (a word, NaN, +-inf, -1, 0, 1e300 and,
    for integers, 0.5), each expected to give an ERROR naming the keyword, or a documented acceptance;
  * the line cut off where each value should stand (the keyword is the last word): an ERROR naming it;
  * every word option given a wrong word, and an unknown keyword at the end: an ERROR naming them.
The engine part supplies the scene around the line (atoms, law, what invokes a compute)."""
import sweep_common as SC

# documented acceptances beyond the class table (docs/limits.md): (case, slot, value) -> expect
EXCEPT = {}


def mutations(cls):
    m = dict(SC.ALWAYS)
    m.update(SC.CLASSES[cls])
    return m


def value_cases(case, template, slots, words=(), except_=None):
    """(line, case name, expectation, words the ERROR must contain one of) for every mutation of
    every slot and for the line cut off before each slot."""
    except_ = EXCEPT if except_ is None else except_
    good = [g for _, _, g in slots]
    parts = template.split("{}")
    assert len(parts) == len(slots) + 1, (case, template)
    out = []
    for k, (slot, cls, _) in enumerate(slots):
        for val, expect in mutations(cls).items():
            expect = except_.get((case, slot, val), expect)
            vals = list(good)
            vals[k] = val
            out.append((template.format(*vals), "%s: %s = %s" % (case, slot, val), expect, [slot] + list(words)))
    for k, (slot, _, _) in enumerate(slots):
        head = "".join(p + g for p, g in zip(parts[:k], good[:k])) + parts[k]
        out.append((head.rstrip(), "%s: the line ends before value %d of %s" % (case, k + 1, slot), "error",
                    [slot] + list(words)))
    return out


def word_cases(case, template, good, key, allowed, bad="sideways"):
    """`template` has one '{}' where the word option `key VALUE` goes: a wrong word, and the keyword
    without a value (at the end of the line, or before the next keyword)."""
    return [(template.format(key + " " + bad), "%s: %s %s" % (case, key, bad), "error", [key, bad]),
            (template.format(key).rstrip(), "%s: %s without a value" % (case, key), "error", [key]),
            (template.format(key + " " + good), "%s: %s %s (good)" % (case, key, good), "accept", [key])]


def unknown_keyword(case, line):
    return [(line + " colour red", "%s: unknown keyword 'colour'" % case, "error", ["colour"])]


# ----------------------------------------------------------------------------- the styles
def clump_cases():
    """fix tdem/clump (same syntax in both engines): the scene creates no atoms, the fix inserts
    two tetra clumps into region 'ins'; type 1 exists."""
    base = "fix c all tdem/clump template t shape tetra {} {} density {} insert {} region ins seed {} type {} vel {} {} {}"
    slots = [("shape", "pos", "0.002"), ("shape", "pos", "0.003"), ("density", "pos", "2500"),
             ("insert", "int1", "2"), ("seed", "int1", "3"), ("type", "int1", "1"), ("vel", "any", "0"),
             ("vel", "any", "0"), ("vel", "any", "-0.1")]
    out = value_cases("clump", base, slots)
    good = base.format(*[g for _, _, g in slots])
    out += value_cases("clump rod", "fix c all tdem/clump template t shape rod 0.002 0.003 {} density 2500 insert 2 "
                       "region ins seed 3", [("shape", "int1", "3")])
    out += value_cases("clump resolution", good + " resolution {}", [("resolution", "int1", "16")])
    for key, ok in (("integration", "voxel"), ("rotation", "richardson"), ("correction", "none"),
                    ("shape", None)):
        if ok:
            out += word_cases("clump", good + " {}", ok, key, "")
    out.append((good.replace("shape tetra", "shape blob"), "clump: shape blob", "error", ["shape", "blob"]))
    out.append((good.replace("shape tetra 0.002 0.003", "file nothere.txt"), "clump: file nothere.txt", "error",
                ["nothere.txt"]))
    out.append((good.replace("region ins", "region nowhere"), "clump: region nowhere", "error", ["nowhere"]))
    out.append((good + " bodies atoms", "clump: bodies atoms", "error", ["bodies", "atoms"]))
    out += unknown_keyword("clump", good)
    return out


def grate_cases(head, extra_slots=(), except_=None):
    """fix tdem/grate: `head` is the start of the line up to the grate keywords (the LAMMPS form
    names a contact law); extra_slots: [(keyword, class, good)] of the host's own keywords; except_:
    the host's documented exceptions to the class table."""
    geo = ("rows {} bar_length {} bar_height {} bar_thickness {} bar_gap {} step_height {} overlap {} "
           "declination {} width {} origin {} {} {}")
    geo_slots = [("rows", "int1", "3"), ("bar_length", "pos", "0.1"), ("bar_height", "pos", "0.02"),
                 ("bar_thickness", "nonneg", "0.05"), ("bar_gap", "nonneg", "0"), ("step_height", "nonneg", "0.01"),
                 ("overlap", "bounded0", "0.01"), ("declination", "deg80", "12"), ("width", "pos", "0.1"),
                 ("origin", "any", "0"), ("origin", "any", "0"), ("origin", "any", "0")]
    out = value_cases("grate", head + geo, geo_slots, except_=except_)
    g = head + geo.format(*[s[2] for s in geo_slots])
    g0 = head + "rows 3 bar_length 0.1 bar_height 0.02 width 0.1"
    out += value_cases("grate side walls", g0 + " side_walls yes wall_height {} wall_thickness {}",
                       [("wall_height", "pos", "0.1"), ("wall_thickness", "pos", "0.01")])
    mo = ("row_group -1 {} -1 group_phase {} profile trapezoidal stroke {} period {} t_start {} dwell_out {} "
          "dwell_home {} forward_share {} ramp {}")
    mo_slots = [("row_group", "int0", "0"), ("group_phase", "unit0", "0.25"), ("stroke", "nonneg", "0.01"),
                ("period", "pos", "0.5"), ("t_start", "anyfinite", "0"), ("dwell_out", "unit0", "0.1"),
                ("dwell_home", "unit0", "0.1"), ("forward_share", "open01", "0.5"), ("ramp", "half", "0.25")]
    out += value_cases("grate motion", g0 + " " + mo, mo_slots)
    out += value_cases("grate frequency", g0 + " stroke 0.01 frequency {}", [("frequency", "pos", "2")])
    out += value_cases("grate vtk", g0 + " vtk {} bars", [("vtk", "int1", "5")])
    for key, cls, good in extra_slots:
        out += value_cases("grate " + key, g0 + " " + key + " {}", [(key, cls, good)])
    for key, good in (("side_walls", "no"), ("type", "reverse"), ("profile", "sinusoidal"), ("frame", "xyz")):
        out += word_cases("grate", g0 + " {}", good, key, "")
    out.append((g0 + " frame xy", "grate: frame xy in 3D", "error", ["frame", "dimension 2"]))
    out.append((g0 + " row_group -1 0", "grate: row_group with 2 of 3 rows", "error", ["row_group"]))
    out.append((g0 + " row_group -1 0 -1 group_phase 0.1 0.2", "grate: 2 phases for 1 group", "error",
                ["group_phase", "phase"]))
    out.append((g0 + " stroke 0.01 dwell_out 0.6 dwell_home 0.5", "grate: dwell_out + dwell_home = 1.1", "error",
                ["dwell_out + dwell_home"]))
    out.append((g0.replace("rows 3", "rows 1001"), "grate: rows 1001", "error", ["rows", "1001"]))
    out += unknown_keyword("grate", g)
    return out


def mixing_cases(grate_line):
    """compute tdem/mixing/velocity and fix tdem/mixing/depth (same syntax in both engines). The
    box is periodic in x and y with length 0.1 and 0.04; `grate_line` defines a grate fix 'gr'."""
    v = "compute m all tdem/mixing/velocity radius {} bins x {} {} {}"
    v_slots = [("radius", "pos", "0.01"), ("bins", "lohi_lo", "0"), ("bins", "lohi_hi", "0.1"),
               ("bins", "int1", "4")]
    out = [(l, n, e, w) for l, n, e, w in value_cases("mixing velocity", v, v_slots)]
    vg = v.format(*[s[2] for s in v_slots])
    out += value_cases("mixing velocity periodic", vg.replace("radius 0.01", "radius {}") + " periodic x",
                       [("radius", "halfbox", "0.01")])
    out += word_cases("mixing velocity", vg + " {}", "x y", "periodic", "")
    out += word_cases("mixing velocity", vg + " {}", "all", "exclude", "", bad="nogroup")
    out.append((vg.replace("bins x", "bins w"), "mixing velocity: bins w", "error", ["bins", "w"]))
    out += unknown_keyword("mixing velocity", vg)
    d = "fix d all tdem/mixing/depth every {} column {} bins x {} {} {} floor {}"
    d_slots = [("every", "int1", "1"), ("column", "colbox", "0.02"), ("bins", "lohi_lo", "0"),
               ("bins", "lohi_hi", "0.1"), ("bins", "int1", "4"), ("floor", "anyfinite", "0")]
    out += value_cases("mixing depth", d, d_slots)
    dg = d.format(*[s[2] for s in d_slots])
    for key, good in (("normalise", "no"), ("up", "z"), ("lateral", "none")):
        out += word_cases("mixing depth", dg + " {}", good, key, "")
    out += word_cases("mixing depth", dg + " {}", "mixing.txt", "file", "", bad="/nonexistent/dir/mix.txt")
    out += word_cases("mixing depth", dg.replace(" floor 0", "") + " {}", "gr", "grate", "", bad="nofix")
    out.append((dg.replace(" floor 0", ""), "mixing depth: neither grate nor floor", "error", ["grate", "floor"]))
    out.append((dg + " up x", "mixing depth: up = the transport axis", "error", ["up"]))
    out += unknown_keyword("mixing depth", dg)
    return [(grate_line + "\n" + l if " grate " in l and "nofix" not in l else l, n, e, w) for l, n, e, w in out]


def integrate_cases():
    good = "fix i all tdem/integrate scheme velocity_verlet"
    out = word_cases("integrate", "fix i all tdem/integrate {}", "gear5", "scheme", "", bad="rk7")
    out += word_cases("integrate", good + " {}", "no", "rotation", "", bad="maybe")
    out.append(("fix i all tdem/integrate", "integrate: no scheme", "error", ["scheme"]))
    out += unknown_keyword("integrate", good)
    return out
