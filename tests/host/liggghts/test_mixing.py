#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""compute tdem/mixing/velocity and fix tdem/mixing/depth in tdem-liggghts (module 'mixing',
docs/mixing_hosts.md); the scenes are data files written here (LIGGGHTS 3.8 has no displace_atoms
random), the reference is the brute-force numpy evaluation of tests/host/lammps/mixing_ref.py.
Parts (--part):
  velocity  rest / uniform translation: P' = 0; prescribed field on a jittered lattice vs numpy to
            1e-12 (also with exclude, and through fix ave/time mode vector)
  depth     layered bed on a floor: D = 0 at the surface, 1 at the grate (closed form); varying
            column heights; normalise no; jittered bed vs numpy
  rate      prescribed motion (fix nve, no forces): Q' per atom / per bin = closed form to 1e-10
  parallel  -np 1 vs -np 2 identical; write_restart / read_restart continues identically
  bad_input bad arguments end with an error naming keyword, value and the allowed values
"""
import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lammps"))
import mixing_ref as mr  # noqa: E402

sys.path.insert(0, HERE)
import tdem_lig as T  # noqa: E402
from mixing_report import GRIDS, held  # noqa: E402 (tests/host)

ap = argparse.ArgumentParser()
ap.add_argument("--tdem", required=True)
ap.add_argument("--stock", default="/usr/bin/liggghts")
ap.add_argument("--mpirun", default="mpirun")
ap.add_argument("--workdir", default=None)
ap.add_argument("--part", default="velocity")
args = ap.parse_args()
chk = T.Checks()
NAME = "liggghts.mixing." + args.part


def wd(name):
    return T.workdir(args, "tdem_lig_mix_" + args.part + "_" + name)


def run(d, text, name="test", np_=1, check=True):
    r = T.run(args.tdem, text, d, name, np_=np_, mpirun=args.mpirun, check=check)
    return r


def write_data(d, x, diam, v=None, box=((0, 0.1), (0, 0.06), (-0.01, 0.1)), name="scene.data"):
    n = len(x)
    v = np.zeros((n, 3)) if v is None else v
    lines = ["tdem mixing scene", "", "%d atoms" % n, "1 atom types", ""]
    lines += ["%.17g %.17g %slo %shi" % (box[k][0], box[k][1], a, a) for k, a in enumerate("xyz")]
    lines += ["", "Atoms", ""]
    lines += ["%d 1 %.17g 2500 %.17g %.17g %.17g" % (i + 1, diam[i], *x[i]) for i in range(n)]
    lines += ["", "Velocities", ""]
    lines += ["%d %.17g %.17g %.17g 0 0 0" % (i + 1, *v[i]) for i in range(n)]
    with open(os.path.join(d, name), "w") as f:
        f.write("\n".join(lines) + "\n")


HEAD = """
units si
atom_style granular
boundary {bnd}
atom_modify map array sort 0 0.0
neighbor 0.002 bin
communicate single vel yes
{proc}
read_data scene.data
"""


def dump_cmd(cols, name="dump.txt"):
    fmt = "%d" + " %.17g" * (len(cols) - 1)
    return 'write_dump all custom %s %s modify sort id format "%s"\n' % (name, " ".join(cols), fmt)


def last_dump(d, name="dump.txt"):
    step, cols, a = T.read_dump(os.path.join(d, name))[-1]
    return a


def thermo_rows(d, name="test"):
    with open(os.path.join(d, "log." + name)) as f:
        blocks = T.thermo_blocks(f.read())
    return [[float(v) for v in r.split()] for _, rows in blocks for r in rows]


def lattice(nx, ny, nz, a=0.01, jitter=0.0, seed=1):
    pts = np.array([(a * (i + 0.5), a * (j + 0.5), a * (k + 0.5)) for k in range(nz) for j in range(ny)
                    for i in range(nx)])
    if jitter:
        pts = pts + np.random.default_rng(seed).uniform(-jitter, jitter, pts.shape)
    return pts


# ----------------------------------------------------------------------------- velocity
def part_velocity():
    x = lattice(10, 6, 5, jitter=0.002, seed=4711)
    diam = np.full(len(x), 0.01)
    cols = ["c_m[%d]" % k for k in range(1, 6)]
    body = """
compute m all tdem/mixing/velocity radius {rv} bins x 0 0.1 4 periodic x y {excl}
fix av all ave/time 1 1 1 %s mode vector file mv.txt
thermo_style custom step c_m %s
thermo_modify format float %%.17g
run 0
""" % (" ".join(cols), " ".join("c_m[%d][%d]" % (b, k) for b in range(1, 6) for k in range(1, 6)))

    def case(v, rv=0.015, excl=""):
        d = wd("v")
        write_data(d, x, diam, v)
        run(d, HEAD.format(bnd="p p f", proc="") + body.format(rv=rv, excl=excl) + dump_cmd(["id", "x", "y", "z", "vx", "vy", "vz"]))
        row = thermo_rows(d)[-1]
        table = np.array(row[2:]).reshape(5, 5)
        a = last_dump(d)
        with open(os.path.join(d, "mv.txt")) as f:
            mv = np.array([[float(s) for s in l.split()[1:]] for l in f if not l.startswith("#")
                           and len(l.split()) == 6])
        return table, row[1], a, mv

    t, s, a, mv = case(np.zeros_like(x))
    chk.check(np.all(t[:, 1:] == 0.0) and s == 0.0 and t[4, 0] == len(x),
              "bed at rest: P' = p_k = 0 exactly, count %d" % t[4, 0])
    t, s, a, mv = case(np.tile([0.31, -0.27, 0.113], (len(x), 1)))
    chk.check(np.abs(t[:, 1:]).max() < 1e-12, "uniform translation: max P', p_k = %.3g" % np.abs(t[:, 1:]).max())
    v = np.column_stack([3.0 * x[:, 2], 0.2 * np.sin(61 * x[:, 0]) + 0.1 * x[:, 2], 0.05 * np.cos(97 * x[:, 1]) * x[:, 0]])
    for rv in (0.012, 0.021):
        t, s, a, mv = case(v, rv=rv)
        ref = mr.velocity_table(a[:, 1:4], a[:, 4:7], rv, 0, 0.0, 0.1, 4, lengths=(0.1, 0.06, None))
        chk.check(np.abs(t - ref).max() < 1e-12 and ref[4, 4] > 0.01,
                  "field v_x = 3 z + ..., r_v = %g: count/p_k/P' per bin vs numpy max diff %.3g (P' %.5g)"
                  % (rv, np.abs(t - ref).max(), ref[4, 4]))
        chk.check(abs(s - ref[4, 4]) < 1e-12, "global scalar = P' of all bins")
        chk.check(mv.shape == (5, 5) and np.abs(mv - ref).max() <= 1e-5 * np.abs(ref).max(),
                  "fix ave/time mode vector reproduces the table (6 digits): max diff %.3g" % np.abs(mv - ref).max())
    d = wd("vx")
    write_data(d, x, diam, v)
    run(d, HEAD.format(bnd="p p f", proc="") + "group low id <= 60\n" + body.format(rv=0.015, excl="exclude low")
        + dump_cmd(["id", "x", "y", "z", "vx", "vy", "vz"]))
    t = np.array(thermo_rows(d)[-1][2:]).reshape(5, 5)
    a = last_dump(d)
    ref = mr.velocity_table(a[:, 1:4], a[:, 4:7], 0.015, 0, 0.0, 0.1, 4, lengths=(0.1, 0.06, None),
                            include=a[:, 0] > 60)
    chk.check(np.abs(t - ref).max() < 1e-12 and t[4, 0] == len(x) - 60,
              "exclude low (60 atoms): vs numpy max diff %.3g" % np.abs(t - ref).max())


# ----------------------------------------------------------------------------- depth
def depth_case(x, c, floor=0.0, extra="", box=((0, 0.1), (0, 0.04), (0, 0.1))):
    d = wd("d")
    write_data(d, x, np.full(len(x), 0.01), box=box)
    run(d, HEAD.format(bnd="p p f", proc="") +
        "fix d all tdem/mixing/depth every 1 column %g bins x 0 0.1 5 floor %g %s\nrun 0\n" % (c, floor, extra) +
        dump_cmd(["id", "x", "y", "z", "radius", "f_d[1]", "f_d[2]", "f_d[3]", "f_d[4]"]))
    return last_dump(d)


def part_depth():
    x = lattice(10, 4, 5)
    a = depth_case(x, 0.025)
    z, D = a[:, 3], a[:, 5]
    expect = (0.045 - z) / 0.04
    chk.check(np.abs(D - expect).max() < 1e-12, "5 layers: D = (z_top - z)/(z_top - z_bot), max diff %.3g"
              % np.abs(D - expect).max())
    top, bot = np.isclose(z, 0.045), np.isclose(z, 0.005)
    chk.check(np.all(D[top] == 0.0) and np.all(np.abs(D[bot] - 1) < 1e-12) and top.sum() == 40,
              "D = 0 at the surface (%d atoms), 1 at the grate (%d atoms)" % (top.sum(), bot.sum()))
    x = lattice(10, 4, 8)
    keep = (x[:, 2] - 0.005) <= 0.01 * (1 + (np.floor(x[:, 0] / 0.01) % 4)) + 1e-9
    x = x[keep]
    a = depth_case(x, 0.015)
    ztop = 0.005 + 0.01 * (1 + (np.floor(a[:, 1] / 0.01) % 4))
    chk.check(np.abs(a[:, 5] - (ztop - a[:, 3]) / (ztop - 0.005)).max() < 1e-12,
              "columns of 2-5 layers: D closed form, max diff %.3g" % np.abs(a[:, 5] - (ztop - a[:, 3]) / (ztop - 0.005)).max())
    a = depth_case(x, 0.015, extra="normalise no")
    chk.check(np.abs(a[:, 5] - (ztop - a[:, 3])).max() < 1e-12, "normalise no: D = z_top - z [m]")
    x = lattice(10, 4, 5, jitter=0.002, seed=17)
    a = depth_case(x, 0.027, floor=-0.002, box=((0, 0.1), (0, 0.04), (-0.01, 0.1)))
    ref = mr.depths(a[:, 1:4], a[:, 4], 0, 2, 1, 0.027, -0.002, lengths=(0.1, 0.04, None))
    chk.check(np.abs(a[:, 5] - ref).max() < 1e-12 and 0 < ref.mean() < 1,
              "jittered bed, c = 0.027, floor -0.002: D vs numpy max diff %.3g" % np.abs(a[:, 5] - ref).max())


# ----------------------------------------------------------------------------- rate
def rate_case(u, w, tx, tz, extra=""):
    d = wd("r")
    x = np.vstack([lattice(10, 3, 6), [[tx, 0.01, tz]]])
    v = np.zeros_like(x)
    v[-1] = [u, 0, w]
    write_data(d, x, np.full(len(x), 0.01), v, box=((0, 0.1), (0, 0.03), (0, 0.1)))
    run(d, HEAD.format(bnd="p p f", proc="") + """
fix nve all nve
timestep 1e-4
fix d all tdem/mixing/depth every 10 column 0.025 bins x 0 0.1 2 floor 0 %s
thermo_style custom step f_d f_d[1][4] f_d[2][4] f_d[3][4]
thermo_modify format float %%.17g
thermo 100
run 1000
""" % extra + dump_cmd(["id", "x", "y", "z", "f_d[1]", "f_d[2]", "f_d[3]", "f_d[4]"]))
    return thermo_rows(d)[-1], last_dump(d)


def part_rate():
    w = 0.02
    last, a = rate_case(0.0, w, 0.0251, 0.012)
    q = w / 0.05
    chk.check(abs(a[-1, 7] - q) < 1e-10 * q, "tracer moving up: Q' = %.15g, closed form %.15g" % (a[-1, 7], q))
    chk.check(np.all(a[:-1, 7] == 0.0), "static particles: Q' = 0 exactly")
    chk.check(abs(last[2] - q / 91) < 1e-10 * q and last[3] == 0.0 and abs(last[4] - q / 181) < 1e-10 * q
              and last[1] == last[4], "Q'_bin1 = w/(0.05 91), Q'_bin2 = 0, Q' all = w/(0.05 181) = scalar")
    last, a = rate_case(0.0, w, 0.0251, 0.012, extra="normalise no")
    chk.check(abs(a[-1, 7] - w) < 1e-10 * w, "normalise no: Q' = w (got %.15g)" % a[-1, 7])
    u, w, tx, tz = 0.043, -0.017, 0.04813, 0.048
    last, a = rate_case(u, w, tx, tz)
    tk = np.arange(0, 1001, 10) * 1e-4
    xk, Dk = tx + u * tk, (0.055 - (tz + w * tk)) / 0.05
    dD, in1 = np.abs(np.diff(Dk)), (tx + u * tk)[:-1] < 0.05
    q1 = dD[in1].sum() / (90 * tk[-1] + 1e-3 * in1.sum())
    q2 = dD[~in1].sum() / (90 * tk[-1] + 1e-3 * (~in1).sum())
    chk.check(0 < in1.sum() < len(in1) and abs(last[2] - q1) < 1e-10 * q1 and abs(last[3] - q2) < 1e-10 * q2,
              "diagonal tracer across bins: Q'_bin1 %.12g vs %.12g, Q'_bin2 %.12g vs %.12g" % (last[2], q1, last[3], q2))


# ----------------------------------------------------------------------------- parallel / restart
SETUP = """
group half id <= 100
fix nve all nve
timestep 1e-4
compute m all tdem/mixing/velocity radius 0.015 bins x 0 0.1 4 periodic x y exclude half
fix d all tdem/mixing/depth every 5 column 0.025 bins x 0 0.1 4 floor 0
thermo_style custom step c_m c_m[1][5] c_m[2][2] c_m[3][3] f_d f_d[1][2] f_d[2][3] f_d[3][4] f_d[4][5] f_d[5][6]
thermo_modify format float %.17g
thermo 50
"""
DUMP = dump_cmd(["id", "x", "y", "z", "f_d[1]", "f_d[2]", "f_d[3]", "f_d[4]"])


def fly(d, nx=10):
    rng = np.random.default_rng(4711)
    x = lattice(nx, 4, 5, jitter=0.002, seed=31)
    v = np.column_stack([0.2 + 0.25 * rng.uniform(-1, 1, len(x)), 0.1 * rng.uniform(-1, 1, len(x)),
                         0.025 * rng.uniform(-1, 1, len(x))])
    write_data(d, x, np.full(len(x), 0.01), v, box=((0, 0.01 * nx), (0, 0.04), (-0.01, 0.1)))


def part_parallel():
    """-np 1, 2, 4, 8 (oversubscribed; splits along the up axis z, and 1 x 4 x 2 where a sub-domain is
    narrower than r_v): every output bitwise equal to -np 1; on a longer bed no rank holds the group."""
    os.environ["TDEM_MIXING_REPORT"] = "1"
    res = []
    for np_, proc in GRIDS:
        d = wd("np%d_%s" % (np_, proc.replace(" ", "")))
        fly(d)
        r = run(d, HEAD.format(bnd="p p f", proc=proc) + SETUP + "run 300\n" + DUMP, np_=np_)
        res.append((np.array(thermo_rows(d)), last_dump(d), r.stdout))
    a, da = res[0][0], res[0][1]
    chk.check(a.shape[0] == 7 and np.all(a[1:, 1:6] > 0), "thermo rows non-trivial")
    for (np_, proc), (b, db, out) in zip(GRIDS[1:], res[1:]):
        grid = " by ".join(proc.split()[1:])
        chk.check(grid in out, "-np %d runs on a %s grid" % (np_, grid))
        chk.check(a.shape == b.shape and np.abs(a - b).max() == 0.0,
                  "-np 1 vs -np %d (%s): P', p_k, Q', bin table identical (max diff %.3g)"
                  % (np_, grid, np.abs(a - b).max() if a.shape == b.shape else np.inf))
        chk.check(da.shape == db.shape and np.abs(da - db).max() == 0.0,
                  "-np 1 vs -np %d (%s): per-atom D, Dbar, sigma_D, Q' identical" % (np_, grid))
    # a bed 4 times as long on 4 ranks along x: each rank holds its own atoms and a halo, not the group
    long_setup = SETUP.replace("bins x 0 0.1 4", "bins x 0 0.4 8")
    out = {}
    for np_, proc in ((1, ""), (4, "processors 4 1 1")):
        d = wd("long%d" % np_)
        fly(d, nx=40)
        r = run(d, HEAD.format(bnd="p p f", proc=proc) + long_setup + "run 100\n" + DUMP, np_=np_)
        out[np_] = (np.array(thermo_rows(d)), last_dump(d), r.stdout)
    (a1, d1, _), (a4, d4, o4) = out[1], out[4]
    same = a1.shape == a4.shape and np.abs(a1 - a4).max() == 0.0 and np.abs(d1 - d4).max() == 0.0
    chk.check(same, "800-atom bed, -np 1 vs -np 4 (4 by 1 by 1): thermo and per-atom output identical")
    h = held(o4)
    for style in ("velocity", "depth"):
        per = [v for k, v in h.items() if k[0] == style]
        most = max(o + m for o, m, g in per) if per else -1
        chk.check(len(per) == 4 and all(g == 800 for _, _, g in per) and 0 < most < 400,
                  "800-atom bed on 4 ranks, %s: a rank holds at most %d rows (< half the group; owned, halo "
                  "incl. periodic images per rank: %s)" % (style, most, sorted((o, m) for o, m, g in per)))
    # restart
    d = wd("rst")
    fly(d)
    run(d, HEAD.format(bnd="p p f", proc="") + SETUP + "run 150\nwrite_restart mix.restart\nrun 300\n" + DUMP,
        name="ref")
    ref_rows, ref = thermo_rows(d, "ref"), last_dump(d)
    cont = """
units si
read_restart mix.restart
atom_modify sort 0 0.0
neighbor 0.002 bin
communicate single vel yes
""" + SETUP + "run 300\n" + DUMP
    for np_ in (1, 2):
        run(d, cont, name="cont%d" % np_, np_=np_)
        rows, got = thermo_rows(d, "cont%d" % np_), last_dump(d)
        same = ref_rows[-1] == rows[-1] and ref_rows[-1][0] == 450
        chk.check(same, "restart (-np %d): thermo row of step 450 identical:\n  %s\n  %s" % (np_, ref_rows[-1], rows[-1]))
        chk.check(got.shape == ref.shape and np.abs(got - ref).max() == 0.0,
                  "restart (-np %d): per-atom D, Dbar, sigma_D, Q' identical" % np_)


# ----------------------------------------------------------------------------- bad input
V = "compute m all tdem/mixing/velocity "
F = "fix d all tdem/mixing/depth "
BAD = [
    (V + "radius -1 bins x 0 0.1 4", ["radius", "'-1'", "a number > 0"]),
    (V + "radius 0.01 bins w 0 0.1 4", ["bins", "'w'", "x, y, z"]),
    (V + "radius 0.01 bins x 0 0.1 4 periodic z", ["periodic", "'z'", "periodic axes"]),
    (V + "radius 0.01 bins x 0 0.1 4 exclude nogroup", ["exclude", "'nogroup'", "existing group"]),
    (V + "radius 0.01 bins x 0 0.1 4 colour red", ["unknown keyword 'colour'", "radius, bins, periodic, exclude"]),
    (V + "radius 0.03 bins x 0 0.1 4 periodic x", ["radius", "'0.03'", "R_V <= half the periodic box length"]),
    (F + "every 0 column 0.02 bins x 0 0.1 4 floor 0", ["every", "'0'", "an integer in [1, 100000000]"]),
    (F + "every 1 column 0.02 bins x 0 0.03 100000000 floor 0", ["bins", "'100000000'", "an integer in [1, 100000]"]),
    (V + "radius 0.01 bins x 0 0.1 1000000", ["bins", "'1000000'", "an integer in [1, 100000]"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4", ["missing keyword 'grate FIXID' or 'floor H'"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 floor 0 normalise maybe", ["normalise", "'maybe'", "yes, no"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 grate nofix", ["grate", "'nofix'", "grate fix"]),
    (F + "every 1 column 0.06 bins x 0 0.1 4 floor 0", ["column", "'0.06'", "C <= the periodic box length"]),
]


def part_bad_input():
    d = wd("bad")
    write_data(d, np.array([[0.025, 0.02, 0.05]]), [0.01], box=((0, 0.05), (0, 0.04), (0, 0.1)))
    for body, subs in BAD:
        r = run(d, HEAD.format(bnd="p p f", proc="") + body + "\nrun 0\n", check=False)
        with open(os.path.join(d, "log.test"), errors="replace") as f:
            text = f.read() + r.stdout
        err = [l for l in text.splitlines() if "ERROR" in l]
        msg = err[0] if err else text[-300:]
        ok = r.returncode != 0 and err and all(s in msg for s in subs)
        chk.check(bool(ok), "%-60s -> %s" % (body[:60], msg.strip()))
    r = run(d, HEAD.format(bnd="p p f", proc="") + V + "radius 0.01 bins x 0 0.1 4 periodic x y\n" + F +
            "every 1 column 0.02 bins x 0 0.1 4 floor 0 lateral y up z normalise no\nrun 0\n", check=False)
    chk.check(r.returncode == 0, "good input runs (control)")


{"velocity": part_velocity, "depth": part_depth, "rate": part_rate, "parallel": part_parallel,
 "bad_input": part_bad_input}[args.part]()
print(NAME)
chk.done()
