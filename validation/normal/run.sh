#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Fits every tdem normal law to every data file in validation/normal/data/ with tdem-fit and
# writes the plots and the table to validation/normal/results/ (see README.md).
#
#   validation/normal/run.sh [path/to/tdem-fit]
#
# tdem-fit is taken from the argument, else $TDEM_FIT, else build/bin/tdem-fit.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
fit=${1:-${TDEM_FIT:-$root/build/bin/tdem-fit}}
case $fit in /*) ;; *) fit="$(pwd)/$fit" ;; esac
py=/usr/bin/python3
if [ ! -x "$fit" ]; then
  echo "run.sh: tdem-fit not found at '$fit' (build it: cmake --build build --target tdem-fit)" >&2
  exit 2
fi
results="$here/results"
mkdir -p "$results"
rm -f "$results"/*.json "$results"/*.txt "$results"/*.png "$results"/table.md "$results"/hosts.md
status=0
found=0
cd "$here" || exit 2
. "$root/tools/progress.sh"
stages=""
for f in data/*.csv; do [ -e "$f" ] && stages="$stages $(basename "$f" .csv):4"; done
progress_init "$stages plots:1 hosts:2"
for f in data/*.csv; do
  [ -e "$f" ] || continue
  found=1
  stem=$(basename "$f" .csv)
  echo "fitting $stem ..."
  # --curve: every fitted law is also evaluated (integrated) at 60 impact velocities for the plots
  "$fit" "$f" --json "results/$stem.json" --curve 60 > "results/$stem.txt"
  rc=$?
  if [ $rc -ne 0 ]; then
    echo "run.sh: tdem-fit exited with $rc for $f (see $results/$stem.txt)" >&2
    status=1
  fi
  sed -n '/^summary/,$p' "results/$stem.txt"
  progress_done "$stem"
done
if [ $found -eq 0 ]; then
  echo "run.sh: no data files in $here/data" >&2
  exit 2
fi
"$py" plot.py results || status=1
progress_done plots
# The printed input lines in the hosts, where the host executables are built next to tdem-fit
# (or given as $TDEM_LIGGGHTS / $TDEM_LAMMPS).
bindir=$(dirname "$fit")
lig=${TDEM_LIGGGHTS:-$bindir/tdem-liggghts}
lmp=${TDEM_LAMMPS:-$bindir/tdem-lammps}
hostargs=""
[ -x "$lig" ] && hostargs="$hostargs --liggghts $lig"
[ -x "$lmp" ] && hostargs="$hostargs --lammps $lmp"
if [ -n "$hostargs" ]; then
  echo "running the printed input lines in the hosts ..."
  # shellcheck disable=SC2086
  "$py" check_hosts.py results $hostargs || status=1
  progress_done hosts
else
  echo "(no tdem-liggghts / tdem-lammps next to tdem-fit: results/hosts.md not written)"
fi
echo "results in $results (table.md, hosts.md, *_e.png, *_tc.png, *.txt, *.json)"
exit $status
