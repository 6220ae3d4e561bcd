#!/bin/bash
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
#   or /var/cache/tdem/debian-lammps-*/bench)
set -eu
BENCH=bench_linear
source "$(dirname "$0")/bench_chute.sh"
chute_setup "$@"
kt=$(python3 -c 'print(repr(200000.0*2.0/7.0))')

names=(stock tdem)
declare -A inter
inter[stock]="pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *"
inter[tdem]="pair_style tdem/gran
pair_coeff * * normal lsd stiffness 200000.0 50.0 tangential cundall_strack $kt 0.0 0.5"

# alternate the order (stock first, then tdem first, ...) so neither style always runs on a
# freshly started process
chute_run
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

chute_callgrind stock tdem
