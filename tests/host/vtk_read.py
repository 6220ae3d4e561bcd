# SPDX-License-Identifier: GPL-2.0-or-later
"""Read tdem's VTK XML output back with the VTK library (Debian python3-vtk9), for the host tests.

  read_dataset(path)  .vtp or .vtu -> dict(points (n,3), cells [point id arrays], types,
                      point {name: array}, cell {name: array}, time)
  read_pvd(path)      ParaView collection -> [(time, absolute file path)], in file order
"""
import os
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader


def _arrays(data):
    out = {}
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        out[a.GetName()] = vtk_to_numpy(a).copy()
    return out


def read_dataset(path):
    if not os.path.isfile(path):
        raise FileNotFoundError(path)
    poly = path.endswith(".vtp")
    r = vtkXMLPolyDataReader() if poly else vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    ds = r.GetOutput()
    pts = vtk_to_numpy(ds.GetPoints().GetData()).astype(float) if ds.GetPoints() else np.zeros((0, 3))
    cells, types = [], []
    for c in range(ds.GetNumberOfCells()):
        cell = ds.GetCell(c)
        cells.append(np.array([cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())], dtype=int))
        types.append(ds.GetCellType(c))
    fd = _arrays(ds.GetFieldData())
    return dict(points=pts, cells=cells, types=types, point=_arrays(ds.GetPointData()),
                cell=_arrays(ds.GetCellData()), time=float(fd["TimeValue"][0]) if "TimeValue" in fd else None,
                npoints=ds.GetNumberOfPoints())


def read_pvd(path):
    root = ET.parse(path).getroot()
    assert root.tag == "VTKFile" and root.get("type") == "Collection", path
    base = os.path.dirname(os.path.abspath(path))
    return [(float(e.get("timestep")), os.path.join(base, e.get("file"))) for e in root.iter("DataSet")]
