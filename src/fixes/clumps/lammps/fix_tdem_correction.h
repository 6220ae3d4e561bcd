// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/correction, the multiple-contact correction of fix tdem/clump for bodies
// that another fix integrates (issue 20; docs/clumps_lammps.md, "Multiple-contact correction"):
//
//   fix ID group tdem/correction count|overlap bodies FIXID
//
// FIXID is a rigid-body fix that exports its bodies as fix rigid does (extract("body"): body index
// per owned and ghost atom, extract("masstotal"): mass per body), e.g. the stock fix rigid/small
// molecule or fix rigid molecule. The sides of the contact tally are the molecule IDs of the atoms
// (per-atom, ghosts included: `fix property/atom mol ghost yes`), so every body must have a
// molecule ID of its own. pair tdem/gran and fix tdem/wall/gran find this fix as they find a fix
// tdem/clump with a correction (pair_styles/lammps/clump_correction_host.h). local_mass needs the
// bodies' centres of mass and inertia, which the stock fixes do not export: not offered here.
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
#include <vector>

namespace LAMMPS_NS {

class FixTDEMCorrection : public Fix {
 public:
  FixTDEMCorrection(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

 private:
  std::string where;
  std::string bodies_id;  // the fix that integrates the bodies
  int correction;         // tdem::clumps::Correction (count or overlap)
  class Fix *bodies;
  std::vector<std::int64_t> key;  // per atom (owned and ghost): molecule ID of a body atom, else -1
  void update_keys();
  [[noreturn]] void no_bodies();
};

}  // namespace LAMMPS_NS

#endif
#endif
