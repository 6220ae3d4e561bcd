#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Grate showcase scenes (issue 7) on 2 MPI ranks and their analysis (README.md in this directory):
#   input_scripts/liggghts/grate_forward_2d.in   forward-acting grate, disks, enforce2d
#   input_scripts/liggghts/grate_forward_3d.in   forward-acting grate, spheres, periodic width
#   input_scripts/liggghts/grate_reverse_3d.in   reverse-acting grate, steeper (18 deg instead of 10 deg)
#   the forward 3D scene with stroke 0 and a finite feed (standing grate: P' -> 0), at dt and dt/2
# then analyse.py: P' and Q' over time and along the grate, the comparison table, the residence-time
# distribution and the sanity checks (exit status 1 if one fails).
#
#   validation/grate/run.sh [--short | --long]
#
# --short: 1.5 s of grate time per scene (about a minute on 2 cores), written to WORKDIR/results;
# without: 20 s per scene, the plots and table go to validation/grate/results/.
# --long: the large grates instead: the forward scenes with 8 rows, in 2D with disks of 4.5 and 5.5 mm
# (dscale 0.5) fed at 240 per second, in 3D 120 mm wide fed at 180 spheres per second, 60 s each, so
# that the bed holds more than 2000 particles and the mixing measures are stationary over the
# evaluation window (30 - 60 s); results in validation/grate/results/long/ (about 6 min on 2 cores).
# Environment: TDEM_LIGGGHTS (executable, default build/bin/tdem-liggghts), VTKOUT (interval of the
# VTK files in seconds of grate time, default 0.5; 0.05 gives the frames of an animation), WORKDIR (run directory,
# default validation/grate/work), RESULTS (overrides the results directory), MPIRUN (default "mpirun
# --allow-run-as-root --oversubscribe --bind-to none --mca mpi_yield_when_idle 1 -np 2": ranks that yield
# when idle, which matters on a shared machine).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
short=0
for a in "$@"; do
  case $a in
    --short) short=1 ;;
    --long) short=2 ;;
    *) echo "run.sh: unknown argument '$a' (allowed: --short, --long)" >&2; exit 2 ;;
  esac
done
exe=${TDEM_LIGGGHTS:-$root/build/bin/tdem-liggghts}
case $exe in /*) ;; *) exe="$(pwd)/$exe" ;; esac
if [ ! -x "$exe" ]; then
  echo "run.sh: tdem-liggghts not found at '$exe' (build it, or set TDEM_LIGGGHTS)" >&2
  exit 2
fi
mpirun=${MPIRUN:-mpirun --allow-run-as-root --oversubscribe --bind-to none --mca mpi_yield_when_idle 1 -np 2}
work=${WORKDIR:-$here/work}
if [ "$short" = 1 ]; then
  tend=1.5; stop_n=60; stop_t=1.5; results=${RESULTS:-$work/results}; opt=--short
elif [ "$short" = 2 ]; then
  tend=${TEND:-60}; results=${RESULTS:-$here/results/long}; opt=--long
else
  tend=20; stop_n=200; stop_t=4; results=${RESULTS:-$here/results}; opt=
fi
rm -rf "$work"
mkdir -p "$work" "$results" || exit 2
# Open MPI 4.1 keeps a session directory in $TMPDIR that concurrent runs race on (see
# tests/host/mpi_env.py): this script's runs get a directory of their own
TMPDIR=$(mktemp -d /tmp/tdem_mpi_XXXXXX) || exit 2
export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT
scenes="$root/input_scripts/liggghts"
. "$root/tools/progress.sh"
if [ "$short" = 2 ]; then
  progress_init "fwd2dL:2 fwd3dL:3 analyse:1"
else
  progress_init "fwd2d:3 fwd3d:6 rev3d:6 stop3d:1 stop3d_dt1:2 analyse:1"
fi

run_scene() { # $1 scene file, $2 tag, further args: -var pairs
  in=$1; tag=$2; shift 2
  t0=$(date +%s)
  # shellcheck disable=SC2086
  (cd "$work" && $mpirun "$exe" -in "$scenes/$in" -var tag "$tag" -var vtkout "${VTKOUT:-0.5}" "$@" -log "log.$tag" -echo none \
    -screen /dev/null) || { echo "run.sh: $in ($tag) failed, see $work/log.$tag" >&2; exit 2; }
  echo "  $tag: $in $*: $(( $(date +%s) - t0 )) s, $(grep -c . "$work/${tag}_series.txt") output lines"
  progress_done "$tag"
}
echo "grate scenes in $work (tend = $tend s per scene, 2 ranks, $exe)"
if [ "$short" = 2 ]; then
  run_scene grate_forward_2d.in fwd2dL -var tend "$tend" -var rows 8 -var dscale 0.5 -var rate 240 || exit 2
  run_scene grate_forward_3d.in fwd3dL -var tend "$tend" -var rows 8 -var width 0.12 -var rate 180 || exit 2
  /usr/bin/python3 "$here/analyse.py" "$work" "$results" --long
  status=$?
  progress_done analyse
  echo "results: $results (table.md, mixing_time.png, mixing_along.png, residence.png, checks.txt)"
  exit $status
fi
run_scene grate_forward_2d.in fwd2d -var tend "$tend" || exit 2
run_scene grate_forward_3d.in fwd3d -var tend "$tend" || exit 2
run_scene grate_reverse_3d.in rev3d -var tend "$tend" || exit 2
run_scene grate_forward_3d.in stop3d -var tend "$stop_t" -var stroke 0 -var npart "$stop_n" || exit 2
run_scene grate_forward_3d.in stop3d_dt1 -var tend "$stop_t" -var stroke 0 -var npart "$stop_n" -var dt 1e-4 || exit 2
echo "VTK files: $(ls "$work"/*.vtp "$work"/*.vtk 2>/dev/null | wc -l) (bars: <tag>_bars_<step>.vtp with the series <tag>_bars.pvd, particles: <tag>_atoms_<step>.vtk)"

# shellcheck disable=SC2086
/usr/bin/python3 "$here/analyse.py" "$work" "$results" $opt
status=$?
progress_done analyse
echo "results: $results (table.md, mixing_time.png, mixing_along.png, residence.png, checks.txt)"
exit $status
