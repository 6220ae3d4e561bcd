#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of fix tdem/integrate (every scheme) against fix nve/sphere in LAMMPS, 1 rank.
#
# Scene: a bed of ~2600 spheres (diameters 4.0-4.8 mm, density 2500, the scene of
# tests/host/lammps/lmp_common.py) settled for SETTLE steps under gravity in a box with
# frictional walls (pair tdem/gran + fix tdem/wall/gran, lsd + Cundall-Strack, dt = 2e-5),
# written once with write_data; then for each integrator one tdem-lammps run of STEPS steps from
# that state. Reported: LAMMPS "Loop time" and the "Modify" section time (where the integrator,
# the walls and gravity are counted) of each run, their ratios to nve/sphere, and the history
# doubles per atom (from the fix's log line; plus one flag double). nve/sphere runs first and
# last; the reference is the faster of the two. Wall clock on a shared machine varies by +-10 %.
# Writes validation/integrators/results/cost_lammps.csv (scheme,ratio_to_nve_sphere,history_doubles;
# ratio = loop time ratio) and prints a Markdown table.
# usage: bench/lammps/bench_integrate.sh [BUILD_DIR] [STEPS] [SETTLE]
#   BUILD_DIR default build (tdem-lammps is BUILD_DIR/bin/tdem-lammps); STEPS default 2000;
#   SETTLE default 6000
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
STEPS=${2:-2000}
SETTLE=${3:-6000}
LMP=$BUILD/bin/tdem-lammps
[ -x "$LMP" ] || { echo "bench_integrate.sh: $LMP not found (build the tdem-lammps target)" >&2; exit 1; }
OUT=$ROOT/validation/integrators/results/cost_lammps.csv
mkdir -p "$(dirname "$OUT")"
WD=$(mktemp -d /tmp/tdem_bench_integrate_XXXXXX)
trap 'rm -rf "$WD"' EXIT
cd "$WD"

LAW="normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5"
INTER="pair_style tdem/gran
pair_coeff * * $LAW
fix w0 all tdem/wall/gran $LAW xplane 0 0.1
fix w1 all tdem/wall/gran $LAW yplane 0 0.1
fix w2 all tdem/wall/gran $LAW zplane 0 0.2
fix g all gravity 9.81 vector 0 0 -1"

cat > in.settle <<EOF
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block 0 0.1 0 0.1 0 0.2 units box
create_box 1 box
lattice sc 0.0052
region fill block 0.003 0.097 0.003 0.097 0.003 0.045 units box
create_atoms 1 region fill
variable d atom 0.0040+0.0008*random(0,1,4711)
set group all diameter v_d
set group all density 2500
variable vx atom 0.05*(random(0,1,13)-0.5)
variable vy atom 0.05*(random(0,1,17)-0.5)
variable vz atom 0.05*(random(0,1,19)-0.5)
velocity all set v_vx v_vy v_vz
neighbor 0.001 bin
neigh_modify delay 0
$INTER
fix nve all nve/sphere
timestep 2e-5
run $SETTLE
write_data bed.data nocoeff
EOF
"$LMP" -in in.settle -log log.settle -echo none -screen none

run_one() {  # $1 label, $2 fix line
  cat > in.$1 <<EOF
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
read_data bed.data
neighbor 0.001 bin
neigh_modify delay 0
$INTER
$2
timestep 2e-5
thermo 1000
run $STEPS
EOF
  "$LMP" -in in.$1 -log log.$1 -echo none -screen none
}

SCHEMES="euler symplectic_euler taylor2 taylor3 leapfrog position_verlet velocity_verlet
velocity_verlet_sync beeman ab2 ab3 ab4 ab5 abm4 gear4 gear5 gear6"
run_one nve_first "fix nve all nve/sphere"
. "$ROOT/tools/progress.sh"
_st=""
for s in $SCHEMES; do _st="$_st $s:1"; done
progress_init "$_st"
for s in $SCHEMES; do run_one "$s" "fix nve all tdem/integrate scheme $s"; progress_done "$s"; done
run_one nve_last "fix nve all nve/sphere"

/usr/bin/python3 - "$OUT" "$STEPS" $SCHEMES <<'EOF'
import re, sys
out, steps, schemes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]

def parse(label):
    text = open("log." + label).read()
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+) on", text).group(1))
    natoms = int(re.search(r"for \d+ steps with (\d+) atoms", text).group(1))
    modify = float(re.search(r"^Modify\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)", text, re.M).group(1))
    m = re.search(r"tdem/integrate: scheme \S+ \(.*\), rotation \S+: (\d+) doubles", text)
    return loop, modify, natoms, int(m.group(1)) if m else 0

first, last = parse("nve_first"), parse("nve_last")
ref = first if first[0] <= last[0] else last
print("%d atoms, %d steps, 1 rank; fix nve/sphere: loop %.3f s (first) / %.3f s (last), Modify %.3f / %.3f s"
      % (ref[2], steps, first[0], last[0], first[1], last[1]))
print()
print("| scheme | loop time [s] | ratio to nve/sphere | Modify [s] | Modify ratio | history doubles/atom |")
print("|---|---|---|---|---|---|")
print("| nve/sphere | %.3f | 1.000 | %.3f | 1.000 | 0 |" % (ref[0], ref[1]))
rows = []
for s in schemes:
    loop, modify, _, nh = parse(s)
    rows.append((s, loop / ref[0], nh))
    print("| %s | %.3f | %.3f | %.3f | %.3f | %d |" % (s, loop, loop / ref[0], modify, modify / ref[1], nh))
with open(out, "w") as f:
    f.write("scheme,ratio_to_nve_sphere,history_doubles\n")
    for s, r, nh in rows:
        f.write("%s,%.4f,%d\n" % (s, r, nh))
print()
print("written: " + out)
EOF
