#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Runs the DEM verification suite (dem_suite.py) in every built engine: LIGGGHTS and each LAMMPS
# version found in build/bin, with the stock styles in each engine's own stock executable, and
# writes validation/dem_suite/results.md (one table row per case, law, engine and rank count).
#
#   validation/dem_suite/run.sh [build directory]      (default: build)
#
# Stock executables: /usr/bin/liggghts, /usr/bin/lmp (the Debian LAMMPS), and
# /var/cache/tdem/lammps-<date>/bin/lmp for the LAMMPS versions built from source.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
case $build in /*) ;; *) build="$(pwd)/$build" ;; esac
py=/usr/bin/python3
out="$here/results.md"
work=$(mktemp -d /tmp/tdem_dem_suite.XXXXXX)
rows="$work/rows.md"
: > "$rows"
status=0
run() {  # label host exe stock version
  [ -x "$3" ] || { echo "dem_suite: $3 not built, skipped"; return; }
  echo "== $1 ($3)"
  "$py" "$here/dem_suite.py" --host "$2" --exe "$3" --stock "$4" --version "$5" --mpirun "$(command -v mpirun)" \
    --workdir "$work/$1" --table "$rows" --label "$1" || status=1
  progress_done "$1"
}
started=$(date +%s)
. "$root/tools/progress.sh"
progress_init "LIGGGHTS-3.8:1 LAMMPS-2022:1 LAMMPS-4Feb2025:1 LAMMPS-4Jul2026:1"
run LIGGGHTS-3.8 liggghts "$build/bin/tdem-liggghts" /usr/bin/liggghts 3.8
run LAMMPS-2022 lammps "$build/bin/tdem-lammps" /usr/bin/lmp 29Sep2021
run LAMMPS-4Feb2025 lammps "$build/bin/tdem-lammps-4Feb2025" /var/cache/tdem/lammps-20250204/bin/lmp 4Feb2025
run LAMMPS-4Jul2026 lammps "$build/bin/tdem-lammps-4Jul2026" /var/cache/tdem/lammps-20260704/bin/lmp 4Jul2026
{
  echo "# DEM verification suite: results"
  echo
  echo "Written by \`validation/dem_suite/run.sh\` on $(date -u +%Y-%m-%d) in $(( $(date +%s) - started )) s:"
  echo "$(grep -c '| pass |' "$rows") runs passed, $(grep -c '| FAIL |' "$rows") failed," \
       "$(grep -c '| skip |' "$rows") laws not available in an engine (README.md)."
  echo
  echo "| case | check | engine | tdem law | ranks | error | tolerance | result | values (reference in parentheses); 2 ranks vs 1; stock |"
  echo "|---|---|---|---|---|---|---|---|---|"
  cat "$rows"
} > "$out"
echo "wrote $out"
rm -rf "$work"
exit $status
