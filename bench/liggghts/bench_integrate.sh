#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of every scheme of `fix tdem/integrate` against `fix nve/sphere` in LIGGGHTS, one rank.
#
# Scene: the settled bed of bench_bed.sh (NATOMS spheres of two types, six primitive walls,
# gravity; pair gran and wall/gran model tdem/lsd tangential tdem/cundall_strack, stiffness
# parameters), inserted and settled ONCE (dt 2e-5 s, about 25 steps per contact), saved with
# write_data. Every integrator then starts from that bed (read_data) with the time step DT
# (default 2.5e-6 s): 200 untimed steps, STEPS timed steps; time = LIGGGHTS "Loop time" of the
# timed run, one run per integrator (as asked by issue 5). DT is 8 x below the settling step so
# that every scheme keeps the bed settled and the runs do the same force work: at 2e-5 s
# explicit Euler (stable for a damped contact only below 2 delta / omega^2, here ~5e-6 s)
# makes the bed explode, and taylor2 and ab5 make it boil (a third of the contacts). The table
# shows the contacts per particle of every run next to nve/sphere's. The ratio is loop time /
# loop time of nve/sphere (a whole step: pair forces, walls, neighbour lists and integration; the
# fixes (integrator, gravity, walls) are in the "Other" part of LIGGGHTS's timing breakdown,
# printed too).
# history_doubles: Kernel<S, true>::history + Kernel<S, false>::history (the scheme's own
# per-atom history with rotation); the fix stores 7 more doubles per atom (started flag, the
# last translational and angular acceleration), as it prints in the log.
#
# Writes validation/integrators/results/cost_liggghts.csv (scheme,ratio_to_nve_sphere,
# history_doubles) and prints a table. Not part of ctest.
# Usage: [KEEP=1] [DT=2.5e-6] bench_integrate.sh [tdem-liggghts] [steps] [natoms] [settle]
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
EXE=${1:-$HERE/../../build/bin/tdem-liggghts}
STEPS=${2:-5000}
NATOMS=${3:-4000}
SETTLE=${4:-15000}
DT=${DT:-0.0000025}
REPEATS=1
CG_STEPS=0
OUT=$HERE/../../validation/integrators/results/cost_liggghts.csv
WORK=$(mktemp -d /tmp/tdem_bench_integrate.XXXXXX)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT
SCHEMES="euler symplectic_euler taylor2 taylor3 leapfrog position_verlet velocity_verlet velocity_verlet_sync
beeman ab2 ab3 ab4 ab5 abm4 gear4 gear5 gear6"

MU="fix m_mu all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4"
STIFF="fix m_kn all property/global kn peratomtypepair 2 6000 5500 5500 5000;fix m_kt all property/global kt peratomtypepair 2 1800 1700 1700 1600;fix m_gn all property/global gamman peratomtypepair 2 300 280 280 260;fix m_gt all property/global gammat peratomtypepair 2 120 110 110 100"
echo "bed|model tdem/lsd tangential tdem/cundall_strack|$STIFF;$MU" > "$WORK/laws"
. "$HERE/bench_bed.sh"

other_time() { grep '^Other time' "$1" | tail -1 | awk '{print $5}'; }
# A scheme that is unstable at this time step (explicit Euler gains energy in every contact) makes
# the bed explode: the neighbour lists grow without bound and the run never ends. Such a run is
# stopped after LIMIT seconds (default 10 x the nve/sphere run, at least 30 s) and reported as
# "unstable".
run_one() { # $1 name, $2 integrator fix arguments
  sed -e "s|^fix integr all nve/sphere\$|fix integr all $2|" -e "s|^timestep 0.00002\$|timestep $DT|" \
    "$WORK/in.bed" > "$WORK/in.$1"
  if (cd "$WORK" && timeout -s KILL "${LIMIT:-600}" "$EXE" -in "in.$1" -log "log.$1" -echo none -screen /dev/null); then
    echo "$1 $(loop_time "$WORK/log.$1") $(other_time "$WORK/log.$1") $(contacts "$WORK/log.$1")" >> "$WORK/times"
  else
    echo "$1 unstable unstable -" >> "$WORK/times"
  fi
}
: > "$WORK/times"
. "$HERE/../../tools/progress.sh"
_st="nve_sphere:1"
for s in $SCHEMES; do _st="$_st $s:1"; done
progress_init "$_st"
run_one nve_sphere nve/sphere
progress_done nve_sphere
if [ -z "${LIMIT:-}" ]; then
  LIMIT=$(awk '$1 == "nve_sphere" {l = int(10 * $2) + 1; print (l < 30 ? 30 : l)}' "$WORK/times")
fi
for s in $SCHEMES; do
  run_one "$s" "tdem/integrate scheme $s"
  progress_done "$s"
done

# ------------------------------------------------------------------ the integrator alone
# 3840 spheres on a simple cubic lattice in free fall (no contact, gravity only), FREE_STEPS
# steps: LIGGGHTS's "Other" time (the fixes: this integrator and fix gravity) per particle-step.
FREE_STEPS=${FREE_STEPS:-10000}
cat > "$WORK/in.free" <<EOI
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block 0 0.16 0 0.16 0 0.16 units box
create_box 1 box
lattice sc 0.01
create_atoms 1 box
set group all diameter 0.004 density 2500
set group all vz -0.1
neighbor 0.001 bin
neigh_modify delay 0
fix m_kn all property/global kn peratomtypepair 1 6000
fix m_kt all property/global kt peratomtypepair 1 1800
fix m_gn all property/global gamman peratomtypepair 1 300
fix m_gt all property/global gammat peratomtypepair 1 120
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model tdem/lsd tangential tdem/cundall_strack
pair_coeff * *
timestep 1e-6
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix integr all \${integ}
thermo 100000
run $FREE_STEPS
EOI
free_ns() { # $1 name, $2 integrator -> ns per particle-step in the fixes
  (cd "$WORK" && "$EXE" -in in.free -var integ "$2" -log "free.$1" -echo none -screen /dev/null)
  awk '/^Other time/ {o = $5} /^Loop time/ {n = $9; na = $12} END {printf "%.1f", o / (n * na) * 1e9}' "$WORK/free.$1"
}
echo "nve_sphere $(free_ns nve_sphere nve/sphere)" > "$WORK/free"
for s in $SCHEMES; do
  echo "$s $(free_ns "$s" "tdem/integrate scheme $s")" >> "$WORK/free"
done

echo "scheme,ratio_to_nve_sphere,history_doubles" > "$OUT"
printf '%-22s %10s %10s %9s %9s %9s %8s %6s %s\n' scheme loop_s other_s ratio oth_ratio contacts free_ns hist bytes_per_atom
base=$(awk '$1 == "nve_sphere" {print $2}' "$WORK/times")
bmod=$(awk '$1 == "nve_sphere" {print $3}' "$WORK/times")
bcon=$(awk '$1 == "nve_sphere" {print $4}' "$WORK/times")
printf '%-22s %10s %10s %9s %9s %9s %8s %6s %s\n' nve/sphere "$base" "$bmod" 1.000 1.000 "$bcon" \
  "$(awk '$1 == "nve_sphere" {print $2}' "$WORK/free")" 0 0
for s in $SCHEMES; do
  t=$(awk -v s="$s" '$1 == s {print $2}' "$WORK/times")
  m=$(awk -v s="$s" '$1 == s {print $3}' "$WORK/times")
  con=$(awk -v s="$s" '$1 == s {print $4}' "$WORK/times")
  line=$(grep -h "tdem/integrate: scheme $s," "$WORK/log.$s" | head -1 || true)
  hist=$(echo "$line" | sed -n 's/.*rotation [a-z]*: \([0-9]*\) history doubles.*/\1/p')
  bytes=$(echo "$line" | sed -n 's/.*doubles (\([0-9]*\) bytes) per atom.*/\1/p')
  if [ "$t" = unstable ]; then
    ratio=nan; mratio=unstable
  else
    ratio=$(awk -v a="$t" -v b="$base" 'BEGIN {printf "%.3f", a / b}')
    mratio=$(awk -v a="$m" -v b="$bmod" 'BEGIN {printf "%.3f", a / b}')
  fi
  fns=$(awk -v s="$s" '$1 == s {print $2}' "$WORK/free")
  printf '%-22s %10s %10s %9s %9s %9s %8s %6s %s\n' "$s" "$t" "$m" "$ratio" "$mratio" "$con" "$fns" "$hist" "$bytes"
  echo "$s,$ratio,$hist" >> "$OUT"
done
echo "($NATOMS spheres, $STEPS timed steps of $DT s, one run each, 1 rank; ratio = loop time / nve/sphere"
echo " (nan: the run did not end within $LIMIT s, the scheme is unstable at this step);"
echo " contacts = mean contacts per particle over the timed run;"
echo " free_ns = the fixes (integrator + gravity) per particle-step, 3840 spheres in free fall, $FREE_STEPS steps;"
echo " oth_ratio = LIGGGHTS 'Other' time (the fixes: integrator, gravity, walls) / nve/sphere's;"
echo " bytes_per_atom = what the fix stores per atom; written $OUT)"
