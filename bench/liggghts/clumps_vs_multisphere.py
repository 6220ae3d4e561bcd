#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/clump against the stock LIGGGHTS fix multisphere in the same scene (issue 6).

Runs input_scripts/liggghts/clumps_vs_multisphere.in (400 tetra-sphere clumps, r = 2 mm, edge 3 mm,
density 2500, poured for 10000 steps into a 6 x 6 x 12 cm box, stock hertz + history for spheres and
walls; on 1 rank - bench/clumps_scaling.py compares both fixes at 1 and 2 ranks) with -var stock 0 (fix
tdem/clump) and -var stock 1 (fix multisphere), interleaved (T S S T T S ...), and reports
 * speed: the loop time LIGGGHTS prints (whole pour, insertion excluded), median over the rounds, and
   the ratio stock/tdem per round (> 1: tdem faster);
 * physics of the same scene, statistically (the two fixes place their bodies with their own random
   insertion): mass per clump (tdem: union by column integration; multisphere: Monte Carlo), mean
   and highest sphere centre at the end, kinetic energy at the end.
Writes bench/results/clumps_vs_multisphere.md.

usage: bench/liggghts/clumps_vs_multisphere.py [--exe build/bin/tdem-liggghts] [--rounds 3]
       [--n 400] [--steps 10000]
"""
import argparse
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "tools"))
from progress import Progress  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPTS = os.path.join(ROOT, "input_scripts", "liggghts")
FILES = ("clumps_vs_multisphere.in", "clumps_vs_multisphere_tdem.inc", "clumps_vs_multisphere_stock.inc")


def run_one(exe, wd, stock, n, steps):
    r = subprocess.run([exe, "-in", "in.case", "-log", "none", "-var", "stock", str(stock), "-var", "n", str(n),
                        "-var", "steps", str(steps)], cwd=wd, capture_output=True, text=True, errors="replace")
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:] + r.stderr[-2000:])
        raise SystemExit("clumps_vs_multisphere.py: run with stock %d failed" % stock)
    out = r.stdout
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+) on", out).group(1))
    if stock:
        m = re.search(r"inserted (\d+) particle templates \(mass ([0-9.eE+-]+)\)", out)
        nb, mass = int(m.group(1)), float(m.group(2)) / int(m.group(1))
    else:
        mass = float(re.search(r"template tetra \(4 spheres\): mass ([0-9.eE+-]+)", out).group(1))
        nb = n
    thermo = [l.split() for l in out.splitlines()
              if re.match(r"^\s*%d\s+\d+\s+\S+\s*$" % steps, l)]
    ke = float(thermo[-1][2])
    z = []
    with open(os.path.join(wd, "final.dump")) as f:
        lines = f.read().splitlines()
    k = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    z = [float(l.split()[1]) for l in lines[k + 1:] if l.strip()]
    return dict(loop=loop, bodies=nb, mass=mass, ke=ke, zmean=statistics.mean(z), zmax=max(z), spheres=len(z))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(ROOT, "build", "bin", "tdem-liggghts"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--steps", type=int, default=10000)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "clumps_vs_multisphere.md"))
    a = ap.parse_args()
    if a.rounds < 1:
        raise SystemExit("clumps_vs_multisphere.py: --rounds %d; allowed: 1 or more" % a.rounds)
    exe = os.path.abspath(a.exe)
    if not os.access(exe, os.X_OK):
        raise SystemExit("clumps_vs_multisphere.py: no executable %s (build first)" % exe)
    wd = tempfile.mkdtemp(prefix="tdem_cvm_")
    try:
        for f in FILES:
            shutil.copy(os.path.join(SCRIPTS, f), wd)
        text = open(os.path.join(wd, FILES[0])).read()
        marker = "run             ${steps}"
        if marker not in text:
            raise SystemExit("clumps_vs_multisphere.py: the run line of %s moved" % FILES[0])
        text = text.replace(marker, "dump            fin all custom ${steps} final.dump id z\n" + marker)
        with open(os.path.join(wd, "in.case"), "w") as f:
            f.write(text)
        res = {0: [], 1: []}
        t0 = time.time()
        prog = Progress(n=4 * a.rounds, label="runs")
        for rnd in range(a.rounds):
            for stock in ((0, 1, 1, 0) if rnd % 2 == 0 else (1, 0, 0, 1)):
                res[stock].append(run_one(exe, wd, stock, a.n, a.steps))
                prog.done("round %d %s" % (rnd + 1, "multisphere" if stock else "tdem/clump"))
        wall = time.time() - t0
    finally:
        shutil.rmtree(wd, ignore_errors=True)
    # per round: (stock loops) / (tdem loops)
    ratios = []
    for rnd in range(a.rounds):
        ts = res[0][2 * rnd]["loop"] + res[0][2 * rnd + 1]["loop"]
        ss = res[1][2 * rnd]["loop"] + res[1][2 * rnd + 1]["loop"]
        ratios.append(ss / ts)
    med = {s: statistics.median(r["loop"] for r in res[s]) for s in (0, 1)}
    last = {s: res[s][-1] for s in (0, 1)}
    rows = []
    for s, name in ((0, "`fix tdem/clump` (splitting)"), (1, "stock `fix multisphere`")):
        r = last[s]
        rows.append("| %s | %s | %.3g | %.6e | %.5f | %.5f | %.3e | %d |" % (
            name, " / ".join("%.2f" % x["loop"] for x in res[s]), r["spheres"] * a.steps / med[s], r["mass"],
            r["zmean"], r["zmax"], r["ke"], r["bodies"]))
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    md = ["# fix tdem/clump vs stock fix multisphere (LIGGGHTS), same scene", "",
          "Generated by `bench/liggghts/clumps_vs_multisphere.py` on %s UTC, %s, %d cores, load average %s; "
          "executable %s." % (time.strftime("%Y-%m-%d %H:%M", time.gmtime()), cpu, os.cpu_count(),
                              " ".join("%.2f" % x for x in os.getloadavg()), exe), "",
          "Scene: `input_scripts/liggghts/clumps_vs_multisphere.in`, %d tetra-sphere clumps (4 spheres r = 2 mm, "
          "edge 3 mm, density 2500), poured for %d steps of 1e-5 s, stock `hertz` + `history` for spheres and "
          "walls, 1 rank (1 and 2 ranks: bench/clumps_scaling.py). Interleaved runs (tdem, stock, stock, tdem, then mirrored), "
          "%d rounds, %.0f s in all." % (a.n, a.steps, a.rounds, wall), "",
          "| fix | loop time per run (s) | sphere-steps/s (median) | mass per clump (kg) | mean sphere z (m) | "
          "highest sphere z (m) | kinetic energy (J) | clumps |", "|---|---|---|---|---|---|---|---|"] + rows + [
          "", "Speed ratio stock/tdem loop time per round (> 1: tdem faster): %s; median **%.3f**." % (
              ", ".join("%.3f" % r for r in ratios), statistics.median(ratios)), "",
          "Positions, energy and mass are from the last run of each fix. The bodies are not the same (each fix "
          "inserts with its own random placement), so the pour agrees statistically only. The mass per clump is "
          "the union of the four spheres in both (tdem: column integration; multisphere: Monte Carlo). The "
          "granular styles see the body mass as m* with `fix multisphere` and the sphere's share with `fix "
          "tdem/clump` in LIGGGHTS (docs/liggghts/fix_tdem_clump.md), so the Hertz damping differs."]
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
