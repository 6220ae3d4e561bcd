# SPDX-License-Identifier: GPL-2.0-or-later
"""Run an MPI program with a temporary directory of its own.

Open MPI 4.1 (Debian 12) keeps its session directory in $TMPDIR/ompi.<host>.<uid>. Each run
creates it at start and removes it at exit when it is empty. When one run starts while another
ends, the check "exists?" and the mkdir race: mkdir fails with "File exists", MPI_Init aborts,
and the program exits with status 1 before it opens its log. That is what made lammps.sweep and
lammps_4Jul2026.timestep.check_warn_stop_off fail now and then. Measured with 12 concurrent
singleton runs of tdem-lammps-4Jul2026 on the 2 cores: 1 of 1200 failed so on an idle machine,
15 of 2400 while a build ran; at the same time 0 of 3600 runs with a private TMPDIR failed.

run() is subprocess.run with TMPDIR set to a fresh directory, removed after the run.
"""
import os
import shutil
import subprocess
import tempfile


def run(cmd, env=None, **kw):
    """subprocess.run(cmd, **kw) with a private TMPDIR (added to env, or to os.environ)."""
    d = tempfile.mkdtemp(prefix="tdem_mpi_", dir="/tmp")  # short: Open MPI puts sockets there
    e = dict(os.environ if env is None else env)
    e["TMPDIR"] = d
    try:
        return subprocess.run(cmd, env=e, **kw)
    finally:
        shutil.rmtree(d, ignore_errors=True)
