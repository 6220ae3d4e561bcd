// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/clump, rigid multi-sphere clumps of one template (issue 6,
// physics_reference.md section 6, core src/fixes/clumps/, shared host code src/fixes/clumps/host_bodies.h).
// See docs/clumps_liggghts.md. Same syntax as the LAMMPS fix (src/fixes/clumps/lammps):
//
//   fix ID group tdem/clump template NAME (file PATH | shape SHAPE r d [n]) [density RHO]
//       [integration columns|voxel|monte_carlo] [resolution N] [rotation splitting|explicit|richardson]
//       [insert N region REGID seed S [type T] [vel vx vy vz]] [bodies molecule]
//       [correction none|count|overlap|local_mass]
//
// Needs per-atom molecule IDs (atom_style hybrid sphere molecular) and
// `neigh_modify exclude molecule GROUP` (the spheres of one clump must not interact).
//
// Design ("global bodies", as LAMMPS fix rigid): every rank keeps the state {x, v, q, L} of every
// body; in final_integrate each rank writes force and torque (about the com) of its owned spheres
// into per-sphere slots and sums them per body in template order; MPI_Allreduce of 6 doubles per
// body (one rank contributes a non-zero value) or, for a body split over ranks, of its 6 nsph slot
// values (summed after the reduction in template order): the sum is bitwise independent of the rank
// count. Every rank advances every body identically (rigid_body.h) and
// sets x, v, omega of its owned spheres. Spheres of one body may lie on several ranks; positions use
// the image flags (x = com + Lambda r_hat - image * L_box).
//
// The force of the last final_integrate is kept (and written to restart files): a new run, or a run
// after read_restart, starts with it instead of the set-up force, which in LIGGGHTS differs from it
// (contact history) - so the fix continues `run N; run M` and restarts exactly as one run (as far as
// the contact styles do: bitwise with tdem's laws; see docs/clumps_liggghts.md).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

#include "fix.h"

#include "contact/multi_contact/contact_tally.h"
#include "contact/multi_contact/contact_tally_mpi.h"
#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/rigid_body.h"
#include "tdem_liggghts_clump_link.h"

namespace LAMMPS_NS {

class FixTDEMClump : public Fix, public tdem::liggghts::clump_link::Correction {
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
  void pre_neighbor();
  void setup_pre_force(int);
  void pre_force(int);
  // multiple-contact correction (tdem_liggghts_clump_link.h): called by the surface model tdem/clump
  double prepare(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const void* owner) const override;
  void reset_dt();
  double compute_scalar();
  double compute_vector(int);
  double compute_array(int, int);
  void* extract(const char*, int&);
  void write_restart(FILE*);
  void restart(char*);
  double memory_usage();

 private:
  std::string where_;  // "fix ID tdem/clump" for messages
  tdem::clumps::Template tmpl_;
  tdem::clumps::Body bprop_;
  tdem::clumps::Rotation scheme_;
  int nsph_;
  std::vector<double> sphere_mass_;
  bool bodies_molecule_, restarted_, formed_, have_force_, need_set_;
  // insertion
  int ninsert_, insert_type_;
  std::string insert_region_;
  long long insert_seed_;
  double insert_vel_[3];
  // global bodies
  std::vector<tdem::clumps::State> st_;
  std::vector<int> molid_;
  std::vector<int> btags_;  // nbody * nsph sphere tags (template order)
  std::vector<double> fsum_;     // 6 per body: force, torque about the com
  std::vector<double> slotf_;    // 6 per sphere slot (local)
  std::vector<double> red_;      // reduction buffer: 6 per whole body, 6 nsph per split body
  std::vector<std::size_t> red_off_;  // offsets into red_ per body
  std::vector<char> split_;      // body split over ranks (set in map_atoms)
  std::vector<tdem::clumps::Mat3> rot_;
  std::vector<tdem::clumps::Vec3> omg_;
  std::unordered_map<int, int> slot_;  // tag -> body * nsph + sphere
  int nmax_idx_;
  int* bodyidx_;
  int* sphidx_;

  // multiple-contact correction (docs/clumps_liggghts.md, "Multiple-contact correction")
  tdem::clumps::Correction correction_;
  tdem::clumps::ContactTally tally_;
  class PairGran* pair_gran_;
  std::vector<class FixWallGran*> walls_;                      // primitive wall/gran fixes
  std::vector<std::pair<const void*, std::int64_t>> wall_sides_;  // contact-model owner -> side id
  tdem::clumps::TallyExchange exchange_;  // scratch of the MPI merge of tally_
  void setup_correction();
  void build_tally();
  double inverse_side_mass(int a, const double* n) const;

  [[noreturn]] void fail(const std::string& msg);
  void log(const std::string& msg);
  void parse(int, char**);
  void insert_clumps();
  int form_bodies();
  void map_atoms();
  void refresh_kinematics();
  void sum_forces();
  void set_spheres(bool positions);
  void add_body(int mol, const tdem::clumps::State& s, const int* tags);
};

}  // namespace LAMMPS_NS
