// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the clump bodies of fix tdem/clump (both engines) as VTK unstructured grids, keyword
// `vtk N prefix` (src/fixes/vtk). Every N steps the bodies of all ranks are gathered to rank 0
// (one MPI_Gatherv of 17 doubles per body, the rows of the fix's array) and rank 0 writes
// prefix_STEP.vtu and adds it to the series prefix.pvd. Nothing is computed in other steps.
//
// The grid: the template spheres of every body placed in space as points (x + Lambda r_hat_i),
// one poly-vertex cell per body (its spheres, in template order), bodies in molecule ID order.
//   point data  radius, body (molecule ID), sphere (index in the template),
//               velocity (of the sphere centre: v + omega x (p - x))
//   cell data   id (molecule ID), centre (centre of mass), orientation (quaternion w x y z, body to
//               space), velocity, omega (angular velocity), angular_momentum (about the centre)
//   field data  TimeValue (simulation time)
#pragma once

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "fixes/clumps/body_output.h"
#include "fixes/clumps/body_set.h"
#include "fixes/vtk/vtk_files.h"

namespace tdem {
namespace clumps {

// rows: kArrayColumns per body (mol, x, v, q, L, omega), as BodyOutput
inline vtkio::Dataset bodies_dataset(const std::vector<double>& rows, const Template& tmpl, double t) {
  constexpr int kC = BodyOutput::kArrayColumns;
  const std::size_t nb = rows.size() / kC, ns = tmpl.body.size();
  vtkio::Dataset d;
  d.time = t;
  d.points.reserve(3 * nb * ns);
  vtkio::Array &radius = d.point_array("radius", 1, false), &pbody = d.point_array("body", 1, true),
               &sphere = d.point_array("sphere", 1, true), &pvel = d.point_array("velocity", 3, false);
  vtkio::Array &id = d.cell_array("id", 1, true), &centre = d.cell_array("centre", 3, false),
               &orient = d.cell_array("orientation", 4, false), &vel = d.cell_array("velocity", 3, false),
               &omega = d.cell_array("omega", 3, false), &mom = d.cell_array("angular_momentum", 3, false);
  std::vector<std::int64_t> cell(ns);
  for (std::size_t b = 0; b < nb; ++b) {
    const double* r = &rows[b * kC];
    const Vec3 x{r[1], r[2], r[3]}, v{r[4], r[5], r[6]}, w{r[14], r[15], r[16]};
    const Quat q{r[7], r[8], r[9], r[10]};
    const Mat3 R = rotation_matrix(q);
    const auto mol = static_cast<std::int64_t>(r[0]);
    for (std::size_t i = 0; i < ns; ++i) {
      const Vec3 arm = mul(R, tmpl.body[i].x);
      const Vec3 p = add(x, arm), vp = add(v, cross(w, arm));
      cell[i] = static_cast<std::int64_t>(d.npoints());
      d.add_point(p[0], p[1], p[2]);
      radius.real.push_back(tmpl.body[i].r);
      pbody.ints.push_back(mol);
      sphere.ints.push_back(static_cast<std::int64_t>(i));
      pvel.real.insert(pvel.real.end(), {vp[0], vp[1], vp[2]});
    }
    d.add_cell(cell.begin(), cell.end(), vtkio::kPolyVertex);
    id.ints.push_back(mol);
    centre.real.insert(centre.real.end(), r + 1, r + 4);
    orient.real.insert(orient.real.end(), r + 7, r + 11);
    vel.real.insert(vel.real.end(), r + 4, r + 7);
    mom.real.insert(mom.real.end(), r + 11, r + 14);
    omega.real.insert(omega.real.end(), r + 14, r + 17);
  }
  return d;
}

// The fix's own clock for the files' time: t(step) = t0 + (step - s0) dt, rebased whenever dt
// changes (follow(), at every set-up and reset_dt) and kept in the fix's restart record. The engines'
// clocks are not enough: LIGGGHTS 3.8 and LAMMPS before 2022-05 restart theirs at 0 after
// read_restart (LAMMPS issue 3096), and LIGGGHTS's `timestep` does not carry its time over a change
// of dt. Without a restart and a dt change, t = step dt as the engine's.
struct Clock {
  double t0 = 0.0, dt = 0.0;
  long long s0 = 0;
  double at(long long step) const { return t0 + static_cast<double>(step - s0) * dt; }
  void follow(long long step, double new_dt) {
    if (new_dt == dt) return;
    t0 = at(step);
    s0 = step;
    dt = new_dt;
  }
};

// `vtk N prefix` of a fix: write(step) on every rank (collective); returns "" or the error of rank 0
// on every rank. The fix calls it at setup and in end_of_step when step % N == 0; a step written
// once is not written again (setup of a following run).
class BodyVtk {
 public:
  BodyVtk(int every, std::string prefix) : every_(every), prefix_(std::move(prefix)) {}
  int every() const { return every_; }
  bool due(long long step) const { return every_ > 0 && step % every_ == 0 && step != last_; }
  std::string write(long long step, double t, const BodySet& set, MPI_Comm world) {
    last_ = step;
    int me = 0;
    MPI_Comm_rank(world, &me);
    const std::vector<double> rows = BodyOutput::rows_on_root(set, world);
    int ok = 1;
    std::string msg;
    if (me == 0) {
      try {
        if (!files_) files_ = std::make_unique<vtkio::StepFiles>(prefix_, vtkio::StepFiles::Kind::unstructured);
        files_->write(step, bodies_dataset(rows, set.tmpl(), t));
      } catch (const std::exception& e) {
        ok = 0;
        msg = e.what();
      }
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    return ok ? std::string() : (me == 0 ? msg : std::string("writing the VTK files failed on rank 0"));
  }

 private:
  int every_;
  std::string prefix_;
  long long last_ = -1;
  std::unique_ptr<vtkio::StepFiles> files_;
};

}  // namespace clumps
}  // namespace tdem
