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

# ---- --params: a unit law's input line as pair_coeff takes it (issue 19), the same closed forms
j = collide("--law walton_braun --params 1e5,1.5625e5 --m1 0.01 --wall --v0 1")
if j:
    check("walton_braun --params e", j["e"], 0.8, 1e-6)
    check("walton_braun --params t_c", j["contact_time"], 8.94113e-4, 1e-6)
    check("walton_braun --params KUL echoed", j["parameters"]["KUL"], 1.5625e5, 1e-15)
j = collide(f"--law thornton --params {E},{nu},{py} --R1 {R} --rho {rho} --wall --v0 1")
if j:
    check("thornton --params e", j["e"], e_th, 1e-6)
# luding (docs/adding_a_law.md), closed forms of Luding's law without adhesion, re-typed here:
# xi_lim = k2max/(k2max-k1) phi 2 R*; below: e = sqrt(k1/k2(xi_max)), k2 = k1 + (k2max-k1) xi_max/xi_lim;
# beyond: elastic on the k2max line about xi_0 = xi_lim (1 - k1/k2max)
def luding_closed(k1, k2m, phi, m, r, v):
    xl = k2m / (k2m - k1) * phi * 2 * r
    a = v * math.sqrt(m / k1)
    if a < xl:
        k2 = k1 + (k2m - k1) * a / xl
        return math.sqrt(k1 / k2), 0.5 * math.pi * (math.sqrt(m / k1) + math.sqrt(m / k2)), a
    x0 = xl * (1 - k1 / k2m)
    w = math.sqrt(k2m / m)
    b = math.sqrt((xl - x0) ** 2 + (v * v - k1 * xl * xl / m) / (w * w))
    return w * b / v, math.sqrt(m / k1) * math.asin(xl / a) + (math.pi - math.asin((xl - x0) / b)) / w, x0 + b


for phi, regime in ((0.05, "below xi_lim"), (0.01, "beyond xi_lim")):
    e_l, tc_l, xm_l = luding_closed(1e5, 5e5, phi, 0.01, 0.005, 1.0)
    j = collide(f"--law luding --params 1e5,5e5,{phi} --m1 0.01 --R1 0.005 --wall --v0 1")
    if j:
        check(f"luding {regime} e", j["e"], e_l, 1e-6)
        check(f"luding {regime} t_c", j["contact_time"], tc_l, 1e-6)
        check(f"luding {regime} xi_max", j["max_overlap"], xm_l, 1e-6)
        check(f"luding {regime} dissipated energy", j["dissipated_energy"], 0.5 * 0.01 * (1 - e_l**2), 1e-5)
# power law with q = 0: e = (a_l / a_ul)^(1/(2p)) for every v0
j = collide("--law power_law --params 1e7,1.5,4e7 --m1 0.01 --wall --v0 1")
if j:
    check("power_law --params e", j["e"], (1e7 / 4e7) ** (1 / 3.0), 1e-6)

# ---- --params for the laws with keyword forms (lsd, hertz, the extended laws): their pair_coeff
# input line, read by the same description as the hosts read it; the same closed forms as above
k, g, m = 1e5, 4.48097, 0.01
w0, d = math.sqrt(k / m), g / (2 * m)
w = math.sqrt(w0 * w0 - d * d)
j = collide(f"--law lsd --params stiffness,{k},{g / m} --m1 {m} --wall --v0 1")  # GAMMAN per m*
if j:
    check("lsd --params stiffness e", j["e"], math.exp(-d * math.pi / w), 1e-6)
    check("lsd --params stiffness t_c", j["contact_time"], math.pi / w, 1e-6)
j = collide("--law lsd --params restitution,0.8,1e-3 --m1 0.01 --wall --v0 1 --end zero_overlap")
if j:
    check("lsd --params restitution e", j["e"], 0.8, 1e-6)
    check("lsd --params restitution t_c", j["contact_time"], 1e-3, 1e-6)
j = collide(f"--law hertz --params {E},{nu} --R1 {R} --rho {rho} --wall --v0 1")
if j:
    xi = (5 * mh * 1.0 / (4 * kh)) ** 0.4
    check("hertz --params E NU xi_max", j["max_overlap"], xi, 1e-5)
    check("hertz --params E NU t_c", j["contact_time"], C * xi, 1e-5)
j = collide(f"--law hertz --params {E},{nu},{E},{nu},damping,tsuji,0.7 --R1 {R} --rho {rho} --wall --v0 1 "
            "--steps 20000")
if j:
    check("hertz --params damping tsuji 0.7 e", j["e"], 0.7, 1e-5)
j = collide("--law extended_linear --params e_fit,constant,0.7,tc_fit,constant,1e-3 --m1 0.01 --wall --v0 2")
if j:
    check("extended_linear --params e", j["e"], 0.7, 1e-6)
    check("extended_linear --params t_c", j["contact_time"], 1e-3, 1e-6)
j = collide("--law extended_linear --params e_fit,power,0.5,0.2,tc_fit,constant,1e-3,v_max,1 --m1 0.01 --wall "
            "--v0 2")
if j:  # v0 = 2 clamped to v_max = 1: e = (1/0.5)^-0.2
    check("extended_linear --params v_max clamps e", j["e"], 2.0 ** -0.2, 1e-6)
j = collide(f"--law extended_hertz --params {E},{nu},e_fit,power,0.5,0.2 --R1 {R} --rho {rho} --wall --v0 1 "
            "--steps 20000")
if j:
    check("extended_hertz --params e = (v0/C0)^-C1", j["e"], 2.0 ** -0.2, 1e-5)

# --params of continuous_potential: EPS N GAMMA with d = X_cut = R1 (wall): conservative, closest
# approach (d/X_min)^n = 1 + m* v0^2 / (2 eps) (the potential cut at d, physics_reference 2.2.1)
j = collide("--law continuous_potential --params 2e-3,36,0 --R1 0.005 --m1 0.01 --wall --v0 1")
if j:
    check("continuous_potential --params e", j["e"], 1.0, 1e-9)
    check("continuous_potential --params xi_max", j["max_overlap"], 0.005 * (1 - (1 + 0.01 / (2 * 2e-3)) ** (-1 / 36)),
          1e-6)

# ---- continuous potential: conservative, closest approach as asked
j = collide("--law continuous_potential --R1 0.005 --m1 0.01 --wall --x-min 0.00499 --v0 1")
if j:
    check("continuous_potential e", j["e"], 1.0, 1e-9)
    check("continuous_potential xi_max = d - X_min", j["max_overlap"], 1e-5, 1e-6)

# ---- oblique impacts, physics_reference 8.5 (LSD k, gamma from e = 0.98, t_n = 1e-5 s with the
# variant-A formulas, no attraction; Cundall-Strack spring kappa = 2/7, mu = 0.092; |v| = 3.9 m/s)
OBL = ("--law lsd --k 2.583963e7 --gamma 1.057811 --end zero_force --R1 0.0025 --rho 4000 --wall --v0 3.9 "
       "--tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857")
table85 = {  # theta: beta, e_t, omega', rebound angle of the contact point
    5: (0.99989, 0.42860, -194.22, -5.101),
    20: (0.75121, 0.49965, -667.40, -15.588),
    30: (0.10427, 0.68449, -615.24, -3.515),
    60: (-0.63189, 0.89483, -355.22, 48.156),
}


def check_abs(name, got, want, tol):
    err = abs(got - want)
    ok = err <= tol
    print(f"{'ok  ' if ok else 'FAIL'} {name}: got {got:.10g}, expected {want:.10g}, abs. error {err:.2e} (tol {tol:g})")
    if not ok:
        failures.append(f"{name}: {got} vs {want} (abs. error {err:.2e} > {tol})")


for theta, (beta, et, om, rb) in table85.items():
    j = collide(f"{OBL} --angle {theta} --steps 20000")
    if not j:
        continue
    for key in ("beta", "e_t", "spin_after", "rebound_angle_com", "rebound_angle_contact", "psi1", "psi2",
                "rigid_body", "stick_slip_switches", "vn0", "vt0", "vs0", "speed", "angle", "tangential"):
        if key not in j:
            failures.append(f"oblique JSON lacks '{key}'")
    # table digits (half a unit of the last one) plus the reference's own accuracy (~1.5e-5)
    check_abs(f"8.5 theta={theta} beta", j["beta"], beta, 0.5e-5 + 1.5e-5)
    check_abs(f"8.5 theta={theta} e_t", j["e_t"], et, 0.5e-5 + 1.5e-5)
    check_abs(f"8.5 theta={theta} spin after", j["spin_after"], om, 0.005 + 1.5e-5 * abs(om))
    check_abs(f"8.5 theta={theta} rebound angle (contact point)", j["rebound_angle_contact"], rb,
              0.0005 + 1.5e-5 * abs(rb))
    check("8.5 realised e", j["e"], 0.98008, 1e-5)
    vn0, vt0 = 3.9 * math.cos(math.radians(theta)), 3.9 * math.sin(math.radians(theta))
    check(f"theta={theta} v_n0", j["vn0"], vn0, 1e-12)
    check(f"theta={theta} psi1 = kappa v_s0/(mu v_n0)", j["psi1"], 2 / 7 * vt0 / (0.092 * vn0), 1e-9)
    check(f"theta={theta} rebound angle CoM = atan(e_t tan(theta)/e)", math.tan(math.radians(j["rebound_angle_com"])),
          j["e_t"] * math.tan(math.radians(theta)) / j["e"], 1e-9)
    if theta == 60:  # gross sliding: rigid-body closed form of 3.1, typed here
        e = j["e"]
        vs1 = vt0 - 3.5 * 0.092 * (1 + e) * vn0
        check_abs("theta=60 rigid-body beta (closed form)", j["beta"], -vs1 / vt0, 3e-5)
        check("theta=60 rigid_body.beta field", j["rigid_body"]["beta"], -vs1 / vt0, 1e-9)
        if j["rigid_body"]["gross_sliding"] is not True:
            failures.append("theta=60: rigid_body.gross_sliding is not true")
# beta_0 given; switches reported as a list
j = collide(f"{OBL} --angle 5 --steps 20000 --beta0 0.5")
if j:
    check("beta0 = 0.5 in the stick range: rigid_body.beta", j["rigid_body"]["beta"], 0.5, 1e-12)
    if j["rigid_body"]["beta0_assumed"] is not False:
        failures.append("--beta0 given but rigid_body.beta0_assumed is not false")
    sw = j["stick_slip_switches"]
    if not sw or sw[-1]["to"] != "slip" or not (0.9 * j["contact_time"] < sw[0]["t"] <= j["contact_time"]):
        failures.append(f"theta=5: expected one late switch to slip, got {sw}")
# head-on: --angle 0 (and --spin 0) gives exactly the output without them
base = "--law lsd --k 1e5 --gamma 4.48097 --m1 0.01 --wall --v0 1"
p0, p1 = run(base), run(base + " --angle 0 --spin 0")
if p0.stdout != p1.stdout or "beta" in p0.stdout:
    failures.append("--angle 0 --spin 0 changed the head-on output")
else:
    print("ok   --angle 0 --spin 0: same output as head-on")
# head-on with a tangential law: e of the normal law (variant A, k = 1e5, gamma = 4.48097), no spin
j = collide(base + " --R1 0.01 --tangential cundall_strack --mu 0.3 --kt 3e4")
if j:
    check("theta=0 with friction: e", j["e"], math.exp(-d * math.pi / w), 1e-6)
    check_abs("theta=0 with friction: spin after", j["spin_after"], 0.0, 0.0)
    if j["beta"] is not None:
        failures.append("theta=0: beta should be null (no incoming slip)")
# a sphere arriving rolling (v_s0 = v_t0 + R omega = 0) keeps its spin and tangential velocity
vt0 = 3.9 * math.sin(math.radians(30))
j = collide(f"{OBL} --angle 30 --spin {-vt0 / 0.0025!r} --steps 20000")
if j:
    check_abs("rolling sphere: v_s0", j["vs0"], 0.0, 1e-12)
    check("rolling sphere: spin after = spin before", j["spin_after"], -vt0 / 0.0025, 1e-9)
    check("rolling sphere: v_t after", j["vt"], vt0, 1e-9)
# frictionless oblique impact: e_t = 1, beta = -1 (no spin)
j = collide(f"--law lsd --k 2.583963e7 --R1 0.0025 --rho 4000 --wall --v0 3.9 --angle 45")
if j:
    check("frictionless e_t", j["e_t"], 1.0, 1e-12)
    check("frictionless beta", j["beta"], -1.0, 1e-12)
    check("frictionless elastic e", j["e"], 1.0, 1e-6)
# two equal spheres: spin of both, same sign
j = collide("--law lsd --k 2.583963e7 --gamma 1.057811 --end zero_force --R1 0.0025 --R2 0.0025 --rho 4000 "
            "--v0 3.9 --angle 60 --tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857 --steps 20000")
if j:
    if j["collision"] != "oblique_sphere_sphere" or "spin2_after" not in j:
        failures.append("sphere-sphere oblique output lacks collision/spin2_after")
    else:
        check("sphere-sphere: spin_after = spin2_after", j["spin2_after"], j["spin_after"], 1e-9)
# other tangential laws run and report their parameters
for tl in ("linear_spring --mu 0.092 --kappa 0.2857142857142857", "haff_werner --mu 0.092 --gammat 0.01",
           "mindlin_no_slip --mu 0.092", "di_renzo --mu 0.092 --gstar 6e10", "mindlin_deresiewicz --mu 0.092",
           "walton_braun --mu 0.092 --kappa 0.87"):
    j = collide(f"--law hertz --E 3.8e11 --nu 0.23 --R1 0.0025 --rho 4000 --wall --v0 3.9 --angle 30 "
                f"--tangential {tl} --steps 20000")
    if j:
        if not (j["ended"] and -1.0 <= j["beta"] <= 1.0 and j["tangential"] == tl.split()[0]):
            failures.append(f"--tangential {tl}: ended {j['ended']}, beta {j['beta']}")
        else:
            print(f"ok   --tangential {tl.split()[0]}: beta = {j['beta']:.6f}, psi1 = {j['psi1']}")
# oblique curve
curve = os.path.join(args.tmp, "collide_oblique.csv")
j = collide(f"{OBL} --angle 20 --steps 2000 --curve {curve}")
if j:
    with open(curve, newline="") as f:
        rows = list(csv.reader(f))
    if rows[0] != ["t", "xi", "xi_dot", "F", "Ft", "vs", "sliding"] or len(rows) != j["steps"] + 2:
        failures.append(f"oblique CSV header {rows[0]} / {len(rows)} rows for {j['steps']} steps")

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
    ("--law walton_braun --params 1e5 --m1 0.01 --wall --v0 1",
     "normal walton_braun needs 2 or 3 values (KL KUL [S]), got 1"),
    ("--law walton_braun --params 1e5,5e4 --m1 0.01 --wall --v0 1",
     "KUL (unloading stiffness) = 50000 is outside the allowed range [KL, inf)"),
    ("--law thornton --params 2e11,0.3,-1 --R1 0.005 --rho 7850 --wall --v0 1",
     "PY (limiting contact pressure) = -1 must be > 0"),
    ("--law walton_braun --params 1e5,abc --m1 0.01 --wall --v0 1", "--params: 'abc' is not a number"),
    ("--law luding --params 1e5,1e5,0.05 --m1 0.01 --R1 0.005 --wall --v0 1", "k2_max"),
    ("--law luding --params 1e5,5e5,0.05 --m1 0.01 --wall --v0 1", "--R1"),
    ("--law lsd --params 1e5,1 --m1 0.01 --wall --v0 1", "--params"),
    ("--law lsd --params stiffness,1e5 --m1 0.01 --wall --v0 1",
     "--params: normal lsd stiffness needs 2 values (KN GAMMAN), got 1"),
    ("--law hertz --params 2e11,0.3,damping,viscous,1 --R1 0.005 --m1 0.01 --wall --v0 1",
     "normal hertz damping 'viscous' is unknown; allowed: linear GAMMA"),
    ("--law hertz --params 2e11,0.3 --m1 0.01 --wall --v0 1", "--R1"),
    ("--law extended_hertz --params 1e9,0.3,e_fit,constant,0.5,tc_fit,constant,1e-3 --R1 0.005 --m1 0.01 --wall "
     "--v0 1", "normal extended_hertz takes no tc_fit"),
    ("--law extended_linear --params e_fit,constant,0.5,tc_fit,constant,1e-3,v_min,2,v_max,1 --m1 0.01 --wall --v0 1",
     "largest impact velocity v_max = 1 is outside the allowed range [v_min, inf)"),
    ("--law continuous_potential --params 1,2 --R1 0.005 --m1 0.01 --wall --v0 1",
     "--params: normal continuous_potential needs 3 values (EPS N GAMMA), got 2"),
    ("--law continuous_potential --params 1e-3,36,0 --m1 0.01 --wall --v0 1", "--R1"),
    ("--law walton_braun --params 1e5,2e5 --kl 1e5 --m1 0.01 --wall --v0 1", "--kl"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --steps 0", "--steps"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --steps 2.5", "--steps"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --rho 7850", "--rho"),
    ("--law continuous_potential --R1 0.005 --m1 0.01 --wall --x-min 0.006 --v0 1", "--x-min"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0", "--v0"),
    # oblique impacts
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 90", "--angle = 90 is outside the allowed range [0, 90)"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 120", "--angle = 120 is outside the allowed range [0, 90)"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle -5", "--angle = -5 is outside the allowed range [0, 90)"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle abc", "--angle"),
    ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --angle 30", "--R1"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential nope", "--tangential"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential cundall_strack --kt 1e4", "--mu"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential cundall_strack --mu -1 --kt 1e4",
     "--mu = -1 is outside the allowed range [0, inf)"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential cundall_strack --mu 0.3", "--kappa"),
    ("--law hertz --k 1e9 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential cundall_strack --mu 0.3 "
     "--kappa 0.3", "--kappa"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential cundall_strack --mu 0.3 "
     "--kt 1e4 --friction-limit sometimes", "--friction-limit"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --beta0 1.5", "--beta0 = 1.5 is outside the allowed range [-1, 1]"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --spin2 10", "--spin2"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --mu 0.3", "--mu"),
    ("--law lsd --k 1e5 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --tangential haff_werner --mu 0.3 --kt 1",
     "--kt"),
]
for cmdline, option in bad:
    p = run(cmdline, expect=2)
    if option not in p.stderr or "Traceback" in p.stderr or p.stdout:
        failures.append(f"'{cmdline}': message does not name {option}: {p.stderr.strip()}")
    else:
        print(f"ok   exit 2: {p.stderr.strip()}")

# ---- --analytic: the closed form of collision/analytic.h against the integrator (default steps), the
# physics_reference 8.5 set-up (lsd --e 0.98 --tc 1e-5 zero_force, kappa 2/7 or the same k_t, mu 0.092).
R85, V85 = 2.5e-3, 3.9
BASE85 = f"--law lsd --e 0.98 --tc 1e-5 --end zero_force --R1 {R85} --rho 4000 --wall --v0 {V85}"
for theta, tang in ((10, "--tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857"),
                    (20, "--tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857"),
                    (40, "--tangential cundall_strack --mu 0.092 --kt 1.0e6"),
                    (30, "--tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857 --spin -300 "
                         "--friction-limit positive_normal")):
    ji = collide(f"{BASE85} --angle {theta} {tang}")
    ja = collide(f"{BASE85} --angle {theta} {tang} --analytic")
    if not ji or not ja:
        continue
    if ja.get("method") != "analytic" or ji.get("method") != "integrated":
        failures.append(f"analytic {theta}: method {ja.get('method')} / {ji.get('method')}")
    missing = [k for k in ji if k not in ja]
    if missing:
        failures.append(f"analytic {theta}: keys missing from the --analytic output: {missing}")
    check_abs(f"analytic {theta} deg beta", ja["beta"], ji["beta"], 1e-5)
    check_abs(f"analytic {theta} deg e_t", ja["e_t"], ji["e_t"], 1e-5)
    check_abs(f"analytic {theta} deg spin R/v", ja["spin_after"] * R85 / V85, ji["spin_after"] * R85 / V85, 1e-5)
    check_abs(f"analytic {theta} deg e", ja["e"], 0.98, 1e-12)  # the fit, closed form
    check(f"analytic {theta} deg contact time", ja["contact_time"], 1e-5, 1e-12)
    check(f"analytic {theta} deg rebound angle", ja["rebound_angle_contact"], ji["rebound_angle_contact"], 1e-4)
    if ja["n_switches"] != ji["n_switches"]:
        failures.append(f"analytic {theta}: {ja['n_switches']} switches, integrated {ji['n_switches']}")
# frictionless, oblique and head-on, zero_overlap end: e = exp(-pi delta/w), e_t = 1, no spin
ja = collide("--law lsd --k 1e5 --gamma 4.48097 --m1 0.01 --R1 0.01 --wall --v0 1 --angle 30 --analytic")
if ja:
    d0 = 4.48097 / 0.02
    check("analytic frictionless e", ja["e"], math.exp(-d0 * math.pi / math.sqrt(1e7 - d0 * d0)), 1e-12)
    check_abs("analytic frictionless e_t", ja["e_t"], 1.0, 1e-12)
    check_abs("analytic frictionless spin", ja["spin_after"], 0.0, 1e-12)
ja = collide("--law lsd --k 1e5 --gamma 4.48097 --m1 0.01 --wall --v0 1 --analytic")
if ja:
    check("analytic head-on max_overlap", ja["max_overlap"], ja["closed_form"]["max_overlap"], 1e-12)
    check("analytic head-on t_c (table 8.1)", ja["contact_time"], 9.95962e-4, 1e-6)
    if "beta" in ja or ja["method"] != "analytic":
        failures.append("analytic head-on: oblique keys printed or method wrong")
# two spheres (radii large against the overlap: the closed form keeps the contact frame fixed, the
# integrator turns it with the line of centres) and the tangential dashpot: closed form = integrator
KAP = "--tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857"
for label, cmd in (
        ("two spheres 20 deg", f"--law lsd --e 0.98 --tc 1e-5 --end zero_force --m1 2.6e-4 --R1 25 --m2 5e-4 --R2 40 "
                               f"--v0 3.9 --angle 20 {KAP} --spin 0.01 --steps 200000"),
        ("two spheres 50 deg", f"--law lsd --e 0.9 --tc 1e-5 --m1 2.6e-4 --R1 25 --m2 2.6e-4 --R2 25 "
                               f"--v0 3.9 --angle 50 {KAP} --steps 200000"),
        ("dashpot 15 deg", f"{BASE85} --angle 15 {KAP} --gammat 0.5 --steps 400000"),
        ("dashpot 30 deg", f"{BASE85} --angle 30 {KAP} --gammat 0.5 --steps 400000")):
    ji = collide(cmd)
    ja = collide(cmd.split(" --steps")[0] + " --analytic")
    if not ji or not ja:
        continue
    for key in ("e", "beta", "e_t"):
        check_abs(f"analytic {label} {key}", ja[key], ji[key], 1e-5)
    check_abs(f"analytic {label} spin R/v", ja["spin_after"] * 25 / 3.9 if "sphere" in label else ja["spin_after"] * R85 / V85,
              ji["spin_after"] * 25 / 3.9 if "sphere" in label else ji["spin_after"] * R85 / V85, 1e-5)
W85 = "--R1 0.01 --rho 4000 --v0 1"
for cmdline, option in (
        (f"--law hertz --k 1e9 --wall {W85} --analytic", "--law hertz"),
        (f"--law lsd --k 1e5 --wall {W85} --angle 20 --tangential linear_spring --mu 0.1 --kt 1e4 --analytic",
         "--tangential linear_spring"),
        (f"--law lsd --k 1e5 --wall {W85} --angle 20 --tangential cundall_strack --mu 0.1 --kt 1e4 "
         "--lever-arm contact_point --analytic", "--lever-arm"),
        (f"--law lsd --k 1e5 --wall {W85} --steps 100 --analytic", "--steps"),
        (f"--law lsd --k 1e5 --wall {W85} --analytic --curve x.csv", "--curve")):
    p = run(cmdline, expect=2)
    if option not in p.stderr or "--analytic supports" not in p.stderr or p.stdout:
        failures.append(f"'{cmdline}': message does not name {option} and what --analytic supports: {p.stderr.strip()}")
    else:
        print(f"ok   exit 2: {p.stderr.strip()[:110]}...")

# ---- --scheme: the whole-step integration of collision/integrate_impact.h
LSD52 = "--law lsd --k 1e5 --gamma 4.48097 --m1 0.01 --R1 0.01 --wall --v0 1"
d52 = 4.48097 / (2 * 0.01)
w52 = math.sqrt(1e5 / 0.01 - d52 * d52)
e52 = math.exp(-d52 * math.pi / w52)  # the closed form (physics_reference 2.2.2, variant A)
# rk4 with dt = t_n/1e4 exactly (the contact lasts a whole number of steps, so the time-grid errors
# of the force jumps at touch (gamma v0) and at separation cancel, as in physics_reference 5.2)
tn52 = math.pi / w52
j = collide(f"{LSD52} --scheme rk4 --dt {tn52 / 1e4!r} --gap 1e-6")
if j:
    check_abs("scheme rk4 dt = t_n/1e4: e vs closed form", j["e"], e52, 1e-6)
    if j.get("scheme") != "rk4" or j.get("gap") != 1e-6 or j.get("evaluations_per_step") != 4:
        failures.append(f"scheme rk4: scheme/gap/evaluations_per_step keys wrong: {j.get('scheme')} {j.get('gap')} "
                        f"{j.get('evaluations_per_step')}")
    check("scheme rk4 reference e (analytic)", j["reference"]["e"], e52, 1e-12)
# at a step that is not a whole fraction of t_n (--steps: t_c estimate/1e4) the force jumps make
# every scheme first order in e: mean |de| over 8 phases ~ gamma v0 dt/m * O(0.1) -> (1e-6, 3e-5)
for s in ("rk4", "velocity_verlet"):
    j = collide(f"{LSD52} --scheme {s} --steps 10000 --phases 8")
    if j:
        err = j["abs_error"]["e"]
        ok = 1e-6 < err < 3e-5
        print(f"{'ok  ' if ok else 'FAIL'} scheme {s} --steps 1e4, 8 phases: mean |de| = {err:.2e} (time-grid error, "
              "first order: in (1e-6, 3e-5))")
        if not ok:
            failures.append(f"scheme {s} --steps 1e4: mean |de| {err}")
# phase average at 20 steps per contact against physics_reference 5.2 (symplectic Euler 4.7e-3 with
# dt = t_n/20 exactly; t_n = pi/w)
j = collide(f"{LSD52} --scheme symplectic_euler --dt {tn52 / 20!r} --phases 16")
if j:
    check("scheme symplectic_euler 16 phases N=20 mean |de| (table 5.2)", j["abs_error"]["e"], 4.7e-3, 0.05)
    if len(j.get("phase_e", [])) != 16:
        failures.append("scheme --phases 16: phase_e does not have 16 entries")
# oblique with a tangential law: the closed-form reference is given and the error is small at 2000 steps
j = collide(f"{BASE85} --angle 25 --tangential cundall_strack --mu 0.092 --kappa 0.2857142857142857 "
            "--scheme gear5 --steps 2000 --gap 1e-7")
if j:
    check_abs("scheme gear5 oblique beta vs analytic", j["beta"], j["reference"]["beta"], 2e-3)
    check_abs("scheme gear5 oblique e vs analytic", j["e"], j["reference"]["e"], 1e-4)
# --energy on (contact/energy.h): the parts' work adds up to the kinetic energy lost, the balance
# closes to round-off (velocity Verlet), and at 2000 steps per contact the damper takes the closed
# form 1/2 m v0^2 (1 - e^2) of variant A within the grid error; no tangential work head-on
j = collide(f"{LSD52} --scheme velocity_verlet --steps 2000 --gap 1e-7 --energy on")
if j:
    en, k0 = j.get("energy", {}), 0.5 * 0.01
    if not en:
        failures.append("--energy on: no \"energy\" object")
    else:
        check_abs("energy: total taken vs kinetic lost", en["total"], en["kinetic_lost"], 1e-13 * k0)
        check_abs("energy: balance residual", en["balance_residual_max"], 0.0, 1e-13 * k0)
        check_abs("energy: damper vs closed form 1/2 m v0^2 (1 - e^2)", en["dissipated"]["normal_damping"],
                  k0 * (1 - e52 * e52), 1e-3 * k0)
        check_abs("energy: no tangential work head-on", en["dissipated"]["tangential"], 0.0, 0.0)
j = collide(f"{LSD52} --scheme velocity_verlet --steps 200 --gap 1e-7")
if j and "energy" in j:
    failures.append("--energy off (default): an \"energy\" object is printed")
for cmdline, option in (
        (f"{LSD52} --scheme rk4 --energy on", "--energy on needs a one-evaluation scheme"),
        (f"{LSD52} --energy on", "--energy needs --scheme"),
        (f"{LSD52} --scheme velocity_verlet --energy yes", "--energy"),
        (f"{LSD52} --scheme rk5", "--scheme = 'rk5' is not one of: euler, symplectic_euler"),
        (f"{LSD52} --scheme heun --gap -1", "--gap = -1"),
        (f"{LSD52} --gap 0.1", "--gap needs --scheme"),
        (f"{LSD52} --phases 4", "--phases needs --scheme"),
        (f"{LSD52} --scheme rk4 --phases 2.5", "--phases"),
        ("--law lsd --k 1e5 --m1 0.01 --m2 0.01 --R1 0.01 --R2 0.01 --v0 1 --scheme rk4", "--wall"),
        ("--law lsd --k 1e5 --m1 0.01 --wall --v0 1 --scheme rk4", "--R1"),
        (f"{LSD52} --scheme rk4 --analytic", "--scheme")):
    p = run(cmdline, expect=2)
    if option not in p.stderr or "Traceback" in p.stderr or p.stdout:
        failures.append(f"'{cmdline}': message does not name {option}: {p.stderr.strip()}")
    else:
        print(f"ok   exit 2: {p.stderr.strip()[:120]}")

if failures:
    print("\nFAILURES:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("all tdem-collide checks passed")
