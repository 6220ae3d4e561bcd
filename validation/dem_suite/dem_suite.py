#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The community DEM verification cases (MFiX-DEM DEM-01 ... DEM-11, as mirrored by LAMMPS 4Jul2026
unittest/granular) run with tdem's own laws in LAMMPS (`tdem-lammps-*`) and LIGGGHTS
(`tdem-liggghts`), checked against the closed forms of the cases (issue 18).

The scenes (geometry, material numbers, steps) follow the suite's scenes; the input scripts, the
laws and the closed forms below are our own. Every scene dumps its particles at every `every`
steps; the checks read the trajectory:

  freefall            z = z0 - g t^2/2, vz = -g t before the first contact (velocity Verlet is exact)
  bounce_height       apex after the k-th bounce h_k = r + e^(2k) (h0 - r), apex = z + vz^2/(2g)
  stack_energy        two elastic spheres between floor and ceiling: KE + m g y + contact energy const
  slip_cessation      a sphere sliding with u0 rolls at u = 5/7 u0, omega = u/r after t_s = 2 u0/(7 mu g)
  oblique_impact      gross sliding on a wall: vz' = e vz, vx' = vx - mu (1+e) vz, omega' = 5/2 mu(1+e) vz/r
  energy_dissipation  a frictional grazing impact never gains kinetic energy
  collision_restitution  two equal spheres head-on at +-vin: -(v1 - v2)/(2 vin) = e
  spin_no_friction    equal and opposite spins with zero slip at the contact: no tangential force
  spin_impact         a spinning sphere on a heavy partner, gross sliding: vz' = e vin, vx' = mu(1+e) vin,
                      omega' = omega0 - 5/2 mu (1+e) vin / r
  hertz_normal_impact elastic Hertz impact: 1/2 m* V^2 = 2/5 F_max xi_max at peak compression, and
                      xi_max, F_max, t_c against Hertz's closed form

  angle_of_repose     a heap of spheres or of rigid clumps with rolling resistance settles at rest with
                      atan(H/R) in [15, 55] deg (H: highest centre, R: farthest centre from the centroid)

Usage: dem_suite.py --host lammps|liggghts --exe EXE [--np 1,2] [--mpirun MPIRUN] [--case NAME,...]
                    [--workdir DIR] [--table FILE] [--seed N]
Prints one line per case, law and rank count, then a summary; exit status 1 if any check failed."""
import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "host", "liggghts"))
import tdem_lig as T  # noqa: E402
import mpi_env  # noqa: E402 (tests/host, put on the path by tdem_lig)

PI = math.pi

# ----------------------------------------------------------------------------- laws
# A law: (label, LAMMPS pair/wall law text, LIGGGHTS (models, settings, {property: value}),
#         closed-form parameters for the checks). Material numbers come from the case.


def lsd_e(e, k, meff, kappa, mu, end="zero_overlap"):
    """lsd from restitution e and the stiffness k at effective mass meff: the contact time of the
    linear spring-dashpot with the damping that gives e (zero-overlap end)."""
    ln = math.log(e)
    tc = math.sqrt(meff / k) * math.sqrt(PI * PI + ln * ln)
    lam = ("normal lsd restitution %.17g %.17g tangential cundall_strack %.17g %.17g" % (e, tc, kappa, mu))
    lig = ("model tdem/lsd tangential tdem/cundall_strack", "parameters restitution",
           {"coefficientRestitution": e, "contactTime": tc, "tangentialStiffnessRatio": kappa,
            "coefficientFriction": mu})
    kt = kappa * k
    stock = {"lammps": ("pair_style granular\npair_coeff * * hooke %.17g %.17g tangential linear_history %.17g 0 %.17g "
                        "damping coeff_restitution" % (k, e, kt, mu),
                        "granular hooke %.17g %.17g tangential linear_history %.17g 0 %.17g damping coeff_restitution"
                        % (k, e, kt, mu)),
             "bitwise": ()}
    return ("lsd + cundall_strack", lam, lig, stock)


def lsd_k(k, gamma, kt, gammat, mu):
    """lsd with stiffness and damping per unit effective mass (the convention of gran/hooke/history)."""
    lam = ("normal lsd stiffness %.17g %.17g tangential cundall_strack %.17g %.17g %.17g damping mass"
           % (k, gamma, kt, gammat, mu))
    lig = ("model tdem/lsd tangential tdem/cundall_strack", "parameters stiffness",
           {"kn": k, "kt": kt, "gamman": gamma, "gammat": gammat, "coefficientFriction": mu})
    hh = "hooke/history %.17g %.17g %.17g %.17g %.17g 1" % (k, kt, gamma, gammat, mu)
    stock = {"lammps": ("pair_style gran/" + hh + "\npair_coeff * *", hh),
             "liggghts": ("model hooke/stiffness tangential history", "", lig[2]),
             "bitwise": ("lammps", "liggghts")}  # docs/lammps.md, docs/liggghts.md: the same arithmetic
    return ("lsd stiffness + cundall_strack", lam, lig, stock)


def hertz(E, nu, mu, damping=None, tangential="mindlin_deresiewicz"):
    """Hertz (one material for both partners and the wall) with Tsuji damping of restitution
    `damping` (None: elastic) and a tangential law."""
    d = " damping tsuji %.17g" % damping if damping is not None else ""
    t = {"mindlin_deresiewicz": "tangential mindlin_deresiewicz %.17g %.17g %.17g" % (E, nu, mu),
         "di_renzo": "tangential di_renzo %.17g %.17g %.17g" % (E, nu, mu),
         "cundall_strack": "tangential cundall_strack %.17g %.17g" % (2 * (1 - nu) / (2 - nu), mu)}[tangential]
    lam = "normal hertz %.17g %.17g%s %s" % (E, nu, d, t)
    props = {"youngsModulus": E, "poissonsRatio": nu, "coefficientFriction": mu}
    if damping is not None:
        props["coefficientRestitution"] = damping
    if tangential == "cundall_strack":
        props["tangentialStiffnessRatio"] = 2 * (1 - nu) / (2 - nu)
    if damping is None:  # elastic: linear damping with coefficient 0
        props["dampingCoefficient"] = 0.0
    lig = ("model tdem/hertz tangential tdem/" + tangential,
           ("damping tsuji" if damping is not None else "damping linear") + " limitForce off", props)
    stock = {}
    if tangential == "mindlin_deresiewicz":  # LAMMPS granular: Hertz, Tsuji damping of e, Mindlin spring
        g = "hertz/material %.17g %.17g %.17g tangential mindlin NULL 0 %.17g damping tsuji" % (
            E, damping if damping is not None else 1.0, nu, mu)
        stock["lammps"] = ("pair_style granular\npair_coeff * * " + g, "granular " + g)
    if damping is not None:  # LIGGGHTS hertz: its own damping from e, Mindlin-type spring in history
        stock["liggghts"] = ("model hertz tangential history", "", props)
    stock["bitwise"] = ()
    return ("hertz%s + %s" % (" tsuji" if damping is not None else "", tangential), lam, lig, stock)


def walton_braun(kl, e, kappa, mu):
    kul = kl / (e * e)
    lam = "normal walton_braun %.17g %.17g tangential cundall_strack %.17g %.17g" % (kl, kul, kappa, mu)
    lig = ("model tdem/walton_braun tangential tdem/cundall_strack", "",
           {"loadingStiffness": kl, "unloadingStiffness": kul, "unloadingStiffnessSlope": 0.0,
            "tangentialStiffnessRatio": kappa, "coefficientFriction": mu})
    return ("walton_braun + cundall_strack", lam, lig, {})


def extended_linear(e, tc, kappa, mu):
    lam = ("normal extended_linear e_fit constant %.17g tc_fit constant %.17g tangential cundall_strack %.17g %.17g"
           % (e, tc, kappa, mu))
    lig = ("model tdem/extended_linear tangential tdem/cundall_strack",
           "restitutionFit constant contactTimeFit constant",
           {"restitutionFitC0": e, "contactTimeFitC0": tc, "tangentialStiffnessRatio": kappa, "coefficientFriction": mu})
    return ("extended_linear + cundall_strack", lam, lig, {})


def tangential_lsd(label, e, k, meff, mu, tlaw):
    """lsd restitution with another tangential law (spring from the normal stiffness)."""
    base = lsd_e(e, k, meff, 0.2857, mu)
    if tlaw == "linear_spring":
        lam = base[1].replace("tangential cundall_strack 0.2857", "tangential linear_spring 0 0.2857 0")
        models = "model tdem/lsd tangential tdem/linear_spring"
    else:
        raise ValueError(tlaw)
    props = dict(base[2][2], tangentialDampingRatio=0.0)
    return (label, lam, (models, base[2][1], props), {})


# ----------------------------------------------------------------------------- scenes
class Scene:
    """One DEM case: box, atoms (x y z, diameter, density, velocity, omega), gravity, wall, steps."""

    def __init__(self, box, atoms, steps, dt, every=1, gravity=(0.0, 0.0, 0.0), wall=None, periodic="fff",
                 skin=0.1, procs=None, clump=None, ranks_bitwise=True):
        self.box, self.atoms, self.steps, self.dt, self.every = box, atoms, steps, dt, every
        self.gravity, self.periodic, self.skin, self.procs = gravity, periodic, skin, procs
        # wall: one "style lo hi" plane pair or a list of them
        self.walls = [] if wall is None else ([wall] if isinstance(wall, str) else list(wall))
        # clump: template spheres [(x, y, z, r)] of rigid bodies made of the atoms with equal "mol"
        self.clump = clump
        # ranks_bitwise: 2 ranks must give the 1-rank trajectory bit for bit (False for the heaps: the
        # order of the force sums differs, and a pour of 85000 steps amplifies that to chaos)
        self.ranks_bitwise = ranks_bitwise
        self.data = len(atoms) > 8 or clump is not None  # LAMMPS too reads the atoms from a data file


def bnd(per, host):
    return " ".join("p" if c == "p" else "f" for c in per)


def lammps_input(sc, law, np_, stock=False):
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary " + bnd(sc.periodic, "lammps"),
             "newton off", "comm_modify vel yes"]
    if np_ > 1 and sc.procs:
        lines.append("processors " + sc.procs)
    if sc.data:
        if sc.clump:
            lines.append("fix pm all property/atom mol ghost yes")
        lines.append("read_data scene.data" + (" fix pm NULL Molecules" if sc.clump else ""))
    else:
        lines += ["region box block %s units box" % " ".join("%.17g" % v for v in sc.box), "create_box 1 box"]
        lines += atom_lines(sc)
    lines += ["neighbor %.17g bin" % sc.skin, "neigh_modify delay 0" + (" exclude molecule/intra all" if sc.clump else "")]
    if stock:
        pair, wall = law[3]["lammps"]
        lines += pair.split("\n")
        lines += ["fix w%d all wall/gran %s %s" % (k, wall, w) for k, w in enumerate(sc.walls)]
    else:
        lines += ["pair_style tdem/gran", "pair_coeff * * " + law[1]]
        lines += ["fix w%d all tdem/wall/gran %s %s" % (k, law[1], w) for k, w in enumerate(sc.walls)]
    if not sc.clump:
        integrator = "fix integr all nve/sphere"
    elif stock:
        integrator = "fix integr all rigid/small molecule"
    else:
        integrator = "fix integr all tdem/clump template t file clump.txt density %.17g bodies molecule" % sc.atoms[0]["rho"]
    lines += tail_lines(sc, integrator=integrator)
    return "\n".join(lines) + "\n"


def liggghts_input(sc, law, np_, stock=False):
    models, settings, props = law[3]["liggghts"] if stock else law[2]
    lines = ["atom_style " + ("hybrid sphere molecular" if sc.clump else "granular"), "atom_modify map array",
             "boundary " + bnd(sc.periodic, "liggghts"),
             "newton off", "communicate single vel yes", "units si", "soft_particles yes"]
    if np_ > 1 and sc.procs:
        lines.append("processors " + sc.procs)
    # LIGGGHTS's `set` has no omega: the atoms come from a data file (with their spins)
    lines += ["read_data scene.data", "neighbor %.17g bin" % sc.skin,
              "neigh_modify delay 0" + (" exclude molecule all" if sc.clump else "")]
    if "hertz" in models and "tangentialStiffnessRatio" not in props:
        props = dict(props, tangentialStiffnessRatio=2 * (1 - props["poissonsRatio"]) / (2 - props["poissonsRatio"]))
    for k, v in props.items():
        kind = "peratomtype" if k in ("youngsModulus", "poissonsRatio") else "peratomtypepair 1"
        lines.append("fix p_%s all property/global %s %s %.17g" % (k, k, kind, v))
    lines += ["pair_style gran %s %s" % (models, settings), "pair_coeff * *"]
    planes = [(w.split()[0], pos) for w in sc.walls for pos in w.split()[1:] if pos != "NULL"]
    for k, (style, pos) in enumerate(planes):  # one primitive wall per plane
        lines.append("fix w%d all wall/gran %s primitive type 1 %s %s %s" % (k, models, style, pos, settings))
    integrator = "fix integr all nve/sphere"
    if sc.clump:
        integrator = "fix integr all tdem/clump template t file clump.txt density %.17g bodies molecule" % sc.atoms[0]["rho"]
    lines += tail_lines(sc, liggghts=True, integrator=integrator)
    return "\n".join(lines) + "\n"


def scene_data(sc, host):
    """Data file of the scene: LIGGGHTS (atom_style granular, or hybrid sphere molecular for clumps)
    or LAMMPS (atom_style sphere; the molecule IDs of clumps in a Molecules section of fix
    property/atom)."""
    b = sc.box
    out = ["DEM case", "", "%d atoms" % len(sc.atoms), "1 atom types", "",
           "%.17g %.17g xlo xhi" % (b[0], b[1]), "%.17g %.17g ylo yhi" % (b[2], b[3]),
           "%.17g %.17g zlo zhi" % (b[4], b[5]), "", "Atoms", ""]
    for i, a in enumerate(sc.atoms, 1):
        if host == "liggghts" and sc.clump:  # hybrid: x y z, then sphere's d rho, then molecular's mol
            out.append("%d 1 %.17g %.17g %.17g %.17g %.17g %d" % ((i,) + tuple(a["x"]) + (a["d"], a["rho"], a["mol"])))
        else:
            out.append("%d 1 %.17g %.17g %.17g %.17g %.17g" % ((i, a["d"], a["rho"]) + tuple(a["x"])))
    out += ["", "Velocities", ""]
    out += ["%d %.17g %.17g %.17g %.17g %.17g %.17g" % ((i,) + tuple(a.get("v", (0, 0, 0))) + tuple(a.get("w", (0, 0, 0))))
            for i, a in enumerate(sc.atoms, 1)]
    if host == "lammps" and sc.clump:
        out += ["", "Molecules", ""] + ["%d %d" % (i, a["mol"]) for i, a in enumerate(sc.atoms, 1)]
    return "\n".join(out) + "\n"


def atom_lines(sc):
    out = []
    for i, a in enumerate(sc.atoms, 1):
        x, d, rho = a["x"], a["d"], a["rho"]
        out.append("create_atoms 1 single %.17g %.17g %.17g units box" % tuple(x))
        out.append("group a%d id %d" % (i, i))
        out.append("set group a%d diameter %.17g density %.17g" % (i, d, rho))
        if any(a.get("v", (0, 0, 0))):
            out.append("velocity a%d set %.17g %.17g %.17g units box" % ((i,) + tuple(a["v"])))
        if any(a.get("w", (0, 0, 0))):
            out.append("set group a%d omega %.17g %.17g %.17g" % ((i,) + tuple(a["w"])))
    return out


def tail_lines(sc, liggghts=False, integrator="fix integr all nve/sphere"):
    g = sc.gravity
    out = []
    gn = math.sqrt(sum(c * c for c in g))
    if gn > 0:
        out.append("fix grav all gravity %.17g vector %.17g %.17g %.17g" % (gn, g[0] / gn, g[1] / gn, g[2] / gn))
    out += [integrator, "timestep %.17g" % sc.dt]
    cols = "id x y z vx vy vz fx fy fz omegax omegay omegaz"
    fmt = '"%d' + " %.17g" * 12 + '"'
    out.append("dump d all custom %d traj.dump %s" % (sc.every, cols))
    out.append("dump_modify d sort id format %s" % (fmt if liggghts else "line " + fmt))
    if sc.clump:  # the temperature's degrees of freedom are not defined for rigid bodies of spheres
        out.append("thermo_style custom step atoms")
    out += ["thermo %d" % max(1, sc.steps // 4), "run %d" % sc.steps]
    return out


def read_traj(path):
    """[(step, [[id, x, y, z, vx, vy, vz, fx, fy, fz, wx, wy, wz], ...] sorted by id)] (the dump
    reader of the LIGGGHTS host tests, which reads LAMMPS dumps too)"""
    return [(step, data.tolist()) for step, _, data in T.read_dump(path)]


# ----------------------------------------------------------------------------- closed forms
def mass(a):
    return a["rho"] * PI * a["d"] ** 3 / 6.0


def first_contact(frames, test):
    for j, (_, rows) in enumerate(frames):
        if test(rows):
            return j
    return len(frames)


def rel(a, b, floor=1e-300):
    return abs(a - b) / max(abs(b), floor)


# ----------------------------------------------------------------------------- cases
CASES = {}


def case(name, dem, physics, tol):
    def reg(fn):
        CASES[name] = (dem, physics, tol, fn)
        return fn
    return reg


G = 9.81


@case("dem01_freefall", "DEM-01", "free fall before the first contact: z = z0 - g t^2/2, vz = -g t", 1e-9)
def dem01():
    r, rho, k = 0.1, 2600.0, 1e4
    m = rho * PI * (2 * r) ** 3 / 6
    sc = Scene((-0.5, 0.5, -0.5, 0.5, 0.0, 1.0), [dict(x=(0, 0, 0.5), d=2 * r, rho=rho)], 250, 1e-3, every=10,
               gravity=(0, 0, -G), wall="zplane 0 NULL")
    laws = [lsd_e(0.6, k, m, 0.2857, 0.5), hertz(5e6, 0.3, 0.5, damping=0.6)]

    def check(frames):
        err = 0.0
        for step, rows in frames:
            t = step * 1e-3
            z, vz = rows[0][3], rows[0][6]
            if z - r <= 0:
                break
            err = max(err, rel(z, 0.5 - 0.5 * G * t * t), abs(vz + G * t) / (G * 0.25))
        return err, "max relative error of z and vz over 250 steps"
    return sc, laws, check


@case("dem02_bounce_height", "DEM-02", "apex height after the first bounce h_1 = r + e^2 (h0 - r)", 0.015)
def dem02():
    r, rho, k, e = 0.1, 2600.0, 1e6, 0.9
    m = rho * PI * (2 * r) ** 3 / 6
    sc = Scene((-0.5, 0.5, -0.5, 0.5, 0.0, 1.0), [dict(x=(0, 0, 0.5), d=2 * r, rho=rho)], 2450, 2e-4, every=10,
               gravity=(0, 0, -G), wall="zplane 0 NULL")
    ln = math.log(e)
    tc = math.sqrt(m / k) * math.sqrt(PI * PI + ln * ln)
    laws = [lsd_e(e, k, m, 0.2857, 0.0), walton_braun(k, e, 0.2857, 0.0), extended_linear(e, tc, 0.2857, 0.0),
            hertz(5e7, 0.3, 0.0, damping=e, tangential="cundall_strack")]

    def check(frames):
        bounces, inside, apex = 0, False, None
        for step, rows in frames:
            z, vz = rows[0][3], rows[0][6]
            if z < r:
                inside = True
            elif inside:
                inside, bounces = False, bounces + 1
            if bounces == 1 and not inside and z >= r:
                apex = z + vz * vz / (2 * G)
        want = r + e ** 2 * (0.5 - r)
        return (rel(apex, want) if apex else 1.0), "apex %.6g m vs %.6g m" % (apex or 0, want)
    return sc, laws, check


@case("dem03_stack_energy", "DEM-03", "elastic two-sphere stack between floor and ceiling: energy conserved", 5e-4)
def dem03():
    r, rho = 0.0005, 10000.0
    atoms = [dict(x=(0, 0.00045, 0), d=2 * r, rho=rho), dict(x=(0, 0.00135, 0), d=2 * r, rho=rho)]
    sc = Scene((-0.005, 0.005, -0.001, 0.003, -0.005, 0.005), atoms, 1000, 2e-6, every=5, gravity=(0, -G, 0),
               wall="yplane 0 0.0018", skin=0.0005, procs="1 2 1")
    k, E, nu = 1e3, 8.6e6, 0.3
    laws = [lsd_k(k, 0.0, 800.0, 0.0, 0.0), hertz(E, nu, 0.0, tangential="cundall_strack")]
    m = mass(atoms[0])

    def energy(rows, law):
        y1, y2 = rows[0][2], rows[1][2]
        ke = sum(0.5 * m * (rw[4] ** 2 + rw[5] ** 2 + rw[6] ** 2) for rw in rows)
        pe = m * G * (y1 + y2)
        overlaps = [(r - y1, r), (2 * r - (y2 - y1), r / 2), (y2 + r - 0.0018, r)]  # (xi, R*)
        el = 0.0
        for xi, reff in overlaps:
            if xi > 0:
                if law.startswith("lsd"):
                    el += 0.5 * k * xi * xi
                else:
                    estar = E / (2 * (1 - nu * nu))
                    el += 0.4 * (4.0 / 3.0 * estar * math.sqrt(reff)) * xi ** 2.5
        return ke + pe + el

    def check(frames, law):
        e0 = energy(frames[0][1], law)
        err = max(abs(energy(rows, law) - e0) for _, rows in frames) / e0
        return err, "max |E - E0|/E0 over %d frames" % len(frames)
    return sc, laws, check


@case("dem04_slip_cessation", "DEM-04", "sliding sphere: u = 5/7 u0 and omega = u/r after t_s = 2 u0/(7 mu g)", 5e-3)
def dem04():
    r, rho, k, mu, g = 0.5, 1.0, 1e4, 0.5, 1.0
    m = rho * PI * (2 * r) ** 3 / 6
    z0 = r - m * g / k  # resting overlap
    sc = Scene((-5, 5, -1, 1, -0.5, 3), [dict(x=(0, 0, z0), d=2 * r, rho=rho, v=(1.0, 0, 0))], 4500, 2e-4,
               every=100, gravity=(0, 0, -g), wall="zplane 0 NULL", periodic="pff", skin=0.3)
    laws = [lsd_k(k, 10.0, 2.0 / 7.0 * k, 5.0, mu), hertz(1e5, 0.3, mu), hertz(1e5, 0.3, mu, tangential="di_renzo")]

    def check(frames):
        rows = frames[-1][1]
        u, wy = rows[0][4], rows[0][11]
        return max(rel(u, 5.0 / 7.0), rel(wy * r, u)), "u = %.6g (5/7 = %.6g), omega r = %.6g" % (u, 5 / 7, wy * r)
    return sc, laws, check


def oblique_check(r, e, mu, vx, vz):
    def check(frames):
        rows = frames[-1][1]
        want = (vx - mu * (1 + e) * vz, e * vz, 2.5 * mu * (1 + e) * vz / r)
        got = (rows[0][4], rows[0][6], rows[0][11])
        err = max(rel(got[0], want[0]), rel(got[1], want[1]), rel(got[2], want[2]))
        return err, "vx' %.6g (%.6g), vz' %.6g (%.6g), omega_y' %.6g (%.6g)" % (got[0], want[0], got[1], want[1],
                                                                              got[2], want[2])
    return check


@case("dem05_oblique", "DEM-05", "gross-sliding oblique impact: vz' = e vz, vx' = vx - mu(1+e)vz, omega' = 5/2 mu(1+e)vz/r",
      5e-3)
def dem05():
    r, rho, k, e, mu, vx, vz = 0.5, 1.0, 1e4, 0.9, 0.3, 4.0, 1.0
    m = rho * PI * (2 * r) ** 3 / 6
    sc = Scene((-10, 10, -2, 2, -0.5, 5), [dict(x=(0, 0, 0.55), d=2 * r, rho=rho, v=(vx, 0, -vz))], 800, 2e-4,
               every=100, wall="zplane 0 NULL", periodic="ppf", skin=0.3)
    laws = [lsd_e(e, k, m, 0.2857, mu), tangential_lsd("lsd + linear_spring", e, k, m, mu, "linear_spring"),
            hertz(1e6, 0.3, mu, damping=e), hertz(1e6, 0.3, mu, damping=e, tangential="di_renzo")]
    # E = 1e6: a peak overlap of 0.4 % of the diameter, as the linear spring's (the closed form is the
    # rigid-sphere limit; LIGGGHTS's lever arm r - xi/2 lowers omega' by about that fraction)
    return sc, laws, oblique_check(r, e, mu, vx, vz)


@case("dem05_grazing_energy", "DEM-05", "grazing frictional impact: kinetic energy after <= before", 1e-3)
def dem05g():
    r, rho = 0.5, 1.0
    sc = Scene((-10, 10, -2, 2, -0.5, 5), [dict(x=(0, 0, 0.55), d=2 * r, rho=rho, v=(4.0, 0, -1.0))], 8000, 2e-5,
               every=400, wall="zplane 0 NULL", periodic="ppf", skin=0.3)
    laws = [lsd_k(1e4, 10.0, 2.0 / 7.0 * 1e4, 5.0, 0.5), hertz(1e5, 0.3, 0.5, damping=0.9)]
    m = rho * PI * (2 * r) ** 3 / 6
    inertia = 0.4 * m * r * r

    def ke(rows):
        w = rows[0]
        return 0.5 * m * (w[4] ** 2 + w[5] ** 2 + w[6] ** 2) + 0.5 * inertia * (w[10] ** 2 + w[11] ** 2 + w[12] ** 2)

    def check(frames):
        gain = ke(frames[-1][1]) / ke(frames[0][1]) - 1.0
        return max(gain, 0.0), "KE'/KE - 1 = %.4g" % gain
    return sc, laws, check


@case("dem07_rolling_decay", "DEM-07", "rolling resistance: omega(t) = omega0 - 5 mu_r g t/(2R) while it spins", 2e-3)
def dem07():
    r, rho, k, e, g, w0 = 0.5, 1.0, 1e4, 0.5, 10.0, 5.0
    m = rho * PI * (2 * r) ** 3 / 6
    sc = Scene((-2, 2, -2, 2, -0.5, 3), [dict(x=(0, 0, r - m * g / k), d=2 * r, rho=rho, w=(0, w0, 0))], 1200, 5e-4,
               every=50, gravity=(0, 0, -g), wall="zplane 0 NULL", periodic="ppf", skin=0.3)
    laws = []
    kr = 1000.0
    ln = math.log(e)
    eta = 2 * (-ln / math.sqrt(PI * PI + ln * ln)) * math.sqrt(k / m)  # gamma / m* of lsd for e
    for mur in (0.05, 0.1, 0.2):
        base = lsd_e(e, k, m, 0.2857, 0.0)
        # tdem's rolling sds (src/contact/rolling/sds.h): LAMMPS `rolling sds`, LIGGGHTS `rolling_friction
        # tdem/sds`; stock: LAMMPS granular rolling sds, LIGGGHTS hooke/stiffness with epsd2 (its
        # spring from k_t, torque capped at mu_r R* F_n)
        lam = base[1] + " rolling sds %.17g 0 %.17g" % (kr, mur)
        lig = (base[2][0] + " rolling_friction tdem/sds", base[2][1],
               dict(base[2][2], rollingStiffness=kr, rollingDamping=0.0, coefficientRollingFriction=mur))
        gs = ("hooke %.17g %.17g tangential linear_nohistory 0 0 rolling sds %.17g 0 %.17g damping mass_velocity"
              % (k, eta, kr, mur))
        stock = {"lammps": ("pair_style granular\npair_coeff * * " + gs, "granular " + gs),
                 "liggghts": ("model hooke/stiffness tangential history rolling_friction epsd2", "",
                              {"kn": k, "kt": 0.2857 * k, "gamman": eta, "gammat": 0.0, "coefficientFriction": 0.0,
                               "coefficientRollingFriction": mur}), "bitwise": ()}
        laws.append(("lsd + rolling mu_r %g" % mur, lam, lig, stock))

    def check(frames, law):
        mur = float(law.split()[-1])
        err, worst = 0.0, ""
        for step, rows in frames:
            t = step * 5e-4
            want = w0 - 5 * mur * g * t / (2 * r)
            if t < 0.1 or want < 0.2 * w0:  # after the rolling spring has loaded, while it spins
                continue
            d = abs(rows[0][11] - want) / w0
            if d > err:
                err, worst = d, "omega_y %.6g vs %.6g at t = %.3g s" % (rows[0][11], want, t)
        return err, "max |omega - omega(t)|/omega0: " + worst
    return sc, laws, check


@case("dem09_restitution", "DEM-09", "two equal spheres head-on: -(v1 - v2)/(2 vin) = e", 0.015)
def dem09():
    r, rho, k, e = 0.5, 1.0, 1e4, 0.9
    m = rho * PI * (2 * r) ** 3 / 6
    atoms = [dict(x=(-0.6, 0, 0), d=2 * r, rho=rho, v=(1, 0, 0)), dict(x=(0.6, 0, 0), d=2 * r, rho=rho, v=(-1, 0, 0))]
    sc = Scene((-3, 3, -2, 2, -2, 2), atoms, 1000, 2e-4, every=100, skin=0.3, procs="2 1 1")
    laws = [lsd_e(e, k, m / 2, 0.2857, 0.0), walton_braun(k, e, 0.2857, 0.0),
            hertz(1e5, 0.3, 0.0, damping=e, tangential="cundall_strack")]

    def check(frames):
        rows = frames[-1][1]
        got = -(rows[0][4] - rows[1][4]) / 2.0
        return rel(got, e), "e = %.6g (%.6g); momentum %.3g" % (got, e, rows[0][4] + rows[1][4])
    return sc, laws, check


@case("dem09_spin_identical", "DEM-09", "opposite spins with no slip at the contact: spin and tangential velocity unchanged",
      1e-8)
def dem09s():
    r, rho, k, e, w0 = 0.5, 1.0, 1e4, 0.9, 10.0
    m = rho * PI * (2 * r) ** 3 / 6
    atoms = [dict(x=(0, 0, -0.5), d=2 * r, rho=rho, v=(0, 0, 1), w=(0, w0, 0)),
             dict(x=(0, 0, 0.5), d=2 * r, rho=rho, v=(0, 0, -1), w=(0, -w0, 0))]
    sc = Scene((-3, 3, -3, 3, -3, 3), atoms, 600, 2e-4, every=100, skin=0.3, procs="1 1 2")
    laws = [lsd_e(e, k, m / 2, 0.2857, 0.5), hertz(1e5, 0.3, 0.5, damping=e)]

    def check(frames):
        rows = frames[-1][1]
        err = max(abs(rows[0][11] - w0) / w0, abs(rows[1][11] + w0) / w0,
                  max(abs(rw[4]) + abs(rw[5]) for rw in rows) / 1.0)
        return err, "omega_y %.12g %.12g (+-%g), |v_t| <= %.3g" % (rows[0][11], rows[1][11], w0,
                                                                    max(abs(rw[4]) + abs(rw[5]) for rw in rows))
    return sc, laws, check


@case("dem09_spin_impact", "DEM-09", "spinning sphere on a heavy sphere, gross sliding: vx', vz', omega' closed form",
      0.02)
def dem09u():
    r, k, e, mu, vin, w0 = 0.5, 1e4, 0.8, 0.4, 1.0, 20.0
    atoms = [dict(x=(0, 0, 3.0), d=1.0, rho=1.0, v=(0, 0, -vin), w=(0, w0, 0)), dict(x=(0, 0, 0), d=5.0, rho=1000.0)]
    m1, m2 = mass(atoms[0]), mass(atoms[1])
    meff = m1 * m2 / (m1 + m2)
    sc = Scene((-4, 4, -4, 4, -3, 6), atoms, 600, 2e-4, every=100, skin=0.3, procs="1 1 2")
    laws = [lsd_e(e, k, meff, 0.2857, mu), hertz(1e5, 0.3, mu, damping=e)]

    def check(frames):
        rows = frames[-1][1]
        want = (mu * (1 + e) * vin, e * vin, w0 - 2.5 * mu * (1 + e) * vin / r)
        got = (rows[0][4] - rows[1][4], rows[0][6] - rows[1][6], rows[0][11])
        err = max(rel(got[0], want[0]), rel(got[1], want[1]), rel(got[2], want[2]))
        return err, "vx' %.6g (%.6g), vz' %.6g (%.6g), omega' %.6g (%.6g)" % (got[0], want[0], got[1], want[1], got[2],
                                                                            want[2])
    return sc, laws, check


def hertz_closed_form(estar, reff, meff, v):
    """Maximum overlap, maximum force and contact time of an elastic Hertz impact."""
    kh = 4.0 / 3.0 * estar * math.sqrt(reff)
    xi = (15.0 * meff * v * v / (16.0 * estar * math.sqrt(reff))) ** 0.4
    # t_c = 2 xi_max / v * integral_0^1 dx / sqrt(1 - x^(5/2)) = 2.943... xi_max / v
    n, s = 20000, 0.0
    for i in range(n):  # midpoint rule in u with x = 1 - u^2 (removes the endpoint singularity)
        u = (i + 0.5) / n
        x = 1 - u * u
        s += 2 * u / math.sqrt(1 - x ** 2.5) / n
    return xi, kh * xi ** 1.5, 2 * xi / v * s


def hertz_impact(two):
    E, nu, rho, vin = 1e5, 0.3, 1.0, 1.0
    estar = E / (2 * (1 - nu * nu))
    if two:
        atoms = [dict(x=(-0.5, 0, 0), d=1.0, rho=rho, v=(vin, 0, 0)), dict(x=(0.5, 0, 0), d=1.0, rho=rho, v=(-vin, 0, 0))]
        sc = Scene((-3, 3, -2, 2, -2, 2), atoms, 340, 1e-4, skin=0.3, procs="2 1 1")
        m = mass(atoms[0])
        meff, reff, vrel = m / 2, 0.25, 2 * vin
    else:
        atoms = [dict(x=(0, 0, 0.5), d=1.0, rho=rho, v=(0, 0, -vin))]
        sc = Scene((-2, 2, -2, 2, -0.5, 3), atoms, 360, 1e-4, wall="zplane 0 NULL", skin=0.3)
        meff, reff, vrel = mass(atoms[0]), 0.5, vin
    laws = [hertz(E, nu, 0.0, tangential="cundall_strack"), hertz(E, nu, 0.0)]
    xi_w, f_w, tc_w = hertz_closed_form(estar, reff, meff, vrel)

    def check(frames):
        best, peak = (0.0, 0.0), 0
        ton = toff = None
        for step, rows in frames:
            xi = (1.0 - (rows[1][1] - rows[0][1])) if two else (0.5 - rows[0][3])
            f = abs(rows[0][7]) if two else abs(rows[0][9])
            if xi > 0 and ton is None:
                ton = step
            if xi <= 0 and ton is not None and toff is None:
                toff = step
            if xi > best[0]:
                best, peak = (xi, f), step
        xi_m, f_m = best
        energy = 0.5 * meff * vrel * vrel / (0.4 * f_m * xi_m)
        tc = ((toff or 0) - (ton or 0)) * 1e-4
        err = max(rel(energy, 1.0), rel(xi_m, xi_w), rel(f_m, f_w), rel(tc, tc_w))
        return err, ("1/2 m* V^2 / (2/5 F xi) = %.5g; xi_max %.5g (%.5g), F_max %.5g (%.5g), t_c %.4g (%.4g, step 1e-4)"
                     % (energy, xi_m, xi_w, f_m, f_w, tc, tc_w))
    return sc, laws, check


@case("dem11_hertz_wall", "DEM-11", "elastic Hertz impact on a wall: peak overlap, force and duration", 0.01)
def dem11w():
    return hertz_impact(False)


@case("dem11_hertz_pair", "DEM-11", "elastic Hertz impact of two spheres: peak overlap, force and duration", 0.01)
def dem11p():
    return hertz_impact(True)


def quat_random(rng):
    """A uniformly distributed unit quaternion (Shoemake's method) from three uniform numbers."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return (a * math.sin(2 * PI * u2), a * math.cos(2 * PI * u2), b * math.sin(2 * PI * u3), b * math.cos(2 * PI * u3))


def rotate(q, v):
    """v rotated by the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    r = ((1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
         (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
         (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)))
    return tuple(sum(r[i][j] * v[j] for j in range(3)) for i in range(3))


def repose_check(lo, hi, g, d, n):
    """Angle of repose of the settled heap, atan(H / R) with H the highest centre above the floor and
    R the largest horizontal distance of a centre from the heap's centroid (the coarse estimate of the
    suite), inside [lo, hi] degrees; the heap at rest: every speed below 0.01 sqrt(g d); and all n
    spheres still there."""
    def check(frames):
        rows = frames[-1][1]
        if len(rows) != n:
            return 1.0, "%d of %d spheres left the box" % (n - len(rows), n)
        xc = sum(rw[1] for rw in rows) / len(rows)
        yc = sum(rw[2] for rw in rows) / len(rows)
        zmax = max(rw[3] for rw in rows)
        rmax = max(math.hypot(rw[1] - xc, rw[2] - yc) for rw in rows)
        ang = math.degrees(math.atan2(zmax, rmax))
        vmax = max(math.sqrt(rw[4] ** 2 + rw[5] ** 2 + rw[6] ** 2) for rw in rows)
        vref = 0.01 * math.sqrt(g * d)
        out = max(lo - ang, ang - hi, 0.0) + (1.0 if vmax > vref else 0.0)
        return out, "angle of repose %.2f deg in [%g, %g] (H %.3f, R %.3f); max speed %.2g (rest: < %.2g)" % (
            ang, lo, hi, zmax, rmax, vmax, vref)
    return check


# the suite's heap numbers (dem10-aor-spheres-3d): d = 1, rho = 1, g = 2, k_n = 1e4, e = 0.3,
# k_t = 8235, mu = 1, rolling k_r = 500, gamma_r = 50, mu_r = 0.5, walls at x, y = +-3.5, dt 5e-4,
# 85000 steps, band [15, 55] degrees
AOR = dict(d=1.0, rho=1.0, g=2.0, k=1e4, e=0.3, kt=8235.0, gt=50.0, mu=1.0, kr=500.0, gr=50.0, mur=0.5,
           lo=15.0, hi=55.0, steps=85000, dt=5e-4)
# the numbers of the suite's clump scene (dem10-clump-3d), for the clump heap
AOR_CLUMP = dict(AOR, g=10.0, e=0.5, gt=20.0, mu=0.5, gr=20.0, mur=0.3)
AOR_WALLS = ["zplane 0 NULL", "xplane -3.5 3.5", "yplane -3.5 3.5"]
HEAP_SEED = [0]  # --seed: offset of the heaps' random starts (a heap is one sample of a statistic)


def aor_laws(meff, a):
    """tdem's laws for the heaps, each with tdem's rolling resistance (src/contact/rolling/sds.h: LAMMPS
    `rolling sds`, LIGGGHTS `rolling_friction tdem/sds`) with the suite's numbers a. Stock: LAMMPS
    `granular ... rolling sds`; LIGGGHTS `rolling_friction epsd2` (its spring from k_t, no dashpot)."""
    rs = " rolling sds %.17g %.17g %.17g" % (a["kr"], a["gr"], a["mur"])
    rprops = {"rollingStiffness": a["kr"], "rollingDamping": a["gr"], "coefficientRollingFriction": a["mur"]}
    lig_roll = " rolling_friction tdem/sds"

    def stock_lig(models, props):
        return (models + " rolling_friction epsd2", "", dict(props, coefficientRollingFriction=a["mur"]))
    base = lsd_e(a["e"], a["k"], meff, a["kt"] / a["k"], a["mu"])
    g = ("hooke %.17g %.17g tangential linear_history %.17g %.17g %.17g rolling sds %.17g %.17g %.17g "
         "damping coeff_restitution" % (a["k"], a["e"], a["kt"], a["gt"], a["mu"], a["kr"], a["gr"], a["mur"]))
    lsd = ("lsd + cundall_strack + rolling", base[1] + rs,
           (base[2][0] + lig_roll, base[2][1], dict(base[2][2], **rprops)),
           {"lammps": ("pair_style granular\npair_coeff * * " + g, "granular " + g), "bitwise": ()})
    # the same spring-dashpot in the form of equal physics with a stock style: stiffness k, damping
    # m* eta with eta from e at m* (damping mass), tangential damping gt m* eta (as linear_history's
    # gt times the normal damping), the Coulomb limit on spring + dashpot (LIGGGHTS: slip_rule
    # spring_dashpot; LIGGGHTS's `tangential history` caps the spring only, and its dashpot of
    # gammat dt = 3.5 is then unstable); stock granular hooke ... damping mass_velocity (also in 2022)
    ln = math.log(a["e"])
    eta = 2 * (-ln / math.sqrt(PI * PI + ln * ln)) * math.sqrt(a["k"] / meff)
    lk = lsd_k(a["k"], eta, a["kt"], a["gt"] * eta, a["mu"])
    gk = ("hooke %.17g %.17g tangential linear_history %.17g %.17g %.17g rolling sds %.17g %.17g %.17g "
          "damping mass_velocity" % (a["k"], eta, a["kt"], a["gt"], a["mu"], a["kr"], a["gr"], a["mur"]))
    lsdk = ("lsd stiffness + cundall_strack + rolling", lk[1] + rs,
            (lk[2][0] + lig_roll, lk[2][1] + " slip_rule spring_dashpot", dict(lk[2][2], **rprops)),
            {"lammps": ("pair_style granular\npair_coeff * * " + gk, "granular " + gk),
             "liggghts": stock_lig("model hooke/stiffness tangential history", lk[2][2]), "bitwise": ()})
    E, nu = 1e5, 0.3
    h = hertz(E, nu, a["mu"], damping=a["e"])
    gh = ("hertz/material %.17g %.17g %.17g tangential mindlin NULL 0 %.17g rolling sds %.17g %.17g %.17g damping tsuji"
          % (E, a["e"], nu, a["mu"], a["kr"], a["gr"], a["mur"]))
    hz = ("hertz tsuji + mindlin_deresiewicz + rolling", h[1] + rs,
          (h[2][0] + lig_roll, h[2][1], dict(h[2][2], **rprops)),
          {"lammps": ("pair_style granular\npair_coeff * * " + gh, "granular " + gh),
           "liggghts": stock_lig("model hertz tangential history", h[2][2]), "bitwise": ()})
    return [lsd, lsdk, hz]


@case("dem10_repose_spheres", "DEM-10", "a heap of 120 spheres with rolling resistance settles at an angle of "
      "repose atan(H/R) in [15, 55] deg, at rest", 0.0)
def dem10s():
    """The suite pours 120 spheres with fix pour from a 2.4 x 2.4 x 1.5 region at z = 3 ... 4.5; here the
    same 120 spheres start as a column of 3 x 3 spheres per layer (spacing 1.1, jitter +-0.03 from a
    fixed seed) from z = 3 up, the same in both engines and on any rank count."""
    import random
    rng = random.Random(20261202 + HEAP_SEED[0])
    a = AOR
    atoms = []
    for k in range(120):
        layer, cell = divmod(k, 9)
        ix, iy = divmod(cell, 3)
        x = ((ix - 1) * 1.1 + rng.uniform(-0.03, 0.03), (iy - 1) * 1.1 + rng.uniform(-0.03, 0.03), 3.0 + 1.1 * layer)
        atoms.append(dict(x=x, d=a["d"], rho=a["rho"]))
    sc = Scene((-4, 4, -4, 4, -0.5, 18.5), atoms, a["steps"], a["dt"], every=a["steps"], gravity=(0, 0, -a["g"]),
               wall=AOR_WALLS, skin=0.3, procs="2 1 1", ranks_bitwise=False)
    m = mass(atoms[0])
    return sc, aor_laws(m / 2, a), repose_check(a["lo"], a["hi"], a["g"], a["d"], len(atoms))


TETRA = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, math.sqrt(3) / 2, 0.0), (0.5, math.sqrt(3) / 6, math.sqrt(2.0 / 3.0))]


@case("dem10_repose_clumps", "DEM-10", "a heap of 30 rigid tetrahedral clumps (4 touching spheres) settles at an "
      "angle of repose atan(H/R) in [15, 55] deg, at rest", 0.0)
def dem10c():
    """The suite's clump (dem10-clump-3d: four unit spheres at the corners of a regular tetrahedron of
    edge 1) as a heap: 30 clumps of random orientation (fixed seed) on a 3 x 3 lattice of spacing 2.3
    per layer from z = 1.5 up, with the material numbers and gravity of the suite's clump scene (e = 0.5,
    mu = 0.5, mu_r = 0.3, g = 10). tdem: fix tdem/clump (bodies from the molecule IDs); LAMMPS stock:
    fix rigid/small molecule."""
    import random
    rng = random.Random(9183 + HEAP_SEED[0])
    a = AOR_CLUMP
    com = tuple(sum(p[i] for p in TETRA) / 4 for i in range(3))
    local = [tuple(p[i] - com[i] for i in range(3)) for p in TETRA]
    atoms = []
    for b in range(30):
        layer, cell = divmod(b, 9)
        ix, iy = divmod(cell, 3)
        c = ((ix - 1) * 2.3, (iy - 1) * 2.3, 1.5 + 2.3 * layer)
        q = quat_random(rng)
        for p in local:
            r = rotate(q, p)
            atoms.append(dict(x=tuple(c[i] + r[i] for i in range(3)), d=a["d"], rho=a["rho"], mol=b + 1))
    sc = Scene((-4, 4, -4, 4, -0.5, 11.5), atoms, a["steps"], a["dt"], every=a["steps"], gravity=(0, 0, -a["g"]),
               wall=AOR_WALLS, skin=0.3, procs="2 1 1", clump=[p + (a["d"] / 2,) for p in local], ranks_bitwise=False)
    mbody = 4 * mass(atoms[0])
    laws = aor_laws(mbody / 2, a)
    for law in laws:  # LIGGGHTS has no stock counterpart of fix tdem/clump in this scene
        law[3].pop("liggghts", None)
    return sc, laws, repose_check(a["lo"], a["hi"], a["g"], a["d"], len(atoms))


# ----------------------------------------------------------------------------- runner
# LAMMPS versions whose stock fix wall/gran hooke/history does what fix tdem/wall/gran lsd +
# cundall_strack does, bit for bit. 4Jul2026 agrees to round-off (its frictional wall was rewritten
# by PR 5007); 4Feb2025's frictional wall has the defect that PR 5007 fixed.
WALL_BITWISE = ("29Sep2021", "20220106")

def run_one(args, name, sc, law, check, np_, wd, stock=False):
    """Runs the scene with the law (or its stock equivalent); returns (error, text, frames)."""
    d = os.path.join(wd, "%s_%s_np%d%s" % (name, law[0].replace(" ", "").replace("+", "_"), np_, "_stock" if stock else ""))
    os.makedirs(d, exist_ok=True)
    text = (lammps_input if args.host == "lammps" else liggghts_input)(sc, law, np_, stock)
    exe = args.stock if stock and args.stock else args.exe
    with open(os.path.join(d, "in.case"), "w") as f:
        f.write(text)
    if args.host == "liggghts" or sc.data:
        with open(os.path.join(d, "scene.data"), "w") as f:
            f.write(scene_data(sc, args.host))
    if sc.clump:
        with open(os.path.join(d, "clump.txt"), "w") as f:
            f.write("".join("sphere %.17g %.17g %.17g %.17g\n" % s_ for s_ in sc.clump))
    cmd = [exe, "-in", "in.case", "-log", "log.case", "-echo", "none", "-screen", "none"]
    if np_ > 1:
        cmd = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    r = mpi_env.run(cmd, cwd=d, capture_output=True, text=True, errors="replace", timeout=300)
    if r.returncode != 0:
        log = open(os.path.join(d, "log.case"), errors="replace").read() if os.path.exists(os.path.join(d, "log.case")) else ""
        err = [l for l in (log + r.stdout + r.stderr).splitlines() if "ERROR" in l]
        return None, "run failed (exit %d): %s" % (r.returncode, err[0] if err else (r.stdout + r.stderr)[-200:]), None
    frames = read_traj(os.path.join(d, "traj.dump"))
    try:
        err, what = check(frames, law[0]) if check.__code__.co_argcount == 2 else check(frames)
    except Exception as ex:  # a malformed trajectory is a failure, not a crash of the suite
        return None, "check failed: %r" % ex, frames
    return err, what, frames


def final_diff(a, b):
    """Largest difference of the final velocities and spins, relative to the largest of them."""
    ra, rb = a[-1][1], b[-1][1]
    scale = max(max(abs(v) for v in row[4:7] + row[10:13]) for row in ra) or 1.0
    return max(max(abs(x - y) for x, y in zip(p[4:7] + p[10:13], q[4:7] + q[10:13])) for p, q in zip(ra, rb)) / scale


def traj_diff(a, b):
    """Largest absolute difference of all dumped values of two trajectories (inf if they differ in shape)."""
    if a is None or b is None or len(a) != len(b):
        return float("inf")
    d = 0.0
    for (sa, ra), (sb, rb) in zip(a, b):
        if sa != sb or len(ra) != len(rb):
            return float("inf")
        for x, y in zip(ra, rb):
            d = max(d, max(abs(u - v) for u, v in zip(x, y)))
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--host", choices=["lammps", "liggghts"], required=True)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--np", default="1,2", help="rank counts for the scenes of more than one particle")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--stock", default=None, help="executable for the stock styles (default: --exe)")
    ap.add_argument("--version", default="29Sep2021", help="LAMMPS version of --exe (e.g. 4Jul2026)")
    ap.add_argument("--case", default="all")
    ap.add_argument("--workdir", default=None)
    ap.add_argument("--table", default=None, help="append the result rows (markdown) to this file")
    ap.add_argument("--label", default=None, help="host label in the table (default: --host)")
    ap.add_argument("--seed", type=int, default=0, help="offset of the random starts of the DEM-10 heaps")
    args = ap.parse_args()
    HEAP_SEED[0] = args.seed
    wd = args.workdir or tempfile.mkdtemp(prefix="tdem_dem_suite_")
    os.makedirs(wd, exist_ok=True)
    names = list(CASES) if args.case == "all" else args.case.split(",")
    nps = [int(n) for n in args.np.split(",")]
    failed, rows, t0 = 0, [], time.time()
    for ci, name in enumerate(names):
        dem, physics, tol, fn = CASES[name]
        sc, laws, check = fn()
        for law in laws:
            if law[1 if args.host == "lammps" else 2] is None:
                print("SKIP %s %-22s %-34s: %s has no such law yet" % (dem, name, law[0], args.host), flush=True)
                rows.append((dem, name, physics, law[0], 0, None, tol, None, "not available in %s" % args.host))
                continue
            first = None
            for np_ in ([1] if len(sc.atoms) == 1 else nps):
                err, what, frames = run_one(args, name, sc, law, check, np_, wd)
                ok = err is not None and err <= tol
                extra = ""
                if first is None:
                    first = frames
                else:  # more ranks: the same trajectory
                    dn = traj_diff(first, frames)
                    if sc.ranks_bitwise:
                        extra = "; np %d vs np 1: %.2g" % (np_, dn)
                        ok = ok and dn <= 1e-12
                    else:
                        extra = ("; np %d vs np 1: %.2g (not required to be 0: the order of the force sums may differ, "
                                 "and the pour amplifies it)" % (np_, dn))
                stock = law[3].get(args.host)
                if stock and np_ == 1:
                    serr, swhat, sframes = run_one(args, name, sc, law, check, 1, wd, stock=True)
                    bit = args.host in law[3].get("bitwise", ())
                    if bit and args.host == "lammps" and sc.walls and args.version not in WALL_BITWISE:
                        bit = False  # the stock wall of this version differs (WALL_BITWISE)
                    dst = traj_diff(frames, sframes)
                    sname = stock[0].split("\n")[0].replace("pair_style ", "").replace("model ", "").split()[0]
                    if serr is None:  # e.g. damping coeff_restitution is not in LAMMPS 2021/2022
                        extra += "; stock %s: not available (%s)" % (sname, swhat.split("ERROR: ")[-1][:80])
                    elif not sc.ranks_bitwise:  # a heap: its own result, not a trajectory to compare
                        extra += "; stock %s: %s" % (sname, swhat)
                    elif bit:
                        extra += "; stock %s: error %.3g, trajectory difference %.2g (bitwise promised)" % (
                            sname, serr, dst)
                    else:
                        extra += "; stock %s: error %.3g, final velocities and spins differ by %.2g" % (
                            sname, serr, final_diff(frames, sframes))
                    if bit:
                        ok = ok and dst == 0.0
                failed += not ok
                print("%s %s %-22s %-34s np %d: %s error %s (tol %g) -- %s%s" % (
                    "PASS" if ok else "FAIL", dem, name, law[0], np_, args.host,
                    "%.3g" % err if err is not None else "-", tol, what, extra), flush=True)
                rows.append((dem, name, physics, law[0], np_, err, tol, ok, what + extra))
        print("[%d/%d cases, %.0f s]" % (ci + 1, len(names), time.time() - t0), flush=True)
    if args.table:
        with open(args.table, "a") as f:
            for dem, name, physics, law, np_, err, tol, ok, what in rows:
                f.write("| %s | %s | %s | %s | %s | %s | %g | %s | %s |\n" % (
                    dem, name, args.label or args.host, law, np_ or "-", "%.2g" % err if err is not None else "-", tol,
                    "pass" if ok else ("skip" if ok is None else "FAIL"), what))
    skipped = sum(1 for row in rows if row[7] is None)
    ran = len(rows) - skipped
    print(("%d of %d runs failed" % (failed, ran) if failed else "all %d runs passed" % ran) +
          (", %d law(s) not available in %s" % (skipped, args.host) if skipped else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
