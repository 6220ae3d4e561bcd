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

. "$(dirname "$0")/bench_bed.sh"

if [ -n "${CALLGRIND:-}" ]; then
  callgrind_counts
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

timed_runs
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
