# SPDX-License-Identifier: GPL-2.0-or-later
"""Independent numpy evaluation of the mixing definitions (physics_reference 7.2, docs/grate.md 4),
brute force over all pairs, for the host tests of compute tdem/mixing/velocity and
fix tdem/mixing/depth (LAMMPS and LIGGGHTS)."""
import numpy as np


def bin_index(x, axis, lo, hi, n):
    """Region of each point: equal bins of coordinate `axis` in [lo, hi]; -1 outside."""
    f = (x[:, axis] - lo) / (hi - lo)
    idx = np.minimum(n - 1, np.floor(f * n).astype(int))
    idx[(f < 0) | (f > 1)] = -1
    return idx


def min_image(d, lengths):
    """d: (..., 3) differences; lengths[k] = period of axis k or None."""
    d = d.copy()
    for k, L in enumerate(lengths):
        if L:
            d[..., k] -= L * np.round(d[..., k] / L)
    return d


def velocity_table(x, v, rv, axis, lo, hi, n, lengths=(None, None, None), include=None):
    """(n + 1) x 5: count, p_x, p_y, p_z, P' per bin (last row: all bins)."""
    d = min_image(x[None, :, :] - x[:, None, :], lengths)
    nb = (d ** 2).sum(axis=2) <= rv * rv
    vbar = (nb[:, :, None] * v[None, :, :]).sum(axis=1) / nb.sum(axis=1)[:, None]
    vt = v - vbar
    idx = bin_index(x, axis, lo, hi, n)
    if include is None:
        include = np.ones(len(x), bool)
    out = np.zeros((n + 1, 5))
    for b in range(n + 1):
        sel = include & ((idx == b) if b < n else (idx >= 0))
        out[b, 0] = sel.sum()
        if sel.sum():
            p = vt[sel].std(axis=0)  # population std (1/N)
            out[b, 1:4] = p
            out[b, 4] = np.sqrt((p ** 2).sum())
    return out


def depths(x, r, transport, up, lateral, c, floor, normalise=True, lengths=(None, None, None)):
    """D of every particle: surface = highest centre in the column |dt| <= c/2 (|dl| <= c/2)."""
    d = min_image(x[None, :, :] - x[:, None, :], lengths)
    inside = np.abs(d[:, :, transport]) <= 0.5 * c
    if lateral is not None and lateral >= 0:
        inside &= np.abs(d[:, :, lateral]) <= 0.5 * c
    z = x[:, up]
    s = np.where(inside, z[None, :], -np.inf).max(axis=1)
    depth = s - z
    if not normalise:
        return depth
    bed = s - (floor + r)
    with np.errstate(divide="ignore", invalid="ignore"):
        D = np.where(bed > 0, np.clip(depth / np.where(bed > 0, bed, 1.0), 0.0, 1.0), 0.0)
    return D
