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


def restart_case(args, checks, name, model, reissue, n1=3000, n2=2000):
    d = T.workdir(args, "tdem_lig_restart_" + name)
    for sub in ("one", "two"):
        os.makedirs(os.path.join(d, sub))
    T.run(args.tdem, S.settling(model, REST_PROPS, steps=n1, dump_every=1000,
                                extra_end="write_restart r.restart\nrun %d\n" % n2),
          os.path.join(d, "one"), "one")
    T.run(args.tdem, S.settling(model, REST_PROPS, steps=n2, dump_every=1000,
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


def main():
    args = T.parse_args(lambda p: p.add_argument("--steps", type=int, default=8000))
    checks = T.Checks()

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
