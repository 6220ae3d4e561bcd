// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/walton_braun` -- Walton & Braun's hysteretic linear law
// (src/contact/normal/walton_braun.h) as a LIGGGHTS NormalModel. Binding only; the body is
// HistoryNormalModel (normal_model_tdem_history.h).
//
//   pair_style gran model tdem/walton_braun [tangential ...]
//
// Properties (peratomtypepair): loadingStiffness k_l > 0, unloadingStiffness k_u >= k_l,
// unloadingStiffnessSlope s >= 0 (k_ul = k_u + s F_max), tangentialStiffnessRatio kappa
// (kt = kappa k_l). Per-contact history: xi_max (a scalar, no sign flip), reset when the
// particles separate. No damping, no attraction.
#pragma once

#include <cstdio>

#include "contact/normal/walton_braun.h"
#include "normal_model_tdem_history.h"
#include "tdem_liggghts_ids.h"

namespace tdem {
namespace liggghts {

struct WaltonBraunBinding {
  static constexpr const law::Description& description = walton_braun::description;
  static constexpr const char* model = "tdem/walton_braun";
  static constexpr const char* caller = "model tdem/walton_braun";
  static constexpr double stress_strain_exponent = 1.0;
  static constexpr bool needs_reff = false;
  static constexpr advice::Law advice = advice::Law::walton_braun;
  using Params = walton_braun::Params<double>;

  static void connect(LAMMPS_NS::LAMMPS* lmp, ::PropertyRegistry& registry, const char* caller,
                      int n, PairTable<HistoryCoefficients<Params>>& coef) {
    double **kl = nullptr, **ku = nullptr, **s = nullptr, **kappa = nullptr;
    registry.registerProperty(kPropLoadingStiffness, &create_loading_stiffness);
    registry.registerProperty(kPropUnloadingStiffness, &create_unloading_stiffness);
    registry.registerProperty(kPropUnloadingSlope, &create_unloading_slope);
    registry.registerProperty(kPropStiffnessRatio, &create_stiffness_ratio);
    registry.connect(kPropLoadingStiffness, kl, caller);
    registry.connect(kPropUnloadingStiffness, ku, caller);
    registry.connect(kPropUnloadingSlope, s, caller);
    registry.connect(kPropStiffnessRatio, kappa, caller);
    const double nktv2p = lmp->force->nktv2p;
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        if (!(ku[i][j] >= kl[i][j])) {
          char buf[512];
          std::snprintf(buf, sizeof buf,
                        "%s: fix property/global unloadingStiffness has value %.15g for atom types %d %d; "
                        "allowed: unloadingStiffness >= loadingStiffness (%.15g)",
                        caller, ku[i][j], i, j, kl[i][j]);
          lmp->error->all(FLERR, buf);
        }
        HistoryCoefficients<Params>& pc = coef(i, j);
        pc.p = {kl[i][j] / nktv2p, ku[i][j] / nktv2p, s[i][j]};
        pc.kappa = kappa[i][j];
      }
  }

  static tdem::NormalResult<double> force(const Params& p, const tdem::NormalKinematics<double>& kin, double* hist,
                                          bool update) {
    return walton_braun::force(p, kin, hist, update);
  }
  // kt = kappa k_l: the loading stiffness, also while unloading
  static double tangential_stiffness(const HistoryCoefficients<Params>& pc, const tdem::NormalResult<double>&) {
    return pc.kappa * pc.p.k_load;
  }
  static void advise(advice::Coefficients& c, const Params& p) { c.walton_braun = p; }
};

}  // namespace liggghts
}  // namespace tdem

namespace LIGGGHTS {
namespace ContactModels {
template <>
class NormalModel<TDEM_WALTON_BRAUN> : public TdemHistoryNormalModel<tdem::liggghts::WaltonBraunBinding> {
 public:
  using TdemHistoryNormalModel::TdemHistoryNormalModel;
};
}  // namespace ContactModels
}  // namespace LIGGGHTS
