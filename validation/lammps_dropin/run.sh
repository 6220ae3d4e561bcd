#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The third way to use tdem with LAMMPS, checked end to end: copy the styles into a copy of a
# LAMMPS source tree (tools/lammps_dropin.sh), build that LAMMPS with its own CMake (no tdem
# build system involved, about 6 minutes on 2 cores), and check that its `lmp -h` lists every
# tdem style and that input_scripts/lammps/in.tdem_settle gives the same thermo output as
# tdem-lammps of the same version.
#
#   bash validation/lammps_dropin/run.sh [LAMMPS_DIR] [BUILD_DIR]
#     LAMMPS_DIR: a LAMMPS of tools/lammps_from_source.sh (default /var/cache/tdem/lammps-20260704)
#     BUILD_DIR:  tdem's build with tdem-lammps-<version> for it (default build/)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
lmpdir="${1:-/var/cache/tdem/lammps-20260704}"
build="${2:-$here/build}"
[ -f "$lmpdir/source/src/version.h" ] || { echo "no LAMMPS source tree in $lmpdir/source"; exit 1; }
ver="$(grep -h 'define LAMMPS_VERSION ' "$lmpdir/source/src/version.h" | sed 's/.*"\(.*\)".*/\1/' | tr -d ' ')"
ref="$build/bin/tdem-lammps-$ver"
[ -x "$ref" ] || ref="$build/bin/tdem-lammps"
work="$(mktemp -d /tmp/tdem_dropin.XXXXXX)"
echo "[dropin] copying the LAMMPS $ver tree to $work"
cp -a "$lmpdir/source" "$work/lammps"
bash "$here/tools/lammps_dropin.sh" "$work/lammps"
echo "[dropin] configuring and building LAMMPS with its own CMake (GRANULAR RIGID MOLECULE)"
cmake -S "$work/lammps/cmake" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O2 \
  -DBUILD_MPI=ON -DBUILD_OMP=OFF -DPKG_GRANULAR=ON -DPKG_RIGID=ON -DPKG_MOLECULE=ON >"$work/configure.log" 2>&1
cmake --build "$work/build" -j "$(nproc)" >"$work/build.log" 2>&1 &
pid=$!; t0=$(date +%s)
while kill -0 $pid 2>/dev/null; do
  sleep 30
  pct="$(grep -oE '^\[ *[0-9]+%\]' "$work/build.log" | tail -n 1 | tr -dc '0-9')"
  el=$(($(date +%s) - t0))
  if [ -n "$pct" ] && [ "$pct" -gt 0 ]; then rem=$((el * (100 - pct) / pct)); else rem="?"; fi
  echo "[dropin] building ... ${pct:-0} % after $el s, about $rem s to go"
done
wait $pid || { tail -n 30 "$work/build.log"; echo "[dropin] FAIL: the LAMMPS build failed"; exit 1; }
lmp="$work/build/lmp"
styles="$("$lmp" -h | grep -o 'tdem/[a-z/]*' | sort -u | tr '\n' ' ')"
echo "[dropin] lmp -h lists: $styles"
fail=0
for s in tdem/gran tdem/wall/gran tdem/integrate tdem/clump tdem/grate tdem/mixing/depth tdem/mixing/velocity tdem/timestep; do
  grep -q " $s " <<<" $styles" || { echo "[dropin] FAIL: $s missing"; fail=1; }
done
sed 's/run             50000/run             3000/' "$here/input_scripts/lammps/in.tdem_settle" >"$work/in.settle"
a="$(cd "$work" && "$lmp" -in in.settle -log none | grep -E '^ +[0-9]+ ' | md5sum)"
b="$(cd "$work" && "$ref" -in in.settle -log none | grep -E '^ +[0-9]+ ' | md5sum)"
if [ "$a" = "$b" ]; then echo "[dropin] PASS: in.tdem_settle thermo identical to $(basename "$ref")"; else echo "[dropin] FAIL: thermo differs"; fail=1; fi
[ $fail = 0 ] && rm -rf "$work"
exit $fail
