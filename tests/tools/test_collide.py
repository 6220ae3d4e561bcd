#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Runs tdem-collide: JSON parses, the numbers agree with closed forms re-typed here or with
physics_reference.md 8.1-8.3 (never with the program's own output), the CSV curve has the
right columns, bad input exits 2 with a message naming the option. Prints the measured errors;
exits non-zero on failure."""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--exe", required=True)
ap.add_argument("--tmp", default=".")
args = ap.parse_args()

failures = []


def run(cmdline, expect=0):
    p = subprocess.run([args.exe] + cmdline.split(), capture_output=True, text=True, timeout=60)
    if p.returncode != expect:
        failures.append(f"'{cmdline}': exit {p.returncode}, expected {expect}; stderr: {p.stderr.strip()}")
    return p


def collide(cmdline):
    p = run(cmdline)
    try:
        return json.loads(p.stdout)
    except json.JSONDecodeError as exc:
        failures.append(f"'{cmdline}': output is not JSON ({exc}): {p.stdout[:200]}")
        return None


def check(name, got, want, rel):
    err = abs(got - want) / abs(want)
    ok = err <= rel
    print(f"{'ok  ' if ok else 'FAIL'} {name}: got {got:.10g}, expected {want:.10g}, rel. error {err:.2e} (tol {rel:g})")
    if not ok:
        failures.append(f"{name}: {got} vs {want} (rel. error {err:.2e} > {rel})")


# ---- LSD, physics_reference 8.1: k = 1e5, m* = 0.01, v0 = 1, e = 0.8 row
k, g, m = 1e5, 4.48097, 0.01
w0, d = math.sqrt(k / m), g / (2 * m)
w = math.sqrt(w0 * w0 - d * d)
j = collide(f"--law lsd --k {k} --gamma {g} --m1 {m} --wall --v0 1")
if j:
    check("lsd A e", j["e"], math.exp(-d * math.pi / w), 1e-6)
    check("lsd A t_c", j["contact_time"], math.pi / w, 1e-6)
    check("lsd A t_c (table)", j["contact_time"], 9.95962e-4, 1e-6)
    check("lsd A closed_form.e field", j["closed_form"]["e"], math.exp(-d * math.pi / w), 1e-12)
    check("lsd A closed_form.contact_time field", j["closed_form"]["contact_time"], math.pi / w, 1e-12)
    for key in ("e", "contact_time", "max_overlap", "max_force", "residual_overlap", "steps", "dt", "ended",
                "rebound_velocity", "dissipated_energy", "parameters", "m_eff", "v0", "closed_form"):
        if key not in j:
            failures.append(f"JSON lacks '{key}'")
j = collide(f"--law lsd --k {k} --gamma {g} --m1 {m} --wall --v0 1 --end zero_force")
if j:
    tc = 2 * math.atan(w / d) / w
    check("lsd B e", j["e"], math.exp(-d * tc), 1e-6)
    check("lsd B t_c", j["contact_time"], tc, 1e-6)
    check("lsd B e (table)", j["e"], 0.808099, 1e-6)
# sphere-sphere: m1 = m2 = 0.02 gives the same m*
j = collide(f"--law lsd --k {k} --gamma {g} --m1 0.02 --m2 0.02 --v0 1")
if j:
    check("lsd sphere-sphere e", j["e"], math.exp(-d * math.pi / w), 1e-6)
# inverse: e = 0.8, t_c = 1e-4 for both end conventions; with the curve
curve = os.path.join(args.tmp, "collide_curve.csv")
if os.path.exists(curve):
    os.remove(curve)
j = collide(f"--law lsd --e 0.8 --tc 1e-4 --end zero_force --m1 0.01 --wall --v0 1 --curve {curve}")
if j:
    check("lsd (e, t_c) -> e", j["e"], 0.8, 1e-6)
    check("lsd (e, t_c) -> t_c", j["contact_time"], 1e-4, 1e-6)
    with open(curve, newline="") as f:
        rows = list(csv.reader(f))
    if rows[0] != ["t", "xi", "xi_dot", "F"]:
        failures.append(f"CSV header {rows[0]}")
    data = [[float(x) for x in r] for r in rows[1:]]
    if len(data) != j["steps"] + 1 or any(len(r) != 4 for r in data):
        failures.append(f"CSV has {len(data)} rows, expected steps + 1 = {j['steps'] + 1}")
    if data[0][:3] != [0.0, 0.0, 1.0] or abs(data[-1][0] - j["contact_time"]) > 0:
        failures.append(f"CSV first/last row {data[0]} {data[-1]}")
    print(f"ok   CSV {len(data)} rows, columns {rows[0]}")
j = collide("--law lsd --e 0.8 --tc 1e-4 --m1 0.01 --wall --v0 1")
if j:
    check("lsd A (e, t_c) gamma", j["parameters"]["gamma"], 44.62871, 1e-6)
    check("lsd A (e, t_c) k", j["parameters"]["k"], 9.919397e6, 1e-6)

# ---- Hertz, physics_reference 8.2: steel sphere R = 5 mm on a steel half-space
E, nu, R, rho = 2.1e11, 0.3, 0.005, 7850
es = E / (2 * (1 - nu * nu))
kh = 4 / 3 * es * math.sqrt(R)
mh = 4 / 3 * math.pi * R**3 * rho
C = 0.8 * math.sqrt(math.pi) * math.gamma(0.4) / math.gamma(0.9)
for v0, xi_tab, tc_tab in ((0.1, 1.860727e-6, 5.4766e-5), (1, 1.174039e-5, 3.4555e-5), (10, 7.407688e-5, 2.1803e-5)):
    j = collide(f"--law hertz --E {E} --nu {nu} --R1 {R} --rho {rho} --wall --v0 {v0}")
    if j:
        xi = (5 * mh * v0 * v0 / (4 * kh)) ** 0.4
        check(f"hertz v0={v0} xi_max", j["max_overlap"], xi, 1e-5)
        check(f"hertz v0={v0} t_c", j["contact_time"], C * xi / v0, 1e-5)
        check(f"hertz v0={v0} xi_max (table)", j["max_overlap"], xi_tab, 1e-6)
        check(f"hertz v0={v0} t_c (table, 5 digits)", j["contact_time"], tc_tab, 2e-5)
        check(f"hertz v0={v0} m* from --rho", j["m_eff"], 4.110250e-3, 1e-6)
# Tsuji alpha -> e (table), and e -> alpha -> e
for alpha, e_f, e_o in ((0.2, 0.76641, 0.75418), (0.5, 0.53942, 0.48640)):
    for end, e_tab in (("zero_force", e_f), ("zero_overlap", e_o)):
        j = collide(f"--law hertz --damping tsuji --alpha {alpha} --end {end} --E {E} --nu {nu} --R1 {R} "
                    f"--rho {rho} --wall --v0 5 --steps 20000")
        if j:
            check(f"tsuji alpha={alpha} {end} e (table)", j["e"], e_tab, 1e-5)
j = collide(f"--law hertz --damping tsuji --E {E} --nu {nu} --R1 {R} --rho {rho} --wall --e 0.7 --v0 1 --steps 20000")
if j:
    check("tsuji e=0.7 -> e", j["e"], 0.7, 1e-5)
    check("tsuji alpha(0.7), zero_overlap closed form", j["parameters"]["alpha"],
          -math.sqrt(5) * math.log(0.7) / math.sqrt(math.log(0.7) ** 2 + math.pi**2), 1e-9)

# ---- Walton-Braun, physics_reference 8.3
j = collide("--law walton_braun --kl 1e5 --kul 1.5625e5 --m1 0.01 --wall --v0 1")
if j:
    check("walton_braun e", j["e"], 0.8, 1e-6)
    check("walton_braun t_c", j["contact_time"], 8.94113e-4, 1e-6)
    check("walton_braun xi_f/xi_max = 1 - e^2", j["residual_overlap"] / j["max_overlap"], 1 - 0.8**2, 1e-6)
    check("walton_braun dissipated energy", j["dissipated_energy"], 0.5 * 0.01 * (1 - 0.8**2), 1e-6)
j = collide("--law walton_braun --e 0.8 --tc 8.94113e-4 --m1 0.01 --wall --v0 1")
if j:
    check("walton_braun (e, t_c) -> k_l", j["parameters"]["k_l"], 1e5, 1e-5)

# ---- Thornton: e(v_y / v0), closed form of Thornton (1997)
py = 1e9
vy = math.pi**2 / math.sqrt(40) * math.sqrt(py**5 / (es**4 * rho))
r = vy / 1.0
e_th = math.sqrt(6 * math.sqrt(3) / 5 * (1 - r * r / 6)) * (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25
j = collide(f"--law thornton --E {E} --nu {nu} --py {py} --R1 {R} --rho {rho} --wall --v0 1")
if j:
    check("thornton e", j["e"], e_th, 1e-6)
    check("thornton v_y", j["parameters"]["v_y"], vy, 1e-9)
    check("thornton energy", j["dissipated_energy"], 0.5 * mh * (1 - e_th**2), 1e-6)

# ---- continuous potential: conservative, closest approach as asked
j = collide("--law continuous_potential --R1 0.005 --m1 0.01 --wall --x-min 0.00499 --v0 1")
if j:
    check("continuous_potential e", j["e"], 1.0, 1e-9)
    check("continuous_potential xi_max = d - X_min", j["max_overlap"], 1e-5, 1e-6)

# ---- help and bad input
p = run("--help")
if "--law" not in p.stdout or "--curve" not in p.stdout:
    failures.append("--help does not document the options")
bad = [
    ("--law lsd --k -1 --m1 0.01 --wall --v0 1", "--k"),
    ("--law lsd --e 1.5 --tc 1e-4 --m1 0.01 --wall --v0 1", "--e"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 0", "--v0"),
    ("--law nope --v0 1", "--law"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --bogus 3", "--bogus"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --kl 3", "--kl"),
    ("--law lsd --k 1e5 --m1 0.01 --v0 1", "--m2"),
    ("--law lsd --k abc --m1 0.01 --wall --v0 1", "--k"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --end sideways", "--end"),
    ("--law hertz --E 2e11 --nu 0.7 --R1 0.005 --m1 0.01 --wall --v0 1", "--nu"),
    ("--law hertz --E 2e11 --nu 0.3 --m1 0.01 --wall --v0 1", "--R1"),
    ("--law walton_braun --kl 1e5 --kul 1e4 --m1 0.01 --wall --v0 1", "--kul"),
    ("--law walton_braun --kl 1e5 --m1 0.01 --wall --v0 1 --end zero_overlap", "--end"),
    ("--law thornton --E 2e11 --nu 0.3 --R1 0.005 --rho 7850 --wall --v0 1 --e 1", "--e"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --steps 0", "--steps"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --steps 2.5", "--steps"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --rho 7850", "--rho"),
    ("--law continuous_potential --R1 0.005 --m1 0.01 --wall --x-min 0.006 --v0 1", "--x-min"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0", "--v0"),
]
for cmdline, option in bad:
    p = run(cmdline, expect=2)
    if option not in p.stderr or "Traceback" in p.stderr or p.stdout:
        failures.append(f"'{cmdline}': message does not name {option}: {p.stderr.strip()}")
    else:
        print(f"ok   exit 2: {p.stderr.strip()}")

if failures:
    print("\nFAILURES:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("all tdem-collide checks passed")
