// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/correction, the multiple-contact correction of fix tdem/clump for bodies
// that another fix integrates (issue 20; docs/lammps/fix_tdem_clump.md, "Multiple-contact correction"):
//
//   fix ID group tdem/correction count|overlap|local_mass bodies FIXID
//
// FIXID is a rigid-body fix that exports its bodies as fix rigid does (extract("body"): body index
// per owned atom, extract("masstotal"): mass per body), e.g. the stock fix rigid/small molecule or
// fix rigid molecule; local_mass needs a rigid/small style (its bodies' centres of mass, orientations
// and principal inertia come from an internal compute rigid/local). The sides of the contact tally
// are the molecule IDs of the atoms (per-atom, ghosts included: `fix property/atom mol ghost yes`),
// so every body must have a molecule ID of its own. pair tdem/gran and fix tdem/wall/gran find this
// fix as they find a fix tdem/clump with a correction (pair_styles/lammps/clump_correction_host.h).
//
// Per step (pre_force) the fix marks the body atoms, owned and ghost (the body fix knows only its
// owned atoms; a forward communication of 1 value per ghost), and for local_mass gives every body
// atom its body's mass, centre of mass and inverse inertia in the space frame: the rank owning a
// body (its owning atom) sends them to that atom's ghosts, every owned atom of the body copies them
// from there, and a second forward communication brings them to the ghosts (12 values per ghost
// each). The exported "body index" of an atom is the atom's own index.
#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/correction,FixTDEMCorrection);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_CORRECTION_H
#define TDEM_LMP_FIX_TDEM_CORRECTION_H

#include "fix.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

class FixTDEMCorrection : public Fix {
 public:
  FixTDEMCorrection(class LAMMPS *, int, char **);
  ~FixTDEMCorrection() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void *extract(const char *, int &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  std::string where;
  std::string bodies_id;  // the fix that integrates the bodies
  int correction;         // tdem::clumps::Correction (count, overlap or local_mass)
  class Fix *bodies;
  std::string compute_id;  // local_mass: the compute rigid/local of the bodies
  class Compute *rigid_local;
  // per atom (owned and ghost)
  std::vector<double> state;      // 0 free, 1 body atom, 2 the atom owning its body (local_mass)
  std::vector<int> body;          // the atom's own index for a body atom, else -1
  std::vector<std::int64_t> key;  // molecule ID of a body atom, else -1
  std::vector<double> mass;       // local_mass: body mass
  std::vector<double> com;        // local_mass: 3, body centre of mass
  std::vector<double> pose;       // local_mass: 7, quaternion and principal inertia
  std::vector<double> inv_inertia;  // local_mass: 9, space frame
  std::unordered_map<std::int64_t, int> owner;  // local_mass: molecule ID -> an owning atom here
  int comm_values;                              // values per atom of the current communication
  void grow();
  void refresh();
  void body_data();
  [[noreturn]] void no_bodies();
};

}  // namespace LAMMPS_NS

#endif
#endif
