// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/clump, rigid multi-sphere clumps of one template (issue 6,
// physics_reference.md section 6, core src/fixes/clumps/). See docs/clumps_lammps.md.
//
//   fix ID group tdem/clump template NAME (file PATH | shape SHAPE r d [n]) [density RHO]
//       [integration columns|voxel|monte_carlo] [resolution N] [rotation splitting|explicit|richardson]
//       [insert N region REGID seed S [type T] [vel vx vy vz]] [bodies molecule]
//       [correction none|count|overlap|local_mass]
//
// Design ("global bodies", as fix rigid): every rank keeps the state {x, v, q, L} of every body;
// per half step each rank sums force and torque of the spheres it owns, MPI_Allreduce, every rank
// advances every body identically (core rigid_body.h) and sets x, v, omega of its owned spheres.
// The sphere -> (body, sphere of the template) map is a global tag map; per-atom body indices
// (owned and ghost) are refreshed in pre_neighbor. rigid_flag = 1 with extract("body") and
// extract("masstotal"), so the granular pair and wall styles use the body mass as m*.
// The multiple-contact correction (clumps/multi_contact.h) is applied by pair tdem/gran and fix
// tdem/wall/gran, which read it with extract("tdem_clump_correction") and, for local_mass, the
// per-body com ("tdem_clump_com", 3 per body, unwrapped) and inverse inertia in the space frame
// ("tdem_clump_inv_inertia", 9 per body, row-major), current after initial_integrate.

#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/clump,FixTDEMClump);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_CLUMP_H
#define TDEM_LMP_FIX_TDEM_CLUMP_H

#include "fix.h"

#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/rigid_body.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

class FixTDEMClump : public Fix {
 public:
  FixTDEMClump(class LAMMPS *, int, char **);
  ~FixTDEMClump() override;
  int setmask() override;
  void post_constructor() override;
  void init() override;
  void setup_pre_neighbor() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void pre_neighbor() override;
  void reset_dt() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  double compute_array(int, int) override;
  void *extract(const char *, int &) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

 private:
  std::string where;  // "fix ID tdem/clump" for messages
  tdem::clumps::Template tmpl;
  tdem::clumps::Body bprop;
  tdem::clumps::Rotation scheme;
  int nsph;                          // spheres per body
  std::vector<double> sphere_mass;   // mass of each template sphere (volume share of M)
  int bodies_molecule;               // form bodies from the group's molecules at the first setup
  int correction;                    // tdem::clumps::Correction, for the pair and wall styles
  int restarted;                     // bodies read from a restart file
  int formed;                        // bodies from molecules formed
  // insertion
  int ninsert, insert_type;
  std::string insert_region;
  long long insert_seed;
  double insert_vel[3];
  // global bodies
  std::vector<tdem::clumps::State> st;
  std::vector<tagint> molid;          // molecule ID of each body
  std::vector<tagint> btags;          // nbody * nsph sphere tags (template order)
  std::vector<double> masstotal;      // body masses (for extract)
  std::vector<double> fsum;           // 6 per body: force, torque of the last force evaluation
  std::vector<double> sphere_f;       // 6 per sphere slot (body * nsph + sphere): force, torque about the com
  std::vector<tdem::clumps::Mat3> rot;  // rotation matrix per body (current q)
  std::vector<tdem::clumps::Vec3> omg;  // angular velocity per body
  std::vector<double> bcom, binv;       // per body: com (3), inverse inertia, space frame (9)
  std::unordered_map<tagint, int> slot;  // tag -> body * nsph + sphere
  // per atom (owned + ghost): body index (-1: not a clump sphere) and sphere index
  int nmax_idx;
  int *bodyidx, *sphidx;
  double dtv, dtf;

  void parse(int, char **);
  void insert_clumps();
  void form_bodies();
  void map_atoms();
  void refresh_kinematics();
  void sum_forces();
  void set_spheres(bool positions);
  void add_body(tagint mol, const tdem::clumps::State &s, const tagint *tags);
  void unwrapped(int i, double *xu) const;
};

}  // namespace LAMMPS_NS

#endif
#endif
