# SPDX-License-Identifier: GPL-2.0-or-later
"""The issue-4 tangential laws in LIGGGHTS (tangential tdem/haff_werner, tdem/linear_spring,
tdem/walton_braun, tdem/mindlin_deresiewicz, tdem/mindlin_no_slip, tdem/di_renzo).

(1) Slope: a sphere that cannot rotate (fix nve: a sliding block) resting on a plane wall under
    gravity tilted by theta with tan(theta) = 0.5 mu, 0.05 s. Every law with memory holds it: the
    positions of the last quarter of the run stay inside the range of the second quarter (+-2e-9 m;
    the undamped tangential springs oscillate with up to ~4e-7 m, Walton-Braun's hysteresis lets its
    oscillation settle by ~3e-10 m; a creep faster than ~2e-7 m/s = 1/2000 of the Haff-Werner creep
    would leave the range) and the total displacement is < 1e-6 m. Haff-Werner has no static friction and creeps at the
    closed-form speed v = m g sin(theta) / gamma_t (1 %; 2e-5 m over the run).
(2) Sliding to rolling on a plane wall (fix nve/sphere, gravity): closed form for a solid sphere
    started with v0 and no spin: v -> 5/7 v0 (angular momentum about the contact point is
    conserved whatever the friction law); asserted to 1e-2 v0 at the end, and rolling without
    slip |v - omega R| < 1e-2 v0 (Haff-Werner only approaches it; same tolerance).
(3) Oblique sphere-wall impacts (gravity off; 3 spheres per process: 10 deg and 45 deg without
    spin, 20 deg with back spin -20 1/s, i.e. v_s0 = 0.71 v_t0) against tdem-collide (velocity Verlet, same time step, lever arm
    R - xi/2 as LIGGGHTS: --lever-arm contact_point): |beta|, |e_t| and |spin_after| R / v_s0
    within 1e-4 of the harness (and e within 1e-4), at dt = 4e-9 s (50000 steps per lsd contact,
    155000 per Hertz contact; the differences are first order in dt, measured 2e-7 ... 3.9e-5).
    (A back spin that nearly cancels the slip, v_s0 = 0.12 v_t0, was dropped: beta = -v_s'/v_s0
    then amplifies the discretisation error, and for Mindlin-Deresiewicz both the host and the
    harness converge only slowly in dt there - beta 0.1872, 0.1889, 0.1902, 0.1910 at dt = 8, 4, 2,
    1 ns in the harness, host within 8e-4 ... 1e-4 of it.) An oblique sphere-sphere impact (equal
    spheres, 30 deg) against tdem-collide for every law as well.
(4) Restart in the middle of a contact and -np 2 = -np 1: two spheres colliding obliquely
    across x = 0 plus a sphere hitting the floor obliquely; `run N; write_restart; run M` vs
    `read_restart; run M` equal to 1e-12, and `processors 2 1 1` with -np 2 equals -np 1 to 1e-10
    (every law with history).
"""
import json
import math
import os
import subprocess

import numpy as np

import tdem_lig as T

R, RHO = 0.005, 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
E_REST, TC = 0.5, 2.0e-4
KAPPA, MU, DRATIO = 0.3, 0.3, 0.5
YOUNG, NU = 5.0e7, 0.3
# G* of two bodies of the same material (the wall is atom type 1 too): 1/G* = 2 (2 - nu)/G
GSTAR = 1.0 / (2.0 * (2.0 - NU) / (YOUNG / (2.0 * (1.0 + NU))))
GAMMA_LSD_WALL = -2.0 * MASS * math.log(E_REST) / TC   # lsd, zero-overlap end, m* = m

LAWS = {
    "haff_werner": "tdem/lsd", "linear_spring": "tdem/lsd", "walton_braun": "tdem/lsd",
    "mindlin_deresiewicz": "tdem/hertz", "mindlin_no_slip": "tdem/hertz", "di_renzo": "tdem/hertz",
}
MEMORY = [l for l in LAWS if l != "haff_werner"]


def props(ntypes=1, mu=MU):
    def pair(name, v):
        return "fix m_%s all property/global %s peratomtypepair %d %s\n" % (
            name, name, ntypes, " ".join([repr(v)] * ntypes * ntypes))
    return (pair("coefficientRestitution", E_REST) + pair("contactTime", TC) +
            pair("tangentialStiffnessRatio", KAPPA) + pair("coefficientFriction", mu) +
            pair("tangentialDampingRatio", DRATIO) +
            "fix m_E all property/global youngsModulus peratomtype %s\n" % " ".join([repr(YOUNG)] * ntypes) +
            "fix m_nu all property/global poissonsRatio peratomtype %s\n" % " ".join([repr(NU)] * ntypes))


def model(law, settings=""):
    normal = LAWS[law]
    extra = " parameters restitution" if normal == "tdem/lsd" else ""
    return "model %s tangential tdem/%s%s %s" % (normal, law, extra, settings)


def harness_opts(law, gamma_n):
    """tdem-collide options of the same normal and tangential law (gamma_n: the lsd damping)."""
    normal = ["--law", "lsd", "--e", repr(E_REST), "--tc", repr(TC)] if LAWS[law] == "tdem/lsd" else \
        ["--law", "hertz", "--E", repr(YOUNG), "--nu", repr(NU), "--damping", "tsuji", "--e", repr(E_REST)]
    t = {"haff_werner": ["--mu", repr(MU), "--gammat", repr(DRATIO * gamma_n)],
         "linear_spring": ["--mu", repr(MU), "--kappa", repr(KAPPA), "--gammat", repr(DRATIO * gamma_n)],
         "walton_braun": ["--mu", repr(MU), "--kappa", repr(KAPPA)],
         "mindlin_deresiewicz": ["--mu", repr(MU), "--gstar", repr(GSTAR)],
         "mindlin_no_slip": ["--mu", repr(MU), "--gstar", repr(GSTAR), "--eta-ratio", repr(DRATIO)],
         "di_renzo": ["--mu", repr(MU), "--gstar", repr(GSTAR)]}[law]
    return normal + ["--tangential", law] + t


HEAD = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
"""


def single_wall_scene(law, gravity, integrator, vx0, steps, dt, dump_every, mu=MU):
    return HEAD + """
region box block -0.05 0.2 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %r
create_atoms 1 single -0.04 0.0 %r units box
set group all diameter %r density %r
velocity all set %r 0.0 0.0 units box
fix gravi all gravity 9.81 vector %s
fix wz all wall/gran %s primitive type 1 zplane 0.0 %s
fix integr all %s
dump d all custom %d dump.s id x z vx vz omegay
dump_modify d format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 100000
run %d
""" % (props(mu=mu), model(law), dt, R, 2 * R, RHO, vx0, gravity, " ".join(model(law).split()[:4]),
       " ".join(model(law).split()[4:]), integrator, dump_every, steps)


def frames_arr(path):
    fr = T.read_dump(path)
    c = {k: i for i, k in enumerate(fr[0][1])}
    return np.array([f[0] for f in fr]), np.array([f[2] for f in fr]), c


def slope(args, checks):
    theta = math.atan(0.5 * MU)
    g = "%r 0.0 %r" % (math.sin(theta), -math.cos(theta))
    dt, steps = 2e-6, 25000
    for law in LAWS:
        d = T.workdir(args, "tdem_lig_tslope_" + law)
        T.run(args.tdem, single_wall_scene(law, g, "nve", 0.0, steps, dt, 10), d, "slope")
        st, a, c = frames_arr(os.path.join(d, "dump.s"))
        x = a[:, 0, c["x"]]
        n = len(x)
        if law == "haff_werner":
            # creep speed over the second half, closed form m g sin(theta) / gamma_t
            v = (x[-1] - x[n // 2]) / ((st[-1] - st[n // 2]) * dt)
            ref = MASS * 9.81 * math.sin(theta) / (DRATIO * GAMMA_LSD_WALL)
            checks.check(abs(v / ref - 1) < 1e-2,
                         "slope %s: creeps (no static friction) at %.5e m/s, closed form m g sin/gamma_t = %.5e m/s"
                         % (law, v, ref))
        else:
            q2, q4 = x[n // 4: n // 2], x[3 * n // 4:]
            bounded = q4.max() <= q2.max() + 2e-9 and q4.min() >= q2.min() - 2e-9
            checks.check(bounded and abs(x[-1] - x[0]) < 1e-6,
                         "slope %s: at rest below the friction angle: position in the last quarter within "
                         "[%.3e, %.3e] m, inside the range of the second quarter [%.3e, %.3e] m (+-2e-9; the "
                         "undamped springs oscillate), total displacement %.2e m (< 1e-6)"
                         % (law, q4.min() - x[0], q4.max() - x[0], q2.min() - x[0], q2.max() - x[0], x[-1] - x[0]))


def rolling(args, checks):
    v0, dt = 0.5, 4e-6
    t_slide = 2 * v0 / (7 * MU * 9.81)
    steps = int(round(2.5 * t_slide / dt / 100)) * 100
    for law in LAWS:
        d = T.workdir(args, "tdem_lig_troll_" + law)
        T.run(args.tdem, single_wall_scene(law, "0.0 0.0 -1.0", "nve/sphere", v0, steps, dt, 100), d, "roll")
        st, a, c = frames_arr(os.path.join(d, "dump.s"))
        vx, wy = a[-1, 0, c["vx"]], a[-1, 0, c["omegay"]]
        checks.check(abs(vx - 5.0 / 7.0 * v0) < 1e-2 * v0 and abs(vx - wy * R) < 1e-2 * v0,
                     "rolling %s: final v = %.5f m/s (5/7 v0 = %.5f), v - omega R = %.2e m/s"
                     % (law, vx, 5.0 / 7.0 * v0, vx - wy * R))


def harness(args, opts):
    r = subprocess.run([args.collide] + opts, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("FAIL: tdem-collide %s: %s" % (" ".join(opts), r.stderr[-2000:]))
    return json.loads(r.stdout)


IMPACTS = [(10.0, 0.0), (45.0, 0.0), (20.0, -20.0)]   # (angle deg, spin W of the harness [1/s])


def run_steps(law):
    """Steps of 1e-8 s past every contact (lsd: t_c = 2e-4 s; Hertz: about 6.2e-4 s on the wall)."""
    return 40000 if LAWS[law] == "tdem/lsd" else 90000


def oblique_wall(args, checks, law, speed=1.0, dt=4e-9):
    n0 = 100
    atoms = ""
    for k, (ang, w) in enumerate(IMPACTS):
        vn, vt = speed * math.cos(math.radians(ang)), speed * math.sin(math.radians(ang))
        z0 = R + vn * (n0 + 0.5) * dt
        atoms += "create_atoms 1 single %r 0.0 %r units box\n" % (-0.04 + 0.04 * k, z0)
        atoms += "set atom %d diameter %r density %r\nset atom %d vx %r vz %r\nset atom %d omegay %r\n" % (
            k + 1, 2 * R, RHO, k + 1, vt, -vn, k + 1, -w)
    m = model(law).split()
    text = HEAD + """
region box block -0.06 0.1 -0.05 0.05 -0.001 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %r
%s
fix wz all wall/gran %s primitive type 1 zplane 0.0 %s
fix integr all nve/sphere
thermo 1000000
run %d
write_dump all custom dump.end id vx vz omegay modify format "%%d %%.17g %%.17g %%.17g"
""" % (props(), " ".join(m), dt, atoms, " ".join(m[:4]), " ".join(m[4:]), int(run_steps(law) * 1e-8 / dt))
    d = T.workdir(args, "tdem_lig_tobl_" + law)
    T.run(args.tdem, text, d, "obl")
    _, cols, a = T.read_dump(os.path.join(d, "dump.end"))[-1]
    c = {k: i for i, k in enumerate(cols)}
    worst = 0.0
    for k, (ang, w) in enumerate(IMPACTS):
        h = harness(args, harness_opts(law, GAMMA_LSD_WALL) + [
            "--R1", repr(R), "--rho", repr(RHO), "--wall", "--v0", repr(speed), "--angle", repr(ang),
            "--spin", repr(w), "--lever-arm", "contact_point", "--dt", repr(dt)])
        vx, vz, wy = a[k, c["vx"]], a[k, c["vz"]], a[k, c["omegay"]]
        vt0 = speed * math.sin(math.radians(ang))
        vs0 = vt0 + R * w
        beta = -(vx - R * wy) / vs0
        e_t = vx / vt0
        e = vz / (speed * math.cos(math.radians(ang)))
        errs = (abs(beta - h["beta"]), abs(e_t - h["e_t"]), abs(-wy - h["spin_after"]) * R / abs(vs0),
                abs(e - h["e"]))
        worst = max(worst, max(errs))
        checks.check(max(errs) <= 1e-4,
                     "oblique wall %s %g deg spin %g: beta %.6f (harness %.6f), e_t %.6f (%.6f), spin %.3f (%.3f) 1/s, "
                     "e %.6f (%.6f); max error %.1e (<= 1e-4)" % (law, ang, w, beta, h["beta"], e_t, h["e_t"], -wy,
                                                                 h["spin_after"], e, h["e"], max(errs)))
    return worst


def oblique_pair(args, checks, law, speed=1.0, ang=30.0, dt=4e-9):
    """Two equal spheres moving symmetrically, relative velocity `speed` at `ang` from the line of centres."""
    n0 = 100
    vn, vt = speed * math.cos(math.radians(ang)), speed * math.sin(math.radians(ang))
    gap = vn * (n0 + 0.5) * dt
    m = model(law).split()
    text = HEAD + """
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %r
create_atoms 1 single %r 0.0 0.0 units box
create_atoms 1 single %r 0.0 0.0 units box
set group all diameter %r density %r
set atom 1 vx %r vz %r
set atom 2 vx %r vz %r
fix integr all nve/sphere
thermo 1000000
run %d
write_dump all custom dump.end id x y z vx vy vz omegay modify format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
""" % (props(), " ".join(m), dt, -(R + gap / 2), R + gap / 2, 2 * R, RHO, vn / 2, vt / 2, -vn / 2, -vt / 2, int(run_steps(law) * 1e-8 / dt))
    d = T.workdir(args, "tdem_lig_tpair_" + law)
    T.run(args.tdem, text, d, "pair")
    _, cols, a = T.read_dump(os.path.join(d, "dump.end"))[-1]
    c = {k: i for i, k in enumerate(cols)}
    gamma_pair = -2.0 * (MASS / 2) * math.log(E_REST) / TC
    h = harness(args, harness_opts(law, gamma_pair) + [
        "--R1", repr(R), "--rho", repr(RHO), "--R2", repr(R), "--v0", repr(speed), "--angle", repr(ang),
        "--lever-arm", "contact_point", "--dt", repr(dt)])
    # The harness reports in the contact frame at separation: n = line of centres (from 2 to 1) at
    # separation, a = -y (the spin axis, as in the harness: t0 x n0 = z x (-x)), t = n x a. The
    # motion after the contact is free, so the separation is found by going back along it.
    x = lambda k: np.array([a[k, c["x"]], a[k, c["y"]], a[k, c["z"]]])
    v = lambda k: np.array([a[k, c["vx"]], a[k, c["vy"]], a[k, c["vz"]]])
    dd, w = x(0) - x(1), v(0) - v(1)
    dw, ww = dd.dot(w), w.dot(w)
    tau = (dw - math.sqrt(dw * dw - ww * (dd.dot(dd) - 4 * R * R))) / ww
    n = (dd - w * tau) / np.linalg.norm(dd - w * tau)
    ax = np.array([0.0, -1.0, 0.0])
    t = np.cross(n, ax)
    vn_after, vt_after = w.dot(n), w.dot(t)
    vs_after = vt_after + R * (-a[0, c["omegay"]] - a[1, c["omegay"]])
    beta = -vs_after / vt
    e_t = vt_after / vt
    e = vn_after / vn
    errs = (abs(beta - h["beta"]), abs(e_t - h["e_t"]), abs(e - h["e"]))
    checks.check(max(errs) <= 1e-4,
                 "oblique pair %s %g deg: beta %.6f (harness %.6f), e_t %.6f (%.6f), e %.6f (%.6f); "
                 "max error %.1e (<= 1e-4)" % (law, ang, beta, h["beta"], e_t, h["e_t"], e, h["e"], max(errs)))


def two_body(law, dt, processors="", tail="", restart=None):
    """Two spheres meeting obliquely at x = 0 and one sphere hitting the floor obliquely."""
    if restart:
        head, atoms = "read_restart %s\n" % restart, ""
    else:
        head = "region box block -0.03 0.03 -0.03 0.03 -0.001 0.04 units box\ncreate_box 2 box\n"
        atoms = """create_atoms 1 single -0.0052 0.0 0.02 units box
create_atoms 1 single 0.0052 0.0 0.02 units box
create_atoms 2 single 0.015 0.0 0.0052 units box
set group all diameter 0.01 density 2500
set atom 1 vx 1.0 vy 0.4 vz 0.1
set atom 2 vx -1.0 vy -0.4
set atom 3 vz -1.0 vx 0.3 vy 0.1
set atom 3 omegax 10.0 omegay -20.0 omegaz 5.0
"""
    m = model(law).split()
    return HEAD + """
%s
%s
neighbor 0.002 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %r
%s
fix wz all wall/gran %s primitive type 1 zplane 0.0 %s
fix integr all nve/sphere
dump d all custom 100 dump.h id x y z vx vy vz omegax omegay omegaz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 100000
%s
""" % (processors, head, props(2), " ".join(m), dt, atoms, " ".join(m[:4]), " ".join(m[4:]), tail)


def restart_and_np(args, checks, law):
    dt, n1, n2 = 1e-7, 3000, 3000     # touch near step 2000, restart during both contacts
    d1 = T.workdir(args, "tdem_lig_tmid_one_" + law)
    T.run(args.tdem, two_body(law, dt, tail="run %d\nwrite_restart r.restart\nrun %d\n" % (n1, n2)), d1, "one")
    d2 = T.workdir(args, "tdem_lig_tmid_two_" + law)
    T.run(args.tdem, two_body(law, dt, tail="run %d\n" % n2, restart="../%s/r.restart" % os.path.basename(d1)),
          d2, "two")
    fr1 = T.read_dump(os.path.join(d1, "dump.h"))
    c = {k: i for i, k in enumerate(fr1[0][1])}
    mid = [a for st, _, a in fr1 if st == n1][0]
    xi_pair = 0.01 - np.linalg.norm(mid[1, c["x"]:c["z"] + 1] - mid[0, c["x"]:c["z"] + 1])
    xi_wall = 0.005 - mid[2, c["z"]]
    a, b = fr1[-1], T.read_dump(os.path.join(d2, "dump.h"))[-1]
    rel = T.max_rel_diff(a[2][:, 1:], b[2][:, 1:])
    turned = abs(a[2][0, c["omegaz"]]) > 0 and abs(a[2][2, c["omegax"]] - 10.0) > 1e-3
    checks.check(xi_pair > 0 and xi_wall > 0 and a[0] == b[0] == n1 + n2 and rel <= 1e-12 and turned,
                 "%s restart mid-contact (pair overlap %.2e m, wall overlap %.2e m at the restart): "
                 "max rel. diff of the final state %.2e (<= 1e-12)" % (law, xi_pair, xi_wall, rel))
    fin = []
    for npr in (1, 2):
        dd = T.workdir(args, "tdem_lig_tmid_np%d_%s" % (npr, law))
        T.run(args.tdem, two_body(law, dt, processors="processors 2 1 1" if npr == 2 else "",
                                  tail="run %d\n" % (n1 + n2)), dd, "np", np_=npr, mpirun=args.mpirun)
        fin.append(T.read_dump(os.path.join(dd, "dump.h"))[-1][2][:, 1:])
    rel = T.max_rel_diff(fin[0], fin[1])
    checks.check(rel < 1e-10, "%s -np 2 (contact across the boundary) vs -np 1: max rel. diff %.2e (< 1e-10)"
                 % (law, rel))


def main():
    args = T.parse_args(lambda p: (p.add_argument("--collide", required=True),
                                   p.add_argument("--only", default=None)))
    checks = T.Checks()
    laws = [l for l in LAWS if not args.only or args.only in l]
    for law in laws:
        oblique_wall(args, checks, law)
        oblique_pair(args, checks, law)
    slope(args, checks)
    rolling(args, checks)
    for law in laws:
        if law in MEMORY:
            restart_and_np(args, checks, law)
    checks.done()


if __name__ == "__main__":
    main()
