# SPDX-License-Identifier: GPL-2.0-or-later
"""fix tdem/integrate (src/integrators/liggghts) in tdem-liggghts.

Parts (--part, all by default):

nve     `scheme velocity_verlet` against the stock `fix nve/sphere` in the same executable: a bed of
        300 spheres (two types) falling onto a floor inside four side walls, gravity, pair gran
        tdem/lsd + tdem/cundall_strack (tangential history), wall/gran with the same model, 2000
        steps. The spheres are inserted in a first `run 1` without any integrator, so both runs
        start from the same state and no atom appears during the compared run. With radii,
        masses and time step that are powers of two (products scale without rounding): the
        maximum difference of x, v, omega, relative to the largest magnitude of that quantity, is
        <= 1e-10 at steps 500 ... 2000 (measured: bitwise equal), and the tdem run prints no
        warning that the nve/sphere run does not print (nothing looks for a fix nve/sphere).
        With generic values the two differ by one rounding per step (dt/2 * (f/m) vs
        (dt/2/m) * f), which the bed amplifies: asserted <= 1e-12 at step 500, growth reported.

restart History through MPI migration and restart, for ab4, gear5, beeman, abm4, gear6 and
        velocity_verlet_sync: five rows of two spheres on a floor (wall/gran, friction, gravity;
        initial spin) collide head-on around x = 0, the boundary of the two sub-domains under
        `processors 2 1 1`. Reference: one uninterrupted `run 2000` on 1 rank. Compared:
        `run N1; write_restart` on 2 ranks, then `read_restart` (fix re-issued with the same ID)
        and `run 2000-N1` on 2 ranks, N1 in the middle of a pair contact. Asserted: spheres cross
        x = 0 (change rank) on the floor and during pair contacts; the restart is written during
        a pair contact; final x, v, omega equal the reference within 1e-10 relative to each
        quantity's largest magnitude. Tolerance: the two runs differ at most in summation order (a
        sphere has at most one pair contact, the wall and gravity), and in this non-chaotic
        few-body motion round-off stays near 1e-15 (measured: bitwise equal); a lost or re-started
        history changes the result by the start-up error of the scheme, which the negative
        control measures: the same restart with the fix under another ID (history not restored,
        every atom starts again) must differ by more than 1e2 times the tolerance. Also: `run 777;
        run 1223` equals `run 2000`; a new time step and a restart file of another scheme restart
        the histories with a warning.

harness Host vs the single-collision harness: a head-on sphere-wall impact (wall/gran tdem/lsd,
        parameters stiffness, absolute_damping on, no gravity), the sphere starting at gap G
        above the wall with -v0, for every scheme at 20 and 80 steps per contact; one process per
        time step, one sphere (and its own fix tdem/integrate) per scheme. The restitution
        e = v_after / v0 read at the end (contact over, >= 10 free-flight steps) must equal
        `tdem-collide --law lsd --k K --gamma G --m1 M --R1 R --wall --v0 V --scheme NAME --dt DT
        --gap GAP` (key "e") within 1e-9.

bad     Unknown scheme, missing scheme, scheme without value, bad rotation value, unknown keyword,
        atom style without radius/omega: LIGGGHTS error (exit status 1) naming the keyword, the
        value and what is allowed.

insert  Atoms inserted during a run (fix insert/pack every 100 steps, lost atoms' slots and IDs
        re-used) in free fall: every scheme exact for constant acceleration gives the parabola
        from the inserted state to 1e-12 of the box.
"""
import json
import math
import os
import re
import subprocess

import numpy as np

import scenes as S
import tdem_lig as T

SCHEMES = ["euler", "symplectic_euler", "taylor2", "taylor3", "leapfrog", "position_verlet",
           "velocity_verlet", "velocity_verlet_sync", "beeman", "ab2", "ab3", "ab4", "ab5", "abm4",
           "gear4", "gear5", "gear6", "velocity_verlet_ab2"]
MODEL = "model tdem/lsd tangential tdem/cundall_strack"
HEAD = """
atom_style granular
atom_modify map array
boundary %s
newton off
communicate single vel yes
units si
%s
"""


def rel_by_scale(a, b):
    """max |a - b| / max(|a|, |b|) over a block of columns (one physical quantity)."""
    scale = max(np.abs(a).max(), np.abs(b).max(), 1e-300)
    return float(np.abs(a - b).max() / scale)


def compare_state(a, b, cols):
    out = {}
    for name, keys in (("x", ("x", "y", "z")), ("v", ("vx", "vy", "vz")),
                       ("omega", ("omegax", "omegay", "omegaz"))):
        idx = [cols.index(k) for k in keys]
        out[name] = rel_by_scale(a[:, idx], b[:, idx])
    return out


def warnings_of(text):
    return sorted(set(l.strip() for l in text.splitlines() if "WARNING" in l))


# ---------------------------------------------------------------- 1. velocity_verlet == nve/sphere
def bed_input(integrator, exact, steps=2000):
    """exact: radii 2^-8, 2^-9 m, masses 2^-10, 2^-13 kg and dt 2^-16 s, so that f/m, dt/2 and the
    inertia factor 1/0.4 (rounds to 2.5) scale without rounding and velocity Verlet and
    nve/sphere, which order the products differently (dt/2 * (f/m) vs (dt/2/m) * f), round
    identically; otherwise (r 2.5 and 2 mm, density, dt 2e-5 s) they differ by one rounding per
    step, which the bed amplifies about 100-fold per 500 steps."""
    walls = "\n".join(S.wall_line("w%d" % k, MODEL, "primitive type 1 " + w)
                      for k, w in enumerate(["xplane -0.03", "xplane 0.03", "yplane -0.03", "yplane 0.03",
                                             "zplane 0.0"]))
    if exact:
        r1, r2, dt = 2.0 ** -8, 2.0 ** -9, 2.0 ** -16
        masses = "set type 1 mass %r\nset type 2 mass %r\n" % (2.0 ** -10, 2.0 ** -13)
    else:
        r1, r2, dt, masses = 0.0025, 0.0020, 2e-5, ""
    return HEAD % ("m m m", "") + """
region box block -0.03 0.03 -0.03 0.03 0.0 0.06 units box
create_box 2 box
neighbor 0.001 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %r
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
%s
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant %r
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2000 radius constant %r
fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.026 0.026 -0.026 0.026 0.004 0.05 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel uniform 0.0 0.0 -0.5 0.3 0.3 0.3 omega constant 0 0 0 &
    region ins particles_in_region 300
thermo_style custom step atoms ke
thermo 500
thermo_modify lost ignore norm no
run 1
unfix ins
%s
fix integr all %s
dump d all custom 500 dump.bed id type mass x y z vx vy vz omegax omegay omegaz
dump_modify d sort id format "%%d %%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
run %d
""" % (S.STIFFNESS_PROPS, MODEL, dt, walls, r1, r2, masses, integrator, steps)


def part_nve(args, checks):
    for exact in (True, False):
        label = "nve (exactly scaling r, m, dt)" if exact else "nve (generic r, m, dt)"
        res = {}
        for tag, integ in (("nve", "nve/sphere"), ("tdem", "tdem/integrate scheme velocity_verlet")):
            d = T.workdir(args, "tdem_lig_integrate_nve_%s_%s" % ("exact" if exact else "generic", tag))
            r = T.run(args.tdem, bed_input(integ, exact), d, tag)
            res[tag] = (T.read_dump(os.path.join(d, "dump.bed")), r.stdout)
        fa, fb = res["nve"][0], res["tdem"][0]
        checks.check([s for s, _, _ in fa] == [s for s, _, _ in fb] and len(fa) >= 4,
                     "%s: both runs dump steps %s" % (label, [s for s, _, _ in fa]))
        per_step = []
        for (s, cols, a), (_, _, b) in zip(fa, fb):
            if a.shape != b.shape:
                checks.check(False, "%s: step %d atom count %d vs %d" % (label, s, len(a), len(b)))
                continue
            c = compare_state(a, b, cols)
            per_step.append((s, c, int(np.count_nonzero(a[:, 3:] != b[:, 3:])), a[:, 3:].size))
        s, cols, a = fa[-1]
        spin = float(np.abs(a[:, cols.index("omegax"):]).max())
        checks.check(len(a) == 300 and spin > 0,
                     "%s: 300 spheres, spinning at the end (max |omega| %.3g rad/s: tangential contacts act)"
                     % (label, spin))
        text = "; ".join("step %d: x %.1e v %.1e omega %.1e, %d/%d values differ bitwise"
                         % (st, c["x"], c["v"], c["omega"], nb, nt) for st, c, nb, nt in per_step)
        if exact:
            masses = set(np.unique(a[:, cols.index("mass")]).tolist())
            checks.check(masses == {2.0 ** -10, 2.0 ** -13}, "%s: masses %s" % (label, sorted(masses)))
            worst = max(max(c.values()) for _, c, _, _ in per_step)
            checks.check(worst <= 1e-10, "%s: velocity_verlet vs nve/sphere, max relative difference %.2e "
                         "(<= 1e-10): %s" % (label, worst, text))
            extra = [w for w in warnings_of(res["tdem"][1]) if w not in warnings_of(res["nve"][1])]
            checks.check(not extra, "%s: no warning beyond those of the nve/sphere run%s"
                         % (label, (": " + "; ".join(extra)) if extra else ""))
        else:
            first = max(per_step[0][1].values())
            checks.check(first <= 1e-12, "%s: one rounding apart per step, amplified by the bed: at step %d "
                         "%.2e (<= 1e-12); %s" % (label, per_step[0][0], first, text))


# ---------------------------------------------------------------- 2. MPI migration and restart
ROWS = [  # y, (x, vx, omega_y) of sphere A, (x, vx, omega_y) of sphere B
    (-0.02, (-0.028, 1.0, 20.0), (-0.004, 0.2, 0.0)),
    (-0.01, (-0.020, 1.2, 0.0), (0.002, -0.3, -30.0)),
    (0.0, (-0.0225, 1.5, 10.0), (0.0065, -0.5, 0.0)),
    (0.01, (-0.010, 0.8, 0.0), (-0.0001, 0.0, 0.0)),
    (0.02, (0.012, -0.7, 0.0), (0.0001, 0.0, 0.0)),
]
RAD = 0.004
MIG_PROPS = """
fix m_kn  all property/global kn peratomtypepair 1 10000
fix m_kt  all property/global kt peratomtypepair 1 3000
fix m_gn  all property/global gamman peratomtypepair 1 300
fix m_gt  all property/global gammat peratomtypepair 1 100
fix m_mu  all property/global coefficientFriction peratomtypepair 1 0.5
"""
MIG_DT = 2e-5
MIG_STEPS = 2000


def mig_input(scheme, steps, processors="", restart_in=None, restart_out=None, fix_id="integr", every=10):
    if restart_in:
        setup = "read_restart %s\nneighbor 0.0005 bin\nneigh_modify delay 0\n" % restart_in
    else:
        atoms = []
        sets = []
        k = 0
        for y, a, b in ROWS:
            for (x, vx, wy) in (a, b):
                k += 1
                atoms.append("create_atoms 1 single %r %r %r units box" % (x, y, RAD - 6.5e-7))  # ~ resting
                sets.append("set atom %d vx %r vy 0.0 vz 0.0 omegax 0.0 omegay %r omegaz 0.0" % (k, vx, wy))
        setup = """region box block -0.04 0.04 -0.03 0.03 0.0 0.03 units box
create_box 1 box
neighbor 0.0005 bin
neigh_modify delay 0
%s
set group all diameter %r density 2500
%s
""" % ("\n".join(atoms), 2 * RAD, "\n".join(sets))
    tail = "run %d\n" % steps
    if restart_out:
        tail += "write_restart %s\n" % restart_out
    return HEAD % ("f f f", processors) + setup + MIG_PROPS + """
pair_style gran %s
pair_coeff * *
timestep %r
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
%s
fix %s all tdem/integrate scheme %s
dump d all custom %d dump.mig id x y z vx vy vz omegax omegay omegaz fx fy fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
%s""" % (MODEL, MIG_DT, S.wall_line("wz", MODEL, "primitive type 1 zplane 0.0"), fix_id, scheme, every, tail)


def pair_overlaps(a, cols):
    """overlap of each row's pair, from a frame (atoms 2k-1, 2k form row k)."""
    ix, iy, iz = cols.index("x"), cols.index("y"), cols.index("z")
    out = []
    for k in range(len(ROWS)):
        p, q = a[2 * k], a[2 * k + 1]
        out.append(2 * RAD - math.sqrt((p[ix] - q[ix]) ** 2 + (p[iy] - q[iy]) ** 2 + (p[iz] - q[iz]) ** 2))
    return out


def part_restart(args, checks, schemes):
    tol = 1e-10
    for scheme in schemes:
        d = T.workdir(args, "tdem_lig_integrate_mig_" + scheme)
        subs = {}
        for sub in ("ref", "one", "two", "ctl"):
            subs[sub] = os.path.join(d, sub)
            os.makedirs(subs[sub])
        T.run(args.tdem, mig_input(scheme, MIG_STEPS, every=1), subs["ref"], "ref")
        ref = T.read_dump(os.path.join(subs["ref"], "dump.mig"))
        cols = ref[0][1]
        ix, iz = cols.index("x"), cols.index("z")
        # steps with a pair contact; atoms crossing x = 0 in contact with the floor (z < R) and
        # with the other sphere of their row
        contact_steps = [s for s, _, a in ref if max(pair_overlaps(a, cols)) > 0]
        cross_wall = cross_pair = 0
        for (s0, _, a0), (s1, _, a1) in zip(ref[:-1], ref[1:]):
            ov = pair_overlaps(a1, cols)
            for i in range(len(a1)):
                if a0[i, ix] * a1[i, ix] < 0:
                    if min(a0[i, iz], a1[i, iz]) < RAD:
                        cross_wall += 1
                    if ov[i // 2] > 0:
                        cross_pair += 1
        checks.check(cross_wall >= 3 and cross_pair >= 2,
                     "%s: spheres cross x = 0 (the rank boundary) %d times on the floor, %d times in a pair contact"
                     % (scheme, cross_wall, cross_pair))
        if not contact_steps:
            checks.check(False, "%s: no pair contact" % scheme)
            continue
        # restart in the middle of the longest run of contact steps after the first crossing
        n1 = contact_steps[len(contact_steps) // 2]
        mid = [a for s, _, a in ref if s == n1][0]
        T.run(args.tdem, mig_input(scheme, n1, processors="processors 2 1 1", restart_out="r.restart"),
              subs["one"], "one", np_=2, mpirun=args.mpirun)
        checks.check(max(pair_overlaps(mid, cols)) > 0,
                     "%s: restart written at step %d during a pair contact (overlap %.3e m)"
                     % (scheme, n1, max(pair_overlaps(mid, cols))))
        r2 = T.run(args.tdem, mig_input(scheme, MIG_STEPS - n1, processors="processors 2 1 1",
                                        restart_in="../one/r.restart", every=MIG_STEPS),
                   subs["two"], "two", np_=2, mpirun=args.mpirun)
        nloc = [l for l in r2.stdout.splitlines() if l.startswith("Nlocal:")]
        T.run(args.tdem, mig_input(scheme, MIG_STEPS - n1, restart_in="../one/r.restart", fix_id="other",
                                   every=MIG_STEPS), subs["ctl"], "ctl")
        a = ref[-1][2]
        b = T.read_dump(os.path.join(subs["two"], "dump.mig"))[-1]
        c = T.read_dump(os.path.join(subs["ctl"], "dump.mig"))[-1]
        ok = ref[-1][0] == b[0] == c[0] == MIG_STEPS and a.shape == b[2].shape == c[2].shape
        checks.check(ok, "%s: all runs end at step %d with %d atoms" % (scheme, MIG_STEPS, len(a)))
        if not ok:
            continue
        diff = compare_state(a, b[2], cols)
        ctl = compare_state(a, c[2], cols)
        checks.check(max(diff.values()) <= tol,
                     "%s: -np 2 with write/read_restart at step %d vs uninterrupted -np 1: x %.2e, v %.2e, "
                     "omega %.2e (<= %g)%s" % (scheme, n1, diff["x"], diff["v"], diff["omega"], tol,
                                               " [%s]" % nloc[-1] if nloc else ""))
        checks.check(max(ctl.values()) > 1e2 * tol,
                     "%s: control (history not restored, every atom started again at step %d) differs: "
                     "x %.2e, v %.2e, omega %.2e (> %g)" % (scheme, n1, ctl["x"], ctl["v"], ctl["omega"], 1e2 * tol))

    # `run N; run M` continues as one run; a new time step and a restart file of another scheme
    # re-start every atom, with a warning
    d = T.workdir(args, "tdem_lig_integrate_runs")
    for scheme in ("gear5", "ab4"):
        T.run(args.tdem, mig_input(scheme, MIG_STEPS, every=MIG_STEPS), d, "a")
        a = T.read_dump(os.path.join(d, "dump.mig"))[-1]
        T.run(args.tdem, mig_input(scheme, 777, every=MIG_STEPS) + "run %d\n" % (MIG_STEPS - 777), d, "b")
        b = T.read_dump(os.path.join(d, "dump.mig"))[-1]
        diff = compare_state(a[2], b[2], a[1])
        checks.check(a[0] == b[0] == MIG_STEPS and max(diff.values()) <= tol,
                     "%s: run 777; run %d equals run %d: x %.1e, v %.1e, omega %.1e (<= %g)"
                     % (scheme, MIG_STEPS - 777, MIG_STEPS, diff["x"], diff["v"], diff["omega"], tol))
    r = T.run(args.tdem, mig_input("ab4", 500, every=MIG_STEPS) + "timestep 1e-5\nrun 10\n", d, "c")
    w = warnings_of(r.stdout)
    checks.check(len(w) == 1 and "time step changed from 2e-05 to 1e-05" in w[0] and "started again" in w[0],
                 "a new time step restarts the histories with a warning: %s" % w)
    T.run(args.tdem, mig_input("ab4", 500, restart_out="r.restart"), d, "d")
    r = T.run(args.tdem, mig_input("gear5", 10, restart_in="r.restart"), d, "e")
    w = warnings_of(r.stdout)
    checks.check(any("history of scheme ab4" in x and "uses scheme gear5" in x and "started again" in x for x in w),
                 "read_restart with another scheme restarts the histories with a warning: %s" % w)


# ---------------------------------------------------------------- 3. host vs harness
HR = 0.005
HMASS = 1.25e-3
HK = 1.2e4
HGAMMA = 0.55
HV0 = 1.0


def part_harness(args, checks):
    if not args.collide:
        checks.check(False, "harness: --collide (tdem-collide) not given")
        return
    w0 = math.sqrt(HK / HMASS)
    delta = HGAMMA / (2 * HMASS)
    tc = math.pi / math.sqrt(w0 * w0 - delta * delta)
    worst = 0.0
    for spc in (20, 80):
        dt = tc / spc
        gap = HV0 * dt * 7.37   # touch between two steps, after 7 free-flight steps
        nsteps = int(gap / (HV0 * dt)) + 2 * spc + 30
        spacing = 0.02
        atoms = "\n".join("create_atoms 1 single %r 0.0 %r units box" % (k * spacing, HR + gap)
                          for k in range(len(SCHEMES)))
        groups = "\n".join("group g%d id %d\nfix i%d g%d tdem/integrate scheme %s" % (k, k + 1, k, k, s)
                           for k, s in enumerate(SCHEMES))
        text = HEAD % ("f f f", "") + """
region box block -0.01 %r -0.01 0.01 -0.001 0.05 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
fix m_kn all property/global kn peratomtypepair 1 %r
fix m_kt all property/global kt peratomtypepair 1 %r
fix m_gn all property/global gamman_abs peratomtypepair 1 %r
fix m_gt all property/global gammat_abs peratomtypepair 1 0.0
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran %s absolute_damping on
pair_coeff * *
timestep %r
%s
set group all diameter %r density 2500
set group all mass %r
set group all vz %r
%s
fix wz all wall/gran %s primitive type 1 zplane 0.0 absolute_damping on
dump d all custom %d dump.h id mass z vz fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
run %d
""" % (len(SCHEMES) * spacing, HK, 0.3 * HK, HGAMMA, MODEL, dt, atoms, 2 * HR, HMASS, -HV0, groups, MODEL,
            nsteps, nsteps)
        d = T.workdir(args, "tdem_lig_integrate_harness_%d" % spc)
        T.run(args.tdem, text, d, "h%d" % spc)
        frames = T.read_dump(os.path.join(d, "dump.h"))
        st, cols, a = frames[-1]
        checks.check(st == nsteps and len(a) == len(SCHEMES) and np.all(a[:, cols.index("mass")] == HMASS),
                     "harness %d steps/contact: %d spheres at step %d, mass %r" % (spc, len(a), st, HMASS))
        for k, scheme in enumerate(SCHEMES):
            z, vz, fz = a[k, cols.index("z")], a[k, cols.index("vz")], a[k, cols.index("fz")]
            ended = z > HR and fz == 0.0 and vz > 0
            e_host = vz / HV0
            cmd = [args.collide, "--law", "lsd", "--k", repr(HK), "--gamma", repr(HGAMMA), "--m1", repr(HMASS),
                   "--R1", repr(HR), "--wall", "--v0", repr(HV0), "--scheme", scheme, "--dt", repr(dt),
                   "--gap", repr(gap)]
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                checks.check(False, "harness: %s failed (%d): %s" % (" ".join(cmd), r.returncode,
                                                                      (r.stderr or r.stdout).strip()[:300]))
                continue
            e_ref = json.loads(r.stdout)["e"]
            de = abs(e_host - e_ref)
            worst = max(worst, de)
            checks.check(ended and de <= 1e-9, "harness %-20s %2d steps/contact: e host %.15f, tdem-collide %.15f, "
                         "|de| %.1e (<= 1e-9)%s" % (scheme, spc, e_host, e_ref, de, "" if ended else " CONTACT NOT OVER"))
    print("harness: largest |de| %.2e" % worst)


# ---------------------------------------------------------------- 5. atoms inserted during a run
EXACT_CONST = ["taylor2", "taylor3", "position_verlet", "velocity_verlet_sync", "beeman", "ab4", "ab5", "abm4",
               "gear5", "gear6"]
INS_DT = 1e-4
PRIMES = [1000003, 1000033, 1000037, 1000039, 1000081, 1000099, 1000117, 1000121, 1000133, 1000151]  # insertion seeds: primes > 10000, all different
INS_G = 9.81


def insert_input(schemes, steps):
    lines = []
    for k, sch in enumerate(schemes):
        x0 = -0.09 + 0.02 * k
        lines.append("region r%d block %r %r -0.008 0.008 0.089 0.095 units box" % (k, x0 - 0.008, x0 + 0.008))
        lines.append("group g%d region r%d" % (k, k))   # empty now; fix insert adds its atoms to it
        lines.append("fix ins%d g%d insert/pack seed %d distributiontemplate pdd1 maxattempt 100 insert_every 100 "
                     "overlapcheck yes all_in yes vel constant 0.01 0.0 -1.0 omega constant 0 0 0 "
                     "region r%d particles_in_region 3" % (k, k, PRIMES[k], k))
        lines.append("fix i%d g%d tdem/integrate scheme %s" % (k, k, sch))
    return HEAD % ("f f f", "") + """
region box block -0.1 %r -0.01 0.01 0.0 0.1 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
fix m_kn  all property/global kn peratomtypepair 1 1000
fix m_kt  all property/global kt peratomtypepair 1 300
fix m_gn  all property/global gamman peratomtypepair 1 30
fix m_gt  all property/global gammat peratomtypepair 1 10
fix m_mu  all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran %s
pair_coeff * *
timestep %r
fix gravi all gravity %r vector 0.0 0.0 -1.0
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002
fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0
%s
thermo_style custom step atoms
thermo 500
thermo_modify lost ignore norm no
dump d all custom 1 dump.ins id x y z vx vy vz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
run %d
""" % (-0.09 + 0.02 * len(schemes), MODEL, INS_DT, INS_G, "\n".join(lines), steps)


def part_insert(args, checks):
    """Batches of 3 spheres inserted every 100 steps (the previous batch has left the thin insertion
    region by then and falls faster, so no two spheres touch) fall freely out of the box (boundary f: they are lost, so
    later insertions reuse their slots; a reused row must not carry the old history). Every
    scheme exact for constant acceleration must then give x0 + v0 t - g t^2 / 2 for every atom,
    from the state it was inserted with (its first dump frame: the step it appears in does not
    move it)."""
    steps = 2000
    d = T.workdir(args, "tdem_lig_integrate_insert")
    r = T.run(args.tdem, insert_input(EXACT_CONST, steps), d, "ins")
    frames = T.read_dump(os.path.join(d, "dump.ins"))
    first = {}
    err = {}
    natoms = [len(a) for _, _, a in frames]
    cols = frames[0][1]
    ix, iz, ivx, ivz = cols.index("x"), cols.index("z"), cols.index("vx"), cols.index("vz")
    last = {}
    ninserted = 0
    for st, _, a in frames:
        for row in a:
            i = int(row[0])
            new = i not in first or last[i] != st - 1   # LIGGGHTS re-uses the IDs of lost atoms
            last[i] = st
            if new:
                first[i] = (st, row.copy())
                ninserted += 1
                continue
            s0, r0 = first[i]
            t = (st - s0) * INS_DT
            zx = r0[iz] + r0[ivz] * t - 0.5 * INS_G * t * t
            xx = r0[ix] + r0[ivx] * t
            k = int((r0[ix] + 0.1) / 0.02)
            err[k] = max(err.get(k, 0.0), abs(row[iz] - zx) / 0.1, abs(row[ix] - xx) / 0.1)
    lost = max(natoms) - natoms[-1]
    checks.check(ninserted >= 3 * len(EXACT_CONST) * 15 and lost > 0,
                 "insert: %d atoms inserted over %d steps in %d groups, %d lost through the floor (slots and IDs "
                 "reused)" % (ninserted, steps, len(EXACT_CONST), lost))
    for k, sch in enumerate(EXACT_CONST):
        checks.check(err.get(k, 1.0) <= 1e-12, "insert %-20s: free fall of atoms inserted during the run, "
                     "max position error / box %.1e (<= 1e-12)" % (sch, err.get(k, float("nan"))))
    checks.check(not warnings_of(r.stdout), "insert: no warnings %s" % warnings_of(r.stdout))


# ---------------------------------------------------------------- 4. bad input
def bad_input(fix_args, style="granular"):
    return """
atom_style %s
atom_modify map array
boundary f f f
units si
region box block -0.05 0.05 -0.05 0.05 0 0.05 units box
create_box 1 box
create_atoms 1 single 0 0 0.01 units box
fix i all %s
run 1
""" % (style, fix_args)


BAD = [
    ("unknown scheme", "tdem/integrate scheme rk4", "granular",
     [r"tdem/integrate", r"keyword 'scheme'", r"'rk4'", r"allowed values: euler \| symplectic_euler .*\| gear6"]),
    ("missing scheme", "tdem/integrate", "granular",
     [r"tdem/integrate", r"'scheme' is missing", r"allowed values of scheme: euler .*gear6"]),
    ("missing scheme with rotation", "tdem/integrate rotation no", "granular",
     [r"'scheme' is missing", r"euler .*gear6"]),
    ("scheme without value", "tdem/integrate scheme", "granular", [r"'scheme' needs a value", r"gear6"]),
    ("rotation value", "tdem/integrate scheme ab4 rotation maybe", "granular",
     [r"keyword 'rotation'", r"'maybe'", r"allowed values: yes \| no"]),
    ("unknown keyword", "tdem/integrate scheme ab4 order 4", "granular",
     [r"unknown keyword 'order'", r"scheme NAME, rotation yes\|no"]),
    ("atom style without radius", "tdem/integrate scheme ab4", "atomic",
     [r"tdem/integrate", r"radius, rmass, omega and torque", r"'atomic'"]),
]


def part_bad(args, checks):
    d = T.workdir(args, "tdem_lig_integrate_bad")
    for i, (name, fix_args, style, patterns) in enumerate(BAD):
        r = T.run(args.tdem, bad_input(fix_args, style), d, "bad%d" % i, check=False, timeout=60)
        out = r.stdout + r.stderr
        err = [l for l in out.splitlines() if "ERROR" in l]
        line = err[0] if err else ""
        missing = [p for p in patterns if not re.search(p, line)]
        checks.check(r.returncode > 0 and bool(err) and not missing,
                     "bad input, %s: exit status %d, message %r%s"
                     % (name, r.returncode, line, (" lacks " + ", ".join(missing)) if missing else ""))


def main():
    args = T.parse_args(lambda p: (p.add_argument("--collide", default=None, help="tdem-collide executable"),
                                   p.add_argument("--part", default="nve,restart,harness,bad,insert"),
                                   p.add_argument("--schemes", default="ab4,gear5,beeman,abm4,gear6,velocity_verlet_sync")))
    checks = T.Checks()
    parts = args.part.split(",")
    if "bad" in parts:
        part_bad(args, checks)
    if "nve" in parts:
        part_nve(args, checks)
    if "restart" in parts:
        part_restart(args, checks, args.schemes.split(","))
    if "harness" in parts:
        part_harness(args, checks)
    if "insert" in parts:
        part_insert(args, checks)
    checks.done()


if __name__ == "__main__":
    main()
