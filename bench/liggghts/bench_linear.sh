#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of the tdem linear spring-dashpot + Cundall-Strack laws against the stock LIGGGHTS
# models with the same physics, both run by tdem-liggghts on one rank:
#   stock: pair_style gran model hooke/stiffness tangential history
#   tdem:  pair_style gran model tdem/lsd tangential tdem/cundall_strack
# Scene: 4000 spheres (two types) inserted into a box with six primitive walls, settling under
# gravity; after an insertion run, STEPS steps are timed (LIGGGHTS "Loop time"). Runs alternate
# stock/tdem REPEATS times; the best time of each is reported as particle-steps per second
# (and the ratio of the medians).
# With CALLGRIND=1 it also counts instructions (valgrind --tool=callgrind, 1000 timed steps):
# total and inside the pair style's compute_force -- a measure that other load on the machine
# does not disturb.
# Not part of ctest. Usage: [CALLGRIND=1] [KEEP=1] bench_linear.sh [tdem-liggghts] [repeats] [steps]
set -eu
EXE=${1:-$(dirname "$0")/../../build/bin/tdem-liggghts}
REPEATS=${2:-3}
STEPS=${3:-5000}
NATOMS=4000
WORK=$(mktemp -d /tmp/tdem_bench_linear.XXXXXX)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT

write_input() { # $1 file, $2 model keywords
  cat > "$1" <<EOI
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0.0 0.20 units box
create_box 2 box
neighbor 0.0015 bin
neigh_modify delay 0
fix m_kn  all property/global kn peratomtypepair 2 6000 5500 5500 5000
fix m_kt  all property/global kt peratomtypepair 2 1800 1700 1700 1600
fix m_gn  all property/global gamman peratomtypepair 2 300 280 280 260
fix m_gt  all property/global gammat peratomtypepair 2 120 110 110 100
fix m_mu  all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4
pair_style gran $2
pair_coeff * *
timestep 0.00002
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix w0 all wall/gran $2 primitive type 1 xplane -0.05
fix w1 all wall/gran $2 primitive type 1 xplane 0.05
fix w2 all wall/gran $2 primitive type 1 yplane -0.05
fix w3 all wall/gran $2 primitive type 1 yplane 0.05
fix w4 all wall/gran $2 primitive type 1 zplane 0.0
fix w5 all wall/gran $2 primitive type 1 zplane 0.20
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0025
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2000 radius constant 0.0020
fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.048 0.048 -0.048 0.048 0.002 0.12 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel uniform -0.3 0.3 -0.3 0.3 -0.6 0.0 omega constant 0 0 0 &
    region ins particles_in_region $NATOMS
fix integr all nve/sphere
thermo_style custom step atoms ke
thermo_modify format float %.15g
thermo 1000
thermo_modify lost ignore norm no
run 1
unfix ins
run $STEPS
EOI
}

write_input "$WORK/in.stock" "model hooke/stiffness tangential history"
write_input "$WORK/in.tdem" "model tdem/lsd tangential tdem/cundall_strack"

if [ -n "${CALLGRIND:-}" ]; then
  for m in stock tdem; do
    sed "s/^run $STEPS\$/run 1000/" "$WORK/in.$m" > "$WORK/cg.in.$m"
    valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.$m" "$EXE" -in "$WORK/cg.in.$m" -log none \
      -echo none -screen /dev/null > "$WORK/cg.$m.txt" 2>&1
    total=$(grep 'Collected' "$WORK/cg.$m.txt" | awk '{print $4}')
    pair=$(callgrind_annotate --inclusive=yes "$WORK/cg.$m" 2>/dev/null |
           grep -E '\?\?\?:LIGGGHTS::PairStyles::Granular<.*compute_force' | head -1 | awk '{gsub(",","",$1); print $1}')
    echo "$m $total $pair" >> "$WORK/cg.summary"
  done
  awk '{t[$1]=$2; p[$1]=$3} END{
    printf "callgrind, 1000 steps: instructions total stock %.4g, tdem %.4g, ratio %.4f\n", t["stock"], t["tdem"], t["tdem"]/t["stock"];
    printf "callgrind, 1000 steps: instructions in pair compute_force stock %.4g, tdem %.4g, ratio %.4f\n", p["stock"], p["tdem"], p["tdem"]/p["stock"] }' "$WORK/cg.summary"
fi

loop_time() { # $1 input -> seconds of the timed run; also checks the final thermo line
  # (not "-screen none": LIGGGHTS 3.8.0 Region::reset_random then writes to a NULL screen)
  "$EXE" -in "$1" -log "$1.log" -echo none -screen /dev/null
  grep '^Loop time' "$1.log" | tail -1 | awk '{print $4}'
}
pair_time() { # $1 input -> seconds in the pair style (force kernel) during the timed run
  grep '^Pair  time' "$1.log" | tail -1 | awk '{print $5}'
}

best_stock=""; best_tdem=""; pair_stock=""; pair_tdem=""
. "$(cd "$(dirname "$0")/../.." && pwd)/tools/progress.sh"
_st=""
i=1
while [ "$i" -le "$REPEATS" ]; do _st="$_st r$i.stock:1 r$i.tdem:1"; i=$((i + 1)); done
progress_init "$_st"
i=1
while [ "$i" -le "$REPEATS" ]; do
  for m in stock tdem; do
    t=$(loop_time "$WORK/in.$m")
    p=$(pair_time "$WORK/in.$m")
    echo "run $i $m: $t s (pair $p s)"
    progress_done "r$i.$m"
    echo "$t" >> "$WORK/times.$m"
    eval "best=\${best_$m}"
    if [ -z "$best" ] || awk "BEGIN{exit !($t < $best)}"; then eval "best_$m=$t"; fi
    eval "bestp=\${pair_$m}"
    if [ -z "$bestp" ] || awk "BEGIN{exit !($p < $bestp)}"; then eval "pair_$m=$p"; fi
  done
  i=$((i + 1))
done
# same trajectory (the laws are bitwise equivalent): compare the last thermo lines
if [ "$(grep -B1 '^Loop time' "$WORK/in.stock.log" | head -1)" != "$(grep -B1 '^Loop time' "$WORK/in.tdem.log" | head -1)" ]; then
  echo "WARNING: final thermo lines differ between stock and tdem" >&2
fi
median() { sort -g "$1" | awk '{a[NR]=$1} END{print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
med_stock=$(median "$WORK/times.stock"); med_tdem=$(median "$WORK/times.tdem")
awk -v n="$NATOMS" -v s="$STEPS" -v ts="$best_stock" -v tt="$best_tdem" -v qs="$pair_stock" -v qt="$pair_tdem" \
    -v ms="$med_stock" -v mt="$med_tdem" 'BEGIN{
  ps = n * s / ts; pt = n * s / tt;
  printf "particles %d, timed steps %d, best of runs\n", n, s;
  printf "stock hooke/stiffness + history     : %.4g s  %.4g particle-steps/s\n", ts, ps;
  printf "tdem  tdem/lsd + tdem/cundall_strack: %.4g s  %.4g particle-steps/s\n", tt, pt;
  printf "ratio tdem/stock (throughput)       : %.4f  (%+.1f%%)\n", pt / ps, (pt / ps - 1) * 100;
  printf "pair (force) time, best: stock %.4g s, tdem %.4g s, ratio tdem/stock %.4f\n", qs, qt, qt / qs;
  printf "median loop time: stock %.4g s, tdem %.4g s, throughput ratio tdem/stock %.4f\n", ms, mt, ms / mt }'
