// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/hertz` -- Hertz spring plus an overlap-dependent damper
// (src/contact/normal/hertz_damped.h) as a LIGGGHTS NormalModel. Adapter only.
//
//   pair_style gran model tdem/hertz [tangential ...] [damping linear|kuwabara_kono|tsuji|general]
//              [limitForce off|on]
//
// F = k~ xi^(3/2) + c xi^Theta xi_dot with k~ = 4/3 Y* sqrt(R*) (Y* = LIGGGHTS's Yeff from
// youngsModulus / poissonsRatio; R* = R_i for a wall).
//   damping tsuji (default): c = alpha sqrt(m* k~), alpha from coefficientRestitution in the
//     convention of limitForce (tdem::hertz::tsuji_alpha_from_restitution), once per type pair.
//   damping linear | kuwabara_kono | general: c = dampingCoefficient (Theta = 0 | 1/2 |
//     dampingExponent).
// Tangential: kt = tangentialStiffnessRatio * dF/dxi (dF/dxi = 2 Y* a = 3/2 k~ sqrt(xi)), gammat = 0.
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/hertz_damped.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_HERTZ> : public NormalModelBase {
 public:
  enum DampingWord { LINEAR = 0, KUWABARA_KONO = 1, TSUJI = 2, GENERAL = 3 };

  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {}

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings& settings) {
    // the damping members of normal hertz (src/contact/normal/hertz_damped.h), in Damping order
    tdem::liggghts::register_enum(lmp, settings, "model tdem/hertz", "damping", damping_word_,
                                  tdem::liggghts::choice_words(tdem::hertz::groups[0]), TSUJI);
    tdem::liggghts::register_on_off(lmp, settings, "model tdem/hertz", "limitForce", limit_force_, false);
  }

  void postSettings(IContactHistorySetup*, ContactModelBase*) {
    damping_ = static_cast<tdem::hertz::Damping>(damping_word_);  // the choice index is the member
    end_ = limit_force_ ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;
  }

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/hertz";
    if (force->cg_active())
      error->all(FLERR, "model tdem/hertz does not support coarse-graining (cg factor != 1)");
    postSettings(nullptr, nullptr);
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    double **yeff = nullptr, **kappa = nullptr, **e = nullptr, **c = nullptr, **theta = nullptr;
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff);
    registry.registerProperty(tdem::liggghts::kPropStiffnessRatio, &tdem::liggghts::create_stiffness_ratio);
    registry.connect("Yeff", yeff, caller);
    registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
    if (damping_ == tdem::hertz::Damping::tsuji) {
      registry.registerProperty(tdem::liggghts::kPropRestitution, &tdem::liggghts::create_restitution);
      registry.connect(tdem::liggghts::kPropRestitution, e, caller);
    } else {
      registry.registerProperty(tdem::liggghts::kPropDampingCoefficient,
                                &tdem::liggghts::create_damping_coefficient);
      registry.connect(tdem::liggghts::kPropDampingCoefficient, c, caller);
      if (damping_ == tdem::hertz::Damping::general) {
        registry.registerProperty(tdem::liggghts::kPropDampingExponent, &tdem::liggghts::create_damping_exponent);
        registry.connect(tdem::liggghts::kPropDampingExponent, theta, caller);
      }
    }
    tdem::liggghts::check_matrix(lmp, yeff, n, "youngsModulus (effective modulus Yeff)", caller, 0);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        PairCoefficients& pc = coef_(i, j);
        pc.k_per_sqrt_r = 4.0 / 3.0 * yeff[i][j] / force->nktv2p;  // k~ / sqrt(R*)
        pc.kappa = kappa[i][j];
        pc.theta = theta ? theta[i][j] : 0.0;
        if (e) {
          try {
            pc.damp = tdem::hertz::tsuji_alpha_from_restitution(e[i][j], end_);
          } catch (const std::exception& ex) {
            char buf[512];
            std::snprintf(buf, sizeof buf,
                          "model tdem/hertz: atom types %d %d: coefficientRestitution %.17g gives no "
                          "Tsuji damping (%s)", i, j, e[i][j], ex.what());
            error->all(FLERR, buf);
          }
        } else {
          pc.damp = c[i][j];
        }
      }
    publish_advice();
  }

  inline double stressStrainExponent() { return 1.5; }

  // the two entry points of evaluate() (tdem_liggghts_apply.h)
  [[gnu::flatten]] void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    tdem::liggghts::intersect(*this, sidata, i_forces, j_forces);
  }
  tdem::NormalResult<double> law(SurfacesIntersectData& sidata) { return tdem::liggghts::law_result(*this, sidata); }
  // The law on the contact data, its result published to sidata (see normal_model_tdem_lsd.h).
  template <bool Result>
  [[gnu::always_inline]] inline void evaluate(SurfacesIntersectData& sidata, tdem::NormalResult<double>* out) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, "model tdem/hertz", sidata.i, sidata.j, sidata.is_wall);
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    const double reff = sidata.is_wall ? sidata.radi : (sidata.radi * sidata.radj / (sidata.radi + sidata.radj));
    const tdem::hertz::Params<double> p{pc.k_per_sqrt_r * std::sqrt(reff), pc.damp, pc.theta};
    // overlap rate = -vn (LIGGGHTS's vn has the opposite sign)
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, reff};
    const tdem::NormalResult<double> r = tdem::hertz::force(damping_, end_, p, kin);
    tdem::liggghts::publish_normal_result(sidata, r.force, r.stiffness, pc.kappa * r.stiffness, r.damping);
    if constexpr (Result) *out = r;
  }
  tdem::ContactEnd contact_end() const { return end_; }
  static constexpr bool linear = false;
  // The exponents of the force's two parts for the grid correction (tdem_liggghts_grid.h), in place
  // of its probe of the law at xi/2 (false with limitForce on: it probes).
  bool power_exponents(const SurfacesIntersectData& d, double& p, double& q) const {
    return tdem::hertz::power_exponents(damping_, coef_(d.itype, d.jtype).theta, end_, p, q);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The settings and coefficients for fix tdem/timestep (tdem_liggghts_advice.h).
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    ad::publish_table(
        advice_owner_, this, ad::Law::hertz, "tdem/hertz", end_,
        std::string("damping ") + tdem::hertz::to_string(damping_) + ", limitForce " + ad::on_off(limit_force_), coef_,
        [](const PairCoefficients& pc, const ad::PairData& d, ad::Coefficients& c) {
          c.hertz = {pc.k_per_sqrt_r * std::sqrt(d.reff), pc.damp, pc.theta};
        },
        damping_);
  }


 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    double k_per_sqrt_r, damp, theta, kappa;
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  int damping_word_ = TSUJI;
  bool limit_force_ = false;
  tdem::hertz::Damping damping_ = tdem::hertz::Damping::tsuji;
  tdem::ContactEnd end_ = tdem::ContactEnd::zero_overlap;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
