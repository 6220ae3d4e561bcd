// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/thornton` -- Thornton's elastic-perfectly-plastic law
// (src/contact/normal/thornton.h) as a LIGGGHTS NormalModel. Binding only; the body is
// HistoryNormalModel (normal_model_tdem_history.h).
//
//   pair_style gran model tdem/thornton [tangential ...]
//
// Properties: youngsModulus, poissonsRatio (peratomtype; LIGGGHTS's Yeff is E*), yieldPressure
// p_y > 0 and tangentialStiffnessRatio kappa (peratomtypepair); kt = kappa dF/dxi.
// Per-contact history: xi_max, f_max (scalars, no sign flip), reset when the particles separate.
#pragma once

#include "contact/normal/thornton.h"
#include "global_properties.h"
#include "normal_model_tdem_history.h"
#include "tdem_liggghts_ids.h"

namespace tdem {
namespace liggghts {

struct ThorntonBinding {
  static constexpr const law::Description& description = thornton::description;
  static constexpr const char* model = "tdem/thornton";
  static constexpr const char* caller = "model tdem/thornton";
  static constexpr double stress_strain_exponent = 1.5;
  static constexpr bool needs_reff = true;
  static constexpr advice::Law advice = advice::Law::thornton;
  using Params = thornton::Params<double>;

  static void connect(LAMMPS_NS::LAMMPS* lmp, ::PropertyRegistry& registry, const char* caller,
                      int n, PairTable<HistoryCoefficients<Params>>& coef) {
    double **yeff = nullptr, **py = nullptr, **kappa = nullptr;
    registry.registerProperty("Yeff", &::MODEL_PARAMS::createYeff);
    registry.registerProperty(kPropYieldPressure, &create_yield_pressure);
    registry.registerProperty(kPropStiffnessRatio, &create_stiffness_ratio);
    registry.connect("Yeff", yeff, caller);
    registry.connect(kPropYieldPressure, py, caller);
    registry.connect(kPropStiffnessRatio, kappa, caller);
    check_matrix(lmp, yeff, n, "youngsModulus (effective modulus Yeff)", caller, 0);
    const double nktv2p = lmp->force->nktv2p;
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        HistoryCoefficients<Params>& pc = coef(i, j);
        pc.p = {yeff[i][j] / nktv2p, py[i][j] / nktv2p};
        pc.kappa = kappa[i][j];
      }
  }

  static tdem::NormalResult<double> force(const Params& p, const tdem::NormalKinematics<double>& kin, double* hist,
                                          bool update) {
    return thornton::force(p, kin, hist, update);
  }
  // kt = kappa dF/dxi of the branch in use
  static double tangential_stiffness(const HistoryCoefficients<Params>& pc, const tdem::NormalResult<double>& r) {
    return pc.kappa * r.stiffness;
  }
  static void advise(advice::Coefficients& c, const Params& p) { c.thornton = p; }
};

}  // namespace liggghts
}  // namespace tdem

namespace LIGGGHTS {
namespace ContactModels {
template <>
class NormalModel<TDEM_THORNTON> : public TdemHistoryNormalModel<tdem::liggghts::ThorntonBinding> {
 public:
  using TdemHistoryNormalModel::TdemHistoryNormalModel;
};
}  // namespace ContactModels
}  // namespace LIGGGHTS
