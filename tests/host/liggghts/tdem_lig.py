# SPDX-License-Identifier: GPL-2.0-or-later
"""Helpers shared by the LIGGGHTS host tests: run an engine on an input text, read dumps and logs.

Expected values in the tests come from closed forms or from the stock engine, never from tdem.
"""
import argparse
import os
import re
import shutil
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import mpi_env  # noqa: E402


def parse_args(extra=None):
    p = argparse.ArgumentParser()
    p.add_argument("--tdem", required=True, help="tdem-liggghts executable")
    p.add_argument("--stock", default="/usr/bin/liggghts", help="stock liggghts executable")
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--workdir", default=None)
    p.add_argument("--keep", action="store_true")
    if extra:
        extra(p)
    return p.parse_args()


def workdir(args, name):
    base = args.workdir or tempfile.gettempdir()
    d = os.path.join(base, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def run(exe, text, cwd, name, np_=1, mpirun="mpirun", check=True, timeout=600):
    """Write `text` to cwd/in.<name> and run exe on it. Returns CompletedProcess."""
    inp = os.path.join(cwd, "in." + name)
    with open(inp, "w") as f:
        f.write(text)
    cmd = [exe, "-in", inp, "-log", os.path.join(cwd, "log." + name), "-echo", "none"]
    if np_ > 1:
        cmd = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
    r = mpi_env.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace", timeout=timeout,
                       env=env)
    if check and r.returncode != 0:
        sys.stderr.write(r.stdout[-4000:] + r.stderr[-4000:])
        raise SystemExit("FAIL: %s on %s exited with %d" % (os.path.basename(exe), name, r.returncode))
    return r


def read_dump(path):
    """Frames of a LAMMPS text dump: list of (step, columns, array sorted by id)."""
    frames = []
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            j = i + 4
            while not lines[j].startswith("ITEM: ATOMS"):
                j += 1
            cols = lines[j].split()[2:]
            data = np.array([[float(x) for x in l.split()] for l in lines[j + 1 : j + 1 + n]]).reshape(n, len(cols))
            if n:
                data = data[np.argsort(data[:, cols.index("id")])]
            frames.append((step, cols, data))
            i = j + 1 + n
        else:
            i += 1
    return frames


def thermo_blocks(log_text):
    """Thermo tables of a LIGGGHTS log: list of (header, rows as strings)."""
    blocks = []
    lines = log_text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].strip().startswith("Step ") or lines[i].strip() == "Step":
            header = lines[i].split()
            rows = []
            i += 1
            while i < len(lines) and not lines[i].startswith("Loop time"):
                parts = lines[i].split()
                if parts and re.match(r"^-?\d+$", parts[0]) and len(parts) == len(header):
                    rows.append(lines[i].strip())
                i += 1
            blocks.append((header, rows))
        i += 1
    return blocks


def max_rel_diff(a, b, floor=1e-300):
    """max |a-b| / max(|a|,|b|), elementwise, with zero where both are zero."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    den = np.maximum(np.maximum(np.abs(a), np.abs(b)), floor)
    d = np.abs(a - b) / den
    d[(a == b)] = 0.0
    return float(d.max()) if d.size else 0.0


class Checks:
    """Collects named assertions, prints them, exits non-zero if any failed."""

    def __init__(self):
        self.failed = []

    def check(self, ok, what):
        print(("PASS " if ok else "FAIL ") + what, flush=True)
        if not ok:
            self.failed.append(what)

    def done(self):
        if self.failed:
            print("%d check(s) failed" % len(self.failed))
            sys.exit(1)
        print("all checks passed")
