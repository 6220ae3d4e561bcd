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
#   or /var/cache/tdem/debian-lammps-*/bench)
set -eu
BENCH=bench_tangential
source "$(dirname "$0")/bench_chute.sh"
chute_setup "$@"

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

chute_run
chute_table stock_hooke stock_hertz
# lsd_cundall_strack and stock_hooke have identical physics: the thermo line after each of their runs agrees
chute_identical stock_hooke lsd_cundall_strack
chute_callgrind stock_hooke stock_hertz
