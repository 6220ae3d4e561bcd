// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/continuous_potential` -- Langston's steep repulsive potential
// (src/contact/normal/continuous_potential.h) as a LIGGGHTS NormalModel. Adapter only.
//
//   pair_style gran model tdem/continuous_potential [tangential ...] [limitForce off|on]
//
// F = n eps d^n / X^(n+1) + gamma xi_dot for overlapping pairs, with X the centre distance
// (distance of the centre from the wall), d = R_i + R_j (R_i for a wall), so the potential acts
// from geometric touch on (cut-off X_cut = d: LIGGGHTS calls a normal model only for touching
// pairs). Properties (peratomtypepair): potentialEnergy eps > 0 [J], potentialExponent n > 0,
// dampingCoefficient gamma >= 0 [kg/s], tangentialStiffnessRatio kappa (kt = kappa dF/dxi).
#pragma once

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/continuous_potential.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_CONTINUOUS_POTENTIAL> : public NormalModelBase {
 public:
  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {}

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings& settings) {
    tdem::liggghts::register_on_off(lmp, settings, "model tdem/continuous_potential", "limitForce", limit_force_, false);
  }
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/continuous_potential";
    if (force->cg_active())
      error->all(FLERR, "model tdem/continuous_potential does not support coarse-graining (cg factor != 1)");
    end_ = limit_force_ ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    double **eps = nullptr, **expo = nullptr, **gamma = nullptr, **kappa = nullptr;
    registry.registerProperty(tdem::liggghts::kPropPotentialEnergy, &tdem::liggghts::create_potential_energy);
    registry.registerProperty(tdem::liggghts::kPropPotentialExponent, &tdem::liggghts::create_potential_exponent);
    registry.registerProperty(tdem::liggghts::kPropDampingCoefficient, &tdem::liggghts::create_damping_coefficient);
    registry.registerProperty(tdem::liggghts::kPropStiffnessRatio, &tdem::liggghts::create_stiffness_ratio);
    registry.connect(tdem::liggghts::kPropPotentialEnergy, eps, caller);
    registry.connect(tdem::liggghts::kPropPotentialExponent, expo, caller);
    registry.connect(tdem::liggghts::kPropDampingCoefficient, gamma, caller);
    registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        PairCoefficients& pc = coef_(i, j);
        pc.eps = eps[i][j] / force->nktv2p;
        pc.n = expo[i][j];
        pc.gamma = gamma[i][j];
        pc.kappa = kappa[i][j];
      }
    publish_advice();
  }

  inline double stressStrainExponent() { return 1.; }

  inline void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, "model tdem/continuous_potential", sidata.i, sidata.j, sidata.is_wall);
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    const double d = sidata.is_wall ? sidata.radi : sidata.radi + sidata.radj;
    const tdem::continuous_potential::Params<double> p{pc.eps, d, pc.n, d, pc.gamma};
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, 0.0};
    const tdem::NormalResult<double> r = tdem::continuous_potential::force(end_, p, kin);
    tdem::liggghts::publish_normal_result(sidata, r.force, r.stiffness, pc.kappa * r.stiffness, r.damping);
    tdem::liggghts::apply_normal_force(sidata, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The settings and coefficients for fix tdem/timestep (tdem_liggghts_advice.h): d = R_i + R_j
  // (R_i for a wall) as in surfacesIntersect.
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    ad::publish_table(advice_owner_, this, ad::Law::continuous_potential, "tdem/continuous_potential", end_,
                      std::string("limitForce ") + ad::on_off(limit_force_), coef_,
                      [](const PairCoefficients& pc, const ad::PairData& d, ad::Coefficients& c) {
                        c.potential = {pc.eps, d.distance, pc.n, d.distance, pc.gamma};
                      });
  }


 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    double eps, n, gamma, kappa;
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  bool limit_force_ = false;
  tdem::ContactEnd end_ = tdem::ContactEnd::zero_overlap;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
