#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of fix tdem/grate per particle-step (issue 7) in tdem-liggghts: the same bed of NATOMS spheres
# (the particles and the contact law of the grate scenes, input_scripts/liggghts/grate_forward_3d.in)
#   moving    on the forward-acting grate of the scenes, rows 1 and 3 stroking 30 mm at 2 Hz
#   standing  on the same grate with stroke 0 (the same meshes, never moved)
#   floor     on a flat stock primitive floor (fix wall/gran ... primitive zplane)
# in a closed box (plane walls at both ends of the grate, periodic width), so that the bed stays.
# Each case: the bed is poured (insert/pack) and settled for SETTLE steps, then STEPS steps are timed
# (LIGGGHTS "Loop time" of the last run). REPEATS round-robin rounds, the fastest of each case is used.
# Prints and writes bench/results/grate_liggghts.md: particle-steps per second and the ratios.
#
#   bench/liggghts/bench_grate.sh [path/to/tdem-liggghts]
# Environment: NATOMS (1000), SETTLE (8000), STEPS (6000), REPEATS (3), NP (MPI ranks, 1),
# MPIRUN (default "mpirun --allow-run-as-root --oversubscribe").
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
EXE=${1:-${TDEM_LIGGGHTS:-$root/build/bin/tdem-liggghts}}
case $EXE in /*) ;; *) EXE="$(pwd)/$EXE" ;; esac
[ -x "$EXE" ] || { echo "bench_grate.sh: tdem-liggghts not found at '$EXE'" >&2; exit 2; }
NATOMS=${NATOMS:-1000}
SETTLE=${SETTLE:-8000}
STEPS=${STEPS:-6000}
REPEATS=${REPEATS:-3}
NP=${NP:-1}
MPIRUN=${MPIRUN:-mpirun --allow-run-as-root --oversubscribe}
WORK=$(mktemp -d /tmp/bench_grate.XXXXXX)
out="$root/bench/results/grate_liggghts.md"
mkdir -p "$root/bench/results"

LAW="model tdem/lsd tangential tdem/cundall_strack rolling_friction cdt"
write_input() { # $1 case name
  cat <<EOI
atom_style granular
atom_modify map array
boundary f p f
newton off
communicate single vel yes
units si
region box block -0.02 0.43 -0.03 0.03 -0.16 0.25 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
fix m_e  all property/global coefficientRestitution peratomtypepair 1 0.5
fix m_tc all property/global contactTime peratomtypepair 1 4e-3
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.2857
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
fix m_rf all property/global coefficientRollingFriction peratomtypepair 1 0.25
pair_style gran $LAW parameters restitution
pair_coeff * *
timestep 2e-4
EOI
  case $1 in
    moving|standing)
      if [ "$1" = moving ]; then s=0.03; else s=0; fi
      echo "fix g all tdem/grate rows 4 bar_length 0.12 bar_height 0.015 step_height 0.015 overlap 0.035 &"
      echo "    declination 10 width 0.06 type forward frame xyz origin 0 0 0 profile sinusoidal stroke $s frequency 2"
      echo "fix walls all wall/gran $LAW mesh n_meshes 2 meshes g_fixed g_moving0 parameters restitution" ;;
    floor)
      echo "fix walls all wall/gran $LAW primitive type 1 zplane -0.06 parameters restitution" ;;
  esac
  cat <<EOI
fix back all wall/gran $LAW primitive type 1 xplane 0.0 parameters restitution
fix front all wall/gran $LAW primitive type 1 xplane 0.37 parameters restitution
fix grav all gravity 9.81 vector 0 0 -1
fix integr all nve/sphere
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0045
fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.0055
fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block 0.01 0.36 -0.03 0.03 0.01 0.24 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel constant 0 0 -0.3 region ins particles_in_region $NATOMS
compute cn all contact/atom
compute nc all reduce sum c_cn
thermo_style custom step atoms ke c_nc
thermo_modify lost ignore norm no
thermo 1000
run $SETTLE
unfix ins
run $STEPS
EOI
}

CASES="moving standing floor"
for c in $CASES; do write_input "$c" > "$WORK/in.$c"; done
. "$root/tools/progress.sh"
_st=""
i=1
while [ "$i" -le "$REPEATS" ]; do for c in $CASES; do _st="$_st r$i.$c:1"; done; i=$((i + 1)); done
progress_init "$_st"
: > "$WORK/times"
i=1
while [ "$i" -le "$REPEATS" ]; do
  for c in $CASES; do
    # shellcheck disable=SC2086
    if [ "$NP" = 1 ]; then
      (cd "$WORK" && "$EXE" -in "in.$c" -log "log.$c" -echo none -screen /dev/null) || exit 2
    else
      (cd "$WORK" && $MPIRUN -np "$NP" "$EXE" -in "in.$c" -log "log.$c" -echo none -screen /dev/null) || exit 2
    fi
    lt=$(grep '^Loop time' "$WORK/log.$c" | tail -1 | awk '{print $4}')
    nat=$(grep '^Loop time' "$WORK/log.$c" | tail -1 | awk '{print $12}')
    nc=$(awk '/^ *Step/ {k = 0; s = 0; next} /^Loop time/ {m = (k ? s / k : 0)} $1 ~ /^[0-9]+$/ && NF == 4 {s += $4; k++} END {printf "%.2f", m}' "$WORK/log.$c")
    echo "$c $lt $nat $nc" >> "$WORK/times"
    echo "  round $i: $c: loop time $lt s for $STEPS steps, $nat atoms, $nc = contact/atom summed"
    progress_done "r$i.$c"
  done
  i=$((i + 1))
done

/usr/bin/python3 - "$WORK/times" "$out" "$STEPS" "$NATOMS" "$NP" "$REPEATS" "$SETTLE" <<'EOF'
import sys
times, out, steps, natoms, np_, rep, settle = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5], sys.argv[6], sys.argv[7]
best, allt, nat, nc = {}, {}, {}, {}
for line in open(times):
    c, t, n, k = line.split()
    allt.setdefault(c, []).append(float(t))
    best[c] = min(best.get(c, 1e300), float(t))
    nat[c] = int(n)
    nc[c] = float(k)
rate = {c: nat[c] * steps / best[c] for c in best}
lines = ["# Cost of fix tdem/grate in LIGGGHTS (bench/liggghts/bench_grate.sh)", "",
         "The same bed (%d spheres of 9/11 mm poured, settled %s steps, then %d steps timed; tdem/lsd + "
         "tdem/cundall_strack + CDT rolling friction, dt = 2e-4 s) on the moving forward grate of the scenes (rows 1 and 3: 30 mm, 2 Hz), "
         "on the same grate standing (stroke 0) and on a flat stock `primitive zplane` floor; %s MPI rank(s), "
         "fastest of %s round-robin repetitions on the shared 2-core machine (all loop times listed)."
         % (natoms, settle, steps, np_, rep), "",
         "| case | atoms | loop times [s] | particle-steps/s (fastest) | cost relative to the floor | contact/atom summed (2 x pair contacts), mean |",
         "|---|---|---|---|---|---|"]
for c in ("moving", "standing", "floor"):
    lines.append("| %s | %d | %s | %.3g | %.2f | %.0f |" % (c, nat[c], " ".join("%.2f" % t for t in allt[c]), rate[c],
                                                          rate["floor"] / rate[c], nc[c]))
lines += ["", "Ratios (cost per particle-step): moving / standing = %.2f, moving / floor = %.2f, standing / floor = %.2f."
          % (rate["standing"] / rate["moving"], rate["floor"] / rate["moving"], rate["floor"] / rate["standing"]),
          "The particle-particle work is the same in the three cases (same bed; the contact count is listed); the "
          "difference is the mesh contact detection of wall/gran (standing / floor) and moving the meshes with their "
          "neighbour-list updates (moving / standing)."]
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
rm -rf "$WORK"
