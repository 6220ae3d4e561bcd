#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Robustness of the tdem LIGGGHTS models (issue 17): regressions of the defects a bad-input and
fault sweep found.

--part absent_types
    `create_box 2` with every per-type-pair table given for 2 types, but only type-1 atoms and a
    type-1 wall so far. LIGGGHTS fills its property tables only for the types present
    (Properties::max_type), and the tdem models read rows 1..ntypes of them: SIGSEGV, or
    uninitialised values ("contactTime 4.6485e-310"). For every normal law and setting (with
    cundall_strack) and every tdem tangential law (with hertz), the scene must run and give
    bitwise the dump of the same scene built with `create_box 1` and 1-type tables; then type-2
    atoms are created and a second run must run with them (new init, new tables).
--part zero_distance
    Two atoms with the same centre, and a centre on the wall plane: an ERROR naming the atom IDs
    (the normal is undefined; stock LIGGGHTS gives NaN and exit 0), for every normal law.
--part settings_end
    A model keyword given last without its value (`... limitForce`): LIGGGHTS hands a setting no
    argument count, so it read a stale pointer ("value 'rce' is not allowed"). The error must say
    that the value is missing, for every tdem on/off and word keyword, in pair_style and wall/gran.
--part vanish
    A step 2.5 x the contact time, or `kn 1e300`, made every atom leave the box; LIGGGHTS drops
    lost atoms silently and the run exited 0. fix tdem/timestep (default check warn) must stop
    with an ERROR naming the lost atoms and the unstable step; within the advice, atoms leaving
    through the box only give a warning.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import law_props as LP  # noqa: E402
import tdem_lig as T  # noqa: E402

args = T.parse_args(lambda p: p.add_argument("--part", required=True,
                                             choices=["absent_types", "zero_distance", "settings_end",
                                                                      "vanish"]))
chk = T.Checks()

R, RHO = 0.0025, 2500.0
COLS = "id type x y z vx vy vz omegax omegay omegaz fx fy fz".split()

PAIR = LP.PAIR


def props(ntypes):
    """Every property for ntypes types; the entries other than type pair 1-1 (type 1) differ, so
    that a row read for the wrong types changes the result."""
    return LP.lines(ntypes,
                    lambda k, v, i, j: v if (i, j) == (0, 0) else v * (0.9 if k != "coefficientRestitution" else 0.95),
                    lambda k, v, t: v * (1.0 if t == 0 else 1.1))


# (name, models, settings): every normal law and setting with cundall_strack, and every tdem
# tangential law with tdem/hertz.
CS = "tangential tdem/cundall_strack"
LAWS = [
    ("lsd_stiffness", "model tdem/lsd " + CS, "parameters stiffness"),
    ("lsd_stiffness_absolute", "model tdem/lsd " + CS, "parameters stiffness absolute_damping on"),
    ("lsd_restitution", "model tdem/lsd " + CS, "parameters restitution"),
    ("lsd_restitution_limitforce", "model tdem/lsd " + CS, "parameters restitution limitForce on"),
    ("lsd_material", "model tdem/lsd " + CS, "parameters material"),
    ("hertz_linear", "model tdem/hertz " + CS, "damping linear"),
    ("hertz_kuwabara_kono", "model tdem/hertz " + CS, "damping kuwabara_kono"),
    ("hertz_tsuji", "model tdem/hertz " + CS, "damping tsuji"),
    ("hertz_general", "model tdem/hertz " + CS, "damping general"),
    ("walton_braun", "model tdem/walton_braun " + CS, ""),
    ("thornton", "model tdem/thornton " + CS, ""),
    ("power_law", "model tdem/power_law " + CS, ""),
    ("continuous_potential", "model tdem/continuous_potential " + CS, "limitForce off"),
    ("extended_linear", "model tdem/extended_linear " + CS, "restitutionFit rational contactTimeFit power"),
    ("extended_hertz", "model tdem/extended_hertz " + CS, "restitutionFit constant"),
]
for tl in ("haff_werner", "linear_spring", "walton_braun", "mindlin_deresiewicz", "mindlin_no_slip", "di_renzo"):
    LAWS.append(("hertz+" + tl, "model tdem/hertz tangential tdem/" + tl, "damping tsuji"))


def scene(models, settings, ntypes, later=""):
    """A sphere thrown at the wall (type-1 primitive zplane) and two spheres in an oblique
    collision, all of type 1; `later`: lines after the first run."""
    return """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.05 units box
create_box %d box
neighbor 0.001 bin
neigh_modify delay 0
%s
pair_style gran %s %s
pair_coeff * *
timestep 1e-6
create_atoms 1 single 0 0 %r units box
create_atoms 1 single 0.02 0 0.02 units box
create_atoms 1 single %r 0.001 0.02 units box
set group all diameter %r density %r
set atom 1 vx 0.2 vy 0 vz -0.5
set atom 2 vx 0.5 vy 0 vz 0
set atom 3 vx -0.5 vy 0 vz 0
fix w all wall/gran %s primitive type 1 zplane 0.0 %s
fix integr all nve/sphere
dump d all custom 400 dump.rob %s
dump_modify d sort id format "%%d %%d%s"
thermo 400
run 2000
%s""" % (ntypes, props(ntypes), models, settings, R + 0.0004, 0.02 + 2 * R + 0.0004, 2 * R, RHO,
         models, settings, " ".join(COLS), " %.17g" * (len(COLS) - 2), later)


def part_absent_types():
    later = """create_atoms 2 single -0.02 0.02 0.01 units box
set atom 4 diameter %r density %r vz -0.5
run 2000
""" % (2 * R, RHO)
    for name, models, settings in LAWS:
        runs = {}
        for ntypes in (1, 2):
            wd = T.workdir(args, "rob_absent_%s_%d" % (name.replace("+", "_"), ntypes))
            r = T.run(args.tdem, scene(models, settings, ntypes, later if ntypes == 2 else ""), wd, "rob",
                      check=False, timeout=300)
            frames = T.read_dump(os.path.join(wd, "dump.rob")) if os.path.exists(os.path.join(wd, "dump.rob")) else []
            err = [l for l in (r.stdout + r.stderr).splitlines() if "ERROR" in l or "Signal" in l]
            runs[ntypes] = (r.returncode, frames, err)
        rc1, f1, e1 = runs[1]
        rc2, f2, e2 = runs[2]
        first = [f for f in f2 if f[0] <= 2000]
        same = (rc1 == 0 and len(f1) == 6 and len(first) >= 6 and
                all(a[0] == b[0] and (a[2] == b[2]).all() for a, b in zip(f1, first[:6])))
        chk.check(rc1 == 0 and rc2 == 0 and same,
                  "%s: create_box 2 with only type 1 present runs (rc %d) and equals create_box 1 bitwise "
                  "over %d frames%s" % (name, rc2, len(f1), "" if rc2 == 0 else ": " + "; ".join(e2)[:300]))
        last = f2[-1] if f2 else None
        ok = (rc2 == 0 and last is not None and last[0] == 4000 and last[2].shape[0] == 4 and
              all(map(lambda v: v == v and abs(v) < 1e3, last[2].ravel())))
        chk.check(ok, "%s: after create_atoms 2 the second run uses the type-2 rows (4 atoms, finite)" % name)


def part_zero_distance():
    for name, models, settings in LAWS[:15]:
        for what in ("pair", "wall"):
            if what == "pair":
                atoms = "create_atoms 1 single 0 0 0.02 units box\ncreate_atoms 1 single 0 0 0.02 units box\n"
                expect = r"model tdem/[a-z_]+: atoms 1 and 2 have coincident centres \(distance 0\) at step 0"
            else:
                atoms = "create_atoms 1 single 0.01 0 0.0 units box\n"
                expect = r"model tdem/[a-z_]+: atom 1 has its centre on a wall surface \(distance 0\) at step 0"
            text = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 -0.01 0.05 units box
create_box 1 box
neighbor 0.001 bin
%s
pair_style gran %s %s
pair_coeff * *
timestep 1e-6
%sset group all diameter %r density %r
fix w all wall/gran %s primitive type 1 zplane 0.0 %s
fix integr all nve/sphere
run 10
""" % (props(1), models, settings, atoms, 2 * R, RHO, models, settings)
            wd = T.workdir(args, "rob_zero_%s_%s" % (name, what))
            r = T.run(args.tdem, text, wd, "rob", check=False, timeout=120)
            out = r.stdout + r.stderr
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            chk.check(0 < r.returncode < 128 and err and re.search(expect, err[0]) and "nan" not in out.lower(),
                      "%s %s at distance 0: %s" % (name, what, err[0][:200] if err else "rc %d, no error" % r.returncode))


def part_settings_end():
    # (models, the keyword given last without its value, allowed values named in the message)
    cases = [
        ("model tdem/lsd " + CS, "parameters restitution limitForce", "limitForce", "off | on"),
        ("model tdem/lsd " + CS, "parameters", "parameters", "stiffness | restitution | material"),
        ("model tdem/lsd " + CS, "parameters restitution tangential_damping", "tangential_damping", "off | on"),
        ("model tdem/lsd " + CS, "parameters stiffness absolute_damping", "absolute_damping", "off | on"),
        ("model tdem/hertz " + CS, "damping", "damping", "linear | kuwabara_kono | tsuji | general"),
        ("model tdem/hertz " + CS, "damping tsuji limitForce", "limitForce", "off | on"),
        ("model tdem/extended_linear " + CS, "restitutionFit constant contactTimeFit", "contactTimeFit",
         "constant | power"),
        ("model tdem/extended_hertz " + CS, "restitutionFit", "restitutionFit", "constant | rational | power"),
        ("model tdem/continuous_potential " + CS, "limitForce", "limitForce", "off | on"),
        ("model tdem/lsd tangential tdem/cundall_strack", "parameters restitution slip_rule", "slip_rule",
         "spring | spring_dashpot"),
        ("model tdem/hertz tangential tdem/linear_spring", "damping tsuji slipReset", "slipReset",
         "spring_only | spring_and_dashpot"),
        ("model tdem/hertz tangential tdem/mindlin_deresiewicz", "damping tsuji frictionLimit", "frictionLimit",
         "absolute | positive_normal"),
    ]
    # a long earlier command leaves stale pointers behind the argument list of the short one
    filler = "variable long_line string \"%s\"" % " ".join("word%d" % k for k in range(40))
    for models, settings, key, allowed in cases:
        for where in ("pair", "wall"):
            if where == "pair":
                inter = "pair_style gran %s %s\npair_coeff * *\n" % (models, settings)
            else:
                good = re.sub(r"\b%s$" % key, "", settings).strip()
                inter = ("pair_style gran %s %s\npair_coeff * *\n%s\n"
                         "fix w all wall/gran %s primitive type 1 zplane 0.0 %s\n" % (models, good, filler, models,
                                                                                     settings))
            text = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.05 units box
create_box 1 box
%s
%s
%stimestep 1e-6
run 0
""" % (props(1), filler, inter)
            wd = T.workdir(args, "rob_end_%s_%s" % (key, where))
            r = T.run(args.tdem, text, wd, "rob", check=False, timeout=120)
            out = r.stdout + r.stderr
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            want = "keyword '%s' needs a value; allowed: %s" % (key, allowed)
            chk.check(0 < r.returncode < 128 and err and want in err[0],
                      "%s: '%s' last without a value (%s): %s" % (models.split()[1], key, where,
                                                                  err[0][:200] if err else "rc %d" % r.returncode))


def part_vanish():
    def text(settings, dt, extra_props="", vz=0.0):
        return """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.05 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
%s
%s
pair_style gran model tdem/lsd %s %s
pair_coeff * *
timestep %r
create_atoms 1 single 0 0 0.01 units box
create_atoms 1 single 0 0 0.0152 units box
create_atoms 1 single 0.01 0 0.01 units box
set group all diameter 0.005 density 2500
set atom 3 vz %r
set atom 1 vz -0.5
fix w all wall/gran model tdem/lsd %s primitive type 1 zplane 0.0 %s
fix g all gravity 9.81 vector 0 0 -1
fix integr all nve/sphere
fix ts all tdem/timestep
thermo 100
run 2000
""" % (props(1) if not extra_props else props(1).replace("kn peratomtypepair 1 10000.0", extra_props), "",
       CS, settings, dt, vz, CS, settings)
    tc = PAIR["contactTime"]
    for name, settings, dt, extra in (
            ("dt = 2.5 t_c", "parameters restitution", 2.5 * tc, ""),
            ("kn 1e300", "parameters stiffness", 1e-5,
             "kn peratomtypepair 1 1e300")):
        wd = T.workdir(args, "rob_vanish_%s" % name.split()[0])
        r = T.run(args.tdem, text(settings, dt, extra), wd, "rob", check=False, timeout=120)
        out = r.stdout + r.stderr
        err = [l for l in out.splitlines() if l.startswith("ERROR")]
        ok = (0 < r.returncode < 128 and err and re.search(r"fix ts tdem/timestep: \d+ of 3 atoms of the group were lost "
                                                           r"by step \d+", err[0])
              and "the time step is unstable" in err[0] and "x the critical step" in err[0])
        chk.check(ok, "%s: %s" % (name, err[0][:260] if err else "rc %d, no error" % r.returncode))
    # within the advice: an atom thrown out of the box is a warning, the run goes on
    wd = T.workdir(args, "rob_vanish_ok")
    r = T.run(args.tdem, text("parameters restitution", tc / 50, vz=30.0), wd, "rob", check=False, timeout=120)
    out = r.stdout + r.stderr
    warn = [l for l in out.splitlines() if l.startswith("WARNING") and "were lost" in l]
    chk.check(r.returncode == 0 and warn and "within the advice" in warn[0],
              "dt = t_c/50, one atom thrown out of the box: rc %d, %s" % (r.returncode, warn[0][:200] if warn else "no warning"))


{"absent_types": part_absent_types, "zero_distance": part_zero_distance, "settings_end": part_settings_end,
 "vanish": part_vanish}[args.part]()
chk.done()
