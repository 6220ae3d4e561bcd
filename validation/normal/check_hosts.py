#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Pastes the LIGGGHTS and LAMMPS lines that tdem-fit printed into a one-sphere input script, runs
the head-on impact in tdem-liggghts / tdem-lammps, and compares the restitution with the one
tdem-fit computed (its single-collision integration) at a data velocity.

    check_hosts.py RESULTS_DIR --liggghts PATH --lammps PATH [--point I]

Only for wall data (the sphere, atom type 1, hits the wall at z = 0). Writes RESULTS_DIR/hosts.md
and exits 1 if a script fails or |e_host - e_fit| > 1e-3 (velocity Verlet with dt = t_c/4000:
the host's own error is about 1e-4 at most, at the dashpot jump of lsd)."""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

ap = argparse.ArgumentParser()
ap.add_argument("results")
ap.add_argument("--liggghts")
ap.add_argument("--lammps")
ap.add_argument("--point", type=int, default=-1, help="data point (default: the middle one)")
args = ap.parse_args()
TOL = 1e-3

HEAD = {
    "liggghts": """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block {lo} {hi} {lo} {hi} {zlo} {zhi} units box
create_box 2 box
neighbor {skin} bin
neigh_modify delay 0
""",
    "lammps": """units si
atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
region box block {lo} {hi} {lo} {hi} {zlo} {zhi} units box
create_box 1 box
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
""",
}
TAIL = """timestep {dt!r}
create_atoms 1 single 0 0 {z!r} units box
set group all diameter {d!r}
set group all density {rho!r}
set atom 1 vx 0 vy 0 vz {vz!r}
fix integr all nve/sphere
variable vz equal vz[1]
thermo_style custom step v_vz
thermo_modify format float %.15g
thermo {n}
run {n}
"""


def run_one(host, exe, lines, R, rho, v0, tc, wd):
    dt = tc / 4000
    n = int(2.5 * tc / dt) + 10
    text = HEAD[host].format(lo=-4 * R, hi=4 * R, zlo=-R, zhi=8 * R, skin=R / 2)
    text += "\n".join(l for l in lines if not l.startswith("#")) + "\n"
    text += TAIL.format(dt=dt, z=R + 5 * dt * v0, d=2 * R, rho=rho, vz=-v0, n=n)
    path = os.path.join(wd, "in." + host)
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.run([exe, "-in", path, "-log", "none", "-echo", "none"], capture_output=True, text=True,
                       timeout=300, cwd=wd)
    rows = [l.split() for l in p.stdout.splitlines() if l.split()[:1] == [str(n)]]
    if p.returncode != 0 or not rows:
        err = [l for l in (p.stdout + p.stderr).splitlines() if "ERROR" in l]
        return None, (err[-1] if err else "exit %d" % p.returncode)
    return float(rows[-1][1]) / v0, ""


hosts = [(h, exe) for h, exe in (("liggghts", args.liggghts), ("lammps", args.lammps)) if exe]
if not hosts:
    sys.exit("check_hosts.py: give --liggghts and/or --lammps")
out = ["# The printed input lines in the hosts", "",
       "Written by `validation/normal/check_hosts.py` (run.sh). For every data set on a wall and every law, the "
       "LIGGGHTS and LAMMPS lines printed by tdem-fit are pasted into a one-sphere script; the sphere hits the "
       "wall at a data velocity v0 (dt = t_c/4000). e host is the rebound velocity / v0 in the host; e fit is "
       "tdem-fit's own single-collision solution. Tolerance %g." % TOL, "",
       "| data set | v0 [m/s] | law | host | e host | e fit | diff |", "|---|---|---|---|---|---|---|"]
bad = 0
with tempfile.TemporaryDirectory() as wd:
    for path in sorted(glob.glob(os.path.join(args.results, "*.json"))):
        j = json.load(open(path))
        stem = os.path.splitext(os.path.basename(path))[0]
        if j["configuration"] != "wall":
            out.append("| %s | - | - | - | (pair data: not checked) | | |" % stem)
            continue
        i = args.point if args.point >= 0 else len(j["data"]["v0"]) // 2
        v0 = j["data"]["v0"][i]
        for law in j["laws"]:
            e_fit, tc = law["model"]["e"][i], law["model"]["tc"][i]
            if e_fit is None or tc is None:
                continue
            for host, exe in hosts:
                e, err = run_one(host, exe, law[host], j["R1"], j["rho"], v0, tc, wd)
                if e is None:
                    bad += 1
                    out.append("| %s | %g | %s | %s | FAILED: %s | %.6f | |" % (stem, v0, law["law"], host, err, e_fit))
                    continue
                ok = abs(e - e_fit) <= TOL
                bad += not ok
                out.append("| %s | %g | %s | %s | %.6f | %.6f | %+.1e%s |"
                           % (stem, v0, law["law"], host, e, e_fit, e - e_fit, "" if ok else " FAIL"))
with open(os.path.join(args.results, "hosts.md"), "w") as f:
    f.write("\n".join(out) + "\n")
print("check_hosts.py: %s (%d problems)" % (os.path.join(args.results, "hosts.md"), bad))
sys.exit(1 if bad else 0)
