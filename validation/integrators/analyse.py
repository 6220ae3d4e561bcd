#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Table and plots of the integrator study (validation/integrators/run.sh).

Reads results/errors.csv (study.cpp) and, if present, results/cost_lammps.csv and
results/cost_liggghts.csv (columns scheme,ratio_to_nve_sphere,history_doubles: measured host cost per
particle-step relative to fix nve/sphere). Writes results/table.md, results/errors_vs_N.png and
results/pareto.png.

Cost per contact = N x (force evaluations per step) x (host cost ratio per particle-step; 1.0 where
no host measurement exists, marked in the table). Observed orders: the slope of log|error| against
log N, between N = 20 and 80 (the physics_reference 5.2 convention) and a least-squares fit over
N = 40 ... 320."""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
res = os.path.join(here, "results")
rows = list(csv.DictReader(open(os.path.join(res, "errors.csv"))))


def val(r, k):
    return float(r[k]) if r[k] not in ("", "nan") else math.nan


schemes = []
for r in rows:
    if r["scheme"] not in schemes:
        schemes.append(r["scheme"])
MULTI = ("heun", "rk4", "vv2", "abm4_pece")
info = {r["scheme"]: (int(r["evaluations_per_step"]), int(r["history_doubles"])) for r in rows}
BASE_DOUBLES = 15  # x, v, f, omega, torque


def series(case, grid, key):
    d = {}
    for r in rows:
        if r["case"] == case and r["grid"] == grid:
            d.setdefault(r["scheme"], []).append((int(r["N"]), val(r, key)))
    return {s: sorted(v) for s, v in d.items()}


def err_at(case, grid, key, scheme, n):
    for N, e in series(case, grid, key).get(scheme, []):
        if N == n:
            return e
    return math.nan


def order_pair(case, grid, key, scheme, n1, n2):
    e1, e2 = err_at(case, grid, key, scheme, n1), err_at(case, grid, key, scheme, n2)
    if not (e1 > 0 and e2 > 0):
        return math.nan
    return math.log(e1 / e2) / math.log(n2 / n1)


def order_fit(case, grid, key, scheme, nmin=40, nmax=320):
    pts = [(math.log(N), math.log(e)) for N, e in series(case, grid, key).get(scheme, [])
           if nmin <= N <= nmax and e > 0]
    if len(pts) < 2:
        return math.nan
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return -sxy / sxx


# ---- host cost ratios
cost = {}
cost_src = {}
for host in ("lammps", "liggghts"):
    p = os.path.join(res, f"cost_{host}.csv")
    if os.path.exists(p):
        for r in csv.DictReader(open(p)):
            try:
                cost.setdefault(r["scheme"], {})[host] = float(r["ratio_to_nve_sphere"])
            except (KeyError, ValueError):
                pass
        cost_src[host] = p
measured_hosts = sorted(cost_src)


GC = "+gc"  # the one-evaluation schemes with the time-grid correction (contact/grid_correction.h)


def base(s):
    return s[:-len(GC)] if s.endswith(GC) else s


def ratio(s):
    """Host cost ratio per particle-step (mean over the hosts that measured it), 1.0 if none. A
    corrected scheme costs its scheme's ratio (the correction acts in the pair loop at the start and
    end steps of contacts only; its overhead there is measured separately, bench/grid_correction)."""
    s = base(s)
    v = [cost[s][h] for h in measured_hosts if s in cost and h in cost[s]]
    return (sum(v) / len(v), True) if v else (1.0, False)


def cost_per_contact(s, n):
    return n * info[s][0] * ratio(s)[0]


def cost_for(case, grid, key, s, target):
    """Cost per contact at which |error| reaches target (log-log interpolation in N), NaN if never
    within N = 5 ... 500."""
    pts = [(N, e) for N, e in series(case, grid, key).get(s, []) if e > 0]
    for (n1, e1), (n2, e2) in zip(pts, pts[1:]):
        if e1 <= target:
            return cost_per_contact(s, n1)
        if e2 <= target < e1:
            t = math.log(e1 / target) / math.log(e1 / e2)
            n = math.exp(math.log(n1) + t * math.log(n2 / n1))
            return cost_per_contact(s, n)
    return math.nan


def fmt(x, spec=".1e"):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


# ---- plots
palette = [plt.cm.tab20(i) for i in range(20)] + [plt.cm.tab20b(i) for i in range(0, 20, 4)]
colors = {s: palette[i % len(palette)] for i, s in enumerate(schemes)}
styles = {s: ("--" if s in MULTI else "-") for s in schemes}
plain = [s for s in schemes if not s.endswith(GC)]
SHOWN_GC = ["velocity_verlet", "velocity_verlet_sync", "velocity_verlet_ab2", "beeman"]
for s in schemes:
    if s.endswith(GC):
        colors[s] = colors[base(s)]
panels = [("headon_52", "integer", "err_e", "|Δe|, 5.2 head-on, dt = t_c/N (integer N)"),
          ("headon_52", "generic", "err_e", "|Δe|, 5.2 head-on, generic dt"),
          ("oblique_25", "generic", "err_e", "|Δe|, 8.5 oblique 25°, generic dt"),
          ("oblique_25", "generic", "err_beta", "|Δβ|, 8.5 oblique 25°, generic dt"),
          ("oblique_5", "generic", "err_beta", "|Δβ|, 8.5 oblique 5° (stick), generic dt"),
          ("oblique_25", "generic", "err_rebound_contact_deg", "|Δ rebound angle (contact point)| [deg], 25°"),
          ("headon_hertz_tsuji", "generic", "err_e", "|Δe|, Hertz + Tsuji α = 0.2 head-on, generic dt"),
          ("headon_hertz_tsuji", "integer", "err_e", "|Δe|, Hertz + Tsuji, dt = t_c/N (integer N)"),
          ("oblique_60", "generic", "err_beta", "|Δβ|, 8.5 oblique 60° (gross slip), generic dt")]
fig, axs = plt.subplots(3, 3, figsize=(17, 15))
for ax, (case, grid, key, title) in zip(axs.flat, panels):
    for s, pts in series(case, grid, key).items():
        if s.endswith(GC):
            continue  # grid_correction.png
        pts = [(n, e) for n, e in pts if e > 0]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], styles[s], marker="o", ms=3, color=colors[s], label=s)
    for p, ls in ((1, ":"), (2, "-.")):
        ax.loglog([10, 320], [1e-2 * (10 / 10) ** -p, 1e-2 * (320 / 10) ** -p], ls, color="grey", lw=0.8)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("steps per contact N")
    ax.grid(True, which="both", alpha=0.3)
axs.flat[0].legend(fontsize=6, ncol=2)
fig.suptitle("Phase-averaged errors against the closed form (collision/analytic.h); dashed: multi-evaluation "
             "schemes; grey: slopes 1 and 2", fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(res, "errors_vs_N.png"), dpi=110)
plt.close(fig)

pareto_panels = [("headon_52", "generic", "err_e", "|Δe|, 5.2 head-on, generic dt"),
                 ("headon_hertz_tsuji", "generic", "err_e", "|Δe|, Hertz + Tsuji head-on, generic dt"),
                 ("oblique_25", "generic", "err_beta", "|Δβ|, 8.5 oblique 25°, generic dt"),
                 ("headon_52", "integer", "err_e", "|Δe|, 5.2 head-on, dt = t_c/N (integer N)")]
fig, axs = plt.subplots(2, 2, figsize=(15, 12))
axs = list(axs.flat)
fronts = {}
for ax, (case, grid, key, title) in zip(axs, pareto_panels):
    allpts = []
    for s, pts in series(case, grid, key).items():
        if s.endswith(GC) and base(s) not in SHOWN_GC:
            continue
        xs = [(cost_per_contact(s, n), e) for n, e in pts if e > 0]
        allpts += [(c, e, s) for c, e in xs]
        if s.endswith(GC):  # the corrected curves: thick, with squares
            ax.loglog([p[0] for p in xs], [p[1] for p in xs], "-", marker="s", ms=4, lw=2.2, color=colors[s], label=s)
        else:
            ax.loglog([p[0] for p in xs], [p[1] for p in xs], styles[s], marker="o", ms=3, color=colors[s], label=s)
    allpts.sort()
    front, best = [], math.inf
    for c, e, s in allpts:
        if e < best:
            front.append((c, e, s))
            best = e
    fronts[(case, grid, key)] = front
    ax.loglog([p[0] for p in front], [p[1] for p in front], "k-", lw=2.5, alpha=0.35, label="Pareto front")
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("cost per contact = N × F/step × host ratio" + ("" if measured_hosts else " (ratio 1.0)"))
    ax.set_ylabel("phase-averaged |error|")
    ax.grid(True, which="both", alpha=0.3)
axs[0].legend(fontsize=6, ncol=2)
fig.tight_layout()
fig.savefig(os.path.join(res, "pareto.png"), dpi=110)
plt.close(fig)

# ---- the time-grid correction (issue 22): off (dashed) and on (solid) for the Verlet forms
gc_panels = [("headon_52", "err_e", "|Δe|, LSD e = 0.8, zero-overlap end"),
             ("headon_52_zf", "err_e", "|Δe|, LSD, zero-force end"),
             ("headon_hertz_tsuji", "err_e", "|Δe|, Hertz + Tsuji α = 0.2"),
             ("oblique_25", "err_beta", "|Δβ|, oblique 25° (LSD e = 0.98 + Cundall–Strack)"),
             ("headon_52", "err_tc_rel", "|Δt_c|/t_c, LSD zero-overlap end"),
             ("headon_hertz_tsuji", "err_tc_rel", "|Δt_c|/t_c, Hertz + Tsuji")]
fig, axs = plt.subplots(2, 3, figsize=(17, 10))
for ax, (case, key, title) in zip(axs.flat, gc_panels):
    ser = series(case, "generic", key)
    for b in SHOWN_GC:
        for s, ls, lw in ((b, "--", 1.0), (b + GC, "-", 2.0)):
            pts = [(n, e) for n, e in ser.get(s, []) if e > 0]
            if pts:
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], ls, lw=lw, marker="o", ms=3,
                          color=colors[b], label=s)
    for p, ls in ((1, ":"), (2, "-.")):
        ax.loglog([5, 500], [1e-2 * (5 / 10) ** -p, 1e-2 * (500 / 10) ** -p], ls, color="grey", lw=0.8)
    ax.axhline(1e-3, color="k", lw=0.5)
    ax.axhline(1e-4, color="k", lw=0.5)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("steps per contact N (generic dt = t_c/(N + f))")
    ax.grid(True, which="both", alpha=0.3)
axs.flat[0].legend(fontsize=7)
fig.suptitle("Time-grid correction of the contact start and end steps: dashed off, solid on; grey: slopes 1 and 2",
             fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(res, "grid_correction.png"), dpi=110)
plt.close(fig)

# ---- table
L = []
L.append("# Integrator study: error against the closed form vs steps per contact, and cost\n")
L.append("Generated by `validation/integrators/run.sh` (study.cpp + analyse.py) from `errors.csv`. "
         "Errors are phase-averaged (16 start phases of the contact on the time grid) |result − closed form| "
         "(collision/analytic.h). *integer*: dt = t_c/N exactly (the physics_reference 5.2 convention); "
         "*generic*: dt = t_c/(N + f), mean over f = 1/8, 3/8, 5/8, 7/8. Cases: `headon_52` = 5.2 test "
         "(m = 0.01 kg, k = 1e5 N/m, γ = 4.48097 kg/s, variant A, frictionless); `oblique_θ` = 8.5(a) "
         "(LSD e = 0.98, t_n = 1e-5 s, zero-force end, Cundall–Strack κ = 2/7, μ = 0.092, |v| = 3.9 m/s); "
         "`headon_hertz_tsuji` = Hertz + Tsuji damping α = 0.2 (8.2 steel sphere, 1 m/s; reference: "
         "head_on.h RK4 with the located end, 160000 steps).\n")
if measured_hosts:
    L.append("Host cost ratio per particle-step (to `nve/sphere`) from " +
             ", ".join(f"`results/cost_{h}.csv`" for h in measured_hosts) +
             " (mean of the hosts); schemes without a measurement use 1.0 (marked *).\n")
else:
    L.append("**No host cost measurement found** (`results/cost_lammps.csv`, `results/cost_liggghts.csv`): "
             "the host cost ratio is taken as 1.0 for every scheme, so cost = N × force evaluations per step.\n")
L.append("Memory per particle = 15 doubles (x, v, f, ω, torque) + the scheme's history (translation + "
         "rotation; multi-evaluation schemes: what must be kept through a step).\n")
L.append("| scheme | F/step | history | memory [doubles] | host ratio | \\|Δe\\| 5.2 int. N=20 | N=80 | order 20→80 "
         "| \\|Δe\\| 5.2 generic N=20 | N=80 | order (fit 40–320) | \\|Δβ\\| 25° gen. N=80 | order | "
         "\\|Δ rebound\\| 25° N=80 [deg] | order | \\|Δe\\| Hertz–Tsuji gen. N=80 | order | "
         "cost for \\|Δe\\| ≤ 1e-3 (generic) | cost for \\|Δβ\\| ≤ 2e-4 (25°) |")
L.append("|" + "---|" * 19)
for s in schemes:
    ev, hist = info[s]
    rt, measured = ratio(s)
    L.append("| " + " | ".join([
        s, str(ev), str(hist), str(BASE_DOUBLES + hist), f"{rt:.2f}" + ("" if measured else "*"),
        fmt(err_at("headon_52", "integer", "err_e", s, 20)), fmt(err_at("headon_52", "integer", "err_e", s, 80)),
        fmt(order_pair("headon_52", "integer", "err_e", s, 20, 80), ".2f"),
        fmt(err_at("headon_52", "generic", "err_e", s, 20)), fmt(err_at("headon_52", "generic", "err_e", s, 80)),
        fmt(order_fit("headon_52", "generic", "err_e", s), ".2f"),
        fmt(err_at("oblique_25", "generic", "err_beta", s, 80)),
        fmt(order_fit("oblique_25", "generic", "err_beta", s), ".2f"),
        fmt(err_at("oblique_25", "generic", "err_rebound_contact_deg", s, 80)),
        fmt(order_fit("oblique_25", "generic", "err_rebound_contact_deg", s), ".2f"),
        fmt(err_at("headon_hertz_tsuji", "generic", "err_e", s, 80)),
        fmt(order_fit("headon_hertz_tsuji", "generic", "err_e", s), ".2f"),
        fmt(cost_for("headon_52", "generic", "err_e", s, 1e-3), ".0f"),
        fmt(cost_for("oblique_25", "generic", "err_beta", s, 2e-4), ".0f")]) + " |")
L.append("")
L.append("## Time-grid correction of the contact start and end steps (issue 22)\n")
L.append("`SCHEME+gc`: the same one-evaluation scheme with `grid_correction on` (contact/grid_correction.h). "
         "Generic dt = t_c/(N + f), f = 1/8 … 7/8, 16 phases each. Order: least-squares fit over N = 80 … 500. "
         "Target (issue 22): \\|Δe\\| ≤ 1e-3 at N ≤ 25 and ≤ 1e-4 at N ≤ 80, order ≥ 1.8; the 25° β error at "
         "most half of the uncorrected one.\n")
L.append("| case | scheme | \\|Δe\\| off N=25 | on N=25 | off N=80 | on N=80 | on N=320 | order off | order on "
         "| \\|Δt_c\\|/t_c off N=80 | on N=80 |")
L.append("|" + "---|" * 11)
for case in ("headon_52", "headon_52_zf", "headon_hertz_tsuji", "oblique_25"):
    for b in [x for x in plain if x not in MULTI]:
        if b not in SHOWN_GC and case != "headon_52":
            continue
        g = b + GC
        L.append("| " + " | ".join([
            case, b, fmt(err_at(case, "generic", "err_e", b, 25)), fmt(err_at(case, "generic", "err_e", g, 25)),
            fmt(err_at(case, "generic", "err_e", b, 80)), fmt(err_at(case, "generic", "err_e", g, 80)),
            fmt(err_at(case, "generic", "err_e", g, 320)),
            fmt(order_fit(case, "generic", "err_e", b, 80, 500), ".2f"),
            fmt(order_fit(case, "generic", "err_e", g, 80, 500), ".2f"),
            fmt(err_at(case, "generic", "err_tc_rel", b, 80)), fmt(err_at(case, "generic", "err_tc_rel", g, 80))]) + " |")
L.append("")
L.append("25° oblique, \\|Δβ\\| with / without the correction (generic dt):\n")
Ns = sorted({int(r["N"]) for r in rows})
L.append("| scheme | " + " | ".join(f"N={n}" for n in Ns) + " |")
L.append("|" + "---|" * (len(Ns) + 1))
for b in SHOWN_GC:
    cells = []
    for n in Ns:
        on, off = err_at("oblique_25", "generic", "err_beta", b + GC, n), err_at("oblique_25", "generic", "err_beta", b, n)
        cells.append(f"{fmt(on)} / {fmt(off)} ({on / off:.2f})" if on > 0 and off > 0 else "-")
    L.append(f"| {b} | " + " | ".join(cells) + " |")
L.append("")
L.append("## Energy per contact (issue 23)\n")
L.append("The energy the impact took out of the motion (kinetic energy lost, translation and rotation) against "
         "the closed form, \\|ΔE\\|/K0, phase-averaged, generic dt, next to \\|Δe\\|; and the largest residual of "
         "the energy balance K~ − K~(0) − W of contact/energy.h over the run (W: the trapezoid work of the contact "
         "force; K~ = K − h²/8 (\\|F\\|²/m + \\|T\\|²/I)), /K0: round-off for the kick-drift-kick schemes "
         "(velocity Verlet and its variants), the scheme's energy error in that sense for the others. "
         "One-evaluation schemes (the multi-evaluation ones have no such balance).\n")
L.append("| scheme | \\|Δe\\| 5.2 N=25 | \\|ΔE\\|/K0 5.2 N=25 | \\|Δe\\| 5.2 N=80 | \\|ΔE\\|/K0 5.2 N=80 "
         "| \\|ΔE\\|/K0 25° N=80 | \\|ΔE\\|/K0 Hertz–Tsuji N=80 | balance residual/K0 5.2 N=80 "
         "| balance residual/K0 Hertz–Tsuji N=80 |")
L.append("|" + "---|" * 9)
for s in schemes:
    if s in MULTI:
        continue
    L.append("| " + " | ".join([
        s, fmt(err_at("headon_52", "generic", "err_e", s, 25)), fmt(err_at("headon_52", "generic", "err_energy_rel", s, 25)),
        fmt(err_at("headon_52", "generic", "err_e", s, 80)), fmt(err_at("headon_52", "generic", "err_energy_rel", s, 80)),
        fmt(err_at("oblique_25", "generic", "err_energy_rel", s, 80)),
        fmt(err_at("headon_hertz_tsuji", "generic", "err_energy_rel", s, 80)),
        fmt(err_at("headon_52", "generic", "energy_residual_rel", s, 80)),
        fmt(err_at("headon_hertz_tsuji", "generic", "energy_residual_rel", s, 80))]) + " |")
L.append("")
L.append("## Cheapest scheme per accuracy (cost per contact, log-log interpolation in N = 5 … 500)\n")
L.append("| target | cheapest (cost) | next (cost) | velocity_verlet (= nve/sphere) cost |")
L.append("|---|---|---|---|")
targets = [("headon_52", "generic", "err_e", t, f"\\|Δe\\| ≤ {t:g}, generic dt") for t in (1e-2, 1e-3, 1e-4)]
targets += [("oblique_25", "generic", "err_beta", t, f"\\|Δβ\\| ≤ {t:g} (25°), generic dt") for t in (1e-3, 2e-4)]
targets += [("headon_hertz_tsuji", "generic", "err_e", t, f"\\|Δe\\| ≤ {t:g} (Hertz–Tsuji), generic dt")
            for t in (1e-3, 1e-4)]
targets += [("headon_52", "integer", "err_e", t, f"\\|Δe\\| ≤ {t:g}, dt = t_c/N") for t in (1e-3, 1e-5)]
for case, grid, key, t, label in targets:
    c = sorted((cost_for(case, grid, key, s, t), s) for s in schemes)
    c = [x for x in c if not math.isnan(x[0])]
    vv = cost_for(case, grid, key, "velocity_verlet", t)
    first = f"{c[0][1]} ({c[0][0]:.0f})" if c else "none within N ≤ 500"
    second = f"{c[1][1]} ({c[1][0]:.0f})" if len(c) > 1 else "-"
    L.append(f"| {label} | {first} | {second} | {fmt(vv, '.0f')} |")
L.append("")
L.append("## Pareto fronts (scheme at N on the front, generic dt)\n")
for (case, grid, key), front in fronts.items():
    L.append(f"- {case} {key} ({grid}): " + ", ".join(f"{s} ({c:.0f}: {e:.1e})" for c, e, s in front))
L.append("")
L.append("Plots: `errors_vs_N.png` (errors against N, uncorrected), `pareto.png` (error against cost per contact, "
         "with the corrected Verlet forms as thick lines), `grid_correction.png` (off and on).")
open(os.path.join(res, "table.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))
