# SPDX-License-Identifier: GPL-2.0-or-later
"""Input texts of the LIGGGHTS host tests."""

# Material blocks: how the same physics is configured for each model.
# kn, kt [N/m], gamman, gammat [1/s] (per unit effective mass), mu, for 2 atom types.
STIFFNESS_PROPS = """
fix m_kn  all property/global kn peratomtypepair 2 6000 5500 5500 5000
fix m_kt  all property/global kt peratomtypepair 2 1800 1700 1700 1600
fix m_gn  all property/global gamman peratomtypepair 2 300 280 280 260
fix m_gt  all property/global gammat peratomtypepair 2 120 110 110 100
fix m_mu  all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4
"""

HOOKE_PROPS = """
fix m_E   all property/global youngsModulus peratomtype 5.e6 6.e6
fix m_vc  all property/global characteristicVelocity scalar 1.0
fix m_nu  all property/global poissonsRatio peratomtype 0.45 0.4
fix m_e   all property/global coefficientRestitution peratomtypepair 2 0.5 0.55 0.55 0.6
fix m_mu  all property/global coefficientFriction peratomtypepair 2 0.5 0.45 0.45 0.4
"""


def split_model(model_args):
    """'model A tangential B k1 v1 ...' -> ('model A tangential B', 'k1 v1 ...'): model keywords
    and settings (fix wall/gran wants its own keywords between the two)."""
    w = model_args.split()
    kw = ("model", "tangential", "cohesion", "rolling_friction", "surface")
    i = 0
    while i + 1 < len(w) and w[i] in kw:
        i += 2
    return " ".join(w[:i]), " ".join(w[i:])


def wall_line(fix_id, model_args, wall):
    models, settings = split_model(model_args)
    return "fix %s all wall/gran %s %s %s" % (fix_id, models, wall, settings)


def write_v_floor_stl(path):
    """A V-shaped floor (two planes falling 1.2 cm towards x = 0, 8 triangles) as ASCII STL."""
    def tri(a, b, c):
        return ("facet normal 0 0 0\n outer loop\n" + "".join("  vertex %g %g %g\n" % v for v in (a, b, c))
                + " endloop\nendfacet\n")
    h, L = 0.012, 0.04
    pts = {}
    for ix, x in enumerate((-L, 0.0, L)):
        for iy, y in enumerate((-L, 0.0, L)):
            pts[ix, iy] = (x, y, 0.002 + h * abs(x) / L)
    text = "solid floor\n"
    for ix in range(2):
        for iy in range(2):
            a, b, c, d = pts[ix, iy], pts[ix + 1, iy], pts[ix + 1, iy + 1], pts[ix, iy + 1]
            text += tri(a, b, c) + tri(a, c, d)
    with open(path, "w") as f:
        f.write(text + "endsolid floor\n")


def settling(model_args, props, steps=3000, dump_every=None, extra_end="", processors="",
             restart_read=None, reissue_pair=True, natoms=2400, thermo_every=500, seed_shift=0,
             mesh_floor=False):
    """A bed of two sphere types inserted in a box with six primitive walls, settling under
    gravity. model_args: the text after `pair_style gran` (also used for fix wall/gran).
    restart_read: continue from this restart file instead of inserting; reissue_pair=False then
    keeps the pair style the restart file names (LIGGGHTS restores the model from its hash, with
    default settings). mesh_floor: add a V-shaped mesh floor (fix mesh/surface + wall/gran mesh;
    write floor.stl with write_v_floor_stl first)."""
    dump_every = dump_every or steps
    if restart_read:
        head = """
atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
%s
read_restart %s
neighbor 0.0015 bin
neigh_modify delay 0
""" % (processors, restart_read)
        insert = ""
    else:
        head = """
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
%s
region box block -0.04 0.04 -0.04 0.04 0.0 0.16 units box
create_box 2 box
neighbor 0.0015 bin
neigh_modify delay 0
""" % processors
        insert = """
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0025
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2000 radius constant 0.0020
fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.038 0.038 -0.038 0.038 0.016 0.09 units box
fix ins all insert/pack seed %d distributiontemplate pdd1 maxattempt 300 insert_every once &
    overlapcheck yes all_in yes vel uniform -0.3 0.3 -0.3 0.3 -0.6 0.0 omega constant 0 0 0 &
    region ins particles_in_region %d
""" % (32452867 + seed_shift, natoms)
    walls = "\n".join(
        wall_line("w%d" % k, model_args, "primitive type 1 " + w)
        for k, w in enumerate(["xplane -0.04", "xplane 0.04", "yplane -0.04", "yplane 0.04",
                               "zplane 0.0", "zplane 0.16"]))
    if mesh_floor:
        walls = ("fix cad all mesh/surface file floor.stl type 1\n" + walls + "\n" +
                 wall_line("wmesh", model_args, "mesh n_meshes 1 meshes cad"))
    pair = "pair_style gran %s\npair_coeff * *" % model_args
    if restart_read and not reissue_pair:
        pair = ""
    return head + props + """
%s
timestep 0.00002
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
%s
%s
fix integr all nve/sphere
compute rke all erotate/sphere
thermo_style custom step atoms ke c_rke
thermo %d
thermo_modify lost ignore norm no format float %%.16g
dump d all custom %d dump.settle id type x y z vx vy vz omegax omegay omegaz
dump_modify d sort id format "%%d %%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
run %d
%s
""" % (pair, walls, insert, thermo_every, dump_every, steps, extra_end)
