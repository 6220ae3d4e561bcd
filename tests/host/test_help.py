#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""`-h` of tdem-lammps / tdem-liggghts lists tdem's styles after the engine's own lists (issue 21).

Expected names, independent of the listing code: every style the source registers (LAMMPS: the
entries of the registration tables, `StyleKind::...` / `fix_entry<...>("NAME"` / `compute_entry`;
LIGGGHTS: `add_fix_style(lmp, "NAME"` / `add_compute_style`) and every tdem contact model that the
project's input scripts, validation cases and docs use (`model tdem/...`, `tangential tdem/...`,
`surface ...`, `rolling_friction ...`). The engine's own help stays in front and the run ends
normally (LAMMPS 0; LIGGGHTS ends its help with status 1 itself).

usage: test_help.py --exe BIN --engine lammps|liggghts --repo DIR
"""
import argparse
import os
import re
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--exe", required=True)
ap.add_argument("--engine", required=True, choices=["lammps", "liggghts"])
ap.add_argument("--repo", required=True)
a = ap.parse_args()


def files(top, exts):
    for d, _, names in os.walk(top):
        for n in names:
            if n.endswith(exts):
                yield os.path.join(d, n)


def grep(top, exts, pattern):
    found = set()
    for p in files(top, exts):
        found |= set(re.findall(pattern, open(p, errors="replace").read()))
    return found


src = os.path.join(a.repo, "src")
if a.engine == "lammps":
    styles = grep(src, (".cpp", ".h"), r'StyleKind::(?:pair|fix|compute), "(tdem/[^"]+)"')
    styles |= grep(src, (".cpp", ".h"), r'(?:fix|compute)_entry<[A-Za-z_:]+>\(\s*"(tdem/[^"]+)"')
    first = "* Pair styles:"
else:
    styles = grep(src, (".cpp", ".h"), r'add_(?:fix|compute)_style\(\s*lmp,\s*"(tdem/[^"]+)"')
    users = set()
    for top in ("input_scripts", "validation", "docs"):
        users |= grep(os.path.join(a.repo, top), (".in", ".md", ".py", ".sh"),
                      r"(?:model|tangential|surface|rolling_friction) (tdem/[a-z_]+)")
    styles |= users
    first = "* Pair styles:"
r = subprocess.run([a.exe, "-h"], capture_output=True, text=True, errors="replace", timeout=120)
out = r.stdout
fails = []
cut = out.find("* tdem")
if cut < 0 or out.find(first) < 0 or out.find(first) > cut:
    fails.append("the tdem section does not follow the engine's own style lists")
listed = set(re.findall(r"tdem/[a-z_/]+", out[cut:] if cut >= 0 else ""))
missing = sorted(styles - listed)
if missing:
    fails.append("not listed: " + ", ".join(missing))
ok_rc = r.returncode == 0 if a.engine == "lammps" else 0 <= r.returncode < 128
if not ok_rc:
    fails.append("exit status %d" % r.returncode)
print("%s -h: %d tdem names expected, %d listed in the tdem section%s" % (
    os.path.basename(a.exe), len(styles), len(listed), "" if cut < 0 else ":\n" + out[cut:]))
for f in fails:
    print("FAIL " + f)
if not fails:
    print("PASS every tdem style is listed after the engine's own lists")
sys.exit(1 if fails else 0)
