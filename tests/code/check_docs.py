#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Checks of the documentation's shape (issue 21): the README is a landing page of at most 200 lines,
and every relative link and image of README.md, docs/**/*.md and validation/*/README.md points to a
file or directory that exists.

  python3 tests/code/check_docs.py [--root DIR]
Exits 1 and names every broken link.
"""
import argparse
import glob
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    root = os.path.abspath(ap.parse_args().root)
    files = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True)) \
        + sorted(glob.glob(os.path.join(root, "validation", "*", "README.md")))
    bad = []
    for f in files:
        text = open(f, encoding="utf-8").read()
        text = re.sub(r"```.*?```", "", text, flags=re.S)  # links inside code blocks are code
        for target in LINK.findall(text):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            path = os.path.normpath(os.path.join(os.path.dirname(f), target.split("#")[0]))
            if not os.path.exists(path):
                bad.append("%s: link to %s: no such file" % (os.path.relpath(f, root), target))
    n = sum(1 for _ in open(os.path.join(root, "README.md"), encoding="utf-8"))
    if n > 200:
        bad.append("README.md: %d lines (a landing page: at most 200)" % n)
    print("%d files checked, README.md %d lines" % (len(files), n))
    for b in bad:
        print("FAIL " + b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
