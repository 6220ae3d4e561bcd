#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Pictures of tdem scenes, rendered off-screen with the VTK library (python3-vtk9) under Xvfb.

  xvfb-run -a python3 tools/render.py grate DIR TAG OUT_DIR [--color depth|speed] [--frames] [--title T]
      the grate TAG of a run of validation/grate/run.sh in DIR: the bars of TAG_bars.pvd (fix tdem/grate
      `vtk N prefix`) with the particles of TAG_atoms.txt (id x y z vx vy vz radius D) at the same
      step; writes OUT_DIR/TAG.png (the last frame with bars); with --frames also one PNG per bar file
      (OUT_DIR/TAG_frames/NNNN.png) and the animated OUT_DIR/TAG.gif
  xvfb-run -a python3 tools/render.py dump DUMP OUT.png [--color body|speed|height] [--title T]
      the last frame of a LAMMPS/LIGGGHTS text dump with columns x y z radius (and mol, vx vy vz):
      clumps coloured by body (mol), beds by speed or height

Spheres are glyphs scaled by their radius; colours from matplotlib's viridis (scalars) or tab20
(bodies), with a colour bar. The camera looks along -z at a 2D scene (all z equal) and obliquely
at a 3D scene. Every picture is checked before it is written: a frame whose pixels are all the
background colour is an error (exit status 1).
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL back end)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkGlyph3DMapper, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)

BG = (1.0, 1.0, 1.0)
SIZE = (1280, 720)


def colormap(name, n=256):
    import matplotlib
    cm = matplotlib.colormaps[name]
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(n)
    for i in range(n):
        r, g, b, _ = cm(i / (n - 1) if cm.N > 32 else (i % cm.N) / cm.N)
        lut.SetTableValue(i, r, g, b, 1.0)
    lut.Build()
    return lut


def read_dump(path):
    """Frames of a text dump: list of (step, {column: array})."""
    frames = []
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            j = k + 4
            while not lines[j].startswith("ITEM: ATOMS"):
                j += 1
            cols = lines[j].split()[2:]
            a = np.array([[float(v) for v in l.split()] for l in lines[j + 1:j + 1 + n]]).reshape(n, len(cols))
            frames.append((step, {c: a[:, i] for i, c in enumerate(cols)}))
            k = j + 1 + n
        else:
            k += 1
    return frames


def spheres(cols, scalar, lut, rng):
    pts = vtkPoints()
    xyz = np.column_stack([cols["x"], cols["y"], cols["z"]]).astype(float)
    pts.SetData(numpy_to_vtk(xyz, deep=True))
    pd = vtkPolyData()
    pd.SetPoints(pts)
    r = numpy_to_vtk(2.0 * cols["radius"].astype(float), deep=True)  # the glyph has diameter 1
    r.SetName("diameter")
    s = numpy_to_vtk(scalar.astype(float), deep=True)
    s.SetName("colour")
    pd.GetPointData().AddArray(r)
    pd.GetPointData().AddArray(s)
    src = vtkSphereSource()
    src.SetRadius(0.5)
    src.SetThetaResolution(18)
    src.SetPhiResolution(12)
    m = vtkGlyph3DMapper()
    m.SetInputData(pd)
    m.SetSourceConnection(src.GetOutputPort())
    m.SetScaleArray("diameter")
    m.SetScaleModeToScaleByMagnitude()
    m.SetScaleFactor(1.0)
    m.SetLookupTable(lut)
    m.SetScalarRange(*rng)
    m.SetScalarModeToUsePointFieldData()
    m.SelectColorArray("colour")
    m.ScalarVisibilityOn()
    a = vtkActor()
    a.SetMapper(m)
    return a


def bars(vtp):
    rd = vtkXMLPolyDataReader()
    rd.SetFileName(vtp)
    rd.Update()
    pd = rd.GetOutput()
    group = vtk_to_numpy(pd.GetCellData().GetArray("group"))
    col = vtkLookupTable()  # -2 side wall, -1 fixed bar, >= 0 moving (phase group)
    col.SetNumberOfTableValues(4)
    col.SetTableRange(-2, 1)
    for i, c in enumerate([(0.85, 0.85, 0.85, 1.0), (0.45, 0.45, 0.48, 1.0), (0.75, 0.35, 0.20, 1.0),
                           (0.80, 0.55, 0.15, 1.0)]):
        col.SetTableValue(i, *c)
    col.Build()
    pd.GetCellData().SetActiveScalars("group")
    m = vtkPolyDataMapper()
    m.SetInputData(pd)
    m.SetLookupTable(col)
    m.SetScalarRange(-2, 1)
    m.SetScalarModeToUseCellData()
    a = vtkActor()
    a.SetMapper(m)
    if (group == -2).any():
        a.GetProperty().SetOpacity(1.0)
    return a, pd.GetBounds()


class Scene:
    def __init__(self, title, bar_title=None, lut=None, rng=None, two_d=False):
        self.ren = vtkRenderer()
        self.ren.SetBackground(*BG)
        self.win = vtkRenderWindow()
        self.win.SetOffScreenRendering(1)
        self.win.SetSize(*SIZE)
        self.win.AddRenderer(self.ren)
        self.two_d = two_d
        self.camera_set = False
        t = vtkTextActor()
        t.SetInput(title)
        t.GetTextProperty().SetFontSize(22)
        t.GetTextProperty().SetColor(0.1, 0.1, 0.1)
        t.SetPosition(15, SIZE[1] - 40)
        self.ren.AddActor2D(t)
        self.title = t
        if lut is not None:
            sb = vtkScalarBarActor()
            sb.SetLookupTable(lut)
            sb.SetTitle(bar_title or "")
            sb.SetNumberOfLabels(5)
            sb.GetTitleTextProperty().SetColor(0.1, 0.1, 0.1)
            sb.GetLabelTextProperty().SetColor(0.1, 0.1, 0.1)
            sb.GetTitleTextProperty().SetFontSize(14)
            sb.SetMaximumWidthInPixels(90)
            sb.SetPosition(0.90, 0.1)
            sb.SetHeight(0.8)
            self.ren.AddActor2D(sb)

    def camera(self, bounds):
        """Fix the camera on the bounds (xmin xmax ymin ymax zmin zmax) once: every frame alike."""
        if self.camera_set:
            return
        c = np.array([(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2])
        span = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
        cam = self.ren.GetActiveCamera()
        if self.two_d:
            cam.SetFocalPoint(*c)
            cam.SetPosition(c[0], c[1], c[2] + 3 * span)
            cam.SetViewUp(0, 1, 0)
            cam.ParallelProjectionOn()
        else:
            cam.SetFocalPoint(*c)
            cam.SetPosition(*(c + span * np.array([0.55, -1.6, 0.9])))
            cam.SetViewUp(0, 0, 1)
        self.ren.ResetCamera(bounds)
        # ResetCamera fits the bounding sphere: a wide scene can be enlarged, a tall one not
        wide = (bounds[1] - bounds[0]) >= 1.2 * (bounds[5] - bounds[4] if not self.two_d else bounds[3] - bounds[2])
        cam.Zoom((1.45 if self.two_d else 1.3) if wide else 1.0)
        self.camera_set = True

    def write(self, path):
        self.win.Render()
        f = vtkWindowToImageFilter()
        f.SetInput(self.win)
        f.ReadFrontBufferOff()
        f.Update()
        img = vtk_to_numpy(f.GetOutput().GetPointData().GetScalars())
        bg = np.array([int(round(255 * v)) for v in BG])
        drawn = np.any(img[:, :3] != bg, axis=1).mean()
        if drawn < 0.02:
            raise SystemExit("render.py: %s would be blank (%.1f %% of the pixels drawn)" % (path, 100 * drawn))
        w = vtkPNGWriter()
        w.SetFileName(path)
        w.SetInputConnection(f.GetOutputPort())
        w.Write()
        return drawn


def pvd_entries(path):
    root = ET.parse(path).getroot()
    base = os.path.dirname(os.path.abspath(path))
    return [(float(e.get("timestep")), int(e.get("step", -1)), os.path.join(base, e.get("file")))
            for e in root.iter("DataSet")]


def grate(a):
    series = pvd_entries(os.path.join(a.dir, a.tag + "_bars.pvd"))
    frames = dict(read_dump(os.path.join(a.dir, a.tag + "_atoms.txt")))
    pairs = [(t, s, f) for t, s, f in series if s in frames]
    if not pairs:
        raise SystemExit("render.py: no step has both bars and particles for %s" % a.tag)
    os.makedirs(a.out, exist_ok=True)
    if a.color == "depth":
        lut, rng, label = colormap("viridis"), (0.0, 1.0), "depth D"
    else:
        vmax = np.median([np.percentile(np.sqrt(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2), 95)
                          for c in frames.values() if len(c["vx"])])
        lut, rng, label = colormap("viridis"), (0.0, max(vmax, 1e-6)), "speed [m/s]"

    def scalar(c):
        if a.color == "depth":
            return c["f_dp[1]"]
        return np.sqrt(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2)
    two_d = all(np.ptp(c["z"]) == 0.0 for c in frames.values() if len(c["z"]))
    sc = Scene(a.title or a.tag, label, lut, rng, two_d)
    todo = pairs if a.frames else pairs[-1:]
    paths = []
    if a.frames:
        os.makedirs(os.path.join(a.out, a.tag + "_frames"), exist_ok=True)
    # the camera: the bars and every particle position of the run
    allx = np.concatenate([np.column_stack([c["x"], c["y"], c["z"]]) for c in frames.values()])
    for k, (t, s, f) in enumerate(todo):
        c = frames[s]
        ba, bb = bars(f)
        sp = spheres(c, scalar(c), lut, rng)
        sc.ren.AddActor(ba)
        sc.ren.AddActor(sp)
        bounds = [min(bb[0], allx[:, 0].min()), max(bb[1], allx[:, 0].max()), min(bb[2], allx[:, 1].min()),
                  max(bb[3], allx[:, 1].max()), min(bb[4], allx[:, 2].min()), max(bb[5], allx[:, 2].max())]
        sc.camera(bounds)
        sc.title.SetInput("%s   t = %.2f s   %d particles" % (a.title or a.tag, t, len(c["x"])))
        p = os.path.join(a.out, a.tag + "_frames", "%04d.png" % k) if a.frames else os.path.join(a.out, a.tag + ".png")
        sc.write(p)
        paths.append(p)
        sc.ren.RemoveActor(ba)
        sc.ren.RemoveActor(sp)
    if a.frames:
        import shutil
        shutil.copy(paths[-1], os.path.join(a.out, a.tag + ".png"))
        from PIL import Image
        imgs = [Image.open(p).convert("P", palette=Image.ADAPTIVE) for p in paths]
        imgs[0].save(os.path.join(a.out, a.tag + ".gif"), save_all=True, append_images=imgs[1:], duration=120, loop=0)
    print("render.py: %s: %d picture(s) in %s%s" % (a.tag, len(paths), a.out, " and %s.gif" % a.tag if a.frames else ""))


def dump(a):
    step, c = read_dump(a.dump)[-1]
    if a.color == "body":
        lut = colormap("tab20", 20)
        lut.SetNumberOfTableValues(20)
        s, rng, label = np.mod(c["mol"], 20), (0, 19), "body (molecule ID mod 20)"
    elif a.color == "height":
        lut, s, label = colormap("viridis"), c["z"], "height z [m]"
        rng = (float(s.min()), float(s.max()))
    else:
        s = np.sqrt(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2)
        lut, rng, label = colormap("viridis"), (0.0, max(float(np.percentile(s, 98)), 1e-12)), "speed"
    sc = Scene("%s   step %d   %d spheres" % (a.title or os.path.basename(a.dump), step, len(c["x"])),
               label if a.color != "body" else None, lut if a.color != "body" else None, rng)
    sc.ren.AddActor(spheres(c, s, lut, rng))
    x = np.column_stack([c["x"], c["y"], c["z"]])
    r = c["radius"].max()
    sc.camera([x[:, 0].min() - r, x[:, 0].max() + r, x[:, 1].min() - r, x[:, 1].max() + r, x[:, 2].min() - r,
               x[:, 2].max() + r])
    sc.write(a.out)
    print("render.py: %s" % a.out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="kind", required=True)
    g = sub.add_parser("grate")
    g.add_argument("dir")
    g.add_argument("tag")
    g.add_argument("out")
    g.add_argument("--color", choices=("depth", "speed"), default="depth")
    g.add_argument("--frames", action="store_true")
    g.add_argument("--title", default="")
    d = sub.add_parser("dump")
    d.add_argument("dump")
    d.add_argument("out")
    d.add_argument("--color", choices=("body", "speed", "height"), default="speed")
    d.add_argument("--title", default="")
    a = ap.parse_args()
    {"grate": grate, "dump": dump}[a.kind](a)


if __name__ == "__main__":
    sys.exit(main())
