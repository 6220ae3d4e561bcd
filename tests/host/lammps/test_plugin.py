#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The LAMMPS plugin (tdem_lammps_plugin.so, lammpsplugin_init) and the `plugin` command.

1. The settling-bed input run by tdem-lammps with its built-in styles and the same input
   preceded by `plugin load tdem_lammps_plugin.so` give identical thermo output and dumps;
   the log shows that the plugin's creators replaced the built-in ones (so the plugin code
   ran) and `plugin list` lists both styles.
2. `clear` rebuilds LAMMPS's style tables; the tdem styles (built-in and plugin-loaded) must
   still be usable after it.
3. The example input_scripts/lammps/in.tdem_settle (run shortened) runs with the built-in
   styles and with `-var plugin <so>` (its plugin path), with identical thermo output.
4. `plugin load` of a missing file and of a shared object without lammpsplugin_init end with
   an error that names the file (tdem-lammps's own `plugin` command), or are reported by
   LAMMPS's PLUGIN command, which carries on (a liblammps with the PLUGIN package).
With --mode plugin (the stock lmp with the plugin auto-loaded from LAMMPS_PLUGIN_PATH): the
auto-load, `plugin list`, equality with an explicit `plugin load`, a repeated load and `clear`.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.plugin")
N = 3000
wd = lc.workdir("plugin")

if args["mode"] == "plugin":
    # --tdem is the stock lmp with LAMMPS_PLUGIN_PATH naming the plugin's directory: the plugin
    # is loaded at start-up (auto-load), without any `plugin` line in the script
    base = "plugin list\n" + lc.scene(lc.tdem_interaction(), N, "dump.auto")
    _, out_a = lc.run(args["tdem"], base, wd, "in.auto")
    chk.check("Loaded 1 plugins from" in out_a, "auto-load: LAMMPS_PLUGIN_PATH loaded the plugin")
    chk.check("pair style plugin tdem/gran" in out_a and "fix style plugin tdem/wall/gran" in out_a and
              "fix style plugin tdem/clump" in out_a, "auto-load: plugin list shows the tdem styles")
    # the same scene with an explicit `plugin load` in the plain stock lmp
    _, out_l = lc.run(args["lmp"], "plugin load %s\n" % args["plugin"] + lc.scene(lc.tdem_interaction(), N, "dump.load"),
                      wd, "in.load")
    chk.check("Loading plugin: tdem pair style tdem/gran" in out_l, "plugin load: the plugin loads into lmp")
    ta, tl = lc.thermo_blocks(out_a), lc.thermo_blocks(out_l)
    _, a = lc.read_dump(os.path.join(wd, "dump.auto"))
    _, b = lc.read_dump(os.path.join(wd, "dump.load"))
    chk.check(len(ta) > 3 and ta == tl and a.shape == b.shape and (a == b).all(),
              "auto-loaded and `plugin load`: identical thermo and dumps (%d thermo lines)" % len(ta))
    # loading it again is ignored by LAMMPS; `clear` keeps the plugin styles
    text = "plugin load %s\nclear\n" % args["plugin"] + lc.scene(lc.tdem_interaction(), 200, "dump.clear")
    rc, out = lc.run(args["tdem"], text, wd, "in.again", check=False)
    # (LAMMPS 4Jul2026 says "Ignoring load of pair style tdem/gran"; 4Feb2025 says nothing after an auto-load)
    chk.check(rc == 0 and "Loop time" in out, "a second load does no harm and the styles survive clear")
    ex = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts",
                      "lammps", "in.tdem_settle")
    text = open(ex).read().replace("run             50000", "run             3000")
    _, o1 = lc.run(args["tdem"], text, wd, "in.settle")
    _, o2 = lc.run(args["lmp"], text, wd, "in.settle_plugin", extra=("-var", "plugin", args["plugin"]))
    t1, t2 = lc.thermo_blocks(o1), lc.thermo_blocks(o2)
    chk.check(len(t1) > 1 and t1 == t2, "example in.tdem_settle: auto-loaded and -var plugin runs identical")
    chk.done()
base = lc.scene(lc.tdem_interaction(), N, "dump.builtin")
_, out_b = lc.run(args["tdem"], base, wd, "in.builtin")
plug = "plugin load %s\nplugin list\n" % args["plugin"] + lc.scene(lc.tdem_interaction(), N, "dump.plugin")
_, out_p = lc.run(args["tdem"], plug, wd, "in.plugin")
chk.check("Loading plugin: tdem pair style tdem/gran" in out_p and
          "Loading plugin: tdem fix style tdem/wall/gran" in out_p, "plugin: both styles loaded")
chk.check("Overriding built-in pair style tdem/gran from plugin" in out_p and
          "Overriding built-in fix style tdem/wall/gran from plugin" in out_p,
          "plugin: plugin creators replaced the built-in ones")
chk.check("pair style plugin tdem/gran" in out_p and "fix style plugin tdem/wall/gran" in out_p,
          "plugin list shows both styles")
tb, tp = lc.thermo_blocks(out_b), lc.thermo_blocks(out_p)
chk.check(len(tb) > 3 and tb == tp, "plugin: thermo output identical to built-in (%d lines)" % len(tb))
_, a = lc.read_dump(os.path.join(wd, "dump.builtin"))
_, b = lc.read_dump(os.path.join(wd, "dump.plugin"))
chk.check(a.shape == b.shape and (a == b).all(), "plugin: dump identical to built-in")

# clear: built-in and plugin styles survive
for name, pre in (("builtin", ""), ("plugin", "plugin load %s\n" % args["plugin"])):
    text = pre + "clear\n" + lc.scene(lc.tdem_interaction(), 200, "dump.clear_" + name)
    rc, out = lc.run(args["tdem"], text, wd, "in.clear_" + name, check=False)
    chk.check(rc == 0 and "Loop time" in out, "clear (%s): tdem styles usable after clear" % name)

# the example script, built in and through its plugin switch
ex = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts",
                  "lammps", "in.tdem_settle")
text = open(ex).read().replace("run             50000", "run             3000")
_, o1 = lc.run(args["tdem"], text, wd, "in.settle")
_, o2 = lc.run(args["tdem"], text, wd, "in.settle_plugin", extra=("-var", "plugin", args["plugin"]))
t1, t2 = lc.thermo_blocks(o1), lc.thermo_blocks(o2)
chk.check("Loading plugin" in o2 and "Loading plugin" not in o1 and len(t1) > 1 and t1 == t2,
          "example in.tdem_settle: built-in and plugin runs identical (%d thermo lines)" % len(t1))

# bad plugin files
# tdem-lammps adds its own `plugin` command only where liblammps has none; with a PLUGIN-enabled
# liblammps (and in lmp itself) the command is LAMMPS's, which reports a failed load and goes on
rc, out = lc.run(args["tdem"], "plugin load %s/nonexistent_plugin.so\n" % wd, wd, "in.bad1", check=False)
if "Open of file" in out:
    chk.check(rc == 0 and "nonexistent_plugin.so failed" in out,
              "plugin load of a missing file: LAMMPS's PLUGIN command reports it, naming the file")
else:
    chk.check(rc != 0 and rc > 0 and "plugin load: cannot open" in out and "nonexistent_plugin.so" in out,
              "plugin load of a missing file: error naming the file (status %d)" % rc)
libm = "/lib/x86_64-linux-gnu/libm.so.6"
rc, out = lc.run(args["tdem"], "plugin load %s\n" % libm, wd, "in.bad2", check=False)
if "Plugin symbol lookup failure" in out:
    chk.check(rc == 0 and "libm.so.6" in out, "plugin load of a non-plugin: LAMMPS's PLUGIN command reports it")
else:
    chk.check(rc > 0 and "has no lammpsplugin_init" in out, "plugin load of a non-plugin: error (status %d)" % rc)
chk.done()
