// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/clump, rigid multi-sphere clumps of one template (issue 6,
// physics_reference.md section 6, core src/fixes/clumps/, shared host code src/fixes/clumps/host_bodies.h).
// See docs/liggghts/fix_tdem_clump.md. Same syntax as the LAMMPS fix (src/fixes/clumps/lammps):
//
//   fix ID group tdem/clump template NAME (file PATH | shape SHAPE r d [n]) [density RHO]
//       [integration columns|voxel|monte_carlo] [resolution N] [rotation splitting|explicit|richardson]
//       [insert N region REGID seed S [type T] [vel vx vy vz]] [bodies molecule]
//       [correction none|count|overlap|local_mass] [vtk N prefix]
//
// Needs per-atom molecule IDs (atom_style hybrid sphere molecular) and
// `neigh_modify exclude molecule GROUP` (the spheres of one clump must not interact).
//
// Design ("local bodies", shared with the LAMMPS fix: src/fixes/clumps/body_set.h): a rank keeps
// the bodies of the spheres it owns; the body state travels with the spheres (exchange and
// per-atom restart records), the forces of ghost spheres come by forward communication, and
// every rank holding a body advances it identically, so the bodies are bitwise the same on any
// number of ranks. extend_cut_ghost() makes the ghost cutoff at least the largest distance between
// two spheres of the template. Positions use the image flags (x = com + Lambda r_hat - image * L_box).
//
// The force of the last final_integrate is kept (and written to restart files): a new run, or a run
// after read_restart, starts with it instead of the set-up force, which in LIGGGHTS differs from it
// (contact history) - so the fix continues `run N; run M` and restarts exactly as one run (as far as
// the contact styles do: bitwise with tdem's laws; see docs/liggghts/fix_tdem_clump.md).
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "fix.h"

#include "clump_correction.h"
#include "fixes/clumps/body_output.h"
#include "fixes/clumps/body_set.h"
#include "fixes/clumps/body_vtk.h"
#include "fixes/clumps/clump_args.h"

namespace LAMMPS_NS {

class FixTDEMClump : public Fix {
 public:
  FixTDEMClump(class LAMMPS*, int, char**);
  ~FixTDEMClump();
  int setmask();
  void post_create();
  void init();
  void setup_pre_neighbor();
  void setup(int);
  void initial_integrate(int);
  void final_integrate();
  void end_of_step();
  void pre_neighbor();
  void setup_pre_force(int);
  void pre_force(int);
  void reset_dt();
  double compute_scalar();
  double compute_vector(int);
  double compute_array(int, int);
  void* extract(const char*, int&);
  void write_restart(FILE*);
  void restart(char*);
  double memory_usage();
  double extend_cut_ghost();
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  int pack_exchange(int, double*);
  int unpack_exchange(int, double*);
  int pack_restart(int, double*);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();
  int pack_comm(int, int*, double*, int, int*);
  void unpack_comm(int, int, double*);

 private:
  std::string where_;  // "fix ID tdem/clump" for messages
  tdem::clumps::BodySet bodies_;  // the bodies, shared with LAMMPS (fixes/clumps/body_set.h)
  tdem::clumps::BodyOutput reports_;  // scalar, vector, array over the ranks
  tdem::clumps::ClumpArgs args_;  // the fix's arguments (insert, bodies molecule, correction)
  bool restarted_, formed_, have_force_, need_set_;
  std::unique_ptr<tdem::clumps::BodyVtk> vtk_;  // vtk N prefix (body_vtk.h), or none
  tdem::clumps::Clock clock_;  // simulation time of the VTK files (kept in the restart record)

  // multiple-contact correction (docs/liggghts/fix_tdem_clump.md, "Multiple-contact correction"): the bodies
  // of this fix as the sides of the shared LIGGGHTS correction (clump_correction.h)
  tdem::clumps::Correction correction_;
  struct Sides : CorrectionSides {
    const tdem::clumps::BodySet* bodies = nullptr;
    bool in_body(int i) const override { return bodies->body_index()[i] >= 0; }
    std::int64_t key(int i) const override { return bodies->body_key()[i]; }
    double inverse_side_mass(int i, const double* n) const override {
      return bodies->inverse_side_mass(bodies->body_index()[i], bodies->sphere_index()[i], n);
    }
  } sides_;
  ClumpCorrection link_;

  [[noreturn]] void fail(const std::string& msg);
  void log(const std::string& msg);
  void parse(int, char**);
  void insert_clumps();
  int form_bodies();
  void map_atoms();
  void set_spheres(bool positions);
  void forward(tdem::clumps::BodySet::Comm c);
  void write_vtk();
};

}  // namespace LAMMPS_NS
