#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Set up (packages, LAMMPS headers, the newer LAMMPS releases, build) and run the whole test
# suite with ctest. Besides Debian's own LAMMPS, the suite runs against LAMMPS 4Feb2025 and
# 4Jul2026 (built once from their Debian source packages and cached in /var/cache/tdem).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
t0=$(date +%s)
bash "$here/tools/setup.sh" --lammps "20250204 20260704"
t1=$(date +%s)
build_dir="${TDEM_BUILD_DIR:-$here/build}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# ctest starts the longest tests first when it knows their cost: on a build that has not run the
# suite yet, seed its cost file from the times measured on 2 cores (tests/test_costs.txt, written by
# tools/test_costs.sh), so that the long suites start first (the tests that take both cores still run
# one at a time when the machine has two).
costs="$build_dir/Testing/Temporary/CTestCostData.txt"
if [ ! -s "$costs" ] && [ -f "$here/tests/test_costs.txt" ]; then
  mkdir -p "$(dirname "$costs")"
  { grep -v '^#' "$here/tests/test_costs.txt" | awk 'NF == 2 {print $2, 1, $1}'; echo "---"; } > "$costs"
fi
rc=0
ctest --test-dir "$build_dir" -j "${TDEM_JOBS:-$(nproc)}" --output-on-failure --timeout 900 "$@" || rc=$?
t2=$(date +%s)
echo "[tdem tests] set-up and build $((t1 - t0)) s, tests $((t2 - t1)) s"
exit $rc
