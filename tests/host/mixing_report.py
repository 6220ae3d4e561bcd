# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared by tests/host/{lammps,liggghts}/test_mixing.py: the processor grids of the rank-count tests
and the reader of the TDEM_MIXING_REPORT lines (docs/mixing_hosts.md)."""

# -np 1, 2, 4, 8 (oversubscribed): a split along x, one along the up axis z, and 1 x 4 x 2 where a
# sub-domain is narrower than r_v
GRIDS = ((1, ""), (2, "processors 2 1 1"), (4, "processors 1 2 2"), (8, "processors 2 2 2"), (8, "processors 1 4 2"))


def held(out):
    """{(style, rank): (owned, halo, group)} of the last evaluation, from TDEM_MIXING_REPORT lines."""
    h = {}
    for line in out.splitlines():
        w = line.split()
        if line.startswith("tdem mixing report:") and len(w) >= 13:
            h[(w[3], int(w[5]))] = (int(w[9]), int(w[11]), int(w[13]))
    return h
