#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Shared part of bench_linear.sh, bench_laws.sh and bench_tangential.sh (sourced, not run): the
# LAMMPS benchmark scene bench/in.chute (32000 spheres of diameter 1 and density 1, frozen rough
# base, 26 degree chute, lj units, dt = 1e-4) for every style NAME of the caller's array `names`
# with the interaction lines ${inter[NAME]}, the timed runs inside one tdem-lammps process, the
# Markdown table and the callgrind counts.
# The caller sets BENCH (its name) and calls, in this order:
#   chute_setup "$@"          arguments [BUILD_DIR] [STEPS] [REPEATS]; sets exe, work, steps, repeats
#   chute_run                 REPEATS rounds of all styles in one input (order reversed every other
#                             round, separated by `clear`); output in $work/out.bench
#   chute_table A B           table of the best particle-steps/s with ratios to styles A and B
#   chute_identical A B       whether the thermo after every run of B equals the first of A
#   chute_callgrind A B       with CALLGRIND=1: instructions (CALLGRIND_STEPS=50 steps of each style
#                             in its own process), total and in the pair style's compute()
# optional: integrate[NAME] replaces the line "fix 3 active nve/sphere" of style NAME
declare -A integrate=()

chute_setup() {
  here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  build=$(cd "${1:-$here/build}" && pwd)
  steps=${2:-1000}
  repeats=${3:-2}
  exe=$build/bin/tdem-lammps
  [ -x "$exe" ] || { echo "no $exe (build first)" >&2; exit 1; }
  local src=${TDEM_LAMMPS_SOURCE:-$(ls -d /var/cache/tdem/debian-lammps-* /opt/tdem-deps/lammps-* 2>/dev/null | head -1)}
  local data=$src/bench/data.chute
  [ -f "$data" ] || { echo "no data.chute under $src/bench (set TDEM_LAMMPS_SOURCE)" >&2; exit 1; }
  work=$(mktemp -d "/tmp/tdem_$BENCH.XXXXXX")
  trap 'rm -rf "$work"' EXIT
  cp "$data" "$work/"
}

chute_scene() {  # $1 = style name
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
${integrate[$1]:-fix             3 active nve/sphere}
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

chute_run() {
  : > "$work/in.bench"
  local i k n order
  for ((i = 0; i < repeats; i++)); do
    if ((i % 2 == 0)); then order=("${names[@]}"); else
      order=(); for ((k = ${#names[@]} - 1; k >= 0; k--)); do order+=("${names[k]}"); done; fi
    for n in "${order[@]}"; do chute_scene "$n" >> "$work/in.bench"; done
  done
  echo "$BENCH: ${#names[@]} styles x $repeats rounds x $steps steps, 32000 spheres (in.chute), $(date -u '+%Y-%m-%d %H:%M UTC')"
  # one process for all runs: a progress line (with the remaining time) when a run ends
  local total=$((${#names[@]} * repeats)) t0 k=0 line
  t0=$(date +%s)
  (cd "$work" && ${TDEM_BENCH_WRAP:-} "$exe" -in in.bench -log log.bench -echo none) | tee "$work/out.bench" |
    while IFS= read -r line; do
      case $line in
        "Loop time of"*)
          k=$((k + 1))
          el=$(($(date +%s) - t0))
          echo "[progress] run $k/$total done; elapsed $el s, about $((el * (total - k) / k)) s to go" ;;
      esac
    done
  [ "${PIPESTATUS[0]}" = 0 ] || { echo "$BENCH: tdem-lammps failed (see $work/log.bench)" >&2; exit 1; }
}

chute_table() {  # $1, $2 = reference styles of the two ratio columns
  awk -v order="${names[*]}" -v r1="$1" -v r2="$2" '
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
      print "| style | particle-steps/s (best wall) | per cpu-s (best) | vs " r1 " | vs " r2 " | contacts/particle | runs (wall) |"
      print "|---|---|---|---|---|---|---|"
      for (i = 1; i <= m; i++) {
        s = o[i]
        printf "| %s | %.4g | %.4g | %.3f | %.3f | %.3g | %s |\n", s, bw[s], bc[s], bw[s] / bw[r1], bw[s] / bw[r2], nc[s], runs[s]
      }
    }' "$work/out.bench"
}

chute_identical() {  # $1 = reference style, $2 = style with the same physics
  awk -v a="$1" -v b="$2" '/^bench-style/ { style = $2 } $1 == "Step" { getline; getline; line[style, ++c[style]] = $0 }
       END { same = c[b] > 0; for (i = 1; i <= c[b]; i++) if (line[b, i] != line[a, 1]) same = 0;
             print ""; print "thermo after the runs: " b (same ? " identical to " : " DIFFERS from ") a }' "$work/out.bench"
}

chute_callgrind() {  # $1, $2 = reference styles of the two ratio columns
  [ -n "${CALLGRIND:-}" ] || return 0
  local timed_steps=$steps n total pair
  steps=${CALLGRIND_STEPS:-50}
  : > "$work/cg.summary"
  for n in "${names[@]}"; do
    chute_scene "$n" > "$work/cg.in.$n"
    (cd "$work" && valgrind --tool=callgrind --callgrind-out-file="cg.$n" "$exe" -in "cg.in.$n" -log none \
       -echo none -screen none > "cg.$n.txt" 2>&1)
    total=$(grep 'Collected' "$work/cg.$n.txt" | awk '{print $4}')
    pair=$(callgrind_annotate --inclusive=yes "$work/cg.$n" 2>/dev/null |
           grep -E 'PairGranHookeHistory::compute\(|PairGranHertzHistory::compute\(|PairTDEMGran::compute\(' |
           head -1 | awk '{gsub(",","",$1); print $1}')
    echo "$n $total $pair" >> "$work/cg.summary"
  done
  steps=$timed_steps
  awk -v n="${CALLGRIND_STEPS:-50}" -v r1="$1" -v r2="$2" '{ s[++m] = $1; t[$1] = $2; p[$1] = $3 } END {
    print ""
    printf "callgrind, %d steps each (instructions; not disturbed by other load):\n\n", n
    print "| style | total | pair compute() | pair vs " r1 " | pair vs " r2 " |"
    print "|---|---|---|---|---|"
    for (i = 1; i <= m; i++)
      printf "| %s | %.4g | %.4g | %.3f | %.3f |\n", s[i], t[s[i]], p[s[i]], p[s[i]] / p[r1], p[s[i]] / p[r2]
  }' "$work/cg.summary"
}
