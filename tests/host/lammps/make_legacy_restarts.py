#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Writes the legacy restart files of data/restart_v6/ with a tdem-lammps that writes pair
tdem/gran restart data of format 6 (tdem before issue 19's format 7, e.g. commit d24f679, built
against Debian 12's LAMMPS 29Sep2021):

  python3 make_legacy_restarts.py --tdem OLD/build/bin/tdem-lammps --out data/restart_v6

Prints the state at the restart point (every contact must be unloading there)."""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import legacy_restart_scene as sc  # noqa: E402
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
out_dir = os.path.abspath(args["out"])
os.makedirs(out_dir, exist_ok=True)
for name, law, tc, dt in sc.LAWS:
    n1, _ = sc.steps(tc, dt)
    wd = lc.workdir("make_" + name)
    _, out = lc.run(args["tdem"], sc.base(law, dt) + "run %d\n" % n1 + sc.STATE + "write_restart v6.restart\n", wd)
    print(name, "state at the restart point:", sc.results(out, "STATE"))
    shutil.copy(os.path.join(wd, "v6.restart"), os.path.join(out_dir, name + ".restart"))
