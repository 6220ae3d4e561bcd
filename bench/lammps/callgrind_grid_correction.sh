#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Instruction counts (valgrind callgrind) of the pair compute() of pair tdem/gran with
# `grid_correction off` and `on` (issue 22), on the chute of bench/perf.py (32000 spheres,
# normal lsd stiffness 2e5 50 + cundall_strack, about 50 steps per contact) and on the settled bed
# of bench/perf.py (hertz kuwabara_kono). Instruction counts do not depend on other load on the
# machine. Each run is its own process under callgrind, from the same data, for STEPS steps; the
# table gives the pair compute (inclusive: the loop, the deferred start/end steps and their law
# evaluations), the ratio on/off and the thermo line after the run.
#
# usage: bench/lammps/callgrind_grid_correction.sh [BUILD_DIR] [CHUTE_STEPS] [BED_STEPS] [NATOMS]
#        (defaults: build, 100, 100, 100000; about 4 minutes)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
chute_steps=${2:-100}
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
work=$(mktemp -d /tmp/tdem_cggc.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$src/bench/data.chute" "$work/data.chute"
cp "$bed" "$work/bed.data"
KT=$(/usr/bin/python3 -c 'print(repr(200000.0 * 2.0 / 7.0))')
GKK=$(/usr/bin/python3 -c 'print(repr(3.141592653589793 / 12.0 * 50.0 * 0.5))')

scene() {  # $1 = chute|bed, $2 = off|on, $3 = steps
  local data grav procs="" law
  if [ "$1" = chute ]; then
    data=data.chute; grav="fix 1 all gravity 1.0 chute 26.0"
    law="normal lsd stiffness 200000.0 50.0 tangential cundall_strack $KT 0.0 0.5"
  else
    data=bed.data; grav="fix 1 all gravity 1.0 vector 0.0 0.0 -1.0"; procs="processors * * 1"
    law="normal hertz 3e5 0 damping kuwabara_kono $GKK tangential cundall_strack 0.8 0.5"
  fi
  cat <<EOS
units lj
atom_style sphere
boundary p p fs
newton off
comm_modify vel yes
$procs
read_data $data
pair_style tdem/gran
pair_coeff * * $law grid_correction $2
neighbor 0.1 bin
neigh_modify every 1 delay 0
timestep 0.0001
group bottom type 2
group active subtract all bottom
neigh_modify exclude group bottom bottom
$grav
fix 2 bottom freeze
fix 3 active nve/sphere
compute 1 all erotate/sphere
thermo_style custom step atoms ke c_1
thermo_modify norm no format float %.15g
thermo $3
run $3
EOS
}

echo "callgrind: pair compute() instructions, grid_correction off / on, $(date -u '+%Y-%m-%d %H:%M UTC'), $exe"
echo
echo "| scene | steps | grid_correction | pair compute() (inclusive) | on / off | thermo after the run |"
echo "|---|---|---|---|---|---|"
. "$here/tools/progress.sh"
progress_init "chute.off:1 chute.on:1 bed.off:1 bed.on:1"
for sc in chute bed; do
  steps=$chute_steps; [ $sc = bed ] && steps=$bed_steps
  off_pair=""
  for gc in off on; do
    tag=$sc.$gc
    scene $sc $gc $steps > "$work/in.$tag"
    (cd "$work" && valgrind --tool=callgrind --callgrind-out-file="cg.$tag" "$exe" -in "in.$tag" \
       -log "log.$tag" -echo none -screen none > "vg.$tag" 2>&1)
    pair=$(callgrind_annotate --inclusive=yes "$work/cg.$tag" 2>/dev/null |
           grep -E 'PairTDEMGran::compute\(' | head -1 | awk '{gsub(",", "", $1); print $1}')
    thermo=$(awk '/^ *Step/ {f = 1; next} /^Loop time/ {f = 0} f {l = $0} END {gsub(/^ +| +$/, "", l); gsub(/ +/, " ", l); print l}' "$work/log.$tag")
    ratio=""
    if [ $gc = off ]; then off_pair=$pair; else ratio=$(awk -v a="$pair" -v b="$off_pair" 'BEGIN {printf "%.4f", a / b}'); fi
    echo "| $sc | $steps | $gc | $pair | $ratio | $thermo |"
    progress_done "$tag" >&2
  done
done
