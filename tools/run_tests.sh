#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Set up (packages, LAMMPS headers, build) and run the whole test suite with ctest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/tools/setup.sh"
build_dir="${TDEM_BUILD_DIR:-$here/build}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
ctest --test-dir "$build_dir" -j "${TDEM_JOBS:-$(nproc)}" --output-on-failure --timeout 900 "$@"
