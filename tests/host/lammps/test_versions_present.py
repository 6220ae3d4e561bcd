#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Every LAMMPS version the test suite must cover (CMake TDEM_REQUIRE_LAMMPS, set by
tools/run_tests.sh) has been built against. A version that is missing fails here with what to
do, so that its host tests can never be skipped silently."""
import sys

args = dict(zip(sys.argv[1::2], sys.argv[2::2]))
have = [v for v in args.get("--have", "").split(",") if v]
need = [v for v in args.get("--need", "").split(",") if v]
print("LAMMPS versions built against: %s" % (", ".join(have) or "none"))
print("LAMMPS versions required:      %s" % (", ".join(need) or "none (TDEM_REQUIRE_LAMMPS is empty)"))
missing = [v for v in need if v not in have]
if missing:
    print("FAIL the build has no tdem for LAMMPS %s. Build that LAMMPS with "
          "tools/lammps_from_source.sh UPSTREAM (or run tools/setup.sh --lammps \"UPSTREAM ...\") "
          "and configure with -DTDEM_LAMMPS_EXTRA=/var/cache/tdem/lammps-UPSTREAM" % ", ".join(missing))
    sys.exit(1)
print("PASS every required LAMMPS version is built against")
