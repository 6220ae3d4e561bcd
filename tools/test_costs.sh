#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Writes tests/test_costs.txt ("SECONDS NAME" per test, longest first) from the times of the last
# full ctest run of a build (its Testing/Temporary/CTestCostData.txt). tools/run_tests.sh seeds a
# fresh build's cost file from it, so that ctest -j starts the long tests first.
#
#   bash tools/test_costs.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${1:-${TDEM_BUILD_DIR:-$here/build}}"
src="$build_dir/Testing/Temporary/CTestCostData.txt"
[ -s "$src" ] || { echo "test_costs.sh: no $src (run the test suite first)" >&2; exit 1; }
out="$here/tests/test_costs.txt"
{
  echo "# SECONDS NAME: the time of each test in a full run on 2 cores (tools/test_costs.sh)"
  awk '$0 == "---" {exit} NF == 3 {printf "%.1f %s\n", $3, $1}' "$src" | sort -k1,1gr -k2
} > "$out"
echo "test_costs.sh: $(grep -vc '^#' "$out") tests written to $out"
