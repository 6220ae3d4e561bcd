#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""tools/lammps_dropin.sh puts tdem's LAMMPS styles into a LAMMPS source tree (README, "Drop-in").

On a copy of the src/ directory of the LAMMPS tdem is built against:
  - the drop-in copies the styles and every header they include (a header missing from its list
    fails the compile below);
  - every copied .cpp compiles there with LAMMPS's own headers (-fsyntax-only: what LAMMPS's
    build would compile, without building LAMMPS);
  - `--remove` takes out exactly what it put in: the tree's file list is the original again.

  test_dropin.py --repo REPO --lammps-src LAMMPS/src --cxx MPICXX
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor


def files_of(root):
    out = set()
    for d, _, fs in os.walk(root):
        for f in fs:
            out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repo", required=True)
    ap.add_argument("--lammps-src", required=True)
    ap.add_argument("--cxx", required=True)
    a = ap.parse_args()
    fails = []
    with tempfile.TemporaryDirectory(prefix="tdem_dropin_") as tmp:
        src = os.path.join(tmp, "src")
        shutil.copytree(a.lammps_src, src, symlinks=True)
        before = files_of(src)
        tool = os.path.join(a.repo, "tools", "lammps_dropin.sh")
        r = subprocess.run(["bash", tool, tmp], capture_output=True, text=True)
        print(r.stdout.strip())
        if r.returncode != 0:
            print(r.stderr)
            print("FAIL: lammps_dropin.sh exited with", r.returncode)
            return 1
        listed = [l.strip() for l in open(os.path.join(src, "tdem_dropin_files.txt")) if l.strip()]
        sources = [f for f in listed if f.endswith(".cpp")]
        inc = ["-I" + src] + ["-I" + os.path.join(src, p) for p in ("GRANULAR", "RIGID", "MOLECULE")]

        def compile_one(f):
            r = subprocess.run([a.cxx, "-std=c++17", "-fsyntax-only"] + inc + [os.path.join(src, f)],
                               capture_output=True, text=True)
            return f, r.returncode, r.stderr

        with ThreadPoolExecutor(max_workers=2) as ex:
            for f, rc, err in ex.map(compile_one, sources):
                if rc != 0:
                    fails.append("%s does not compile in the drop-in tree:\n%s" % (f, err[:2000]))
        print("%d files copied, %d sources compiled (-fsyntax-only), %d failed" %
              (len(listed), len(sources), sum(1 for m in fails if "compile" in m)))
        if len(sources) < 10:
            fails.append("only %d sources copied (the styles are missing)" % len(sources))
        r = subprocess.run(["bash", tool, "--remove", tmp], capture_output=True, text=True)
        after = files_of(src)
        if r.returncode != 0 or after != before:
            fails.append("--remove left %s and removed %s" % (sorted(after - before)[:10], sorted(before - after)[:10]))
    for m in fails:
        print("FAIL:", m)
    print("PASS" if not fails else "FAILED")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
