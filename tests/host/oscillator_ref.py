# SPDX-License-Identifier: GPL-2.0-or-later
"""The damped linear oscillator x'' + 2 z x' + x = 0 (omega0 = 1, x(0) = 0, x'(0) = 1), solved here
from its exact under- and over-damped solutions: reference values for the host tests of both
engines, independent of tdem's own closed forms."""
import math


def zero_force_end(z):
    """Linear oscillator x'' + 2 z x' + x = 0 (omega0 = 1), x(0) = 0, x'(0) = 1: the contact ends
    with the force k x + c x' = -m x'' returning to zero. Returns (e, t_c), found numerically from
    the exact x''(t) of the under- or over-damped solution (independent of tdem's closed forms)."""
    if z < 1.0:
        wd = math.sqrt(1.0 - z * z)
        def acc(t):
            return math.exp(-z * t) * ((z * z - wd * wd) * math.sin(wd * t) - 2 * z * wd * math.cos(wd * t)) / wd
        def vel(t):
            return math.exp(-z * t) * (wd * math.cos(wd * t) - z * math.sin(wd * t)) / wd
        lo, hi = 1e-12, math.pi / wd
    else:
        q = math.sqrt(z * z - 1.0)
        r1, r2 = -z + q, -z - q
        def acc(t):
            return (r1 * r1 * math.exp(r1 * t) - r2 * r2 * math.exp(r2 * t)) / (r1 - r2)
        def vel(t):
            return (r1 * math.exp(r1 * t) - r2 * math.exp(r2 * t)) / (r1 - r2)
        lo, hi = 1e-12, 1.0
        while acc(hi) < 0.0:
            hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if acc(mid) < 0.0:
            lo = mid
        else:
            hi = mid
    t = 0.5 * (lo + hi)
    return abs(vel(t)), t


def zeta_for_zero_force_e(e):
    lo, hi = 0.0, 1e6  # e falls with z
    for _ in range(300):
        mid = math.sqrt(lo * hi) if lo > 0 else 0.5 * hi
        if zero_force_end(mid)[0] > e:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)
