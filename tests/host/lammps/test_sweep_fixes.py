#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Generated bad-input sweep of the tdem LAMMPS fixes and computes (issue 17): fix tdem/clump,
fix tdem/grate, compute tdem/mixing/velocity, fix tdem/mixing/depth and fix tdem/integrate.

The cases come from tests/host/fix_sweep.py (every numeric value replaced by a word, NaN, +-inf, -1,
0, 1e300 and, for integers, 0.5; the line cut off before each value; every word option given a
wrong word and no value; an unknown keyword). Each case runs in its own directory for 10 steps and
must end in an ERROR line naming the keyword (exit 1..127, no signal, in time) or in a documented
acceptance (docs/limits.md). Counts: crashes, hangs and silent acceptances must all be 0."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import lmp_common as lc  # noqa: E402
import sweep_common as SC  # noqa: E402
import fix_sweep as FS  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.sweep_fixes")

HEAD = """units si
atom_style sphere
atom_modify map array
boundary {bnd}
newton off
comm_modify vel yes
region box block {box} units box
create_box 1 box
"""
LAW = "normal lsd restitution 0.5 5e-4 tangential cundall_strack 0.8 0.5"
PAIR = "pair_style tdem/gran\npair_coeff * * " + LAW + "\n"


def clump_scene(line):
    return (HEAD.format(bnd="f f f", box="0 0.05 0 0.05 0 0.05") +
            "fix pm all property/atom mol ghost yes\nregion ins block 0.01 0.04 0.01 0.04 0.01 0.04 units box\n"
            "neigh_modify exclude molecule/intra all\n" + PAIR + line + "\ntimestep 1e-6\nrun 10\n")


def grate_scene(line):
    return (HEAD.format(bnd="f p f", box="-0.1 0.5 -0.05 0.05 -0.2 0.3") +
            "create_atoms 1 single 0.05 0 0.2 units box\nset group all diameter 0.01 density 2500\n" + PAIR +
            line + "\nfix nve all nve/sphere\ntimestep 1e-5\nrun 10\n")


MIX_GRATE = ("fix gr all tdem/grate %s rows 2 bar_length 0.05 bar_height 0.01 width 0.04 declination 0 "
             "origin 0 0.02 0.03" % LAW)


def mixing_scene(line):
    atoms = "".join("create_atoms 1 single %g %g %g units box\n" % (x, y, z)
                    for x, y, z in ((0.02, 0.01, 0.05), (0.04, 0.02, 0.06), (0.06, 0.03, 0.05), (0.08, 0.02, 0.07)))
    invoke = "thermo_style custom step c_m\nthermo 5\n" if line.startswith("compute m ") else ""
    return (HEAD.format(bnd="p p f", box="0 0.1 0 0.04 0 0.1") + atoms +
            "set group all diameter 0.005 density 2500\n" + PAIR + line + "\n" + invoke +
            "fix nve all nve/sphere\ntimestep 1e-5\nrun 10\n")


def integrate_scene(line):
    return (HEAD.format(bnd="f f f", box="0 0.1 0 0.1 0 0.1") +
            "create_atoms 1 single 0.05 0.05 0.003 units box\ncreate_atoms 1 single 0.05 0.05 0.0075 units box\n"
            "set group all diameter 0.005 density 2500\n" + PAIR + line + "\ntimestep 1e-7\nrun 10\n")


CASES = []
for scene, cases in ((clump_scene, FS.clump_cases()),
                     (grate_scene, FS.grate_cases("fix gr all tdem/grate %s " % LAW, [("max_contacts", "int1", "4")])),
                     (mixing_scene, FS.mixing_cases(MIX_GRATE)),
                     (integrate_scene, FS.integrate_cases())):
    for line, name, expect, words in cases:
        CASES.append((scene(line), name, expect, words))

wd = lc.workdir("sweep_fixes")


def execute(k):
    text, name, expect, words = CASES[k]
    d = os.path.join(wd, "c%03d" % k)
    os.makedirs(d, exist_ok=True)
    try:
        rc, out = lc.run(args["tdem"], text, d, "in.case", check=False, timeout=60)
    except Exception as ex:  # subprocess.TimeoutExpired
        return [(False, "%s: no hang (%s)" % (name, type(ex).__name__))], "hang"
    return SC.verdict(name, rc, out, expect, words)


SC.finish(SC.run_all(len(CASES), execute, chk), chk, "the keyword")
chk.done()
