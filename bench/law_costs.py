#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Cost of every tdem normal law against the stock LAMMPS law it replaces, measured in one run.

Scene: the LAMMPS benchmark bench/in.chute (32000 spheres, frozen rough base, 26 degree chute, lj
units, dt = 1e-4; data.chute from the Debian LAMMPS source package that tools/setup.sh fetches),
every law with tangential Cundall-Strack (mu = 0.5), fix nve/sphere, 1 rank.

Arms (the law lines as bench/lammps/bench_laws.sh):
  stock_hooke   gran/hooke/history 2e5 NULL 50 NULL 0.5 0          reference of the linear laws
  stock_hertz   gran/hertz/history 2e5 NULL 50 NULL 0.5 0          reference of the Hertz-type laws
  control       gran/hooke/history again: the A/A control (its ratio to stock_hooke is the noise)
  lsd (stiffness 2e5 50: stock_hooke's physics), lsd_restitution, walton_braun, power_law,
  extended_linear (-> stock_hooke); hertz_kk (kuwabara_kono: stock_hertz's physics for mobile
  pairs), hertz_tsuji, thornton, extended_hertz (-> stock_hertz)
Method: ROUNDS rounds; a round is one tdem-lammps process that runs every arm twice, in a
palindromic order (A B C ... C B A, the start rotated each round), so a linear drift of the machine
cancels. Each arm runs WARM untimed steps first (the scene is perf.py's). Per run the CPU time of the timed loop (LAMMPS "Loop time" x "% CPU"); per round the cost
ratio law/reference = (t1 + t2)_law / (t1 + t2)_reference. The table gives the median over the rounds
and the range; the control row is the noise floor (a ratio inside the control's spread is not a
difference). contacts/particle: at the end of each arm's runs (laws that change the flow change it).

usage: bench/law_costs.py [--build DIR] [--steps S] [--warm W] [--rounds R] [--out FILE]
Prints a progress line per round with the remaining time, then the Markdown table (also to --out).
"""
import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import perf  # noqa: E402  (the chute scene and the LAMMPS source tree)
KT = 200000.0 * 2.0 / 7.0
GKK = math.pi / 12.0 * 50.0 * 0.5  # G = m* gamma_n sqrt(R*), m* = (pi/6)/2, R* = 1/4
TS = "tangential cundall_strack 0.8 0.5"


def tdem(normal):
    return "pair_style tdem/gran\npair_coeff * * %s %s" % (normal, TS)


ARMS = [
    ("stock_hooke", None, "pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *"),
    ("stock_hertz", None, "pair_style gran/hertz/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *"),
    ("control", "stock_hooke", "pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *"),
    ("lsd", "stock_hooke", "pair_style tdem/gran\npair_coeff * * normal lsd stiffness 200000.0 50.0 "
                           "tangential cundall_strack %r 0.0 0.5" % KT),
    ("lsd_restitution", "stock_hooke", tdem("normal lsd restitution 0.7 3.6e-3")),
    ("walton_braun", "stock_hooke", tdem("normal walton_braun 2e5 4.08e5")),
    ("power_law", "stock_hooke", tdem("normal power_law 1e5 1.5 2.915e5")),
    ("extended_linear", "stock_hooke", tdem("normal extended_linear e_fit rational 1 1 0.2 tc_fit power 3.6e-3 0.2")),
    ("hertz_kk", "stock_hertz", tdem("normal hertz 3e5 0 damping kuwabara_kono %r" % GKK)),
    ("hertz_tsuji", "stock_hertz", tdem("normal hertz 3e5 0 damping tsuji 0.7")),
    ("thornton", "stock_hertz", tdem("normal thornton 3e5 0 3000")),
    ("extended_hertz", "stock_hertz", tdem("normal extended_hertz 3e5 0 e_fit rational 1 1 0.2")),
]

def arm_input(name, inter, steps, warm):
    """One arm: the chute scene of perf.py (WARM untimed steps, then STEPS timed steps without set-up),
    marked for parse() and followed by `clear`, so that all arms run in one process."""
    return 'print "arm %s"\n' % name + perf.scene_input("chute", "lammps", inter, steps, warm, "data.chute") + "clear\n"


def data_chute():
    path = os.path.join(perf.lammps_source(), "bench", "data.chute")
    if not os.path.isfile(path):
        raise SystemExit("law_costs: no data.chute (run tools/setup.sh, or set TDEM_LAMMPS_SOURCE)")
    return path


def parse(out):
    """{arm: [(cpu seconds, contacts/particle), ...]} of one round's output: per arm the second of its
    three runs (warm-up, timed, run 0), and the contacts per particle at the end of the timed run."""
    res, arm, k, nc = {}, None, 0, float("nan")
    lines = out.splitlines()
    for i, l in enumerate(lines):
        w = l.split()
        if l.startswith("arm "):
            arm, k = w[1], 0
        elif w[:1] == ["Step"] and "c_snc" in w:
            last = lines[i + 1].split() if i + 1 < len(lines) else []
            j = i + 1
            while j < len(lines) and not lines[j].startswith("Loop time of"):
                if lines[j].split():
                    last = lines[j].split()
                j += 1
            try:
                nc = float(last[w.index("c_snc")]) / float(last[w.index("Atoms")])
            except (ValueError, IndexError):
                nc = float("nan")
        elif l.startswith("Loop time of"):
            k += 1
            if k != 2:
                continue
            wall = float(w[3])
            cpu_line = lines[i + 1] if i + 1 < len(lines) else ""
            pct = float(cpu_line.split("%")[0]) if "% CPU" in cpu_line else 100.0
            res.setdefault(arm, []).append((wall * pct / 100.0, nc))
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--steps", type=int, default=500)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--warm", type=int, default=50)
    ap.add_argument("--out", default="")
    a = ap.parse_args()
    exe = os.path.join(a.build, "bin", "tdem-lammps")
    if not os.access(exe, os.X_OK):
        raise SystemExit("law_costs: %s not built" % exe)
    work = tempfile.mkdtemp(prefix="tdem_law_costs_")
    os.symlink(data_chute(), os.path.join(work, "data.chute"))
    names = [n for n, _, _ in ARMS]
    inter = {n: t for n, _, t in ARMS}
    ref = {n: r for n, r, _ in ARMS}
    rounds, t0 = [], time.time()
    print("law costs: %d arms x 2 runs x %d rounds x %d steps, 32000 spheres (in.chute), 1 rank"
          % (len(names), a.rounds, a.steps), flush=True)
    for r in range(a.rounds):
        k = (r * 5) % len(names)
        order = names[k:] + names[:k]
        order = order + order[::-1]
        text = "".join(arm_input(n, inter[n], a.steps, a.warm) for n in order)
        with open(os.path.join(work, "in.round"), "w") as f:
            f.write(text)
        p = subprocess.run([exe, "-in", "in.round", "-log", "none", "-echo", "none"], cwd=work,
                           capture_output=True, text=True)
        if p.returncode != 0:
            sys.stderr.write(p.stdout[-3000:] + p.stderr[-2000:])
            raise SystemExit("law_costs: round %d failed" % (r + 1))
        rounds.append(parse(p.stdout))
        el = time.time() - t0
        print("  round %d/%d done, %.0f s elapsed, about %.0f s to go"
              % (r + 1, a.rounds, el, el / (r + 1) * (a.rounds - r - 1)), flush=True)
    lines = ["| law | reference | cost / reference (median of %d rounds) | range | contacts/particle |" % a.rounds,
             "|---|---|---|---|---|"]
    for n in names:
        if ref[n] is None:
            nc = statistics.median([x[1] for rr in rounds for x in rr[n]])
            lines.append("| %s | - | 1 | - | %.3g |" % (n, nc))
            continue
        ratios = [sum(x[0] for x in rr[n]) / sum(x[0] for x in rr[ref[n]]) for rr in rounds]
        nc = statistics.median([x[1] for rr in rounds for x in rr[n]])
        lines.append("| %s | %s | %.3f | %.3f - %.3f | %.3g |" % (n, ref[n], statistics.median(ratios), min(ratios),
                                                                 max(ratios), nc))
    table = "\n".join(lines)
    print(table)
    ctrl = [sum(x[0] for x in rr["control"]) / sum(x[0] for x in rr["stock_hooke"]) for rr in rounds]
    print("A/A control (stock_hooke again / stock_hooke): median %.3f, range %.3f - %.3f: differences inside "
          "this spread are not resolved." % (statistics.median(ctrl), min(ctrl), max(ctrl)))
    if a.out:
        with open(a.out, "w") as f:
            f.write("# Cost of the tdem normal laws against the stock LAMMPS laws (bench/law_costs.py)\n\n")
            f.write("Measured %s, %d rounds x %d steps, CPU time of the timed loop.\n\n"
                    % (time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), a.rounds, a.steps) + table + "\n")
    subprocess.run(["rm", "-rf", work])


if __name__ == "__main__":
    main()
