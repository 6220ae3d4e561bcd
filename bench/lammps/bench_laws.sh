#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Speed of every normal law of pair tdem/gran against the stock pair styles, in ONE tdem-lammps
# run, on the scene of bench_linear.sh: the LAMMPS benchmark bench/in.chute (32000 spheres of
# diameter 1 and density 1, frozen rough base, 26 degree chute, lj units, dt = 1e-4).
#
# Styles (each with tangential cundall_strack, mu = 0.5):
#   stock_hooke      gran/hooke/history 2e5 NULL 50 NULL 0.5 0
#   stock_hertz      gran/hertz/history 2e5 NULL 50 NULL 0.5 0
#                    (LAMMPS multiplies spring AND dashpot by sqrt(xi R*): F = sqrt(xi R*)
#                    (kn xi + m* gamma_n xi'), i.e. Hertz with a Kuwabara-Kono-type dashpot
#                    m* gamma_n sqrt(R*) sqrt(xi) xi')
#   lsd              normal lsd stiffness 2e5 50 (= stock_hooke, bit for bit)
#   lsd_restitution  normal lsd restitution 0.7 3.6e-3
#   hertz_kk         normal hertz E NU damping kuwabara_kono G with 4/3 E* = kn (E = 3e5, NU = 0)
#                    and G = m* gamma_n sqrt(R*) for two mobile spheres: the same physics as
#                    stock_hertz for mobile-mobile contacts (the equal-complexity comparison)
#   hertz_tsuji      normal hertz 3e5 0 damping tsuji 0.7 (one sqrt(m* k~ sqrt(xi)) more)
#   walton_braun     normal walton_braun 2e5 4.08e5 (e = 0.7)
#   thornton         normal thornton 3e5 0 3000 (limiting pressure 3000)
#   power_law        normal power_law 1e5 1.5 2.915e5 (a_l = k~ of hertz, e = 0.7)
#   power_law_p1     normal power_law 2e5 1 4.08e5: the physics of walton_braun (p = 1, q = 0)
#   ext_linear       normal extended_linear e_fit constant 0.7 tc_fit constant 3.6e-3: the
#                    physics of lsd_restitution (k, gamma from the history instead of the table)
#   ext_linear_fit   normal extended_linear e_fit rational 1 1 0.2 tc_fit power 3.6e-3 0.2
#                    (velocity-dependent; v0 in lj units)
#   ext_hertz        normal extended_hertz 3e5 0 e_fit constant 0.7: the physics of hertz_tsuji
#   ext_hertz_fit    normal extended_hertz 3e5 0 e_fit rational 1 1 0.2
# The pairs with the same physics (lsd_restitution / ext_linear, hertz_tsuji / ext_hertz,
# walton_braun / power_law_p1) give the cost of the new laws' machinery (history slots, first
# touch, pow) at equal contact numbers; the other laws change the flow itself (overlaps, number
# of contacts: see the column "contacts/particle", counted at the end of the run).
# The styles run in turn inside one input script (separated by `clear`), REPEATS rounds, the
# order reversed every other round; the best run of each is reported as particle-steps per
# second of wall time (LAMMPS loop time) and per CPU second, with the ratios to stock_hooke and
# stock_hertz, as a Markdown table. Wall-clock varies by about +-10 % on a shared machine.
#
# With CALLGRIND=1 it also counts instructions (valgrind --tool=callgrind, CALLGRIND_STEPS=50
# steps of each style in its own process): total, and inside the pair style's compute(), a
# measure that other load on the machine does not disturb.
# usage: [CALLGRIND=1] bench/lammps/bench_laws.sh [BUILD_DIR] [STEPS] [REPEATS]
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

work=$(mktemp -d /tmp/tdem_bench_laws.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$data" "$work/"

kt=$(awk 'BEGIN { printf "%.17g", 200000.0 * 2.0 / 7.0 }')
# hertz_kk: G = m* gamma_n sqrt(R*), m* = (pi/6)/2, R* = 1/4
gkk=$(awk 'BEGIN { printf "%.17g", atan2(0, -1) / 12.0 * 50.0 * 0.5 }')
TS="tangential cundall_strack 0.8 0.5"

names=(stock_hooke stock_hertz lsd lsd_restitution hertz_kk hertz_tsuji walton_braun thornton
       power_law power_law_p1 ext_linear ext_linear_fit ext_hertz ext_hertz_fit)
declare -A inter
inter[stock_hooke]="pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *"
inter[stock_hertz]="pair_style gran/hertz/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *"
inter[lsd]="pair_style tdem/gran
pair_coeff * * normal lsd stiffness 200000.0 50.0 tangential cundall_strack $kt 0.0 0.5"
tdem() { printf 'pair_style tdem/gran\npair_coeff * * %s %s' "$1" "$TS"; }
inter[lsd_restitution]=$(tdem "normal lsd restitution 0.7 3.6e-3")
inter[hertz_kk]=$(tdem "normal hertz 3e5 0 damping kuwabara_kono $gkk")
inter[hertz_tsuji]=$(tdem "normal hertz 3e5 0 damping tsuji 0.7")
inter[walton_braun]=$(tdem "normal walton_braun 2e5 4.08e5")
inter[thornton]=$(tdem "normal thornton 3e5 0 3000")
inter[power_law]=$(tdem "normal power_law 1e5 1.5 2.915e5")
inter[power_law_p1]=$(tdem "normal power_law 2e5 1 4.08e5")
inter[ext_linear]=$(tdem "normal extended_linear e_fit constant 0.7 tc_fit constant 3.6e-3")
inter[ext_linear_fit]=$(tdem "normal extended_linear e_fit rational 1 1 0.2 tc_fit power 3.6e-3 0.2")
inter[ext_hertz]=$(tdem "normal extended_hertz 3e5 0 e_fit constant 0.7")
inter[ext_hertz_fit]=$(tdem "normal extended_hertz 3e5 0 e_fit rational 1 1 0.2")

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

echo "bench_laws: ${#names[@]} styles x $repeats rounds x $steps steps, 32000 spheres (in.chute), $(date -u '+%Y-%m-%d %H:%M UTC')"
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
# lsd and stock_hooke have identical physics: the thermo line after each of their runs agrees
awk '/^bench-style/ { style = $2 } $1 == "Step" { getline; getline; line[style, ++c[style]] = $0 }
     END { same = 1; for (i = 1; i <= c["lsd"]; i++) if (line["lsd", i] != line["stock_hooke", 1]) same = 0;
           print ""; print (same ? "thermo after the runs: lsd identical to stock_hooke" : "thermo after the runs: lsd DIFFERS from stock_hooke") }' "$work/out.bench"

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
