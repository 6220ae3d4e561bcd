#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Oblique sphere-wall impacts over the impact angle for every tangential law of tdem-collide.

    sweep.py TDEM_COLLIDE OUT.csv [--step DEG] [--jobs N]

Set-up of Kharaz, Gorham & Salman (2001) (data/kharaz2001.csv): 5 mm Al2O3 sphere on soda-lime
glass, |v| = 3.9 m/s, no initial spin, mu = 0.092, normal restitution e = 0.98. Every case below
(normal law x tangential law, parameters in CONFIGS) is run at the impact angles
0.01, 0.05, 0.1, 0.25, 0.5, 1, 1+STEP, ... 85 deg from the normal. One CSV row per (case, angle) with the harness's
outcome and its rigid-body (Walton) prediction for beta_0 = 1. The same columns are what a host
run must write (README.md, "Host runs").
"""
import argparse
import concurrent.futures
import csv
import json
import math
import subprocess
import sys

# ---- the Kharaz set-up (physics_reference.md 3.5) -------------------------------------------------
R = 0.0025            # sphere radius [m]
RHO = 4000.0          # [kg/m^3]
E1, NU1 = 3.8e11, 0.23   # Al2O3
E2, NU2 = 7.0e10, 0.25   # soda-lime glass
SPEED = 3.9           # |v| [m/s]
MU = 0.092
E_N = 0.98            # normal restitution
TC_LSD = 1e-5         # contact time of the linear normal law [s] (physics_reference 8.5); the
                      # dimensionless outcome of LSD + linear tangential laws does not depend on it

MASS = 4.0 / 3.0 * math.pi * R ** 3 * RHO
M_T = 2.0 / 7.0 * MASS                       # contact-point (tangential) effective mass on a wall
ESTAR = 1.0 / ((1 - NU1 ** 2) / E1 + (1 - NU2 ** 2) / E2)
G1, G2 = E1 / (2 * (1 + NU1)), E2 / (2 * (1 + NU2))
GSTAR = 1.0 / ((2 - NU1) / G1 + (2 - NU2) / G2)
KAPPA_HM = 4.0 * GSTAR / ESTAR               # Mindlin / Hertz tangent stiffness ratio 8G*a / 2E*a
KAPPA_LIN = 2.0 / 7.0                        # equal normal and tangential periods (physics_ref 3.4)
# Hertz overlap at the head-on impact at |v| (undamped closed form), for a constant Hertz-Mindlin kt
XI_MAX = (15.0 * MASS * SPEED ** 2 / (16.0 * ESTAR * math.sqrt(R))) ** 0.4
KT_HM_MAX = 8.0 * GSTAR * math.sqrt(R * XI_MAX)
GAMMAT_HW = 10.0 * M_T / TC_LSD              # Haff-Werner: slip relaxes in t_c/10

BODY = ["--R1", repr(R), "--rho", repr(RHO), "--wall", "--v0", repr(SPEED)]
LSD = ["--law", "lsd", "--e", repr(E_N), "--tc", repr(TC_LSD), "--end", "zero_force"]
HERTZ = ["--law", "hertz", "--damping", "tsuji", "--e", repr(E_N), "--E", repr(E1), "--nu", repr(NU1),
         "--E2", repr(E2), "--nu2", repr(NU2), "--end", "zero_force"]


def lsd_gamma(collide):
    """gamma_n of the LSD law (head-on run; a parameter, not a reference value)."""
    out = subprocess.run([collide] + LSD + BODY, check=True, capture_output=True, text=True).stdout
    return json.loads(out)["parameters"]["gamma"]


def configs(collide):
    gamma_n = lsd_gamma(collide)
    mu = ["--mu", repr(MU)]
    # id, normal law, tangential law, label, family, arguments, parameter note
    return [
        ("lsd_cs", "lsd", "cundall_strack", "LSD + Cundall-Strack", "linear",
         LSD + ["--tangential", "cundall_strack"] + mu + ["--kappa", repr(KAPPA_LIN)],
         "kappa = 2/7, spring truncated on slip (the chapter-4 model, physics_reference 8.5)"),
        ("lsd_sd", "lsd", "linear_spring", "LSD + spring-dashpot", "linear",
         LSD + ["--tangential", "linear_spring"] + mu + ["--kappa", repr(KAPPA_LIN),
                                                          "--gammat", repr(KAPPA_LIN * gamma_n)],
         "kappa = 2/7, gamma_t = (2/7) gamma_n = %.5g kg/s (beta_0 = e), reset: spring only" %
         (KAPPA_LIN * gamma_n)),
        ("lsd_ls0", "lsd", "linear_spring", "LSD + linear spring, no dashpot", "linear",
         LSD + ["--tangential", "linear_spring"] + mu + ["--kappa", repr(KAPPA_LIN), "--gammat", "0"],
         "kappa = 2/7, gamma_t = 0, reset: spring only (must coincide with lsd_cs and the closed form)"),
        ("lsd_hw", "lsd", "haff_werner", "LSD + Haff-Werner", "linear",
         LSD + ["--tangential", "haff_werner"] + mu + ["--gammat", repr(GAMMAT_HW)],
         "gamma_t = 10 m_t/t_c = %.4g kg/s (slip relaxes in t_c/10)" % GAMMAT_HW),
        ("lsd_wb", "lsd", "walton_braun", "LSD + Walton-Braun", "linear",
         LSD + ["--tangential", "walton_braun"] + mu + ["--kappa", repr(KAPPA_LIN)],
         "k_t0 = (2/7) k_n"),
        ("lsd_md", "lsd", "mindlin_deresiewicz", "LSD + Mindlin-Deresiewicz", "nonlinear",
         LSD + ["--tangential", "mindlin_deresiewicz"] + mu + ["--gstar", repr(GSTAR)],
         "G* = %.4g Pa (a = sqrt(R xi) from the LSD overlap)" % GSTAR),
        ("hz_cs", "hertz_tsuji", "cundall_strack", "Hertz-Tsuji + Cundall-Strack", "linear",
         HERTZ + ["--tangential", "cundall_strack"] + mu + ["--kt", repr(KT_HM_MAX)],
         "constant k_t = 8 G* a_max = %.4g N/m (Mindlin stiffness at the head-on xi_max)" % KT_HM_MAX),
        ("hz_ls", "hertz_tsuji", "linear_spring", "Hertz-Tsuji + linear spring k_t = kappa k_n(xi)",
         "linear",
         HERTZ + ["--tangential", "linear_spring"] + mu + ["--kappa", repr(KAPPA_HM)],
         "k_t = kappa dF_n/dxi, kappa = 4G*/E* = %.4f (incremental no-slip Mindlin, no dashpot)"
         % KAPPA_HM),
        ("hz_mns", "hertz_tsuji", "mindlin_no_slip", "Hertz-Tsuji + Mindlin no-slip (Tsuji)",
         "nonlinear",
         HERTZ + ["--tangential", "mindlin_no_slip"] + mu,
         "k_t = 8 G* a, eta_t = eta_n (eta ratio 1)"),
        ("hz_dr", "hertz_tsuji", "di_renzo", "Hertz-Tsuji + Di Renzo-Di Maio", "nonlinear",
         HERTZ + ["--tangential", "di_renzo"] + mu, "k_t = (2/3) 8 G* a, no dashpot"),
        ("hz_md", "hertz_tsuji", "mindlin_deresiewicz", "Hertz-Tsuji + Mindlin-Deresiewicz",
         "nonlinear",
         HERTZ + ["--tangential", "mindlin_deresiewicz"] + mu, "G* from E, nu of both materials"),
    ]


# physics_reference.md 8.5 exactly as tabulated (k, gamma from the zero-overlap formulas, realised
# e = 0.98008 with the zero-force end): compared with data/physics_reference_8_5.csv, not plotted.
REF85_ANGLES = [5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 60.0, 80.0]
REF85 = ("ref85", "lsd", "cundall_strack", "physics_reference 8.5", "linear",
         ["--law", "lsd", "--k", "2.583963e7", "--gamma", "1.057811", "--end", "zero_force",
          "--tangential", "cundall_strack", "--mu", repr(MU), "--kappa", repr(KAPPA_LIN)],
         "physics_reference 8.5 parameters")


# The closed form of chapter 4 (tdem-collide --analytic, src/collision/analytic.h: event-driven,
# no time stepping) for the cases it covers: LSD + a linear spring with Coulomb limit, truncated on
# slip, no tangential dashpot. Both lsd_cs and lsd_ls0 are this model (the same curve); ref85 is
# the closed form with the 8.5 coefficients. Written to --analytic OUT with the columns below.
ANALYTIC_CASES = {"lsd_cs": ("lsd_cs", "lsd_ls0"), "ref85": ("ref85",)}


def analytic_case(case):
    """The case as a --analytic run: same normal law and k_t, tangential law cundall_strack."""
    cid, normal, _tang, label, family, args, note = case
    args = list(args)
    i = args.index("--tangential")
    args[i + 1] = "cundall_strack"
    if "--gammat" in args:          # linear_spring without dashpot only
        j = args.index("--gammat")
        if float(args[j + 1]) != 0.0:
            raise ValueError("case %s: the closed form has no tangential dashpot" % cid)
        del args[j:j + 2]
    return (cid, normal, "cundall_strack", label + " (closed form)", family, args + ["--analytic"], note)


COLUMNS = ["case", "normal", "tangential", "family", "angle_deg", "psi1", "slip_ratio_in",
           "beta", "e_t", "spin_after", "rebound_angle_com", "rebound_angle_contact", "slip_ratio_out",
           "e", "contact_time", "dissipated_energy", "max_tangential_force", "sliding_at_start", "n_switches",
           "rb_beta", "rb_e_t", "rb_spin_after", "rb_rebound_angle_com", "rb_rebound_angle_contact",
           "rb_gross_sliding"]


def run_one(collide, case, angle):
    cid, normal, tang, _label, family, args, _note = case
    cmd = [collide] + args + BODY + ["--angle", repr(angle), "--psi-kappa", repr(KAPPA_HM)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("tdem-collide failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr))
    j = json.loads(p.stdout)
    rb = j["rigid_body"]
    row = {
        "case": cid, "normal": normal, "tangential": tang, "family": family, "angle_deg": angle,
        "psi1": j["psi1"], "slip_ratio_in": j["slip_ratio_in"], "beta": j["beta"], "e_t": j["e_t"],
        "spin_after": j["spin_after"], "rebound_angle_com": j["rebound_angle_com"],
        "rebound_angle_contact": j["rebound_angle_contact"], "slip_ratio_out": j["slip_ratio_out"],
        "e": j["e"], "contact_time": j["contact_time"], "dissipated_energy": j["dissipated_energy"],
        "max_tangential_force": j["max_tangential_force"],
        "sliding_at_start": int(bool(j["sliding_at_start"])), "n_switches": j["n_switches"],
        "rb_beta": rb["beta"], "rb_e_t": rb["e_t"], "rb_spin_after": rb["spin_after"],
        "rb_rebound_angle_com": rb["rebound_angle_com"],
        "rb_rebound_angle_contact": rb["rebound_angle_contact"],
        "rb_gross_sliding": int(bool(rb["gross_sliding"])),
    }
    if "--analytic" in args:   # the closed form's first stick -> slip switch (regime of the angle)
        ts = [sw["t"] for sw in j.get("stick_slip_switches") or [] if sw.get("to") == "slip"]
        row["t_first_slip"] = 0.0 if j["sliding_at_start"] else (ts[0] if ts else "")
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("collide")
    ap.add_argument("out")
    ap.add_argument("--step", type=float, default=1.0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--cases-md", help="also write the case table (markdown) here")
    ap.add_argument("--analytic", help="also write the closed form (tdem-collide --analytic) of the "
                    "cases in ANALYTIC_CASES here")
    ap.add_argument("--extra-angles", default="",
                    help="comma-separated angles added to the closed form's (the host angles)")
    a = ap.parse_args()
    if not (0 < a.step <= 10):
        sys.exit("sweep.py: --step = %g is outside the allowed range (0, 10]" % a.step)
    angles = [0.01, 0.05, 0.1, 0.25, 0.5]
    x = 1.0
    while x <= 85.0 + 1e-9:
        angles.append(round(x, 6))
        x += a.step
    cases = configs(a.collide)
    jobs = [(c, t) for c in cases for t in angles] + [(REF85, t) for t in REF85_ANGLES]
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        rows = list(ex.map(lambda ct: run_one(a.collide, *ct), jobs))
    with open(a.out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    if a.analytic:
        try:
            extra = [float(x) for x in a.extra_angles.split(",") if x.strip()]
        except ValueError:
            sys.exit("sweep.py: --extra-angles '%s' is not a comma-separated list of numbers" % a.extra_angles)
        bad = [x for x in extra if not (0 < x < 90)]
        if bad:
            sys.exit("sweep.py: --extra-angles value %g is outside the allowed range (0, 90) deg" % bad[0])
        by_id = {c[0]: c for c in cases + [REF85]}
        ajobs = []
        for cid in ANALYTIC_CASES:
            ang = REF85_ANGLES if cid == "ref85" else sorted(set(angles + extra))
            ajobs += [(analytic_case(by_id[cid]), t) for t in ang]
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
            arows = list(ex.map(lambda ct: run_one(a.collide, *ct), ajobs))
        with open(a.analytic, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=COLUMNS + ["t_first_slip"])
            w.writeheader()
            for r in arows:
                w.writerow(r)
        print("sweep.py: closed form of %s -> %s" % (", ".join(ANALYTIC_CASES), a.analytic))
    if a.cases_md:
        with open(a.cases_md, "w") as f:
            f.write("| case | normal law | tangential law | parameters |\n|---|---|---|---|\n")
            for cid, normal, tang, label, family, args, note in cases:
                f.write("| `%s` | %s | %s (%s) | %s |\n" % (cid, normal, tang, family, note))
            f.write("\nCommon: R = %g m, rho = %g kg/m^3 (m = %.6g kg), |v| = %g m/s, mu = %g, e = %g; "
                    "E* = %.5g Pa, G* = %.5g Pa, psi_1 = kappa v_s0/(mu v_n0) with kappa = 4G*/E* = "
                    "%.5f for every case; LSD t_c = %g s; all normal laws end at zero force.\n"
                    % (R, RHO, MASS, SPEED, MU, E_N, ESTAR, GSTAR, KAPPA_HM, TC_LSD))
    print("sweep.py: %d cases x %d angles -> %s" % (len(cases), len(angles), a.out))


if __name__ == "__main__":
    main()
