#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Rolling resistance `rolling sds KR GAMMAR MUR` of pair tdem/gran and fix tdem/wall/gran
(src/contact/rolling/sds.h, issue 18):

  pair decay   a spinning sphere resting on a fixed sphere (no friction), mu_r = 0.05, 0.1, 0.2:
               omega(t) = omega0 - 5/2 mu_r R* g t / R^2 (gross rolling) against the closed form;
               the fixed sphere gets the opposite torque
  restart      a loaded rolling spring (below the limit) across write_restart / read_restart: the
               continued run equals the uninterrupted one bitwise
  mpi          the two spheres on two ranks (newton off and on) = one rank, bitwise
  bad input    missing or bad values, unknown model, fix tdem/grate (refused by name)
The wall form is in validation/dem_suite (DEM-07, against the closed form and the stock
`granular ... rolling sds`)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.rolling")
TDEM = args["tdem"]
R, RHO, G, K = 0.5, 1.0, 10.0, 1e4
M = RHO * 4.0 / 3.0 * 3.141592653589793 * R ** 3


def scene(law, w0, steps, processors="", newton="off", restart_write=None, restart_read=None, extra_steps=0):
    """Sphere 1 fixed at the origin, sphere 2 resting on it (overlap m g / k), spinning about y."""
    if restart_read:
        head = ["read_restart " + restart_read, "newton " + newton, "comm_modify vel yes",
                "pair_style tdem/gran", "pair_coeff * * " + law, "group top id 2"]
    else:
        head = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "newton " + newton,
                "comm_modify vel yes", processors, "region box block -2 2 -2 2 -1 2.5 units box", "create_box 1 box",
                "create_atoms 1 single 0 0 0 units box", "create_atoms 1 single 0 0 %.17g units box" % (2 * R - M * G / K),
                "set group all diameter %.17g density %.17g" % (2 * R, RHO), "group top id 2",
                "set group top omega 0 %.17g 0" % w0, "pair_style tdem/gran", "pair_coeff * * " + law]
    body = head + ["neighbor 0.2 bin", "fix g top gravity %.17g vector 0 0 -1" % G, "fix n top nve/sphere",
                   "timestep 5e-4",
                   "dump d all custom 50 traj.dump id x y z vx vy vz omegax omegay omegaz tqx tqy tqz",
                   'dump_modify d sort id format line "%d' + " %.17g" * 12 + '"',
                   "run %d" % steps]
    if restart_write:
        body.append("write_restart " + restart_write)
    if extra_steps:
        body.append("run %d" % extra_steps)
    return "\n".join(l for l in body if l) + "\n"


def law(mur, kr=1000.0):
    ln = -0.6931471805599453  # e = 0.5
    meff = M / 2
    tc = (meff / K) ** 0.5 * (3.141592653589793 ** 2 + ln * ln) ** 0.5
    return "normal lsd restitution 0.5 %.17g tangential cundall_strack 0.8 0 rolling sds %.17g 0 %.17g" % (tc, kr, mur)


def frames(d):
    return lc_frames(os.path.join(d, "traj.dump"))


def lc_frames(path):
    out, lines, i = [], open(path).read().splitlines(), 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, n = int(lines[i + 1]), int(lines[i + 3])
            k = i + 4
            while not lines[k].startswith("ITEM: ATOMS"):
                k += 1
            out.append((step, sorted([float(w) for w in l.split()] for l in lines[k + 1:k + 1 + n])))
            i = k + 1 + n
        else:
            i += 1
    return out


# --------------------------------------------------------------------- pair decay (closed form)
wd = lc.workdir("rolling")
reff = R * R / (2 * R)
for mur in (0.05, 0.1, 0.2):
    d = os.path.join(wd, "decay_%g" % mur)
    os.makedirs(d, exist_ok=True)
    lc.run(TDEM, scene(law(mur), 5.0, 1200), d, "in.decay")
    rate = 2.5 * mur * reff * G / R ** 2
    err, worst, tq = 0.0, "", 0.0
    for step, rows in frames(d):
        t = step * 5e-4
        want = 5.0 - rate * t
        if t < 0.1 or want < 1.0:
            continue
        e = abs(rows[1][8] - want) / 5.0
        if e > err:
            err, worst = e, "omega_y %.6g vs %.6g at t = %.3g s" % (rows[1][8], want, t)
        tq = max(tq, abs(rows[0][11] + rows[1][11]))  # torque on the fixed sphere = -torque on the top one
    chk.check(err < 2e-3, "pair, mu_r %g: spin decays at 5/2 mu_r R* g / R^2 within %.3g of omega0 (%s)" % (mur, err, worst))
    chk.check(tq < 1e-12, "pair, mu_r %g: the fixed sphere gets the opposite torque (|sum| <= %.2g)" % (mur, tq))

# --------------------------------------------------------------------- restart (spring regime)
slow = law(0.5, kr=200.0)  # the limit mu_r R* N = 0.16 N m is never reached at omega0 = 0.2 /s
d = os.path.join(wd, "restart")
os.makedirs(d, exist_ok=True)
lc.run(TDEM, scene(slow, 0.2, 400), d, "in.full")
full = frames(d)[-1][1]
lc.run(TDEM, scene(slow, 0.2, 200, restart_write="half.restart"), d, "in.a")
lc.run(TDEM, scene(slow, 0.2, 200, restart_read="half.restart"), d, "in.b")
cont = frames(d)[-1][1]
diff = max(abs(a - b) for ra, rb in zip(full, cont) for a, b in zip(ra, rb))
moved = abs(full[1][8] - 0.2)
chk.check(diff == 0.0 and moved > 1e-3, "restart in the spring regime: run 200 + restart + run 200 = run 400 (max diff %.2g; "
          "omega moved by %.3g)" % (diff, moved))

# --------------------------------------------------------------------- MPI
for newton in ("off", "on"):
    d = os.path.join(wd, "mpi_" + newton)
    os.makedirs(d, exist_ok=True)
    lc.run(TDEM, scene(slow, 0.2, 400, newton=newton), d, "in.np1")
    one = frames(d)[-1][1]
    lc.run(TDEM, scene(slow, 0.2, 400, processors="processors 1 1 2", newton=newton), d, "in.np2", np_=2,
           mpirun=args["mpirun"])
    two = frames(d)[-1][1]
    diff = max(abs(a - b) for ra, rb in zip(one, two) for a, b in zip(ra, rb))
    chk.check(diff == 0.0, "newton %s: -np 2 (one sphere per rank) = -np 1 (max diff %.2g)" % (newton, diff))

# --------------------------------------------------------------------- bad input
base = "normal lsd restitution 0.5 1e-3 tangential cundall_strack 0.8 0.5 "
BAD = [
    ("rolling", "keyword 'rolling' needs a model"),
    ("rolling sds 1000 0", "rolling sds needs 3 values"),
    ("rolling epsd 1000 0 0.1", "rolling 'epsd' is unknown; allowed: sds"),
    ("rolling sds 0 0 0.1", "rolling sds KR = 0 must be > 0"),
    ("rolling sds 1000 -1 0.1", "rolling sds GAMMAR = -1 must be >= 0"),
    ("rolling sds 1000 0 nan", "rolling sds MUR expects a finite number, got 'nan'"),
]
d = os.path.join(wd, "bad")
os.makedirs(d, exist_ok=True)
for extra, want in BAD:
    text = scene(base + extra, 1.0, 1)
    rc, out = lc.run(TDEM, text, d, "in.bad", check=False)
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    chk.check(rc != 0 and err and want in err[0], "'%s' -> %s" % (extra, err[0][:150] if err else "no error (rc %d)" % rc))
text = ("units si\natom_style sphere\nboundary f p f\nregion box block -0.1 0.5 -0.05 0.05 -0.2 0.3 units box\n"
        "create_box 1 box\nfix gr all tdem/grate " + base + "rolling sds 1000 0 0.1 rows 3 bar_length 0.1 bar_height 0.02 "
        "width 0.1\nrun 1\n")
rc, out = lc.run(TDEM, text, d, "in.grate", check=False)
err = [l for l in out.splitlines() if l.startswith("ERROR")]
chk.check(rc != 0 and err and "'rolling' is not available for the bars" in err[0],
          "fix tdem/grate with rolling -> %s" % (err[0][:150] if err else "no error"))
chk.done()
