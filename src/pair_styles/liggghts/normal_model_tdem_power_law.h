// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/power_law` -- power-law loading/unloading hysteresis
// (src/contact/normal/power_law_hysteresis.h) as a LIGGGHTS NormalModel. Binding only; the body
// is HistoryNormalModel (normal_model_tdem_history.h).
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
#include <exception>

#include "contact/normal/power_law_hysteresis.h"
#include "normal_model_tdem_history.h"
#include "tdem_liggghts_ids.h"

namespace tdem {
namespace liggghts {

struct PowerLawBinding {
  static constexpr const law::Description& description = power_law::description;
  static constexpr const char* model = "tdem/power_law";
  static constexpr const char* caller = "model tdem/power_law";
  static constexpr double stress_strain_exponent = 1.0;
  static constexpr bool needs_reff = false;
  static constexpr advice::Law advice = advice::Law::power_law;
  using Params = power_law::Params<double>;

  static void connect(LAMMPS_NS::LAMMPS* lmp, ::PropertyRegistry& registry, const char* caller,
                      int n, PairTable<HistoryCoefficients<Params>>& coef) {
    double **al = nullptr, **p = nullptr, **aul = nullptr, **q = nullptr, **kappa = nullptr;
    registry.registerProperty(kPropLoadingCoefficient, &create_loading_coefficient);
    registry.registerProperty(kPropLoadingExponent, &create_loading_exponent);
    registry.registerProperty(kPropUnloadingCoefficient, &create_unloading_coefficient);
    registry.registerProperty(kPropUnloadingExponentIncrement, &create_unloading_exponent_increment);
    registry.registerProperty(kPropStiffnessRatio, &create_stiffness_ratio);
    registry.connect(kPropLoadingCoefficient, al, caller);
    registry.connect(kPropLoadingExponent, p, caller);
    registry.connect(kPropUnloadingCoefficient, aul, caller);
    registry.connect(kPropUnloadingExponentIncrement, q, caller);
    registry.connect(kPropStiffnessRatio, kappa, caller);
    const double nktv2p = lmp->force->nktv2p;
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        HistoryCoefficients<Params>& pc = coef(i, j);
        // coefficients in force units as model hooke/stiffness converts kn (1 in SI)
        pc.p = {al[i][j] / nktv2p, p[i][j], aul[i][j] / nktv2p, q[i][j]};
        pc.kappa = kappa[i][j];
        try {
          power_law::validate(pc.p);
        } catch (const std::exception& ex) {
          char buf[512];
          std::snprintf(buf, sizeof buf, "%s: atom types %d %d: %s", caller, i, j, ex.what());
          lmp->error->all(FLERR, buf);
        }
      }
  }

  static tdem::NormalResult<double> force(const Params& p, const tdem::NormalKinematics<double>& kin, double* hist,
                                          bool update) {
    return power_law::force(p, kin, hist, update);
  }
  // kt = kappa dF/dxi of the branch in use
  static double tangential_stiffness(const HistoryCoefficients<Params>& pc, const tdem::NormalResult<double>& r) {
    return pc.kappa * r.stiffness;
  }
  static void advise(advice::Coefficients& c, const Params& p) { c.power_law = p; }
};

}  // namespace liggghts
}  // namespace tdem

namespace LIGGGHTS {
namespace ContactModels {
template <>
class NormalModel<TDEM_POWER_LAW> : public TdemHistoryNormalModel<tdem::liggghts::PowerLawBinding> {
 public:
  using TdemHistoryNormalModel::TdemHistoryNormalModel;
};
}  // namespace ContactModels
}  // namespace LIGGGHTS
