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
#   or /var/cache/tdem/debian-lammps-*/bench)
set -eu
BENCH=bench_laws
source "$(dirname "$0")/bench_chute.sh"
chute_setup "$@"

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

chute_run
chute_table stock_hooke stock_hertz
# lsd and stock_hooke have identical physics: the thermo line after each of their runs agrees
chute_identical stock_hooke lsd
chute_callgrind stock_hooke stock_hertz
