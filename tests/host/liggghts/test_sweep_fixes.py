#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Generated bad-input sweep of the tdem LIGGGHTS fixes and computes (issue 17): fix tdem/clump,
fix tdem/grate, compute tdem/mixing/velocity, fix tdem/mixing/depth and fix tdem/integrate.

The cases come from tests/host/fix_sweep.py, as in the LAMMPS sweep of the same name (the grate
has no law here, its bars are meshes, and its own keyword is wall_type). Each case runs in its own
directory (the grate writes its meshes as STL files there) for 10 steps with the output unbuffered
(stdbuf -o0 -e0) and must end in an ERROR line naming the keyword (exit 1..127, no signal, in time)
or in a documented acceptance (docs/limits.md). Counts: crashes, hangs and silent acceptances 0."""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import sweep_common as SC  # noqa: E402
import fix_sweep as FS  # noqa: E402
import law_props as LP  # noqa: E402
import tdem_lig as T  # noqa: E402
import mpi_env  # noqa: E402

args = T.parse_args()
chk = T.Checks()

HEAD = """atom_style {style}
atom_modify map array
boundary {bnd}
newton off
communicate single vel yes
units si
region box block {box} units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0{exclude}
""" + LP.lines(1) + """
pair_style gran model tdem/lsd tangential tdem/cundall_strack parameters restitution
pair_coeff * *
"""


def head(bnd, box, style="granular", exclude=""):
    return HEAD.format(style=style, bnd=bnd, box=box, exclude=exclude)


def clump_scene(line):
    return (head("f f f", "0 0.05 0 0.05 0 0.05", "hybrid sphere molecular", " exclude molecule all") +
            "region ins block 0.01 0.04 0.01 0.04 0.01 0.04 units box\n" + line + "\ntimestep 1e-6\nrun 10\n")


def grate_scene(line):
    return (head("f p f", "-0.1 0.5 -0.05 0.05 -0.2 0.3") +
            "create_atoms 1 single 0.05 0 0.2 units box\nset group all diameter 0.01 density 2500\n" +
            line + "\nfix nve all nve/sphere\ntimestep 1e-5\nrun 10\n")


MIX_GRATE = "fix gr all tdem/grate rows 2 bar_length 0.05 bar_height 0.01 width 0.04 declination 0 origin 0 0.02 0.03"


def mixing_scene(line):
    atoms = "".join("create_atoms 1 single %g %g %g units box\n" % (x, y, z)
                    for x, y, z in ((0.02, 0.01, 0.05), (0.04, 0.02, 0.06), (0.06, 0.03, 0.05), (0.08, 0.02, 0.07)))
    invoke = "thermo_style custom step c_m\nthermo 5\n" if line.startswith("compute m ") else ""
    return (head("p p f", "0 0.1 0 0.04 0 0.1") + atoms + "set group all diameter 0.005 density 2500\n" + line +
            "\n" + invoke + "fix nve all nve/sphere\ntimestep 1e-5\nrun 10\n")


def integrate_scene(line):
    return (head("f f f", "0 0.1 0 0.1 0 0.1") +
            "create_atoms 1 single 0.05 0.05 0.003 units box\ncreate_atoms 1 single 0.05 0.05 0.0075 units box\n"
            "set group all diameter 0.005 density 2500\n" + line + "\ntimestep 1e-7\nrun 10\n")


# LIGGGHTS needs every mesh element inside the box: origin -1 puts the bars outside (docs/limits.md)
GRATE_EXCEPT = {("grate", "origin", "-1"): "error"}

CASES = []
for scene, cases in ((clump_scene, FS.clump_cases()),
                     (grate_scene, FS.grate_cases("fix gr all tdem/grate ", [("wall_type", "int1", "1")],
                                                  GRATE_EXCEPT)),
                     (mixing_scene, FS.mixing_cases(MIX_GRATE)),
                     (integrate_scene, FS.integrate_cases())):
    for line, name, expect, words in cases:
        CASES.append((scene(line), name, expect, words))

wd = T.workdir(args, "sweep_fixes")


def execute(k):
    text, name, expect, words = CASES[k]
    d = os.path.join(wd, "c%03d" % k)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "in.case"), "w") as f:
        f.write(text)
    cmd = ["stdbuf", "-o0", "-e0", args.tdem, "-in", "in.case", "-log", "log.case", "-echo", "none"]
    try:
        r = mpi_env.run(cmd, cwd=d, capture_output=True, text=True, errors="replace", timeout=60)
    except subprocess.TimeoutExpired:
        return [(False, "%s: no hang (timeout)" % name)], "hang"
    return SC.verdict(name, r.returncode, r.stdout + r.stderr, expect, words)


SC.finish(SC.run_all(len(CASES), execute, chk), chk, "the keyword")
chk.done()
