#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Validation of fix tdem/clump (issue 6): flat-face impacts against the N-contact closed form,
# tilted single-contact impacts against rigid-body impact theory, the same scenes with the stock
# fix rigid/small (LAMMPS), and the multiple-contact correction (none, count, overlap, local_mass)
# in LAMMPS and LIGGGHTS. Writes validation/clumps/results/ (table.md, *.png, results.json,
# correction_lammps.*, liggghts_correction.*).
#
#   validation/clumps/run.sh [path/to/tdem-lammps] [--quick]
#
# tdem-lammps from the argument, else $TDEM_LAMMPS, else build/bin/tdem-lammps (it must have the
# clump module, CMake option TDEM_LAMMPS_CLUMP); tdem-liggghts from $TDEM_LIGGGHTS, else next to
# tdem-lammps (skipped when missing). About 2 min on 2 shared cores.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
lmp=${TDEM_LAMMPS:-$root/build/bin/tdem-lammps}
quick=""
for a in "$@"; do
  case $a in --quick) quick=--quick ;; *) lmp=$a ;; esac
done
case $lmp in /*) ;; *) lmp="$(pwd)/$lmp" ;; esac
if [ ! -x "$lmp" ]; then
  echo "run.sh: tdem-lammps not found at '$lmp'" >&2
  exit 2
fi
# the executable must know fix tdem/clump and fix rigid/small
probe=$(mktemp -d)
printf 'units si\natom_style sphere\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\nfix pm all property/atom mol\nfix c all tdem/clump template s shape single 0.1 0 density 1\n' > "$probe/in"
if ! (cd "$probe" && "$lmp" -in in -log none -echo none -screen none) ; then
  echo "run.sh: $lmp has no fix tdem/clump (build with -DTDEM_LAMMPS_CLUMP=ON)" >&2
  rm -rf "$probe"; exit 2
fi
rm -rf "$probe"
# the multiple-contact correction is in the core only: its numbers come from the unit test
ut=$(dirname "$lmp")/../tests/unit/tdem_unit_tests
if [ -x "$ut" ]; then
  "$ut" --gtest_filter='ClumpMultiContact.*' > "$here/unit_clumps.txt" 2>&1 || echo "run.sh: unit test failed" >&2
fi
mkdir -p "$here/results"
rm -f "$here/results"/*.png "$here/results/table.md" "$here/results/results.json"
cd "$here" || exit 2
. "$root/tools/progress.sh"
progress_init "lammps:4 liggghts:1"
/usr/bin/python3 study.py --lammps "$lmp" --parts flat,tilted,rigid,correction_lammps $quick || exit 1
progress_done lammps
lig=${TDEM_LIGGGHTS:-$(dirname "$lmp")/tdem-liggghts}
if [ -x "$lig" ]; then
  /usr/bin/python3 study.py --liggghts "$lig" || exit 1
  progress_done liggghts
else
  echo "run.sh: no tdem-liggghts at '$lig': the LIGGGHTS correction section is skipped" >&2
fi
