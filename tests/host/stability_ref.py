# SPDX-License-Identifier: GPL-2.0-or-later
"""Closed forms and physical bounds of the stability suite (issue 8), shared by
tests/host/lammps/test_stability.py and tests/host/liggghts/test_stability.py.

Everything here is re-derived from the physics (physics_reference 2.2, 5.x), never taken from
the output of the code under test."""
import math

import numpy as np

G = 9.81
HERTZ_TC = 0.8 * math.sqrt(math.pi) * math.gamma(0.4) / math.gamma(0.9)   # 2.94328...


def sphere_mass(d, rho):
    return rho * math.pi * d ** 3 / 6.0


def dt_critical_verlet(k, gamma, meff):
    """Largest stable step of velocity Verlet on m x'' = -k x - gamma x':
    dt_c = 2/omega (sqrt(1 + zeta^2) - zeta), omega = sqrt(k/m), zeta = gamma/(2 sqrt(k m))
    (the eigenvalues of the one-step matrix leave the unit circle at -1)."""
    omega = math.sqrt(k / meff)
    zeta = gamma / (2.0 * math.sqrt(k * meff))
    return 2.0 / omega * (math.sqrt(1.0 + zeta * zeta) - zeta), omega, zeta


def verlet_step_matrix(k, gamma, meff, h):
    """One step of velocity Verlet as the hosts run it (nve/sphere: half kick, drift, force with
    the half-step velocity, half kick) on m x'' = -k x - gamma x', as a 3x3 matrix on the state
    (x, v, a). Its spectral radius confirms independently that 0.9 dt_c is stable and 1.1 dt_c
    is not."""
    w2, c = k / meff, gamma / meff
    cols = []
    for x, v, a in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
        vh = v + 0.5 * h * a
        x1 = x + h * vh
        a1 = -w2 * x1 - c * vh
        cols.append((x1, vh + 0.5 * h * a1, a1))
    return np.array(cols).T


def spectral_radius(m):
    return float(max(abs(np.linalg.eigvals(m))))


def lsd_e_zero_overlap(k, gamma, meff):
    beta = gamma / (2.0 * math.sqrt(k * meff))
    return math.exp(-math.pi * beta / math.sqrt(1.0 - beta * beta))


def estar(e1, nu1, e2=None, nu2=None):
    """1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (both partners of material 1 by default)."""
    if e2 is None:
        e2, nu2 = e1, nu1
    return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)


def hertz_ktilde(es, rstar):
    return 4.0 / 3.0 * es * math.sqrt(rstar)


def hertz_ximax(meff, kt, v):
    """Largest overlap of an undamped Hertz impact at v: 2/5 k~ xi^(5/2) = 1/2 m* v^2."""
    return (5.0 * meff * v * v / (4.0 * kt)) ** 0.4


def hertz_tc(meff, kt, v):
    """Undamped Hertz contact time 2.94328 xi_max / v (physics_reference 2.2.2)."""
    return HERTZ_TC * hertz_ximax(meff, kt, v) / v


def coulomb_impulse_bound(mu, e, vn):
    """|change of the tangential velocity of the contact point's body| <= mu (1 + e) vn for a
    sphere on a wall (tangential impulse <= mu x normal impulse, normal impulse = m (1 + e) vn)."""
    return mu * (1.0 + e) * vn


def rational_fit(c0, c1, c2, v):
    return c0 / (c1 + v ** c2)


def power_tc(c0, c1, v):
    return c0 * v ** (-c1)


def power_efit(c0, c1, v):
    return min(1.0, (v / c0) ** (-c1))


def energy_series(frames, g=0.0, gdir=2):
    """Total mechanical energy outside contacts per frame: sum 1/2 m v^2 + 1/5 m r^2 w^2 + m g z.
    frames: list of dicts of per-atom arrays with keys mass, radius, x y z vx vy vz omegax...
    Returns arrays (kinetic incl. rotation, gravity potential)."""
    ke, pe = [], []
    for f in frames:
        m = f["mass"]
        v2 = f["vx"] ** 2 + f["vy"] ** 2 + f["vz"] ** 2
        w2 = f["omegax"] ** 2 + f["omegay"] ** 2 + f["omegaz"] ** 2
        ke.append(float(np.sum(0.5 * m * v2 + 0.2 * m * f["radius"] ** 2 * w2)))
        pe.append(float(np.sum(m * g * f["xyz"[gdir]])))
    return np.array(ke), np.array(pe)


def verlet_impact_e(k, c, meff, v0, dt, gap_steps):
    """Independent model of a linear spring-dashpot impact (zero-overlap end, attraction allowed)
    integrated by velocity Verlet exactly as the hosts step it (half kick, drift, force with the
    half-step velocity, half kick); the contact starts gap_steps steps after t = 0. Returns e."""
    x = -gap_steps * v0 * dt   # overlap (negative: gap)
    v, a = v0, 0.0
    touched = False
    for _ in range(1000000):
        vh = v + 0.5 * dt * a
        x = x + dt * vh
        a = -(k * x + c * vh) / meff if x > 0 else 0.0
        v = vh + 0.5 * dt * a
        touched = touched or x > 0
        if touched and x <= 0:
            return -v / v0
    raise RuntimeError("no separation")


def read_frames(path, natoms, cols):
    """All frames of a text custom dump (sorted by id, columns `cols`) as a dict of [frame, atom]
    arrays, the steps, and the number of frames whose atom count differs from natoms (lost atoms)."""
    with open(path) as f:
        lines = f.read().split("\n")
    steps, rows, bad = [], [], 0
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            if n != natoms:
                bad += 1
            else:
                steps.append(step)
                rows.append(" ".join(lines[i + 9:i + 9 + n]))
            i += 9 + n
        else:
            i += 1
    data = np.array(" ".join(rows).split(), dtype=float).reshape(len(rows), natoms, len(cols))
    return np.array(steps), {c: data[:, :, j] for j, c in enumerate(cols)}, bad


def kinetic(fr):
    """per frame and atom: translational + rotational kinetic energy (solid spheres)."""
    m, r = fr["mass"], fr["radius"]
    v2 = fr["vx"] ** 2 + fr["vy"] ** 2 + fr["vz"] ** 2
    w2 = fr["omegax"] ** 2 + fr["omegay"] ** 2 + fr["omegaz"] ** 2
    return 0.5 * m * v2 + 0.2 * m * r * r * w2


def fcc_points(d, n, shrink=2e-4):
    """Face-centred cubic packing of equal spheres: centres on the cubic grid of spacing
    s = d (1 - shrink)/sqrt(2) with i + j + k even (12 neighbours at d (1 - shrink): small initial
    overlaps), n x n x n grid points, walls touching the outer spheres. Returns centres, box side."""
    s = d * (1 - shrink) / math.sqrt(2)
    r = d / 2
    pts = [(r + i * s, r + j * s, r + k * s) for i in range(n) for j in range(n) for k in range(n)
           if (i + j + k) % 2 == 0]
    return pts, 2 * r + (n - 1) * s


def bed_energy(fr, kn, L, d):
    """kinetic + gravity + elastic energy of the linear normal springs (pairs and the four side
    walls and the floor of a box [0, L]^2 x [0, ...)) per frame."""
    ke = kinetic(fr).sum(axis=1)
    pe = (fr["mass"] * G * fr["z"]).sum(axis=1)
    x, y, z = fr["x"], fr["y"], fr["z"]
    el = np.zeros(len(x))
    r = d / 2
    for f in range(len(x)):
        p = np.stack([x[f], y[f], z[f]], axis=1)
        dd = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(axis=2))
        xi = np.triu(np.maximum(d - dd, 0.0), 1)
        w = sum(np.maximum(r - q, 0.0) ** 2 for q in (x[f], L - x[f], y[f], L - y[f], z[f]))
        el[f] = 0.5 * kn * (np.sum(xi ** 2) + np.sum(w))
    return ke, pe, el


def thornton_e(meff, rstar, es, py, v):
    """Thornton (1997) restitution of a head-on impact at v: xi_y = R* (pi p_y/(2 E*))^2,
    v_y^2 = 4 k~ xi_y^(5/2)/(5 m*), e = 1 below v_y (physics_reference 2.2.4)."""
    k = hertz_ktilde(es, rstar)
    xi_y = rstar * (math.pi * py / (2 * es)) ** 2
    vy = math.sqrt(4.0 * k * xi_y ** 2.5 / (5.0 * meff))
    r = vy / v
    if r >= 1:
        return 1.0
    return (math.sqrt(6 * math.sqrt(3) / 5 * (1 - r * r / 6)) *
            (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25)


def bounce_checks(check, name, tag, z, vz, wy, xi, m, r, g, e_bound, lasting_required):
    """Checks of a sphere bouncing under gravity on a surface (overlap series xi), for a law that
    forbids attraction: every contact (a new contact after a separation) restitutes at most the
    gravity-free closed form e_bound(v_entry) + 1e-2 (gravity during the contact only lowers e),
    the energy 1/2 m v^2 + 1/5 m r^2 w^2 + m g z at each contact exit never grows (beyond 1e-4
    relative: the velocity-Verlet error of an elastic contact at the step used), the sphere ends in
    a lasting contact whose overlap amplitude does not grow (1e-4)."""
    inc = xi > 0
    exits = np.where(inc[:-1] & ~inc[1:])[0] + 1
    ents = np.where(~inc[:-1] & inc[1:])[0]
    E = 0.5 * m * vz ** 2 + m * g * z + 0.2 * m * r * r * wy ** 2
    Ex = E[exits]
    nb = len(exits)
    gain = float(np.max(np.diff(Ex))) if nb > 1 else 0.0
    pairs = [(a, b) for a, b in zip(ents, exits) if b > a]
    e_b = np.array([-vz[b] / vz[a] for a, b in pairs])
    e_cf = np.array([e_bound(-vz[a]) for a, b in pairs])
    last = ents[-1] + 1 if len(ents) else 0
    tailxi = xi[last:] if np.all(xi[last:] > 0) else xi[:0]
    print("%s %s: %d bounces, e %s (gravity-free closed form at the entry speed %s), energy at exits %s; "
          "lasting contact over %d frames" % (name, tag, nb, " ".join("%.4f" % x for x in e_b[:8]),
                                              " ".join("%.4f" % x for x in e_cf[:8]),
                                              " ".join("%.6e" % x for x in Ex[:6]), len(tailxi)))
    check(nb >= 3, "%s %s: at least 3 loading cycles (bounces) seen" % (name, tag))
    worst = float(np.max(e_b - e_cf)) if len(e_b) else 0.0
    check(bool(np.all(e_b >= 0)) and worst <= 1e-2,
          "%s %s: every new contact dissipates as the law says: 0 <= e <= closed form + 1e-2 (worst excess %.2e)"
          % (name, tag, worst))
    check(gain <= 1e-4 * abs(Ex[0]), "%s %s: no energy gain from one bounce to the next (max rise %.3e J)"
          % (name, tag, gain))
    if lasting_required:
        check(len(tailxi) > 400, "%s %s: the sphere ends in a lasting contact (repeated elastic cycles)" % (name, tag))
    if len(tailxi) > 400:
        h1, h2 = tailxi[:len(tailxi) // 2].max(), tailxi[len(tailxi) // 2:].max()
        check(h2 <= h1 * (1 + 1e-4), "%s %s: lasting contact: the overlap amplitude does not grow "
              "(first half %.6e, second %.6e)" % (name, tag, h1, h2))


# ---------------------------------------------------------------------------- clumps (issue 6)
def lsd_k_gamma(e, tc, meff):
    """lsd from restitution e and contact time t_c (zero-overlap end) for the effective mass m*:
    k = m* (pi^2 + ln^2 e)/t_c^2, gamma = -2 m* ln e / t_c (physics_reference 2.1)."""
    le = math.log(e)
    return meff * (math.pi ** 2 + le * le) / tc ** 2, -2.0 * meff * le / tc


def lsd_n_contacts(e, tc, n):
    """N identical simultaneous lsd contacts (k -> N k, gamma -> N gamma, body mass M) of a body whose
    single contact has e, t_c: e_N = exp(-pi sqrt(N) beta / sqrt(1 - N beta^2)),
    t_N = pi / (omega_0 sqrt(N) sqrt(1 - N beta^2)) (physics_reference 6.4). Returns (e_N, t_N)."""
    a = -math.log(e) / math.pi
    beta = a / math.sqrt(1 + a * a)
    w0 = math.pi / tc / math.sqrt(1 - beta * beta)
    bn = math.sqrt(n) * beta
    return math.exp(-math.pi * bn / math.sqrt(1 - bn * bn)), math.pi / (math.sqrt(n) * w0 * math.sqrt(1 - bn * bn))


def cube8(c, d):
    """2 x 2 x 2 sphere centres at spacing d around c (a face touches a plane with 4 spheres)."""
    return [np.array(c) + d * np.array([i - 0.5, j - 0.5, k - 0.5]) for k in (0, 1) for j in (0, 1) for i in (0, 1)]


def plate8(c, d):
    """2 x 4 coplanar sphere centres at spacing d around c (8 spheres touch a plane at once)."""
    return [np.array(c) + d * np.array([i - 1.5, j - 0.5, 0.0]) for j in (0, 1) for i in range(4)]


def rigid_worst(fr, bodies_atoms):
    """largest relative change over all frames of any sphere-sphere distance inside a body
    (fr: dict of [frame, atom] arrays x y z; bodies_atoms: lists of 0-based atom columns)."""
    worst = 0.0
    P = np.stack([fr["x"], fr["y"], fr["z"]], axis=2)
    for ids in bodies_atoms:
        q = P[:, ids, :]
        dd = np.sqrt(((q[:, :, None, :] - q[:, None, :, :]) ** 2).sum(axis=3))
        iu = np.triu_indices(len(ids), 1)
        dd = dd[:, iu[0], iu[1]]
        worst = max(worst, float((np.abs(dd - dd[0]) / dd[0]).max()))
    return worst
