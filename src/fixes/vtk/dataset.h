// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: a VTK dataset as plain data (no VTK header here), filled by the fix cores (grate bars,
// clump bodies) and written by vtk_files.h through the VTK library.
//
// Points are x y z triples. Cells are given by `offsets` (ncells + 1 entries, starting at 0) into
// `connectivity` (point indices) and, for an unstructured grid, one VTK cell type per cell
// (kPolyVertex, kTriangle, ...). A polydata file (.vtp) takes every cell as a polygon. Each array
// holds either real or integer values, `components` per point or per cell.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace tdem {
namespace vtkio {

// VTK cell type numbers (vtkCellType.h)
constexpr int kPolyVertex = 2;
constexpr int kTriangle = 5;

struct Array {
  std::string name;
  int components = 1;
  bool integer = false;            // integer values (ids, indices) in `ints`, else reals in `real`
  std::vector<double> real;
  std::vector<std::int64_t> ints;
  std::size_t size() const { return integer ? ints.size() : real.size(); }
};

struct Dataset {
  std::vector<double> points;
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> connectivity;
  std::vector<int> types;  // unstructured grids only
  std::deque<Array> point_data, cell_data;  // a deque: references to arrays stay valid as more are added
  double time = 0.0;       // written as field data "TimeValue" (ParaView's time of the file)

  std::size_t npoints() const { return points.size() / 3; }
  std::size_t ncells() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  void add_point(double x, double y, double z) { points.insert(points.end(), {x, y, z}); }
  // a cell of the given point indices (and VTK type, for unstructured grids)
  template <class It>
  void add_cell(It first, It last, int type) {
    connectivity.insert(connectivity.end(), first, last);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(type);
  }
  Array& cell_array(const std::string& name, int components, bool integer) {
    return add_array(cell_data, name, components, integer);
  }
  Array& point_array(const std::string& name, int components, bool integer) {
    return add_array(point_data, name, components, integer);
  }

 private:
  static Array& add_array(std::deque<Array>& v, const std::string& name, int components, bool integer) {
    v.push_back(Array{name, components, integer, {}, {}});
    return v.back();
  }
};

}  // namespace vtkio
}  // namespace tdem
