#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Set up (packages, LAMMPS headers, build) and run the showcase (tools/showcase.py).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/tools/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
py=/usr/bin/python3                      # Debian's python3 has python3-matplotlib/numpy
[ -x "$py" ] || py=python3
"$py" "$here/tools/showcase.py" "${TDEM_BUILD_DIR:-$here/build}"
