// SPDX-License-Identifier: GPL-2.0-or-later
// VTK XML output (src/fixes/vtk): files written by tdem_vtk and read back with the VTK library's own
// readers; the .pvd series and its continuation; errors for unwritable paths and bad data.
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUtilities.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "fixes/grate/geometry.h"
#include "fixes/vtk/vtk_files.h"

namespace fs = std::filesystem;
using namespace tdem;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tdem_vtk_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

struct PvdEntry {
  double t;
  std::string file;
};
std::vector<PvdEntry> read_pvd(const std::string& path) {
  std::vector<PvdEntry> out;
  vtkXMLDataElement* root = vtkXMLUtilities::ReadElementFromFile(path.c_str());
  if (!root) return out;
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* c = root->FindNestedElementWithName("Collection");
  for (int i = 0; c && i < c->GetNumberOfNestedElements(); ++i)
    out.push_back({std::strtod(c->GetNestedElement(i)->GetAttribute("timestep"), nullptr),
                   c->GetNestedElement(i)->GetAttribute("file")});
  root->Delete();
  return out;
}

grate::GrateParams params() {
  grate::GrateParams p;
  p.rows = 3;
  p.bar_length = 0.1;
  p.bar_height = 0.02;
  p.width = 0.05;
  p.motion.stroke = 0.03;
  p.motion.period = 0.5;
  return p;
}
}  // namespace

TEST(VtkFiles, GrateBarsReadBackWithTheVtkReader) {
  const fs::path dir = scratch("bars");
  grate::Grate g(params());
  const auto boxes = g.boxes(0.013);
  const grate::Mesh m = grate::box_mesh(boxes);
  const std::string f = (dir / "bars_7.vtp").string();
  vtkio::write_polydata(f, grate::bars_dataset(boxes, 0.013));

  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName(f.c_str());
  r->Update();
  vtkPolyData* pd = r->GetOutput();
  ASSERT_EQ(pd->GetNumberOfPoints(), static_cast<vtkIdType>(m.points.size()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i) {
    double p[3];
    pd->GetPoint(i, p);
    EXPECT_EQ(p[0], m.points[i].x);  // doubles, binary: exact
    EXPECT_EQ(p[1], m.points[i].y);
    EXPECT_EQ(p[2], m.points[i].z);
  }
  ASSERT_EQ(pd->GetNumberOfPolys(), static_cast<vtkIdType>(m.triangles.size()));
  vtkDataArray* box = pd->GetCellData()->GetArray("box");
  vtkDataArray* row = pd->GetCellData()->GetArray("row");
  vtkDataArray* vel = pd->GetCellData()->GetArray("velocity");
  ASSERT_TRUE(box && row && vel);
  EXPECT_EQ(vel->GetNumberOfComponents(), 3);
  vtkCellArray* polys = pd->GetPolys();
  for (vtkIdType c = 0; c < pd->GetNumberOfPolys(); ++c) {
    vtkIdType n;
    const vtkIdType* pts;
    polys->GetCellAtId(c, n, pts);
    ASSERT_EQ(n, 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(pts[k], m.triangles[c][k]);
    const int b = static_cast<int>(box->GetTuple1(c));
    EXPECT_EQ(b, m.triangle_box[c]);
    EXPECT_EQ(row->GetTuple1(c), boxes[b].row);
    EXPECT_EQ(vel->GetComponent(c, 0), boxes[b].velocity.x);
  }
  vtkDataArray* t = pd->GetFieldData()->GetArray("TimeValue");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->GetTuple1(0), 0.013);
  fs::remove_all(dir);
}

TEST(VtkFiles, PolyVertexGridWithIntegerArrays) {
  const fs::path dir = scratch("ug");
  vtkio::Dataset d;
  d.time = 2.5;
  for (int i = 0; i < 5; ++i) d.add_point(i, 2.0 * i, -1.0 * i);
  const std::int64_t a[2] = {0, 1}, b[3] = {2, 3, 4};
  d.add_cell(a, a + 2, vtkio::kPolyVertex);
  d.add_cell(b, b + 3, vtkio::kPolyVertex);
  d.cell_array("id", 1, true).ints = {1234567890123LL, 7};
  d.cell_array("orientation", 4, false).real = {1, 0, 0, 0, 0.5, 0.5, 0.5, 0.5};
  d.point_array("radius", 1, false).real = {0.1, 0.2, 0.3, 0.4, 0.5};
  const std::string f = (dir / "b.vtu").string();
  vtkio::write_unstructured(f, d);
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(f.c_str());
  r->Update();
  vtkUnstructuredGrid* ug = r->GetOutput();
  ASSERT_EQ(ug->GetNumberOfCells(), 2);
  EXPECT_EQ(ug->GetCellType(0), vtkio::kPolyVertex);
  EXPECT_EQ(ug->GetCell(1)->GetNumberOfPoints(), 3);
  EXPECT_EQ(ug->GetCell(1)->GetPointId(2), 4);
  EXPECT_EQ(ug->GetCellData()->GetArray("id")->GetTuple1(0), 1234567890123.0);
  EXPECT_EQ(ug->GetCellData()->GetArray("orientation")->GetComponent(1, 3), 0.5);
  EXPECT_EQ(ug->GetPointData()->GetArray("radius")->GetTuple1(4), 0.5);
  EXPECT_EQ(ug->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 2.5);
  fs::remove_all(dir);
}

TEST(VtkFiles, SeriesListsEveryFileAndContinuesAfterARestart) {
  const fs::path dir = scratch("series");
  const std::string prefix = (dir / "out" / "bars").string();
  fs::create_directories(dir / "out");
  vtkio::Dataset d;
  d.add_point(0, 0, 0);
  {
    vtkio::StepFiles s(prefix, vtkio::StepFiles::Kind::polydata);
    for (int step = 0; step <= 300; step += 100) {
      d.time = 1e-4 * step + 1.0 / 3.0;
      s.write(step, d);
    }
    d.time = 1e-4 * 300 + 1.0 / 3.0;  // the same step again (a second run command): replaced
    s.write(300, d);
  }
  auto e = read_pvd(prefix + ".pvd");
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[2].t, 1e-4 * 200 + 1.0 / 3.0);  // %.17g: the time round-trips exactly
  EXPECT_EQ(e[2].file, "bars_200.vtp");        // relative to the .pvd
  for (const auto& x : e) EXPECT_TRUE(fs::exists(dir / "out" / x.file)) << x.file;
  // a run continued from a restart at step 200: the earlier entries stay, the later are replaced,
  // whatever the time (here the clock restarted at 0, as LAMMPS before 2022-05 does)
  {
    vtkio::StepFiles s(prefix, vtkio::StepFiles::Kind::polydata);
    d.time = 0.0;
    s.write(200, d);
    d.time = 1e-4 * 250 + 1.0 / 3.0;
    s.write(250, d);
  }
  e = read_pvd(prefix + ".pvd");
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[1].file, "bars_100.vtp");
  EXPECT_EQ(e[2].file, "bars_200.vtp");
  EXPECT_EQ(e[3].file, "bars_250.vtp");
  EXPECT_EQ(e[2].t, 0.0);
  fs::remove_all(dir);
}

TEST(VtkFiles, ErrorsNameTheFile) {
  vtkio::Dataset d;
  d.add_point(0, 0, 0);
  try {
    vtkio::write_polydata("/nonexistent-dir/x.vtp", d);
    FAIL() << "no error for a missing directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.vtp"), std::string::npos) << e.what();
  }
  d.cell_array("bad", 1, false).real = {1.0, 2.0};  // two values for no cell
  EXPECT_THROW(vtkio::write_polydata("/tmp/never.vtp", d), std::runtime_error);
  vtkio::Dataset u;
  u.add_point(0, 0, 0);
  const std::int64_t c[1] = {3};  // no point 3
  u.add_cell(c, c + 1, vtkio::kPolyVertex);
  EXPECT_THROW(vtkio::write_unstructured("/tmp/never.vtu", u), std::runtime_error);
  vtkio::Series s("/nonexistent-dir/x.pvd");
  EXPECT_THROW(s.add(0, 0.0, "/nonexistent-dir/x_0.vtp"), std::runtime_error);
}
