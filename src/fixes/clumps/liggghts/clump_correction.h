// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: the multiple-contact correction (src/contact/multi_contact/, docs/liggghts/fix_tdem_clump.md)
// for any kind of bodies, as fix tdem/clump (its own bodies) and fix tdem/correction (the bodies of
// the stock fix multisphere) use it. The bodies are named by a CorrectionSides: which atoms (owned
// and ghost) belong to a body and the body's key, the same on every rank. Per step, tally() counts
// every touching contact per pair of sides over all ranks (contact_tally.h); prepare() is called by
// the surface model tdem/clump for every contact (tdem_liggghts_clump_link.h) and gives its factor.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "contact/multi_contact/contact_tally.h"
#include "contact/multi_contact/contact_tally_mpi.h"
#include "contact/multi_contact/multi_contact.h"
#include "tdem_liggghts_clump_link.h"

namespace LAMMPS_NS {

class CorrectionSides {
 public:
  virtual ~CorrectionSides() {}
  virtual bool in_body(int i) const = 0;      // atom i (owned or ghost) belongs to a body
  virtual std::int64_t key(int i) const = 0;  // its body's key, >= 1 (when in_body(i))
  // 1/M + (r x n).I^-1 (r x n) of the body of atom i at its contact along n (correction local_mass)
  virtual double inverse_side_mass(int i, const double* n) const = 0;
};

class ClumpCorrection : public tdem::liggghts::clump_link::Correction {
 public:
  ClumpCorrection(class LAMMPS* lmp, const CorrectionSides& sides) : lmp_(lmp), sides_(sides) {}
  // Checks that the granular pair style and the wall/gran fixes carry `surface tdem/clump` (the
  // correction acts through it) and sets the tally's length scale (diameter: the largest sphere that
  // may appear beyond the present atoms). Stops with a message naming `where` otherwise.
  void setup(tdem::clumps::Correction mode, const std::string& where, double diameter);
  // the contact tally of this step (count, overlap), merged over the ranks
  void tally();
  double prepare(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const void* owner) const override;
  tdem::clumps::Correction mode() const { return mode_; }
  bool tallies() const {
    return mode_ == tdem::clumps::Correction::count || mode_ == tdem::clumps::Correction::overlap_share;
  }

 private:
  class LAMMPS* lmp_;
  const CorrectionSides& sides_;
  tdem::clumps::Correction mode_ = tdem::clumps::Correction::none;
  tdem::clumps::ContactTally tally_;
  class PairGran* pair_gran_ = nullptr;
  std::vector<class FixWallGran*> walls_;                         // primitive wall/gran fixes
  std::vector<std::pair<const void*, std::int64_t>> wall_sides_;  // contact-model owner -> side id
  tdem::clumps::TallyExchange exchange_;                          // scratch of the MPI merge
  tdem::clumps::TallyNeighbours near_;                            // the ranks it merges with
  std::vector<std::int64_t> side_;                                // per atom: its side this step
  std::int64_t side(int a) const;
  double inverse_mass(int a, const double* n) const;
};

}  // namespace LAMMPS_NS
