#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of every tdem normal law in LIGGGHTS against the stock models, in one invocation.
#
# Scene: the bed of bench_linear.sh (NATOMS spheres of two types in a box with six primitive
# walls, gravity), inserted and settled ONCE with the stock hooke/stiffness model (SETTLE steps),
# saved with write_data; every law then starts from that same settled bed (read_data), runs 200
# untimed steps and STEPS timed steps (LIGGGHTS "Loop time" and "Pair time", one rank). All runs
# use `tangential history`, so that the normal law is the only difference, and the same time
# step; the material data give contact times of 10 ... 50 steps for every law.
# Runs are repeated REPEATS times (round robin); the best time is reported as particle-steps per
# second, with the ratio to stock hooke and to stock hertz, as a Markdown table.
# Equal physics (the equal-complexity pairs): tdem/lsd parameters material vs hooke,
# tdem/lsd (stiffness) vs hooke/stiffness, tdem/hertz damping tsuji vs hertz.
#
# CALLGRIND=1: instead of timing, counts instructions with valgrind --tool=callgrind over
# CG_STEPS steps (default 300) from the settled bed, collected only inside the pair style's
# compute_force (LIGGGHTS::PairStyles::Granular<...>::compute_force, --toggle-collect), per
# particle-step and per contact-step, and the ratio to stock hooke / hertz -- a measure that
# other load on the machine does not disturb. The number of touching contacts differs between
# laws (different stiffness, same bed), so "contacts / particle" (compute contact/atom, mean of
# the outputs) is printed with both tables; compare laws by instructions per contact-step.
#
# Not part of ctest. Usage:
#   [CALLGRIND=1] [KEEP=1] bench_laws.sh [tdem-liggghts] [repeats] [steps] [natoms] [settle]
set -eu
EXE=${1:-$(dirname "$0")/../../build/bin/tdem-liggghts}
REPEATS=${2:-3}
STEPS=${3:-5000}
NATOMS=${4:-4000}
SETTLE=${5:-15000}
CG_STEPS=${CG_STEPS:-300}
WORK=$(mktemp -d /tmp/tdem_bench_laws.XXXXXX)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT

# ------------------------------------------------------------------ laws: name | model | properties
# (properties: fix property/global lines, two atom types; separated by ';')
MAT="fix m_E all property/global youngsModulus peratomtype 5.e6 6.e6;fix m_nu all property/global poissonsRatio peratomtype 0.45 0.4"
MU="fix m_mu all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4"
KAPPA="fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 2 0.3 0.3 0.3 0.3"
E="fix m_e all property/global coefficientRestitution peratomtypepair 2 0.5 0.55 0.55 0.6"
STIFF="fix m_kn all property/global kn peratomtypepair 2 6000 5500 5500 5000;fix m_kt all property/global kt peratomtypepair 2 1800 1700 1700 1600;fix m_gn all property/global gamman peratomtypepair 2 300 280 280 260;fix m_gt all property/global gammat peratomtypepair 2 120 110 110 100"
VC="fix m_vc all property/global characteristicVelocity scalar 1.0"
FIT="fix m_c0 all property/global restitutionFitC0 peratomtypepair 2 0.9 0.85 0.85 0.8;fix m_c1 all property/global restitutionFitC1 peratomtypepair 2 1 1 1 1;fix m_c2 all property/global restitutionFitC2 peratomtypepair 2 0.5 0.5 0.5 0.5;fix m_vmax all property/global impactVelocityMax scalar 5.0"
cat > "$WORK/laws" <<EOL
hooke_stiffness|model hooke/stiffness tangential history|$STIFF;$MU
hooke|model hooke tangential history|$MAT;$E;$VC;$MU
hertz|model hertz tangential history|$MAT;$E;$MU
tdem_lsd_stiffness|model tdem/lsd tangential history|$STIFF;$MU
tdem_lsd_material|model tdem/lsd tangential history parameters material|$MAT;$E;$VC;$KAPPA;$MU
tdem_hertz_tsuji|model tdem/hertz tangential history damping tsuji|$MAT;$E;$KAPPA;$MU
tdem_walton_braun|model tdem/walton_braun tangential history|fix m_kl all property/global loadingStiffness peratomtypepair 2 6000 5500 5500 5000;fix m_ku all property/global unloadingStiffness peratomtypepair 2 24000 22000 22000 20000;fix m_s all property/global unloadingStiffnessSlope peratomtypepair 2 0 0 0 0;$KAPPA;$MU
tdem_thornton|model tdem/thornton tangential history|$MAT;fix m_py all property/global yieldPressure peratomtypepair 2 3e5 3e5 3e5 3e5;$KAPPA;$MU
tdem_power_law|model tdem/power_law tangential history|fix m_al all property/global loadingCoefficient peratomtypepair 2 1.3e5 1.3e5 1.3e5 1.3e5;fix m_p all property/global loadingExponent peratomtypepair 2 1.5 1.5 1.5 1.5;fix m_aul all property/global unloadingCoefficient peratomtypepair 2 6e5 6e5 6e5 6e5;fix m_q all property/global unloadingExponentIncrement peratomtypepair 2 0 0 0 0;$KAPPA;$MU
tdem_extended_linear|model tdem/extended_linear tangential history restitutionFit rational contactTimeFit power|$FIT;fix m_t0 all property/global contactTimeFitC0 peratomtypepair 2 4e-4 4e-4 4e-4 4e-4;fix m_t1 all property/global contactTimeFitC1 peratomtypepair 2 0.2 0.2 0.2 0.2;$KAPPA;$MU
tdem_extended_hertz|model tdem/extended_hertz tangential history restitutionFit rational|$MAT;$FIT;$KAPPA;$MU
tdem_continuous_potential|model tdem/continuous_potential tangential history|fix m_eps all property/global potentialEnergy peratomtypepair 2 1e-5 1e-5 1e-5 1e-5;fix m_n all property/global potentialExponent peratomtypepair 2 36 36 36 36;fix m_g all property/global dampingCoefficient peratomtypepair 2 0.01 0.01 0.01 0.01;$KAPPA;$MU
EOL

. "$(dirname "$0")/bench_bed.sh"

if [ -n "${CALLGRIND:-}" ]; then
  callgrind_counts
  echo
  echo "callgrind: instructions in the pair style's compute_force, $CG_STEPS steps from the settled bed ($NATOMS spheres)"
  echo
  awk -v n="$NATOMS" -v s="$CG_STEPS" '{ name[NR]=$1; ins[NR]=$2; c[NR]=$3; idx[$1]=NR } END {
    h = ins[idx["hooke"]]; z = ins[idx["hertz"]];
    print "| law | contacts / particle | instructions / particle-step | instructions / contact-step (all pair work) | ratio to hooke | ratio to hertz |";
    print "|---|---|---|---|---|---|";
    for (i = 1; i <= NR; i++) printf "| %s | %.2f | %.1f | %.1f | %.3f | %.3f |\n", name[i], c[i], ins[i] / (n * s),
      ins[i] / (n * s * c[i] / 2), ins[i] / h, ins[i] / z }' "$WORK/cg.summary"
  exit 0
fi

timed_runs
echo
echo "$NATOMS spheres (settled bed), $STEPS timed steps, best of $REPEATS runs, one rank, tangential history for all"
echo
awk -v n="$NATOMS" -v s="$STEPS" '
  { if (!($1 in best) || $2 < best[$1]) best[$1] = $2; if (!($1 in pbest) || $3 < pbest[$1]) pbest[$1] = $3; nc[$1] = $4;
    if (!($1 in seen)) { seen[$1] = 1; order[++k] = $1 } }
  END {
    h = best["hooke"]; z = best["hertz"];
    print "| law | contacts / particle | loop time [s] | pair time [s] | particle-steps/s | ratio to hooke | ratio to hertz |";
    print "|---|---|---|---|---|---|---|";
    for (i = 1; i <= k; i++) { m = order[i];
      printf "| %s | %.2f | %.3f | %.3f | %.4g | %.3f | %.3f |\n", m, nc[m], best[m], pbest[m], n * s / best[m], h / best[m], z / best[m] }
    printf "\nequal physics: tdem_lsd_material / hooke %.3f, tdem_lsd_stiffness / hooke_stiffness %.3f, tdem_hertz_tsuji / hertz %.3f (throughput ratios)\n",
      best["hooke"] / best["tdem_lsd_material"], best["hooke_stiffness"] / best["tdem_lsd_stiffness"], best["hertz"] / best["tdem_hertz_tsuji"] }' "$WORK/times"
