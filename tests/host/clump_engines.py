#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The same `fix tdem/clump ... insert N region R seed S` gives the same clumps in LAMMPS and in
LIGGGHTS (issue 19: both fixes place them with src/fixes/clumps/host_bodies.h).

Both engines insert 200 tetra clumps (and 100 rods in a second region, after them) into the same
box around one existing sphere, with the same seeds, and write the atoms after `run 0`. Asserted:
the same atom IDs, molecule IDs and radii, the positions equal to 1e-14 m (the engines' remap of
the positions into the box is the only arithmetic that may differ), both on 1 rank and with
LAMMPS on 2 ranks; and a check independent of both: no two spheres of different clumps overlap.

usage: clump_engines.py --lammps TDEM_LAMMPS --liggghts TDEM_LIGGGHTS [--mpirun MPIRUN] [--workdir DIR]"""
import argparse
import os
import shutil
import sys
import tempfile

import numpy as np

import mpi_env  # private TMPDIR per run (Open MPI 4.1 session-directory race)

ap = argparse.ArgumentParser()
ap.add_argument("--lammps", required=True)
ap.add_argument("--liggghts", required=True)
ap.add_argument("--mpirun", default="mpirun")
ap.add_argument("--workdir", default=None)
args = ap.parse_args()
args.lammps, args.liggghts = os.path.abspath(args.lammps), os.path.abspath(args.liggghts)

COMMON = """units si
newton off
region box block 0 0.06 0 0.06 0 0.08 units box
region ins1 block 0.005 0.055 0.005 0.055 0.005 0.045 units box
region ins2 block 0.005 0.055 0.005 0.055 0.045 0.075 units box
"""
LAMMPS = """atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
{procs}
""" + COMMON + """create_box 2 box
fix pm all property/atom mol ghost yes
create_atoms 2 single 0.03 0.03 0.03 units box
set atom 1 diameter 0.01 density 2500
group tet type 1
group rod type 1
fix c1 tet tdem/clump template tet shape tetra 0.0015 0.0025 density 2500 insert 200 region ins1 seed 4711 type 1
fix c2 rod tdem/clump template rod shape rod 0.001 0.0018 3 density 2500 insert 100 region ins2 seed 4712 type 1
neigh_modify exclude molecule/intra all
pair_style tdem/gran
pair_coeff * * normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.4
timestep 1e-6
run 0
write_dump all custom atoms.dump id mol radius x y z modify sort id format float %.17g
"""
LIGGGHTS = """atom_style hybrid sphere molecular
atom_modify map array
boundary f f f
communicate single vel yes
""" + COMMON + """create_box 2 box
neighbor 0.002 bin
neigh_modify delay 0 exclude molecule all
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-6
create_atoms 2 single 0.03 0.03 0.03 units box
set atom 1 diameter 0.01 density 2500
group tet type 1
group rod type 1
fix c1 tet tdem/clump template tet shape tetra 0.0015 0.0025 density 2500 insert 200 region ins1 seed 4711 type 1
fix c2 rod tdem/clump template rod shape rod 0.001 0.0018 3 density 2500 insert 100 region ins2 seed 4712 type 1
dump d all custom 1 atoms.dump id mol radius x y z
dump_modify d sort id format "%d %d %.17g %.17g %.17g %.17g"
run 0
"""

failed = []


def check(ok, what):
    print(("PASS " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failed.append(what)


def run(exe, text, d, np_=1):
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "in.ins"), "w") as f:
        f.write(text)
    cmd = [exe, "-in", "in.ins", "-log", "log.ins", "-echo", "none"]
    if np_ > 1:
        cmd = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    r = mpi_env.run(cmd, cwd=d, capture_output=True, text=True, errors="replace", timeout=300)
    if r.returncode != 0:
        sys.exit("FAIL: %s exited with %d:\n%s" % (exe, r.returncode, (r.stdout + r.stderr)[-3000:]))
    rows = []
    lines = open(os.path.join(d, "atoms.dump")).read().splitlines()
    n = int(lines[3])
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    for l in lines[start:start + n]:
        rows.append([float(w) for w in l.split()])
    a = np.array(rows)
    return a[np.argsort(a[:, 0])]


wd = args.workdir or tempfile.mkdtemp(prefix="tdem_clump_engines_")
shutil.rmtree(os.path.join(wd, "clump_engines"), ignore_errors=True)
wd = os.path.join(wd, "clump_engines")
lmp = run(args.lammps, LAMMPS.format(procs=""), os.path.join(wd, "lammps"))
lmp2 = run(args.lammps, LAMMPS.format(procs="processors 2 1 1"), os.path.join(wd, "lammps_np2"), np_=2)
lig = run(args.liggghts, LIGGGHTS, os.path.join(wd, "liggghts"))
n = 1 + 200 * 4 + 100 * 3
check(lmp.shape[0] == lig.shape[0] == lmp2.shape[0] == n, "%d, %d (LAMMPS -np 2), %d atoms (expected %d)"
      % (lmp.shape[0], lmp2.shape[0], lig.shape[0], n))
if lmp.shape == lig.shape == lmp2.shape:
    same_ids = np.array_equal(lmp[:, :3], lig[:, :3])
    check(same_ids, "the same atom IDs, molecule IDs and radii in both engines")
    dx = float(np.max(np.abs(lmp[:, 3:] - lig[:, 3:])))
    check(dx <= 1e-14, "the same positions in both engines: largest difference %.3g m (<= 1e-14)" % dx)
    dx2 = float(np.max(np.abs(lmp[:, 1:] - lmp2[:, 1:])))
    check(np.array_equal(lmp[:, 0], lmp2[:, 0]) and dx2 == 0.0, "LAMMPS -np 2 = -np 1 (largest difference %.3g)" % dx2)
    # independent: no overlap between spheres of different bodies (the existing sphere: molecule 0)
    x, r, mol = lmp[:, 3:6], lmp[:, 2], lmp[:, 1]
    gap = np.inf
    for i in range(len(x)):
        d = np.sqrt(np.sum((x - x[i]) ** 2, axis=1)) - (r + r[i])
        other = mol != mol[i]
        if mol[i] == 0:
            other = np.arange(len(x)) != i
        gap = min(gap, float(np.min(d[other])))
    check(gap >= 0.0, "no two spheres of different clumps overlap (smallest gap %.3g m)" % gap)
if failed:
    print("%d check(s) failed" % len(failed))
    sys.exit(1)
print("all checks passed")
