// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/clump, rigid multi-sphere clumps of one template (issue 6,
// physics_reference.md section 6, core src/fixes/clumps/). See docs/lammps/fix_tdem_clump.md.
//
//   fix ID group tdem/clump template NAME (file PATH | shape SHAPE r d [n]) [density RHO]
//       [integration columns|voxel|monte_carlo] [resolution N] [rotation splitting|explicit|richardson]
//       [insert N region REGID seed S [type T] [vel vx vy vz]] [bodies molecule]
//       [correction none|count|overlap|local_mass] [vtk N prefix]
//
// Design ("local bodies", shared with the LIGGGHTS fix: src/fixes/clumps/body_set.h): a rank keeps
// the bodies of the spheres it owns; the body state travels with the spheres (exchange and
// per-atom restart records), the forces of ghost spheres come by forward communication, and
// every rank holding a body advances it identically. The ghost cutoff is raised to the largest
// distance between two spheres of the template when the pair cutoff is shorter.
// rigid_flag = 1 with extract("body") and extract("masstotal") (per local body), so the granular
// pair and wall styles use the body mass as m*. The multiple-contact correction
// (clumps/multi_contact.h) is applied by pair tdem/gran and fix tdem/wall/gran, which read it with
// extract("tdem_clump_correction"), the body key per atom ("tdem_clump_key", int64, the same on
// every rank: the sides of the contact tally) and, for local_mass, the per-body com
// ("tdem_clump_com", 3 per local body, unwrapped) and inverse inertia in the space frame
// ("tdem_clump_inv_inertia", 9 per local body, row-major), current after initial_integrate.

#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/clump,FixTDEMClump);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_CLUMP_H
#define TDEM_LMP_FIX_TDEM_CLUMP_H

#include "fix.h"

#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/body_output.h"
#include "fixes/clumps/body_set.h"
#include "fixes/clumps/body_vtk.h"
#include "fixes/clumps/clump_args.h"

#include <memory>
#include <string>

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
  void end_of_step() override;
  void pre_neighbor() override;
  void reset_dt() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  double compute_array(int, int) override;
  void *extract(const char *, int &) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

 private:
  std::string where;  // "fix ID tdem/clump" for messages
  tdem::clumps::BodySet bodies;      // the bodies, shared with LIGGGHTS (fixes/clumps/body_set.h)
  tdem::clumps::BodyOutput reports;  // scalar, vector, array over the ranks
  tdem::clumps::ClumpArgs args;     // the fix's arguments (insert, bodies molecule, correction)
  int correction;                    // tdem::clumps::Correction, for the pair and wall styles
  std::unique_ptr<tdem::clumps::BodyVtk> vtk;  // vtk N prefix (body_vtk.h), or none
  tdem::clumps::Clock clock;         // simulation time of the VTK files (kept in the restart record)
  int restarted;                     // bodies read from a restart file
  int formed;                        // bodies from molecules formed
  double dtv, dtf;

  void parse(int, char **);
  void insert_clumps();
  void form_bodies();
  void map_atoms();
  void set_spheres(bool positions);
  void forward(tdem::clumps::BodySet::Comm c);
  void write_vtk();
};

}  // namespace LAMMPS_NS

#endif
#endif
