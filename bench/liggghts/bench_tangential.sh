#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of every issue-4 tangential law in LIGGGHTS against the stock `tangential history`, in one
# invocation, in the scene of bench_laws.sh: NATOMS spheres of two types in a box with six
# primitive walls under gravity, inserted and settled ONCE with stock hooke/stiffness (SETTLE
# steps), saved with write_data; every case starts from that same bed (read_data), runs 200 untimed
# and STEPS timed steps (LIGGGHTS "Loop time", "Pair time", one rank), same time step.
# Cases: each tangential law (tdem/haff_werner, tdem/linear_spring, tdem/walton_braun,
# tdem/mindlin_deresiewicz, tdem/mindlin_no_slip, tdem/di_renzo) with stock `model hertz` and with
# `model tdem/hertz`, and the reference `tangential history` with both.
# The best of REPEATS runs (round robin) is reported as particle-steps per second and as the ratio
# to the reference with the same normal model (hertz + history, tdem/hertz + history), Markdown.
#
# CALLGRIND=1: instead of timing, counts instructions with valgrind --tool=callgrind over CG_STEPS
# steps (default 300), collected only inside the pair style's compute_force (pair contacts; the
# walls are not counted), per particle-step and per contact-step, with the same ratios.
#
# Not part of ctest. Usage:
#   [CALLGRIND=1] [KEEP=1] bench_tangential.sh [tdem-liggghts] [repeats] [steps] [natoms] [settle]
set -eu
EXE=${1:-$(dirname "$0")/../../build/bin/tdem-liggghts}
REPEATS=${2:-2}
STEPS=${3:-3000}
NATOMS=${4:-4000}
SETTLE=${5:-15000}
CG_STEPS=${CG_STEPS:-300}
WORK=$(mktemp -d /tmp/tdem_bench_tangential.XXXXXX)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT

# ------------------------------------------------------------------ cases: name | model | properties
MAT="fix m_E all property/global youngsModulus peratomtype 5.e6 6.e6;fix m_nu all property/global poissonsRatio peratomtype 0.45 0.4"
MU="fix m_mu all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4"
KAPPA="fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 2 0.3 0.3 0.3 0.3"
TDR="fix m_td all property/global tangentialDampingRatio peratomtypepair 2 0.5 0.5 0.5 0.5"
E="fix m_e all property/global coefficientRestitution peratomtypepair 2 0.5 0.55 0.55 0.6"
STIFF="fix m_kn all property/global kn peratomtypepair 2 6000 5500 5500 5000;fix m_kt all property/global kt peratomtypepair 2 1800 1700 1700 1600;fix m_gn all property/global gamman peratomtypepair 2 300 280 280 260;fix m_gt all property/global gammat peratomtypepair 2 120 110 110 100"
P="$MAT;$E;$KAPPA;$TDR;$MU"
: > "$WORK/laws"
for normal in hertz tdem/hertz; do
  tag=$(echo "$normal" | tr '/' '_')
  for t in history tdem/haff_werner tdem/linear_spring tdem/walton_braun tdem/mindlin_deresiewicz \
           tdem/mindlin_no_slip tdem/di_renzo; do
    echo "${tag}+$(echo "$t" | sed 's,tdem/,,')|model $normal tangential $t|$P" >> "$WORK/laws"
  done
done

walls() { # $1 model keywords (model ... tangential ...), $2 settings after them
  n=0
  for w in "xplane -0.05" "xplane 0.05" "yplane -0.05" "yplane 0.05" "zplane 0.0" "zplane 0.20"; do
    echo "fix w$n all wall/gran $1 primitive type 1 $w $2"
    n=$((n + 1))
  done
}

head_lines() {
  cat <<EOI
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
EOI
}

# ------------------------------------------------------------------ the settled bed (once)
{
  head_lines
  cat <<EOI
region box block -0.05 0.05 -0.05 0.05 0.0 0.20 units box
create_box 2 box
neighbor 0.0015 bin
neigh_modify delay 0
EOI
  echo "$STIFF;$MU" | tr ';' '\n'
  cat <<EOI
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
region ins block -0.048 0.048 -0.048 0.048 0.002 0.12 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel uniform -0.3 0.3 -0.3 0.3 -0.6 0.0 omega constant 0 0 0 &
    region ins particles_in_region $NATOMS
fix integr all nve/sphere
thermo_style custom step atoms ke
thermo 5000
thermo_modify lost ignore norm no
run 1
unfix ins
run $SETTLE
write_data bed.data
EOI
} > "$WORK/in.settle"
(cd "$WORK" && "$EXE" -in in.settle -log log.settle -echo none -screen /dev/null)
echo "settled bed: $NATOMS spheres, $SETTLE steps; kinetic energy at the end: $(grep -B1 '^Loop time' "$WORK/log.settle" | head -1 | awk '{print $3}') J"

# ------------------------------------------------------------------ one input per law
while IFS='|' read -r name model props; do
  models=$(echo "$model" | awk '{print $1, $2, $3, $4}')
  settings=$(echo "$model" | cut -d' ' -f5-)
  {
    head_lines
    echo "read_data bed.data"
    echo "neighbor 0.0015 bin"
    echo "neigh_modify delay 0"
    echo "$props" | tr ';' '\n'
    echo "pair_style gran $model"
    echo "pair_coeff * *"
    echo "timestep 0.00002"
    echo "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0"
    walls "$models" "$settings"
    echo "fix integr all nve/sphere"
    echo "compute cn all contact/atom"
    echo "compute nc all reduce sum c_cn"
    echo "thermo_style custom step atoms ke c_nc"
    echo "thermo_modify format float %.15g lost ignore norm no"
    echo "thermo 1000"
    echo "run 200"
    echo "run $STEPS"
  } > "$WORK/in.$name"
done < "$WORK/laws"
NAMES=$(cut -d'|' -f1 "$WORK/laws")

contacts() { # $1 log -> mean number of contacts per particle over the outputs of the last run
  awk -v n="$NATOMS" '/^ *Step/ {k = 0; sum = 0; next} /^Loop time/ {m = sum / k} $1 ~ /^[0-9]+$/ && NF == 4 {sum += $4; k++}
       END {printf "%.3f", m / n}' "$1"
}

if [ -n "${CALLGRIND:-}" ]; then
  # one run of CG_STEPS steps from the settled bed, instructions collected inside the pair
  # style's compute_force only (--toggle-collect); contacts counted in a separate plain run
  for m in $NAMES; do
    sed -e "/^run 200\$/d" -e "s/^run $STEPS\$/run $CG_STEPS/" -e "s/^thermo 1000\$/thermo 50/" "$WORK/in.$m" > "$WORK/cg.in.$m"
    (cd "$WORK" && valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.out.$m" --collect-atstart=no \
      '--toggle-collect=LIGGGHTS::PairStyles::Granular<*>::compute_force*' "$EXE" -in "cg.in.$m" \
      -log none -echo none -screen /dev/null > "$WORK/cg.txt.$m" 2>&1)
    (cd "$WORK" && "$EXE" -in "cg.in.$m" -log "cg.log.$m" -echo none -screen /dev/null)
    ins=$(grep 'Collected' "$WORK/cg.txt.$m" | awk '{gsub(",","",$4); print $4}')
    echo "$m $ins $(contacts "$WORK/cg.log.$m")" >> "$WORK/cg.summary"
  done
  echo
  echo "callgrind: instructions in the pair style's compute_force, $CG_STEPS steps from the settled bed ($NATOMS spheres)"
  echo
  awk -v n="$NATOMS" -v s="$CG_STEPS" '{ name[NR]=$1; ins[NR]=$2; c[NR]=$3; idx[$1]=NR } END {
    print "| normal + tangential | contacts / particle | instructions / particle-step | instructions / contact-step | ratio to history (same normal) |";
    print "|---|---|---|---|---|";
    for (i = 1; i <= NR; i++) { split(name[i], p, "+"); r = ins[idx[p[1] "+history"]];
      printf "| %s | %.2f | %.1f | %.1f | %.3f |\n", name[i], c[i], ins[i] / (n * s), ins[i] / (n * s * c[i] / 2), ins[i] / r } }' "$WORK/cg.summary"
  exit 0
fi

loop_time() { grep '^Loop time' "$1" | tail -1 | awk '{print $4}'; }
pair_time() { grep '^Pair  time' "$1" | tail -1 | awk '{print $5}'; }
i=1
while [ "$i" -le "$REPEATS" ]; do
  for m in $NAMES; do
    (cd "$WORK" && "$EXE" -in "in.$m" -log "log.$m" -echo none -screen /dev/null)
    echo "$m $(loop_time "$WORK/log.$m") $(pair_time "$WORK/log.$m") $(contacts "$WORK/log.$m")" >> "$WORK/times"
  done
  i=$((i + 1))
done
echo
echo "$NATOMS spheres (settled bed), $STEPS timed steps, best of $REPEATS runs, one rank"
echo
awk -v n="$NATOMS" -v s="$STEPS" '
  { if (!($1 in best) || $2 < best[$1]) best[$1] = $2; if (!($1 in pbest) || $3 < pbest[$1]) pbest[$1] = $3; nc[$1] = $4;
    if (!($1 in seen)) { seen[$1] = 1; order[++k] = $1 } }
  END {
    print "| normal + tangential | contacts / particle | loop time [s] | pair time [s] | particle-steps/s | cost ratio to history (same normal, loop) | pair-time ratio |";
    print "|---|---|---|---|---|---|---|";
    for (i = 1; i <= k; i++) { m = order[i]; split(m, p, "+"); r = p[1] "+history";
      printf "| %s | %.2f | %.3f | %.3f | %.4g | %.3f | %.3f |\n", m, nc[m], best[m], pbest[m], n * s / best[m], best[m] / best[r], pbest[m] / pbest[r] } }' "$WORK/times"
