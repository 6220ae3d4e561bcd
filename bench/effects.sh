#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Effect-selective cost (issue 8): one settled bed per engine (LAMMPS: 3564 spheres of 4.0/4.8 mm,
# LIGGGHTS: 3000 spheres of 4/5 mm) run with the normal law only, + tangential (Cundall-Strack),
# + rolling resistance (LIGGGHTS), + clumps (LAMMPS fix tdem/clump, one-sphere bodies), + grate
# (fix tdem/grate standing and moving instead of the flat floor), and with the stock law of equal
# physics; instructions counted with callgrind (200 steps, set-up excluded). With OFF_BUILD_DIR
# (a build configured with every module OFF: -DTDEM_{LAMMPS,LIGGGHTS}_{GRATE,MIXING,TIMESTEP,CLUMP}=OFF)
# the normal-only and tangential variants also run with its executables: compiled-in but unused
# modules must not change the pair-loop instruction count (|difference| <= 0.5 %).
# Writes bench/results/effects.md; about 10 minutes on the 2-core machine (valgrind).
# usage: bash bench/effects.sh [BUILD_DIR] [OFF_BUILD_DIR]   (extra options: EFFECTS_ARGS="--wallclock ...")
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
OFF=${2:-}
command -v valgrind > /dev/null || { echo "effects.sh: valgrind not found (apt-get install valgrind)" >&2; exit 1; }
ARGS=(--out "$ROOT/bench/results/effects.md" --settle 10000)
[ -n "$OFF" ] && ARGS+=(--off "$OFF")
# shellcheck disable=SC2086
exec /usr/bin/python3 "$ROOT/bench/effects/effects.py" "$BUILD" "${ARGS[@]}" ${EFFECTS_ARGS:-}
