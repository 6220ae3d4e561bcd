#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Instruction counts (valgrind callgrind) of the pair compute() of pair tdem/gran against the
# stock LAMMPS style of the same physics, on the two scenes of bench/perf.py (issue 9):
#   chute  bench/in.chute (32000 spheres): gran/hooke/history 2e5 NULL 50 NULL 0.5 0
#          vs tdem/gran normal lsd stiffness 2e5 50 tangential cundall_strack 2/7*2e5 0 0.5
#   bed    the settled bed of bench/perf.py (BUILD/bench_cache/bed<N>.data, made by
#          `bench/perf.py --engines lammps --scenes bed` if missing): gran/hertz/history
#          2e5 NULL 50 NULL 0.5 0 vs tdem/gran normal hertz 3e5 0 damping kuwabara_kono G
#          tangential cundall_strack 0.8 0.5 (the normal law of gran/hertz/history for mobile
#          pairs; the tangential stiffness is not the same, so the bed slips more often)
# Instruction counts do not depend on other load on the machine (wall clock does). Each style
# runs in its own process under callgrind, from the same data, for STEPS steps; the thermo line
# after the run is printed too (for the chute it must be the same for both styles).
#
# With TDEM_CG_COMPARE=grid_correction the two runs per scene are tdem/gran with `grid_correction
# off` and `on` (issue 22: the correction's cost in the pair loop) instead of stock and tdem; with
# TDEM_CG_COMPARE=energy `pair_style tdem/gran` and `pair_style tdem/gran energy yes` (issue 23);
# with TDEM_CG_COMPARE=base tdem/gran of another build's tdem-lammps (TDEM_CG_BASE_EXE, e.g. the
# commit before a change) and of this build: a change that should leave the loop alone.
#
# usage: [TDEM_CG_COMPARE=stock|grid_correction|energy|base] bench/lammps/callgrind_pair.sh [BUILD_DIR]
#        [CHUTE_STEPS] [BED_STEPS] [NATOMS]   (defaults: build, 200, 100, 100000; about 3 minutes)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
chute_steps=${2:-200}
bed_steps=${3:-100}
natoms=${4:-100000}
exe=$build/bin/tdem-lammps
[ -x "$exe" ] || { echo "no $exe (build first)" >&2; exit 1; }
command -v valgrind > /dev/null || { echo "valgrind not found" >&2; exit 1; }
src=${TDEM_LAMMPS_SOURCE:-$( (ls -d /var/cache/tdem/debian-lammps-* /opt/tdem-deps/lammps-* 2>/dev/null || true) | head -1)}
[ -f "$src/bench/data.chute" ] || { echo "no data.chute under $src/bench (set TDEM_LAMMPS_SOURCE)" >&2; exit 1; }
bed=$build/bench_cache/bed$natoms.data
if [ ! -f "$bed" ]; then
  echo "settling the bed once: bench/perf.py --engines lammps --scenes bed --natoms $natoms" >&2
  /usr/bin/python3 "$here/bench/perf.py" --build "$build" --engines lammps --scenes bed --ranks 1 --no-control \
    --natoms "$natoms" --steps 1 --warm 1 --repeats 1 --out "" > /dev/null
fi
work=$(mktemp -d /tmp/tdem_cgpair.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$src/bench/data.chute" "$work/data.chute"
cp "$bed" "$work/bed.data"

KT=$(/usr/bin/python3 -c 'print(repr(200000.0 * 2.0 / 7.0))')
GKK=$(/usr/bin/python3 -c 'print(repr(3.141592653589793 / 12.0 * 50.0 * 0.5))')

compare=${TDEM_CG_COMPARE:-stock}
case $compare in stock) runs="stock tdem" ;; grid_correction) runs="tdem tdem_gc" ;; energy) runs="tdem tdem_energy" ;;
  base) runs="tdem_base tdem"
        [ -x "${TDEM_CG_BASE_EXE:-}" ] || { echo "TDEM_CG_COMPARE=base needs TDEM_CG_BASE_EXE (a tdem-lammps)" >&2; exit 2; } ;;
  *) echo "TDEM_CG_COMPARE=$compare: allowed stock, grid_correction, energy, base" >&2; exit 2 ;; esac

scene() {  # $1 = chute|bed, $2 = stock|tdem|tdem_gc, $3 = steps
  local data grav procs="" inter
  if [ "$1" = chute ]; then
    data=data.chute; grav="fix 1 all gravity 1.0 chute 26.0"
    if [ "$2" = stock ]; then inter=$'pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *'
    else inter=$'pair_style tdem/gran\npair_coeff * * normal lsd stiffness 200000.0 50.0 tangential cundall_strack '"$KT"' 0.0 0.5'; fi
    [ "$2" = tdem_gc ] && inter="$inter grid_correction on"
    [ "$2" = tdem_energy ] && inter=${inter/pair_style tdem\/gran/pair_style tdem\/gran energy yes}
  else
    data=bed.data; grav="fix 1 all gravity 1.0 vector 0.0 0.0 -1.0"; procs="processors * * 1"
    if [ "$2" = stock ]; then inter=$'pair_style gran/hertz/history 200000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *'
    else inter=$'pair_style tdem/gran\npair_coeff * * normal hertz 3e5 0 damping kuwabara_kono '"$GKK"' tangential cundall_strack 0.8 0.5'; fi
    [ "$2" = tdem_gc ] && inter="$inter grid_correction on"
    [ "$2" = tdem_energy ] && inter=${inter/pair_style tdem\/gran/pair_style tdem\/gran energy yes}
  fi
  cat <<EOS
units lj
atom_style sphere
boundary p p fs
newton off
comm_modify vel yes
$procs
read_data $data
$inter
neighbor 0.1 bin
neigh_modify every 1 delay 0
timestep 0.0001
group bottom type 2
group active subtract all bottom
neigh_modify exclude group bottom bottom
$grav
fix 2 bottom freeze
fix 3 active nve/sphere
compute nc all contact/atom
compute snc all reduce sum c_nc
compute 1 all erotate/sphere
thermo_style custom step atoms ke c_1 c_snc
thermo_modify norm no format float %.15g
thermo $3
run $3
EOS
}

echo "callgrind: pair compute() instructions, $(date -u '+%Y-%m-%d %H:%M UTC'), $exe"
echo
echo "| scene | steps | style | total instructions | pair compute() | pair second / first ($runs) | thermo after the run |"
echo "|---|---|---|---|---|---|---|"
. "$here/tools/progress.sh"
set -- $runs
progress_init "chute.$1:1 chute.$2:1 bed.$1:1 bed.$2:1"
first=$1
for sc in chute bed; do
  steps=$chute_steps; [ $sc = bed ] && steps=$bed_steps
  stock_pair=""
  for st in $runs; do
    tag=$sc.$st
    scene $sc $st $steps > "$work/in.$tag"
    run_exe=$exe; [ $st = tdem_base ] && run_exe=$TDEM_CG_BASE_EXE
    (cd "$work" && valgrind --tool=callgrind --callgrind-out-file="cg.$tag" "$run_exe" -in "in.$tag" \
       -log "log.$tag" -echo none -screen none > "vg.$tag" 2>&1)
    total=$(awk '/Collected/ {print $4}' "$work/vg.$tag")
    pair=$(callgrind_annotate --inclusive=yes "$work/cg.$tag" 2>/dev/null |
           grep -E 'PairGranHookeHistory::compute\(|PairGranHertzHistory::compute\(|PairTDEMGran::compute\(' |
           head -1 | awk '{gsub(",", "", $1); print $1}')
    thermo=$(awk '/^ *Step/ {f = 1; next} /^Loop time/ {f = 0} f {l = $0} END {gsub(/^ +| +$/, "", l); gsub(/ +/, " ", l); print l}' "$work/log.$tag")
    if [ $st = "$first" ]; then stock_pair=$pair; ratio=""; else
      ratio=$(awk -v a="$pair" -v b="$stock_pair" 'BEGIN {printf "%.4f", a / b}'); fi
    name="gran/hooke/history"; [ $sc = bed ] && name="gran/hertz/history"
    [ $st != stock ] && { name="tdem/gran lsd + cundall_strack"; [ $sc = bed ] && name="tdem/gran hertz kuwabara_kono + cundall_strack"; }
    [ $st = tdem_gc ] && name="$name, grid_correction on"
    [ $st = tdem_energy ] && name="$name, energy yes"
    [ $st = tdem_base ] && name="$name (base build)"
    echo "| $sc | $steps | \`$name\` | $total | $pair | $ratio | $thermo |"
    progress_done "$tag" >&2  # stderr: stdout is the table
  done
done
