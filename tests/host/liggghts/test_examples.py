# SPDX-License-Identifier: GPL-2.0-or-later
"""The LIGGGHTS tutorials shipped with liggghts-doc, shortened (every `run` of more than 10 steps
becomes `run K`), run once with the stock `liggghts` and once with `tdem-liggghts`: the thermo
output must be identical line for line (tdem-liggghts only adds styles; every stock style
must behave exactly as before). Tutorials that do not run with the stock Debian build either are
listed in SKIPPED with the reason."""
import os
import re
import shutil
import sys
import time

import tdem_lig as T

TUT = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"

# (directory, input file, steps per shortened run[, input run first in the same directory])
CASES = [
    ("packing", "in.packing", 1500),
    ("contactModels", "in.newModels", 1500),
    ("hysteresis", "in.hysteresis", 1500),
    ("hysteresis", "in.noHysteresis", 1500),
    ("cohesion", "in.cohesion", 1500),
    ("cohesion", "in.noCohesion", 1500),
    ("chute_wear", "in.chute_wear", 3000),
    ("conveyor", "in.conveyor", 3000),
    ("insert_stream", "in.insert_stream", 3000),
    ("insert_stream", "in.insert_stream_reset_timestep", 3000, "in.insert_stream"),  # reads its restart
    ("meshGran", "in.meshGran", 2000),
    ("movingMeshGran", "in.movingMeshGran", 1000),
    ("heatTransfer_1", "in.heatGran", 1500),
    ("heatTransfer_2", "in.heatGran", 1500),
    ("mesh_tet", "in.mesh_tet", 1000),
    ("hydrogel_multicontact", "in.hydrogel_default", 500),
    ("hydrogel_multicontact", "in.hydrogel_multicontact", 100),
    ("sph_1", "in.sph_1", 300),
    ("sph_2", "in.sph_2", 1000),
    ("multisphere_stone_restitution", "in.multisphere", 1000),
]

# Tutorials that fail with the stock Debian liggghts as well (not run):
SKIPPED = {
    "contactModels/in.oldModels": "stock: 'ERROR: Invalid pair style' -- uses the pre-3.0 styles "
                                  "(pair_style gran/hooke/history ...) removed from LIGGGHTS 3.x",
    "superquadric/in.particle_particle": "stock: 'ERROR: Invalid atom style' -- atom_style superquadric "
                                         "needs SUPERQUADRIC_ACTIVE_FLAG, not set in the Debian build",
    "ParScale": "no LIGGGHTS input (needs the ParScale coupling library)",
}


def high_precision_thermo(text):
    """Print thermo floats with 15 significant digits (after every thermo_style)."""
    return re.sub(r"^(\s*thermo_style[^\n]*)$", r"\1\nthermo_modify format float %.15g", text, flags=re.M)


def shorten(text, k):
    def repl(m):
        arg = m.group(2)
        if re.fullmatch(r"\d+", arg) and int(arg) <= 10:
            return m.group(0)
        return "%srun %d" % (m.group(1), k)
    return re.sub(r"^(\s*)run\s+(\S+)(\s+upto)?[^\n]*$", repl, text, flags=re.M)


def thermo_rows(log_text):
    out = []
    for header, rows in T.thermo_blocks(log_text):
        drop = [i for i, h in enumerate(header) if h.lower() in ("cpu", "cpuremain", "tpcpu", "spcpu")]
        out.append(" ".join(header))
        for r in rows:
            parts = r.split()
            out.append(" ".join(p for i, p in enumerate(parts) if i not in drop))
    return out


def main():
    args = T.parse_args(lambda p: p.add_argument("--only", default=None))
    checks = T.Checks()
    for case in CASES:
        tdir, inp, k = case[:3]
        pre = case[3] if len(case) > 3 else None
        name = "%s/%s" % (tdir, inp)
        if args.only and args.only not in name:
            continue
        if name in SKIPPED:
            print("SKIP %s: %s" % (name, SKIPPED[name]))
            continue
        res = {}
        for tag, exe in (("stock", args.stock), ("tdem", args.tdem)):
            d = T.workdir(args, "tdem_lig_ex_%s_%s_%s" % (tdir, inp.replace(".", "_"), tag))
            shutil.rmtree(d)
            shutil.copytree(os.path.join(TUT, tdir), d)
            if pre:
                with open(os.path.join(d, pre)) as f:
                    T.run(exe, high_precision_thermo(shorten(f.read(), k)), d, "pre", check=False)
            with open(os.path.join(d, inp)) as f:
                text = high_precision_thermo(shorten(f.read(), k))
            t0 = time.time()
            r = T.run(exe, text, d, "short", check=False)
            res[tag] = (r, thermo_rows(r.stdout), time.time() - t0)
        (rs, ts, dts), (rt, tt, dtt) = res["stock"], res["tdem"]
        print("  %s: stock rc %d %.1fs, tdem rc %d %.1fs, %d thermo lines" % (name, rs.returncode, dts, rt.returncode, dtt, len(ts)))
        if rs.returncode != 0:
            print("    stock error: " + " | ".join(l for l in (rs.stdout + rs.stderr).splitlines() if "ERROR" in l)[:300])
        checks.check(rs.returncode == 0 and rt.returncode == 0, name + ": stock and tdem-liggghts both finish")
        checks.check(len(ts) > 1 and ts == tt, name + ": identical thermo output (%d lines)" % len(ts))
    # the tdem example of this repository (input_scripts/liggghts), shortened
    for example in ("in.tdem_lsd_box", "in.tdem_nonlinear_box", "in.tdem_tangential_box"):
        if args.only and "input_scripts" not in args.only:
            break
        ex = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "input_scripts",
                          "liggghts", example)
        d = T.workdir(args, "tdem_lig_ex_input_scripts_" + example[3:])
        with open(ex) as f:
            text = shorten(f.read(), 4000)
        r = T.run(args.tdem, text, d, "box", check=False)
        rows = [l.split() for l in T.thermo_blocks(r.stdout)[-1][1]] if T.thermo_blocks(r.stdout) else []
        checks.check(r.returncode == 0 and rows and rows[-1][:2] == ["4000", "1000"],
                     "input_scripts/liggghts/%s: runs under tdem-liggghts, 1000 atoms at step 4000" % example)
    for name, why in SKIPPED.items():
        print("not run: %s: %s" % (name, why))
    checks.done()


if __name__ == "__main__":
    main()
