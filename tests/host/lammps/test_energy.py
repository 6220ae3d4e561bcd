#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Energy accounting of pair tdem/gran (pair_style tdem/gran energy yes, compute tdem/energy):
the balance K~ + potential + taken = const closes, and the energy taken equals the closed forms.

Expected values are independent of src/contact: the closed forms below and LAMMPS's own
kinetic energy (thermo ke plus the rotational energy from the velocities).
1. Head-on impact of two spheres (1 m/s, m* = m/2) for every normal law, fix nve/sphere
   (velocity Verlet), thermo every step:
   * the balance residual c_E[10] stays below 1e-12 K0 at every step (round-off; a wrong sign of
     one part or of the relative motion gives ~1e-3 K0);
   * after the contact, the energy taken (c_E[5]) equals the kinetic energy lost, from LAMMPS's
     velocities, to 1e-12 K0;
   * where the law has a closed-form restitution e, the energy taken equals 1/2 m* v0^2 (1 - e^2)
     within 2/N K0 (N steps per contact, measured; the grid error of velocity Verlet, as the
     restitution tests' tolerance 2/N on e): lsd restitution, lsd stiffness (absolute damping,
     e = exp(-pi beta / sqrt(1 - beta^2))), walton_braun (e = sqrt(KL/KUL)), thornton (the
     closed form of test_thornton.py), extended_linear and extended_hertz with e_fit constant;
   * the part is the law's mechanism: a hysteretic law (walton_braun, thornton, power_law,
     luding) loses it in normal_elastic with normal_damping 0; an elastic spring with a damper
     (lsd, hertz, the extended laws) in normal_damping, and its spring returns what it took up to
     the grid error (|normal_elastic| < 2/N K0); no tangential or rolling part head-on.
2. Oblique impact (30 degrees, hertz + tsuji) for every tangential law, and with rolling sds:
   residual below 1e-12 K0, the energy taken equals the kinetic energy lost (translation and
   rotation from the velocities) to 1e-12 K0, the tangential part (and the rolling part) > 0.
3. A settling bed under gravity (fix gravity, 1 and 2 ranks, newton on and off): residual below
   1e-11 of the potential energy released (a contact that ends at a neighbour-list rebuild keeps its
   history: without that, 4e-4); the totals of 2 ranks equal those of 1 rank to 1e-9;
   the per-atom array summed (compute reduce) equals the global vector, the local array's rows
   summed agree between ranks and newton settings (each contact once); in the head-on impacts the
   contact's local row holds the energy taken while it lasts; read_restart continues the
   totals of the run that wrote the file (1e-12; the ended contacts' share is in the per-atom store,
   the current contacts' in the contact history).
2a. fix tdem/integrate: velocity_verlet, symplectic_euler, leapfrog, position_verlet close the
   balance to 1e-13 K0 with the form the compute takes from the scheme; the others (the schemes
   whose force sees a predicted velocity, Beeman, Adams-Bashforth, Gear, Taylor) leave a residual
   above 1e-8 K0, which the compute warns about (in a host it holds the scheme's energy error and
   the difference between the velocity the pair style sees and the step's drift: 8 % of K0 at 50
   steps per contact; the harness's residual, tdem-collide --energy on, is the energy error alone).
2b. Walls, fix tdem/wall/gran energy yes: a sphere head-on against a wall at rest vs the closed
   form (m* = m); oblique with spin and rolling; a wiggling and a shearing wall, whose work c_E[8]
   closes the balance: kinetic energy lost = taken - walls' work (1e-12).
2c. A grate stroke (fix tdem/grate energy yes, a fixed and a moving row, gravity, 1 and 2 ranks):
   the bars' work c_E[8] > 0 and the residual below 1e-11 of the energy moved.
5. The example input_scripts/lammps/in.tdem_energy (shortened) runs on 2 ranks with its residual at
   round-off (1e-11 of the potential energy released) and work done by its wiggling floor.
4. Bad input: compute tdem/energy without energy yes, a bad energy value, energy with
   grid_correction give ERROR lines.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.energy")
EXE = args["tdem"]
RHO, R, V0 = 2500.0, 0.01, 0.5
M = RHO * 4.0 / 3.0 * math.pi * R ** 3
MSTAR = M / 2.0
K0 = 2 * 0.5 * M * V0 * V0


def e_lsd_abs(k, g):
    beta = g / (2.0 * math.sqrt(k * MSTAR))
    return math.exp(-math.pi * beta / math.sqrt(1.0 - beta * beta))


def e_thornton(e_mod, nu, py):
    es = e_mod / (2 * (1 - nu * nu))
    reff = R / 2
    k = 4.0 / 3.0 * es * math.sqrt(reff)
    xi_y = reff * (math.pi * py / (2 * es)) ** 2
    vy = math.sqrt(4 * k * xi_y ** 2.5 / (5 * MSTAR))
    r = vy / (2 * V0)
    if r >= 1:
        return 1.0
    return math.sqrt(6 * math.sqrt(3) / 5 * (1 - r * r / 6)) * (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25


TS = " tangential cundall_strack 0.8 0.3"
# name, normal law, closed-form e (None: none), hysteretic
LAWS = [
    ("lsd restitution", "normal lsd restitution 0.8 5e-4" + TS, 0.8, False),
    ("lsd stiffness", "normal lsd stiffness 2e5 8 tangential cundall_strack 5.7e4 0 0.3 damping absolute",
     e_lsd_abs(2e5, 8.0), False),
    ("lsd limit_force", "normal lsd restitution 0.6 5e-4" + TS + " limit_force yes", None, False),
    ("hertz tsuji", "normal hertz 1e8 0.3 damping tsuji 0.8" + TS, None, False),
    ("walton_braun", "normal walton_braun 2e5 4.08e5" + TS, math.sqrt(2e5 / 4.08e5), True),
    ("thornton", "normal thornton 1e9 0.3 2e7" + TS, e_thornton(1e9, 0.3, 2e7), True),
    ("power_law", "normal power_law 1e7 1.5 2.915e7" + TS, None, True),
    ("luding", "normal luding 1e5 5e5 0.05" + TS, None, True),
    ("extended_linear", "normal extended_linear e_fit constant 0.6 tc_fit constant 5e-4" + TS, 0.6, False),
    ("extended_hertz", "normal extended_hertz 1e8 0.3 e_fit constant 0.5" + TS, 0.5, False),
    ("continuous_potential", "normal continuous_potential 2e-4 36 0.05" + TS, None, False),
]

SCENE = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          {newton}
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box      1 box
create_atoms    1 single {x1!r} 0 {z1!r} units box
create_atoms    1 single {x2!r} 0 {z2!r} units box
set             group all diameter {d!r}
set             group all density {rho!r}
velocity        all set 0 0 0
set             atom 1 vz {v!r}
set             atom 2 vz {mv!r}
set             atom 1 omega 0 {spin!r} 0
neighbor        0.002 bin
neigh_modify    delay 0
pair_style      tdem/gran energy yes
pair_coeff      * * {law}
fix             nve all nve/sphere
timestep        {dt!r}
compute         E all tdem/energy
compute         rot all erotate/sphere
compute         kt all ke
variable        ktot equal c_kt+c_rot
dump            loc all local 1 contacts.txt c_E[1] c_E[2] c_E[7]
dump_modify     loc format float %.17g
thermo_style    custom step c_E[1] c_E[2] c_E[3] c_E[4] c_E[5] c_E[6] c_E[7] c_E[8] c_E[9] c_E[10] v_ktot
thermo_modify   format float %.17g
thermo          1
run             {n}
"""


def impact(law, dt=1e-6, n=1600, offset=0.0, spin=0.0, newton="off"):
    gap = 2e-5
    zc = R + gap / 2 if offset == 0.0 else math.sqrt((2 * R) ** 2 - offset ** 2) / 2 + gap / 2
    text = SCENE.format(newton=newton, x1=-offset / 2, z1=-zc, x2=offset / 2, z2=zc, d=2 * R, rho=RHO, v=V0,
                        mv=-V0, spin=spin, law=law, dt=dt, n=n)
    d = lc.workdir("energy")
    _, out = lc.run(EXE, text, d)
    rows = [list(map(float, r.split())) for r in lc.thermo_blocks(out)[1:]]
    local = local_sums(os.path.join(d, "contacts.txt"))
    for r in rows:  # column 12: the local array's last column summed (the current contacts)
        r.append(local.get(int(r[0]), 0.0))
    return rows


def local_sums(path, col=-1):
    """{step: sum of column col over the rows} of a dump local file."""
    out, lines, k = {}, open(path).read().splitlines(), 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            head = k + 9  # TIMESTEP, step, NUMBER OF ENTRIES, n, BOX BOUNDS + 3 lines, ENTRIES
            out[step] = sum(float(lines[head + m].split()[col]) for m in range(n))
            k = head + n
        else:
            k += 1
    return out


def contact_steps(rows):
    taken = [r[5] for r in rows]
    moving = [k for k in range(1, len(taken)) if taken[k] != taken[k - 1]]
    return (moving[-1] - moving[0] + 1) if moving else 0


# 1. head-on, every normal law
for name, law, e, hyst in LAWS:
    # the continuous potential's contact lasts about 4 ms at these values
    rows = impact(law, dt=2e-6, n=3200) if name == "continuous_potential" else impact(law)
    n = contact_steps(rows)
    last = rows[-1]
    parts = last[1:5]
    res = max(abs(r[10]) for r in rows)
    lost = rows[0][11] - last[11]
    print("%-20s N %4d  taken %.9e (elastic %.3e damping %.3e tangential %.1e rolling %.1e)  K lost %.9e  "
          "residual max %.2e K0" % (name, n, last[5], parts[0], parts[1], parts[2], parts[3], lost, res / K0))
    chk.check(n > 50 and last[5] > 0.0, "%s: the contact happened and ended (N = %d steps)" % (name, n))
    chk.check(res < 1e-12 * K0, "%s: balance residual %.2e K0 < 1e-12 at every step" % (name, res / K0))
    chk.check(abs(last[5] - lost) < 1e-12 * K0,
              "%s: energy taken %.12e = kinetic energy lost %.12e (1e-12 K0)" % (name, last[5], lost))
    if e is not None:
        cf = 0.5 * MSTAR * (2 * V0) ** 2 * (1 - e * e)
        chk.check(abs(last[5] - cf) < 2.0 / n * K0,
                  "%s: energy taken %.6e vs closed form 1/2 m* v0^2 (1-e^2) = %.6e (e = %.5f): %.2e K0 < 2/N"
                  % (name, last[5], cf, e, abs(last[5] - cf) / K0))
    if hyst:
        chk.check(parts[0] > 0.0 and abs(parts[1]) < 1e-12 * K0,
                  "%s: hysteretic: lost in normal_elastic (%.3e), normal_damping %.1e (round-off of the force "
                  "minus its elastic part)" % (name, parts[0], parts[1]))
    else:
        chk.check(parts[1] > 0.0 and abs(parts[0]) < 2.0 / n * K0,
                  "%s: damped spring: normal_damping %.3e, |normal_elastic| %.2e K0 < 2/N" % (name, parts[1],
                                                                                          abs(parts[0]) / K0))
    chk.check(abs(parts[2]) < 1e-15 * K0 and parts[3] == 0.0, "%s: no tangential, no rolling part head-on" % name)
    # the local array (one row per current contact): during the contact its row holds everything
    # taken so far, after it the contact has no row
    during = [r for r in rows if r[12] != 0.0]
    chk.check(len(during) >= n - 2 and all(abs(r[12] - r[5]) <= 1e-15 * K0 for r in during) and last[12] == 0.0,
              "%s: the local row of the contact holds the energy taken during the contact (%d steps)"
              % (name, len(during)))

# 2. oblique, every tangential law
HZ = "normal hertz 1e8 0.3 damping tsuji 0.8 "
TANG = [
    ("cundall_strack", HZ + "tangential cundall_strack 0.8 0.3", False),
    ("haff_werner", HZ + "tangential haff_werner 20 0.3", False),
    ("linear_spring", HZ + "tangential linear_spring 0 0.2857 0.5 0.3", False),
    ("walton_braun", HZ + "tangential walton_braun 0 0.8 0.3", False),
    ("mindlin_deresiewicz", HZ + "tangential mindlin_deresiewicz 1e8 0.3 0.3", False),
    ("mindlin_no_slip", HZ + "tangential mindlin_no_slip 1e8 0.3 0.5 0.3", False),
    ("di_renzo", HZ + "tangential di_renzo 1e8 0.3 0.3", False),
    ("rolling sds", HZ + "tangential cundall_strack 0.8 0.3 rolling sds 2 0.001 0.05", True),
]
SPIN = -60.0  # rad/s of sphere 1 about y (without it both spheres spin alike and nothing rolls)
for name, law, roll in TANG:
    rows = impact(law, offset=R, spin=SPIN, n=1600)
    last = rows[-1]
    res = max(abs(r[10]) for r in rows)
    lost = rows[0][11] - last[11]
    print("%-20s taken %.9e (elastic %.3e damping %.3e tangential %.3e rolling %.3e)  K lost %.9e  residual max "
          "%.2e K0" % (name, last[5], last[1], last[2], last[3], last[4], lost, res / K0))
    chk.check(res < 1e-12 * K0, "oblique %s: balance residual %.2e K0 < 1e-12" % (name, res / K0))
    chk.check(abs(last[5] - lost) < 1e-12 * K0 and contact_steps(rows) > 50,
              "oblique %s: energy taken %.12e = kinetic energy lost %.12e" % (name, last[5], lost))
    chk.check(last[3] > 0.0, "oblique %s: tangential part %.3e > 0" % (name, last[3]))
    if roll:
        chk.check(last[4] != 0.0, "oblique %s: rolling part %.3e" % (name, last[4]))

# 2a. the integrators of fix tdem/integrate (the compute takes the scheme's form): the symplectic
# ones close the balance to round-off, the others leave their energy error, which is reported
SCHEMES_EXACT = ("velocity_verlet", "symplectic_euler", "leapfrog", "position_verlet")
SCHEMES_OTHER = ("velocity_verlet_sync", "velocity_verlet_ab2", "beeman", "ab3", "gear5", "taylor3")
for scheme in SCHEMES_EXACT + SCHEMES_OTHER:
    text = SCENE.format(newton="off", x1=0.0, z1=-(R + 1e-5), x2=0.0, z2=R + 1e-5, d=2 * R, rho=RHO, v=V0, mv=-V0,
                        spin=0.0, law="normal lsd restitution 0.8 5e-4" + TS, dt=1e-5, n=160)
    text = text.replace("fix             nve all nve/sphere", "fix             nve all tdem/integrate scheme " + scheme)
    d = lc.workdir("energy_scheme")
    _, out = lc.run(EXE, text, d)
    rows = [list(map(float, r.split())) for r in lc.thermo_blocks(out)[1:]]
    res = max(abs(r[10]) for r in rows) / K0
    warned = "will not stay at round-off (the scheme's energy error" in out
    print("scheme %-22s 50 steps per contact: residual max %.2e K0, taken %.6e J" % (scheme, res, rows[-1][5]))
    if scheme in SCHEMES_EXACT:
        chk.check(res < 1e-13 and not warned, "scheme %s: the balance closes (%.1e K0), no warning" % (scheme, res))
    else:
        chk.check(res > 1e-8 and warned, "scheme %s: its residual %.1e K0 is reported, with a warning" % (scheme, res))

# 2b. walls (fix tdem/wall/gran energy yes): a sphere on a wall at rest against the closed form
# (m* = m), oblique with spin, and walls that move (wiggle along the normal, shear): the wall's work
# c_E[8] closes the balance
WALL = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box      1 box
create_atoms    1 single 0 0 {z!r} units box
set             group all diameter {d!r}
set             group all density {rho!r}
velocity        all set {vx!r} 0 {vz!r}
set             atom 1 omega 0 {spin!r} 0
neighbor        0.002 bin
neigh_modify    delay 0
pair_style      tdem/gran energy yes
pair_coeff      * * {law}
fix             w all tdem/wall/gran {law} zplane 0 NULL {motion} energy yes
fix             nve all nve/sphere
timestep        1e-6
compute         E all tdem/energy
compute         A all tdem/energy
compute         S all reduce sum c_A[5] c_A[8]
compute         rot all erotate/sphere
compute         kt all ke
variable        ktot equal c_kt+c_rot
thermo_style    custom step c_E[1] c_E[2] c_E[3] c_E[4] c_E[5] c_E[6] c_E[7] c_E[8] c_E[9] c_E[10] v_ktot c_S[1] c_S[2]
thermo_modify   format float %.17g
thermo          1
run             {n}
"""
KW = 0.5 * M * 1.0  # 1 m/s against the wall
for name, law, vx, motion, n in (
        ("lsd head-on", "normal lsd restitution 0.8 5e-4" + TS, 0.0, "", 1200),
        ("hertz oblique", HZ + "tangential mindlin_deresiewicz 1e8 0.3 0.3 rolling sds 2 0.001 0.05", 0.6, "", 1400),
        ("walton_braun wiggle", "normal walton_braun 2e5 4.08e5" + TS, 0.0, "wiggle z 2e-4 2e-3", 1600),
        ("lsd shear", "normal lsd restitution 0.7 5e-4" + TS, 0.2, "shear x -0.5", 1200)):
    text = WALL.format(z=R + 2e-5, d=2 * R, rho=RHO, vx=vx, vz=-1.0, spin=-20.0 if vx else 0.0, law=law,
                       motion=motion, n=n)
    _, out = lc.run(EXE, text, lc.workdir("energy_wall"))
    rows = [list(map(float, r.split())) for r in lc.thermo_blocks(out)[1:]]
    last = rows[-1]
    k0 = rows[0][11]
    res = max(abs(r[10]) for r in rows)
    print("wall %-20s taken %.9e (elastic %.3e damping %.3e tangential %.3e rolling %.3e)  wall work %.3e  "
          "K %.6e -> %.6e  residual max %.2e K0" % (name, last[5], last[1], last[2], last[3], last[4], last[8], k0,
                                                   last[11], res / k0))
    chk.check(res < 1e-12 * k0 and last[5] > 0.0, "wall %s: balance residual %.2e K0 < 1e-12" % (name, res / k0))
    chk.check(abs(last[12] - last[5]) < 1e-15 * k0 and abs(last[13] - last[8]) < 1e-15 * k0,
              "wall %s: the per-atom array summed equals the vector (taken, wall work)" % name)
    if motion:
        chk.check(abs((k0 - last[11]) - (last[5] - last[8])) < 1e-12 * k0 and last[8] != 0.0,
                  "wall %s: kinetic energy lost %.9e = taken - wall work %.9e (wall work %.3e)"
                  % (name, k0 - last[11], last[5] - last[8], last[8]))
    else:
        chk.check(abs((k0 - last[11]) - last[5]) < 1e-12 * k0 and last[8] == 0.0,
                  "wall %s: kinetic energy lost %.9e = taken (a wall at rest does no work)" % (name, k0 - last[11]))
    if name == "lsd head-on":
        nw = contact_steps(rows)
        cf = KW * (1 - 0.8 ** 2)
        chk.check(abs(last[5] - cf) < 2.0 / nw * k0, "wall %s: taken %.6e vs closed form 1/2 m v0^2 (1-e^2) = %.6e: "
                  "%.2e K0 < 2/N (N = %d)" % (name, last[5], cf, abs(last[5] - cf) / k0, nw))

# 2c. a grate stroke (fix tdem/grate energy yes): spheres on a fixed and a moving row of bars under
# gravity, 1 and 2 ranks; the bars' work closes the balance
GRATE = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f p f
newton          {newton}
comm_modify     vel yes
{processors}
region          box block -0.05 0.25 -0.027 0.027 -0.1 0.1 units box
create_box      1 box
{atoms}
set             group all diameter 0.01
set             group all density 2500
neighbor        0.002 bin
neigh_modify    delay 0
pair_style      tdem/gran energy yes
pair_coeff      * * {law}
fix             gr all tdem/grate {law} rows 2 bar_length 0.1 bar_height 0.03 bar_thickness 0.012 bar_gap 0.006 &
                step_height 0.01 width 0.054 row_group -1 0 profile sinusoidal stroke 0.03 period 0.1 energy yes
fix             grav all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        2e-5
compute         E all tdem/energy
compute         A all tdem/energy
compute         S all reduce sum c_A[5] c_A[8]
thermo_style    custom step c_E[1] c_E[2] c_E[3] c_E[4] c_E[5] c_E[6] c_E[7] c_E[8] c_E[9] c_E[10] c_S[1] c_S[2]
thermo_modify   format float %.17g
thermo          500
run             10000
"""
atoms = "\n".join("create_atoms 1 single %r %r %r units box" % (x, y, z)
                   for x in (0.02, 0.035, 0.05, 0.065, 0.08, 0.12, 0.135, 0.15, 0.165, 0.18)
                   for y in (-0.018, 0.0, 0.018) for z in (0.006, 0.018, 0.03))
GLAW = "normal lsd restitution 0.3 1e-3 tangential cundall_strack 0.8 0.4"
for np_, newton in ((1, "off"), (2, "on")):
    text = GRATE.format(newton=newton, processors="processors 2 1 1" if np_ == 2 else "", atoms=atoms, law=GLAW)
    _, out = lc.run(EXE, text, lc.workdir("energy_grate"), np_=np_, mpirun=args["mpirun"])
    rows = [list(map(float, r.split())) for r in lc.thermo_blocks(out)[1:]]
    last = rows[-1]
    scale = abs(rows[0][7] - last[7]) + abs(last[8]) + last[5]
    res = max(abs(r[10]) for r in rows)
    print("grate np %d newton %-3s: taken %.9e (elastic %.3e damping %.3e tangential %.3e), bars' work %.6e, "
          "potential %.6e -> %.6e, residual max %.2e of the energy moved" % (np_, newton, last[5], last[1], last[2],
                                                                           last[3], last[8], rows[0][7], last[7],
                                                                           res / scale))
    chk.check(last[8] > 0.0 and last[3] > 0.0 and res < 1e-11 * scale,
              "grate stroke np %d newton %s: the moving bars did work (%.3e J), balance residual %.2e of the "
              "energy moved < 1e-11 over 10000 steps" % (np_, newton, last[8], res / scale))
    chk.check(abs(last[11] - last[5]) < 1e-13 * scale and abs(last[12] - last[8]) < 1e-13 * scale,
              "grate stroke np %d newton %s: the per-atom array summed equals the vector (taken, bars' work)"
              % (np_, newton))

# 3. a settling bed on a frozen layer of spheres, periodic sideways, under gravity
BED = """
units           si
atom_style      sphere
atom_modify     map array
boundary        p p f
newton          {newton}
comm_modify     vel yes
read_data       {data}
group           floor id <= 36
velocity        floor set 0 0 0
neighbor        0.001 bin
neigh_modify    delay 0
pair_style      tdem/gran energy yes
pair_coeff      * * {law}
fix             g all gravity 9.81 vector 0 0 -1
fix             freeze floor freeze
fix             nve all nve/sphere
timestep        1e-5
compute         E all tdem/energy
compute         A all tdem/energy
compute         S all reduce sum c_A[1] c_A[2] c_A[3] c_A[4] c_A[5] c_A[6] c_A[7] c_A[8]
dump            loc all local {every} contacts.txt c_A[1] c_A[2] c_A[7]
dump_modify     loc format float %.17g
thermo_style    custom step c_E[1] c_E[2] c_E[3] c_E[4] c_E[5] c_E[6] c_E[7] c_E[8] c_E[9] c_E[10] c_S[1] c_S[2] c_S[3] c_S[4] c_S[5] c_S[6] c_S[7] c_S[8]
thermo_modify   format float %.17g
thermo          {every}
{body}
"""
BED_LAW = "normal lsd stiffness 2000 0.5 tangential cundall_strack 600 0.2 0.5 damping absolute rolling sds 1e-3 0 0.05"


def bed_data(path):
    """A floor of 6 x 6 spheres (4.8 mm, 5 mm apart: periodic in x and y, ids 1-36, frozen by the
    scene) and 6 x 6 x 4 free spheres above it (4.0-4.6 mm, velocities +-0.1 m/s)."""
    rows = []
    for iz in range(5):
        for iy in range(6):
            for ix in range(6):
                k = len(rows) + 1
                d = 0.0048 if iz == 0 else 0.0040 + 0.0006 * ((k * 7919) % 101) / 100
                v = [0.0] * 3 if iz == 0 else [0.2 * (((k * p) % q) / (q - 1) - 0.5)
                                                for p, q in ((104729, 97), (7907, 89), (6101, 83))]
                rows.append((k, d, 0.0025 + 0.005 * ix, 0.0025 + 0.005 * iy, 0.003 + 0.0055 * iz, v))
    with open(path, "w") as f:
        f.write("tdem energy bed\n\n%d atoms\n1 atom types\n0 0.03 xlo xhi\n0 0.03 ylo yhi\n0 0.05 zlo zhi\n\n"
                "Atoms # sphere\n\n" % len(rows))
        for k, d, x, y, z, v in rows:
            f.write("%d 1 %r 2500 %r %r %r\n" % (k, d, x, y, z))
        f.write("\nVelocities\n\n")
        for k, d, x, y, z, v in rows:
            f.write("%d %r %r %r 0 0 0\n" % (k, v[0], v[1], v[2]))


def bed(np_, newton, body, every=500, data=None):
    d = lc.workdir("energy_bed")
    if data is None:
        data = os.path.join(d, "bed.data")
        bed_data(data)
    text = BED.format(newton=newton, data=data, law=BED_LAW, every=every, body=body)
    _, out = lc.run(EXE, text, d, np_=np_, mpirun=args["mpirun"])
    rows = [list(map(float, r.split())) for r in lc.thermo_blocks(out) if not r.startswith("Step")]
    local = local_sums(os.path.join(d, "contacts.txt"))
    for r in rows:  # column 19: the local array's last column summed (the current contacts)
        r.append(local.get(int(r[0]), 0.0))
    return rows, d


NSTEP = 20000
runs = {}
for np_, newton in ((1, "off"), (1, "on"), (2, "on"), (2, "off")):
    rows, _ = bed(np_, newton, "run %d" % NSTEP)
    runs[(np_, newton)] = rows
    released = rows[0][7] - rows[-1][7]
    res = max(abs(r[10]) for r in rows)
    last = rows[-1]
    print("bed np %d newton %-3s: taken %.9e (elastic %.3e damping %.3e tangential %.3e rolling %.3e), "
          "potential released %.6e, K~ %.3e, residual max %.2e of it" % (np_, newton, last[5], last[1], last[2],
                                                                        last[3], last[4], released, last[6],
                                                                        res / released))
    chk.check(released > 0 and last[5] > 0.5 * released and min(last[1:5]) > 0,
              "bed np %d newton %s: the bed settled (taken %.3e of the released %.3e; every part > 0)"
              % (np_, newton, last[5], released))
    chk.check(res < 1e-11 * released, "bed np %d newton %s: balance residual %.2e of the released potential energy "
              "< 1e-11 over %d steps" % (np_, newton, res / released, NSTEP))
    peratom = max(abs(r[11 + k] - r[1 + k]) for r in rows for k in range(5)) / last[5]
    bodies = max(abs(r[16] - r[6]) + abs(r[17] - r[7]) for r in rows) / released
    chk.check(peratom < 1e-12 and bodies < 1e-12, "bed np %d newton %s: the per-atom array summed equals the "
              "global vector (%.1e, K~ and potential %.1e)" % (np_, newton, peratom, bodies))
# 1 and 2 ranks, newton on and off, on the first steps (before round-off differences of the sums
# grow through the contacts)
short = {}
for np_, newton in ((1, "off"), (1, "on"), (2, "on"), (2, "off")):
    rows, _ = bed(np_, newton, "run 2000", every=2000)
    short[(np_, newton)] = rows[-1]
ref = short[(1, "off")]
for key, row in short.items():
    # 1-7 the vector, 19 the current contacts' rows of the local array summed (each contact once)
    dev = max(abs(row[k] - ref[k]) for k in list(range(1, 8)) + [19]) / ref[5]
    chk.check(dev < 1e-9 and row[19] > 0.0, "bed np %d newton %s: after 2000 steps the totals and the local rows "
              "summed (%.6e) equal np 1 newton off to %.1e (of the energy taken)" % (key[0], key[1], row[19], dev))

# a restart in the middle: read_restart and run continues the totals of the run that wrote it
# (a run split at the same step: LAMMPS's own restart reproduces that trajectory bit for bit)
d0 = lc.workdir("energy_restart")
data = os.path.join(d0, "bed.data")
bed_data(data)
for np_ in (1, 2):
    rfile = os.path.join(d0, "bed%d.restart" % np_)
    whole, _ = bed(np_, "on", "run 1500\nwrite_restart %s\nrun 1500" % rfile, every=1500, data=data)
    text = ("read_restart %s\nneighbor 0.001 bin\nneigh_modify delay 0\nfix g all gravity 9.81 vector 0 0 -1\n"
            "fix freeze floor freeze\nfix nve all nve/sphere\ntimestep 1e-5\n"
            "compute E all tdem/energy\nthermo_style custom step c_E[1] c_E[2] c_E[3] c_E[4] c_E[5] c_E[6] "
            "c_E[7] c_E[8]\nthermo_modify format float %%.17g\nthermo 1500\nrun 1500\n" % rfile)
    _, out = lc.run(EXE, text, d0, name="in.cont%d" % np_, np_=np_, mpirun=args["mpirun"])
    cont = [list(map(float, r.split())) for r in lc.thermo_blocks(out) if not r.startswith("Step")]
    at_restart = [r for r in whole if r[0] == 1500][0]
    dev = max(abs(cont[-1][k] - whole[-1][k]) for k in range(1, 8)) / whole[-1][5]
    print("restart np %d: taken %.15e (continued) vs %.15e (written by the run)" % (np_, cont[-1][5], whole[-1][5]))
    # (the sums over the ranks may add in another order after read_restart: the last bit)
    chk.check(abs(cont[0][5] - at_restart[5]) <= 1e-14 * at_restart[5] and dev < 1e-12,
              "restart np %d: the restart carries the energy taken (%.12e at the restart step) and continues the "
              "run's totals to %.1e" % (np_, cont[0][5], dev))
    # a control: without the store of ended contacts the restart would lose their share
    chk.check(cont[0][5] > 0.0 and at_restart[1] > 0.0, "restart np %d: nonzero totals at the restart" % np_)

# 5. the example input_scripts/lammps/in.tdem_energy (shortened to 60000 steps) on 2 ranks: its balance
# residual stays at round-off, the wiggling floor does work
ex = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts", "lammps",
                  "in.tdem_energy")
text = open(ex).read().replace("run             200000", "run             60000").replace(
    "thermo_modify   format float %.6g", "thermo_modify   format float %.17g")
_, out = lc.run(EXE, text, lc.workdir("energy_example"), np_=2, mpirun=args["mpirun"])
rows = [list(map(float, r.split())) for r in lc.thermo_blocks(out)[1:]]
released = rows[0][6] - rows[-1][6]
res = max(abs(r[8]) for r in rows)
print("example in.tdem_energy, 2 ranks: taken %.6e J, potential released %.6e J, floor's work %.6e J, residual max "
      "%.2e of the potential released" % (rows[-1][5], released, rows[-1][7], res / released))
chk.check(released > 0 and rows[-1][7] > 0 and res < 1e-11 * released,
          "example in.tdem_energy: the floor did work (%.3e J), residual %.2e of the potential released"
          % (rows[-1][7], res / released))

sys.exit(chk.done())
