// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/correction, the multiple-contact correction of fix tdem/clump for
// the bodies of the stock fix multisphere (issue 20; docs/clumps_liggghts.md, "Multiple-contact
// correction"). Same syntax as the LAMMPS fix (src/fixes/clumps/lammps/fix_tdem_correction.h):
//
//   fix ID group tdem/correction count|overlap bodies FIXID
//
// FIXID is a fix multisphere (or a style derived from it, multisphere/break). The sides of the
// contact tally are its body IDs (FixMultisphere::belongs_to, forwarded to ghost atoms by the fix).
// The contacts must go through `surface tdem/clump` (pair style and primitive wall/gran fixes), as
// with fix tdem/clump. local_mass needs the centre of mass and inertia of the body of every ghost
// sphere, which fix multisphere keeps only on the rank owning the body: not offered here.
#pragma once

#include <cstdint>
#include <string>

#include "fix.h"

#include "clump_correction.h"

namespace LAMMPS_NS {

class FixTDEMCorrection : public Fix {
 public:
  FixTDEMCorrection(class LAMMPS*, int, char**);
  ~FixTDEMCorrection();
  int setmask();
  void init();
  void setup_pre_force(int);
  void pre_force(int);

 private:
  std::string where_;
  std::string bodies_id_;
  tdem::clumps::Correction mode_;
  struct Sides : CorrectionSides {
    class FixMultisphere* ms = nullptr;
    bool in_body(int i) const override;
    std::int64_t key(int i) const override;
    double inverse_side_mass(int, const double*) const override { return 0.0; }  // local_mass: refused
  } sides_;
  ClumpCorrection link_;
  [[noreturn]] void fail(const std::string& msg);
};

}  // namespace LAMMPS_NS
