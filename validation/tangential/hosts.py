#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Host sweeps of the oblique-impact validation: the cases of sweep.configs() in a real engine.

    hosts.py liggghts|lammps HOST_EXE OUT.csv [--collide TDEM_COLLIDE] [--angles A,B,...] [--jobs N]

Every case (normal law x tangential law, the parameters of sweep.configs()) is run as spheres
hitting the plane wall z = 0 of `fix wall/gran` (LIGGGHTS) or `fix tdem/wall/gran` (LAMMPS), one
sphere per impact angle, all angles of a case in one host process (the spheres are 1 cm apart and
never touch each other; no gravity). Each sphere starts 20 steps above the wall, so it touches at
a step boundary as in the harness. OUT.csv gets the columns of sweep.COLUMNS (the ones a host run
defines: psi1, slip ratios, beta, e_t, spin_after, both rebound angles, e; the rest empty), with
the sign convention of the harness (v_s = v_t + R omega, spin about the axis t0 x n0).

The reference of each host is tdem-collide with that host's lever arm (LIGGGHTS: R - xi/2,
`--lever-arm contact_point`; LAMMPS: R, `--lever-arm radius`) and the host's time step; it is
written next to OUT.csv as sweep_harness_<host>.csv and plot.py compares the host with it (the
issue asks for 1e-4). The time step of a case is the harness's default step (1e5 velocity-Verlet
steps per estimated contact time) at the smallest angle (shortest contact for Hertz).

Not expressible in LIGGGHTS: `hz_cs` (Cundall-Strack with a constant k_t on a Hertz normal law:
`tdem/hertz` hands the tangential law k_t = kappa dF/dxi, which grows with the overlap). It is
skipped there and listed on stderr.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import sweep as S  # noqa: E402

ANGLES = [1.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0]
N0 = 20            # free steps before the touch
SPACING = 0.01     # distance between the spheres along x [m]
LEVER = {"liggghts": "contact_point", "lammps": "radius"}


def case_params(cid, gamma_n):
    """Tangential parameters of a case in the units both hosts take."""
    return {
        "lsd_cs": dict(kappa=S.KAPPA_LIN),
        "lsd_sd": dict(kappa=S.KAPPA_LIN, gammat=S.KAPPA_LIN * gamma_n, ratio=S.KAPPA_LIN),
        "lsd_ls0": dict(kappa=S.KAPPA_LIN, gammat=0.0, ratio=0.0),
        "lsd_hw": dict(gammat=S.GAMMAT_HW, ratio=S.GAMMAT_HW / gamma_n),
        "lsd_wb": dict(kappa=S.KAPPA_LIN),
        "lsd_md": dict(),
        "hz_cs": dict(kt=S.KT_HM_MAX),
        "hz_ls": dict(kappa=S.KAPPA_HM),
        "hz_mns": dict(ratio=1.0),
        "hz_dr": dict(),
        "hz_md": dict(),
    }[cid]


# ---- LIGGGHTS ----------------------------------------------------------------------------------
def liggghts_script(case, p, dt, nsteps, starts):
    cid, normal, tang = case[0], case[1], case[2]
    if cid == "hz_cs":
        return None
    mat = lambda name, v: "fix m_%s all property/global %s peratomtypepair 2 %s\n" % (
        name, name, " ".join([repr(v)] * 4))
    props = (mat("coefficientRestitution", S.E_N) + mat("contactTime", S.TC_LSD) +
             mat("coefficientFriction", S.MU) + mat("tangentialStiffnessRatio", p.get("kappa", 0.0)) +
             mat("tangentialDampingRatio", p.get("ratio", 0.0)) +
             "fix m_E all property/global youngsModulus peratomtype %r %r\n" % (S.E1, S.E2) +
             "fix m_nu all property/global poissonsRatio peratomtype %r %r\n" % (S.NU1, S.NU2))
    if normal == "lsd":
        model, settings = "model tdem/lsd tangential tdem/%s" % tang, "parameters restitution limitForce on"
    else:
        model, settings = "model tdem/hertz tangential tdem/%s" % tang, "damping tsuji limitForce on"
    if tang in ("linear_spring", "mindlin_no_slip"):
        settings += " slipReset spring_only"
    atoms = ""
    for k, (x, z, vx, vz) in enumerate(starts, 1):
        atoms += "create_atoms 1 single %r 0.0 %r units box\n" % (x, z)
        atoms += "set atom %d diameter %r density %r\nset atom %d vx %r vz %r\n" % (
            k, 2 * S.R, S.RHO, k, vx, vz)
    return """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
hard_particles yes
region box block %r %r -0.01 0.01 -0.001 0.01 units box
create_box 2 box
neighbor 0.001 bin
neigh_modify delay 0
%s
pair_style gran %s %s
pair_coeff * *
timestep %r
%s
fix wz all wall/gran %s primitive type 2 zplane 0.0 %s
fix integr all nve/sphere
thermo 10000000
run %d
write_dump all custom dump.end id vx vz omegay modify sort id format "%%d %%.17g %%.17g %%.17g"
""" % (-SPACING, SPACING * (len(starts) + 1), props, model, settings, dt, atoms, model, settings, nsteps)


# ---- LAMMPS ------------------------------------------------------------------------------------
def lammps_law(case, p):
    cid, normal, tang = case[0], case[1], case[2]
    if normal == "lsd":
        n = "normal lsd restitution %r %r" % (S.E_N, S.TC_LSD)
    else:
        n = "normal hertz %r %r %r %r damping tsuji %r" % (S.E1, S.NU1, S.E2, S.NU2, S.E_N)
    mat = "%r %r %r %r" % (S.E1, S.NU1, S.E2, S.NU2)
    mu = repr(S.MU)
    t = {
        # a constant k_t on a Hertz normal law: cundall_strack takes KT only with `lsd stiffness`;
        # linear_spring KT 0 0 MU is the same spring + Coulomb slider without dashpot
        "cundall_strack": ("linear_spring %r 0 0 %s" % (p["kt"], mu)) if "kt" in p
        else ("cundall_strack %r %s" % (p.get("kappa", 0.0), mu)),
        "linear_spring": "linear_spring 0 %r %r %s" % (p.get("kappa", 0.0), p.get("gammat", 0.0), mu),
        "haff_werner": "haff_werner %r %s" % (p.get("gammat", 0.0), mu),
        "walton_braun": "walton_braun 0 %r %s" % (p.get("kappa", 0.0), mu),
        "mindlin_deresiewicz": "mindlin_deresiewicz %s %s" % (mat, mu),
        "mindlin_no_slip": "mindlin_no_slip %s %r %s" % (mat, p.get("ratio", 1.0), mu),
        "di_renzo": "di_renzo %s %s" % (mat, mu),
    }[tang]
    return "%s tangential %s limit_force yes slip spring" % (n, t)


def lammps_script(case, p, dt, nsteps, starts):
    law = lammps_law(case, p)
    atoms = ""
    for k, (x, z, vx, vz) in enumerate(starts, 1):
        atoms += "create_atoms 1 single %r 0 %r units box\n" % (x, z)
        atoms += "set atom %d diameter %r\nset atom %d mass %r\nset atom %d vx %r vz %r\n" % (
            k, 2 * S.R, k, S.MASS, k, vx, vz)
    return """units si
atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
region box block %r %r -0.01 0.01 -0.001 0.01 units box
create_box 1 box
%s
pair_style tdem/gran
pair_coeff * * %s
fix w all tdem/wall/gran %s zplane 0 NULL
neighbor 0.001 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep %r
thermo 10000000
run %d
write_dump all custom dump.end id vx vz omegay modify sort id format float %%.17g
""" % (-SPACING, SPACING * (len(starts) + 1), atoms, law, law, dt, nsteps)


def read_end(path):
    """id -> (vx, vz, omegay) from a single-snapshot custom dump."""
    with open(path) as f:
        lines = f.read().splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.startswith("ITEM: ATOMS"))
    out = {}
    for ln in lines[i + 1:]:
        v = ln.split()
        if len(v) == 4:
            out[int(v[0])] = tuple(float(x) for x in v[1:])
    return out


def run_case(host, exe, collide, case, gamma_n, angles, workroot):
    cid = case[0]
    p = case_params(cid, gamma_n)
    lever = LEVER[host]
    # time step: the harness default at the smallest angle (largest v_n)
    j0 = harness_json(collide, case, angles[0], ["--lever-arm", lever])
    dt = j0["dt"]
    refs = [harness_json(collide, case, a, ["--lever-arm", lever, "--dt", repr(dt)]) for a in angles]
    ref_rows = [row_from_json(case, a, j) for a, j in zip(angles, refs)]
    tc_max = max(j["contact_time"] for j in refs)
    nsteps = N0 + int(1.2 * tc_max / dt) + 200
    starts = []
    for k, a in enumerate(angles):
        vn, vt = S.SPEED * math.cos(math.radians(a)), S.SPEED * math.sin(math.radians(a))
        starts.append((SPACING * k, S.R + vn * N0 * dt, vt, -vn))
    script = (liggghts_script if host == "liggghts" else lammps_script)(case, p, dt, nsteps, starts)
    if script is None:
        return cid, None, ref_rows, "not expressible in %s" % host
    wd = tempfile.mkdtemp(prefix="tdem_sweep_%s_%s_" % (host, cid), dir=workroot)
    with open(os.path.join(wd, "in.sweep"), "w") as f:
        f.write(script)
    cmd = [exe, "-in", "in.sweep", "-log", "log.sweep", "-echo", "none"]
    r = subprocess.run(cmd, cwd=wd, capture_output=True, text=True, errors="replace")
    if r.returncode != 0 or not os.path.exists(os.path.join(wd, "dump.end")):
        raise RuntimeError("%s failed on case %s (status %d) in %s:\n%s" % (
            os.path.basename(exe), cid, r.returncode, wd, (r.stdout + r.stderr)[-3000:]))
    end = read_end(os.path.join(wd, "dump.end"))
    rows = []
    for k, a in enumerate(angles, 1):
        vx, vz, wy = end[k]
        rows.append(host_row(case, a, vx, vz, wy))
    shutil.rmtree(wd)     # kept only when the host failed
    return cid, rows, ref_rows, "dt = %.4g s, %d steps" % (dt, nsteps)


def harness_json(collide, case, angle, extra):
    cmd = [collide] + case[5] + S.BODY + ["--angle", repr(angle), "--psi-kappa", repr(S.KAPPA_HM)] + extra
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("tdem-collide failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr))
    j = json.loads(p.stdout)
    j.pop("curve", None)
    return j


def row_from_json(case, angle, j):
    cid, normal, tang, _label, family = case[:5]
    rb = j["rigid_body"]
    return {
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


def host_row(case, angle, vx, vz, wy):
    """Outcome of one host impact in the harness's frame: n = +z, t = +x (the incident slip),
    spin about -y (t x n), so v_s = v_t + R omega with omega = -omega_y."""
    cid, normal, tang, _label, family = case[:5]
    th = math.radians(angle)
    vn0, vt0 = S.SPEED * math.cos(th), S.SPEED * math.sin(th)
    omega = -wy
    vs = vx + S.R * omega
    row = {k: "" for k in S.COLUMNS}
    row.update({
        "case": cid, "normal": normal, "tangential": tang, "family": family, "angle_deg": angle,
        "psi1": S.KAPPA_HM * vt0 / (S.MU * vn0), "slip_ratio_in": vt0 / (S.MU * vn0),
        "beta": -vs / vt0, "e_t": vx / vt0, "spin_after": omega,
        "rebound_angle_com": math.degrees(math.atan2(vx, vz)),
        "rebound_angle_contact": math.degrees(math.atan2(vs, vz)),
        "slip_ratio_out": vs / (S.MU * vn0), "e": vz / vn0,
    })
    return row


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=S.COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow(r)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("host", choices=["liggghts", "lammps"])
    ap.add_argument("exe")
    ap.add_argument("out")
    ap.add_argument("--collide", default=None, help="tdem-collide (default: next to the host executable)")
    ap.add_argument("--angles", default=None, help="comma-separated impact angles in degrees")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("JOBS", "2")))
    a = ap.parse_args()
    collide = a.collide or os.environ.get("TDEM_COLLIDE") or os.path.join(os.path.dirname(a.exe), "tdem-collide")
    if not os.access(a.exe, os.X_OK):
        sys.exit("hosts.py: host executable '%s' not found" % a.exe)
    if not os.access(collide, os.X_OK):
        sys.exit("hosts.py: tdem-collide '%s' not found (--collide)" % collide)
    angles = ANGLES
    if a.angles:
        try:
            angles = [float(x) for x in a.angles.split(",")]
        except ValueError:
            sys.exit("hosts.py: --angles '%s' is not a comma-separated list of numbers" % a.angles)
        bad = [x for x in angles if not (0 < x < 90)]
        if bad:
            sys.exit("hosts.py: --angles value %g is outside the allowed range (0, 90) deg" % bad[0])
    if a.jobs < 1:
        sys.exit("hosts.py: --jobs = %d is outside the allowed range >= 1" % a.jobs)
    gamma_n = S.lsd_gamma(collide)
    cases = S.configs(collide)
    workroot = tempfile.mkdtemp(prefix="tdem_hosts_%s_" % a.host)
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
            res = list(ex.map(lambda c: run_case(a.host, a.exe, collide, c, gamma_n, angles, workroot), cases))
    except RuntimeError as err:
        sys.exit("hosts.py: %s" % err)
    rows, refs = [], []
    for cid, hr, rr, note in res:
        refs += rr
        if hr is None:
            print("hosts.py: %s: case %s skipped (%s)" % (a.host, cid, note), file=sys.stderr)
            continue
        rows += hr
        worst = max(max(abs(h["beta"] - r["beta"]), abs(h["e_t"] - r["e_t"]),
                        abs(h["spin_after"] - r["spin_after"]) * S.R / (S.SPEED * math.sin(math.radians(h["angle_deg"]))))
                    for h, r in zip(hr, rr))
        print("hosts.py: %s %-7s %s, max |host - harness| (beta, e_t, spin R/v_t0) = %.2e" % (
            a.host, cid, note, worst))
    write_csv(a.out, rows)
    try:
        os.rmdir(workroot)
    except OSError:
        pass
    ref_path = os.path.join(os.path.dirname(os.path.abspath(a.out)), "sweep_harness_%s.csv" % a.host)
    write_csv(ref_path, refs)
    print("hosts.py: %s: %d cases x %d angles -> %s (reference: %s, lever arm %s)" % (
        a.host, len(set(r["case"] for r in rows)), len(angles), a.out, ref_path, LEVER[a.host]))


if __name__ == "__main__":
    main()
