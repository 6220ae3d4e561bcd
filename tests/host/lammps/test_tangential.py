#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The tangential laws haff_werner, linear_spring, walton_braun, mindlin_deresiewicz,
mindlin_no_slip and di_renzo in pair tdem/gran and fix tdem/wall/gran (issue 4 host checks).

1. Oblique impacts against tdem-collide (velocity Verlet with the same time step, lever arm R as
   the LAMMPS granular styles): a sphere (m = 0.01 kg, R = 5 mm, solid) hits the plane z = 0
   (fix tdem/wall/gran), and two such spheres collide (pair tdem/gran; sphere 2 at rest), for
   each law at impact angles 25 and 65 degrees (sticking/micro-slip and gross sliding) and once
   with initial spin. The sphere starts touching (xi = 0) as in the harness. Compared: beta
   (contact-point tangential restitution), e_t (tangential CoM restitution) and the spin after
   the impact, |host - harness| <= 1e-4 (spin relative to the incident v_t/R). A control run with
   another friction coefficient in the host must differ by more than that.
2. Slope below the friction angle (tan theta = mu/2): a sphere that cannot rotate (fix nve) on the
   plane, gravity tilted to theta over 0.1 s. Every law with memory holds it: the mean position
   over 0.3-0.5 s equals that over 0.1-0.3 s to 1e-9 m (no creep). Haff-Werner has no static
   friction: it creeps at the closed-form velocity m g sin(theta)/gamma_t (1 %). (The drift when
   the whole load is applied at once, which leaves an undamped tangential oscillation, is printed
   for information: walton_braun and mindlin_deresiewicz then drift by ~1e-7 m.)
3. Sliding to rolling: a sphere (fix nve/sphere) put on the floor sliding at v0 = 0.5 m/s without
   spin. After the Coulomb phase (t_s = 2 v0 / (7 mu g) = 49 ms) it rolls with v = 5/7 v0
   (mean over 75-150 ms, relative error <= 2e-3 for every law).
4. For the laws with history: restart in the middle of an oblique pair contact and an oblique
   sliding wall contact (write_restart / read_restart / run M equals run N + run M within 1e-10;
   a control that loses the history differs by > 1e-6), and -np 2 = -np 1 (processors 2 1 1,
   both contacts cross the rank boundary while in contact) within 1e-10.
"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.tangential")
COLLIDE = args.get("collide")
if not COLLIDE or not os.path.exists(COLLIDE):
    print("tdem-collide not given (--collide PATH)")
    sys.exit(1)

M, R = 0.01, 0.005
E, NU = 1e9, 0.3
MU = 0.3
G = 9.81
# name, LAMMPS normal + tangential words, tdem-collide options (normal + tangential; the
# Mindlin-type laws take E, nu of the normal hertz options there)
LSD = ("normal lsd stiffness 1e5 4", ["--law", "lsd", "--k", "1e5", "--gamma", "4", "--end", "zero_overlap"])
HZ = ("normal hertz %r %r damping linear 2" % (E, NU),
      ["--law", "hertz", "--E", "%r" % E, "--nu", "%r" % NU, "--damping", "linear", "--gamma", "2",
       "--end", "zero_overlap"])
LAWS = [
    ("haff_werner", LSD, "tangential haff_werner 20 %r" % MU, "damping absolute",
     ["--tangential", "haff_werner", "--gammat", "20", "--mu", "%r" % MU]),
    ("linear_spring", LSD, "tangential linear_spring 2e4 0.2 1 %r" % MU, "damping absolute slip spring_dashpot",
     ["--tangential", "linear_spring", "--kt", "2e4", "--kappa", "0.2", "--gammat", "1", "--mu", "%r" % MU,
      "--slip-reset", "spring_and_dashpot"]),
    ("linear_spring spring_only", LSD, "tangential linear_spring 3e4 0 2 %r" % MU,
     "damping absolute slip spring friction_limit positive_normal",
     ["--tangential", "linear_spring", "--kt", "3e4", "--gammat", "2", "--mu", "%r" % MU,
      "--slip-reset", "spring_only", "--friction-limit", "positive_normal"]),
    ("walton_braun", LSD, "tangential walton_braun 0 0.8 %r" % MU, "damping absolute",
     ["--tangential", "walton_braun", "--kappa", "0.8", "--mu", "%r" % MU]),
    ("mindlin_deresiewicz", HZ, "tangential mindlin_deresiewicz %r %r %r" % (E, NU, MU), "",
     ["--tangential", "mindlin_deresiewicz", "--mu", "%r" % MU]),
    ("mindlin_no_slip", HZ, "tangential mindlin_no_slip %r %r 1 %r" % (E, NU, MU), "slip spring",
     ["--tangential", "mindlin_no_slip", "--eta-ratio", "1",
      "--mu", "%r" % MU, "--slip-reset", "spring_only"]),
    ("di_renzo", HZ, "tangential di_renzo %r %r %r" % (E, NU, MU), "",
     ["--tangential", "di_renzo", "--mu", "%r" % MU]),
]


def law_words(normal, tang, opts):
    return ("%s %s %s" % (normal[0], tang, opts)).strip()


def collide(normal, topts, wall, angle, spin, steps=20000):
    bodies = ["--m1", "%r" % M, "--R1", "%r" % R] + (["--wall"] if wall else ["--m2", "%r" % M, "--R2", "%r" % R])
    cmd = ([COLLIDE] + normal[1] + topts + bodies +
           ["--v0", "1", "--angle", "%r" % angle, "--spin", "%r" % spin, "--lever-arm", "radius",
            "--steps", str(steps)])
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s: %s" % (" ".join(cmd), p.stdout))
    return json.loads(p.stdout)


HEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.1 0.1 -0.05 0.05 -0.05 0.1 units box
create_box      1 box
"""
REPORT = "write_dump all custom res.dump id x z vx vz omegay modify sort id format float %.17g\n"


def results(wd, name="res.dump"):
    """The values of the dump (atoms in id order, columns after id) as one flat list."""
    _, data = lc.read_dump(os.path.join(wd, name))
    return [float(v) for row in data[:, 1:] for v in row]


def impact_host(law, wall, angle, spin, dt, tc, wd):
    """One impact in LAMMPS; returns beta, e_t, spin after (harness sign: about -y)."""
    vt, vn = math.sin(math.radians(angle)), math.cos(math.radians(angle))
    nsteps = int(1.5 * tc / dt) + 50
    if wall:
        atoms = ("create_atoms 1 single 0 0 %r units box\ncreate_atoms 1 single 0.04 0 0.05 units box\n" % R)
        inter = ("pair_style tdem/gran\npair_coeff * * %s\nfix w all tdem/wall/gran %s zplane 0 NULL\n"
                 % (law, law))
    else:
        atoms = ("create_atoms 1 single 0 0 %r units box\ncreate_atoms 1 single 0 0 0 units box\n" % (2 * R))
        inter = "pair_style tdem/gran\npair_coeff * * %s\n" % law
    text = (HEAD + atoms + "set group all diameter %r\nset group all mass %r\n" % (2 * R, M) +
            "set atom 1 vx %r vz %r omega 0 %r 0\n" % (vt, -vn, -spin) + inter +
            "neighbor 0.001 bin\nneigh_modify delay 0 every 1 check yes\nfix nve all nve/sphere\n"
            "timestep %r\nrun %d\n" % (dt, nsteps) + REPORT)
    lc.run(args["tdem"], text, wd, "in.impact")
    x1, z1, vx1, vz1, wy1, x2, z2, vx2, vz2, wy2 = results(wd)
    if wall:
        # plane wall: the frame is fixed (n = z, t = x)
        vs1 = vx1 - R * wy1
        return -vs1 / (vt + R * spin), vx1 / vt, -wy1
    # two spheres: the harness reports the velocities after in the frame of the line of centres
    # at separation; go back along the free flight to |x1 - x2| = 2R
    dx, dz, ux, uz = x1 - x2, z1 - z2, vx1 - vx2, vz1 - vz2
    a, b, c = ux * ux + uz * uz, -2.0 * (dx * ux + dz * uz), dx * dx + dz * dz - 4.0 * R * R
    tau = (-b - math.sqrt(b * b - 4.0 * a * c)) / (2.0 * a)  # the smaller root: time since separation
    nx, nz = (dx - ux * tau) / (2 * R), (dz - uz * tau) / (2 * R)
    vtp = ux * nz - uz * nx  # along t' = (n_z, -n_x) (t' = x before the impact)
    vs1 = vtp - R * (wy1 + wy2)
    return -vs1 / (vt + R * spin), vtp / vt, -wy1


# ---------------------------------------------------------------- 1. oblique impacts
wd = lc.workdir("oblique")
worst = 0.0
for name, normal, tang, opts, topts in LAWS:
    law = law_words(normal, tang, opts)
    cases = [(True, 25.0, 0.0), (True, 65.0, 0.0), (True, 40.0, 150.0), (False, 25.0, 0.0), (False, 65.0, 0.0)]
    for wall, angle, spin in cases:
        j = collide(normal, topts, wall, angle, spin)
        beta, et, sp = impact_host(law, wall, angle, spin, j["dt"], j["contact_time"], wd)
        scale = j["vt0"] / R
        d = max(abs(beta - j["beta"]), abs(et - j["e_t"]), abs(sp - j["spin_after"]) / scale)
        worst = max(worst, d)
        chk.check(d <= 1e-4, "%s %s angle %g spin %g: beta %.6f (harness %.6f), e_t %.6f (%.6f), spin %.4f (%.4f), "
                  "max diff %.2g" % (name, "wall" if wall else "pair", angle, spin, beta, j["beta"], et, j["e_t"],
                                     sp, j["spin_after"], d))
print("oblique impacts: max |host - harness| = %.3g" % worst)
# control: another mu in the host must be seen
name, normal, tang, opts, topts = LAWS[1]
j = collide(normal, topts, True, 65.0, 0.0)
beta, et, sp = impact_host(law_words(normal, tang.replace("%r" % MU, "0.25"), opts), True, 65.0, 0.0,
                           j["dt"], j["contact_time"], wd)
chk.check(abs(beta - j["beta"]) > 1e-3, "control: mu 0.25 in the host vs 0.3 in the harness differs (beta %.5f vs %.5f)"
          % (beta, j["beta"]))

# ---------------------------------------------------------------- 2. slope, 3. rolling
FLOOR = """
create_atoms    1 single -0.08 0 {z!r} units box
set             group all diameter {d!r}
set             group all mass {m!r}
set             atom 1 vx {vx!r}
pair_style      tdem/gran
pair_coeff      * * {law}
fix             w all tdem/wall/gran {law} zplane 0 NULL
variable        th equal {theta!r}*((step/{nr!r})*(step<{nr!r})+(step>={nr!r}))
variable        gx equal sin(v_th)
variable        gz equal -cos(v_th)
fix             g all gravity {g!r} vector v_gx 0 v_gz
fix             nve all {integ}
timestep        {dt!r}
run             {nramp}
variable        xx equal x[1]
variable        vv equal vx[1]
fix             ax all ave/time 1 {nhalf} {nhalf} v_xx v_vv
thermo_style    custom step f_ax[1] f_ax[2]
thermo_modify   format float %.17g
thermo          {nhalf}
run             {n}
"""


def floor_run(law, wd, theta, integ, vx, t_end, dt, zeq, tramp=0.0):
    """Tilt gravity to theta over tramp (0: at once), then two windows of t_end/2: their mean
    x and vx."""
    nhalf = int(round(t_end / dt)) // 2
    g = FLOOR.format(z=R - zeq, d=2 * R, m=M, vx=vx, law=law, g=G, theta=theta, nr=max(int(round(tramp / dt)), 1),
                     integ=integ, nramp=int(round(tramp / dt)), nhalf=nhalf, dt=dt, n=2 * nhalf)
    _, out = lc.run(args["tdem"], HEAD + g, wd, "in.floor")
    rows = [r.split() for r in lc.thermo_blocks(out) if not r.startswith("Step")]
    rows = [r for r in rows if len(r) == 3]
    return [(float(r[1]), float(r[2])) for r in rows[-2:]]


wd = lc.workdir("slope")
theta = math.atan(MU / 2)
for name, normal, tang, opts, topts in LAWS:
    law = law_words(normal, tang, opts)
    zeq = M * G * math.cos(theta) / 1e5 if normal is LSD else (M * G / (4.0 / 3.0 * E / (1 - NU * NU) / 2 * math.sqrt(R))) ** (2.0 / 3.0)
    dt = 1e-5 if normal is LSD else 2e-6
    if name == "haff_werner":
        (x1, v1), (x2, v2) = floor_run(law, wd, theta, "nve", 0.0, 0.4, dt, zeq)
        vc = M * G * math.sin(theta) / 20.0
        chk.check(abs(v2 - vc) <= 0.01 * vc and x2 - x1 > 0.1 * vc,
                  "slope %s: creeps (no static friction) at %.5g m/s, closed form m g sin(theta)/gamma_t = %.5g m/s"
                  % (name, v2, vc))
        continue
    # gravity tilted over 0.1 s (quasi-static: the tangential contact frequencies are > 100 Hz)
    (x1, v1), (x2, v2) = floor_run(law, wd, theta, "nve", 0.0, 0.4, dt, zeq, tramp=0.1)
    chk.check(abs(x2 - x1) <= 1e-9, "slope %s: no creep below the friction angle (mean x %.4g -> %.4g m, "
              "drift %.2g m)" % (name, x1 + 0.08, x2 + 0.08, x2 - x1))
    # for information: the load applied at once (undamped tangential oscillation)
    (x1, v1), (x2, v2) = floor_run(law, wd, theta, "nve", 0.0, 0.4, dt, zeq)
    print("slope %s, tilt at once: drift of the mean x between 0-0.2 s and 0.2-0.4 s %.3g m" % (name, x2 - x1))

wd = lc.workdir("roll")
for name, normal, tang, opts, topts in LAWS:
    law = law_words(normal, tang, opts)
    zeq = M * G / 1e5 if normal is LSD else (M * G / (4.0 / 3.0 * E / (1 - NU * NU) / 2 * math.sqrt(R))) ** (2.0 / 3.0)
    dt = 1e-5 if normal is LSD else 2e-6
    v0 = 0.5
    # mean velocity over the second half of 0.15 s (the sliding phase ends at 49 ms)
    rows = floor_run(law, wd, 0.0, "nve/sphere", v0, 0.15, dt, zeq)
    vend = rows[-1][1]
    err = abs(vend - 5.0 / 7.0 * v0) / (5.0 / 7.0 * v0)
    chk.check(err <= 2e-3, "rolling %s: v = %.6f m/s after sliding, 5/7 v0 = %.6f (rel err %.2g)"
              % (name, vend, 5.0 / 7.0 * v0, err))

# ---------------------------------------------------------------- 4. restart and MPI
HH = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          {newton}
comm_modify     vel yes
{processors}
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 box
"""
HT = """
neighbor        0.001 bin
neigh_modify    delay 0 every 1 check yes
fix             nve all nve/sphere
timestep        {dt!r}
"""
HREPORT = "write_dump all custom {f} id x z vx vy vz omegax omegay omegaz modify sort id format float %.17g\n"


def hatoms(dt):
    # pair along x (relative speed 1, drift -5 m/s, relative tangential velocity 0.6 m/s along z,
    # spin about y and z); atom 3 hits the floor at 1 m/s sliding at 5 m/s with spin about z
    gap = 20 * dt
    specs = [(-0.0025 - R, 0.05, -4.5, 0.3, 50.0), (-0.0025 + R + gap, 0.05, -5.5, -0.3, -20.0),
             (-0.0025 - gap * 5.0, R + gap, 5.0, -1.0, 80.0)]
    out = ["create_atoms 1 single %r 0 %r units box" % (x, z) for x, z, _, _, _ in specs]
    for k, (x, z, vx, vz, w) in enumerate(specs, 1):
        out.append("set atom %d diameter %r\nset atom %d mass %r\nset atom %d vx %r vz %r omega 0 %r %r"
                   % (k, 2 * R, k, M, k, vx, vz, w, 0.5 * w))
    return "\n".join(out)


def worst_rel(a, b):
    assert len(a) == len(b) and a, (a, b)
    return max(abs(x - y) / max(abs(x), abs(y), 1e-300) for x, y in zip(a, b))


wd = lc.workdir("restart")
dt = 1e-6
n1, n2 = 20 + 300, 800
for name, normal, tang, opts, topts in LAWS:
    if name == "haff_werner":
        continue  # no memory
    law = law_words(normal, tang, opts)
    inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL\n" % (law, law)
    base = HH.format(newton="off", processors="") + hatoms(dt) + "\n" + inter + HT.format(dt=dt)
    lc.run(args["tdem"], base + "run %d\nrun %d\n" % (n1, n2) + HREPORT.format(f="ref.dump"), wd, "in.ref")
    _, first = lc.run(args["tdem"], base + "run %d\n" % n1 +
                      'print "STATE $(fx[1]:%.17g) $(fz[1]:%.17g) $(fx[3]:%.17g) $(fz[3]:%.17g)"\n'
                      "write_restart h.restart\n", wd, "in.first")
    st = [float(x) for l in first.splitlines() if l.startswith("STATE ") for x in l.split()[1:]]
    chk.check(len(st) == 4 and st[0] < 0 and st[1] != 0 and st[2] != 0 and st[3] > 0,
              "%s: restart point inside the oblique pair and wall contacts (pair fx %.3g fz %.3g, wall fx %.3g fz %.3g)"
              % ((name,) + tuple(st + [0] * (4 - len(st)))))
    second = ("atom_modify map array\nread_restart h.restart\nneighbor 0.001 bin\n"
              "neigh_modify delay 0 every 1 check yes\ncomm_modify vel yes\n"
              "fix floor all tdem/wall/gran %s zplane 0 NULL\nfix nve all nve/sphere\ntimestep %r\nrun %d\n"
              % (law, dt, n2) + HREPORT.format(f="rs.dump"))
    lc.run(args["tdem"], second, wd, "in.second")
    lost = second.replace("fix floor all", "pair_style none\npair_style tdem/gran\npair_coeff * * %s\nfix floor2 all" % law)
    lc.run(args["tdem"], lost.replace("rs.dump", "ls.dump"), wd, "in.lost")
    r_ref, r_rs, r_ls = results(wd, "ref.dump"), results(wd, "rs.dump"), results(wd, "ls.dump")
    w = worst_rel(r_ref, r_rs)
    wl = worst_rel(r_ref, r_ls)
    chk.check(w <= 1e-10, "%s: restart mid-contact equals run N + run M (max rel diff %.3g)" % (name, w))
    chk.check(wl > 1e-6, "%s: control: losing the history changes the result (max rel diff %.3g)" % (name, wl))
    for newton in ("off", "on"):
        outs = []
        for np_ in (1, 2):
            text = (HH.format(newton=newton, processors="processors 2 1 1" if np_ == 2 else "") + hatoms(dt) + "\n" +
                    inter + HT.format(dt=dt) + "run %d\n" % (n1 + n2) + HREPORT.format(f="np%d.dump" % np_))
            lc.run(args["tdem"], text, wd, "in.np%d" % np_, np_=np_, mpirun=args["mpirun"])
            outs.append(results(wd, "np%d.dump" % np_))
        w = worst_rel(outs[0], outs[1])
        crossed = outs[1][8] < 0 < outs[1][16]
        chk.check(crossed and w <= 1e-10, "%s, newton %s: -np 2 equals -np 1, atoms cross ranks in contact "
                  "(max rel diff %.3g)" % (name, newton, w))
chk.done()
