#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Oblique sphere-wall impacts (Kharaz, Gorham & Salman 2001 set-up) over impact angles 0-85 deg for
# every tangential law of tdem-collide; plots and the regime/error table in results/ (README.md).
#
#   validation/tangential/run.sh [path/to/tdem-collide]
#
# tdem-collide is taken from the argument, else $TDEM_COLLIDE, else build/bin/tdem-collide.
# Environment: STEP (angle step in deg, default 1), JOBS (parallel runs, default 2).
# Exit status: 0 all consistency checks passed, 1 a check failed (listed at the end of
# results/table.md), 2 bad set-up.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
collide=${1:-${TDEM_COLLIDE:-$root/build/bin/tdem-collide}}
case $collide in /*) ;; *) collide="$(pwd)/$collide" ;; esac
py=/usr/bin/python3
if [ ! -x "$collide" ]; then
  echo "run.sh: tdem-collide not found at '$collide' (build it: cmake --build build --target tdem-collide)" >&2
  exit 2
fi
results="$here/results"
mkdir -p "$results"
rm -f "$results"/*.png "$results"/table.md "$results"/cases.md "$results"/sweep_harness.csv
status=0
cd "$here" || exit 2

# 1. The harness: every case of sweep.py (normal law x tangential law) at every angle.
echo "sweeping the impact angle with $collide ..."
"$py" sweep.py "$collide" results/sweep_harness.csv --step "${STEP:-1}" --jobs "${JOBS:-2}" \
  --cases-md results/cases.md || exit 2

# 2. HOST HOOK (not wired yet: the host adapters of the tangential laws are being written).
#    A host driver runs the same cases (sweep.configs() gives the normal and tangential
#    parameters; sweep.py's constants the bodies and speed) as one sphere hitting a wall in
#    tdem-liggghts / tdem-lammps, and writes
#        results/sweep_liggghts.csv   results/sweep_lammps.csv
#    with the columns of sweep.COLUMNS (at least case, angle_deg, psi1, beta, e_t, spin_after,
#    rebound_angle_com, rebound_angle_contact; same case ids, same spin sign convention
#    v_s = v_t + R omega). plot.py then draws the host points over the harness curves and
#    adds the table "Host runs" (max |beta_host - beta_harness| etc.; the issue asks for 1e-4).
#    Put the call here, e.g.:
#        [ -x "$lig" ] && "$py" hosts.py liggghts "$lig" results/sweep_liggghts.csv || status=1
#        [ -x "$lmp" ] && "$py" hosts.py lammps "$lmp" results/sweep_lammps.csv || status=1
#    Stale host files are removed here so that an old host run is never compared silently.
bindir=$(dirname "$collide")
lig=${TDEM_LIGGGHTS:-$bindir/tdem-liggghts}
lmp=${TDEM_LAMMPS:-$bindir/tdem-lammps}
if [ -f "$here/hosts.py" ]; then
  rm -f results/sweep_liggghts.csv results/sweep_lammps.csv
  [ -x "$lig" ] && { "$py" hosts.py liggghts "$lig" results/sweep_liggghts.csv || status=1; }
  [ -x "$lmp" ] && { "$py" hosts.py lammps "$lmp" results/sweep_lammps.csv || status=1; }
else
  echo "(no hosts.py yet: harness only; see the HOST HOOK in run.sh)"
fi

# 3. Plots and table.
"$py" plot.py results || status=1
echo "results in $results (table.md, cases.md, beta_vs_psi1.png, rebound_angle.png, spin.png, e_t.png, sweep_*.csv)"
exit $status
