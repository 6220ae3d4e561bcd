// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: VTK XML output through the VTK library (vtk_files.h).
#include "fixes/vtk/vtk_files.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLUtilities.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace tdem {
namespace vtkio {
namespace {

void check(const Dataset& d, const std::string& path) {
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("VTK file '" + path + "': inconsistent data (" + what + ")");
  };
  if (d.points.size() % 3 != 0) fail("point coordinates not a multiple of 3");
  if (d.offsets.empty() || d.offsets.front() != 0 ||
      d.offsets.back() != static_cast<std::int64_t>(d.connectivity.size()))
    fail("cell offsets");
  for (std::int64_t p : d.connectivity)
    if (p < 0 || static_cast<std::size_t>(p) >= d.npoints()) fail("a cell names a point that does not exist");
  for (const auto& a : d.point_data)
    if (a.size() != d.npoints() * a.components) fail("point array '" + a.name + "' has the wrong length");
  for (const auto& a : d.cell_data)
    if (a.size() != d.ncells() * a.components) fail("cell array '" + a.name + "' has the wrong length");
}

vtkSmartPointer<vtkDataArray> make_array(const Array& a) {
  vtkSmartPointer<vtkDataArray> out;
  const vtkIdType n = static_cast<vtkIdType>(a.size() / a.components);
  if (a.integer) {
    auto v = vtkSmartPointer<vtkTypeInt64Array>::New();
    v->SetNumberOfComponents(a.components);
    v->SetNumberOfTuples(n);
    for (std::size_t i = 0; i < a.ints.size(); ++i) v->SetValue(static_cast<vtkIdType>(i), a.ints[i]);
    out = v;
  } else {
    auto v = vtkSmartPointer<vtkDoubleArray>::New();
    v->SetNumberOfComponents(a.components);
    v->SetNumberOfTuples(n);
    for (std::size_t i = 0; i < a.real.size(); ++i) v->SetValue(static_cast<vtkIdType>(i), a.real[i]);
    out = v;
  }
  out->SetName(a.name.c_str());
  return out;
}

// points, arrays and the time of d into ds; the cells as one vtkCellArray
template <class DS>
vtkSmartPointer<vtkCellArray> fill(DS* ds, const Dataset& d) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(d.npoints()));
  for (std::size_t i = 0; i < d.npoints(); ++i)
    pts->SetPoint(static_cast<vtkIdType>(i), d.points[3 * i], d.points[3 * i + 1], d.points[3 * i + 2]);
  ds->SetPoints(pts);
  vtkNew<vtkIdTypeArray> off, conn;
  off->SetNumberOfValues(static_cast<vtkIdType>(d.offsets.size()));
  for (std::size_t i = 0; i < d.offsets.size(); ++i) off->SetValue(static_cast<vtkIdType>(i), d.offsets[i]);
  conn->SetNumberOfValues(static_cast<vtkIdType>(d.connectivity.size()));
  for (std::size_t i = 0; i < d.connectivity.size(); ++i)
    conn->SetValue(static_cast<vtkIdType>(i), d.connectivity[i]);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(off, conn);
  for (const auto& a : d.point_data) ds->GetPointData()->AddArray(make_array(a));
  for (const auto& a : d.cell_data) ds->GetCellData()->AddArray(make_array(a));
  vtkNew<vtkDoubleArray> t;
  t->SetName("TimeValue");
  t->SetNumberOfTuples(1);
  t->SetValue(0, d.time);
  ds->GetFieldData()->AddArray(t);
  return cells;
}

// the directory of path exists and is writable (checked first: VTK's writer would print a
// page of pipeline state before failing)
void check_directory(const std::string& path) {
  const std::filesystem::path dir = std::filesystem::absolute(std::filesystem::path(path)).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write the VTK file '" + path + "': the directory '" + dir.string() +
                             "' does not exist or is not writable");
}

template <class Writer>
void write(Writer* w, const std::string& path) {
  check_directory(path);
  w->SetFileName(path.c_str());
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  w->SetCompressorTypeToZLib();
  if (w->Write() != 1 || w->GetErrorCode() != 0)
    throw std::runtime_error("cannot write the VTK file '" + path + "' (does its directory exist?)");
}

std::string format_time(double t) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", t);
  return buf;
}

}  // namespace

void write_polydata(const std::string& path, const Dataset& d) {
  check(d, path);
  vtkNew<vtkPolyData> pd;
  pd->SetPolys(fill(pd.GetPointer(), d));
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(pd);
  write(w.GetPointer(), path);
}

void write_unstructured(const std::string& path, const Dataset& d) {
  check(d, path);
  if (d.types.size() != d.ncells())
    throw std::runtime_error("VTK file '" + path + "': inconsistent data (one cell type per cell)");
  vtkNew<vtkUnstructuredGrid> ug;
  auto cells = fill(ug.GetPointer(), d);
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(static_cast<vtkIdType>(d.types.size()));
  for (std::size_t i = 0; i < d.types.size(); ++i)
    types->SetValue(static_cast<vtkIdType>(i), static_cast<unsigned char>(d.types[i]));
  ug->SetCells(types, cells);
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(ug);
  write(w.GetPointer(), path);
}

void Series::load_earlier(long long step) {
  loaded_ = true;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(pvd_, ec)) return;  // no series yet (VTK's parser would complain)
  std::unique_ptr<vtkXMLDataElement, void (*)(vtkXMLDataElement*)> root(
      vtkXMLUtilities::ReadElementFromFile(pvd_.c_str()), [](vtkXMLDataElement* e) {
        if (e) e->Delete();
      });
  if (!root) return;  // no series yet
  vtkXMLDataElement* coll = root->FindNestedElementWithName("Collection");
  if (!coll) return;
  for (int i = 0; i < coll->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = coll->GetNestedElement(i);
    const char* ts = e->GetAttribute("timestep");
    const char* st = e->GetAttribute("step");
    const char* f = e->GetAttribute("file");
    if (!ts || !st || !f) continue;  // not written here: dropped
    const long long s = std::strtoll(st, nullptr, 10);
    if (s < step) entries_.push_back({s, std::strtod(ts, nullptr), f});
  }
}

void Series::save() const {
  vtkNew<vtkXMLDataElement> root, coll;
  root->SetName("VTKFile");
  root->SetAttribute("type", "Collection");
  root->SetAttribute("version", "0.1");
  root->SetAttribute("byte_order", "LittleEndian");
  coll->SetName("Collection");
  for (const Entry& en : entries_) {
    vtkNew<vtkXMLDataElement> e;
    e->SetName("DataSet");
    e->SetAttribute("timestep", format_time(en.time).c_str());
    e->SetAttribute("part", "0");
    e->SetAttribute("step", std::to_string(en.step).c_str());
    e->SetAttribute("file", en.file.c_str());
    coll->AddNestedElement(e);
  }
  root->AddNestedElement(coll);
  // write to a temporary file and rename: a reader never sees half a series
  check_directory(pvd_);
  const std::string tmp = pvd_ + ".tmp";
  vtkIndent indent;
  if (!vtkXMLUtilities::WriteElementToFile(root, tmp.c_str(), &indent) || std::rename(tmp.c_str(), pvd_.c_str()) != 0)
    throw std::runtime_error("cannot write the VTK series file '" + pvd_ + "' (does its directory exist?)");
}

void Series::add(long long step, double time, const std::string& file) {
  if (!loaded_) load_earlier(step);
  namespace fs = std::filesystem;
  const fs::path dir = fs::absolute(fs::path(pvd_)).parent_path();
  const std::string rel = fs::absolute(fs::path(file)).lexically_normal().lexically_relative(dir).generic_string();
  // a repeated step (written again by the set-up of the next run) replaces its entry
  while (!entries_.empty() && entries_.back().step >= step) entries_.pop_back();
  entries_.push_back({step, time, rel.empty() ? file : rel});
  save();
}

}  // namespace vtkio
}  // namespace tdem
