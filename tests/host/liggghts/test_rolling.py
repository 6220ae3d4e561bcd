# SPDX-License-Identifier: GPL-2.0-or-later
"""Rolling resistance `rolling_friction tdem/sds` (the kernel src/contact/rolling/sds.h of LAMMPS
`rolling sds`) in LIGGGHTS pair gran and fix wall/gran (issue 18):

  pair decay   a spinning sphere resting on a fixed sphere (no friction), mu_r = 0.05, 0.1, 0.2:
               omega(t) = omega0 - 5/2 mu_r R* g t / R^2 (gross rolling), closed form; the fixed
               sphere gets the opposite torque
  wall decay   a spinning sphere on a wall: omega(t) = omega0 - 5/2 mu_r g t / R
  hertz        the same pair decay with model tdem/hertz + tangential tdem/mindlin_deresiewicz
  restart      a loaded rolling spring (below the limit): `run 200; write_restart; run 200` in one
               process equals `read_restart; run 200` bitwise
  mpi          the two spheres on two ranks = one rank, bitwise
  bad input    a missing property, k_r = 0, gamma_r < 0, mu_r < 0, an unknown rolling model"""
import math
import os

import tdem_lig as T

R, RHO, G, K = 0.5, 1.0, 10.0, 1e4
M = RHO * 4.0 / 3.0 * math.pi * R ** 3
LN = math.log(0.5)
TC = math.sqrt(M / 2 / K) * math.sqrt(math.pi ** 2 + LN * LN)  # lsd of e = 0.5 at m* = m/2


def data(pair, w0, hertz=False):
    """Sphere 1 fixed at the origin and sphere 2 resting on it (pair), or sphere 1 on the floor z = 0
    (wall), at the static overlap; the top sphere spins about y with w0 (LIGGGHTS's `set` has no
    omega: a data file)."""
    xi = M * G / K if pair else M * G / (2 * K)  # lsd (wall contact: k = 2 K, m* = m)
    if hertz:  # m g = 4/3 E* sqrt(R*) xi^3/2, E* = E / (2 (1 - nu^2))
        xi = (M * G / (4.0 / 3.0 * 1e5 / (2 * (1 - 0.09)) * math.sqrt(R / 2))) ** (2.0 / 3.0)
    z = (2 * R - xi) if pair else (R - xi)
    atoms = [(0.0, 0.0, 0.0), (0.0, 0.0, z)] if pair else [(0.0, 0.0, z)]
    out = ["rolling", "", "%d atoms" % len(atoms), "1 atom types", "", "-2 2 xlo xhi", "-2 2 ylo yhi",
           "-1 2.5 zlo zhi", "", "Atoms", ""]
    out += ["%d 1 %.17g %.17g %.17g %.17g %.17g" % ((i, 2 * R, RHO) + a) for i, a in enumerate(atoms, 1)]
    out += ["", "Velocities", ""]
    out += ["%d 0 0 0 0 %.17g 0" % (i, w0 if i == len(atoms) else 0.0) for i in range(1, len(atoms) + 1)]
    return "\n".join(out) + "\n"


def props(kr, gr, mur, hertz=False, skip=None):
    p = {"coefficientRestitution": 0.5, "contactTime": TC, "tangentialStiffnessRatio": 0.8, "coefficientFriction": 0.0,
         "rollingStiffness": kr, "rollingDamping": gr, "coefficientRollingFriction": mur}
    if hertz:
        p.update(youngsModulus=1e5, poissonsRatio=0.3)
        del p["contactTime"]
    out = []
    for k, v in p.items():
        if k == skip:
            continue
        kind = "peratomtype" if k in ("youngsModulus", "poissonsRatio") else "peratomtypepair 1"
        out.append("fix p_%s all property/global %s %s %.17g" % (k, k, kind, v))
    return "\n".join(out)


def model(hertz=False):
    if hertz:
        return "model tdem/hertz tangential tdem/mindlin_deresiewicz rolling_friction tdem/sds", "damping tsuji"
    return "model tdem/lsd tangential tdem/cundall_strack rolling_friction tdem/sds", "parameters restitution"


def scene(p, pair=True, hertz=False, steps=1200, tail="", restart=None, processors=""):
    m, settings = model(hertz)
    top = "id 2" if pair else "id 1"
    head = ("read_restart %s" % restart) if restart else "read_data scene.data"
    wall = "" if pair else "fix w all wall/gran %s primitive type 1 zplane 0 %s" % (m, settings)
    return """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
soft_particles yes
%s
%s
neighbor 0.2 bin
neigh_modify delay 0
%s
pair_style gran %s %s
pair_coeff * *
%s
group top %s
fix g top gravity %.17g vector 0 0 -1
fix n top nve/sphere
timestep 5e-4
dump d all custom 50 traj.dump id x y z vx vy vz omegax omegay omegaz tqx tqy tqz
dump_modify d sort id format "%%d%s"
thermo 100000
run %d
%s""" % (processors, head, p, m, settings, wall, top, G, " %.17g" * 12, steps, tail)


def frames(d):
    return T.read_dump(os.path.join(d, "traj.dump"))


def decay(args, checks, name, p, pair, hertz, mur, wd):
    d = os.path.join(wd, name)
    os.makedirs(d)
    with open(os.path.join(d, "scene.data"), "w") as f:
        f.write(data(pair, 5.0, hertz))
    T.run(args.tdem, scene(p, pair, hertz), d, "decay")
    reff = R / 2 if pair else R
    rate = 2.5 * mur * reff * G / R ** 2
    err, worst, tq = 0.0, "", 0.0
    top = 1 if pair else 0
    for step, cols, a in frames(d):
        t = step * 5e-4
        want = 5.0 - rate * t
        if t < 0.1 or want < 1.0:
            continue
        w = a[top, cols.index("omegay")]
        e = abs(w - want) / 5.0
        if e > err:
            err, worst = e, "omega_y %.6g vs %.6g at t = %.3g s" % (w, want, t)
        if pair:
            tq = max(tq, abs(a[0, cols.index("tqy")] + a[1, cols.index("tqy")]))
    checks.check(err < 2e-3, "%s: spin decays at 5/2 mu_r R* g / R^2 within %.3g of omega0 (%s)" % (name, err, worst))
    if pair:
        checks.check(tq < 1e-12, "%s: the fixed sphere gets the opposite torque (|sum| <= %.2g)" % (name, tq))


def main():
    args = T.parse_args()
    checks = T.Checks()
    wd = T.workdir(args, "tdem_lig_rolling")
    for mur in (0.05, 0.1, 0.2):
        decay(args, checks, "pair_mur%g" % mur, props(1000.0, 0.0, mur), True, False, mur, wd)
    decay(args, checks, "wall_mur0.1", props(1000.0, 0.0, 0.1), False, False, 0.1, wd)
    decay(args, checks, "hertz_mindlin_mur0.1", props(1000.0, 0.0, 0.1, hertz=True), True, True, 0.1, wd)

    # restart in the spring regime (the limit mu_r R* N = 0.64 N m is never reached at omega0 = 0.2)
    slow = props(200.0, 1.0, 0.5)
    d1, d2 = os.path.join(wd, "restart_one"), os.path.join(wd, "restart_two")
    for d in (d1, d2):
        os.makedirs(d)
        with open(os.path.join(d, "scene.data"), "w") as f:
            f.write(data(True, 0.2))
    T.run(args.tdem, scene(slow, steps=200, tail="write_restart r.restart\nrun 200\n"), d1, "one")
    T.run(args.tdem, scene(slow, steps=200, restart="../restart_one/r.restart"), d2, "two")
    a, b = frames(d1)[-1], frames(d2)[-1]
    moved = abs(a[2][1, a[1].index("omegay")] - 0.2)
    diff = T.max_rel_diff(a[2][:, 1:], b[2][:, 1:])
    checks.check(a[0] == b[0] == 400 and diff == 0.0 and moved > 1e-3,
                 "restart with a loaded rolling spring: read_restart + run 200 = the run that wrote it "
                 "(max rel. diff %.2g; omega moved by %.3g)" % (diff, moved))

    # MPI: one sphere per rank
    res = {}
    for npr in (1, 2):
        d = os.path.join(wd, "np%d" % npr)
        os.makedirs(d)
        with open(os.path.join(d, "scene.data"), "w") as f:
            f.write(data(True, 0.2))
        T.run(args.tdem, scene(slow, steps=400, processors="processors 1 1 2" if npr == 2 else ""), d, "np",
              np_=npr, mpirun=args.mpirun)
        res[npr] = frames(d)[-1][2]
    diff = T.max_rel_diff(res[1][:, 1:], res[2][:, 1:])
    checks.check(diff == 0.0, "-np 2 (one sphere per rank) = -np 1 (max rel. diff %.2g)" % diff)

    # bad input
    bad = [
        ("missing rollingStiffness", props(1000.0, 0.0, 0.1, skip="rollingStiffness"), None, "rollingStiffness"),
        ("k_r = 0", props(0.0, 0.0, 0.1), None, "rollingStiffness"),
        ("gamma_r < 0", props(1000.0, -1.0, 0.1), None, "rollingDamping"),
        ("mu_r < 0", props(1000.0, 0.0, -0.1), None, "coefficientRollingFriction"),
        ("unknown model", props(1000.0, 0.0, 0.1), "tdem/sdz", "allowed:"),
    ]
    d = os.path.join(wd, "bad")
    os.makedirs(d)
    with open(os.path.join(d, "scene.data"), "w") as f:
        f.write(data(True, 1.0))
    for name, p, rolling, want in bad:
        text = scene(p, steps=1)
        if rolling:
            text = text.replace("rolling_friction tdem/sds", "rolling_friction " + rolling)
        r = T.run(args.tdem, text, d, "bad", check=False)
        out = r.stdout + r.stderr
        err = [l for l in out.splitlines() if "ERROR" in l]
        checks.check(r.returncode != 0 and err and want in err[0] and (rolling is None or "tdem/sds" in err[0]),
                     "%s -> %s" % (name, err[0][:160] if err else "no error (rc %d)" % r.returncode))
    checks.done()


if __name__ == "__main__":
    main()
