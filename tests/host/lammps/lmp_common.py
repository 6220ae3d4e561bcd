# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared helpers of the LAMMPS host tests: run an executable on an input text, read dumps
and thermo output, compare arrays."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import mpi_env  # noqa: E402


def parse_args(argv):
    """--tdem PATH --lmp PATH --plugin PATH --mpirun PATH (all optional)."""
    out = {"tdem": None, "lmp": "/usr/bin/lmp", "plugin": None, "mpirun": "mpirun",
           "examples": "/usr/share/lammps/examples", "version": "29Sep2021", "mode": "tdem"}
    i = 1
    while i < len(argv):
        key = argv[i].lstrip("-")
        out[key] = argv[i + 1]
        i += 2
    return out


_MONTHS = {m: i + 1 for i, m in enumerate(
    ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"))}


def lammps_date(args):
    """The release date of the LAMMPS under test (--version 4Jul2026) as (year, month, day)."""
    m = re.match(r"^(\d+)([A-Za-z]{3})(\d{4})$", args.get("version", ""))
    if not m:
        raise SystemExit("unknown LAMMPS version name '%s' (expected e.g. 4Jul2026)" % args.get("version"))
    return int(m.group(3)), _MONTHS[m.group(2)], int(m.group(1))


def classic_walls(args):
    """True where the stock fix wall/gran hooke/history and hertz/history are the classic code
    that tdem's fix tdem/wall/gran reproduces bit for bit (LAMMPS before mid-2023). Later
    versions compute them through the GranularModel sub-models (granular_model.cpp), with the
    same physics in another order of operations (the unit normal in place of the centre
    distance, the Coulomb rescaling through the damping force), so their results agree with
    tdem's to round-off but not bitwise, and the zcylinder wall is gone from fix wall/gran."""
    return lammps_date(args) < (2023, 6, 1)


def stock_wall_friction_sound(args):
    """False for the LAMMPS versions whose sub-model fix wall/gran hooke/history (and
    wall/gran/region) has the classic-tangential defect that LAMMPS fixed on 2026-05-29 (PR
    5007: too little dissipation, or energy gain, at grazing frictional impacts): from mid-2023
    up to the first release after the fix, 4Jul2026. There the stock walls are compared with
    tdem's only without friction."""
    d = lammps_date(args)
    return d < (2023, 6, 1) or d >= (2026, 6, 1)


_WORKDIRS = []


def workdir(name):
    """A fresh temporary directory; removed by Checker.done() when every check passed."""
    d = tempfile.mkdtemp(prefix="tdem_lmp_" + name + "_")
    _WORKDIRS.append(d)
    return d


def run(exe, text, cwd, name="in.test", np_=1, mpirun="mpirun", extra=(), timeout=300,
        check=True):
    """Write `text` to cwd/name and run `exe -in name`. Returns (returncode, stdout+stderr)."""
    path = os.path.join(cwd, name)
    with open(path, "w") as f:
        f.write(text)
    cmd = [exe, "-in", name, "-log", "log." + name, "-echo", "none"] + list(extra)
    if np_ > 1:
        cmd = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    p = mpi_env.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=timeout, text=True)
    if check and p.returncode != 0:
        sys.stdout.write(p.stdout[-4000:])
        raise RuntimeError("%s failed with status %d" % (" ".join(cmd), p.returncode))
    return p.returncode, p.stdout


def read_dump(path):
    """Read a (single-snapshot) custom dump, return (column names, array sorted by id)."""
    with open(path) as f:
        lines = f.read().splitlines()
    k = [i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")][-1]
    cols = lines[k].split()[2:]
    data = np.array([[float(x) for x in l.split()] for l in lines[k + 1:] if l.strip()])
    data = data[np.argsort(data[:, cols.index("id")])]
    return cols, data


def thermo_blocks(text):
    """All thermo lines (the rows between a 'Step' header and 'Loop time')."""
    rows, on = [], False
    for line in text.splitlines():
        s = line.split()
        if s and s[0] == "Step":
            on = True
            rows.append(line.strip())
            continue
        if line.startswith("Loop time"):
            on = False
            continue
        if on and s and re.match(r"^-?\d", s[0]):
            rows.append(line.strip())
    return rows


def rel_diff(a, b):
    """max |a-b| / max |b| per column (scale-aware relative difference), and overall max."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    scale = np.max(np.abs(b), axis=0)
    scale[scale == 0] = 1.0
    per = np.max(np.abs(a - b), axis=0) / scale
    return per, float(np.max(per))


class Checker:
    def __init__(self, name):
        self.name = name
        self.failures = []

    def check(self, ok, msg):
        print(("PASS " if ok else "FAIL ") + msg, flush=True)
        if not ok:
            self.failures.append(msg)

    def done(self):
        if self.failures:
            print("%s: %d check(s) failed; work directories kept: %s"
                  % (self.name, len(self.failures), " ".join(_WORKDIRS)))
            sys.exit(1)
        for d in _WORKDIRS:
            shutil.rmtree(d, ignore_errors=True)
        print("%s: all checks passed" % self.name)
        sys.exit(0)


# A settling bed: ~2600 spheres (diameters 4.0-4.8 mm) on a cubic lattice with random
# velocities in a box with frictional walls on all six sides, under gravity.
SCENE = """
units           si
atom_style      sphere
boundary        f f f
newton          off
comm_modify     vel yes
{processors}
region          box block 0 0.1 0 0.1 0 0.2 units box
create_box      1 box
lattice         sc 0.0052
region          fill block 0.003 0.097 0.003 0.097 0.003 0.045 units box
create_atoms    1 region fill
variable        d atom 0.0040+0.0008*random(0,1,4711)
set             group all diameter v_d
set             group all density 2500
variable        vx atom 0.05*(random(0,1,13)-0.5)
variable        vy atom 0.05*(random(0,1,17)-0.5)
variable        vz atom 0.05*(random(0,1,19)-0.5)
velocity        all set v_vx v_vy v_vz
neighbor        0.001 bin
neigh_modify    delay 0
{interaction}
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
compute         rke all erotate/sphere
thermo_style    custom step atoms ke c_rke
thermo_modify   format float %.15g
thermo          {thermo}
run             {nsteps}
write_dump      all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""

WALLS = ("xplane 0 0.1", "yplane 0 0.1", "zplane 0 0.2")


def stock_interaction(kn=2000, kt=600, gn=50, gt=25, mu=0.5, limit=False):
    arg = "%r %r %r %r %r 1%s" % (kn, kt, gn, gt, mu, " limit_damping" if limit else "")
    lines = ["pair_style gran/hooke/history " + arg, "pair_coeff * *"]
    for k, w in enumerate(WALLS):
        lines.append("fix w%d all wall/gran hooke/history %s %s" % (k, arg, w))
    return "\n".join(lines)


def stock_pair_tdem_walls(kn=2000, kt=600, gn=50, gt=25, mu=0.5, limit=False):
    """The stock pair gran/hooke/history with fix tdem/wall/gran walls of the same physics: run
    by tdem-lammps (which has every stock style), it isolates the stock pair style where the
    stock walls are not the classic code (classic_walls)."""
    arg = "%r %r %r %r %r 1%s" % (kn, kt, gn, gt, mu, " limit_damping" if limit else "")
    law = tdem_law(kn, kt, gn, gt, mu, limit)
    lines = ["pair_style gran/hooke/history " + arg, "pair_coeff * *"]
    for k, w in enumerate(WALLS):
        lines.append("fix w%d all tdem/wall/gran %s %s" % (k, law, w))
    return "\n".join(lines)


def stock_reference(args, limit=False):
    """(executable, interaction) of the stock reference run of the settling-bed scene: the stock
    lmp with stock pair and walls where the walls are classic, else tdem-lammps with the stock
    pair and tdem walls (see classic_walls)."""
    if classic_walls(args):
        return args["lmp"], stock_interaction(limit=limit)
    return args["tdem"], stock_pair_tdem_walls(limit=limit)


def tdem_law(kn=2000, kt=600, gn=50, gt=25, mu=0.5, limit=False):
    return ("normal lsd stiffness %r %r tangential cundall_strack %r %r %r limit_force %s"
            % (kn, gn, kt, gt, mu, "yes" if limit else "no"))


def tdem_interaction(law=None, walls=True, **kw):
    law = law or tdem_law(**kw)
    lines = ["pair_style tdem/gran", "pair_coeff * * " + law]
    if walls:
        for k, w in enumerate(WALLS):
            lines.append("fix w%d all tdem/wall/gran %s %s" % (k, law, w))
    return "\n".join(lines)


def scene(interaction, nsteps, dump, thermo=1000, processors=""):
    return SCENE.format(interaction=interaction, nsteps=nsteps, dump=dump, thermo=thermo,
                        processors=processors)


def small_bed_data(path, xhi=0.03, vz_shift=0.0):
    """5 x 5 x 7 spheres on a 5.2 mm lattice in a box of xhi x 0.03 x 0.06 m, diameters 4.0-4.8 mm,
    velocities +-0.1 m/s (vertical ones shifted by vz_shift), written as a LAMMPS data file."""
    rows = []
    k = 0
    for iz in range(7):
        for iy in range(5):
            for ix in range(5):
                k += 1
                x, y, z = (0.003 + 0.0052 * (i + 0.5) for i in (ix, iy, iz))
                d = 0.0040 + 0.0008 * ((k * 7919) % 101) / 100
                v = [0.2 * (((k * p) % q) / (q - 1) - 0.5) for p, q in ((104729, 97), (7907, 89), (6101, 83))]
                v[2] += vz_shift
                rows.append((k, d, x, y, z, v))
    with open(path, "w") as f:
        f.write("tdem small bed\n\n%d atoms\n1 atom types\n0 %r xlo xhi\n0 0.03 ylo yhi\n"
                "0 0.06 zlo zhi\n\nAtoms # sphere\n\n" % (len(rows), xhi))
        for k, d, x, y, z, v in rows:
            f.write("%d 1 %r 2500 %r %r %r\n" % (k, d, x, y, z))
        f.write("\nVelocities\n\n")
        for k, d, x, y, z, v in rows:
            f.write("%d %r %r %r 0 0 0\n" % (k, v[0], v[1], v[2]))
