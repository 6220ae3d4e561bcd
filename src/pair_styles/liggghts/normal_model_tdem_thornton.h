// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/thornton` -- Thornton's elastic-perfectly-plastic law
// (src/contact/normal/thornton.h) as a LIGGGHTS NormalModel. Adapter only.
//
//   pair_style gran model tdem/thornton [tangential ...]
//
// Properties: youngsModulus, poissonsRatio (peratomtype; LIGGGHTS's Yeff is E*), yieldPressure
// p_y > 0 and tangentialStiffnessRatio kappa (peratomtypepair); kt = kappa dF/dxi.
// Per-contact history: xi_max, f_max (scalars, no sign flip), reset when the particles separate.
#pragma once

#include <cmath>

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"
#include "update.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/thornton.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_THORNTON> : public NormalModelBase {
 public:
  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {
    history_offset_ = hsetup->add_history_value("xi_max", "0");
    const int second = hsetup->add_history_value("f_max", "0");
    if (second != history_offset_ + 1)
      error->all(FLERR, "model tdem/thornton: history values xi_max, f_max are not adjacent");
    stamp_offset_ = hsetup->add_history_value("tdem_step", "0");  // last step evaluated + 1
  }

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings&) {}
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/thornton";
    if (force->cg_active())
      error->all(FLERR, "model tdem/thornton does not support coarse-graining (cg factor != 1)");
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    double **yeff = nullptr, **py = nullptr, **kappa = nullptr;
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff);
    registry.registerProperty(tdem::liggghts::kPropYieldPressure, &tdem::liggghts::create_yield_pressure);
    registry.registerProperty(tdem::liggghts::kPropStiffnessRatio, &tdem::liggghts::create_stiffness_ratio);
    registry.connect("Yeff", yeff, caller);
    registry.connect(tdem::liggghts::kPropYieldPressure, py, caller);
    registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
    tdem::liggghts::check_matrix(lmp, yeff, n, "youngsModulus (effective modulus Yeff)", caller, 0);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        PairCoefficients& pc = coef_(i, j);
        pc.p = {yeff[i][j] / force->nktv2p, py[i][j] / force->nktv2p};
        pc.kappa = kappa[i][j];
      }
    publish_advice();
  }

  inline double stressStrainExponent() { return 1.5; }

  inline void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, "model tdem/thornton", sidata.i, sidata.j, sidata.is_wall);
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    const double reff = sidata.is_wall ? sidata.radi : (sidata.radi * sidata.radj / (sidata.radi + sidata.radj));
    double* const hist = &sidata.contact_history[history_offset_];
    tdem::liggghts::clear_history_of_new_contact(sidata.contact_history[stamp_offset_], hist, 2,
                                                 static_cast<double>(update->ntimestep),
                                                 sidata.computeflag && sidata.shearupdate);
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, reff};
    const tdem::NormalResult<double> r =
        tdem::thornton::force(pc.p, kin, hist, sidata.computeflag && sidata.shearupdate);
    tdem::liggghts::apply_normal_result(sidata, r.force, r.stiffness, pc.kappa * r.stiffness, 0.0, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (scdata.contact_history) {
      scdata.contact_history[history_offset_] = 0.0;
      scdata.contact_history[history_offset_ + 1] = 0.0;
    }
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The coefficients for fix tdem/timestep (tdem_liggghts_advice.h).
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    ad::Entry e;
    e.model = this;
    e.law = ad::Law::thornton;
    e.name = "tdem/thornton";
    e.end = tdem::ContactEnd::zero_force;
    const auto coef = coef_;
    e.coefficients = [coef](const ad::PairData& d) {
      ad::Coefficients c;
      c.thornton = coef(d.itype, d.jtype).p;
      return c;
    };
    ad::publish(advice_owner_, std::move(e));
  }

 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    tdem::thornton::Params<double> p;
    double kappa;
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  int history_offset_ = 0;
  int stamp_offset_ = 0;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
