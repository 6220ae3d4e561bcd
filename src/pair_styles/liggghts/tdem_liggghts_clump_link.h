// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: the link through which fix tdem/clump (src/fixes/clumps/liggghts) applies its
// multiple-contact correction (src/contact/multi_contact/multi_contact.h, docs/liggghts/fix_tdem_clump.md) in the surface
// model `tdem/clump` (surface_model_tdem_clump.h).
//
// The fix publishes itself in `active` (one fix with a correction other than none at a time) and
// withdraws in its destructor. The surface model tdem/clump asks `active` per contact: nullptr (no
// clump fix, or correction none) -> the default surface model. Otherwise prepare() may replace
// sidata.meff by the locally reduced mass at the contact (local_mass) and returns the factor s of
// the contact (count, overlap), by which the surface model multiplies the whole output of the
// contact after all laws ran. Pair styles and walls without `surface tdem/clump` never look here.
#pragma once

#include "contact_interface.h"

namespace tdem {
namespace liggghts {
namespace clump_link {

class Correction {
 public:
  virtual ~Correction() {}
  // Called for every contact of a `surface tdem/clump` contact model while the fix is active, after
  // the default surface kinematics (sidata.deltan set) and before the laws. owner: the
  // IContactHistorySetup* the model was constructed with (PairGran or FixWallGran). May change
  // sidata.meff; returns the factor s (1: unscaled).
  virtual double prepare(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const void* owner) const = 0;
};

inline Correction* active = nullptr;

}  // namespace clump_link
}  // namespace liggghts
}  // namespace tdem
