#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Speed of pair tdem/gran (normal lsd stiffness + tangential cundall_strack) against the stock
# pair gran/hooke/history with the same physics, in one tdem-lammps run, on the LAMMPS
# benchmark scene bench/in.chute (32000 spheres, frozen rough base, 26 degree chute).
# The two styles alternate (stock, tdem, tdem, stock, ...) inside one input script, separated
# by `clear`; the best of each is reported as particle-steps per second of wall time (LAMMPS
# loop time) and per CPU second (loop time x LAMMPS's '% CPU use'; less sensitive to other
# processes on a shared machine).
# The thermo output of the two styles is also compared (identical physics => identical lines).
#
# With CALLGRIND=1 it also counts instructions (valgrind --tool=callgrind, CALLGRIND_STEPS=50
# steps of each style in its own process): total and inside the pair style's compute(), a
# measure that other load on the machine does not disturb.
# usage: [CALLGRIND=1] bench/lammps/bench_linear.sh [BUILD_DIR] [STEPS] [REPEATS]
#   BUILD_DIR  default build (tdem-lammps is BUILD_DIR/bin/tdem-lammps)
#   needs data.chute: from $TDEM_LAMMPS_SOURCE/bench (default: /opt/tdem-deps/lammps-*/bench
#   or /var/cache/tdem/lammps-*/bench)
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
steps=${2:-1000}
repeats=${3:-2}
exe=$build/bin/tdem-lammps
[ -x "$exe" ] || { echo "no $exe (build first)" >&2; exit 1; }
src=${TDEM_LAMMPS_SOURCE:-$(ls -d /var/cache/tdem/lammps-* /opt/tdem-deps/lammps-* 2>/dev/null | head -1)}
data=$src/bench/data.chute
[ -f "$data" ] || { echo "no data.chute under $src/bench (set TDEM_LAMMPS_SOURCE)" >&2; exit 1; }

work=$(mktemp -d /tmp/tdem_bench_lammps.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$data" "$work/"
kt=$(python3 -c 'print(repr(200000.0*2.0/7.0))')

scene() {  # $1 = name, $2 = interaction lines
cat <<EOS
print           "bench-style $1"
units           lj
atom_style      sphere
boundary        p p fs
newton          off
comm_modify     vel yes
read_data       data.chute
$2
neighbor        0.1 bin
neigh_modify    every 1 delay 0
timestep        0.0001
group           bottom type 2
group           active subtract all bottom
neigh_modify    exclude group bottom bottom
fix             1 all gravity 1.0 chute 26.0
fix             2 bottom freeze
fix             3 active nve/sphere
compute         1 all erotate/sphere
thermo_style    custom step atoms ke c_1 vol
thermo_modify   norm no format float %.15g
thermo          $steps
run             $steps
clear
EOS
}
stock="pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *"
tdem="pair_style tdem/gran
pair_coeff * * normal lsd stiffness 200000.0 50.0 tangential cundall_strack $kt 0.0 0.5"

: > "$work/in.bench"
i=0
# alternate the order (stock first, then tdem first, ...) so neither style always runs on a
# freshly started process
while [ $i -lt "$repeats" ]; do
  if [ $((i % 2)) -eq 0 ]; then
    scene stock "$stock" >> "$work/in.bench"; scene tdem "$tdem" >> "$work/in.bench"
  else
    scene tdem "$tdem" >> "$work/in.bench"; scene stock "$stock" >> "$work/in.bench"
  fi
  i=$((i + 1))
done

(cd "$work" && ${TDEM_BENCH_WRAP:-} "$exe" -in in.bench -log log.bench -echo none > out.bench)
awk '
  function median(s,   m, a, i, j, t) {
    m = ns[s]; for (i = 1; i <= m; i++) a[i] = v[s, i]
    for (i = 2; i <= m; i++) { t = a[i]; j = i - 1; while (j >= 1 && a[j] > t) { a[j + 1] = a[j]; j-- } a[j + 1] = t }
    return (m % 2) ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2
  }
  /^bench-style/ { style = $2 }
  /^Loop time of/ { n++; t = $4; st = $9; at = $12; k[n] = style; wall[n] = t; ps[n] = at * st }
  /% CPU use with/ { cpu[n] = t * $1 / 100 }
  END {
    for (i = 1; i <= n; i++) {
      w = ps[i] / wall[i]; c = ps[i] / cpu[i];
      printf "run %d %-5s loop %.3f s (cpu %.3f s): %.4g particle-steps/s wall, %.4g per cpu-second\n", i, k[i], wall[i], cpu[i], w, c
      ns[k[i]]++; v[k[i], ns[k[i]]] = w
      if (w > bw[k[i]]) bw[k[i]] = w
      if (c > bc[k[i]]) bc[k[i]] = c
    }
    printf "stock gran/hooke/history:         %.4g particle-steps/s (best wall), %.4g per cpu-s\n", bw["stock"], bc["stock"]
    printf "tdem/gran (lsd + cundall_strack): %.4g particle-steps/s (best wall), %.4g per cpu-s\n", bw["tdem"], bc["tdem"]
    printf "ratio tdem/stock: %.3f (best wall), %.3f (best cpu), %.3f (median wall: %.4g vs %.4g)\n", bw["tdem"] / bw["stock"], bc["tdem"] / bc["stock"], median("tdem") / median("stock"), median("tdem"), median("stock")
  }' "$work/out.bench"
# identical physics: the last thermo line of each stock run equals that of the next tdem run
awk '$1 == "Step" { getline; getline; line[++n] = $0 }
     END { same = 1; for (i = 2; i <= n; i++) if (line[i] != line[1]) same = 0;
           print (same ? "thermo after every run: identical for stock and tdem" : "thermo after the runs: DIFFERENT") }' "$work/out.bench"

if [ -n "${CALLGRIND:-}" ]; then
  timed_steps=$steps
  steps=${CALLGRIND_STEPS:-50}
  for m in stock tdem; do
    if [ $m = stock ]; then scene stock "$stock" > "$work/cg.in.$m"; else scene tdem "$tdem" > "$work/cg.in.$m"; fi
    (cd "$work" && valgrind --tool=callgrind --callgrind-out-file=cg.$m "$exe" -in cg.in.$m -log none \
       -echo none -screen none > cg.$m.txt 2>&1)
    total=$(grep 'Collected' "$work/cg.$m.txt" | awk '{print $4}')
    pair=$(callgrind_annotate --inclusive=yes "$work/cg.$m" 2>/dev/null |
           grep -E 'PairGranHookeHistory::compute\(|PairTDEMGran::compute\(' | head -1 | awk '{gsub(",","",$1); print $1}')
    echo "$m $total $pair" >> "$work/cg.summary"
  done
  steps=$timed_steps
  awk -v n="${CALLGRIND_STEPS:-50}" '{t[$1]=$2; p[$1]=$3} END{
    printf "callgrind, %d steps: instructions total stock %.4g, tdem %.4g, ratio %.4f\n", n, t["stock"], t["tdem"], t["tdem"]/t["stock"];
    printf "callgrind, %d steps: instructions in pair compute() stock %.4g, tdem %.4g, ratio %.4f\n", n, p["stock"], p["tdem"], p["tdem"]/p["stock"] }' "$work/cg.summary"
fi
