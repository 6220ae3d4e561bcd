#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Integrator study (issue 5): every time-integration scheme of the single-collision harness
# (src/collision/integrate_impact.h: the 18 one-evaluation schemes of src/integrators/schemes.h and
# heun, rk4, vv2, abm4_pece; the one-evaluation ones also with the time-grid correction of
# src/contact/grid_correction.h, issue 22) on a sphere-wall impact from free flight, phase-averaged
# errors of e, beta, e_t, spin, contact time and rebound angles against the closed form
# (src/collision/analytic.h), N = 5 ... 500 steps per contact; observed orders, memory, cost per
# contact (with the host cost ratios of results/cost_lammps.csv / results/cost_liggghts.csv where
# present), Pareto plot, the correction's plot and table.
#
#   validation/integrators/run.sh            (about a minute)
#
# Writes results/errors.csv, results/table.md, results/errors_vs_N.png, results/pareto.png,
# results/grid_correction.png.
# Environment: CXX (default c++), PHASES (start phases per point, default 16).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
results="$here/results"
mkdir -p "$results"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$root/tools/progress.sh"
progress_init "compile:1 study:2 analyse:1"
echo "compiling the study driver (header-only core from $root/src) ..."
${CXX:-c++} -O2 -std=c++17 -I"$root/src" "$here/study.cpp" -o "$tmp/study"
progress_done compile
echo "running $(( (22 + 18) * 6 * 9 * 5 )) phase averages of ${PHASES:-16} impacts ..."
"$tmp/study" "${PHASES:-16}" > "$tmp/errors.csv"
mv "$tmp/errors.csv" "$results/errors.csv"
progress_done study
/usr/bin/python3 "$here/analyse.py" > /dev/null
progress_done analyse
echo "wrote $results/errors.csv, table.md, errors_vs_N.png, pareto.png, grid_correction.png"
