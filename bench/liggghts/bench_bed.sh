#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Shared part of bench_laws.sh and bench_tangential.sh (sourced, not run): writes the input of
# the settled bed for every line "name|model keywords|properties" of $WORK/laws (after settling
# it once), runs the settling, and provides the measurement loops. Expects EXE, WORK, NATOMS,
# STEPS, SETTLE, REPEATS, CG_STEPS set by the caller.
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


# callgrind_counts: per case one run of CG_STEPS steps from the settled bed, instructions
# collected inside the pair style's compute_force only (--toggle-collect); contacts counted in a
# separate plain run. Appends "name instructions contacts" to $WORK/cg.summary.
callgrind_counts() {
  for m in $NAMES; do
    sed -e "/^run 200\$/d" -e "s/^run $STEPS\$/run $CG_STEPS/" -e "s/^thermo 1000\$/thermo 50/" "$WORK/in.$m" > "$WORK/cg.in.$m"
    (cd "$WORK" && valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.out.$m" --collect-atstart=no \
      '--toggle-collect=LIGGGHTS::PairStyles::Granular<*>::compute_force*' "$EXE" -in "cg.in.$m" \
      -log none -echo none -screen /dev/null > "$WORK/cg.txt.$m" 2>&1)
    (cd "$WORK" && "$EXE" -in "cg.in.$m" -log "cg.log.$m" -echo none -screen /dev/null)
    ins=$(grep 'Collected' "$WORK/cg.txt.$m" | awk '{gsub(",","",$4); print $4}')
    echo "$m $ins $(contacts "$WORK/cg.log.$m")" >> "$WORK/cg.summary"
  done
}

# timed_runs: REPEATS round-robin rounds of every case; appends
# "name loop_time pair_time contacts" to $WORK/times.
loop_time() { grep '^Loop time' "$1" | tail -1 | awk '{print $4}'; }
pair_time() { grep '^Pair  time' "$1" | tail -1 | awk '{print $5}'; }
timed_runs() {
  . "$(cd "$(dirname "$0")/../.." && pwd)/tools/progress.sh"
  _st=""
  i=1
  while [ "$i" -le "$REPEATS" ]; do for m in $NAMES; do _st="$_st r$i.$m:1"; done; i=$((i + 1)); done
  progress_init "$_st"
  i=1
  while [ "$i" -le "$REPEATS" ]; do
    for m in $NAMES; do
      (cd "$WORK" && "$EXE" -in "in.$m" -log "log.$m" -echo none -screen /dev/null)
      echo "$m $(loop_time "$WORK/log.$m") $(pair_time "$WORK/log.$m") $(contacts "$WORK/log.$m")" >> "$WORK/times"
      progress_done "r$i.$m"
    done
    i=$((i + 1))
  done
}
