#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of every tangential law of pair tdem/gran per particle-step against the stock
# gran/hooke/history (and gran/hertz/history), in ONE tdem-lammps run, on the scene of
# bench_laws.sh: the LAMMPS benchmark bench/in.chute (32000 spheres of diameter 1 and density 1,
# frozen rough base, 26 degree chute, lj units, dt = 1e-4), mu = 0.5 everywhere.
#
# Styles:
#   stock_hooke          gran/hooke/history 2e5 NULL 50 NULL 0.5 0
#   lsd_cundall_strack   normal lsd stiffness 2e5 50 tangential cundall_strack 2/7*2e5 0 0.5
#                        (= stock_hooke bit for bit; the compile-time specialised path)
#   haff_werner          normal lsd ... tangential haff_werner 6.5 0.5 (gamma_t = m* gamma_n / 2
#                        for two mobile spheres; no memory)
#   linear_spring        normal lsd ... tangential linear_spring 2/7*2e5 0 0 0.5: the physics of
#                        lsd_cundall_strack through the general tangential interface (carried
#                        history incl. omega_t and twist)
#   walton_braun         normal lsd ... tangential walton_braun 2/7*2e5 0 0.5 (8 history values)
#   stock_hertz          gran/hertz/history 2e5 NULL 50 NULL 0.5 0
#   hertz_cundall_strack normal hertz 3e5 0 damping kuwabara_kono G (as bench_laws.sh hertz_kk)
#                        tangential cundall_strack 0.8 0.5
#   mindlin_deresiewicz  same normal law, tangential mindlin_deresiewicz 3e5 0 0.5 (13 values)
#   mindlin_no_slip      same normal law, tangential mindlin_no_slip 3e5 0 1 0.5
#   di_renzo             same normal law, tangential di_renzo 3e5 0 0.5
# The laws change the flow (contacts per particle are printed); the timing is per particle-step.
# The styles run in turn inside one input script (separated by `clear`), REPEATS rounds, the
# order reversed every other round; the best run of each is reported as particle-steps per
# second of wall time (LAMMPS loop time) and per CPU second, with the ratios to stock_hooke and
# stock_hertz, as a Markdown table.
# With CALLGRIND=1 it also counts instructions (valgrind --tool=callgrind, CALLGRIND_STEPS=50
# steps of each style in its own process): total, and inside the pair style's compute().
# usage: [CALLGRIND=1] bench/lammps/bench_tangential.sh [BUILD_DIR] [STEPS] [REPEATS]
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

work=$(mktemp -d /tmp/tdem_bench_tangential.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$data" "$work/"

kt=$(awk 'BEGIN { printf "%.17g", 200000.0 * 2.0 / 7.0 }')
# hertz_kk of bench_laws.sh: G = m* gamma_n sqrt(R*), m* = (pi/6)/2, R* = 1/4
gkk=$(awk 'BEGIN { printf "%.17g", atan2(0, -1) / 12.0 * 50.0 * 0.5 }')
LSD="normal lsd stiffness 200000.0 50.0"
HZ="normal hertz 3e5 0 damping kuwabara_kono $gkk"

names=(stock_hooke lsd_cundall_strack haff_werner linear_spring walton_braun
       stock_hertz hertz_cundall_strack mindlin_deresiewicz mindlin_no_slip di_renzo)
declare -A inter
inter[stock_hooke]="pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *"
inter[stock_hertz]="pair_style gran/hertz/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *"
tdem() { printf 'pair_style tdem/gran\npair_coeff * * %s' "$1"; }
inter[lsd_cundall_strack]=$(tdem "$LSD tangential cundall_strack $kt 0.0 0.5")
inter[haff_werner]=$(tdem "$LSD tangential haff_werner 6.5 0.5")
inter[linear_spring]=$(tdem "$LSD tangential linear_spring $kt 0 0 0.5")
inter[walton_braun]=$(tdem "$LSD tangential walton_braun $kt 0 0.5")
inter[hertz_cundall_strack]=$(tdem "$HZ tangential cundall_strack 0.8 0.5")
inter[mindlin_deresiewicz]=$(tdem "$HZ tangential mindlin_deresiewicz 3e5 0 0.5")
inter[mindlin_no_slip]=$(tdem "$HZ tangential mindlin_no_slip 3e5 0 1 0.5")
inter[di_renzo]=$(tdem "$HZ tangential di_renzo 3e5 0 0.5")

scene() {  # $1 = name
cat <<EOS
print           "bench-style $1"
units           lj
atom_style      sphere
boundary        p p fs
newton          off
comm_modify     vel yes
read_data       data.chute
${inter[$1]}
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
compute         nc all contact/atom
compute         2 all reduce ave c_nc
thermo_style    custom step atoms ke c_1 vol c_2
thermo_modify   norm no format float %.15g
thermo          $steps
run             $steps
clear
EOS
}

: > "$work/in.bench"
for ((i = 0; i < repeats; i++)); do
  if ((i % 2 == 0)); then order=("${names[@]}"); else
    order=(); for ((k = ${#names[@]} - 1; k >= 0; k--)); do order+=("${names[k]}"); done; fi
  for n in "${order[@]}"; do scene "$n" >> "$work/in.bench"; done
done

echo "bench_tangential: ${#names[@]} styles x $repeats rounds x $steps steps, 32000 spheres (in.chute), $(date -u '+%Y-%m-%d %H:%M UTC')"
(cd "$work" && ${TDEM_BENCH_WRAP:-} "$exe" -in in.bench -log log.bench -echo none > out.bench)
awk -v order="${names[*]}" '
  /^bench-style/ { style = $2 }
  $1 == "Step" { getline; getline; nc[style] = $6 }
  /^Loop time of/ { n++; t = $4; st = $9; at = $12; k[n] = style; wall[n] = t; ps[n] = at * st }
  /% CPU use with/ { cpu[n] = t * $1 / 100 }
  END {
    for (i = 1; i <= n; i++) {
      w = ps[i] / wall[i]; c = ps[i] / cpu[i]
      if (w > bw[k[i]]) bw[k[i]] = w
      if (c > bc[k[i]]) bc[k[i]] = c
      runs[k[i]] = runs[k[i]] sprintf("%s%.3g", runs[k[i]] == "" ? "" : ", ", w)
    }
    m = split(order, o, " ")
    print ""
    print "| style | particle-steps/s (best wall) | per cpu-s (best) | vs stock hooke | vs stock hertz | contacts/particle | runs (wall) |"
    print "|---|---|---|---|---|---|---|"
    for (i = 1; i <= m; i++) {
      s = o[i]
      printf "| %s | %.4g | %.4g | %.3f | %.3f | %.3g | %s |\n", s, bw[s], bc[s], bw[s] / bw["stock_hooke"], bw[s] / bw["stock_hertz"], nc[s], runs[s]
    }
  }' "$work/out.bench"
# lsd_cundall_strack and stock_hooke have identical physics: the thermo line after each run agrees
awk '/^bench-style/ { style = $2 } $1 == "Step" { getline; getline; line[style, ++c[style]] = $0 }
     END { same = 1; for (i = 1; i <= c["lsd_cundall_strack"]; i++) if (line["lsd_cundall_strack", i] != line["stock_hooke", 1]) same = 0;
           print ""; print (same ? "thermo after the runs: lsd_cundall_strack identical to stock_hooke" : "thermo after the runs: lsd_cundall_strack DIFFERS from stock_hooke") }' "$work/out.bench"

if [ -n "${CALLGRIND:-}" ]; then
  timed_steps=$steps
  steps=${CALLGRIND_STEPS:-50}
  : > "$work/cg.summary"
  for n in "${names[@]}"; do
    scene "$n" > "$work/cg.in.$n"
    (cd "$work" && valgrind --tool=callgrind --callgrind-out-file="cg.$n" "$exe" -in "cg.in.$n" -log none \
       -echo none -screen none > "cg.$n.txt" 2>&1)
    total=$(grep 'Collected' "$work/cg.$n.txt" | awk '{print $4}')
    pair=$(callgrind_annotate --inclusive=yes "$work/cg.$n" 2>/dev/null |
           grep -E 'PairGranHookeHistory::compute\(|PairGranHertzHistory::compute\(|PairTDEMGran::compute\(' |
           head -1 | awk '{gsub(",","",$1); print $1}')
    echo "$n $total $pair" >> "$work/cg.summary"
  done
  steps=$timed_steps
  awk -v n="${CALLGRIND_STEPS:-50}" '{ s[++m] = $1; t[$1] = $2; p[$1] = $3 } END {
    print ""
    printf "callgrind, %d steps each (instructions; not disturbed by other load):\n\n", n
    print "| style | total | pair compute() | pair vs stock hooke | pair vs stock hertz |"
    print "|---|---|---|---|---|"
    for (i = 1; i <= m; i++)
      printf "| %s | %.4g | %.4g | %.3f | %.3f |\n", s[i], t[s[i]], p[s[i]], p[s[i]] / p["stock_hooke"], p[s[i]] / p["stock_hertz"]
  }' "$work/cg.summary"
fi
