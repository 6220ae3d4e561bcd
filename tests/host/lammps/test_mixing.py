#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""compute tdem/mixing/velocity and fix tdem/mixing/depth (module 'mixing', docs/mixing_hosts.md).
Parts (--part):
  velocity  a bed at rest / in uniform translation has P' = 0; a prescribed velocity field on a
            jittered lattice gives count, p_k, P' per bin equal to an independent numpy evaluation
            (mixing_ref.py, brute force) to 1e-12, also with 'exclude' and through fix ave/time
  depth     layered beds on a floor: D = 0 at the surface, 1 at the grate, linear in between (closed
            form), a jittered 3D bed and a 2D bed vs numpy, normalise no = depth in metres
  rate      prescribed motion (fix nve, no forces): Q' per particle and per bin = closed form to 1e-10
  mpi       -np 1, 2, 4, 8 (atoms migrating between the ranks) give identical outputs; no rank
            holds the whole group
  restart   write_restart / read_restart continues the accumulation identically
  bad_input bad arguments end with an error naming keyword, value and the allowed values
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402
from mixing_report import GRIDS, held  # noqa: E402 (tests/host)
import mixing_ref as mr  # noqa: E402

args = lc.parse_args(sys.argv)
part = args.get("part", "velocity")
chk = lc.Checker("lammps.mixing." + part)
EXE = args["tdem"]


def run(text, d, np_=1, name="in.test", check=True):
    return lc.run(EXE, text, d, name=name, np_=np_, mpirun=args["mpirun"], check=check)


def read_vector_file(path):
    """Last block of a fix ave/time mode vector file: rows of (index, values...)."""
    rows, block = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            s = line.split()
            if len(s) == 2:
                if block:
                    rows = block
                block = []
                continue
            block.append([float(v) for v in s[1:]])
    return np.array(block if block else rows)


HEAD = """
units si
atom_style sphere
dimension {dim}
boundary {bnd}
atom_modify map array
{proc}
region box block {box} units box
create_box 1 box
"""

# ----------------------------------------------------------------------------- velocity
LATTICE = HEAD + """
lattice sc 0.01 origin 0.5 0.5 0.5
region fill block 0 0.1 0 0.06 0.0 0.05 units box
create_atoms 1 region fill
set group all diameter 0.01
displace_atoms all random 0.002 0.002 0.002 4711 units box
group low id <= 60
{vel}
compute m all tdem/mixing/velocity radius {rv} bins x 0 0.1 4 periodic x y {excl}
fix av all ave/time 1 1 1 c_m[*] mode vector file mv.txt format " %.17g"
thermo_style custom step c_m
thermo_modify format float %.17g
run 0
write_dump all custom dump.txt id x y z vx vy vz modify sort id format float %.17g
"""


def lattice_case(vel, excl="", rv=0.015):
    d = lc.workdir("mixvel")
    run(LATTICE.format(dim=3, bnd="p p f", proc="", box="0 0.1 0 0.06 -0.01 0.07", vel=vel, rv=rv,
                       excl=excl), d)
    table = read_vector_file(os.path.join(d, "mv.txt"))
    cols, data = lc.read_dump(os.path.join(d, "dump.txt"))
    x = data[:, 1:4]
    v = data[:, 4:7]
    with open(os.path.join(d, "log.in.test")) as f:
        rows = lc.thermo_blocks(f.read())
    scalar = float(rows[1].split()[1])
    return table, x, v, data[:, 0], scalar


def part_velocity():
    # (1) at rest: exactly 0; uniform translation: < 1e-12
    t, x, v, ids, s = lattice_case("velocity all set 0 0 0")
    chk.check(t.shape == (5, 5) and np.all(t[:, 1:] == 0.0) and s == 0.0,
              "bed at rest: P' = p_k = 0 exactly in every bin (max %g)" % np.abs(t[:, 1:]).max())
    chk.check(t[4, 0] == len(x) and t[:4, 0].sum() == len(x), "bed at rest: counts %s sum to N = %d"
              % (t[:, 0].tolist(), len(x)))
    t, x, v, ids, s = lattice_case("velocity all set 0.31 -0.27 0.113 units box")
    chk.check(np.abs(t[:, 1:]).max() < 1e-12 and abs(s) < 1e-12,
              "uniform translation (0.31, -0.27, 0.113) m/s: max P', p_k = %.3g < 1e-12" % np.abs(t[:, 1:]).max())
    # (2) prescribed field: shear v_x = a z plus non-linear y and z components, vs numpy
    field = ("variable vx atom 3.0*z\nvariable vy atom 0.2*sin(61.0*x)+0.1*z\n"
             "variable vz atom 0.05*cos(97.0*y)*x\nvelocity all set v_vx v_vy v_vz units box")
    for rv in (0.012, 0.021):
        t, x, v, ids, s = lattice_case(field, rv=rv)
        ref = mr.velocity_table(x, v, rv, 0, 0.0, 0.1, 4, lengths=(0.1, 0.06, None))
        err = np.abs(t - ref).max()
        chk.check(err < 1e-12, "field v_x = 3 z + ..., r_v = %g: count/p_k/P' per bin vs numpy: max diff %.3g "
                  "(P' all bins %.6g)" % (rv, err, ref[4, 4]))
        chk.check(abs(s - ref[4, 4]) < 1e-12, "global scalar = P' of all bins (%.12g vs %.12g)" % (s, ref[4, 4]))
        chk.check(ref[4, 4] > 0.01, "the field gives a non-trivial P' (%.4g m/s)" % ref[4, 4])
    # exclude: the excluded atoms are neighbours but not in the statistics
    t, x, v, ids, s = lattice_case(field, excl="exclude low")
    ref = mr.velocity_table(x, v, 0.015, 0, 0.0, 0.1, 4, lengths=(0.1, 0.06, None), include=ids > 60)
    chk.check(np.abs(t - ref).max() < 1e-12 and t[4, 0] == len(x) - 60,
              "exclude low (60 atoms): vs numpy max diff %.3g, count %d" % (np.abs(t - ref).max(), t[4, 0]))
    # a pure shear v_x = a z: p_x of a region is set by the z spread of the lattice -> numpy also
    # without periodic images in x: a check of the minimum image on
    t2 = mr.velocity_table(x, v, 0.015, 0, 0.0, 0.1, 4, lengths=(None, None, None), include=ids > 60)
    chk.check(np.abs(t2 - t).max() > 1e-6, "periodic x y matter (non-periodic numpy differs by %.3g)"
              % np.abs(t2 - t).max())


# ----------------------------------------------------------------------------- depth
BED = HEAD + """
lattice {lat} 0.01 origin 0.5 0.5 {oz}
{fill}
set group all diameter 0.01
{disp}
fix d all tdem/mixing/depth every 1 column {c} bins x 0 0.1 5 floor {floor} {extra}
run 0
write_dump all custom dump.txt id x y z radius f_d[1] f_d[2] f_d[3] f_d[4] modify sort id format float %.17g
"""


def depth_case(fill, c, floor=0.0, disp="", extra="", dim=3, bnd="p p f",
               box="0 0.1 0 0.04 0 0.1"):
    d = lc.workdir("mixdep")
    lat, oz = ("sc", 0.5) if dim == 3 else ("sq", 0.0)
    run(BED.format(lat=lat, oz=oz, dim=dim, bnd=bnd, proc="", box=box, fill=fill, c=c, floor=floor, disp=disp, extra=extra), d)
    cols, data = lc.read_dump(os.path.join(d, "dump.txt"))
    return data


def part_depth():
    # (3) 5 complete layers on the floor z = 0 (centres 0.005 ... 0.045): D = (z_top - z)/(z_top - z_bot)
    fill = "region fill block 0 0.1 0 0.04 0 0.05 units box\ncreate_atoms 1 region fill"
    data = depth_case(fill, 0.025)
    z, D = data[:, 3], data[:, 5]
    expect = (0.045 - z) / (0.045 - 0.005)
    chk.check(np.abs(D - expect).max() < 1e-12, "5 layers: D = (z_top - z)/(z_top - z_bot), max diff %.3g"
              % np.abs(D - expect).max())
    top, bot = np.isclose(z, 0.045), np.isclose(z, 0.005)
    chk.check(np.all(D[top] == 0.0) and np.all(np.abs(D[bot] - 1.0) < 1e-12) and top.sum() == 40 and bot.sum() == 40,
              "D = 0 at the surface (%d atoms), 1 at the grate (%d atoms)" % (top.sum(), bot.sum()))
    chk.check(np.all(data[:, 6] == D) and np.all(data[:, 7] == 0.0) and np.all(data[:, 8] == 0.0),
              "one snapshot: Dbar = D, sigma_D = 0, Q' = 0")
    # bed of varying height (column c = 0.015 sees only the own column): 2 + (ix mod 4) layers
    fill = ("region fill block 0 0.1 0 0.04 0 0.08 units box\ncreate_atoms 1 region fill\n"
            "variable keep atom (z-0.005)<=0.01*(1+(floor(x/0.01)%4))+1e-9\n"
            "group keep variable keep\ngroup gone subtract all keep\ndelete_atoms group gone")
    data = depth_case(fill, 0.015)
    x, z, D = data[:, 1], data[:, 3], data[:, 5]
    ztop = 0.005 + 0.01 * (1 + (np.floor(x / 0.01) % 4))
    expect = (ztop - z) / (ztop - 0.005)
    chk.check(np.abs(D - expect).max() < 1e-12, "columns of 2-5 layers: D = (z_top(x) - z)/(z_top - z_bot), "
              "max diff %.3g" % np.abs(D - expect).max())
    # unnormalised: depth in metres below the own column's top
    data = depth_case(fill, 0.015, extra="normalise no")
    chk.check(np.abs(data[:, 5] - (ztop - data[:, 3])).max() < 1e-12, "normalise no: D = z_top - z [m], max diff %.3g"
              % np.abs(data[:, 5] - (ztop - data[:, 3])).max())
    # jittered bed, floor at -0.002, wide column: vs numpy (periodic x, y)
    fill = "region fill block 0 0.1 0 0.04 0 0.05 units box\ncreate_atoms 1 region fill"
    data = depth_case(fill, 0.027, floor=-0.002, disp="displace_atoms all random 0.002 0.002 0.002 17 units box",
                      box="0 0.1 0 0.04 -0.01 0.1")
    ref = mr.depths(data[:, 1:4], data[:, 4], 0, 2, 1, 0.027, -0.002, lengths=(0.1, 0.04, None))
    chk.check(np.abs(data[:, 5] - ref).max() < 1e-12 and 0.0 < ref.mean() < 1.0,
              "jittered 3D bed, c = 0.027, floor -0.002, periodic x y: D vs numpy max diff %.3g (mean D %.3f)"
              % (np.abs(data[:, 5] - ref).max(), ref.mean()))
    # grate FIXID (only when the module 'grate' is built): a flat one-row grate with its top face at
    # z = -0.002 gives the D of 'floor -0.002' (the height comes through Fix::extract("tdem_grate"))
    gtext = BED.format(lat="sc", oz=0.5, dim=3, bnd="p p f", proc="", box="0 0.1 0 0.04 -0.05 0.1", fill=fill, c=0.027,
                       floor=-0.002, disp="displace_atoms all random 0.002 0.002 0.002 17 units box",
                       extra="\nfix g all tdem/grate normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5 "
                             "rows 1 bar_length 0.1 bar_height 0.02 declination 0 width 0.04 origin 0 0.02 -0.002 "
                             "stroke 0\nfix dg all tdem/mixing/depth every 1 column 0.027 bins x 0 0.1 5 grate g")
    gtext = gtext.replace("f_d[4] modify", "f_d[4] f_dg[1] modify")
    dg = lc.workdir("mixgrate")
    rc, out = run(gtext, dg, check=False)
    if rc != 0 and "Unrecognized fix style 'tdem/grate'" in out:
        print("SKIP grate FIXID: fix tdem/grate is not built (TDEM_LAMMPS_GRATE=OFF)")
    else:
        cols, g = lc.read_dump(os.path.join(dg, "dump.txt")) if rc == 0 else (None, np.zeros((1, 10)))
        chk.check(rc == 0 and np.abs(g[:, 9] - g[:, 5]).max() == 0.0 and g[:, 9].max() > 0.9,
                  "grate FIXID (flat grate, top face at -0.002) = floor -0.002: max diff %.3g"
                  % np.abs(g[:, 9] - g[:, 5]).max())
    # 2D: disks in the x-y plane, up = y, no lateral axis
    fill = ("region fill block 0 0.1 0 0.05 -0.5 0.5 units box\ncreate_atoms 1 region fill\n"
            "displace_atoms all random 0.002 0.002 0 29 units box")
    d2 = depth_case(fill, 0.021, dim=2, bnd="p f p", box="0 0.1 -0.01 0.1 -0.5 0.5", disp="")
    ref = mr.depths(d2[:, 1:4], d2[:, 4], 0, 1, -1, 0.021, 0.0, lengths=(0.1, None, None))
    chk.check(np.abs(d2[:, 5] - ref).max() < 1e-12 and np.any(ref == 0.0) and np.any(ref > 0.9),
              "2D bed (up = y, strip columns): D vs numpy max diff %.3g" % np.abs(d2[:, 5] - ref).max())


# ----------------------------------------------------------------------------- rate
RATE = HEAD + """
lattice sc 0.01 origin 0.5 0.5 0.5
region fill block 0 0.1 0 0.03 0 0.06 units box
create_atoms 1 region fill
create_atoms 1 single {tx} 0.01 {tz} units box
set group all diameter 0.01
group tracer id {tid}
velocity all set 0 0 0
velocity tracer set {u} 0 {w} units box
fix nve all nve
timestep {dt}
fix d all tdem/mixing/depth every {every} column 0.025 bins x 0 0.1 2 floor 0 {extra}
thermo_style custom step f_d f_d[1][4] f_d[2][4] f_d[3][4]
thermo_modify format float %.17g
run {steps}
write_dump all custom dump.txt id x y z f_d[1] f_d[2] f_d[3] f_d[4] modify sort id format float %.17g
"""


def rate_case(u, w, tx, tz, every, steps, dt, extra=""):
    d = lc.workdir("mixrate")
    n_bed = 10 * 3 * 6
    text = RATE.format(dim=3, bnd="p p f", proc="", box="0 0.1 0 0.03 0 0.1", tx=tx, tz=tz, tid=n_bed + 1, u=u,
                       w=w, every=every, extra=extra, steps=steps, dt=dt)
    _, out = run(text, d)
    rows = lc.thermo_blocks(out)
    last = [float(v) for v in rows[-1].split()]
    cols, data = lc.read_dump(os.path.join(d, "dump.txt"))
    return last, data, n_bed


def part_rate():
    # a tracer inside a bed of 6 static layers (top centre 0.055, bottom 0.005, floor 0): moving up with
    # w, D(t) = (0.055 - z(t))/0.05, so Q' = w / 0.05 exactly; the static ones have Q' = 0
    w, dt, every, steps = 0.02, 1e-4, 10, 1000
    last, data, nb = rate_case(0.0, w, 0.0251, 0.012, every, steps, dt)
    tr = data[-1]
    q_ref = w / 0.05
    chk.check(abs(tr[7] - q_ref) < 1e-10 * q_ref, "tracer moving up at w = %g m/s: Q' = %.15g, closed form %.15g "
              "(rel. diff %.2g)" % (w, tr[7], q_ref, abs(tr[7] - q_ref) / q_ref))
    # sigma_D from the sums (sum D^2/n - Dbar^2) has a round-off floor ~ sqrt(eps) D
    chk.check(np.all(data[:-1, 7] == 0.0) and np.all(data[:-1, 6] < 1e-7),
              "static particles: Q' = 0 exactly, sigma_D = %.2g (< 1e-7, round-off of the sums)" % data[:-1, 6].max())
    # D(t_k) linear in t_k: Dbar = mean, sigma_D = rms about it (closed form of uniform samples)
    tk = np.arange(0, steps + 1, every) * dt
    Dk = (0.055 - (0.012 + w * tk)) / 0.05
    chk.check(abs(tr[5] - Dk.mean()) < 1e-10 and abs(tr[6] - Dk.std()) < 1e-10,
              "tracer Dbar %.12g vs %.12g, sigma_D %.12g vs %.12g" % (tr[5], Dk.mean(), tr[6], Dk.std()))
    # bins: x in [0, 0.05) bin 1 holds the tracer and 5*3*6 static ones
    n1 = 5 * 3 * 6 + 1
    chk.check(abs(last[2] - q_ref / n1) < 1e-10 * q_ref and last[3] == 0.0,
              "Q'_bin1 = (sum |dD|)/(sum dt) = w/(0.05 %d) = %.12g (got %.12g), Q'_bin2 = 0" % (n1, q_ref / n1, last[2]))
    chk.check(abs(last[4] - q_ref / (nb + 1)) < 1e-10 * q_ref and abs(last[1] - last[4]) == 0.0,
              "Q' of all bins = w/(0.05 N) (got %.12g, ref %.12g) = scalar" % (last[4], q_ref / (nb + 1)))
    # normalise no: Q' = w [m/s]
    last, data, nb = rate_case(0.0, w, 0.0251, 0.012, every, steps, dt, extra="normalise no")
    chk.check(abs(data[-1][7] - w) < 1e-10 * w, "normalise no: Q' = w = %g (got %.15g)" % (w, data[-1][7]))
    # a tracer moving diagonally across the bin boundary x = 0.05: an increment belongs to the bin of
    # the earlier snapshot; Q'_bin = |dD| of those increments / (dt of all particles of that bin)
    u, w, tx, tz = 0.043, -0.017, 0.04813, 0.048
    last, data, nb = rate_case(u, w, tx, tz, every, steps, dt)
    tk = np.arange(0, steps + 1, every) * dt
    xk = tx + u * tk
    Dk = (0.055 - (tz + w * tk)) / 0.05
    dD = np.abs(np.diff(Dk))
    in1 = xk[:-1] < 0.05
    T = tk[-1]
    n_static = 90
    # static particles are in their bins for all increments: dt = T each
    q1 = dD[in1].sum() / (n_static * T + (every * dt) * in1.sum())
    q2 = dD[~in1].sum() / (n_static * T + (every * dt) * (~in1).sum())
    chk.check(0 < in1.sum() < len(in1), "the tracer crosses the boundary (%d of %d increments in bin 1)"
              % (in1.sum(), len(in1)))
    chk.check(abs(last[2] - q1) < 1e-10 * q1 and abs(last[3] - q2) < 1e-10 * q2,
              "diagonal tracer: Q'_bin1 %.12g vs %.12g, Q'_bin2 %.12g vs %.12g" % (last[2], q1, last[3], q2))


# ----------------------------------------------------------------------------- mpi / restart
FLY = HEAD.replace("create_box 1 box\n", "") + """
read_data fly.data
displace_atoms all random 0.002 0.002 0.002 31 units box
group half id <= 100
fix nve all nve
fix wr all wall/reflect zlo EDGE zhi EDGE
timestep 1e-4
compute m all tdem/mixing/velocity radius 0.015 bins x 0 0.1 4 periodic x y exclude half
fix d all tdem/mixing/depth every 5 column 0.025 bins x 0 0.1 4 floor 0
thermo_style custom step c_m c_m[1][5] c_m[2][2] c_m[3][3] f_d f_d[1][2] f_d[2][3] f_d[3][4] f_d[4][5] f_d[5][6]
thermo_modify format float %.17g
thermo 50
"""


def fly_data(d, nx=10):
    """10 nx spheres (200 by default) on a lattice (ids in lattice order, so that they do not depend on the number of
    ranks) with velocities of fixed seed, as a data file."""
    rng = np.random.default_rng(4711)
    pts = [(0.005 + 0.01 * i, 0.005 + 0.01 * j, 0.005 + 0.01 * k) for k in range(5) for j in range(4)
           for i in range(nx)]
    v = np.column_stack([0.2 + 0.25 * rng.uniform(-1, 1, len(pts)), 0.1 * rng.uniform(-1, 1, len(pts)),
                         0.025 * rng.uniform(-1, 1, len(pts))])
    lines = ["tdem mixing test bed", "", "%d atoms" % len(pts), "1 atom types", "",
             "0 %.17g xlo xhi" % (0.01 * nx), "0 0.04 ylo yhi", "0 0.1 zlo zhi", "", "Atoms # sphere", ""]
    lines += ["%d 1 0.01 2500 %.17g %.17g %.17g" % (n + 1, *p) for n, p in enumerate(pts)]
    lines += ["", "Velocities", ""]
    lines += ["%d %.17g %.17g %.17g 0 0 0" % (n + 1, *v[n]) for n in range(len(pts))]
    with open(os.path.join(d, "fly.data"), "w") as f:
        f.write("\n".join(lines) + "\n")


FLY_RUN = "run 300\nwrite_dump all custom dump.txt id x y z f_d[1] f_d[2] f_d[3] f_d[4] modify sort id format float %.17g\n"


def part_mpi():
    """-np 1, 2, 4, 8 (oversubscribed; splits along the up axis z, and 1 x 4 x 2 where a sub-domain
    is narrower than r_v): every output bitwise equal to -np 1; no rank holds the whole group."""
    os.environ["TDEM_MIXING_REPORT"] = "1"
    res = []
    for np_, proc in GRIDS:
        d = lc.workdir("mixmpi")
        fly_data(d)
        _, out = run(FLY.format(dim=3, bnd="p p f", proc=proc, box="0 0.1 0 0.04 0 0.1") + FLY_RUN, d, np_=np_)
        rows = np.array([[float(v) for v in r.split()] for r in lc.thermo_blocks(out)[1:]])
        cols, data = lc.read_dump(os.path.join(d, "dump.txt"))
        res.append((rows, data, out))
    a, da = res[0][0], res[0][1]
    chk.check(a.shape[0] > 3 and np.all(a[1:, 1:6] > 0), "thermo rows present and non-trivial (%s)" % (a.shape,))
    for (np_, proc), (b, db, out) in zip(GRIDS[1:], res[1:]):
        grid = " by ".join(proc.split()[1:])
        chk.check(grid + " MPI processor grid" in out, "-np %d runs on a %s grid" % (np_, grid))
        dmax = np.abs(a - b).max() if a.shape == b.shape else np.inf
        chk.check(dmax == 0.0, "-np 1 vs -np %d (%s): P', p_k, Q', D columns of the thermo output identical "
                  "(max diff %.3g)" % (np_, grid, dmax))
        dd = np.abs(da - db).max() if da.shape == db.shape else np.inf
        chk.check(dd == 0.0, "-np 1 vs -np %d (%s): per-atom D, Dbar, sigma_D, Q' identical (max diff %.3g)"
                  % (np_, grid, dd))
    # a bed 4 times as long on 4 ranks along x: each rank holds its own atoms and a halo, not the group
    # (the 200-atom scene above is too small for that: its halo and periodic images cover it)
    out4 = {}
    for np_, proc in ((1, ""), (4, "processors 4 1 1")):
        d = lc.workdir("mixlong")
        fly_data(d, nx=40)
        scene = FLY.format(dim=3, bnd="p p f", proc=proc, box="0 0.4 0 0.04 0 0.1").replace(
            "bins x 0 0.1 4", "bins x 0 0.4 8")
        _, out4[np_] = run(scene + FLY_RUN.replace("run 300", "run 100"), d, np_=np_)
        out4[np_] = (np.array([[float(v) for v in r.split()] for r in lc.thermo_blocks(out4[np_])[1:]]),
                     lc.read_dump(os.path.join(d, "dump.txt"))[1], out4[np_])
    (a1, d1, _), (a4, d4, o4) = out4[1], out4[4]
    same = a1.shape == a4.shape and np.abs(a1 - a4).max() == 0.0 and np.abs(d1 - d4).max() == 0.0
    chk.check(same, "800-atom bed, -np 1 vs -np 4 (4 by 1 by 1): thermo and per-atom output identical")
    h = held(o4)
    for style in ("velocity", "depth"):
        per = [v for k, v in h.items() if k[0] == style]
        most = max(o + m for o, m, g in per) if per else -1
        chk.check(len(per) == 4 and all(g == 800 for _, _, g in per) and 0 < most < 400,
                  "800-atom bed on 4 ranks, %s: a rank holds at most %d rows (< half the group; owned, halo "
                  "incl. periodic images per rank: %s)" % (style, most, sorted((o, m) for o, m, g in per)))


def part_restart():
    base = FLY.format(dim=3, bnd="p p f", proc="", box="0 0.1 0 0.04 0 0.1")
    d = lc.workdir("mixrst")
    fly_data(d)
    _, out_ref = run(base + "run 150\nwrite_restart mix.restart\n" + FLY_RUN, d)
    cols, ref = lc.read_dump(os.path.join(d, "dump.txt"))
    os.rename(os.path.join(d, "dump.txt"), os.path.join(d, "dump_ref.txt"))
    cont = """
read_restart mix.restart
group half id <= 100
fix nve all nve
fix wr all wall/reflect zlo EDGE zhi EDGE
compute m all tdem/mixing/velocity radius 0.015 bins x 0 0.1 4 periodic x y exclude half
fix d all tdem/mixing/depth every 5 column 0.025 bins x 0 0.1 4 floor 0
thermo_style custom step c_m c_m[1][5] c_m[2][2] c_m[3][3] f_d f_d[1][2] f_d[2][3] f_d[3][4] f_d[4][5] f_d[5][6]
thermo_modify format float %.17g
thermo 50
""" + FLY_RUN
    for np_ in (1, 2):
        _, out = run(cont, d, np_=np_, name="in.cont")
        cols, got = lc.read_dump(os.path.join(d, "dump.txt"))
        a = [r for r in lc.thermo_blocks(out_ref) if r.split()[0] == "450"]
        b = [r for r in lc.thermo_blocks(out) if r.split()[0] == "450"]
        same = a and b and a[-1] == b[-1]
        chk.check(bool(same), "restart (-np %d): thermo row of step 450 (P', Q', bin table) identical:\n  %s\n  %s"
                  % (np_, a[-1] if a else None, b[-1] if b else None))
        dd = np.abs(got - ref).max() if got.shape == ref.shape else np.inf
        chk.check(dd == 0.0, "restart (-np %d): per-atom D, Dbar, sigma_D, Q' at step 450 identical (max diff %.3g)"
                  % (np_, dd))
    chk.check(np.mean(ref[:, 7] > 0) > 0.8, "the restart scene accumulates (Q' > 0 for %.0f %% of the particles)"
              % (100 * np.mean(ref[:, 7] > 0)))


# ----------------------------------------------------------------------------- bad input
BAD = HEAD + """
create_atoms 1 single 0.025 0.02 0.05 units box
set group all diameter 0.01
{body}
run 0
"""
V = "compute m all tdem/mixing/velocity "
F = "fix d all tdem/mixing/depth "
BAD_CASES = [
    (V + "radius -1 bins x 0 0.1 4", ["radius", "'-1'", "a number > 0"]),
    (V + "radius abc bins x 0 0.1 4", ["radius", "'abc'", "a number > 0"]),
    (V + "radius 0.01 bins w 0 0.1 4", ["bins", "'w'", "x, y, z"]),
    (V + "radius 0.01 bins x 0.1 0 4", ["bins", "'0'", "HI > LO"]),
    (V + "radius 0.01 bins x 0 0.1 0", ["bins", "'0'", "an integer in [1, 100000]"]),
    (V + "radius 0.01 bins x 0 0.1 100000000", ["bins", "'100000000'", "an integer in [1, 100000]"]),
    (F + "every 1 column 0.02 bins x 0 0.03 100000000 floor 0", ["bins", "'100000000'", "an integer in [1, 100000]"]),
    (V + "radius 0.01 bins x 0 0.1 4 periodic q", ["periodic", "'q'", "x, y, z"]),
    (V + "radius 0.01 bins x 0 0.1 4 periodic z", ["periodic", "'z'", "periodic axes"]),
    (V + "radius 0.01 bins x 0 0.1 4 exclude nogroup", ["exclude", "'nogroup'", "existing group"]),
    (V + "radius 0.01 bins x 0 0.1 4 colour red", ["unknown keyword 'colour'", "radius, bins, periodic, exclude"]),
    (V + "bins x 0 0.1 4", ["missing keyword 'radius"]),
    (V + "radius 0.03 bins x 0 0.1 4 periodic x", ["radius", "'0.03'", "'periodic x' (box length 0.05)",
                                                  "R_V <= half the periodic box length"]),
    (F + "every 1 column 0.06 bins x 0 0.1 4 floor 0", ["column", "'0.06'", "periodic axis x (box length 0.05)",
                                                       "C <= the periodic box length"]),
    (F + "every 0 column 0.02 bins x 0 0.1 4 floor 0", ["every", "'0'", "an integer in [1, 100000000]"]),
    (F + "every 1 column -0.02 bins x 0 0.1 4 floor 0", ["column", "'-0.02'", "a number > 0"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4", ["missing keyword 'grate FIXID' or 'floor H'"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 floor 0 normalise maybe", ["normalise", "'maybe'", "yes, no"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 floor 0 up x", ["up", "'x'", "other than the transport"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 floor 0 lateral z", ["lateral", "'z'", "none or the axis"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 grate nofix", ["grate", "'nofix'", "grate fix"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 floor 0 grate g", ["'grate' and 'floor'", "one of them"]),
    (F + "every 1 column 0.02 bins x 0 0.1 4 floor 0 speed 3", ["unknown keyword 'speed'", "every, column, bins"]),
]


def part_bad_input():
    d = lc.workdir("mixbad")
    for body, subs in BAD_CASES:
        rc, out = run(BAD.format(dim=3, bnd="p p f", proc="", box="0 0.05 0 0.04 0 0.1", body=body), d, check=False)
        err = [line for line in out.splitlines() if "ERROR" in line]
        msg = err[0] if err else out[-300:]
        ok = 0 < rc < 128 and err and all(s in msg for s in subs)
        chk.check(bool(ok), "%-70s -> rc %d: %s" % (body[:70], rc, msg.strip()))
    rc, out = run(BAD.format(dim=3, bnd="p p f", proc="", box="0 0.05 0 0.04 0 0.1",
                             body=V + "radius 0.01 bins x 0 0.1 4 periodic x y\n" + F +
                             "every 1 column 0.02 bins x 0 0.1 4 floor 0 lateral y up z normalise no"), d)
    chk.check(rc == 0, "good input runs (control)")


{"velocity": part_velocity, "depth": part_depth, "rate": part_rate, "mpi": part_mpi, "restart": part_restart,
 "bad_input": part_bad_input}[part]()
chk.done()
