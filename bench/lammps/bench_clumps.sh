#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of fix tdem/clump against the stock LAMMPS fix rigid/small (issue 6), 1 and 2 ranks.
#
# Scene (the pour of input_scripts/lammps/clumps_pour.in): NCLUMP tetra clumps (4 spheres of
# radius 2 mm at the corners of a tetrahedron of edge 3 mm, density 2500) inserted by fix
# tdem/clump at random positions and orientations into a 0.06 x 0.06 x 0.15 m box (periodic in x
# and y) and poured onto the floor for SETTLE steps (dt = 1e-5 s); the state is written once with
# write_data. Every timed run reads that data file - the same clumps, molecule IDs and velocities -
# with the same interactions (pair tdem/gran + fix tdem/wall/gran: Hertz, Tsuji damping e = 0.6,
# Cundall-Strack mu = 0.5, both fixes export the body mass as m*; gravity; intra-molecule
# exclusion), and integrates the bodies with either
#   tdem    fix tdem/clump ... bodies molecule (splitting rotation; bodies from the molecule IDs)
#   rigid   fix rigid/small molecule (RIGID package of the same LAMMPS library)
# runs 100 untimed steps (run ... post no, setup) and STEPS timed steps. Both fixes live in the
# same executable tdem-lammps (the Debian LAMMPS has RIGID). Reported: LAMMPS "Loop time", the
# "Modify" share (where both rigid-body integrators are counted), particle-steps per second
# (spheres x steps / loop time) and the ratio tdem/rigid of one run each; order tdem, rigid,
# rigid, tdem over the two rank counts. Note: rigid/small takes its body masses from the sphere
# masses: the data file holds the masses fix tdem/clump gave the spheres (the union's mass shared
# by volume), so both fixes see the same total mass (the inertia differs, see validation/clumps).
# Writes bench/results/clumps_lammps.md.
# usage: bench/lammps/bench_clumps.sh [BUILD_DIR] [NCLUMP] [SETTLE] [STEPS]
#   defaults: build, 1000 (4000 spheres), 20000 (0.2 s: the clumps have reached the floor), 2000
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
NCLUMP=${2:-1000}
SETTLE=${3:-20000}
STEPS=${4:-2000}
LMP=$(cd "$BUILD" && pwd)/bin/tdem-lammps
MPIRUN=${MPIRUN:-mpirun}
[ -x "$LMP" ] || { echo "bench_clumps.sh: $LMP not found (build the tdem-lammps target)" >&2; exit 1; }
OUT=$ROOT/bench/results/clumps_lammps.md
WD=$(mktemp -d /tmp/tdem_bench_clumps_XXXXXX)
trap 'rm -rf "$WD"' EXIT
cd "$WD"

HEAD="units si
atom_style sphere
boundary p p f
newton off
comm_modify vel yes
atom_modify map array
processors * * 1
region box block 0 0.06 0 0.06 0 0.15 units box
create_box 1 box
fix pm all property/atom mol ghost yes"
INTER="neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
variable law string \"normal hertz 5e6 0.3 damping tsuji 0.6 tangential cundall_strack 0.8 0.5 limit_force yes\"
pair_style tdem/gran
pair_coeff * * \${law}
fix floor all tdem/wall/gran \${law} zplane 0 NULL
fix g all gravity 9.81 vector 0 0 -1
timestep 1e-5"

cat > in.settle <<EOF
$HEAD
region ins block 0 0.06 0 0.06 0.005 0.145 units box
fix clumps all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 rotation splitting &
    insert $NCLUMP region ins seed 20261129 vel 0 0 -0.5
$INTER
compute nc all contact/atom
compute snc all reduce sum c_nc
thermo_style custom step atoms f_clumps c_snc
thermo 1000
run $SETTLE
write_data settle.data nocoeff
EOF
echo "bench_clumps.sh: settling $NCLUMP tetra clumps for $SETTLE steps (2 ranks) ..."
t0=$(date +%s)
"$MPIRUN" --allow-run-as-root --oversubscribe -np 2 "$LMP" -in in.settle -log log.settle -echo none -screen none
echo "  settled in $(( $(date +%s) - t0 )) s: $(grep -A$((SETTLE / 1000 + 1)) '^ *Step' log.settle | tail -1)"

integ_line() {
  case $1 in
    tdem) echo "fix clumps all tdem/clump template tetra shape tetra 0.002 0.003 density 2500 rotation splitting bodies molecule" ;;
    rigid) echo "fix clumps all rigid/small molecule" ;;
  esac
}

timed() {  # $1 = tdem|rigid, $2 = ranks
  cat > "in.$1" <<EOF
$HEAD
read_data settle.data add append fix pm NULL Molecules
$(integ_line "$1")
$INTER
compute nc all contact/atom
compute snc all reduce sum c_nc
compute kes all ke
thermo_style custom step atoms c_kes c_snc
thermo_modify norm no
thermo $STEPS
run 100
run $STEPS
EOF
  "$MPIRUN" --allow-run-as-root --oversubscribe -np "$2" "$LMP" -in "in.$1" -log "log.$1.$2" -echo none -screen none
  # last run: loop time, Modify time, contacts at the end
  awk -v k="$1" -v np="$2" -v steps="$STEPS" '
    /^Loop time of/ { loop = $4; atoms = $12 }
    /^Modify/ { split($0, a, "|"); modify = a[3] + 0 }
    /% CPU use with/ { cpu = $1 }
    $1 == "Step" { getline; getline; nc = $4 }
    END { printf "%s %d %.4f %.4f %d %d %.0f %s\n", k, np, loop, modify, atoms, steps, nc, cpu }' "log.$1.$2" >> results.txt
}

: > results.txt
load0=$(cut -d' ' -f1-3 /proc/loadavg)
for np in 1 2; do
  if [ $np -eq 1 ]; then order="tdem rigid"; else order="rigid tdem"; fi
  for k in $order; do
    echo "bench_clumps.sh: $k on $np rank(s), $STEPS steps ..."
    timed "$k" "$np"
    tail -1 results.txt
  done
done
load1=$(cut -d' ' -f1-3 /proc/loadavg)

cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
ver=$(grep -m1 '^LAMMPS (' log.tdem.1 || true)
{
  echo "# Clump pour: fix tdem/clump vs stock fix rigid/small (LAMMPS)"
  echo
  echo "Generated by \`bench/lammps/bench_clumps.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'), $cpu, $(nproc) cores"
  echo "(shared with other jobs: load average $load0 before, $load1 after - wall-clock numbers vary"
  echo "by tens of per cent on this machine; the ratio of one run each is what is reported)."
  echo "Executable: tdem-lammps ($ver, the Debian LAMMPS library with the RIGID package) for both fixes."
  echo
  echo "Scene: $NCLUMP tetra clumps ($((NCLUMP * 4)) spheres, r = 2 mm, edge 3 mm, density 2500) poured for"
  echo "$SETTLE steps in a 0.06 x 0.06 x 0.15 m box (periodic x, y), written with write_data and read by"
  echo "every timed run; pair tdem/gran + fix tdem/wall/gran (Hertz E = 5e6, nu = 0.3, Tsuji e = 0.6,"
  echo "Cundall-Strack kappa 0.8, mu 0.5), gravity, dt = 1e-5 s; 100 untimed + $STEPS timed steps."
  echo
  echo "| ranks | fix | loop time (s) | Modify (s) | particle-steps/s | tdem/rigid | contacts at the end | CPU use (LAMMPS) |"
  echo "|---|---|---|---|---|---|---|---|"
  awk '{ ps[$1 " " $2] = $5 * $6 / $3; line[NR] = $0 }
       END { for (i = 1; i <= NR; i++) { split(line[i], f, " ");
               r = (f[1] == "tdem") ? sprintf("%.3f", ps["tdem " f[2]] / ps["rigid " f[2]]) : "";
               printf "| %d | %s | %.3f | %.3f | %.3e | %s | %d | %s |\n", f[2], (f[1] == "tdem" ? "`tdem/clump`" : "`rigid/small`"),
                      f[3], f[4], f[5] * f[6] / f[3], r, f[7], f[8] } }' results.txt
  echo
  echo "Note: fix tdem/clump keeps every body on every rank (\"global bodies\", like fix rigid) and"
  echo "advances all of them on each rank; fix rigid/small keeps each body on the rank of its owning"
  echo "atom. The body cost therefore does not shrink with more ranks for tdem/clump."
  echo "\"CPU use\" is LAMMPS's ratio of CPU to wall time per rank: far below 100 % means the ranks"
  echo "were descheduled by other jobs (MPI ranks then wait for each other), so those wall times"
  echo "measure the machine load more than the code."
  echo
  echo "Stock LIGGGHTS fix multisphere in the same box with the same shapes (reference for a later"
  echo "LIGGGHTS fix tdem/clump): bench/liggghts/bench_clumps.sh -> bench/results/clumps_liggghts.md."
} > "$OUT"
cat "$OUT"
