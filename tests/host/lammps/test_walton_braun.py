#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""normal walton_braun in pair tdem/gran and fix tdem/wall/gran.

1. Impacts vs closed forms re-implemented here (physics_reference 2.2.4 and 8.3):
   constant k_ul: e = sqrt(k_l/k_ul), t_c = pi/2 (sqrt(m*/k_l) + sqrt(m*/k_ul)); with
   k_l = 1e5, k_ul = 1.5625e5, m* = 0.01: e = 0.8, t_c = 8.94113e-4 s (8.3).
   force-dependent k_ul = k_l + s F_max, F_max = v0 sqrt(m* k_l):
   e = [1 + s v0 sqrt(m*/k_l)]^(-1/2), t_c from the same formula with that k_ul.
   Wall (m* = m) and head-on (two equal spheres, m* = m/2). 1000 steps per contact; contact
   start and end interpolated between steps (end: zero of k_ul (xi - xi_F0) with xi_max the
   largest sampled overlap); tolerance 2 dt/t_c = 2e-3 relative.
2. Restart in the middle of a collision (unloading branch, xi_max in the history of the pair
   and of the wall fix): write_restart / read_restart / run M equals run N + run M within
   1e-10 relative; a control that loses the history (pair style and wall fix defined anew)
   differs by more than 1e-3.
3. -np 2 (processors 2 1 1, boundary x = 0, newton on and off): a head-on pair and a sphere
   sliding on the floor cross the processor boundary during the contact (atoms migrate with
   their history); final positions and velocities equal -np 1 within 1e-10 relative.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.walton_braun")
STEPS = 1000
TOL = 2.0 / STEPS
KL, KUL = 1.0e5, 1.5625e5
M = 0.01
R = 0.005


def wb_closed(kl, ku, s, meff, v0):
    fmax = v0 * math.sqrt(meff * kl)
    kul = ku + s * fmax
    return math.sqrt(kl / kul), 0.5 * math.pi * (math.sqrt(meff / kl) + math.sqrt(meff / kul)), kul


e_ref, tc_ref, _ = wb_closed(KL, KUL, 0.0, M, 1.0)
chk.check(abs(e_ref - 0.8) < 1e-12 and abs(tc_ref / 8.94113e-4 - 1) < 1e-5,
          "closed form reproduces physics_reference 8.3 (e %.6f, t_c %.6e)" % (e_ref, tc_ref))

HEAD = """
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
TAIL_SETTINGS = """
neighbor        0.001 bin
neigh_modify    delay 0 every 1 check yes
fix             nve all nve/sphere
timestep        {dt!r}
"""


def atoms_text(specs):
    """specs: (x, z, vx, vz, mass). Diameter 2R."""
    out = []
    for k, (x, z, vx, vz, m) in enumerate(specs, 1):
        out.append("create_atoms 1 single %r 0 %r units box" % (x, z))
    for k, (x, z, vx, vz, m) in enumerate(specs, 1):
        out.append("set atom %d diameter %r\nset atom %d mass %r\nset atom %d vx %r vz %r"
                   % (k, 2 * R, k, m, k, vx, vz))
    return "\n".join(out)


def law(kl, ku, s=None):
    return "normal walton_braun %r %r%s tangential cundall_strack 0.8 0.3" % (
        kl, ku, "" if s is None else " %r" % s)


# ------------------------------------------------------------------ 1. impacts
def impact(tag, wall, kl, ku, s, v0):
    meff = M if wall else M / 2
    e_exp, tc_exp, kul = wb_closed(kl, ku, s or 0.0, meff, v0)
    dt = float("%.6g" % (tc_exp / STEPS))
    gap = 20
    if wall:
        specs = [(0.0, R + gap * dt * v0, 0.0, -v0, M)]
        inter = "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL" % (
            law(kl, ku, s), law(kl, ku, s))
    else:
        specs = [(0.0, 0.05, 0.0, v0 / 2, M), (0.0, 0.05 + 2 * R + gap * dt * v0, 0.0, -v0 / 2, M)]
        inter = "pair_style tdem/gran\npair_coeff * * %s" % law(kl, ku, s)
    text = (HEAD.format(newton="off", processors="") + atoms_text(specs) + "\n" + inter +
            TAIL_SETTINGS.format(dt=dt) +
            "variable z1 equal z[1]\nvariable v1 equal vz[1]\n"
            "variable z2 equal %s\nvariable v2 equal %s\n" % (("0", "0") if wall else ("z[2]", "vz[2]")) +
            "thermo_style custom step v_z1 v_v1 v_z2 v_v2\nthermo_modify format float %%.17g\n"
            "thermo 1\nrun %d\n" % (gap + int(1.6 * STEPS) + 40))
    wd = lc.workdir("wb_" + tag)
    _, out = lc.run(args["tdem"], text, wd)
    rows = [tuple(float(x) for x in l.split()) for l in lc.thermo_blocks(out)[1:]]
    radsum = R if wall else 2 * R
    t, xi, xid = [], [], []
    for st, z1, v1, z2, v2 in rows:
        xi.append(radsum - z1 if wall else radsum - (z2 - z1))
        xid.append(-v1 if wall else -(v2 - v1))
        t.append(st * dt)
    i0 = next(i for i in range(1, len(xi)) if xi[i] > 0 >= xi[i - 1])
    ts = t[i0 - 1] + dt * (0 - xi[i0 - 1]) / (xi[i0] - xi[i0 - 1])
    xm = max(xi)
    kul_m = ku + (s or 0.0) * kl * xm
    xf0 = xm * (1 - kl / kul_m)
    g = [a - xf0 for a in xi]
    imax = xi.index(xm)
    i1 = next(i for i in range(imax + 1, len(g)) if g[i] <= 0 < g[i - 1])
    te = t[i1 - 1] + dt * g[i1 - 1] / (g[i1 - 1] - g[i1])
    e_m, tc_m = -xid[-1] / xid[0], te - ts
    de, dtc = e_m / e_exp - 1, tc_m / tc_exp - 1
    print("%s: e %.6f (expected %.6f, rel err %+.2e), t_c %.6e (expected %.6e, rel err %+.2e)"
          % (tag, e_m, e_exp, de, tc_m, tc_exp, dtc))
    chk.check(abs(de) <= TOL, "%s: restitution within %.2g" % (tag, TOL))
    chk.check(abs(dtc) <= TOL, "%s: contact time within %.2g" % (tag, TOL))


impact("wall constant k_ul", True, KL, KUL, None, 1.0)
impact("head-on constant k_ul", False, KL, KUL, None, 1.0)
E_FD = 0.7
S_FD = float("%.6g" % ((1 / E_FD ** 2 - 1) / (1.0 * math.sqrt(M / KL))))
impact("wall force-dependent k_ul", True, KL, KL, S_FD, 1.0)
impact("head-on force-dependent k_ul", False, KL, KL, S_FD, 2.0)

# ------------------------------------------------------------------ scene for 2. and 3.
DT = float("%.6g" % (tc_ref / STEPS))


def scene_atoms():
    # pair: head-on along x, relative speed 1, drift -5 m/s (atom 2 crosses x = 0 in contact);
    # atom 3: hits the floor at 1 m/s while sliding at +5 m/s across x = 0
    gap = 20 * DT
    x1 = -0.0025 - R
    x2 = -0.0025 + R + gap * 1.0
    return atoms_text([(x1, 0.05, -5.0 + 0.5, 0.0, M), (x2, 0.05, -5.0 - 0.5, 0.0, M),
                       (-0.0025 - 20 * DT * 5.0, R + gap * 1.0, 5.0, -1.0, M)])


INTER = ("pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL\n"
         % (law(KL, KUL), law(KL, KUL)))
REPORT = "".join('print "RES %d $(x[%d]:%%.17g) $(z[%d]:%%.17g) $(vx[%d]:%%.17g) $(vz[%d]:%%.17g)"\n'
                 % (k, k, k, k, k) for k in (1, 2, 3))


def results(out):
    vals = []
    for line in out.splitlines():
        if line.startswith("RES "):
            vals += [float(x) for x in line.split()[2:]]
    return vals


def worst(a, b):
    assert len(a) == len(b) and a, (a, b)
    return max(abs(x - y) / max(abs(x), abs(y), 1e-300) for x, y in zip(a, b))


N1, N2 = 20 + 600, 1000  # both contacts unloading at N1 (pair 393..707, wall 556..894 steps)
wd = lc.workdir("wb_restart")
base = HEAD.format(newton="off", processors="") + scene_atoms() + "\n" + INTER + TAIL_SETTINGS.format(dt=DT)
_, ref = lc.run(args["tdem"], base + "run %d\nrun %d\n" % (N1, N2) + REPORT, wd, "in.ref")
_, _ = lc.run(args["tdem"], base + "run %d\nwrite_restart wb.restart\n" % N1, wd, "in.first")
second = ("atom_modify map array\nread_restart wb.restart\nneighbor 0.001 bin\nneigh_modify delay 0 every 1 check yes\n"
          "comm_modify vel yes\nfix floor all tdem/wall/gran %s zplane 0 NULL\n"
          "fix nve all nve/sphere\ntimestep %r\nrun %d\n" % (law(KL, KUL), DT, N2) + REPORT)
_, rs = lc.run(args["tdem"], second, wd, "in.second")
lost = second.replace("fix floor all", "pair_style none\npair_style tdem/gran\npair_coeff * * %s\nfix floor2 all" % law(KL, KUL))
_, ls = lc.run(args["tdem"], lost, wd, "in.lost")
r_ref, r_rs, r_ls = results(ref), results(rs), results(ls)
w = worst(r_ref, r_rs)
print("restart mid-collision: max rel diff %.3g; history lost: pair vx %.6f vs %.6f, wall vz %.6f vs %.6f"
      % (w, r_ls[2], r_ref[2], r_ls[11], r_ref[11]))
chk.check(w <= 1e-10, "restart mid-collision equals run N + run M (max rel diff %.3g)" % w)
chk.check(abs(r_ls[2] - r_ref[2]) > 1e-3 and abs(r_ls[11] - r_ref[11]) > 1e-3,
          "control: losing the pair and wall history changes the rebound")
# the rebound itself: e of both collisions from the reference run
e_pair = (r_ref[6] - r_ref[2]) / 1.0
e_wall = r_ref[11] / 1.0
print("scene rebounds: pair e %.5f, wall e %.5f (expected 0.8)" % (e_pair, e_wall))
chk.check(abs(e_pair / 0.8 - 1) < TOL and abs(e_wall / 0.8 - 1) < TOL,
          "scene: both collisions rebound with e = 0.8 within %.2g" % TOL)

# ------------------------------------------------------------------ 3. two ranks
if args.get("mpirun"):
    for newton in ("off", "on"):
        wd = lc.workdir("wb_np2_" + newton)
        outs = []
        for np_ in (1, 2):
            text = (HEAD.format(newton=newton, processors="processors 2 1 1" if np_ == 2 else "") + scene_atoms() + "\n" +
                    INTER + TAIL_SETTINGS.format(dt=DT) + "run %d\n" % (N1 + N2) + REPORT)
            _, out = lc.run(args["tdem"], text, wd, "in.np%d" % np_, np_=np_, mpirun=args["mpirun"])
            outs.append(results(out))
        w = worst(outs[0], outs[1])
        print("newton %s: -np 2 vs -np 1 max rel diff %.3g (atom 2 x %.4f, atom 3 x %.4f at the end)"
              % (newton, w, outs[1][4], outs[1][8]))
        chk.check(w <= 1e-10, "newton %s: -np 2 equals -np 1 (max rel diff %.3g)" % (newton, w))
chk.done()
