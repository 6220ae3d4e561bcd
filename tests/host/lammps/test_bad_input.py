#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Bad input to pair tdem/gran and fix tdem/wall/gran ends with a LAMMPS error (error->all):
exit status > 0 (not a signal, no segfault), an 'ERROR' line, and a message that names the
keyword, the offending value and what is allowed. A good input is run as a control."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.bad_input")

BASE = """
units si
atom_style sphere
boundary f f f
newton off
comm_modify vel yes
region box block 0 0.1 0 0.1 0 0.1 units box
create_box 2 box
create_atoms 1 single 0.05 0.05 0.05 units box
create_atoms 2 single 0.05 0.05 0.0545 units box
set group all diameter 0.005
set group all density 2500
fix nve all nve/sphere
timestep 1e-6
{body}
run 10
"""
GOOD = "normal lsd stiffness 2000 50 tangential cundall_strack 600 25 0.5"
GOODR = "normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8 0.5"
GOODH = "normal hertz 2e8 0.3 damping tsuji 0.7 tangential cundall_strack 0.8 0.5 limit_force yes"
WALL = "fix w all tdem/wall/gran {law} {wall}"


def pair(coeff, style="pair_style tdem/gran"):
    return "%s\npair_coeff * * %s" % (style, coeff)


CASES = [
    # name, body, expected substrings
    ("unknown normal law", pair("normal hooke 2000 50 tangential cundall_strack 600 25 0.5"),
     ["normal law 'hooke' is unknown",
      "allowed: lsd, hertz, walton_braun, thornton, power_law, luding, extended_linear, extended_hertz"]),
    # normal hertz
    ("hertz value count", pair("normal hertz 2e8 0.3 0.1 tangential cundall_strack 0.8 0.5"),
     ["normal hertz needs 2 values (E NU", "or 4 values", "got 3"]),
    ("hertz negative E", pair("normal hertz -2e8 0.3 tangential cundall_strack 0.8 0.5"),
     ["normal hertz E (Young's modulus) = -200000000 must be > 0"]),
    ("hertz nu above 0.5", pair("normal hertz 2e8 0.6 tangential cundall_strack 0.8 0.5"),
     ["normal hertz NU (Poisson ratio) = 0.6 is outside the allowed range (-1, 0.5]"]),
    ("hertz nu -1", pair("normal hertz 2e8 0.3 2e8 -1 tangential cundall_strack 0.8 0.5"),
     ["normal hertz NU2 (Poisson ratio) = -1 is outside the allowed range (-1, 0.5]"]),
    ("hertz tsuji e above 1", pair("normal hertz 2e8 0.3 damping tsuji 1.2 tangential cundall_strack 0.8 0.5"),
     ["normal hertz damping tsuji E = 1.2 is outside the allowed range (0, 1]"]),
    ("hertz tsuji e zero", pair("normal hertz 2e8 0.3 damping tsuji 0 tangential cundall_strack 0.8 0.5"),
     ["normal hertz damping tsuji E = 0 is outside the allowed range (0, 1]"]),
    ("hertz negative gamma", pair("normal hertz 2e8 0.3 damping linear -3 tangential cundall_strack 0.8 0.5"),
     ["normal hertz damping linear GAMMA = -3 must be >= 0"]),
    ("hertz general count", pair("normal hertz 2e8 0.3 damping general 0.5 tangential cundall_strack 0.8 0.5"),
     ["normal hertz damping general needs 2 values (THETA C), got 1"]),
    ("hertz negative theta", pair("normal hertz 2e8 0.3 damping general -0.5 1 tangential cundall_strack 0.8 0.5"),
     ["normal hertz damping general THETA = -0.5 must be >= 0"]),
    ("hertz unknown damping", pair("normal hertz 2e8 0.3 damping viscous 1 tangential cundall_strack 0.8 0.5"),
     ["normal hertz damping 'viscous' is unknown", "allowed: linear GAMMA, kuwabara_kono GAMMA, tsuji E, general THETA C"]),
    ("hertz tangential count", pair("normal hertz 2e8 0.3 tangential cundall_strack 0.8"),
     ["tangential cundall_strack (with normal hertz) needs 2 values (KAPPA MU), got 1"]),
    ("hertz lsd damping option", pair("normal hertz 2e8 0.3 tangential cundall_strack 0.8 0.5 damping mass"),
     ["keyword 'damping mass' after the tangential law applies to 'normal lsd stiffness' only"]),
    ("hertz mixing mismatch", "pair_style tdem/gran\npair_coeff 1 1 normal hertz 2e8 0.3 tangential cundall_strack 0.8 0.5"
     "\npair_coeff 2 2 normal hertz 1e8 0.3 tangential cundall_strack 0.8 0.4",
     ["no pair_coeff for type pair 1 2", "differ in more than the material"]),
    # normal walton_braun
    ("wb value count", pair("normal walton_braun 1e5 tangential cundall_strack 0.8 0.5"),
     ["normal walton_braun needs 2 or 3 values (KL KUL [S]), got 1"]),
    ("wb negative KL", pair("normal walton_braun -1e5 1.5e5 tangential cundall_strack 0.8 0.5"),
     ["normal walton_braun KL (loading stiffness) = -100000 must be > 0"]),
    ("wb KUL below KL", pair("normal walton_braun 1e5 5e4 tangential cundall_strack 0.8 0.5"),
     ["normal walton_braun KUL (unloading stiffness) = 50000 is outside the allowed range [KL, inf) = [100000, inf)"]),
    ("wb negative S", pair("normal walton_braun 1e5 1e5 -2 tangential cundall_strack 0.8 0.5"),
     ["normal walton_braun S (slope of KUL with F_max) = -2 must be >= 0"]),
    ("wb damping", pair("normal walton_braun 1e5 2e5 tangential cundall_strack 0.8 0.5 damping mass"),
     ["keyword 'damping mass' applies to 'normal lsd stiffness' only"]),
    ("wall wb count", pair(GOOD) + "\n" + WALL.format(
        law="normal walton_braun 1e5 2e5 3 4 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL"),
     ["fix w tdem/wall/gran", "normal walton_braun needs 2 or 3 values (KL KUL [S]), got 4"]),
    # normal thornton
    ("thornton value count", pair("normal thornton 2e8 0.3 tangential cundall_strack 0.8 0.5"),
     ["normal thornton needs 3 values (E NU PY", "or 5 values (E1 NU1 E2 NU2 PY), got 2"]),
    ("thornton negative PY", pair("normal thornton 2e8 0.3 -1e6 tangential cundall_strack 0.8 0.5"),
     ["normal thornton PY (limiting contact pressure) = -1000000 must be > 0"]),
    ("thornton nu", pair("normal thornton 2e8 -1.5 1e6 tangential cundall_strack 0.8 0.5"),
     ["normal thornton NU (Poisson ratio) = -1.5 is outside the allowed range (-1, 0.5]"]),
    ("thornton zero E", pair("normal thornton 0 0.3 1e6 tangential cundall_strack 0.8 0.5"),
     ["normal thornton E (Young's modulus) = 0 must be > 0"]),
    ("wall hertz bad nu", pair(GOOD) + "\n" + WALL.format(
        law="normal hertz 2e8 0.3 2e8 0.7 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL"),
     ["fix w tdem/wall/gran", "normal hertz NU2 (Poisson ratio) = 0.7 is outside the allowed range (-1, 0.5]"]),
    # normal power_law
    ("power_law value count", pair("normal power_law 1e7 1.5 tangential cundall_strack 0.8 0.5"),
     ["normal power_law needs 3 or 4 values (AL P AUL [Q]), got 2"]),
    ("power_law negative P", pair("normal power_law 1e7 -1.5 3e7 tangential cundall_strack 0.8 0.5"),
     ["normal power_law P (loading exponent) = -1.5 must be > 0"]),
    ("power_law zero AUL", pair("normal power_law 1e7 1.5 0 tangential cundall_strack 0.8 0.5"),
     ["normal power_law AUL (unloading coefficient a_ul) = 0 must be > 0"]),
    ("power_law negative Q", pair("normal power_law 1e7 1.5 3e7 -0.5 tangential cundall_strack 0.8 0.5"),
     ["normal power_law Q (extra unloading exponent) = -0.5 must be >= 0"]),
    ("power_law damping", pair("normal power_law 1e7 1.5 3e7 tangential cundall_strack 0.8 0.5 damping mass"),
     ["keyword 'damping mass' applies to 'normal lsd stiffness' only", "power_law has no damping"]),
    # normal luding (the worked example of docs/adding_a_law.md): every message from its description
    ("luding value count", pair("normal luding 1e5 5e5 tangential cundall_strack 0.8 0.5"),
     ["normal luding needs 3 values (K1 K2MAX PHIF), got 2"]),
    ("luding K2MAX below K1", pair("normal luding 1e5 5e4 0.05 tangential cundall_strack 0.8 0.5"),
     ["normal luding K2MAX (largest unloading stiffness) = 50000 is outside the allowed range [K1, inf) = [100000, inf)"]),
    ("luding K2MAX = K1", pair("normal luding 1e5 1e5 0.05 tangential cundall_strack 0.8 0.5"),
     ["normal luding: largest unloading stiffness k2_max", "(k1, inf)"]),
    ("luding PHIF = 0", pair("normal luding 1e5 5e5 0 tangential cundall_strack 0.8 0.5"),
     ["normal luding PHIF (plasticity depth) = 0 must be > 0"]),
    ("luding damping", pair("normal luding 1e5 5e5 0.05 tangential cundall_strack 0.8 0.5 damping mass"),
     ["luding has no damping"]),
    # normal continuous_potential
    ("continuous_potential value count", pair("normal continuous_potential 1e-5 36 tangential cundall_strack 0.8 0.5"),
     ["normal continuous_potential needs 3 values (EPS N GAMMA), got 2"]),
    ("continuous_potential N = 0", pair("normal continuous_potential 1e-5 0 0.1 tangential cundall_strack 0.8 0.5"),
     ["normal continuous_potential N (potential exponent) = 0 must be > 0"]),
    ("continuous_potential KT form", pair("normal continuous_potential 1e-5 36 0.1 tangential cundall_strack 600 25 0.5"),
     ["takes 2 values (KAPPA MU) with this normal law"]),
    # normal extended_linear
    ("ext_linear missing e_fit", pair("normal extended_linear tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear needs 'e_fit constant|rational|power C0 ..', got 'tc_fit'"]),
    ("ext_linear unknown e form", pair("normal extended_linear e_fit linear 0.5 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear e_fit form 'linear' is unknown; allowed: constant C0, rational C0 C1 C2, power C0 C1"]),
    ("ext_linear e_fit count", pair("normal extended_linear e_fit rational 1 1 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear e_fit rational needs 3 values (C0 C1 C2), got 2"]),
    ("ext_linear e above 1", pair("normal extended_linear e_fit constant 1.5 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear e_fit constant (C0 = 1.5)", "coefficient of restitution e = 1.5 is outside the allowed range (0, 1]"]),
    ("ext_linear negative chi1", pair("normal extended_linear e_fit rational -1 1 0.2 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["e_fit rational (C0 = -1, C1 = 1, C2 = 0.2)", "restitution fit chi1 = -1 is outside the allowed range (0, inf)"]),
    ("ext_linear power v_c zero", pair("normal extended_linear e_fit power 0 0.1 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["e_fit power (C0 = 0, C1 = 0.1)", "restitution fit v_c = 0 is outside the allowed range (0, inf)"]),
    ("ext_linear missing tc_fit", pair("normal extended_linear e_fit constant 0.5 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear needs 'tc_fit constant|power C0 ..' after e_fit, got 'tangential'"]),
    ("ext_linear rational tc", pair("normal extended_linear e_fit constant 0.5 tc_fit rational 1 1 1 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear tc_fit form 'rational' is unknown; allowed: constant C0, power C0 C1"]),
    ("ext_linear tc zero", pair("normal extended_linear e_fit constant 0.5 tc_fit constant 0 tangential cundall_strack 0.8 0.5"),
     ["tc_fit constant (C0 = 0)", "contact time t_c = 0 is outside the allowed range (0, inf)"]),
    ("ext_linear tc_fit count", pair("normal extended_linear e_fit constant 0.5 tc_fit power 1e-3 tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear tc_fit power needs 2 values (C0 C1), got 1"]),
    ("ext_linear negative v_min", pair("normal extended_linear e_fit constant 0.5 tc_fit constant 1e-3 v_min -1 tangential cundall_strack 0.8 0.5"),
     ["v_min = -1", "smallest impact velocity v_min = -1 is outside the allowed range (0, inf)"]),
    ("ext_linear v_max below v_min", pair("normal extended_linear e_fit constant 0.5 tc_fit constant 1e-3 v_min 1 v_max 0.5 tangential cundall_strack 0.8 0.5"),
     ["largest impact velocity v_max = 0.5 is outside the allowed range [v_min, inf)"]),
    ("ext_linear v_max no value", pair("normal extended_linear e_fit constant 0.5 tc_fit constant 1e-3 v_max tangential cundall_strack 0.8 0.5"),
     ["normal extended_linear v_max needs 1 value (impact velocity), got 0"]),
    ("ext_linear damping", pair("normal extended_linear e_fit constant 0.5 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5 damping absolute"),
     ["keyword 'damping absolute' applies to 'normal lsd stiffness' only", "derive their damping from e_fit"]),
    # normal extended_hertz
    ("ext_hertz value count", pair("normal extended_hertz 1e9 0.3 1e9 e_fit constant 0.5 tangential cundall_strack 0.8 0.5"),
     ["normal extended_hertz needs 2 values (E NU", "or 4 values (E1 NU1 E2 NU2) before e_fit, got 3"]),
    ("ext_hertz nu", pair("normal extended_hertz 1e9 0.7 e_fit constant 0.5 tangential cundall_strack 0.8 0.5"),
     ["normal extended_hertz NU (Poisson ratio) = 0.7 is outside the allowed range (-1, 0.5]"]),
    ("ext_hertz tc_fit", pair("normal extended_hertz 1e9 0.3 e_fit constant 0.5 tc_fit constant 1e-3 tangential cundall_strack 0.8 0.5"),
     ["normal extended_hertz takes no tc_fit"]),
    ("ext_hertz mixing mismatch", "pair_style tdem/gran\npair_coeff 1 1 normal extended_hertz 1e9 0.3 e_fit constant 0.5 "
     "tangential cundall_strack 0.8 0.5\npair_coeff 2 2 normal extended_hertz 2e9 0.3 e_fit constant 0.6 tangential cundall_strack 0.8 0.5",
     ["no pair_coeff for type pair 1 2", "differ in more than the material"]),
    ("wall ext_hertz bad e_fit", pair(GOOD) + "\n" + WALL.format(
        law="normal extended_hertz 1e9 0.3 e_fit power 0.1 -2 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL"),
     ["fix w tdem/wall/gran", "e_fit power (C0 = 0.1, C1 = -2)", "restitution fit exponent p = -2 is outside the allowed range [0, inf)"]),
    ("wall power_law count", pair(GOOD) + "\n" + WALL.format(
        law="normal power_law 1e7 1.5 3e7 0.5 7 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL"),
     ["fix w tdem/wall/gran", "normal power_law needs 3 or 4 values (AL P AUL [Q]), got 5"]),
    ("unknown tangential law", pair("normal lsd stiffness 2000 50 tangential mindlin 600 25 0.5"),
     ["tangential law 'mindlin' is unknown", "allowed: cundall_strack"]),
    # the tangential laws of issue 4
    ("haff_werner count", pair("normal lsd stiffness 2000 50 tangential haff_werner 20"),
     ["tangential haff_werner needs 2 values (GAMMAT MU), got 1"]),
    ("haff_werner negative gamma", pair("normal lsd stiffness 2000 50 tangential haff_werner -20 0.5"),
     ["tangential haff_werner GAMMAT (damping coefficient, mass/time) = -20 must be >= 0"]),
    ("linear_spring count", pair("normal lsd stiffness 2000 50 tangential linear_spring 600 0 25"),
     ["tangential linear_spring needs 4 values (KT KAPPA GAMMAT MU), got 3"]),
    ("linear_spring no stiffness", pair("normal lsd stiffness 2000 50 tangential linear_spring 0 0 25 0.5"),
     ["tangential linear_spring KT = 0, KAPPA = 0", "must be > 0"]),
    ("linear_spring negative kappa", pair("normal lsd stiffness 2000 50 tangential linear_spring 600 -1 25 0.5"),
     ["tangential linear_spring KAPPA (k_t/k_n) = -1 must be >= 0"]),
    ("walton_braun negative mu", pair("normal lsd stiffness 2000 50 tangential walton_braun 600 0 -0.5"),
     ["tangential walton_braun MU (friction coefficient) = -0.5 must be >= 0"]),
    ("mindlin_deresiewicz count", pair("normal hertz 2e8 0.3 tangential mindlin_deresiewicz 2e8 0.3"),
     ["tangential mindlin_deresiewicz needs 3 or 5 values (E NU [E2 NU2] MU), got 2"]),
    ("mindlin_deresiewicz nu 0.7", pair("normal hertz 2e8 0.3 tangential mindlin_deresiewicz 2e8 0.7 0.5"),
     ["tangential mindlin_deresiewicz NU (Poisson ratio) = 0.7 is outside the allowed range (-1, 0.5]"]),
    ("mindlin_no_slip negative ratio", pair("normal hertz 2e8 0.3 tangential mindlin_no_slip 2e8 0.3 -1 0.5"),
     ["tangential mindlin_no_slip RATIO (eta_t/gamma_n) = -1 must be >= 0"]),
    ("di_renzo negative E2", pair("normal hertz 2e8 0.3 tangential di_renzo 2e8 0.3 -1e8 0.3 0.5"),
     ["tangential di_renzo E2 (Young's modulus) = -100000000 must be > 0"]),
    ("di_renzo E not a number", pair("normal hertz 2e8 0.3 tangential di_renzo abc 0.3 0.5"),
     ["tangential di_renzo E expects a finite number, got 'abc'"]),
    ("friction_limit unknown", pair("normal lsd stiffness 2000 50 tangential haff_werner 20 0.5 friction_limit half"),
     ["friction_limit 'half' is unknown; allowed: absolute, positive_normal"]),
    ("friction_limit with cundall_strack", pair(GOOD + " friction_limit absolute"),
     ["keyword 'friction_limit absolute' applies to the tangential laws other than cundall_strack"]),
    ("mixed tangential laws", "pair_style tdem/gran\npair_coeff 1 1 " + GOOD + "\npair_coeff 2 2 " + GOOD +
     "\npair_coeff 1 2 normal lsd stiffness 2000 50 tangential haff_werner 20 0.5",
     ["tangential law", "all type pairs must use the same tangential law"]),
    ("wall mindlin_no_slip count", pair(GOOD) + "\n" + WALL.format(
        law="normal hertz 2e8 0.3 tangential mindlin_no_slip 2e8 0.3 0.5", wall="zplane 0 NULL"),
     ["fix w tdem/wall/gran", "tangential mindlin_no_slip needs 4 or 6 values (E NU [E2 NU2] RATIO MU), got 3"]),
    ("unknown parametrisation", pair("normal lsd damped 2000 50 tangential cundall_strack 600 25 0.5"),
     ["parametrisation 'damped' is unknown", "stiffness KN GAMMAN", "restitution E TC"]),
    ("missing normal value", pair("normal lsd stiffness 2000 tangential cundall_strack 600 25 0.5"),
     ["normal lsd stiffness needs 2 values (KN GAMMAN), got 1"]),
    ("missing tangential value", pair("normal lsd stiffness 2000 50 tangential cundall_strack 600 25"),
     ["needs 3 values (KT GAMMAT MU), got 2"]),
    ("too many normal values", pair("normal lsd stiffness 2000 50 7 tangential cundall_strack 600 25 0.5"),
     ["expected 'tangential LAW ...' after the normal law", "got '7'"]),
    ("restitution tangential count", pair("normal lsd restitution 0.6 1e-4 tangential cundall_strack 0.8"),
     ["needs 2 values (KAPPA MU), got 1"]),
    ("negative KN", pair("normal lsd stiffness -2000 50 tangential cundall_strack 600 25 0.5"),
     ["KN = -2000 must be > 0"]),
    ("negative GAMMAN", pair("normal lsd stiffness 2000 -50 tangential cundall_strack 600 25 0.5"),
     ["GAMMAN = -50 must be >= 0"]),
    ("zero KT", pair("normal lsd stiffness 2000 50 tangential cundall_strack 0 25 0.5"),
     ["KT = 0 must be > 0"]),
    ("negative MU", pair("normal lsd stiffness 2000 50 tangential cundall_strack 600 25 -0.5"),
     ["MU = -0.5 must be >= 0"]),
    ("e above 1", pair("normal lsd restitution 1.5 1e-4 tangential cundall_strack 0.8 0.5"),
     ["restitution E = 1.5 is outside the allowed range (0, 1]"]),
    ("e zero", pair("normal lsd restitution 0 1e-4 tangential cundall_strack 0.8 0.5"),
     ["restitution E = 0 is outside the allowed range (0, 1]"]),
    ("contact time zero", pair("normal lsd restitution 0.6 0 tangential cundall_strack 0.8 0.5"),
     ["TC (contact time) = 0 must be > 0"]),
    ("contact time negative", pair("normal lsd restitution 0.6 -1e-4 tangential cundall_strack 0.8 0.5"),
     ["TC (contact time) = -0.0001 must be > 0"]),
    ("zero KAPPA", pair("normal lsd restitution 0.6 1e-4 tangential cundall_strack 0 0.5"),
     ["KAPPA (kt/kn) = 0 must be > 0"]),
    ("not a number", pair("normal lsd stiffness 2e3x 50 tangential cundall_strack 600 25 0.5"),
     ["KN expects a finite number, got '2e3x'"]),
    ("infinite", pair("normal lsd stiffness inf 50 tangential cundall_strack 600 25 0.5"),
     ["KN expects a finite number, got 'inf'"]),
    ("bad option value", pair(GOOD + " limit_force maybe"),
     ["limit_force 'maybe' is unknown; allowed: yes, no"]),
    ("bad slip value", pair(GOOD + " slip sticky"),
     ["slip 'sticky' is unknown; allowed: spring_dashpot, spring"]),
    ("bad damping value", pair(GOOD + " damping viscous"),
     ["damping 'viscous' is unknown; allowed: mass, absolute"]),
    ("damping with restitution", pair(GOODR + " damping mass"),
     ["'damping mass' applies to 'normal lsd stiffness' only"]),
    ("unknown option", pair(GOOD + " twisting sds"),
     ["unexpected argument 'twisting'", "allowed options", "rolling sds KR GAMMAR MUR"]),
    ("rolling without values", pair(GOOD + " rolling sds"),
     ["rolling sds needs 3 values (KR GAMMAR MUR), got 0"]),
    ("missing law", pair(""),
     ["expected 'normal lsd|hertz|walton_braun|thornton|power_law|luding|extended_linear|extended_hertz|continuous_potential ...' "
      "first, got 'end of line'"]),
    ("pair_style arguments", pair(GOOD, "pair_style tdem/gran 2000 50"),
     ["pair_style tdem/gran: unknown keyword '2000'", "the law goes into pair_coeff"]),
    ("missing type pair", "pair_style tdem/gran\npair_coeff 1 1 " + GOOD + "\npair_coeff 2 2 " + GOOD,
     ["no pair_coeff for type pair 1 2"]),
    ("wall unknown style", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="plane 0 0.1"),
     ["wall style 'plane' is unknown; allowed: xplane, yplane, zplane, zcylinder"]),
    ("wall missing hi", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="zplane 0"),
     ["wall style zplane needs 2 values (lo hi, NULL = no wall), got 1"]),
    ("wall lo above hi", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="zplane 0.1 0"),
     ["zplane lo = 0.1 must be below hi = 0"]),
    ("wall bad restitution", pair(GOOD) + "\n" + WALL.format(
        law="normal lsd restitution 2 1e-4 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL"),
     ["fix w tdem/wall/gran", "restitution E = 2 is outside the allowed range (0, 1]"]),
    ("wall no wall style", pair(GOOD) + "\nfix w all tdem/wall/gran " + GOOD,
     ["missing wall style"]),
    ("wall bad motion", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="zplane 0 NULL wiggle q 0.01 1"),
     ["wiggle dimension 'q' is unknown; allowed: x, y, z"]),
]

# issue 17: misread values, a wall that is no wall, distance-0 contacts (were NaN with exit 0)
CASES += [
    ("stiffness-form tangential after restitution",
     pair("normal lsd restitution 0.7 2e-4 tangential cundall_strack 600 25 0.5"),
     ["tangential cundall_strack takes 2 values (KAPPA MU) with this normal law, but a third number '0.5' "
      "follows '600 25'", "'KT GAMMAT MU' is the form for 'normal lsd stiffness' only"]),
    ("zplane NULL NULL", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="zplane NULL NULL"),
     ["wall style zplane NULL NULL gives no wall; give lo, hi or both"]),
    ("yplane NULL NULL", pair(GOOD) + "\n" + WALL.format(law=GOODR, wall="yplane NULL NULL"),
     ["wall style yplane NULL NULL gives no wall"]),
    ("coincident centres", pair(GOOD) + "\nset atom 2 z 0.05",
     ["pair tdem/gran: atoms 1 and 2 have coincident centres (distance 0) at step 0",
      "the contact normal is undefined"]),
    ("coincident centres hertz", pair(GOODH) + "\nset atom 2 z 0.05",
     ["pair tdem/gran: atoms 1 and 2 have coincident centres (distance 0) at step 0"]),
    ("centre on the wall", pair(GOOD) + "\n" + WALL.format(law=GOODH, wall="zplane 0.05 NULL"),
     ["tdem/wall/gran: atom 1 has its centre on the zplane wall (distance 0) at step 0"]),
    ("centre on the wall, upper", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="xplane NULL 0.05"),
     ["tdem/wall/gran: atom 1 has its centre on the xplane wall (distance 0) at step 0"]),
]

# issue 23: the energy accounting (pair_style tdem/gran energy yes, compute tdem/energy)
CASES += [
    ("energy bad value", pair(GOOD, "pair_style tdem/gran energy maybe"),
     ["pair_style tdem/gran: energy takes no or yes, got 'maybe'"]),
    ("energy no value", pair(GOOD, "pair_style tdem/gran energy"),
     ["pair_style tdem/gran: energy needs a value, no or yes"]),
    ("compute tdem/energy without energy yes", pair(GOOD) + "\ncompute E all tdem/energy\nthermo_style custom step c_E[5]",
     ["compute tdem/energy needs pair_style tdem/gran energy yes"]),
    ("compute tdem/energy bad form", pair(GOOD, "pair_style tdem/gran energy yes") + "\ncompute E all tdem/energy form leapfrog",
     ["compute tdem/energy: form takes kick_drift_kick", "got 'leapfrog'"]),
    ("energy with grid_correction", pair(GOOD + " grid_correction on", "pair_style tdem/gran energy yes"),
     ["energy yes with grid_correction on is not supported in LAMMPS yet"]),
    ("wall energy bad value", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="zplane 0 NULL energy 1"),
     ["tdem/wall/gran: energy takes no or yes, got '1'"]),
    ("compute tdem/energy with a wall without energy", pair(GOOD, "pair_style tdem/gran energy yes") + "\n" +
     WALL.format(law=GOOD, wall="zplane 0 NULL") + "\ncompute E all tdem/energy\nthermo_style custom step c_E[5]",
     ["compute tdem/energy: fix w (tdem/wall/gran) does not account its contacts' energy; add 'energy yes' to it"]),
    ("grate energy bad value", pair(GOOD) + "\nfix gr all tdem/grate " + GOOD + " rows 1 bar_length 0.05 width 0.1 energy on",
     ["keyword 'energy' = 'on' is not allowed; allowed: no, yes"]),
    ("compute tdem/energy with a grate without energy", pair(GOOD, "pair_style tdem/gran energy yes") +
     "\nfix gr all tdem/grate " + GOOD + " rows 1 bar_length 0.05 width 0.1\ncompute E all tdem/energy\n"
     "thermo_style custom step c_E[5]",
     ["compute tdem/energy: fix gr (tdem/grate) does not account its contacts' energy; add 'energy yes' to it"]),
]

wd = lc.workdir("bad")
for k, (name, body, expect) in enumerate(CASES):
    rc, out = lc.run(args["tdem"], BASE.format(body=body), wd, "in.bad%02d" % k, check=False)
    err = [l for l in out.splitlines() if "ERROR" in l]
    ok = rc > 0 and err and all(e in out for e in expect)
    chk.check(ok, "%s: exit %d, %s" % (name, rc, err[0].strip() if err else "no ERROR line"))

for name, body in (("good stiffness", pair(GOOD) + "\n" + WALL.format(law=GOOD, wall="zplane 0 NULL")),
                   ("good energy", pair(GOOD, "pair_style tdem/gran energy yes") + "\n" +
                    WALL.format(law=GOOD, wall="zplane 0 NULL wiggle z 1e-4 1e-3 energy yes") +
                    "\ncompute E all tdem/energy form kick_then_drift\nthermo_style custom step c_E[5] c_E[10]"),
                   ("good restitution", pair(GOODR) + "\n" + WALL.format(law=GOODR, wall="zcylinder 0.2")),
                   ("good walton_braun", pair("normal walton_braun 1e5 2e5 0.1 tangential cundall_strack 0.8 0.5")
                    + "\n" + WALL.format(law="normal walton_braun 1e5 2e5 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL")),
                   ("good thornton", "pair_style tdem/gran\npair_coeff 1 1 normal thornton 2e8 0.3 1e6 tangential cundall_strack 0.8 0.5"
                    "\npair_coeff 2 2 normal thornton 1e8 0.2 1e6 tangential cundall_strack 0.8 0.5\n"
                    + WALL.format(law="normal thornton 2e8 0.3 1e9 0.25 1e6 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL")),
                   ("good power_law", pair("normal power_law 1e7 1.5 3e7 0.2 tangential cundall_strack 0.8 0.5")
                    + "\n" + WALL.format(law="normal power_law 1e7 1.5 3e7 tangential cundall_strack 0.8 0.5", wall="zplane 0 NULL")),
                   ("good extended_linear", pair("normal extended_linear e_fit rational 1 1 0.2 tc_fit power 1e-4 0.2 v_min 0.01 v_max 10 "
                                                 "tangential cundall_strack 0.8 0.5 limit_force yes")
                    + "\n" + WALL.format(law="normal extended_linear e_fit power 0.1 0.1 tc_fit constant 1e-4 tangential cundall_strack 0.8 0.5",
                                         wall="zplane 0 NULL")),
                   ("good extended_hertz mixed", "pair_style tdem/gran\npair_coeff 1 1 normal extended_hertz 2e8 0.3 e_fit constant 0.6 "
                    "tangential cundall_strack 0.8 0.5\npair_coeff 2 2 normal extended_hertz 1e8 0.25 e_fit constant 0.6 "
                    "tangential cundall_strack 0.8 0.5\n" + WALL.format(
                        law="normal extended_hertz 2e8 0.3 1e9 0.2 e_fit rational 1 1 0.2 v_max 5 tangential cundall_strack 0.8 0.5",
                        wall="zplane 0 NULL")),
                   ("good tangential laws", "pair_style tdem/gran\npair_coeff 1 1 normal hertz 2e8 0.3 tangential "
                    "mindlin_deresiewicz 2e8 0.3 0.5\npair_coeff 2 2 normal hertz 1e8 0.25 tangential mindlin_deresiewicz "
                    "1e8 0.25 0.5\n" +
                    "\n".join(WALL.format(law=l, wall="zplane 0 NULL").replace("fix w ", "fix w%d " % k) for k, l in enumerate((
                        "normal lsd stiffness 2000 50 tangential haff_werner 20 0.5 friction_limit positive_normal",
                        "normal lsd restitution 0.6 1e-4 tangential linear_spring 0 0.8 0.1 0.5 slip spring",
                        "normal walton_braun 1e5 2e5 tangential walton_braun 100 0.5 0.5",
                        "normal hertz 2e8 0.3 damping tsuji 0.7 tangential mindlin_no_slip 2e8 0.3 1e9 0.2 1 0.5",
                        "normal extended_hertz 2e8 0.3 e_fit constant 0.6 tangential di_renzo 2e8 0.3 0.5")))),
                   ("good hertz mixed", "pair_style tdem/gran\npair_coeff 1 1 " + GOODH + "\npair_coeff 2 2 "
                    + GOODH.replace("2e8 0.3", "1e8 0.25") + "\n" + WALL.format(law=GOODH.replace("0.3", "0.3 1e9 0.2"), wall="zplane 0 NULL"))):
    rc, out = lc.run(args["tdem"], BASE.format(body=body).replace("0.05 0.05", "0 0"), wd, "in.good", check=False)
    chk.check(rc == 0 and "Loop time" in out, "control %s: runs (exit %d)" % (name, rc))

# values far outside the usual physical range run, with a warning naming the value and the range
for name, body, expect in (
        ("kappa 600 and mu 25", pair("normal lsd restitution 0.7 2e-4 tangential cundall_strack 600 25"),
         ["KAPPA = kt/kn = 600 is unusually large", "usual 0.2 .. 1.5", "MU = 25 is unusually large",
          "granular materials: 0 .. 1.5"]),
        ("stiffness form kt/kn 3", pair("normal lsd stiffness 2000 50 tangential cundall_strack 6000 25 0.5"),
         ["KAPPA = kt/kn = 3 is unusually large"]),
        ("mindlin mu 10", pair("normal hertz 2e8 0.3 tangential mindlin_deresiewicz 2e8 0.3 10"),
         ["tangential mindlin_deresiewicz friction coefficient MU = 10 is unusually large"]),
        ("negative poisson", pair("normal hertz 2e8 -0.5 tangential cundall_strack 0.8 0.5"),
         ["Poisson ratio NU = -0.5 is negative"])):
    rc, out = lc.run(args["tdem"], BASE.format(body=body).replace("0.05 0.05", "0 0"), wd, "in.unusual", check=False)
    warn = [l for l in out.splitlines() if l.startswith("WARNING")]
    chk.check(rc == 0 and "Loop time" in out and all(any(e in w for w in warn) for e in expect),
              "unusual %s: runs (exit %d) and warns: %s" % (name, rc, " | ".join(w[:160] for w in warn) or "no warning"))
chk.done()
