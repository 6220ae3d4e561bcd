#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Analysis of the grate scenes of validation/grate/run.sh (issue 7, physics_reference.md section 7).

    analyse.py WORKDIR RESULTS [--short | --long]

--long: the large grates of run.sh --long instead (prefixes fwd2dL, fwd3dL: 8 rows, a bed of more than
2000 particles), with the checks that the bed holds at least 2000 particles and that the run is
stationary (the two halves of the evaluation window agree: holdup and P' within 10 %, Q' within 15 %).

WORKDIR holds the outputs of the scenes input_scripts/liggghts/grate_{forward_2d,forward_3d,reverse_3d}.in
(prefixes fwd2d, fwd3d, rev3d) and of the stopped-grate run (prefix stop3d): <tag>_series.txt,
<tag>_pv_bins.txt (fix ave/time), <tag>_depth_bins.txt (fix tdem/mixing/depth file), <tag>_atoms.txt
(dump custom, sorted by id). RESULTS receives table.md and the PNG plots.

What is computed here (and what is taken from the styles):
  P'         from compute tdem/mixing/velocity (global scalar and per-region array, one value per snapshot);
             the time mean over the evaluation window is the mean of the snapshot values; per region the
             count-weighted mean of P'^2 over the snapshots (square root).
  D          from fix tdem/mixing/depth (per-atom D at every snapshot, dumped).
  Q'         recomputed here from the dumped D along each trajectory (by id), Q' = sum|D(k+1) - D(k)| /
             sum (t(k+1) - t(k)) over consecutive snapshots in which the particle is present, pooled over all
             particles of the regions (the region of the particle at the earlier snapshot; particles outside
             [0, 0.37] m, i.e. beyond the regions, are left out as in the fix) and over a time window.
             The fix's own Q' (accumulated from t = 0) is checked against the same sum over the whole run.
  bed height highest particle top (centre + r) per x-strip of 23 mm minus the grate surface at the strip centre
             (bars at rest; the geometry below mirrors the scene files), mean over strips and snapshots.
  mass flow  mass of the particles that left (last snapshot seen before the end) in the evaluation window,
             divided by its length (m = 2500 kg/m^3 * 4/3 pi r^3; the 2D disks are given that mass).
  residence  per particle id: first snapshot seen (insertion) to last snapshot seen (it fell off the last row
             and left the box); only particles that left before the end of the run.
The evaluation window is the second half of the run (t >= tend/2) - the bed needs a few seconds to build up.
"""
import math
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The grate of the scene files (input_scripts/liggghts/grate_*.in): rows, L, h, s, overlap, declination.
GRATE = dict(rows=4, L=0.12, h=0.015, s=0.015, overlap=0.035)
CASES = [  # tag, label, dimension, declination [deg], colour
    ("fwd2d", "forward 2D", 2, 3.0, "tab:blue"),
    ("fwd3d", "forward 3D", 3, 3.0, "tab:green"),
    ("rev3d", "reverse 3D", 3, 12.0, "tab:red"),
]
LONG_CASES = [  # run.sh --long: 8 rows; 2D disks of 4.5 and 5.5 mm; 3D 120 mm periodic width
    ("fwd2dL", "forward 2D, 8 rows", 2, 3.0, "tab:blue"),
    ("fwd3dL", "forward 3D, 8 rows", 3, 3.0, "tab:green"),
]
STOPS = [("stop3d", "forward 3D, standing grate (stroke 0)", 3, 3.0, "tab:gray"),
         ("stop3d_dt1", "forward 3D, standing grate, dt/2", 3, 3.0, "k")]
XLO, XHI, NBINS = 0.0, 0.37, 8
RHO = 2500.0  # particle density; the 2D disks have the mass of the sphere of the same diameter  # the regions of the mixing styles in the scenes


def grate_surface(x, decl):
    """Height of the highest bar top face above x (bars at rest, frame of the scenes: heel of row 0 at 0)."""
    a = math.radians(decl)
    p = GRATE["L"] - GRATE["overlap"]
    best = np.full(np.shape(x), np.nan)
    for i in range(GRATE["rows"]):
        xh = i * p * math.cos(a)
        zh = -i * p * math.sin(a) - i * GRATE["s"]
        inside = (x >= xh) & (x <= xh + GRATE["L"] * math.cos(a))
        z = zh - (x - xh) * math.tan(a)
        best = np.where(inside & ~(z <= best), z, best)
    return best


def read_scalar_series(path):
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if "TimeStep" in line:
                    names = line[1:].split()
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    return names, np.array(rows)


def read_vector_series(path):
    """fix ave/time mode vector: list of (step, array rows x columns)."""
    out = []
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#") and l.strip()]
    i = 0
    while i < len(lines):
        step, n = (int(float(v)) for v in lines[i].split()[:2])
        block = np.array([[float(v) for v in l.split()[1:]] for l in lines[i + 1:i + 1 + n]])
        out.append((step, block))
        i += 1 + n
    return out


def read_depth_file(path):
    """fix tdem/mixing/depth file: list of (step, time, rows [bin count meanD mean_sigmaD Q sigmaD samples])."""
    out, cur = [], None
    with open(path) as f:
        for line in f:
            s = line.split()
            if not s:
                continue
            if line.startswith("#"):
                try:
                    cur = (int(float(s[1])), float(s[2]), [])
                    out.append(cur)
                except (ValueError, IndexError):
                    pass
                continue
            if cur is not None:
                cur[2].append([float(v) for v in s])
    return [(st, t, np.array(r)) for st, t, r in out]


def read_dump(path):
    """dump custom: list of (step, column names, array)."""
    frames = []
    with open(path) as f:
        while True:
            line = f.readline()
            if not line:
                break
            if line.startswith("ITEM: TIMESTEP"):
                step = int(f.readline())
                f.readline()
                n = int(f.readline())
                for _ in range(4):
                    f.readline()
                cols = f.readline().split()[2:]
                a = np.loadtxt([f.readline() for _ in range(n)], ndmin=2) if n else np.zeros((0, len(cols)))
                frames.append((step, cols, a))
    return frames


def time_step(path):
    """dt of a scene from its series (grate time f_g[1] / step)."""
    names, s = read_scalar_series(path)
    k = np.nonzero(s[:, 0] > 0)[0][0]
    return s[k, names.index("v_t")] / s[k, 0]


class Case:
    def __init__(self, work, spec):
        self.tag, self.label, self.dim, self.decl, self.colour = spec
        w = lambda s: os.path.join(work, "%s_%s" % (self.tag, s))  # noqa: E731
        self.names, self.series = read_scalar_series(w("series.txt"))
        self.pv = read_vector_series(w("pv_bins.txt"))
        self.depth = read_depth_file(w("depth_bins.txt"))
        self.frames = read_dump(w("atoms.txt"))
        self.dt = time_step(w("series.txt"))
        s = self.series
        col = {n: i for i, n in enumerate(self.names)}
        self.t = s[:, col["v_t"]]
        self.atoms = s[:, col["v_nat"]]
        self.fed = s[:, col["v_fed"]]
        self.mass = s[:, col["v_mass"]]
        self.vx = s[:, col["v_vx"]]
        self.P = s[:, col["v_P"]]
        self.Qfix = s[:, col["v_Q"]]
        self.Dfix = s[:, col["v_Dm"]]
        self.tend = self.t[-1]
        self.t0 = 0.5 * self.tend
        self.up = "y" if self.dim == 2 else "z"
        self._trajectories()

    def _trajectories(self):
        """Per-snapshot D per id; increments for Q' and residence times."""
        self.ft = np.array([st * self.dt for st, _, _ in self.frames])
        first, last, rad = {}, {}, {}
        prev = None
        inc = []  # (t_earlier, x_earlier, |dD|, dt)
        self.bed = []  # (t, mean bed height over strips)
        self.Dmean = []  # (t, mean D)
        strips = np.arange(XLO, XHI + 1e-9, 0.023)
        centres = 0.5 * (strips[1:] + strips[:-1])
        gs = grate_surface(centres, self.decl)
        for (step, cols, a), t in zip(self.frames, self.ft):
            if len(a) == 0:
                prev = None
                continue
            c = {n: i for i, n in enumerate(cols)}
            ids = a[:, c["id"]].astype(int)
            x = a[:, c["x"]]
            up = a[:, c[self.up]]
            r = a[:, c["radius"]]
            D = a[:, c["f_dp[1]"]]
            for i, ri in zip(ids, r):
                first.setdefault(i, t)
                last[i] = t
                rad[i] = ri
            if prev is not None:
                pids, px, pD, pt = prev
                common, ia, ib = np.intersect1d(pids, ids, assume_unique=True, return_indices=True)
                inc.append((np.full(len(common), pt), px[ia], np.abs(D[ib] - pD[ia]), np.full(len(common), t - pt)))
            prev = (ids, x, D, t)
            k = np.digitize(x, strips) - 1
            h = []
            for j in range(len(centres)):
                m = k == j
                if m.any() and np.isfinite(gs[j]):
                    h.append(float(np.max(up[m] + r[m])) - gs[j])
            self.bed.append((t, np.mean(h) if h else 0.0))
            inb = (x >= XLO) & (x <= XHI)
            self.Dmean.append((t, float(D[inb].mean()) if inb.any() else 0.0))
        if inc:
            self.inc = tuple(np.concatenate([e[j] for e in inc]) for j in range(4))
        else:
            self.inc = tuple(np.zeros(0) for _ in range(4))
        tlast = self.ft[-1] if len(self.ft) else 0.0
        gone = [i for i in first if last[i] < tlast - 1e-9]
        self.residence = np.array([last[i] - first[i] for i in gone])
        # removal: the particle was last seen at last[i] (removed before the next snapshot)
        self.t_out = np.array([last[i] for i in gone])
        self.m_out = np.array([RHO * 4.0 / 3.0 * math.pi * rad[i] ** 3 for i in gone])
        self.tlast = tlast
        self.n_seen = len(first)

    def q_window(self, t0, t1, xlo=None, xhi=None):
        """Q' pooled over the increments that start in [t0, t1) at x in [xlo, xhi) (default: all regions)."""
        xlo = XLO if xlo is None else xlo
        xhi = XHI if xhi is None else xhi
        te, xe, dD, dt = self.inc
        m = (te >= t0 - 1e-12) & (te < t1 - 1e-12) & (xe >= xlo) & (xe < xhi)
        return dD[m].sum() / dt[m].sum() if dt[m].sum() > 0 else float("nan")

    def window(self, arr):
        m = self.t >= self.t0 - 1e-12
        return float(np.mean(arr[m])) if m.any() else float("nan")

    def mass_flow(self):
        """Mass of the particles removed in [t0, tlast) / (tlast - t0)."""
        m = self.t_out >= self.t0 - 1e-12
        return float(self.m_out[m].sum() / (self.tlast - self.t0)) if self.tlast > self.t0 else float("nan")

    def mass_left(self, t):
        return np.array([self.m_out[self.t_out < tt - 1e-12].sum() for tt in t])

    def pv_bins(self):
        """Per region: count-weighted mean of P'^2 over the snapshots of the window, square root."""
        num = np.zeros(NBINS)
        den = np.zeros(NBINS)
        for step, b in self.pv:
            if step * self.dt < self.t0 - 1e-12:
                continue
            cnt, P = b[:NBINS, 0], b[:NBINS, 4]
            num += cnt * P ** 2
            den += cnt
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.sqrt(num / den)

    def q_bins(self):
        e = np.linspace(XLO, XHI, NBINS + 1)
        return np.array([self.q_window(self.t0, 1e9, e[j], e[j + 1]) for j in range(NBINS)])

    def d_bins(self):
        """Mean D per region over the window (from the dumps)."""
        e = np.linspace(XLO, XHI, NBINS + 1)
        s = np.zeros(NBINS)
        n = np.zeros(NBINS)
        for (step, cols, a), t in zip(self.frames, self.ft):
            if t < self.t0 - 1e-12 or len(a) == 0:
                continue
            c = {nm: i for i, nm in enumerate(cols)}
            k = np.digitize(a[:, c["x"]], e) - 1
            ok = (k >= 0) & (k < NBINS)
            np.add.at(s, k[ok], a[ok, c["f_dp[1]"]])
            np.add.at(n, k[ok], 1)
        with np.errstate(invalid="ignore", divide="ignore"):
            return s / n


def halves(c):
    """(holdup, P', Q') means over the two halves of the evaluation window [t0, tend]."""
    tm = 0.5 * (c.t0 + c.tend)
    a = (c.t >= c.t0 - 1e-12) & (c.t < tm)
    b = c.t >= tm
    return ((float(np.mean(c.atoms[a])), float(np.mean(c.atoms[b]))), (float(np.mean(c.P[a])), float(np.mean(c.P[b]))),
            (c.q_window(c.t0, tm), c.q_window(tm, 1e9)))


def main():
    global XHI, NBINS
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    short = "--short" in sys.argv
    long_ = "--long" in sys.argv
    work, results = args[0], args[1]
    os.makedirs(results, exist_ok=True)
    if long_:  # the geometry of the scene files for rows = 8 (their variables binhi, nbins)
        GRATE["rows"] = 8
        XHI, NBINS = 0.115 + 7 * 0.085, 16
    cases = [Case(work, spec) for spec in (LONG_CASES if long_ else CASES)]
    stops = [] if long_ else [Case(work, spec) for spec in STOPS
                              if os.path.exists(os.path.join(work, spec[0] + "_series.txt"))]
    checks = []

    def check(ok, what):
        checks.append((bool(ok), what))
        print("%s  %s" % ("PASS" if ok else "FAIL", what))

    # ------------------------------------------------------------------ time series
    fig, ax = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for c in cases + stops:
        ax[0].plot(c.t, c.P, color=c.colour, label=c.label, lw=1)
        win = 0.5
        tw = np.arange(0, c.tend, win)
        qw = [c.q_window(a, a + win) for a in tw]
        ax[1].plot(tw + 0.5 * win, qw, "-o", ms=3, color=c.colour, label=c.label + " (window %.1f s)" % win)
        ax[1].plot(c.t, c.Qfix, "--", color=c.colour, lw=0.8)
        ax[2].plot(c.t, c.mass_left(c.t), color=c.colour, label=c.label)
    ax[0].set_ylabel("P' [m/s]")
    ax[0].set_yscale("symlog", linthresh=1e-4)
    ax[1].set_ylabel("Q' [1/s]")
    ax[1].set_title("Q': windows of 0.5 s from the dumped D (solid), fix tdem/mixing/depth from t = 0 (dashed)",
                    fontsize=8)
    ax[2].set_ylabel("mass left the grate [kg]")
    ax[2].set_xlabel("t [s]")
    for a in ax:
        a.legend(fontsize=7)
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "mixing_time.png"), dpi=110)
    plt.close(fig)

    # ------------------------------------------------------------------ along the grate
    e = np.linspace(XLO, XHI, NBINS + 1)
    xc = 0.5 * (e[1:] + e[:-1])
    fig, ax = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for c in cases:
        ax[0].plot(xc, c.pv_bins(), "-o", color=c.colour, label=c.label)
        ax[1].plot(xc, c.q_bins(), "-o", color=c.colour, label=c.label)
        ax[2].plot(xc, c.d_bins(), "-o", color=c.colour, label=c.label)
    ax[0].set_ylabel("P' [m/s]")
    ax[1].set_ylabel("Q' [1/s]")
    ax[2].set_ylabel("mean D")
    ax[2].set_xlabel("x along the grate [m] (regions of %.4g m)" % (e[1] - e[0]))
    ax[0].set_title("time mean over t >= tend/2", fontsize=9)
    for a in ax:
        a.legend(fontsize=7)
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "mixing_along.png"), dpi=110)
    plt.close(fig)

    # ------------------------------------------------------------------ residence time
    fig, ax = plt.subplots(figsize=(8, 4))
    for c in cases:
        if len(c.residence):
            ax.hist(c.residence, bins=30, histtype="step", color=c.colour,
                    label="%s: n = %d, mean %.2f s, median %.2f s" % (c.label, len(c.residence),
                                                                      c.residence.mean(), np.median(c.residence)))
    ax.set_xlabel("residence time on the grate [s] (insertion to removal)")
    ax.set_ylabel("particles")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "residence.png"), dpi=110)
    plt.close(fig)

    # ------------------------------------------------------------------ table and checks
    rows = []
    for c in cases + stops:
        bm = [b for t, b in c.bed if t >= c.t0 - 1e-12]
        dm = [d for t, d in c.Dmean if t >= c.t0 - 1e-12]
        res = c.residence
        rows.append((c.label, c.window(c.P), c.q_window(c.t0, 1e9), float(np.mean(dm)) if dm else float("nan"),
                     float(np.mean(bm)) if bm else float("nan"), c.mass_flow(), c.window(c.vx),
                     int(c.fed[-1]), int(round(c.fed[-1] - c.atoms[-1])),
                     ("%.2f / %.2f (%d)" % (res.mean(), np.median(res), len(res))) if len(res) else "-"))
    with open(os.path.join(results, "table.md"), "w") as f:
        f.write("# Grate scenes: mixing, transport and residence (validation/grate)\n\n")
        f.write("Run: %s; time means over t >= tend/2 = %.3g s (tend = %.3g s); r_v = 25 mm, column 25 mm, "
                "snapshots every %.3g s (10 per stroke period).\n\n" % (
                    "short (--short)" if short else "full", cases[0].t0, cases[0].tend,
                    cases[0].ft[1] - cases[0].ft[0] if len(cases[0].ft) > 1 else float("nan")))
        f.write("| scene | mean P' [m/s] | mean Q' [1/s] | mean D | bed height [mm] | mass flow out [g/s] | "
                "mean vx [m/s] | fed | left | residence mean / median [s] (n) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s | %.4g | %.4g | %.3f | %.1f | %.3g | %.4f | %d | %d | %s |\n" % (
                r[0], r[1], r[2], r[3], 1e3 * r[4], 1e3 * r[5], r[6], r[7], r[8], r[9]))
        f.write("\nIn 2D each disk has the mass of the sphere of its diameter; the mass flow is that of one layer "
                "of disks (the 3D scenes: %s periodic width).\n" % ("120 mm" if long_ else "60 mm"))
        if long_:
            f.write("\nStationarity: the evaluation window split in two halves (holdup = particles in the box, "
                    "P' from the series, Q' from the dumped D):\n\n| scene | holdup 1st / 2nd half | P' 1st / 2nd "
                    "[m/s] | Q' 1st / 2nd [1/s] |\n|---|---|---|---|\n")
            for c in cases:
                h, p_, q = halves(c)
                f.write("| %s | %.0f / %.0f | %.4g / %.4g | %.4g / %.4g |\n" % (c.label, h[0], h[1], p_[0], p_[1],
                                                                               q[0], q[1]))

    # consistency: Q' recomputed from the dumped D = the fix's Q' accumulated from t = 0
    for c in cases:
        qall = c.q_window(-1.0, 1e9)
        rel = abs(qall - c.Qfix[-1]) / max(abs(c.Qfix[-1]), 1e-300)
        check(rel < 1e-4, "%s: Q' from the dumped D along the trajectories %.6g = fix tdem/mixing/depth %.6g "
              "(rel. diff %.2e < 1e-4; the dump has 6 digits)" % (c.label, qall, c.Qfix[-1], rel))
        check(c.window(c.P) > 0, "%s: P' > 0 on the moving grate (mean %.4g m/s)" % (c.label, c.window(c.P)))
        check(c.window(c.vx) > 0, "%s: the bed moves down the grate, mean vx = %.4g m/s > 0"
              % (c.label, c.window(c.vx)))
        left = c.fed[-1] - c.atoms[-1]
        if short:
            print("  (short run: %s: %d of %d particles left the grate)" % (c.label, left, c.fed[-1]))
        else:
            check(left > 0 and c.mass_flow() > 0, "%s: mass leaves the grate: %d particles, %.3g g/s"
                  % (c.label, left, 1e3 * c.mass_flow()))
    if len(stops) == 2 and short:
        print("  (short run: standing grate: P' over the last 0.5 s %.3g m/s (dt %.3g s), %.3g m/s (dt %.3g s); "
              "the bed has not settled yet - checked in the full run)" % (
                  float(np.mean(stops[0].P[-10:])), stops[0].dt, float(np.mean(stops[1].P[-10:])), stops[1].dt))
    elif len(stops) == 2:
        # The bed on the standing grate comes to rest; what remains of P' is the chatter of the CDT rolling
        # friction (the torque mu_r R F_n flips sign every step: a free top sphere resting on one contact
        # gets dv = mu_r g dt / 0.4 = 1.2e-3 m/s per step at dt = 2e-4 s), which vanishes with dt.
        mv = [c for c in cases if c.tag == "fwd3d"][0]
        Pm = mv.window(mv.P)
        p2, p1 = (float(np.mean(c.P[-10:])) for c in stops)
        check(p1 < 1e-2 * Pm, "standing grate (dt = %.3g s): P' over the last 0.5 s %.3g m/s < 1e-2 x P' of the "
              "moving forward 3D grate (%.3g m/s)" % (stops[1].dt, p1, Pm))
        check(p2 > 2 * p1, "standing grate: the residual P' is a time-step effect (rolling-friction chatter): "
              "%.3g m/s at dt = %.3g s, %.3g m/s at dt = %.3g s (ratio %.2f > 2)"
              % (p2, stops[0].dt, p1, stops[1].dt, p2 / p1))
    if long_:
        for c in cases:
            h, p_, q = halves(c)
            rel = lambda a: abs(a[1] - a[0]) / max(abs(a[0]), abs(a[1]), 1e-300)  # noqa: E731
            check(min(h) >= 2000, "%s: the bed holds at least 2000 particles (mean holdup %.0f / %.0f in the two "
                  "halves of the evaluation window)" % (c.label, h[0], h[1]))
            check(rel(h) <= 0.10 and rel(p_) <= 0.10 and rel(q) <= 0.15,
                  "%s: stationary over the evaluation window: holdup %.1f %%, P' %.1f %% (<= 10 %%), Q' %.1f %% "
                  "(<= 15 %%) between its halves" % (c.label, 100 * rel(h), 100 * rel(p_), 100 * rel(q)))
    with open(os.path.join(results, "checks.txt"), "w") as f:
        for ok, what in checks:
            f.write("%s  %s\n" % ("PASS" if ok else "FAIL", what))
    return 0 if all(ok for ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
