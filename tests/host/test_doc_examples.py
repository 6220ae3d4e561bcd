#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The style pages of docs/<engine>/ (issue 21): every page has the sections of the engine's manual in
order (Syntax, Examples, Description, Restart..., Restrictions, Related commands, Default), and every
example block (```lammps / ```liggghts under "## Examples") runs: it is placed into the scene the page
names (<!-- doc-example-scene: NAME -->, defined below), run for a few steps, and must end without an
ERROR line. Links to other pages of docs/ must point to files that exist.

  test_doc_examples.py --tdem EXE --engine lammps [--docs DIR]   (other arguments are ignored)
"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import mpi_env  # noqa: E402

SECTIONS = ["Syntax", "Examples", "Description", "Restart", "Restrictions", "Related commands", "Default"]

# four spheres in the 1 cm box of the granular scenes, two of them touching
FOUR_SPHERES = """create_atoms 1 single 0.003 0.003 0.0012 units box
create_atoms 1 single 0.0049 0.003 0.0012 units box
create_atoms 1 single 0.007 0.007 0.004 units box
create_atoms 1 single 0.003 0.007 0.006 units box
set group all diameter 0.002 density 2500
velocity all set 0.01 0 -0.2 units box"""

GRANULAR = """units si
atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 1 box
%s
neighbor 0.0005 bin
fix grav all gravity 9.81 vector 0 0 -1
timestep 1e-6
""" % FOUR_SPHERES
PAIR = "pair_style tdem/gran\npair_coeff * * normal lsd restitution 0.7 1e-4 tangential cundall_strack 0.8 0.5\n"

CLUMP = """units si
atom_style sphere
atom_modify map array
boundary p p f
newton off
comm_modify vel yes
region box block 0 0.03 0 0.03 0 0.04 units box
create_box 1 box
fix pm all property/atom mol ghost yes
region ins block 0 0.03 0 0.03 0.004 0.035 units box
neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
fix floor all tdem/wall/gran normal lsd restitution 0.7 1e-4 tangential cundall_strack 0.8 0.5 zplane 0 NULL
fix grav all gravity 9.81 vector 0 0 -1
timestep 5e-6
"""

STOCK_RIGID = """units si
atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
region box block 0 0.03 0 0.03 0 0.03 units box
create_box 1 box
fix pm all property/atom mol ghost yes
create_atoms 1 single 0.010 0.015 0.005 units box
create_atoms 1 single 0.013 0.015 0.005 units box
create_atoms 1 single 0.020 0.015 0.005 units box
create_atoms 1 single 0.020 0.015 0.008 units box
set group all diameter 0.002 density 2500
set atom 1*2 mol 1
set atom 3*4 mol 2
velocity all set 0 0 -0.1 units box
neighbor 0.001 bin
neigh_modify delay 0 exclude molecule/intra all
fix floor all tdem/wall/gran normal lsd restitution 0.7 1e-4 tangential cundall_strack 0.8 0.5 zplane 0 NULL
fix rb all rigid/small molecule
thermo_style custom step atoms
timestep 1e-6
"""

GRATE = """units si
atom_style sphere
atom_modify map array
boundary f p f
newton off
comm_modify vel yes
region box block -0.05 0.45 -0.05 0.05 -0.2 0.1 units box
create_box 1 box
create_atoms 1 single 0.03 0.0 0.03 units box
create_atoms 1 single 0.05 0.01 0.03 units box
set group all diameter 0.004 density 2500
neighbor 0.001 bin
fix grav all gravity 9.81 vector 0 0 -1
timestep 1e-6
"""

MIXING = """units si
atom_style sphere
atom_modify map array
boundary p p f
newton off
comm_modify vel yes
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 1 box
lattice sc 0.0025
region fill block 0 0.01 0 0.01 0.001 0.006 units box
create_atoms 1 region fill
set group all diameter 0.002 density 2500
velocity all create 1e-6 4711 loop geom
neighbor 0.0005 bin
timestep 1e-6
"""

LIG_GRANULAR = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 1 box
%s
neighbor 0.0005 bin
neigh_modify delay 0
fix grav all gravity 9.81 vector 0 0 -1
timestep 1e-6
""" % FOUR_SPHERES
LIG_PAIR = """fix d_e  all property/global coefficientRestitution peratomtypepair 1 0.7
fix d_tc all property/global contactTime peratomtypepair 1 1e-4
fix d_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.3
fix d_mu all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model tdem/lsd tangential tdem/cundall_strack parameters restitution
pair_coeff * *
"""

LIG_CLUMP = """atom_style hybrid sphere molecular
atom_modify map array
boundary p p f
newton off
communicate single vel yes
units si
region box block 0 0.03 0 0.03 0 0.04 units box
create_box 1 box
region ins block 0 0.03 0 0.03 0.004 0.035 units box
neighbor 0.001 bin
neigh_modify delay 0 exclude molecule all
fix grav all gravity 9.81 vector 0 0 -1
timestep 5e-6
"""
LIG_MULTISPHERE = """atom_style sphere
atom_modify map array sort 0 0
boundary f f f
newton off
communicate single vel yes
units si
region b block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box
create_box 1 b
neighbor 0.001 bin
neigh_modify delay 0
fix m_e  all property/global coefficientRestitution peratomtypepair 1 0.8
fix m_tc all property/global contactTime peratomtypepair 1 1e-4
fix m_ka all property/global tangentialStiffnessRatio peratomtypepair 1 0.0
fix m_mu all property/global coefficientFriction peratomtypepair 1 0.0
pair_style gran model tdem/lsd tangential no_history surface tdem/clump parameters restitution
pair_coeff * *
timestep 1e-6
fix w all wall/gran model tdem/lsd tangential no_history surface tdem/clump primitive type 1 zplane 0.0 parameters restitution
fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 2 ntry 1000000 spheres -0.00625 0 0 0.005 0.00625 0 0 0.005 type 1
fix pdd all particledistribution/discrete 32452843 1 pts 1.0
region ins block -0.01 0.01 -0.001 0.001 0.0052 0.0055 units box
fix ins all insert/pack seed 49979687 distributiontemplate pdd vel constant 0 0 -0.5 insert_every once overlapcheck yes region ins particles_in_region 1 ntry_mc 1000
fix ms all multisphere
"""
LIG_GRATE = """atom_style granular
atom_modify map array
boundary f p f
newton off
communicate single vel yes
units si
region box block -0.05 0.45 -0.05 0.05 -0.2 0.1 units box
create_box 1 box
create_atoms 1 single 0.03 0.0 0.03 units box
create_atoms 1 single 0.05 0.01 0.03 units box
set group all diameter 0.004 density 2500
neighbor 0.001 bin
neigh_modify delay 0
fix grav all gravity 9.81 vector 0 0 -1
timestep 1e-6
"""
LIG_MIXING = """atom_style granular
atom_modify map array
boundary p p f
newton off
communicate single vel yes
units si
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 1 box
lattice sc 0.0025
region fill block 0 0.01 0 0.01 0.001 0.006 units box
create_atoms 1 region fill
set group all diameter 0.002 density 2500
neighbor 0.0005 bin
neigh_modify delay 0
timestep 1e-6
"""

# scene: (head, add a default pair style if the example has none, add nve/sphere if it has no integrator)
SCENES = {
    "granular": (GRANULAR, True, True),
    "granular_noint": (GRANULAR, True, False),
    "clump": (CLUMP, True, False),
    "stock_rigid": (STOCK_RIGID, True, False),
    "grate": (GRATE, True, True),
    "mixing": (MIXING, True, True),
    "lig_granular": (LIG_GRANULAR, True, True),
    "lig_granular_noint": (LIG_GRANULAR, True, False),
    "lig_clump": (LIG_CLUMP, True, False),
    "lig_multisphere": (LIG_MULTISPHERE, False, False),
    "lig_grate": (LIG_GRATE, True, True),
    "lig_mixing": (LIG_MIXING, True, True),
}


def blocks(text, lang):
    m = re.search(r"^## Examples\s*$(.*?)^## ", text, re.M | re.S)
    if not m:
        return []
    return [b.strip() for b in re.findall(r"```%s\n(.*?)```" % lang, m.group(1), re.S)]


def scene_input(scene, example):
    head, want_pair, want_int = SCENES[scene]
    text = head
    if want_pair and "pair_style" not in example and "property/global" not in example:
        text += LIG_PAIR if scene.startswith("lig_") else PAIR
    text += example.replace("&\n", " ") + "\n"
    if want_int and "tdem/integrate" not in example and "tdem/clump" not in example:
        text += "fix nve all nve/sphere\n"
    computes = re.findall(r"^compute\s+(\S+)\s+\S+\s+tdem/", example, re.M)
    if computes:  # a compute is evaluated when something asks for it
        text += "thermo_style custom step atoms %s\nthermo 5\n" % " ".join("c_" + c for c in computes)
    text += "run 20\n"
    return text


def tools(a):
    """docs/tools/*.md: every command of the ```sh example blocks runs (exit 0) in a scratch directory
    that links the repository's validation/ and input_scripts/, with the tools of the directory of --tdem."""
    bindir = os.path.dirname(os.path.abspath(a.tdem))
    root = os.path.dirname(os.path.abspath(a.docs))
    fails, n = [], 0
    for p in sorted(glob.glob(os.path.join(a.docs, "tools", "*.md"))):
        text = open(p, encoding="utf-8").read()
        name = os.path.basename(p)
        heads = [h.strip() for h in re.findall(r"^## (.*)$", text, re.M)]
        ok = [h.split()[0] for h in heads] == ["Syntax", "Examples", "Description", "Restart,", "Restrictions",
                                               "Related", "Default"]
        print("%s %s: sections %s" % ("PASS" if ok else "FAIL", name, " / ".join(heads)))
        if not ok:
            fails.append(name)
        for link in re.findall(r"\]\(([^)#:]+\.md)(?:#[^)]*)?\)", text):
            if not os.path.isfile(os.path.join(os.path.dirname(p), link)):
                print("FAIL %s: link %s exists" % (name, link))
                fails.append(link)
        for block in blocks(text, "sh"):
            for cmd in block.replace("\\\n", " ").split("\n"):
                cmd = cmd.strip()
                if not cmd or cmd.startswith("#"):
                    continue
                tool = cmd.split()[0]
                exe = os.path.join(bindir, tool)
                # in a scratch directory that sees the repository's data (files the command writes stay there)
                with tempfile.TemporaryDirectory(prefix="tdem_docex_") as wd:
                    for d in ("validation", "input_scripts"):
                        os.symlink(os.path.join(root, d), os.path.join(wd, d))
                    r = subprocess.run(exe + cmd[len(tool):], shell=True, cwd=wd, stdout=subprocess.PIPE,
                                       stderr=subprocess.STDOUT, text=True, timeout=600,
                                       env=dict(os.environ, TMPDIR=wd))
                n += 1
                ok = r.returncode == 0
                print("%s %s: %s (exit %d)" % ("PASS" if ok else "FAIL", name, cmd[:100], r.returncode), flush=True)
                if not ok:
                    print(r.stdout[-1500:])
                    fails.append(cmd)
    print("%d commands, %d failure(s)" % (n, len(fails)))
    return 1 if fails or n < 10 else 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tdem", required=True)
    ap.add_argument("--engine", default="lammps")
    ap.add_argument("--docs", default=os.path.join(HERE, "..", "..", "docs"))
    a, _ = ap.parse_known_args()
    if a.engine == "tools":
        return tools(a)
    pages = sorted(glob.glob(os.path.join(a.docs, a.engine, "*.md")))
    fails = []

    def check(ok, what):
        print("%s %s" % ("PASS" if ok else "FAIL", what), flush=True)
        if not ok:
            fails.append(what)

    check(len(pages) >= 9, "%d style pages in docs/%s/" % (len(pages), a.engine))
    nex = 0
    for p in pages:
        name = os.path.basename(p)
        text = open(p, encoding="utf-8").read()
        heads = [h.strip() for h in re.findall(r"^## (.*)$", text, re.M)]
        order = [next((k for k, s in enumerate(SECTIONS) if h.startswith(s)), None) for h in heads]
        check(sorted(o for o in order if o is not None) == list(range(len(SECTIONS))) and
              [o for o in order if o is not None] == list(range(len(SECTIONS))),
              "%s: sections %s" % (name, " / ".join(heads)))
        for link in re.findall(r"\]\(([^)#:]+\.md)(?:#[^)]*)?\)", text):
            check(os.path.isfile(os.path.join(os.path.dirname(p), link)), "%s: link %s exists" % (name, link))
        m = re.search(r"<!-- doc-example-scene: (\S+) -->", text)
        check(m is not None and m.group(1) in SCENES, "%s: names a scene for its examples" % name)
        if not m or m.group(1) not in SCENES:
            continue
        exs = blocks(text, a.engine)
        check(len(exs) >= 1, "%s: %d example(s)" % (name, len(exs)))
        for k, ex in enumerate(exs):
            nex += 1
            with tempfile.TemporaryDirectory(prefix="tdem_docex_") as wd:
                with open(os.path.join(wd, "in.ex"), "w") as f:
                    f.write(scene_input(m.group(1), ex))
                r = mpi_env.run([a.tdem, "-in", "in.ex", "-log", "none", "-echo", "none"], cwd=wd,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
                err = [l for l in r.stdout.splitlines() if "ERROR" in l]
                check(r.returncode == 0 and not err, "%s example %d runs: %s" % (
                    name, k + 1, ex.splitlines()[0][:90] + (" ..." if len(ex) > 90 else "")
                    if r.returncode == 0 and not err else (err[0] if err else "exit %d" % r.returncode)))
    check(nex >= 9, "%d examples run" % nex)
    print("%d failure(s)" % len(fails))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
