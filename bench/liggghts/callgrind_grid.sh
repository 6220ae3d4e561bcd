#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Pair-loop instructions of `grid_correction on` against off in LIGGGHTS (issue 22), and of off
# against another build (BASE: e.g. the build before tdem's contact model replaced LIGGGHTS's
# ContactModel, to show that the off path costs nothing).
#
# Scene: NATOMS spheres (two types) inserted with random velocities into the box of
# bench_bed.sh, falling and colliding for PRE steps (stock hooke/stiffness), written with
# write_data: a bed that is still forming, where contacts start and end all the time (the
# correction's events). Every case then runs CG_STEPS steps from that state under callgrind,
# collecting only inside the pair style's compute_force (walls excluded), with
# `tangential tdem/cundall_strack` and fix nve/sphere. Instruction counts are deterministic: no
# repetition is needed. The number of contact starts in the window is printed too (compute
# contact/atom before and after is not enough; the count is the number of touching pairs per step,
# averaged).
#
# Not part of ctest. Usage:
#   [BASE=/path/to/old/tdem-liggghts] [LAWS="lsd hertz"] callgrind_grid.sh [tdem-liggghts] [natoms] [pre] [cg_steps]
# pre = 3000: the forming bed (default); pre = 20000: a bed nearly at rest (few events).
set -eu
EXE=${1:-$(dirname "$0")/../../build/bin/tdem-liggghts}
NATOMS=${2:-4000}
PRE=${3:-3000}
CG_STEPS=${4:-300}
WORK=$(mktemp -d /tmp/tdem_cg_grid.XXXXXX)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT

MU="fix m_mu all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4"
STIFF="fix m_kn all property/global kn peratomtypepair 2 6000 5500 5500 5000
fix m_kt all property/global kt peratomtypepair 2 1800 1700 1700 1600
fix m_gn all property/global gamman peratomtypepair 2 300 280 280 260
fix m_gt all property/global gammat peratomtypepair 2 120 110 110 100"
MAT="fix m_E all property/global youngsModulus peratomtype 5.e6 6.e6
fix m_nu all property/global poissonsRatio peratomtype 0.45 0.4
fix m_e all property/global coefficientRestitution peratomtypepair 2 0.5 0.55 0.55 0.6
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 2 0.3 0.3 0.3 0.3"

head_lines() {
  printf 'atom_style granular\natom_modify map array\nboundary m m m\nnewton off\ncommunicate single vel yes\nunits si\n'
}
walls() { # $1 model, $2 settings
  n=0
  for w in "xplane -0.05" "xplane 0.05" "yplane -0.05" "yplane 0.05" "zplane 0.0" "zplane 0.20"; do
    echo "fix w$n all wall/gran $1 primitive type 1 $w $2"
    n=$((n + 1))
  done
}

{
  head_lines
  cat <<EOI
region box block -0.05 0.05 -0.05 0.05 0.0 0.20 units box
create_box 2 box
neighbor 0.0015 bin
neigh_modify delay 0
$STIFF
$MU
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
timestep 0.00002
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
EOI
  walls "model hooke/stiffness tangential history" ""
  cat <<EOI
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0025
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2000 radius constant 0.0020
fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.048 0.048 -0.048 0.048 0.002 0.19 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel uniform -0.5 0.5 -0.5 0.5 -1.0 0.0 omega constant 0 0 0 &
    region ins particles_in_region $NATOMS
fix integr all nve/sphere
run 1
unfix ins
run $PRE
write_data bed.data
EOI
} > "$WORK/in.pre"
(cd "$WORK" && "$EXE" -in in.pre -log log.pre -echo none -screen /dev/null)

case_input() { # $1 model, $2 settings, $3 properties
  head_lines
  echo "read_data bed.data"
  echo "neighbor 0.0015 bin"
  echo "neigh_modify delay 0"
  echo "$3"
  echo "$MU"
  echo "pair_style gran $1 $2"
  echo "pair_coeff * *"
  echo "timestep 0.00002"
  echo "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0"
  walls "$1" "$2"
  echo "fix integr all nve/sphere"
  echo "compute cn all contact/atom"
  echo "compute nc all reduce sum c_cn"
  echo "thermo_style custom step atoms c_nc"
  echo "thermo 10"
  echo "thermo_modify lost ignore norm no"
  echo "run $CG_STEPS"
}

count() { # $1 exe, $2 tag, $3 model, $4 settings, $5 properties
  case_input "$3" "$4" "$5" > "$WORK/in.$2"
  (cd "$WORK" && valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.out.$2" --collect-atstart=no \
    '--toggle-collect=LIGGGHTS::PairStyles::Granular<*>::compute_force*' "$1" -in "in.$2" \
    -log "log.$2" -echo none -screen /dev/null > "$WORK/cg.txt.$2" 2>&1)
  ins=$(grep 'Collected' "$WORK/cg.txt.$2" | awk '{gsub(",","",$4); print $4}')
  nc=$(awk '/^ *Step/ {on = 1; next} /^Loop time/ {on = 0} on && $1 ~ /^[0-9]+$/ {s += $3; k++} END {printf "%.0f", s / k / 2}' "$WORK/log.$2")
  echo "$2 $ins $nc" >> "$WORK/summary"
  echo "  $2: $ins instructions, $nc touching pairs on average" >&2
}

LSD="model tdem/lsd tangential tdem/cundall_strack"
HZ="model tdem/hertz tangential tdem/cundall_strack"
for law in ${LAWS:-lsd hertz}; do
  if [ $law = lsd ]; then M=$LSD; S=""; P=$STIFF; else M=$HZ; S="damping tsuji"; P=$MAT; fi
  [ -z "${BASE:-}" ] || count "$BASE" "${law}_off_base" "$M" "$S" "$P"
  count "$EXE" "${law}_off" "$M" "$S" "$P"
  count "$EXE" "${law}_on" "$M" "$S grid_correction on" "$P"
done

echo
echo "callgrind: instructions in the pair style's compute_force, $CG_STEPS steps, $NATOMS spheres after $PRE steps of settling"
echo
awk '{ ins[$1] = $2; nc[$1] = $3; order[NR] = $1 } END {
  print "| case | touching pairs | instructions | ratio |"; print "|---|---|---|---|";
  for (i = 1; i <= NR; i++) { m = order[i]; law = m; sub(/_.*/, "", law); ref = ins[law "_off"];
    printf "| %s | %d | %.6g | %.4f |\n", m, nc[m], ins[m], ins[m] / ref } }' "$WORK/summary"
echo
echo "ratio: to the same law with grid_correction off in this build"
