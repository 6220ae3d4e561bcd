// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/power_law` -- power-law loading/unloading hysteresis
// (src/contact/normal/power_law_hysteresis.h) as a LIGGGHTS NormalModel. Adapter only.
//
//   pair_style gran model tdem/power_law [tangential ...]
//
// loading F = a_l xi^p, unloading F = a_ul (xi - xi_f)^(p+q), xi_f from continuity at xi_max.
// Properties (peratomtypepair): loadingCoefficient a_l > 0 [N/m^p], loadingExponent p > 0,
// unloadingCoefficient a_ul > 0 [N/m^(p+q)], unloadingExponentIncrement q >= 0,
// tangentialStiffnessRatio kappa (kt = kappa dF/dxi). Per-contact history: xi_max and xi_f (scalars, no
// sign flip), reset when the particles separate. No damping, no attraction: the contact ends at
// zero force (there is no limitForce keyword).
#pragma once

#include <cstdio>
#include <stdexcept>

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"
#include "update.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/power_law_hysteresis.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_POWER_LAW> : public NormalModelBase {
 public:
  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {
    // The kernel's slots (tdem::power_law::history: xi_max, xi_f), adjacent, no sign flip.
    history_offset_ = hsetup->add_history_value(tdem::power_law::history[0].name, "0");
    for (int s = 1; s < tdem::power_law::history_size; ++s)
      hsetup->add_history_value(tdem::power_law::history[s].name, "0");
    stamp_offset_ = hsetup->add_history_value("tdem_step", "0");  // last step evaluated + 1
  }

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings&) {}
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/power_law";
    if (force->cg_active())
      error->all(FLERR, "model tdem/power_law does not support coarse-graining (cg factor != 1)");
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    double **al = nullptr, **p = nullptr, **aul = nullptr, **q = nullptr, **kappa = nullptr;
    registry.registerProperty(tdem::liggghts::kPropLoadingCoefficient, &tdem::liggghts::create_loading_coefficient);
    registry.registerProperty(tdem::liggghts::kPropLoadingExponent, &tdem::liggghts::create_loading_exponent);
    registry.registerProperty(tdem::liggghts::kPropUnloadingCoefficient, &tdem::liggghts::create_unloading_coefficient);
    registry.registerProperty(tdem::liggghts::kPropUnloadingExponentIncrement,
                              &tdem::liggghts::create_unloading_exponent_increment);
    registry.registerProperty(tdem::liggghts::kPropStiffnessRatio, &tdem::liggghts::create_stiffness_ratio);
    registry.connect(tdem::liggghts::kPropLoadingCoefficient, al, caller);
    registry.connect(tdem::liggghts::kPropLoadingExponent, p, caller);
    registry.connect(tdem::liggghts::kPropUnloadingCoefficient, aul, caller);
    registry.connect(tdem::liggghts::kPropUnloadingExponentIncrement, q, caller);
    registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        PairCoefficients& pc = coef_(i, j);
        // coefficients in force units as model hooke/stiffness converts kn (1 in SI)
        pc.p = {al[i][j] / force->nktv2p, p[i][j], aul[i][j] / force->nktv2p, q[i][j]};
        pc.kappa = kappa[i][j];
        try {
          tdem::power_law::validate(pc.p);
        } catch (const std::exception& ex) {
          char buf[512];
          std::snprintf(buf, sizeof buf, "%s: atom types %d %d: %s", caller, i, j, ex.what());
          error->all(FLERR, buf);
        }
      }
    publish_advice();
  }

  inline double stressStrainExponent() { return 1.; }

  inline void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, "model tdem/power_law", sidata.i, sidata.j, sidata.is_wall);
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    double* const hist = &sidata.contact_history[history_offset_];
    tdem::liggghts::clear_history_of_new_contact(sidata.contact_history[stamp_offset_], hist, tdem::power_law::history_size,
                                                 static_cast<double>(update->ntimestep),
                                                 sidata.computeflag && sidata.shearupdate);
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, 0.0};
    const tdem::NormalResult<double> r =
        tdem::power_law::force(pc.p, kin, hist, sidata.computeflag && sidata.shearupdate);
    tdem::liggghts::apply_normal_result(sidata, r.force, r.stiffness, pc.kappa * r.stiffness, 0.0, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (scdata.contact_history)  // contact over
      for (int s = 0; s < tdem::power_law::history_size; ++s) scdata.contact_history[history_offset_ + s] = 0.0;
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The coefficients for fix tdem/timestep (tdem_liggghts_advice.h).
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    ad::Entry e;
    e.model = this;
    e.law = ad::Law::power_law;
    e.name = "tdem/power_law";
    e.end = tdem::ContactEnd::zero_force;
    const auto coef = coef_;
    e.coefficients = [coef](const ad::PairData& d) {
      ad::Coefficients c;
      c.power_law = coef(d.itype, d.jtype).p;
      return c;
    };
    ad::publish(advice_owner_, std::move(e));
  }

 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    tdem::power_law::Params<double> p;
    double kappa;
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  int history_offset_ = 0;
  int stamp_offset_ = 0;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
