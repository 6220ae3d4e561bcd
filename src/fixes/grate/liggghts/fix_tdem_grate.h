// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/grate, a grate of fixed and moving bar rows (src/fixes/grate/, docs/grate.md)
// whose bars are LIGGGHTS triangle meshes, so that they interact with the particles through the stock
// `fix wall/gran` and therefore through ANY LIGGGHTS or tdem contact law, with its contact history.
//
//   fix ID group tdem/grate <grate keywords> <motion keywords> [wall_type T] [vtk N prefix]
//
// At creation the fix builds Grate::boxes(t) + box_mesh at the current simulation time, writes one
// ASCII STL per mesh into the run directory (tdem_grate_<ID>_<mesh>.stl) and adds
//   fix <ID>_fixed    all mesh/surface file ... type T      fixed bars + side walls (if any)
//   fix <ID>_moving<g> all mesh/surface file ... type T     the moving rows of phase group g
// (one mesh per phase group that has rows). The user then writes the stock
//   fix walls all wall/gran model ... tangential ... mesh n_meshes K meshes <ID>_fixed <ID>_moving0 ...
// Every step (initial_integrate, i.e. at the new step time t_{n+1}) the fix translates the nodes of each
// moving mesh to the kinematic displacement u_g(t) of its group (incremental moves of exactly
// (u_g(t) - u_applied) along the stroke direction) and sets the element property "v" that the stock
// wall/gran uses as the wall velocity. The meshes are registered as translating (registerMove), so the
// neighbour lists of the moving meshes are rebuilt by the stock mechanism.
//
// Time: the fix keeps its own clock (starting at the simulation time when it is created, stored in
// restart files since LIGGGHTS 3.8 restarts the simulation time at 0); t = t_base + (step - step_base) dt.
// `reset_timestep` is not supported while the fix exists.
//
// Global vector (thermo f_ID[i], 1-based): [1] grate time t, then per phase group g: [2+2g] u_g, [3+2g] du_g/dt.
// extract("tdem_grate") -> const tdem::grate::Grate*, extract("tdem_grate_time") -> double* (t of this step).
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "fix.h"

#include "fixes/grate/geometry.h"
#include "fixes/vtk/vtk_files.h"

namespace LAMMPS_NS {

class FixTDEMGrate : public Fix {
 public:
  FixTDEMGrate(class LAMMPS*, int, char**);
  ~FixTDEMGrate();
  int setmask();
  void post_create();
  void pre_delete(bool);
  void init();
  void setup(int);
  void initial_integrate(int);
  void end_of_step();
  double compute_vector(int);
  void* extract(const char*, int&);
  void write_restart(FILE*);
  void restart(char*);

 private:
  struct MeshInfo {
    std::string id;          // fix ID of the mesh/surface
    int group = -1;          // phase group (-1: fixed bars + side walls)
    class FixMeshSurface* fix = nullptr;
    double u_applied = 0.0;  // displacement along the stroke the nodes currently have
  };
  std::unique_ptr<tdem::grate::Grate> grate_;
  std::vector<MeshInfo> meshes_;
  int ngroups_ = 0;
  int wall_type_ = 1;
  int vtk_every_ = 0;
  std::string vtk_prefix_;
  std::unique_ptr<tdem::vtkio::StepFiles> vtk_files_;  // rank 0: prefix_STEP.vtp and prefix.pvd
  // own clock t = tb_ + (ntimestep - sb_) * dtb_, re-based when the time step changes (LIGGGHTS 3.8
  // does not keep the simulation time in restart files, so the clock is written to the restart file)
  double tb_ = 0.0;
  bigint sb_ = 0;
  double dtb_ = 0.0;
  double t_now_ = 0.0;
  double t_created_ = 0.0;
  bigint last_vtk_step_ = -1;
  std::vector<double> u_, v_;  // per phase group at t_now_

  double step_time();
  void update_state(double t);
  void move_meshes();
  void write_vtk();
};

}  // namespace LAMMPS_NS
