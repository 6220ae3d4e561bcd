// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: the link through which fix tdem/clump (src/clumps/liggghts) applies its
// multiple-contact correction (src/clumps/multi_contact.h, docs/clumps_liggghts.md) inside the
// tdem normal models (normal_model_tdem_*.h).
//
// The fix publishes itself in `active` (one fix with a correction other than none at a time) and
// withdraws in its destructor. A normal model's surfacesIntersect tests `active` once: nullptr (no
// clump fix, or correction none) -> the law as before, no other work. Otherwise the model calls
// corrected(): the fix may replace sidata.meff by the locally reduced mass at the contact
// (local_mass) and returns the factor s of the contact (count, overlap); the law then runs
// unchanged and its output - the normal force, and kn, kt, gamman, gammat that the tangential
// model reads after it - is multiplied by s. Tangential models that form their force from
// sidata.kt, sidata.gammat, sidata.gamman and sidata.Fn (stock tangential history, tdem/
// cundall_strack, tdem/linear_spring, tdem/haff_werner) are thereby scaled by s with their stored
// spring unchanged; see docs/clumps_liggghts.md for the others.
#pragma once

#include "contact_interface.h"

namespace tdem {
namespace liggghts {
namespace clump_link {

class Correction {
 public:
  virtual ~Correction() {}
  // Called for every contact of a tdem normal model while the fix is active. owner: the
  // IContactHistorySetup* the model was constructed with (PairGran or FixWallGran). May change
  // sidata.meff; returns the factor s (1: unscaled).
  virtual double prepare(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const void* owner) const = 0;
};

inline Correction* active = nullptr;

// Run the law `law(sidata, i_forces, j_forces)` with the correction of the active fix.
template <class Law>
__attribute__((noinline)) void corrected(Law&& law, LIGGGHTS::ContactModels::SurfacesIntersectData& sidata,
                                         LIGGGHTS::ContactModels::ForceData& i_forces,
                                         LIGGGHTS::ContactModels::ForceData& j_forces, const void* owner) {
  const double s = active->prepare(sidata, owner);
  law(sidata, i_forces, j_forces);
  if (s == 1.0) return;
  sidata.Fn *= s;
  sidata.kn *= s;
  sidata.kt *= s;
  sidata.gamman *= s;
  sidata.gammat *= s;
  // the normal model is the first to add to the forces of the contact (ForceData reset before)
  for (int k = 0; k < 3; k++) {
    i_forces.delta_F[k] *= s;
    i_forces.delta_torque[k] *= s;
    j_forces.delta_F[k] *= s;
    j_forces.delta_torque[k] *= s;
  }
}

}  // namespace clump_link
}  // namespace liggghts
}  // namespace tdem
