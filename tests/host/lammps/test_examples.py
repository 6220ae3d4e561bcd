#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""tdem-lammps is a drop-in for lmp: the granular examples of lammps-examples (pour,
granregion, granular), copied to a temporary directory with their runs shortened, give the
same thermo output with tdem-lammps as with the stock /usr/bin/lmp (columns that measure CPU
time are left out of the comparison). The examples use only stock styles, so this checks the
driver (command line, style registration, `plugin`-free scripts, loops and variables).

In addition pour/in.pour (fix pour inserts 3000 particles, then the chute flows) is run with
its gran/hooke/history pair style and wall/gran fix replaced by tdem/gran and
tdem/wall/gran with the same physics (kt = kn 2/7 as NULL gives, no tangential damping as
dampflag 0 gives) and compared with the stock run printed with 16 digits: identical."""
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.examples")
EX = args["examples"]

# example -> longest `run` kept (steps); chosen so that each takes a few seconds
CASES = [
    ("pour", "in.pour", 4000),
    ("pour", "in.pour.2d", 4000),
    ("pour", "in.pour.2d.molecule", 4000),
    ("granregion", "in.granregion.box", 2000),
    ("granregion", "in.granregion.funnel", 2000),
    ("granregion", "in.granregion.mixer", 3000),
    ("granular", "in.pour.flatwall", 3000),
    ("granular", "in.pour.drum", 400),
]
CPU = {"CPU", "T/CPU", "S/CPU", "CPULeft", "TPS", "Cpu"}


def comparable(rows):
    out, drop = [], []
    for r in rows:
        s = r.split()
        if s[0] == "Step":
            drop = [i for i, c in enumerate(s) if c in CPU]
        out.append(" ".join(x for i, x in enumerate(s) if i not in drop))
    return out


for sub, name, cap in CASES:
    src = os.path.join(EX, sub)
    if not os.path.exists(os.path.join(src, name)):
        chk.check(False, "%s/%s: example not installed (lammps-examples)" % (sub, name))
        continue
    wd = lc.workdir("ex_" + name.replace(".", "_"))
    for f in os.listdir(src):
        shutil.copy(os.path.join(src, f), wd)
    text = open(os.path.join(src, name)).read()
    text = re.sub(r"(?m)^(\s*run\s+)(\d+)",
                  lambda m: m.group(1) + str(min(int(m.group(2)), cap)), text)
    res = {}
    for tag, exe in (("lmp", args["lmp"]), ("tdem", args["tdem"])):
        rc, out = lc.run(exe, text, wd, "in.%s.%s" % (tag, name), check=False)
        res[tag] = (rc, comparable(lc.thermo_blocks(out)))
    (rc_s, t_s), (rc_t, t_t) = res["lmp"], res["tdem"]
    ok = rc_s == 0 and rc_t == 0 and len(t_s) > 1 and t_s == t_t
    chk.check(ok, "%s/%s (runs <= %d steps): exit %d/%d, %d thermo lines, identical: %s"
              % (sub, name, cap, rc_s, rc_t, len(t_s), t_s == t_t))


# ---- pour/in.pour with the tdem styles
def tdem_from_stock(words):
    kn, kt, gn, gt, mu, damp = words[:6]
    kn, gn, mu = float(kn), float(gn), float(mu)
    kt = kn * 2.0 / 7.0 if kt == "NULL" else float(kt)
    gt = 0.5 * gn if gt == "NULL" else float(gt)
    if int(damp) == 0:
        gt = 0.0
    limit = "yes" if "limit_damping" in words[6:] else "no"
    return ("normal lsd stiffness %r %r tangential cundall_strack %r %r %r limit_force %s"
            % (kn, gn, kt, gt, mu, limit))


src = os.path.join(EX, "pour", "in.pour")
if os.path.exists(src):
    text = open(src).read().replace("&\n", " ")
    text = re.sub(r"(?m)^(\s*run\s+)(\d+)", lambda m: m.group(1) + "3000", text)
    text = text.replace("thermo_modify\tlost ignore norm no",
                        "thermo_modify\tlost ignore norm no format float %.16g")
    m = re.search(r"(?m)^pair_style\s+gran/hooke/history\s+(.*)$", text)
    law = tdem_from_stock(m.group(1).split())
    tt = text.replace(m.group(0), "pair_style tdem/gran")
    tt = re.sub(r"(?m)^pair_coeff\s+\* \*\s*$", "pair_coeff * * " + law, tt)
    tt = re.sub(r"(?m)wall/gran hooke/history(\s+\S+){6}", "tdem/wall/gran " + law, tt)
    wd = lc.workdir("ex_pour_tdem")
    if not lc.classic_walls(args):
        # the stock walls are not the classic code here (lmp_common.classic_walls): the stock
        # side keeps its pair style and takes the tdem walls, run by the tdem executable
        text = re.sub(r"(?m)wall/gran hooke/history(\s+\S+){6}", "tdem/wall/gran " + law, text)
    _, out_s = lc.run(args["lmp"] if lc.classic_walls(args) else args["tdem"], text, wd, "in.pour.stock")
    _, out_t = lc.run(args["tdem"], tt, wd, "in.pour.tdem")
    ts, tt_ = lc.thermo_blocks(out_s), lc.thermo_blocks(out_t)
    chk.check("tdem/wall/gran" in tt and "tdem/gran" in tt, "in.pour converted to the tdem styles")
    chk.check(len(ts) > 4 and ts == tt_,
              "pour/in.pour with tdem/gran + tdem/wall/gran: thermo (16 digits) identical to stock "
              "(%d lines, last: %s)" % (len(ts), ts[-1] if ts else ""))
chk.done()
