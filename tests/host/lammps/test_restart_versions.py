#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Restart files across LAMMPS generations: a settling bed (2592 spheres, pair tdem/gran and three
fix tdem/wall/gran walls, contacts with tangential history) is run 3000 steps and written by
tdem-lammps of the main LAMMPS (--old-tdem, Debian's 29Sep2021), then continued 300 steps
  a. by that same tdem-lammps (the reference),
  b. by tdem-lammps of the newer LAMMPS under test (--tdem),
  c. by that newer LAMMPS's own lmp with the plugin loaded (--lmp, --plugin).
The newer LAMMPS stores neighbor-history partner IDs in restart files as integer bits where
LAMMPS 2022 stored their values; read unchanged, every pair contact would lose its history.
pair tdem/gran rewrites them (lammps_compat.h) and says so: b and c must equal a bit for bit
(the two LAMMPS versions give bitwise equal trajectories for this scene). The other way round,
LAMMPS 2022 refuses a file of the newer LAMMPS with its own clear error."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.restart_versions")
old = args["old-tdem"]
wd = lc.workdir("restart_versions")

write = lc.scene(lc.tdem_interaction(), 3000, "dump.w").replace(
    "run             3000", "run             3000\nwrite_restart   restart.bin")
law = lc.tdem_law()
READ = """
variable        plugin index none
variable        haveplugin equal is_file(${plugin})
if "${haveplugin}" then "plugin load ${plugin}"
read_restart    %s
comm_modify     vel yes
neighbor        0.001 bin
neigh_modify    delay 0
""" + "\n".join("fix             w%d all tdem/wall/gran %s %s" % (k, law, w) for k, w in enumerate(lc.WALLS)) + """
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
run             300
write_dump      all custom %s id x y z vx vy vz omegax omegay omegaz modify sort id format float %%.17g
"""
lc.run(old, write, wd, "in.write")
_, oa = lc.run(old, READ % ("restart.bin", "dump.a"), wd, "in.read_a")
_, ob = lc.run(args["tdem"], READ % ("restart.bin", "dump.b"), wd, "in.read_b")
_, oc = lc.run(args["lmp"], READ % ("restart.bin", "dump.c"), wd, "in.read_c", extra=("-var", "plugin", args["plugin"]))
_, a = lc.read_dump(os.path.join(wd, "dump.a"))
for tag, out in (("b", ob), ("c", oc)):
    what = "tdem-lammps %s" % args["version"] if tag == "b" else "lmp %s + plugin" % args["version"]
    _, x = lc.read_dump(os.path.join(wd, "dump." + tag))
    _, worst = lc.rel_diff(x[:, 1:], a[:, 1:])
    conv = [l for l in out.splitlines() if "neighbor-history partner IDs" in l]
    print("%s: %s; max relative difference to the 29Sep2021 continuation %.3g" % (what, conv[0] if conv else "no conversion message", worst))
    chk.check(bool(conv) and "converted" in conv[0], "%s: the 2022 restart's history partner IDs are converted" % what)
    chk.check(x.shape == a.shape and worst == 0.0,
              "%s: continues the 29Sep2021 restart bit for bit like 29Sep2021 itself (max %.3g)" % (what, worst))
chk.check("neighbor-history partner IDs" not in oa, "29Sep2021 reading its own file converts nothing")
# the other way round: the newer file in LAMMPS 2022
lc.run(args["tdem"], write.replace("restart.bin", "restart_new.bin"), wd, "in.write_new")
rc, out = lc.run(old, READ % ("restart_new.bin", "dump.d"), wd, "in.read_d", check=False)
err = [l for l in out.splitlines() if l.startswith("ERROR")]
print("29Sep2021 reading the %s file: status %d, %s" % (args["version"], rc, err[0] if err else "no ERROR line"))
chk.check(rc != 0 and bool(err) and "Restart file" in err[0], "29Sep2021 refuses the newer restart file with an ERROR line")
chk.done()
