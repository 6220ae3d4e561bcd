#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Put tdem's LAMMPS styles into a LAMMPS source tree, to be built by LAMMPS's own CMake (or make)
# like any style of that tree: no plugin, no tdem-lammps.
#
#   bash tools/lammps_dropin.sh LAMMPS_TREE            copy the files in (again: refresh them)
#   bash tools/lammps_dropin.sh --remove LAMMPS_TREE   take them out again
#
# then, e.g.:  cmake -S LAMMPS_TREE/cmake -B build -DPKG_GRANULAR=ON ... && cmake --build build
#
# What it copies into LAMMPS_TREE/src:
#   - the style sources flat (pair_tdem_gran.*, fix_tdem_*.*, compute_tdem_*.*, tdem_lammps_law.*,
#     lammps_compat.h, ...): LAMMPS's build compiles every src/*.cpp and registers every style
#     header with a PairStyle/FixStyle/ComputeStyle block;
#   - tdem's host-free headers under their own paths (contact/, collision/, fixes/,
#     integrators/, pair_styles/*.h), as the styles include them ("contact/normal/hertz_damped.h",
#     "pair_styles/per_atom_rows.h");
#   - tdem_lammps_features.h, the API features of this tree (the compile checks of tdem's build).
# A list of the copied files is kept in LAMMPS_TREE/src/tdem_dropin_files.txt.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
remove=0
if [ "${1:-}" = "--remove" ]; then remove=1; shift; fi
tree="${1:?usage: lammps_dropin.sh [--remove] LAMMPS_TREE}"
[ -d "$tree" ] || { echo "lammps_dropin.sh: no directory $tree" >&2; exit 1; }
tree="$(cd "$tree" && pwd)"
dst="$tree/src"
[ -f "$dst/pair.h" ] && [ -f "$dst/version.h" ] || { echo "lammps_dropin.sh: $tree is no LAMMPS source tree (no src/pair.h)" >&2; exit 1; }
list="$dst/tdem_dropin_files.txt"

if [ -f "$list" ]; then  # remove what an earlier run copied
  while IFS= read -r f; do rm -f "$dst/$f"; done <"$list"
  for d in contact collision fixes integrators pair_styles; do
    [ -d "$dst/$d" ] && find "$dst/$d" -depth -type d -empty -delete
  done
  rm -f "$list"
fi
if [ "$remove" = 1 ]; then echo "tdem files removed from $dst"; exit 0; fi

: >"$list"
copy() {  # copy SRC to dst/REL and record it
  mkdir -p "$(dirname "$dst/$2")"
  cp "$1" "$dst/$2"
  echo "$2" >>"$list"
}
# 1. the styles, flat (the tdem-lammps registration table and the plugin entry are not needed)
for f in "$here"/src/pair_styles/lammps/*.{h,cpp} "$here"/src/integrators/lammps/*.{h,cpp} \
         "$here"/src/fixes/*/lammps/*.{h,cpp} "$here"/src/fixes/*/hosts/*.{h,cpp} \
         "$here"/src/fixes/lammps/*.h; do
  b="$(basename "$f")"
  case "$b" in tdem_lammps_styles.*|*_styles.cpp) continue ;; esac
  copy "$f" "$b"
done
# 2. the host-free headers, under their paths ("contact/normal/hertz_damped.h",
#    "fixes/grate/geometry.h"); the hosts' adapters went flat in step 1
(cd "$here/src" && { find contact collision fixes integrators -name '*.h' \
   -not -path '*/liggghts/*' -not -path '*/lammps/*' -not -path '*/hosts/*'; ls pair_styles/*.h; }) | while IFS= read -r rel; do copy "$here/src/$rel" "$rel"; done
# 3. the API features of this LAMMPS tree
tmp="$(mktemp -d)"
if ! cmake -S "$here/tools/lammps_features" -B "$tmp" -DLAMMPS_HEADER_DIR="$dst" \
      -DOUTPUT="$dst/tdem_lammps_features.h" >"$tmp/log" 2>&1; then
  cat "$tmp/log" >&2; rm -rf "$tmp"; exit 1
fi
grep 'tdem LAMMPS' "$tmp/log" | sed 's/^-- //'
rm -rf "$tmp"
echo "tdem_lammps_features.h" >>"$list"
echo "tdem: $(wc -l <"$list") files copied into $dst (list: $list)"
