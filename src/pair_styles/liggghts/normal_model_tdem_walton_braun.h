// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/walton_braun` -- Walton & Braun's hysteretic linear law
// (src/contact/normal/walton_braun.h) as a LIGGGHTS NormalModel. Adapter only.
//
//   pair_style gran model tdem/walton_braun [tangential ...]
//
// Properties (peratomtypepair): loadingStiffness k_l > 0, unloadingStiffness k_u >= k_l,
// unloadingStiffnessSlope s >= 0 (k_ul = k_u + s F_max), tangentialStiffnessRatio kappa
// (kt = kappa k_l). Per-contact history: xi_max (a scalar, no sign flip), reset when the
// particles separate. No damping, no attraction.
#pragma once

#include <cstdio>

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"
#include "update.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/walton_braun.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_WALTON_BRAUN> : public NormalModelBase {
 public:
  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {
    history_offset_ = hsetup->add_history_value("xi_max", "0");
    stamp_offset_ = hsetup->add_history_value("tdem_step", "0");  // last step evaluated + 1
  }

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings&) {}
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/walton_braun";
    if (force->cg_active())
      error->all(FLERR, "model tdem/walton_braun does not support coarse-graining (cg factor != 1)");
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    double **kl = nullptr, **ku = nullptr, **s = nullptr, **kappa = nullptr;
    registry.registerProperty(tdem::liggghts::kPropLoadingStiffness, &tdem::liggghts::create_loading_stiffness);
    registry.registerProperty(tdem::liggghts::kPropUnloadingStiffness, &tdem::liggghts::create_unloading_stiffness);
    registry.registerProperty(tdem::liggghts::kPropUnloadingSlope, &tdem::liggghts::create_unloading_slope);
    registry.registerProperty(tdem::liggghts::kPropStiffnessRatio, &tdem::liggghts::create_stiffness_ratio);
    registry.connect(tdem::liggghts::kPropLoadingStiffness, kl, caller);
    registry.connect(tdem::liggghts::kPropUnloadingStiffness, ku, caller);
    registry.connect(tdem::liggghts::kPropUnloadingSlope, s, caller);
    registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        if (!(ku[i][j] >= kl[i][j])) {
          char buf[512];
          std::snprintf(buf, sizeof buf,
                        "%s: fix property/global unloadingStiffness has value %.15g for atom types %d %d; "
                        "allowed: unloadingStiffness >= loadingStiffness (%.15g)",
                        caller, ku[i][j], i, j, kl[i][j]);
          error->all(FLERR, buf);
        }
        PairCoefficients& pc = coef_(i, j);
        pc.p = {kl[i][j] / force->nktv2p, ku[i][j] / force->nktv2p, s[i][j]};
        pc.kt = kappa[i][j] * pc.p.k_load;
      }
    publish_advice();
  }

  inline double stressStrainExponent() { return 1.; }

  inline void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, "model tdem/walton_braun", sidata.i, sidata.j, sidata.is_wall);
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    double* const hist = &sidata.contact_history[history_offset_];
    tdem::liggghts::clear_history_of_new_contact(sidata.contact_history[stamp_offset_], hist, 1,
                                                 static_cast<double>(update->ntimestep),
                                                 sidata.computeflag && sidata.shearupdate);
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, 0.0};
    const tdem::NormalResult<double> r =
        tdem::walton_braun::force(pc.p, kin, hist, sidata.computeflag && sidata.shearupdate);
    tdem::liggghts::apply_normal_result(sidata, r.force, r.stiffness, pc.kt, 0.0, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (scdata.contact_history) scdata.contact_history[history_offset_] = 0.0;  // contact over
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The coefficients for fix tdem/timestep (tdem_liggghts_advice.h).
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    ad::Entry e;
    e.model = this;
    e.law = ad::Law::walton_braun;
    e.name = "tdem/walton_braun";
    e.end = tdem::ContactEnd::zero_force;
    const auto coef = coef_;
    e.coefficients = [coef](const ad::PairData& d) {
      ad::Coefficients c;
      c.walton_braun = coef(d.itype, d.jtype).p;
      return c;
    };
    ad::publish(advice_owner_, std::move(e));
  }

 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    tdem::walton_braun::Params<double> p;
    double kt;
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  int history_offset_ = 0;
  int stamp_offset_ = 0;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
