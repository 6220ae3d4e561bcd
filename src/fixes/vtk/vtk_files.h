// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: VTK XML files through the VTK library (Debian libvtk9-dev), for the fixes' own geometry.
//
//   write_polydata(path, d)      .vtp: the cells of d as polygons
//   write_unstructured(path, d)  .vtu: the cells of d with their VTK types
// Both write binary appended data, zlib-compressed, with d.time as field data "TimeValue", and
// throw std::runtime_error naming the file when it cannot be written.
//
//   Series s("out/bars.pvd");  s.add(100, t, "out/bars_100.vtp");
// keeps a ParaView collection (.pvd) of the files written so far, one DataSet per file with its
// time (and its step, an attribute ParaView ignores), and rewrites it after every add (a run that
// stops early leaves a valid series). The first add of a Series reads an existing .pvd of the same
// name and keeps its entries of earlier steps: a run continued from a restart file extends the
// series of the run before it. Entries of the same or later steps are replaced. Steps, not times,
// decide: the clock of LAMMPS before 2022-05 (Debian 12's 20220106) restarts at 0 after
// read_restart (LAMMPS issue 3096), its step does not. Files are recorded relative to the
// directory of the .pvd.
//
// Only the rank that writes calls these (the callers gather to rank 0 or hold global data).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "fixes/vtk/dataset.h"

namespace tdem {
namespace vtkio {

void write_polydata(const std::string& path, const Dataset& d);
void write_unstructured(const std::string& path, const Dataset& d);

class Series {
 public:
  explicit Series(std::string pvd_path) : pvd_(std::move(pvd_path)) {}
  const std::string& path() const { return pvd_; }
  void add(long long step, double time, const std::string& file);
  std::size_t size() const { return entries_.size(); }

 private:
  std::string pvd_;
  bool loaded_ = false;
  struct Entry {
    long long step;
    double time;
    std::string file;  // relative to the .pvd
  };
  std::vector<Entry> entries_;
  void load_earlier(long long step);
  void save() const;
};

// "prefix_STEP.ext" and "prefix.pvd": the file names of a fix's `vtk N prefix` output
inline std::string step_file(const std::string& prefix, long long step, const std::string& ext) {
  return prefix + "_" + std::to_string(step) + "." + ext;
}
inline std::string series_file(const std::string& prefix) { return prefix + ".pvd"; }

// The output of a fix keyword `vtk N prefix`: each write(step, d) writes prefix_STEP.vtp (polydata)
// or prefix_STEP.vtu (unstructured grid) and adds it, at d.time, to the series prefix.pvd.
class StepFiles {
 public:
  enum class Kind { polydata, unstructured };
  StepFiles(std::string prefix, Kind kind) : prefix_(std::move(prefix)), kind_(kind), series_(series_file(prefix_)) {}
  std::string write(long long step, const Dataset& d) {
    const bool poly = kind_ == Kind::polydata;
    const std::string f = step_file(prefix_, step, poly ? "vtp" : "vtu");
    if (poly)
      write_polydata(f, d);
    else
      write_unstructured(f, d);
    series_.add(step, d.time, f);
    return f;
  }

 private:
  std::string prefix_;
  Kind kind_;
  Series series_;
};

}  // namespace vtkio
}  // namespace tdem
