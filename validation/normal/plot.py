#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Plots and table of the normal-law fits: reads the JSON files that tdem-fit wrote into the
results directory (run.sh) and writes <stem>_e.png, <stem>_tc.png and table.md there.
All numbers come from tdem-fit (fits and integrated curves); this script only draws them."""
import glob
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

results = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")
files = sorted(glob.glob(os.path.join(results, "*.json")))
if not files:
    sys.exit(f"plot.py: no tdem-fit JSON files in {results}")

STYLE = {  # law -> (colour, line style)
    "lsd": ("tab:gray", "-"),
    "hertz_linear": ("tab:blue", "--"),
    "hertz_kuwabara_kono": ("tab:blue", "-"),
    "hertz_tsuji": ("tab:blue", ":"),
    "hertz_general": ("tab:cyan", "-."),
    "walton_braun_constant": ("tab:orange", ":"),
    "walton_braun_force_dependent": ("tab:orange", "-"),
    "thornton": ("tab:red", "-"),
    "power_law": ("tab:purple", "-"),
    "extended_linear": ("tab:green", "-"),
    "extended_hertz": ("tab:olive", "--"),
}


def nums(xs):
    return [float("nan") if x is None else x for x in xs]


def fmt(v, p=4):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "n/a"
    return f"{v:.{p}g}"


def short(text, n=90):
    text = " ".join(text.split())
    return text if len(text) <= n else text[: n - 3] + "..."


def plot(j, stem, quantity):
    fig, ax = plt.subplots(figsize=(9, 5.5))
    d = j["data"]
    key = "e" if quantity == "e" else "tc"
    scale = 1.0 if quantity == "e" else 1e3  # t_c in ms
    have_data = any(v is not None for v in d[key])
    if have_data:
        xs = [v for v, y in zip(d["v0"], d[key]) if y is not None]
        ys = [y * scale for y in d[key] if y is not None]
        errs = [(s or 0.0) * scale for y, s in zip(d[key], d[key + "_err"]) if y is not None]
        ax.errorbar(xs, ys, yerr=errs if any(errs) else None, fmt="ko", ms=6, capsize=3, zorder=10,
                    label="measured" if "fit formula" not in j["notes"] else "data (from a published fit)")
    best = {j["best_chi2"], j["best_aic"]}
    for law in j["laws"]:
        c = law["curve"]
        if not c["v0"]:
            continue
        colour, ls = STYLE.get(law["law"], ("k", "-"))
        lw = 2.6 if law["law"] in best else 1.3
        ys = [y * scale if y is not None else float("nan") for y in c[key]]
        label = f"{law['law']} (chi2 {fmt(law['chi2'], 3)})" if have_data else law["law"]
        if law["law"] == j["best_chi2"]:
            label += " best chi2"
        if law["law"] == j["best_aic"]:
            label += f" best {j['criterion']}"
        ax.plot(c["v0"], ys, ls, color=colour, lw=lw, label=label)
    ax.set_xscale("log")
    ax.set_xlabel("impact velocity v0 [m/s]")
    ax.set_ylabel("coefficient of restitution e" if quantity == "e" else "contact time t_c [ms]")
    title = short(j["material"])
    if quantity == "tc" and not have_data:
        title += "\n(no measured t_c: contact time predicted by each fitted law)"
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    out = os.path.join(results, f"{stem}_{quantity}.png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


lines = ["# Normal-law fits to measured impact data", "",
         "Written by `validation/normal/run.sh` (tdem-fit + plot.py); do not edit. How to read it: README.md.", ""]
summary = ["| data file | material | points (e / t_c) | best law, lowest chi^2 | chi^2 | best law, lowest AICc/AIC | chi^2 "
           "| also within 2 of the lowest AICc/AIC | best classical law (not extended_*), lowest AICc/AIC: chi^2 |",
           "|---|---|---|---|---|---|---|---|---|"]
sections = []
for path in files:
    stem = os.path.splitext(os.path.basename(path))[0]
    with open(path) as f:
        j = json.load(f)
    pngs = [plot(j, stem, "e"), plot(j, stem, "tc")]
    by = {l["law"]: l for l in j["laws"]}
    ne = sum(v is not None for v in j["data"]["e"])
    nt = sum(v is not None for v in j["data"]["tc"])
    bc, ba = by.get(j["best_chi2"]), by.get(j["best_aic"])
    ckey = "aicc" if j["criterion"] == "AICc" else "aic"
    classic = [l for l in j["laws"] if l["ok"] and not l["law"].startswith("extended_") and l[ckey] is not None]
    classical = min(classic, key=lambda l: l[ckey]) if classic else None
    summary.append(f"| `{stem}.csv` | {short(j['material'], 60)} | {ne} / {nt} | **{j['best_chi2']}** | "
                   f"{fmt(bc['chi2'] if bc else None, 3)} | **{j['best_aic']}** ({j['criterion']}) | "
                   f"{fmt(ba['chi2'] if ba else None, 3)} | {', '.join(j['near_best_aic']) or '-'} | "
                   f"{classical['law'] if classical else '-'}: {fmt(classical['chi2'] if classical else None, 3)} |")
    s = [f"## `{stem}.csv`", "", f"Material: {' '.join(j['material'].split())}", "",
         f"Configuration: {j['configuration']}; m* = {fmt(j['m_eff'])} kg, R* = {fmt(j['r_eff'])} m, "
         f"E* = {fmt(j['E_star'])} Pa, Hertz k~ = {fmt(j['k_hertz'])} N/m^1.5; weights: {j['weights']}; "
         f"end of contact: {j['end']}.", "",
         f"Plots: [{os.path.basename(pngs[0])}]({os.path.basename(pngs[0])}), "
         f"[{os.path.basename(pngs[1])}]({os.path.basename(pngs[1])}); full output: `{stem}.txt`.", "",
         f"| law | fitted coefficients | fixed | chi^2 | reduced chi^2 | max rel. residual | {j['criterion']} |",
         "|---|---|---|---|---|---|---|"]
    crit = "aicc" if j["criterion"] == "AICc" else "aic"
    order = sorted(j["laws"], key=lambda l: (l[crit] if l[crit] is not None else math.inf))
    for l in order:
        fitted = ", ".join(f"{c['name']} = {fmt(c['value'], 5)}" for c in l["coefficients"] if c["fitted"])
        fixed = ", ".join(f"{c['name']} = {fmt(c['value'], 4)}" for c in l["coefficients"] if not c["fitted"])
        mark = ""
        if l["law"] == j["best_chi2"]:
            mark += " (best chi^2)"
        if l["law"] == j["best_aic"]:
            mark += f" (best {j['criterion']})"
        res = f"{fmt(l['max_rel_residual'], 3)} ({l['max_rel_residual_quantity']})"
        s.append(f"| {l['law']}{mark} | {fitted} | {fixed} | {fmt(l['chi2'], 4)} | {fmt(l['reduced_chi2'], 4)} | "
                 f"{res} | {fmt(l[crit], 5)} |")
    s.append("")
    warn = [f"- {l['law']}: {l['warning']}" for l in j["laws"] if l["warning"]]
    if warn:
        s += ["Notes from tdem-fit:", ""] + warn + [""]
    s += [f"Source: {' '.join(j['source'].split())}", ""]
    sections += s

lines += ["## Best law per data set", ""] + summary + [""] + sections
with open(os.path.join(results, "table.md"), "w") as f:
    f.write("\n".join(lines) + "\n")
print(f"plot.py: wrote {len(files)} x 2 plots and table.md to {results}")
