# SPDX-License-Identifier: GPL-2.0-or-later
"""The scene of the legacy restart files in data/restart_v6/ (test_restart_legacy.py and
make_legacy_restarts.py): a head-on pair (relative speed 1 m/s) and a sphere that hits the floor
at 1 m/s while sliding at 0.5 m/s, all three contacts touching at step 20; the files are written
at step N1, in the unloading of every contact, for the three laws that restart format 7 stores by
name and values (walton_braun, thornton, power_law: modes 4-6 with members of their own in
formats 2-6)."""

TSL = "tangential cundall_strack 0.8 0.3"
RS = 0.005
MS = 0.01
# name, normal law line, head-on wall contact time at 1 m/s (approximate; sets N1, N2), time step
LAWS = [("walton_braun", "normal walton_braun 1e5 1.5625e5 2.0 " + TSL, 8.0e-4, 1.5e-6),
        ("thornton", "normal thornton 2e11 0.3 1e9 " + TSL, 6.0e-5, 1e-7),
        ("power_law", "normal power_law 1e7 1.5 2.915e7 " + TSL, 6.9e-4, 1e-6)]
# the law with other coefficients, for the control (the file's coefficients must matter)
OTHER = {"walton_braun": "normal walton_braun 1e5 4e5 2.0 " + TSL,
         "thornton": "normal thornton 1e11 0.3 1e9 " + TSL,
         "power_law": "normal power_law 1e7 1.5 5e7 " + TSL}

HEAD = """
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
comm_modify     vel yes
region          box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 box
"""
TAIL = """
neighbor        0.001 bin
neigh_modify    delay 0 every 1 check yes
fix             nve all nve/sphere
timestep        {dt!r}
"""
REPORT = "".join('print "RES %d $(x[%d]:%%.17g) $(z[%d]:%%.17g) $(vx[%d]:%%.17g) $(vz[%d]:%%.17g)"\n'
                 % (k, k, k, k, k) for k in (1, 2, 3))
STATE = 'print "STATE $(fx[1]:%.17g) $(fz[3]:%.17g) $(vx[2]-vx[1]:%.17g) $(vz[3]:%.17g)"\n'


def atoms(dt):
    gap = 20 * dt
    specs = [(-RS, 0.05, 0.5, 0.0), (RS + gap, 0.05, -0.5, 0.0), (0.02, RS + gap, 0.5, -1.0)]
    out = ["create_atoms 1 single %r 0 %r units box" % (x, z) for x, z, _, _ in specs]
    for k, (x, z, vx, vz) in enumerate(specs, 1):
        out.append("set atom %d diameter %r\nset atom %d mass %r\nset atom %d vx %r vz %r"
                   % (k, 2 * RS, k, MS, k, vx, vz))
    return "\n".join(out)


def steps(tc, dt):
    """N1 (the restart point) and N2 (the continuation)."""
    return 20 + int(0.7 * tc / dt), int(0.8 * tc / dt) + 100


def interaction(law):
    return "pair_style tdem/gran\npair_coeff * * %s\nfix floor all tdem/wall/gran %s zplane 0 NULL\n" % (law, law)


def base(law, dt):
    return HEAD + atoms(dt) + "\n" + interaction(law) + TAIL.format(dt=dt)


def results(out, key="RES"):
    vals = []
    for line in out.splitlines():
        if line.startswith(key + " "):
            vals += [float(x) for x in line.split()[1 if key == "STATE" else 2:]]
    return vals
