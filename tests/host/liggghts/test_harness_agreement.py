# SPDX-License-Identifier: GPL-2.0-or-later
"""Every tdem normal law in LIGGGHTS against the single-collision harness `tdem-collide`.

For each law (and its variants: end-of-contact convention, damping form, fit forms, parameter
sets) a head-on sphere-wall impact (fix wall/gran, primitive zplane) and a head-on sphere-sphere
impact (pair gran) are run in tdem-liggghts with gravity off, and the same collision is
integrated by tdem-collide (an independent RK4 integration with event location, never LIGGGHTS
output). Asserted: |e_host - e_harness| <= 1e-4 and |t_c,host - t_c,harness| / t_c,harness <= 1e-4.

Several impacts share one LIGGGHTS process: every parameter set is an atom type (type 1 is the
type of the walls and holds no particle; a type-pair property of (i, j) is the value of the set
of type max(i, j), so the wall contact of type k uses set k), impacts are placed far apart, and
the time step is the shortest harness contact time of the process divided by STEPS_PER_CONTACT.
Every touch falls half-way between two steps (the trapezoidal impulse of velocity Verlet is then
exact for a force that jumps at touch, e.g. a dashpot).

Host measurement (one dump line per particle and step): touch and, for the zero-overlap end, the
end of contact are the zero crossings of the overlap (linear interpolation); for the laws that end
at zero force (limitForce on, the hysteretic laws) the end is where the force reaches zero
(extrapolation of the last two positive forces), which is the harness's definition. e is the
rebound velocity after the contact over the impact velocity.
"""
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

import tdem_lig as T

R = 0.005
RHO = 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
STEPS_PER_CONTACT = 20000
TOL_E = 1e-4
TOL_TC = 1e-4
E_YOUNG, NU = 1.0e7, 0.3
HARNESS_STEPS = 20000

# ---------------------------------------------------------------- the cases
# A group is one LIGGGHTS process: the pair_style arguments, the end convention, and parameter
# sets. A set: name, type-pair properties {name: value}, the harness law options, and the impact
# velocities of the wall impacts (v0) and of the pair impacts (relative velocity).
MAT = {"youngsModulus": ("peratomtype", E_YOUNG), "poissonsRatio": ("peratomtype", NU)}
COMMON = {"tangentialStiffnessRatio": 0.3, "coefficientFriction": 0.5}
EMAT = ["--E", repr(E_YOUNG), "--nu", repr(NU)]


def mk(name, props, harness, wall_v=(1.0,), pair_v=(2.0,)):
    p = dict(COMMON)
    p.update(props)
    return dict(name=name, props=p, harness=harness, wall_v=wall_v, pair_v=pair_v)


def k_hertz(reff):
    return 4.0 / 3.0 * E_YOUNG / (2 * (1 - NU * NU)) * math.sqrt(reff)


def groups():
    g = []
    for limit in ("off", "on"):
        end = "zero_force" if limit == "on" else "zero_overlap"
        g.append(dict(name="lsd_limitForce_" + limit, end=end,
                      model="model tdem/lsd tangential tdem/cundall_strack parameters restitution limitForce " + limit,
                      sets=[mk("e0.6", {"coefficientRestitution": 0.6, "contactTime": 5e-4},
                               ["--law", "lsd", "--e", "0.6", "--tc", "5e-4", "--end", end]),
                            mk("e0.3", {"coefficientRestitution": 0.3, "contactTime": 3e-4},
                               ["--law", "lsd", "--e", "0.3", "--tc", "3e-4", "--end", end])]))
    kw = k_hertz(R)
    c_lin = 0.5 * math.sqrt(MASS * kw * math.sqrt(1e-4))
    c_kk = 0.3 * math.sqrt(MASS * kw) / 0.01 ** 0.25
    c_gen = 0.4 * math.sqrt(MASS * kw)
    for damping, props, hopts in (
            ("tsuji", {"coefficientRestitution": 0.6}, ["--damping", "tsuji", "--e", "0.6"]),
            ("linear", {"dampingCoefficient": c_lin}, ["--damping", "linear", "--gamma", repr(c_lin)]),
            ("kuwabara_kono", {"dampingCoefficient": c_kk}, ["--damping", "kuwabara_kono", "--gamma", repr(c_kk)]),
            ("general", {"dampingCoefficient": c_gen, "dampingExponent": 0.25},
             ["--damping", "general", "--gamma", repr(c_gen), "--theta", "0.25"])):
        for limit in ("off", "on"):
            end = "zero_force" if limit == "on" else "zero_overlap"
            p = dict(MAT)
            p.update(props)
            g.append(dict(name="hertz_%s_limitForce_%s" % (damping, limit), end=end,
                          model="model tdem/hertz tangential tdem/cundall_strack damping %s limitForce %s" % (damping, limit),
                          sets=[mk(damping, p, ["--law", "hertz"] + EMAT + hopts + ["--end", end])]))
    KL = 1.0e4
    g.append(dict(name="walton_braun", end="zero_force", model="model tdem/walton_braun tangential tdem/cundall_strack",
                  sets=[mk("constant_kul", {"loadingStiffness": KL, "unloadingStiffness": KL / 0.49,
                                            "unloadingStiffnessSlope": 0.0},
                           ["--law", "walton_braun", "--kl", repr(KL), "--kul", repr(KL / 0.49), "--s", "0"]),
                        mk("force_dependent_kul", {"loadingStiffness": KL, "unloadingStiffness": KL,
                                                   "unloadingStiffnessSlope": 1.0 / 3.6e-4},
                           ["--law", "walton_braun", "--kl", repr(KL), "--kul", repr(KL), "--s", repr(1.0 / 3.6e-4)])]))
    p = dict(MAT)
    p["yieldPressure"] = 6.0e5
    g.append(dict(name="thornton", end="zero_force", model="model tdem/thornton tangential tdem/cundall_strack",
                  sets=[mk("py6e5", p, ["--law", "thornton"] + EMAT + ["--py", "6e5"])]))
    for limit in ("off", "on"):
        end = "zero_force" if limit == "on" else "zero_overlap"
        sets = [mk("damped", {"potentialEnergy": 1e-5, "potentialExponent": 36.0, "dampingCoefficient": 0.1},
                   ["--law", "continuous_potential", "--eps", "1e-5", "--n", "36", "--gamma", "0.1", "--end", end])]
        if limit == "off":
            sets.append(mk("elastic", {"potentialEnergy": 2e-4, "potentialExponent": 36.0, "dampingCoefficient": 0.0},
                           ["--law", "continuous_potential", "--eps", "2e-4", "--n", "36", "--gamma", "0", "--end", end]))
        g.append(dict(name="continuous_potential_limitForce_" + limit, end=end,
                      model="model tdem/continuous_potential tangential tdem/cundall_strack limitForce " + limit,
                      sets=sets))
    # luding (the worked example of docs/adding_a_law.md): below and beyond its plastic limit
    g.append(dict(name="luding", end="zero_force", model="model tdem/luding tangential tdem/cundall_strack",
                  sets=[mk("below", {"loadingStiffness": KL, "unloadingStiffnessMax": 5 * KL, "plasticityDepth": 0.1},
                           ["--law", "luding", "--params", "%r,%r,0.1" % (KL, 5 * KL)]),
                        mk("beyond", {"loadingStiffness": KL, "unloadingStiffnessMax": 5 * KL, "plasticityDepth": 0.02},
                           ["--law", "luding", "--params", "%r,%r,0.02" % (KL, 5 * KL)])]))
    AL = 5.0e5
    g.append(dict(name="power_law", end="zero_force", model="model tdem/power_law tangential tdem/cundall_strack",
                  sets=[mk("q0", {"loadingCoefficient": AL, "loadingExponent": 1.5,
                                  "unloadingCoefficient": AL / 0.7 ** 3, "unloadingExponentIncrement": 0.0},
                           ["--law", "power_law", "--al", repr(AL), "--p", "1.5", "--aul", repr(AL / 0.7 ** 3), "--q", "0"]),
                        mk("q0.5", {"loadingCoefficient": AL, "loadingExponent": 1.5,
                                    "unloadingCoefficient": 2.0e8, "unloadingExponentIncrement": 0.5},
                           ["--law", "power_law", "--al", repr(AL), "--p", "1.5", "--aul", "2e8", "--q", "0.5"]),
                        mk("linear_p1", {"loadingCoefficient": 1.0e4, "loadingExponent": 1.0,
                                         "unloadingCoefficient": 2.0e4, "unloadingExponentIncrement": 0.0},
                           ["--law", "power_law", "--al", "1e4", "--p", "1", "--aul", "2e4", "--q", "0"])]))
    # extended laws: two impact velocities per geometry, so that the velocity dependence is seen
    for limit in ("off", "on"):
        end = "zero_force" if limit == "on" else "zero_overlap"
        g.append(dict(name="extended_linear_rational_power_limitForce_" + limit, end=end,
                      model="model tdem/extended_linear tangential tdem/cundall_strack restitutionFit rational "
                            "contactTimeFit power limitForce " + limit,
                      sets=[mk("fit", {"restitutionFitC0": 0.9, "restitutionFitC1": 1.0, "restitutionFitC2": 0.5,
                                       "contactTimeFitC0": 5e-4, "contactTimeFitC1": 0.2},
                               ["--law", "extended_linear", "--e-fit", "rational", "--e-coef", "0.9,1,0.5",
                                "--tc-fit", "power", "--tc-coef", "5e-4,0.2", "--end", end],
                               wall_v=(0.5, 2.0), pair_v=(1.0, 3.0))]))
    g.append(dict(name="extended_linear_power_constant_defaults", end="zero_overlap",
                  model="model tdem/extended_linear tangential tdem/cundall_strack restitutionFit power contactTimeFit constant",
                  scalars={"impactVelocityMin": 0.8, "impactVelocityMax": 2.5},
                  sets=[mk("fit", {"restitutionFitC0": 0.1, "restitutionFitC1": 0.2, "contactTimeFitC0": 4e-4},
                           ["--law", "extended_linear", "--e-fit", "power", "--e-coef", "0.1,0.2",
                            "--tc-fit", "constant", "--tc-coef", "4e-4", "--v-min", "0.8", "--v-max", "2.5"],
                           wall_v=(0.5, 2.0), pair_v=(1.0, 3.0))]))
    for limit, fit, coef, scal, hscal in (
            ("off", "rational", {"restitutionFitC0": 0.9, "restitutionFitC1": 1.0, "restitutionFitC2": 0.5},
             {}, []),
            ("on", "rational", {"restitutionFitC0": 0.9, "restitutionFitC1": 1.0, "restitutionFitC2": 0.5},
             {"impactVelocityMax": 1.5}, ["--v-max", "1.5"]),
            ("off", "constant", {"restitutionFitC0": 0.45}, {}, [])):
        end = "zero_force" if limit == "on" else "zero_overlap"
        p = dict(MAT)
        p.update(coef)
        ecoef = ",".join(repr(coef["restitutionFitC%d" % k]) for k in range(len(coef)))
        g.append(dict(name="extended_hertz_%s_limitForce_%s" % (fit, limit), end=end,
                      model="model tdem/extended_hertz tangential tdem/cundall_strack restitutionFit %s limitForce %s"
                            % (fit, limit), scalars=scal,
                      sets=[mk("fit", p, ["--law", "extended_hertz"] + EMAT + ["--e-fit", fit, "--e-coef", ecoef,
                                                                            "--end", end] + hscal,
                               wall_v=(0.5, 2.0), pair_v=(1.0, 3.0))]))
    return g


# ---------------------------------------------------------------- harness
def harness(exe, opts, geometry, v0):
    bodies = ["--rho", repr(RHO), "--R1", repr(R)] + (["--wall"] if geometry == "wall" else ["--R2", repr(R)])
    cmd = [exe] + opts + bodies + ["--v0", repr(v0), "--steps", str(HARNESS_STEPS)]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("FAIL: %s -> %d\n%s%s" % (" ".join(cmd), r.returncode, r.stdout, r.stderr))
    out = json.loads(r.stdout)
    if not out["ended"]:
        raise SystemExit("FAIL: harness contact did not end: " + " ".join(cmd))
    return out


# ---------------------------------------------------------------- host scene
def input_text(group, impacts, dt, steps):
    ntypes = 1 + len(group["sets"])
    lines = []
    keys = list(group["sets"][0]["props"].keys())
    for k in keys:
        v0 = group["sets"][0]["props"][k]
        if isinstance(v0, tuple):  # peratomtype, the same for all types
            lines.append("fix p_%s all property/global %s %s %s" % (k, k, v0[0], " ".join([repr(v0[1])] * ntypes)))
            continue
        vals = []
        for i in range(1, ntypes + 1):
            for j in range(1, ntypes + 1):
                s = max(i, j) - 2
                vals.append(repr(group["sets"][max(s, 0)]["props"][k]))
        lines.append("fix p_%s all property/global %s peratomtypepair %d %s" % (k, k, ntypes, " ".join(vals)))
    for k, v in group.get("scalars", {}).items():
        lines.append("fix p_%s all property/global %s scalar %r" % (k, k, v))
    atoms, vels = [], []
    for imp in impacts:
        t = imp["type"]
        if imp["geometry"] == "wall":
            gap = imp["v0"] * dt * 2.5
            atoms.append("create_atoms %d single %r 0.0 %r units box" % (t, imp["x"], R + gap))
            vels.append((0.0, -imp["v0"]))
        else:
            gap = imp["v0"] * dt * 2.5
            atoms.append("create_atoms %d single %r 0.0 0.03 units box" % (t, imp["x"] - R - gap / 2))
            atoms.append("create_atoms %d single %r 0.0 0.03 units box" % (t, imp["x"] + R + gap / 2))
            vels.append((imp["v0"] / 2, 0.0))
            vels.append((-imp["v0"] / 2, 0.0))
    setv = "\n".join("set atom %d vx %r vy 0.0 vz %r" % (i + 1, vx, vz) for i, (vx, vz) in enumerate(vels))
    words = group["model"].split()
    wall = "fix wz all wall/gran %s primitive type 1 zplane 0.0 %s" % (" ".join(words[:4]), " ".join(words[4:]))
    xmax = max(imp["x"] for imp in impacts) + 0.02
    return """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.02 %r -0.02 0.02 -0.001 0.05 units box
create_box %d box
neighbor 0.001 bin
neigh_modify delay 0
%s
pair_style gran %s
pair_coeff * *
timestep %r
%s
set group all diameter %r density %r
%s
%s
fix integr all nve/sphere
dump d all custom 1 dump.h id x z vx vz fx fz
dump_modify d sort id format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
thermo 1000000
run %d
""" % (xmax, ntypes, "\n".join(lines), group["model"], dt, "\n".join(atoms), 2 * R, RHO, setv, wall, steps)


def read_dump_fast(path, natoms):
    with open(path) as f:
        lines = f.read().splitlines()
    per = 9 + natoms
    nframes = len(lines) // per
    steps = np.array([int(lines[k * per + 1]) for k in range(nframes)])
    body = [l for k in range(nframes) for l in lines[k * per + 9: k * per + 9 + natoms]]
    a = np.array(" ".join(body).split(), dtype=float).reshape(nframes, natoms, 7)
    return steps, a   # columns: id x z vx vz fx fz


def measure(t, xi, rate, f, end_by_force):
    n_in = int(np.argmax(xi > 0))
    t_in = t[n_in - 1] + (t[n_in] - t[n_in - 1]) * (-xi[n_in - 1]) / (xi[n_in] - xi[n_in - 1])
    if end_by_force:
        m = n_in + int(np.argmax(f[n_in:] <= 0.0)) - 1   # last positive force
        t_out = t[m] + (t[m] - t[m - 1]) * f[m] / (f[m - 1] - f[m])
        ended = f[m + 1] <= 0.0 and m + 1 < len(f) - 1
    else:
        m = n_in + int(np.argmax(xi[n_in:] <= 0)) - 1
        t_out = t[m] + (t[m + 1] - t[m]) * xi[m] / (xi[m] - xi[m + 1])
        ended = xi[m + 1] <= 0 and m + 1 < len(xi) - 1
    return -rate[-1] / rate[0], t_out - t_in, ended


def main():
    args = T.parse_args(lambda p: (p.add_argument("--collide", required=True, help="tdem-collide executable"),
                                   p.add_argument("--only", default=None, help="run groups whose name contains this")))
    checks = T.Checks()
    t_start = time.time()
    rows = []
    for group in groups():
        if args.only and args.only not in group["name"]:
            continue
        impacts = []
        x = 0.0
        for si, s in enumerate(group["sets"]):
            for geometry, vs in (("wall", s["wall_v"]), ("pair", s["pair_v"])):
                for v in vs:
                    h = harness(args.collide, s["harness"], geometry, v)
                    impacts.append(dict(set=s["name"], type=si + 2, geometry=geometry, v0=v, x=x, ref=h))
                    x += 0.03
        tc_min = min(i["ref"]["contact_time"] for i in impacts)
        dt = tc_min / STEPS_PER_CONTACT
        tc_max = max(i["ref"]["contact_time"] for i in impacts)
        steps = int(1.03 * tc_max / dt) + 40
        d = T.workdir(args, "tdem_lig_harness_" + group["name"])
        T.run(args.tdem, input_text(group, impacts, dt, steps), d, group["name"])
        natoms = sum(1 if i["geometry"] == "wall" else 2 for i in impacts)
        st, a = read_dump_fast(os.path.join(d, "dump.h"), natoms)
        t = st * dt
        row = 0
        end_by_force = group["end"] == "zero_force"
        for imp in impacts:
            if imp["geometry"] == "wall":
                b = a[:, row]
                xi, rate, f = R - b[:, 2], -b[:, 4], b[:, 6]
                row += 1
            else:
                b1, b2 = a[:, row], a[:, row + 1]
                xi, rate, f = 2 * R - (b2[:, 1] - b1[:, 1]), b1[:, 3] - b2[:, 3], b2[:, 5]
                row += 2
            e, tc, ended = measure(t, xi, rate, f, end_by_force)
            ref = imp["ref"]
            de = e - ref["e"]
            dtc = tc / ref["contact_time"] - 1
            label = "%s/%s %s v0=%g" % (group["name"], imp["set"], imp["geometry"], imp["v0"])
            checks.check(ended, "%s: contact ended inside the run" % label)
            checks.check(abs(de) <= TOL_E and abs(dtc) <= TOL_TC,
                         "%s: e host %.7f harness %.7f (diff %+.1e), t_c host %.7e harness %.7e s (rel %+.1e)"
                         % (label, e, ref["e"], de, tc, ref["contact_time"], dtc))
            rows.append((label, ref["e"], de, ref["contact_time"], dtc))
    print("\nhost (tdem-liggghts, %d steps per shortest contact) vs harness (tdem-collide, RK4)" % STEPS_PER_CONTACT)
    print("| case | e (harness) | e_host - e_harness | t_c harness [s] | t_c rel. diff |")
    print("|---|---|---|---|---|")
    for r in rows:
        print("| %s | %.6f | %+.2e | %.5e | %+.2e |" % r)
    if rows:
        print("max |de| = %.2e, max |dtc|/tc = %.2e over %d impacts; %.1f s"
              % (max(abs(r[2]) for r in rows), max(abs(r[4]) for r in rows), len(rows), time.time() - t_start))
    checks.done()


if __name__ == "__main__":
    main()
