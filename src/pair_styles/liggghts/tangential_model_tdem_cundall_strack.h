// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `tangential tdem/cundall_strack` -- the Cundall-Strack tangential law
// (src/contact/tangential/cundall_strack.h) as a LIGGGHTS TangentialModel. Adapter only: the
// tangential stiffness kt and damping gammat come from whatever normal model ran before
// (sidata.kt, sidata.gammat, as for LIGGGHTS's own `tangential history`), the friction
// coefficient from fix property/global coefficientFriction, the spring elongation lives in
// the LIGGGHTS contact history (slots and sign-flip rule from cundall_strack::history).
//
//   ... tangential tdem/cundall_strack [slip_rule spring|spring_dashpot]
//
// slip_rule spring (default): the Coulomb limit caps the spring force (= `tangential history`);
// slip_rule spring_dashpot: the limit caps spring + dashpot (= LAMMPS gran/hooke/history).
#pragma once

#include <cmath>
#include <cstdio>

#include "contact_models.h"
#include "tangential_model_base.h"
#include "global_properties.h"
#include "update.h"
#include "atom.h"
#include "error.h"

#include "contact/tangential/cundall_strack.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "contact/usual_ranges.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class TangentialModel<TDEM_CUNDALL_STRACK> : public TangentialModelBase {
 public:
  enum Rule { SPRING = 0, SPRING_DASHPOT = 1 };

  TangentialModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : TangentialModelBase(lmp, hsetup, c) {
    namespace cs = tdem::cundall_strack;
    // LIGGGHTS stores history values of one model contiguously; "1" = flips sign with the
    // pair order (newton flag), "0" = does not.
    history_offset_ = hsetup->add_history_value(cs::history[0].name, cs::history[0].flips_sign ? "1" : "0");
    for (int k = 1; k < cs::history_size; ++k)
      hsetup->add_history_value(cs::history[k].name, cs::history[k].flips_sign ? "1" : "0");
  }

  void registerSettings(Settings& settings) {
    tdem::liggghts::register_enum(lmp, settings, "tangential tdem/cundall_strack", "slip_rule", rule_, {"spring", "spring_dashpot"}, SPRING);
  }

  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
    registry.connect("coeffFrict", coeff_frict_, "tangential tdem/cundall_strack");
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    tdem::liggghts::check_matrix(lmp, coeff_frict_, n, "coefficientFriction", "tangential tdem/cundall_strack", 1);
    tdem::liggghts::warn_unusual(lmp, coeff_frict_, n, "coefficientFriction", "tangential tdem/cundall_strack",
                                 &tdem::usual::friction);
  }

  inline void surfacesIntersect(const SurfacesIntersectData& sidata, ForceData& i_forces,
                                ForceData& j_forces) {
    namespace cs = tdem::cundall_strack;
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;

    double* const shear = &sidata.contact_history[history_offset_];
    const bool update_history = sidata.computeflag && sidata.shearupdate;
    const cs::Params<double> p{sidata.kt, sidata.gammat, coeff_frict_[sidata.itype][sidata.jtype]};
    const cs::Kinematics<double> kin{{sidata.en[0], sidata.en[1], sidata.en[2]},
                                     1.0,
                                     {sidata.vtr1, sidata.vtr2, sidata.vtr3},
                                     update->dt};
    double Ft[3];
    if (rule_ == SPRING) {
      cs::force<cs::SlipRule::spring_cap>(p, kin, sidata.Fn, update_history, shear, Ft);
    } else {
      // the spring_dashpot rule rescales the spring by gammat/kt on sliding
      if (!(p.kt > 0.0)) kt_error(p.kt, sidata.itype, sidata.jtype);
      cs::force<cs::SlipRule::spring_dashpot_cap>(p, kin, sidata.Fn, update_history, shear, Ft);
    }

    // torques and force application: same arithmetic as LIGGGHTS's tangential models
    const double enx = sidata.en[0], eny = sidata.en[1], enz = sidata.en[2];
    const double tor1 = eny * Ft[2] - enz * Ft[1];
    const double tor2 = enz * Ft[0] - enx * Ft[2];
    const double tor3 = enx * Ft[1] - eny * Ft[0];
    const double torque_i[3] = {-sidata.cri * tor1, -sidata.cri * tor2, -sidata.cri * tor3};

    if (sidata.is_wall) {
      const double area_ratio = sidata.area_ratio;
      i_forces.delta_F[0] += Ft[0] * area_ratio;
      i_forces.delta_F[1] += Ft[1] * area_ratio;
      i_forces.delta_F[2] += Ft[2] * area_ratio;
      i_forces.delta_torque[0] += torque_i[0] * area_ratio;
      i_forces.delta_torque[1] += torque_i[1] * area_ratio;
      i_forces.delta_torque[2] += torque_i[2] * area_ratio;
    } else {
      i_forces.delta_F[0] += Ft[0];
      i_forces.delta_F[1] += Ft[1];
      i_forces.delta_F[2] += Ft[2];
      j_forces.delta_F[0] += -Ft[0];
      j_forces.delta_F[1] += -Ft[1];
      j_forces.delta_F[2] += -Ft[2];
      i_forces.delta_torque[0] += torque_i[0];
      i_forces.delta_torque[1] += torque_i[1];
      i_forces.delta_torque[2] += torque_i[2];
      j_forces.delta_torque[0] += -sidata.crj * tor1;
      j_forces.delta_torque[1] += -sidata.crj * tor2;
      j_forces.delta_torque[2] += -sidata.crj * tor3;
    }
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_TANGENTIAL_MODEL;
    if (!scdata.contact_history) return;  // no history storage in this pass
    double* const shear = &scdata.contact_history[history_offset_];
    for (int k = 0; k < tdem::cundall_strack::history_size; ++k) shear[k] = 0.0;
  }

  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

 private:
  [[gnu::noinline, gnu::cold]] void kt_error(double kt, int itype, int jtype) {
    char buf[384];
    std::snprintf(buf, sizeof buf,
                  "tangential tdem/cundall_strack: 'slip_rule spring_dashpot' needs a tangential "
                  "stiffness kt > 0, but the normal model gives kt = %g for atom types %d %d "
                  "(use slip_rule spring, or kt / tangentialStiffnessRatio > 0)",
                  kt, itype, jtype);
    tdem::liggghts::error_one(lmp, FLERR, buf);
  }

  double** coeff_frict_ = nullptr;
  int history_offset_ = 0;
  int rule_ = SPRING;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
