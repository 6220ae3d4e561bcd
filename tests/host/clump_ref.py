# SPDX-License-Identifier: GPL-2.0-or-later
"""Independent references for the clump tests and validation (issue 6), shared by
tests/host/liggghts/test_clump.py and validation/clumps/study.py. Re-derived from the physics,
never from the output of the code under test."""
import math


def hertz_wall_ode(E, nu, r, e_in, M, meff, v0):
    """Independent reference: a body of mass M pressed by ONE LIGGGHTS hertz contact (sphere r on a wall
    of the same material, damping from m* = meff) at approach speed v0 - F = 4/3 Y* sqrt(r) xi^1.5 +
    2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(r xi) meff) dxi/dt, Y* = E / (2 (1 - nu^2)), beta = ln e /
    sqrt(ln^2 e + pi^2) (LIGGGHTS's documented hertz law), integrated by RK4. Returns (e, t_c)."""
    Y = E / (2.0 * (1.0 - nu * nu))
    lne = math.log(e_in)
    beta = -lne / math.sqrt(lne * lne + math.pi ** 2)
    K = 4.0 / 3.0 * Y * math.sqrt(r)

    def acc(x, v):
        xp = max(x, 0.0)
        return -(K * xp ** 1.5 + 2.0 * math.sqrt(5.0 / 6.0) * beta * math.sqrt(2.0 * Y * math.sqrt(r * xp) * meff) * v) / M

    xmax = (5.0 * M * v0 * v0 / (4.0 * K)) ** 0.4
    h = 2.0 * xmax / v0 / 20000.0
    x, v, t = 0.0, v0, 0.0
    while True:
        k1x, k1v = v, acc(x, v)
        k2x, k2v = v + 0.5 * h * k1v, acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v)
        k3x, k3v = v + 0.5 * h * k2v, acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v)
        k4x, k4v = v + h * k3v, acc(x + h * k3x, v + h * k3v)
        xn = x + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x)
        vn = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
        if xn < 0.0 and t > 0.0:
            f = x / (x - xn)
            return -(v + f * (vn - v)) / v0, t + f * h
        x, v, t = xn, vn, t + h
