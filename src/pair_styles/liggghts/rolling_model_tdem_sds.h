// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `rolling_friction tdem/sds` -- the spring-dashpot-slider rolling resistance of
// src/contact/rolling/sds.h (the kernel of LAMMPS `pair_coeff ... rolling sds KR GAMMAR MUR`) as a
// LIGGGHTS RollingModel. Adapter only.
//
//   pair_style gran model M tangential T rolling_friction tdem/sds
//   fix property/global rollingStiffness peratomtypepair N ...            k_r > 0 [force/length]
//   fix property/global rollingDamping peratomtypepair N ...              gamma_r >= 0 [mass/time]
//   fix property/global coefficientRollingFriction peratomtypepair N ...  mu_r >= 0
//
// n = sidata.en (from j to i; a wall: from the wall to the sphere), R* = R_i R_j/(R_i + R_j) (a
// wall: R_i), the spins of the atoms (a wall does not spin), F_n = sidata.Fn of the normal model.
// The rolling displacement (3 history values, not flipped with the pair order) lives in the
// LIGGGHTS contact history, so it migrates and restarts with the tangential history. Torque
// tau_i = R* n x F_r on i, -tau_i on j (on a wall: times the area ratio of the mesh element).
#pragma once

#include "contact_models.h"
#include "rolling_model_base.h"
#include "atom.h"
#include "update.h"

#include "contact/rolling/sds.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class RollingModel<TDEM_SDS> : public RollingModelBase {
 public:
  RollingModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : RollingModelBase(lmp, hsetup, c) {
    namespace rs = tdem::rolling_sds;
    history_offset_ = hsetup->add_history_value(rs::history[0].name, rs::history[0].flips_sign ? "1" : "0");
    for (int k = 1; k < rs::history_size; ++k)
      hsetup->add_history_value(rs::history[k].name, rs::history[k].flips_sign ? "1" : "0");
  }

  void registerSettings(Settings&) {}
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    namespace L = tdem::liggghts;
    const char* caller = "rolling_friction tdem/sds";
    registry.registerProperty(L::kPropRollingStiffness, &L::create_rolling_stiffness);
    registry.registerProperty(L::kPropRollingDamping, &L::create_rolling_damping);
    registry.registerProperty(L::kPropRollingFriction, &L::create_rolling_friction);
    registry.connect(L::kPropRollingStiffness, kr_, caller);
    registry.connect(L::kPropRollingDamping, gammar_, caller);
    registry.connect(L::kPropRollingFriction, mur_, caller);
  }

  void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_ROLLING_MODEL;
    const int it = sidata.itype, jt = sidata.jtype;
    const tdem::rolling_sds::Params<double> p{kr_[it][jt], gammar_[it][jt], mur_[it][jt]};
    const double reff = sidata.is_wall ? sidata.radi : sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
    static constexpr double still[3] = {0.0, 0.0, 0.0};
    const double* wi = atom->omega[sidata.i];
    const double* wj = sidata.is_wall ? still : atom->omega[sidata.j];
    double* const roll = &sidata.contact_history[history_offset_];
    double tau[3];
    tdem::rolling_sds::torque(p, sidata.en, reff, wi, wj, sidata.Fn, update->dt,
                              sidata.computeflag && sidata.shearupdate, roll, tau);
    if (sidata.is_wall) {
      const double a = sidata.area_ratio;
      i_forces.delta_torque[0] += tau[0] * a;
      i_forces.delta_torque[1] += tau[1] * a;
      i_forces.delta_torque[2] += tau[2] * a;
    } else {
      i_forces.delta_torque[0] += tau[0];
      i_forces.delta_torque[1] += tau[1];
      i_forces.delta_torque[2] += tau[2];
      j_forces.delta_torque[0] -= tau[0];
      j_forces.delta_torque[1] -= tau[1];
      j_forces.delta_torque[2] -= tau[2];
    }
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_ROLLING_MODEL;
    if (!scdata.contact_history) return;  // no history storage in this pass
    double* const roll = &scdata.contact_history[history_offset_];
    for (int k = 0; k < tdem::rolling_sds::history_size; ++k) roll[k] = 0.0;
  }

  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

 private:
  double** kr_ = nullptr;
  double** gammar_ = nullptr;
  double** mur_ = nullptr;
  int history_offset_ = 0;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
