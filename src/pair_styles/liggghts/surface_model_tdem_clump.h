// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: surface model `tdem/clump`, through which fix tdem/clump
// (src/fixes/clumps/liggghts) applies its multiple-contact correction (src/contact/multi_contact/multi_contact.h,
// docs/liggghts/fix_tdem_clump.md) to the contacts of a pair style or wall fix that asks for it:
//
//   pair_style gran model M tangential T surface tdem/clump
//   fix ID all wall/gran model M tangential T surface tdem/clump primitive ...
//
// LIGGGHTS calls per touching contact surfaceModel.surfacesIntersect() first (before the normal,
// cohesion, tangential and rolling models) and surfaceModel.endSurfacesIntersect() after all of
// them, before the pair loop or the wall adds the contact's ForceData to the atoms. This model
//  - does the kinematics of the default surface model (a SurfaceModel<SURFACE_DEFAULT> member:
//    same settings, same sidata fields, bitwise the same numbers);
//  - with an active correction (clump_link::active, set by a fix tdem/clump whose correction is
//    not none): before the laws, lets the fix replace sidata.meff by the locally reduced mass
//    (local_mass) and get the factor s of the contact (count, overlap); after the laws, multiplies
//    the whole output of the contact - force and torque on both sides - by s. This scales normal
//    elastic + damping, tangential (with its Coulomb limit, which follows the normal force) and
//    rolling of any model, stock or tdem, like scaling every stiffness and damping by s; the stored
//    tangential spring is the law's own and stays unscaled;
//  - without an active correction: warns once and acts as the default surface model.
// A pair style or wall without `surface tdem/clump` compiles none of this: it pays nothing.
#pragma once

#include "contact_models.h"
#include "surface_model_base.h"
#include "surface_model_default.h"

#include "tdem_liggghts_clump_link.h"
#include "tdem_liggghts_ids.h"

#include "comm.h"
#include "error.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class SurfaceModel<TDEM_CLUMP_SURFACE> : public SurfaceModelBase {
 public:
  SurfaceModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* cmb)
      : SurfaceModelBase(lmp, hsetup, cmb), base_(lmp, hsetup, cmb), owner_(hsetup) {}

  inline void registerSettings(Settings& settings) { base_.registerSettings(settings); }
  inline void postSettings(IContactHistorySetup* hsetup, ContactModelBase* cmb) { base_.postSettings(hsetup, cmb); }
  inline void connectToProperties(PropertyRegistry& registry) { base_.connectToProperties(registry); }
  inline bool checkSurfaceIntersect(SurfacesIntersectData& sidata) { return base_.checkSurfaceIntersect(sidata); }

  inline void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    base_.surfacesIntersect(sidata, i_forces, j_forces);  // deltan, vn, ... as the default model
    const tdem::liggghts::clump_link::Correction* c = tdem::liggghts::clump_link::active;
    if (c) {
      s_ = c->prepare(sidata, owner_);  // may set sidata.meff (local_mass)
      fi_ = &i_forces;
      fj_ = &j_forces;
    } else {
      s_ = 1.0;
      if (!warned_) warn();
    }
  }

  inline void endSurfacesIntersect(SurfacesIntersectData& sidata, TriMesh* mesh, double* const f) {
    base_.endSurfacesIntersect(sidata, mesh, f);
    if (s_ == 1.0) return;
    const double s = s_;
    for (int k = 0; k < 3; k++) {
      fi_->delta_F[k] *= s;
      fi_->delta_torque[k] *= s;
      fj_->delta_F[k] *= s;
      fj_->delta_torque[k] *= s;
    }
  }

  inline void surfacesClose(SurfacesCloseData& scdata, ForceData& i_forces, ForceData& j_forces) {
    base_.surfacesClose(scdata, i_forces, j_forces);
  }
  void beginPass(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    base_.beginPass(sidata, i_forces, j_forces);
  }
  void endPass(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    base_.endPass(sidata, i_forces, j_forces);
  }
  inline void tally_pp(double val, int i, int j, int index) { base_.tally_pp(val, i, j, index); }
  inline void tally_pw(double val, int i, int j, int index) { base_.tally_pw(val, i, j, index); }

 private:
  SurfaceModel<SURFACE_DEFAULT> base_;
  const void* owner_;  // the IContactHistorySetup (PairGran or FixWallGran) this model belongs to
  double s_ = 1.0;
  ForceData* fi_ = nullptr;
  ForceData* fj_ = nullptr;
  bool warned_ = false;

  __attribute__((noinline, cold)) void warn() {
    warned_ = true;
    error->warning(FLERR,
                   "surface tdem/clump: no fix tdem/clump with a correction other than none is active; the "
                   "surface model acts as 'surface default' (no multiple-contact correction)");
  }
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
