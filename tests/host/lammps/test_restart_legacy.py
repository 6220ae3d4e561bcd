#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Restart files of pair tdem/gran's format 6 (written by tdem before issue 19, which stores
walton_braun, thornton and power_law as modes 4-6 with members of their own) are still read:
data/restart_v6/<law>.restart was written at step N1 in the middle of three collisions (a
head-on pair, a sphere sliding onto the floor; make_legacy_restarts.py, legacy_restart_scene.py).
For each law:
  a. read_restart + the floor fix + run N2 equals this build's own run N1 + run N2 within 1e-10
     relative (the file's coefficients, law and contact history are taken over: a wrong law or a
     lost history changes the rebound by far more);
  b. the same with pair_coeff set anew to other coefficients of the law changes the rebound by
     more than 1e-3 (so (a) can fail when the file's coefficients are misread);
  c. a format-7 file of this build, written at N1 and continued, equals the run N1 + run N2 within
     1e-10 as well."""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import legacy_restart_scene as sc  # noqa: E402
import lmp_common as lc  # noqa: E402

args = lc.parse_args(sys.argv)
chk = lc.Checker("lammps.restart_legacy")
data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "restart_v6")


def worst(a, b):
    assert len(a) == len(b) and a, (a, b)
    return max(abs(x - y) / max(abs(x), abs(y), 1e-300) for x, y in zip(a, b))


def continuation(path, law, dt, n2, coeff=""):
    return ("atom_modify map array\nread_restart %s\n%sneighbor 0.001 bin\n"
            "neigh_modify delay 0 every 1 check yes\ncomm_modify vel yes\n"
            "fix floor all tdem/wall/gran %s zplane 0 NULL\nfix nve all nve/sphere\ntimestep %r\nrun %d\n"
            % (path, coeff, law, dt, n2) + sc.REPORT)


for name, law, tc, dt in sc.LAWS:
    n1, n2 = sc.steps(tc, dt)
    wd = lc.workdir("legacy_" + name)
    shutil.copy(os.path.join(data, name + ".restart"), os.path.join(wd, "v6.restart"))
    _, ref = lc.run(args["tdem"], sc.base(law, dt) + "run %d\n" % n1 + sc.STATE + "run %d\n" % n2 + sc.REPORT, wd,
                    "in.ref")
    fx1, fz3, vrel, vz3 = sc.results(ref, "STATE")
    chk.check(fx1 < 0 and fz3 > 0 and vrel > 0 and vz3 > 0,
              "%s: step %d is inside both collisions, unloading (pair force %.3g N, relative velocity %.3g m/s; "
              "wall force %.3g N, vz %.3g m/s)" % (name, n1, fx1, vrel, fz3, vz3))
    _, old = lc.run(args["tdem"], continuation("v6.restart", law, dt, n2), wd, "in.v6")
    _, other = lc.run(args["tdem"], continuation("v6.restart", law, dt, n2, "pair_coeff * * %s\n" % sc.OTHER[name]),
                      wd, "in.v6_other")
    _, first = lc.run(args["tdem"], sc.base(law, dt) + "run %d\nwrite_restart v7.restart\n" % n1, wd, "in.v7_write")
    _, new = lc.run(args["tdem"], continuation("v7.restart", law, dt, n2), wd, "in.v7")
    r_ref, r_old, r_other, r_new = (sc.results(t) for t in (ref, old, other, new))
    w_old, w_new = worst(r_ref, r_old), worst(r_ref, r_new)
    d_other = max(abs(r_other[k] - r_ref[k]) / max(abs(r_ref[k]), 1e-300) for k in (2, 11))
    print("%s: format 6 file continued: max rel diff %.3g; format 7: %.3g; other coefficients: rebound "
          "changes by %.3g (relative)" % (name, w_old, w_new, d_other))
    chk.check(w_old <= 1e-10, "%s: the format-6 restart continues as run N1 + run N2 (max rel diff %.3g)"
              % (name, w_old))
    chk.check(d_other > 1e-3, "%s: control: other coefficients change the rebound (%.3g)" % (name, d_other))
    chk.check(w_new <= 1e-10, "%s: a format-7 restart continues as run N1 + run N2 (max rel diff %.3g)"
              % (name, w_new))
chk.done()
