# SPDX-License-Identifier: GPL-2.0-or-later
"""The report of the contact tally's neighbourhood (TDEM_TALLY_REPORT=1, src/contact/multi_contact/
contact_tally_mpi.h), shared by the LAMMPS and LIGGGHTS clump tests."""
import re

REPORT = re.compile(r"tdem tally: rank (\d+) of (\d+) merges with ranks \[([0-9,]*)\]")


def slab_neighbours(output, nprocs):
    """(ok, text): every rank of a row of nprocs slabs along a periodic axis reported, and each merges
    with its two neighbouring slabs only. The ranks print concurrently: reports are found anywhere in
    the output."""
    rep = [m for m in REPORT.finditer(output) if int(m.group(2)) == nprocs]
    seen = {int(m.group(1)) for m in rep}
    ok = seen == set(range(nprocs))
    for m in rep:
        me = int(m.group(1))
        got = sorted(int(x) for x in m.group(3).split(",") if x)
        ok = ok and got == sorted({(me - 1) % nprocs, (me + 1) % nprocs})
    return ok, "%d reports from ranks %s, e.g. '%s'" % (len(rep), sorted(seen), rep[0].group(0) if rep else "none")
