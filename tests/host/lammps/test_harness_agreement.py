#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Host-vs-harness agreement: every tdem normal law of pair tdem/gran and fix tdem/wall/gran
against tdem-collide (an independent RK4 integration of the same kernel with exact event
location).

For each law case one LAMMPS run (units si, no gravity) holds two impacts at once:
  wall  atom 1 (m = 0.01 kg, R = 5 mm) hits the plane z = 0 (fix tdem/wall/gran) at v0;
  pair  atoms 2, 3 (same spheres) approach each other along z with relative velocity v0
        (pair tdem/gran); far from atom 1 and from the wall.
The time step is dt = min(t_c wall, t_c pair) / STEPS with t_c from tdem-collide, and every step
is printed (thermo 1). From the samples:
  e    = rebound velocity / v0 (free flight after the contact; pair: relative velocities);
  t_c  = t_end - t_start. t_start: the free-flight line before the first step with a contact
         force, extrapolated to xi = 0 (exact). t_end: if the first force-free step after the
         contact has xi < 0 (the contact ended geometrically), the post-contact free-flight line
         extrapolated back to xi = 0; otherwise (the force reached zero at xi > 0: limit_force yes,
         hysteretic laws) the linear extrapolation to F = 0 of the last two force samples, clipped
         to the step after the last one with a force.
Velocity Verlet in LAMMPS has O(dt) errors at force jumps (lsd's dashpot at touch) and uses
half-step velocities in the damping; with STEPS = 20000 these stay ~1e-5 (estimated
gamma dt / 2 m* <= 2e-5 for the stiffest-damped case), below the tolerances
|e_host - e_harness| <= 1e-4 and |tc_host - tc_harness| / tc_harness <= 1e-4.
tdem-collide runs with --steps 20000 (RK4: its own error is below 1e-10).

A control checks that the comparison can fail: the extended_linear case (rational e fit, power
t_c fit) at v0 = 3 evaluated with the harness at v0 = 1 (other e(v0), t_c(v0)) must disagree by
far more than the tolerance.
A table of the differences is printed (Markdown).
"""
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.harness_agreement")
COLLIDE = args.get("collide")
if not COLLIDE or not os.path.exists(COLLIDE):
    print("tdem-collide not given (--collide PATH)")
    sys.exit(1)

STEPS = 20000
TOL_E = 1e-4
TOL_TC = 1e-4
M = 0.01
R = 0.005
TS = "tangential cundall_strack 0.8 0.3"
TS_LSD = "tangential cundall_strack 3e4 0 0.3"

# name, LAMMPS normal law words (+ options), tdem-collide law options, v0 [m/s].
# The collide options for the wall and the pair differ only where the law takes m* (lsd damping
# mass: gamma = m* GAMMAN), which is filled in by gamma_m.
E, NU = 1e9, 0.3
HZ = ["--E", "%r" % E, "--nu", "%r" % NU]
CASES = [
    ("lsd stiffness mass, limit_force no", "normal lsd stiffness 1e5 500 %s limit_force no" % TS_LSD,
     ["--law", "lsd", "--k", "1e5", "--gamma", "m*500", "--end", "zero_overlap"], 1.0),
    ("lsd stiffness mass, limit_force yes", "normal lsd stiffness 1e5 500 %s limit_force yes" % TS_LSD,
     ["--law", "lsd", "--k", "1e5", "--gamma", "m*500", "--end", "zero_force"], 1.0),
    ("lsd stiffness absolute, limit_force no",
     "normal lsd stiffness 1e5 4 tangential cundall_strack 3e4 0 0.3 damping absolute limit_force no",
     ["--law", "lsd", "--k", "1e5", "--gamma", "4", "--end", "zero_overlap"], 1.0),
    ("lsd stiffness absolute, limit_force yes",
     "normal lsd stiffness 1e5 4 tangential cundall_strack 3e4 0 0.3 damping absolute limit_force yes",
     ["--law", "lsd", "--k", "1e5", "--gamma", "4", "--end", "zero_force"], 1.0),
    ("lsd restitution, limit_force yes", "normal lsd restitution 0.6 1e-3 %s limit_force yes" % TS,
     ["--law", "lsd", "--e", "0.6", "--tc", "1e-3", "--end", "zero_force"], 1.0),
]
for damp, lmp_d, col_d in (("tsuji", "tsuji 0.7", ["--damping", "tsuji", "--e", "0.7"]),
                           ("linear", "linear 2", ["--damping", "linear", "--gamma", "2"]),
                           ("kuwabara_kono", "kuwabara_kono 200", ["--damping", "kuwabara_kono", "--gamma", "200"]),
                           ("general", "general 0.25 20", ["--damping", "general", "--theta", "0.25", "--gamma", "20"])):
    for end in ("no", "yes"):
        CASES.append(("hertz %s, limit_force %s" % (damp, end),
                      "normal hertz %r %r damping %s %s limit_force %s" % (E, NU, lmp_d, TS, end),
                      ["--law", "hertz"] + HZ + col_d + ["--end", "zero_force" if end == "yes" else "zero_overlap"], 1.0))
CASES += [
    ("walton_braun constant k_ul", "normal walton_braun 1e5 1.5625e5 %s" % TS,
     ["--law", "walton_braun", "--kl", "1e5", "--kul", "1.5625e5"], 1.0),
    ("walton_braun force-dependent k_ul", "normal walton_braun 1e5 1e5 3291 %s" % TS,
     ["--law", "walton_braun", "--kl", "1e5", "--kul", "1e5", "--s", "3291"], 1.0),
    ("thornton", "normal thornton %r %r 3e7 %s" % (E, NU, TS),
     ["--law", "thornton"] + HZ + ["--py", "3e7"], 1.0),
    ("power_law q = 0", "normal power_law 1e7 1.5 2.915e7 %s" % TS,
     ["--law", "power_law", "--al", "1e7", "--p", "1.5", "--aul", "2.915e7"], 1.0),
    ("power_law q = 0.5", "normal power_law 1e7 1.5 3e9 0.5 %s" % TS,
     ["--law", "power_law", "--al", "1e7", "--p", "1.5", "--aul", "3e9", "--q", "0.5"], 1.0),
    # luding (the worked example of docs/adding_a_law.md): below and beyond its plastic limit
    ("luding below xi_lim", "normal luding 1e5 5e5 0.05 %s" % TS, ["--law", "luding", "--params", "1e5,5e5,0.05"], 1.0),
    ("luding beyond xi_lim", "normal luding 1e5 5e5 0.01 %s" % TS, ["--law", "luding", "--params", "1e5,5e5,0.01"], 1.0),
    # continuous_potential: d = X_cut = R_i + R_j (the wall: R_i), as LIGGGHTS's model and the
    # harness's default d; damped with both ends, and elastic
    ("continuous_potential damped, limit_force no", "normal continuous_potential 1e-5 36 0.1 %s limit_force no" % TS,
     ["--law", "continuous_potential", "--eps", "1e-5", "--n", "36", "--gamma", "0.1", "--end", "zero_overlap"], 1.0),
    ("continuous_potential damped, limit_force yes", "normal continuous_potential 1e-5 36 0.1 %s limit_force yes" % TS,
     ["--law", "continuous_potential", "--eps", "1e-5", "--n", "36", "--gamma", "0.1", "--end", "zero_force"], 1.0),
    ("continuous_potential elastic", "normal continuous_potential 2e-4 36 0 %s" % TS,
     ["--law", "continuous_potential", "--eps", "2e-4", "--n", "36", "--gamma", "0"], 1.0),
]
EXT_A = ("e_fit rational 1 1 0.2 tc_fit power 1e-3 0.2",
         ["--e-fit", "rational", "--e-coef", "1,1,0.2", "--tc-fit", "power", "--tc-coef", "1e-3,0.2"])
EXT_B = ("e_fit power 0.1 0.1 tc_fit constant 8e-4 v_min 0.01 v_max 50",
         ["--e-fit", "power", "--e-coef", "0.1,0.1", "--tc-fit", "constant", "--tc-coef", "8e-4",
          "--v-min", "0.01", "--v-max", "50"])
for v0 in (1.0, 3.0):
    for end in ("no", "yes"):
        fit = EXT_A if (v0 == 1.0) == (end == "no") else EXT_B
        CASES.append(("extended_linear %s, limit_force %s, v0 %g" % (fit[0].split(" tc_fit")[0], end, v0),
                      "normal extended_linear %s %s limit_force %s" % (fit[0], TS, end),
                      ["--law", "extended_linear"] + fit[1] + ["--end", "zero_force" if end == "yes" else "zero_overlap"], v0))
for end, v0 in (("no", 1.0), ("yes", 2.0)):
    CASES.append(("extended_hertz e_fit rational, limit_force %s, v0 %g" % (end, v0),
                  "normal extended_hertz %r %r e_fit rational 1 1 0.2 v_max 20 %s limit_force %s" % (E, NU, TS, end),
                  ["--law", "extended_hertz"] + HZ + ["--e-fit", "rational", "--e-coef", "1,1,0.2", "--v-max", "20",
                                                       "--end", "zero_force" if end == "yes" else "zero_overlap"], v0))


def collide(opts, wall, v0):
    meff = M if wall else M / 2
    o = [x if not x.startswith("m*") else "%r" % (meff * float(x[2:])) for x in opts]
    bodies = ["--m1", "%r" % M, "--R1", "%r" % R] + (["--wall"] if wall else ["--m2", "%r" % M, "--R2", "%r" % R])
    cmd = [COLLIDE] + o + bodies + ["--v0", "%r" % v0, "--steps", "20000"]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s: %s" % (" ".join(cmd), p.stdout))
    j = json.loads(p.stdout)
    return j["e"], j["contact_time"]


SCRIPT = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 box
create_atoms    1 single -0.03 0 {z1!r} units box
create_atoms    1 single 0.03 0 {z2!r} units box
create_atoms    1 single 0.03 0 {z3!r} units box
set             group all diameter {d!r}
set             group all mass {m!r}
set             atom 1 vz {v1!r}
set             atom 2 vz {v2!r}
set             atom 3 vz {v3!r}
pair_style      tdem/gran
pair_coeff      * * {law}
fix             floor all tdem/wall/gran {law} zplane 0 NULL
neighbor        0.002 bin
neigh_modify    delay 0 every 1 check yes
fix             nve all nve/sphere
timestep        {dt!r}
variable        a1 equal z[1]
variable        a2 equal vz[1]
variable        a3 equal fz[1]
variable        a4 equal z[2]
variable        a5 equal vz[2]
variable        a6 equal fz[2]
variable        a7 equal z[3]
variable        a8 equal vz[3]
thermo_style    custom step v_a1 v_a2 v_a3 v_a4 v_a5 v_a6 v_a7 v_a8
thermo_modify   format float %.17g
thermo          1
run             {n}
"""


def measure(t, xi, xid, F, v0):
    """e and t_c from per-step samples of one impact (see the module docstring)."""
    act = [i for i in range(len(F)) if F[i] != 0.0]
    i1, i2 = act[0], act[-1]
    assert i1 > 0 and i2 + 1 < len(F), "contact not inside the run"
    assert all(F[i] == 0.0 for i in range(i2 + 1, len(F)))
    i0 = i1 - 1
    ts = t[i0] + (0.0 - xi[i0]) / xid[i0]
    j = i2 + 1
    if xi[j] < 0.0:
        te = t[j] + (0.0 - xi[j]) / xid[j]
        how = "xi"
    else:
        dt = t[j] - t[i2]
        slope = (F[i2] - F[i2 - 1]) / dt
        te = t[i2] + (-F[i2] / slope if slope != 0.0 else 0.5 * dt)
        te = min(max(te, t[i2]), t[j])
        how = "F"
    return -xid[-1] / v0, te - ts, how


def host(law, v0, dt_hint, tmax):
    dt = float("%.6g" % dt_hint)
    gap = 20
    z1 = R + gap * dt * v0 + 0.5 * dt * v0  # touch between steps 20 and 21
    z2 = 0.05
    z3 = z2 + 2 * R + gap * dt * v0 + 0.37 * dt * v0
    n = gap + 2 + int(1.25 * tmax / dt)
    text = SCRIPT.format(z1=z1, z2=z2, z3=z3, d=2 * R, m=M, v1=-v0, v2=0.5 * v0, v3=-0.5 * v0,
                         law=law, dt=dt, n=n)
    _, out = lc.run(args["tdem"], text, wd, "in.case")
    rows = [[float(x) for x in l.split()] for l in lc.thermo_blocks(out)[1:]]
    t = [r[0] * dt for r in rows]
    wall = measure(t, [R - r[1] for r in rows], [-r[2] for r in rows], [r[3] for r in rows], v0)
    pair = measure(t, [2 * R - (r[7] - r[4]) for r in rows], [r[5] - r[8] for r in rows],
                   [r[6] for r in rows], v0)
    return wall, pair, dt


wd = lc.workdir("harness")
table = ["| law | v0 [m/s] | impact | e host | e harness | abs. diff e | t_c harness [s] | rel. diff t_c | end located by |",
         "|---|---|---|---|---|---|---|---|---|"]
start = time.time()
worst_e = worst_tc = 0.0
for name, law, copts, v0 in CASES:
    ref_w = collide(copts, True, v0)
    ref_p = collide(copts, False, v0)
    (ew, tw, hw), (ep, tp, hp), dt = host(law, v0, min(ref_w[1], ref_p[1]) / STEPS,
                                          max(ref_w[1], ref_p[1]))
    for tag, (eh, th, how), (er, tr) in (("wall", (ew, tw, hw), ref_w), ("pair", (ep, tp, hp), ref_p)):
        de, dtc = eh - er, th / tr - 1
        worst_e, worst_tc = max(worst_e, abs(de)), max(worst_tc, abs(dtc))
        table.append("| %s | %g | %s | %.7f | %.7f | %+.2e | %.6e | %+.2e | %s |"
                     % (name, v0, tag, eh, er, de, tr, dtc, how))
        chk.check(abs(de) <= TOL_E and abs(dtc) <= TOL_TC,
                  "%s, %s: |de| = %.2e, |dtc|/tc = %.2e (e %.6f vs %.6f, t_c %.6e vs %.6e, dt = t_c/%d)"
                  % (name, tag, abs(de), abs(dtc), eh, er, th, tr, round(tr / dt)))
        if tag == "wall" and name.startswith("extended_linear e_fit rational") and v0 == 3.0:
            # control: the harness at the wrong impact velocity disagrees with the host
            ec, tcc = collide(copts, True, 1.0)
            chk.check(abs(eh - ec) > 10 * TOL_E and abs(th / tcc - 1) > 10 * TOL_TC,
                      "control: extended_linear host at v0 = 3 vs harness at v0 = 1 differ "
                      "(de = %.2e, dtc = %.2e)" % (eh - ec, th / tcc - 1))

print("\n".join(table))
print("worst |e_host - e_harness| = %.2e, worst |tc_host/tc_harness - 1| = %.2e; %d cases, %.1f s"
      % (worst_e, worst_tc, len(CASES), time.time() - start))
chk.done()
