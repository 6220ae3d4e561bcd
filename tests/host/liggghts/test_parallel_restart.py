# SPDX-License-Identifier: GPL-2.0-or-later
"""tdem-liggghts with `model tdem/lsd tangential tdem/cundall_strack` in the settling scene:

restart parity -- `run N; write_restart; run M` in one process equals `read_restart; run M`
  bitwise (positions, velocities, angular velocities), (a) without re-issuing pair_style after
  read_restart (the model is found again from the hash in the restart file; default settings)
  and (b) with `parameters restitution limitForce on`, which after read_restart has to be given
  again (LIGGGHTS restart files keep the model hash, not the model settings). (A single `run N+M` is not the reference:
  every `run` rebuilds neighbour lists, which changes the summation order; that is LIGGGHTS
  behaviour, the same with stock models.)

-np 2 vs -np 1 -- both start from the same restart file written right after insertion (with
  insert/pack the inserted positions depend on the decomposition). The two runs differ only in
  the order in which contact forces are summed (ghost atoms, neighbour order), i.e. by
  round-off, which a dense granular bed amplifies exponentially. Hence:
   * both ranks own atoms (the test really decomposes) and no atom is lost;
   * early on (step 1000, before the bed forms) the kinetic energies agree to 1e-9 relative;
   * at the end only statistics are compared: mean height of the bed within 2 %, kinetic energy
     averaged over the thermo outputs within 5 %, final kinetic energy within 30 % (in a nearly
     settled bed it is carried by a few rattling spheres; measured differences: 0.6 %, 0.15 %, 1.5 %).

New laws (tdem/power_law, tdem/extended_linear, tdem/extended_hertz; per-contact history xi_max |
  v0, k, gamma | v0, alpha), each in a smaller bed (800 spheres) and in a head-on collision:
   * bed restart parity as above (bitwise to 1e-12, pair_style re-issued with the settings);
   * bed -np 2 vs -np 1 from the same restart file: every thermo output up to step 1000 to 1e-9
     (contacts cross the processor boundary by then; a lost or un-migrated history would differ
     at the 1e-3 level), the mean height at the end within 2 %;
   * head-on collision of two spheres plus one sphere on the floor (wall/gran history):
     `run N; write_restart; run M` vs `read_restart; run M`, with the restart written during
     both contacts (checked: overlaps > 0, unloading for the hysteretic law), final states equal
     to 1e-12; and the pair collision across the processor boundary (`processors 2 1 1`,
     contact point at x = 0) under -np 2 gives the rebound of -np 1 to 1e-10.

-np 2 equivalence -- stock `hooke/stiffness`+`history` under `liggghts` and `tdem/lsd`+
  `tdem/cundall_strack` under `tdem-liggghts`, both on 2 ranks (same decomposition, hence the
  same summation order): final state equal to 1e-8 relative (expected: bitwise).
"""
import os

import numpy as np

import scenes as S
import tdem_lig as T

MODEL = "model tdem/lsd tangential tdem/cundall_strack"
REST_PROPS = S.STIFFNESS_PROPS + """
fix m_e  all property/global coefficientRestitution peratomtypepair 2 0.6 0.65 0.65 0.7
fix m_tc all property/global contactTime peratomtypepair 2 4.0e-4 4.0e-4 4.0e-4 4.0e-4
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 2 0.3 0.3 0.3 0.3
"""


def last_frame(path):
    step, cols, a = T.read_dump(path)[-1]
    return step, cols, a


def restart_case(args, checks, name, model, reissue, n1=3000, n2=2000, props=REST_PROPS, natoms=2400):
    d = T.workdir(args, "tdem_lig_restart_" + name)
    for sub in ("one", "two"):
        os.makedirs(os.path.join(d, sub))
    T.run(args.tdem, S.settling(model, props, steps=n1, dump_every=1000, natoms=natoms,
                                extra_end="write_restart r.restart\nrun %d\n" % n2),
          os.path.join(d, "one"), "one")
    T.run(args.tdem, S.settling(model, props, steps=n2, dump_every=1000, natoms=natoms,
                                restart_read="../one/r.restart", reissue_pair=reissue),
          os.path.join(d, "two"), "two")
    sa, cols, a = last_frame(os.path.join(d, "one", "dump.settle"))
    sb, _, b = last_frame(os.path.join(d, "two", "dump.settle"))
    checks.check(sa == sb == n1 + n2 and a.shape == b.shape,
                 "restart %s: both end at step %d with %d atoms" % (name, n1 + n2, len(a)))
    if a.shape == b.shape:
        nbit = int(np.count_nonzero(a != b))
        rel = T.max_rel_diff(a[:, 2:], b[:, 2:])
        checks.check(rel <= 1e-12, "restart %s: max relative difference %.3e (<= 1e-12), %d values differ bitwise"
                     % (name, rel, nbit))


# ---------------------------------------------------------------- the three new laws
def pair2(name, a, b, c, d):
    return "fix m_%s all property/global %s peratomtypepair 2 %r %r %r %r\n" % (name, name, a, b, c, d)


COMMON2 = (pair2("tangentialStiffnessRatio", 0.3, 0.3, 0.3, 0.3) +
           pair2("coefficientFriction", 0.5, 0.45, 0.45, 0.4))
NEW_LAWS = [
    ("power_law", "model tdem/power_law tangential tdem/cundall_strack",
     pair2("loadingCoefficient", 2e5, 1.8e5, 1.8e5, 1.6e5) + pair2("loadingExponent", 1.5, 1.5, 1.5, 1.5) +
     pair2("unloadingCoefficient", 2e7, 1.8e7, 1.8e7, 1.6e7) +
     pair2("unloadingExponentIncrement", 0.5, 0.5, 0.5, 0.5) + COMMON2),
    ("extended_linear", "model tdem/extended_linear tangential tdem/cundall_strack restitutionFit rational "
                        "contactTimeFit power limitForce on",
     pair2("restitutionFitC0", 0.9, 0.85, 0.85, 0.8) + pair2("restitutionFitC1", 1.0, 1.0, 1.0, 1.0) +
     pair2("restitutionFitC2", 0.5, 0.5, 0.5, 0.5) + pair2("contactTimeFitC0", 5e-4, 5e-4, 5e-4, 5e-4) +
     pair2("contactTimeFitC1", 0.2, 0.2, 0.2, 0.2) +
     "fix m_vmax all property/global impactVelocityMax scalar 5.0\n" + COMMON2),
    ("extended_hertz", "model tdem/extended_hertz tangential tdem/cundall_strack restitutionFit power limitForce on",
     "fix m_E all property/global youngsModulus peratomtype 5.e6 6.e6\n"
     "fix m_nu all property/global poissonsRatio peratomtype 0.45 0.4\n" +
     pair2("restitutionFitC0", 0.05, 0.05, 0.05, 0.05) + pair2("restitutionFitC1", 0.15, 0.15, 0.15, 0.15) +
     "fix m_vmin all property/global impactVelocityMin scalar 0.01\n" + COMMON2),
]


def head_on(model, props, dt, processors="", tail="", restart=None):
    """Two spheres (type 1) meeting at x = 0 with 2 m/s and one sphere (type 2) falling onto the
    floor at 1 m/s, gravity off."""
    if restart:
        head = "read_restart %s\n" % restart
        atoms = ""
    else:
        head = ("region box block -0.03 0.03 -0.03 0.03 -0.001 0.04 units box\ncreate_box 2 box\n")
        atoms = """create_atoms 1 single -0.0052 0.0 0.02 units box
create_atoms 1 single 0.0052 0.0 0.02 units box
create_atoms 2 single 0.015 0.0 0.0052 units box
set group all diameter 0.01 density 2500
set atom 1 vx 1.0
set atom 2 vx -1.0
set atom 3 vz -1.0
"""
    words = model.split()
    return """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
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
dump d all custom 1 dump.h id x y z vx vy vz fx fy fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 100000
%s
""" % (processors, head, props, model, dt, atoms, " ".join(words[:4]), " ".join(words[4:]), tail)


def new_law_cases(args, checks, law, model, props):
    # bed restart parity, 800 spheres
    restart_case(args, checks, law, model, reissue=True, n1=2500, n2=1500, props=props, natoms=800)
    # bed -np 1 vs -np 2 from the same restart file
    d = T.workdir(args, "tdem_lig_np_" + law)
    os.makedirs(os.path.join(d, "init"))
    T.run(args.tdem, S.settling(model, props, steps=1, natoms=800, extra_end="write_restart init.restart\n"),
          os.path.join(d, "init"), "init")
    res = {}
    for npr in (1, 2):
        sub = os.path.join(d, "np%d" % npr)
        os.makedirs(sub)
        r = T.run(args.tdem, S.settling(model, props, steps=3000, thermo_every=100, natoms=800,
                                        processors="processors * * 1", restart_read="../init/init.restart"),
                  sub, "np%d" % npr, np_=npr, mpirun=args.mpirun)
        rows = [l.split() for l in T.thermo_blocks(r.stdout)[-1][1]]
        step, cols, a = last_frame(os.path.join(sub, "dump.settle"))
        res[npr] = dict(steps=[int(x[0]) for x in rows], ke=np.array([float(x[2]) for x in rows]),
                        meanz=float(a[:, cols.index("z")].mean()), n=len(a),
                        nlocal_min=float([l for l in r.stdout.splitlines() if l.startswith("Nlocal:")][-1].split()[-2]))
    r1, r2 = res[1], res[2]
    checks.check(r2["nlocal_min"] > 0 and r1["n"] == r2["n"] == 800,
                 "%s np 2: every rank owns atoms, 800 atoms at the end" % law)
    early = [i for i, st in enumerate(r1["steps"]) if 0 < st <= 1000]
    rel = max(abs(r1["ke"][i] / r2["ke"][i] - 1) for i in early)
    checks.check(r1["steps"] == r2["steps"] and rel < 1e-9,
                 "%s np 1 / np 2: kinetic energy at every output up to step 1000 agrees to %.2e (< 1e-9)" % (law, rel))
    dz = abs(r1["meanz"] / r2["meanz"] - 1)
    checks.check(dz < 0.02, "%s np 1 / np 2: mean height at step 3000 %.6f vs %.6f m, rel. %.2e (< 0.02)"
                 % (law, r1["meanz"], r2["meanz"], dz))

    # head-on collisions: restart in the middle of both contacts, and -np 2 across the boundary
    dt = 1e-7
    n1 = 4500 if law == "extended_linear" else 9000   # touch at step 2000; restart past the largest overlap
    n2 = 30000 - n1
    d1 = T.workdir(args, "tdem_lig_mid_one_" + law)
    T.run(args.tdem, head_on(model, props, dt, tail="run %d\nwrite_restart r.restart\nrun %d\n" % (n1, n2)), d1, "one")
    d2 = T.workdir(args, "tdem_lig_mid_two_" + law)
    T.run(args.tdem, head_on(model, props, dt, tail="run %d\n" % n2, restart="../%s/r.restart" % os.path.basename(d1)),
          d2, "two")
    fr1 = T.read_dump(os.path.join(d1, "dump.h"))
    mid = [a for st, _, a in fr1 if st == n1][0]
    c = {k: i for i, k in enumerate(fr1[0][1])}
    xi_pair = 0.01 - (mid[1, c["x"]] - mid[0, c["x"]])
    xi_wall = 0.005 - mid[2, c["z"]]
    xi_pair_max = max(0.01 - (a[1, c["x"]] - a[0, c["x"]]) for _, _, a in fr1)
    checks.check(xi_pair > 0 and xi_wall > 0 and mid[0, c["vx"]] < 0.999,
                 "%s: restart written during both contacts (pair overlap %.3e m, max %.3e; wall overlap %.3e m)"
                 % (law, xi_pair, xi_pair_max, xi_wall))
    checks.check(xi_pair < xi_pair_max and mid[0, c["vx"]] < 0,
                 "%s: restart written after the largest overlap of the pair contact" % law)
    a, b = fr1[-1], T.read_dump(os.path.join(d2, "dump.h"))[-1]
    rel = T.max_rel_diff(a[2][:, 1:], b[2][:, 1:])
    e_a = (a[2][1, c["vx"]] - a[2][0, c["vx"]]) / 2.0
    e_b = (b[2][1, c["vx"]] - b[2][0, c["vx"]]) / 2.0
    ew_a, ew_b = a[2][2, c["vz"]], b[2][2, c["vz"]]
    ended = not a[2][:, c["fx"]:].any() and a[2][1, c["x"]] - a[2][0, c["x"]] > 0.01
    checks.check(a[0] == b[0] == n1 + n2 and rel <= 1e-12 and 0 < e_a < 1 and 0 < ew_a < 1,
                 "%s restart mid-collision: step %d/%d, pair e = %.9f vs %.9f, wall e = %.9f vs %.9f, "
                 "max rel. diff %.2e (<= 1e-12)" % (law, a[0], b[0], e_a, e_b, ew_a, ew_b, rel))
    e_np = []
    for npr in (1, 2):
        dd = T.workdir(args, "tdem_lig_mid_np%d_%s" % (npr, law))
        T.run(args.tdem, head_on(model, props, dt, processors="processors 2 1 1" if npr == 2 else "",
                                 tail="run %d\n" % (n1 + n2)), dd, "np", np_=npr, mpirun=args.mpirun)
        z = T.read_dump(os.path.join(dd, "dump.h"))[-1][2]
        e_np.append(((z[1, c["vx"]] - z[0, c["vx"]]) / 2.0, z[2, c["vz"]]))
    dpair = abs(e_np[1][0] / e_np[0][0] - 1)
    dwall = abs(e_np[1][1] / e_np[0][1] - 1)
    checks.check(ended, "%s: both contacts over at the end (zero forces, the pair apart)" % law)
    checks.check(dpair < 1e-10 and dwall < 1e-10,
                 "%s -np 2 across the boundary: pair e = %.12f vs %.12f (-np 1), wall e rel. diff %.1e (< 1e-10)"
                 % (law, e_np[1][0], e_np[0][0], dwall))


def main():
    args = T.parse_args(lambda p: (p.add_argument("--steps", type=int, default=8000),
                                   p.add_argument("--only-new", default=None,
                                                  help="run only the new-law cases whose law contains this")))
    checks = T.Checks()

    for law, model, props in NEW_LAWS:
        if args.only_new and args.only_new not in law:
            continue
        new_law_cases(args, checks, law, model, props)
    if args.only_new:
        checks.done()
        return

    restart_case(args, checks, "default_settings", MODEL, reissue=False)
    restart_case(args, checks, "restitution_limitForce", MODEL + " parameters restitution limitForce on",
                 reissue=True)

    d = T.workdir(args, "tdem_lig_np")
    os.makedirs(os.path.join(d, "init"))
    T.run(args.tdem, S.settling(MODEL, S.STIFFNESS_PROPS, steps=1, extra_end="write_restart init.restart\n"),
          os.path.join(d, "init"), "init")
    res = {}
    for npr in (1, 2):
        sub = os.path.join(d, "np%d" % npr)
        os.makedirs(sub)
        r = T.run(args.tdem, S.settling(MODEL, S.STIFFNESS_PROPS, steps=args.steps, thermo_every=1000,
                                        processors="processors * * 1", restart_read="../init/init.restart"),
                  sub, "np%d" % npr, np_=npr, mpirun=args.mpirun)
        rows = [l.split() for l in T.thermo_blocks(r.stdout)[-1][1]]
        nlocal = [l for l in r.stdout.splitlines() if l.startswith("Nlocal:")][-1].split()
        step, cols, a = last_frame(os.path.join(sub, "dump.settle"))
        res[npr] = dict(steps=[int(x[0]) for x in rows], atoms=[int(x[1]) for x in rows],
                        ke=np.array([float(x[2]) for x in rows]), nlocal_min=float(nlocal[-2]),
                        meanz=float(a[:, cols.index("z")].mean()), n=len(a))
    r1, r2 = res[1], res[2]
    checks.check(r2["nlocal_min"] > 0, "np 2: every rank owns atoms (min Nlocal %g)" % r2["nlocal_min"])
    checks.check(r1["atoms"] == r2["atoms"] and set(r1["atoms"]) == {2400} and r1["n"] == r2["n"] == 2400,
                 "np 1 / np 2: 2400 atoms at every output")
    checks.check(r1["steps"] == r2["steps"], "np 1 / np 2: same thermo steps")
    ke_early = abs(r1["ke"][1] / r2["ke"][1] - 1)
    checks.check(ke_early < 1e-9, "np 1 / np 2: kinetic energy at step %d agrees to %.2e (< 1e-9)"
                 % (r1["steps"][1], ke_early))
    dz = abs(r1["meanz"] / r2["meanz"] - 1)
    checks.check(dz < 0.02, "np 1 / np 2: mean height %.6f vs %.6f m, rel. %.2e (< 0.02)" % (r1["meanz"], r2["meanz"], dz))
    kavg = abs(r1["ke"][1:].mean() / r2["ke"][1:].mean() - 1)
    checks.check(kavg < 0.05, "np 1 / np 2: time-averaged kinetic energy rel. difference %.2e (< 0.05)" % kavg)
    kend = abs(r1["ke"][-1] / r2["ke"][-1] - 1)
    checks.check(kend < 0.3, "np 1 / np 2: final kinetic energy %.4e vs %.4e J, rel. %.2e (< 0.3)"
                 % (r1["ke"][-1], r2["ke"][-1], kend))

    # -np 2, stock against tdem: same decomposition, same summation order, so the stock
    # equivalence must hold bitwise in parallel too (ghost pairs, history sign flips, migration)
    ends = {}
    for tag, exe, model in (("stock", args.stock, "model hooke/stiffness tangential history limitForce on"),
                            ("tdem", args.tdem, MODEL + " limitForce on")):
        sub = os.path.join(d, "np2_" + tag)
        os.makedirs(sub)
        T.run(exe, S.settling(model, S.STIFFNESS_PROPS, steps=args.steps, processors="processors * * 1"),
              sub, "np2_" + tag, np_=2, mpirun=args.mpirun)
        ends[tag] = last_frame(os.path.join(sub, "dump.settle"))
    (sa, cols, a), (sb, _, b) = ends["stock"], ends["tdem"]
    ok = sa == sb == args.steps and a.shape == b.shape == (2400, len(cols))
    checks.check(ok, "np 2 stock vs tdem: both end at step %d with 2400 atoms" % args.steps)
    if ok:
        rel = T.max_rel_diff(a[:, 2:], b[:, 2:])
        checks.check(rel <= 1e-8, "np 2 stock hooke/stiffness+history vs tdem/lsd+tdem/cundall_strack (limitForce on): "
                     "max relative difference %.3e (<= 1e-8), %d values differ bitwise" % (rel, int(np.count_nonzero(a != b))))
    checks.done()


if __name__ == "__main__":
    main()
