#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Optional (only when CMake gets -DTDEM_LAMMPS_PLUGIN_HOST=<lmp built with PLUGIN and
GRANULAR, same version, shared library>): tdem_lammps_plugin.so loaded with `plugin load` into
that LAMMPS reproduces the stock gran/hooke/history + wall/gran run of the same LAMMPS bit
for bit (settling bed, 6000 steps), and the example in.tdem_settle gives the same thermo
output there as in tdem-lammps."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.plugin_host")
host = args["host"]
wd = lc.workdir("plugin_host")
if lc.classic_walls(args):
    lc.run(host, lc.scene(lc.stock_interaction(), 6000, "dump.stock"), wd, "in.stock")
else:  # the stock pair style with tdem walls (the stock walls are compared in lammps.equivalence)
    lc.run(host, "plugin load %s\n" % args["plugin"] + lc.scene(lc.stock_pair_tdem_walls(), 6000, "dump.stock"),
           wd, "in.stock")
_, out = lc.run(host, "plugin load %s\n" % args["plugin"] + lc.scene(lc.tdem_interaction(), 6000, "dump.tdem"),
                wd, "in.tdem")
chk.check("Loading plugin: tdem pair style tdem/gran" in out, "plugin loaded into %s" % host)
_, a = lc.read_dump(os.path.join(wd, "dump.tdem"))
_, b = lc.read_dump(os.path.join(wd, "dump.stock"))
_, worst = lc.rel_diff(a[:, 1:], b[:, 1:])
chk.check(a.shape == b.shape and worst <= 1e-8, "plugin in PLUGIN LAMMPS equals its stock styles (max %.3g)" % worst)
ex = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts",
                  "lammps", "in.tdem_settle")
text = open(ex).read().replace("run             50000", "run             3000")
_, o1 = lc.run(host, text, wd, "in.settle_host", extra=("-var", "plugin", args["plugin"]))
_, o2 = lc.run(args["tdem"], text, wd, "in.settle_tdem")
t1, t2 = lc.thermo_blocks(o1), lc.thermo_blocks(o2)
chk.check(len(t1) > 1 and t1 == t2, "in.tdem_settle: PLUGIN LAMMPS and tdem-lammps thermo identical")
chk.done()
