// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/correction, the multiple-contact correction of fix tdem/clump for
// the bodies of the stock fix multisphere (issue 20; docs/liggghts/fix_tdem_clump.md, "Multiple-contact
// correction"). Same syntax as the LAMMPS fix (src/fixes/clumps/lammps/fix_tdem_correction.h):
//
//   fix ID group tdem/correction count|overlap|local_mass bodies FIXID
//
// FIXID is a fix multisphere (or a style derived from it, multisphere/break). The sides of the
// contact tally are its body IDs (FixMultisphere::belongs_to, forwarded to ghost atoms by the fix).
// The contacts must go through `surface tdem/clump` (pair style and primitive wall/gran fixes), as
// with fix tdem/clump. local_mass: fix multisphere keeps a body's centre of mass and inertia on the
// rank owning the body, which holds all the body's spheres as owned or ghost atoms; per step that
// rank writes them to its atoms of the body, a reverse communication brings them to the ranks owning
// those atoms and a forward communication to their ghosts (14 values per ghost each way).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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
  int pack_comm(int, int*, double*, int, int*);
  void unpack_comm(int, int, double*);
  int pack_reverse_comm(int, int, double*);
  void unpack_reverse_comm(int, int*, double*);
  double memory_usage();

 private:
  std::string where_;
  std::string bodies_id_;
  tdem::clumps::Correction mode_;
  struct Sides : CorrectionSides {
    class FixMultisphere* ms = nullptr;
    bool in_body(int i) const override;
    std::int64_t key(int i) const override;
    double inverse_side_mass(int i, const double* n) const override;
    // local_mass, per atom (owned and ghost): 1 when set this step, body mass, com (3), inverse
    // inertia in the space frame (9)
    std::vector<double> data;
    class Domain* domain = nullptr;
    class Atom* atom = nullptr;
  } sides_;
  ClumpCorrection link_;
  void body_data();
  [[noreturn]] void fail(const std::string& msg);
};

}  // namespace LAMMPS_NS
