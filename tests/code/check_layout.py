#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Checks of the source tree's shape (issue 19): the layers, and the size of the files.

  python3 tests/code/check_layout.py [--src DIR] [--max-lines N] [--part layers|size|all]

Layers, from the bottom (a file may include files of its own layer and of the layers below it):
  0 contact      src/contact/**            host-free force laws, parameters, checks
  1 core         src/collision/**, src/integrators/*.h
                 host-free harness and schemes
  2 pair_styles  src/pair_styles/<host>/   the law adapters of one host
  3 fix cores    src/fixes/<module>/*.h    host-free cores of the fix modules
  4 host fixes   src/integrators/<host>/, src/fixes/<module>/<host>/, src/fixes/<host>/ and
                 src/fixes/<module>/hosts/ (one source built for each engine)
  5 drivers      src/drivers/**
Besides: a host-free file includes no engine header (every quoted include of it resolves inside
src/); a file of one host includes nothing of the other host (a shared file may include either's).

Exits 1 and names every offending include (or file) when a rule is broken.
"""
import argparse
import os
import re
import sys

HOSTS = ("lammps", "liggghts")
SHARED = "hosts"  # src/fixes/<module>/hosts/: one source compiled for each engine
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def classify(rel):
    """(layer, host or None) of a path relative to src/."""
    parts = rel.split("/")
    top = parts[0]
    host = next((p for p in parts[:-1] if p in HOSTS + (SHARED,)), None)
    if top == "contact":
        return 0, None
    if top == "collision":
        return 1, None
    if top == "integrators":
        return (4 if host else 1), host
    if top == "fixes":
        return (4 if host else 3), host
    if top == "pair_styles":
        return 2, host
    if top == "drivers":
        return 5, host
    return None, host


def top_level(rel):
    return rel.split("/")[0]


def host_dirs(src, host):
    """The directories a host adapter's flat includes ("tdem_lammps_law.h") resolve in: the
    host's own and the shared ones (a shared file: both hosts')."""
    names = set(HOSTS) | {SHARED} if host == SHARED else {host, SHARED}
    out = []
    for root, dirs, _ in os.walk(src):
        if os.path.basename(root) in names:
            out.append(root)
    return sorted(out)


def resolve(src, path, name, flat_dirs):
    for base in [os.path.dirname(path), src] + flat_dirs:
        cand = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(cand) and cand.startswith(src + os.sep):
            return os.path.relpath(cand, src)
    return None


def sources(src):
    for root, _, files in os.walk(src):
        for f in sorted(files):
            if f.endswith((".h", ".hpp", ".cpp", ".cc")):
                yield os.path.join(root, f)


def check_layers(src):
    flat = {h: host_dirs(src, h) for h in HOSTS + (SHARED,)}
    bad = []
    for path in sources(src):
        rel = os.path.relpath(path, src)
        layer, host = classify(rel)
        if layer is None:
            continue
        with open(path, encoding="utf-8", errors="replace") as fh:
            for lineno, line in enumerate(fh, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = resolve(src, path, m.group(1), flat[host] if host else [])
                where = f"{rel}:{lineno}: #include \"{m.group(1)}\""
                if target is None:
                    other = resolve(src, path, m.group(1), flat[SHARED])
                    if other is not None:
                        bad.append(f"{where}: resolves only to {other}, a file of another host")
                    elif not host and top_level(rel) != "drivers":
                        bad.append(f"{where}: a host-free file includes a header from outside src/ (an engine's?)")
                    continue
                tl, th = classify(target)
                if tl is None:
                    continue
                if th and host and th != host and SHARED not in (th, host):
                    bad.append(f"{where}: a {host} file includes the {th} file {target}")
                elif th and not host:
                    bad.append(f"{where}: a host-free file includes the {th} file {target}")
                elif tl > layer:
                    bad.append(f"{where}: layer {layer} includes {target} of layer {tl} (upward)")
    return bad


def check_size(src, max_lines):
    bad = []
    for path in sources(src):
        with open(path, encoding="utf-8", errors="replace") as fh:
            n = sum(1 for _ in fh)
        if n > max_lines:
            bad.append(f"{os.path.relpath(path, src)}: {n} lines (at most {max_lines})")
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "src"))
    ap.add_argument("--max-lines", type=int, default=600)
    ap.add_argument("--part", choices=("layers", "size", "all"), default="all")
    a = ap.parse_args()
    src = os.path.realpath(a.src)
    bad = []
    if a.part in ("layers", "all"):
        bad += check_layers(src)
    if a.part in ("size", "all"):
        bad += check_size(src, a.max_lines)
    for b in bad:
        print(b)
    n = sum(1 for _ in sources(src))
    print(f"check_layout ({a.part}): {n} files, {len(bad)} problems")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
