// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/lsd` -- the linear spring-dashpot normal law (src/contact/normal/
// linear_viscoelastic.h) as a LIGGGHTS NormalModel. This file is an adapter only: it reads the
// per-type-pair parameters, turns LIGGGHTS's contact data into tdem::NormalKinematics, calls
// tdem::lsd::force and applies the result the way LIGGGHTS's own normal models do.
//
//   pair_style gran model tdem/lsd [tangential ...] [parameters stiffness|restitution]
//              [limitForce off|on] [absolute_damping off|on] [tangential_damping on|off]
//
// parameters stiffness (default): fix property/global kn, kt, gamman, gammat (or gamman_abs,
//   gammat_abs with absolute_damping on), exactly as model hooke/stiffness.
// parameters restitution: fix property/global coefficientRestitution, contactTime and
//   tangentialStiffnessRatio; k and gamma of a contact are m* times per-type-pair rates
//   derived once per run (tdem::lsd::rates_from_restitution_and_time), gammat = 0.
// parameters material: fix property/global youngsModulus, poissonsRatio,
//   characteristicVelocity, coefficientRestitution and tangentialStiffnessRatio; per contact
//   k = the linear stiffness with Hertz's maximum overlap at the characteristic velocity
//   (tdem::lsd::stiffness_matching_hertz, as model hooke), gamma from e for that k and m*
//   in the convention of limitForce, kt = ratio * k, gammat = gamma if tangential_damping.
// limitForce off: the contact ends at zero overlap (tdem::ContactEnd::zero_overlap);
// limitForce on: the force is clipped at 0 (tdem::ContactEnd::zero_force). In restitution mode
//   the (e, t_c) -> (k, gamma) derivation uses the same convention.
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/linear_viscoelastic.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_LSD> : public NormalModelBase {
 public:
  enum Parameters { STIFFNESS = 0, RESTITUTION = 1, MATERIAL = 2 };

  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {}

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings& settings) {
    tdem::liggghts::register_enum(lmp, settings, "model tdem/lsd", "parameters", parameters_, {"stiffness", "restitution", "material"},
                                  STIFFNESS);
    tdem::liggghts::register_on_off(lmp, settings, "model tdem/lsd", "tangential_damping", tangential_damping_, true);
    tdem::liggghts::register_on_off(lmp, settings, "model tdem/lsd", "absolute_damping", absolute_damping_, false);
    tdem::liggghts::register_on_off(lmp, settings, "model tdem/lsd", "limitForce", limit_force_, false);
  }

  void postSettings(IContactHistorySetup*, ContactModelBase*) {
    if (parameters_ != STIFFNESS && absolute_damping_)
      error->all(FLERR,
                 "model tdem/lsd: 'absolute_damping on' is not allowed with 'parameters "
                 "restitution' or 'parameters material' (allowed with parameters stiffness only)");
  }

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/lsd";
    if (force->cg_active())
      error->all(FLERR, "model tdem/lsd does not support coarse-graining (cg factor != 1)");
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    end_ = limit_force_ ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;

    if (parameters_ == STIFFNESS) {
      double **kn = nullptr, **kt = nullptr, **gn = nullptr, **gt = nullptr;
      registry.registerProperty("k_n", &MODEL_PARAMS::createKn);
      registry.registerProperty("k_t", &MODEL_PARAMS::createKt);
      registry.connect("k_n", kn, caller);
      registry.connect("k_t", kt, caller);
      const char *gn_name = "gamman", *gt_name = "gammat";
      if (absolute_damping_) {
        gn_name = "gamman_abs";
        gt_name = "gammat_abs";
        registry.registerProperty("gamman_abs", &MODEL_PARAMS::createGammanAbs);
        registry.registerProperty("gammat_abs", &MODEL_PARAMS::createGammatAbs);
      } else {
        registry.registerProperty("gamman", &MODEL_PARAMS::createGamman);
        registry.registerProperty("gammat", &MODEL_PARAMS::createGammat);
      }
      registry.connect(gn_name, gn, caller);
      registry.connect(gt_name, gt, caller);
      tdem::liggghts::check_matrix(lmp, kn, n, "kn", caller, 0);
      tdem::liggghts::check_matrix(lmp, kt, n, "kt", caller, 1);
      tdem::liggghts::check_matrix(lmp, gn, n, gn_name, caller, 1);
      tdem::liggghts::check_matrix(lmp, gt, n, gt_name, caller, 1);
      // k is used as given (pressure units converted as model hooke/stiffness does),
      // gamma is per unit effective mass unless absolute_damping is on.
      stiffness_per_mass_ = false;
      damping_per_mass_ = !absolute_damping_;
      for (int i = 1; i <= n; ++i)
        for (int j = 1; j <= n; ++j) {
          PairCoefficients& c = coef_(i, j);
          c.kn = kn[i][j] / force->nktv2p;
          c.kt = kt[i][j] / force->nktv2p;
          c.gamman = gn[i][j];
          c.gammat = tangential_damping_ ? gt[i][j] : 0.0;
        }
    } else if (parameters_ == MATERIAL) {
      double **yeff = nullptr, **e = nullptr, **kappa = nullptr;
      registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff);
      registry.registerProperty("charVel", &MODEL_PARAMS::createCharacteristicVelocity);
      registry.registerProperty(tdem::liggghts::kPropRestitution, &tdem::liggghts::create_restitution);
      registry.registerProperty(tdem::liggghts::kPropStiffnessRatio,
                                &tdem::liggghts::create_stiffness_ratio);
      registry.connect("Yeff", yeff, caller);
      registry.connect("charVel", char_vel_, caller);
      registry.connect(tdem::liggghts::kPropRestitution, e, caller);
      registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
      if (!(char_vel_ > 0.0)) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "model tdem/lsd: characteristicVelocity %.17g must be > 0 (parameters material)",
                      char_vel_);
        error->all(FLERR, buf);
      }
      stiffness_per_mass_ = false;  // k, gamma, kt, gammat are formed per contact below
      damping_per_mass_ = false;
      for (int i = 1; i <= n; ++i)
        for (int j = 1; j <= n; ++j) {
          PairCoefficients& c = coef_(i, j);
          c.kn = yeff[i][j];  // effective Young's modulus; k follows per contact
          c.kt = kappa[i][j];
          // zero overlap: gamma from ln e in the closed form; zero force: from the damping ratio
          c.gamman = end_ == tdem::ContactEnd::zero_overlap
                         ? std::log(e[i][j])
                         : tdem::lsd::damping_ratio_from_restitution(e[i][j], end_);
          c.gammat = tangential_damping_ ? 1.0 : 0.0;
        }
    } else {
      double **e = nullptr, **tc = nullptr, **kappa = nullptr;
      registry.registerProperty(tdem::liggghts::kPropRestitution, &tdem::liggghts::create_restitution);
      registry.registerProperty(tdem::liggghts::kPropContactTime, &tdem::liggghts::create_contact_time);
      registry.registerProperty(tdem::liggghts::kPropStiffnessRatio,
                                &tdem::liggghts::create_stiffness_ratio);
      registry.connect(tdem::liggghts::kPropRestitution, e, caller);
      registry.connect(tdem::liggghts::kPropContactTime, tc, caller);
      registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
      stiffness_per_mass_ = true;
      damping_per_mass_ = true;
      for (int i = 1; i <= n; ++i)
        for (int j = 1; j <= n; ++j) {
          tdem::lsd::MassRates<double> rates{};
          try {
            rates = tdem::lsd::rates_from_restitution_and_time(e[i][j], tc[i][j], end_);
          } catch (const std::exception& ex) {
            char buf[512];
            std::snprintf(buf, sizeof buf,
                          "model tdem/lsd: atom types %d %d: coefficientRestitution %.17g and "
                          "contactTime %.17g give no valid stiffness and damping (%s)",
                          i, j, e[i][j], tc[i][j], ex.what());
            error->all(FLERR, buf);
          }
          PairCoefficients& c = coef_(i, j);
          c.kn = rates.k_per_mass;
          c.kt = kappa[i][j] * rates.k_per_mass;
          c.gamman = rates.gamma_per_mass;
          c.gammat = 0.0;
        }
    }
    publish_advice();
  }

  inline double stressStrainExponent() { return 1.; }

  // the two entry points of evaluate() (tdem_liggghts_apply.h)
  [[gnu::flatten]] void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    tdem::liggghts::intersect(*this, sidata, i_forces, j_forces);
  }
  tdem::NormalResult<double> law(SurfacesIntersectData& sidata) { return tdem::liggghts::law_result(*this, sidata); }

  // The law on the contact data (the part of surfacesIntersect before the force is applied), its
  // result published to sidata for the tangential law and, if Result, written to *out.
  template <bool Result>
  [[gnu::always_inline]] inline void evaluate(SurfacesIntersectData& sidata, tdem::NormalResult<double>* out) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, "model tdem/lsd", sidata.i, sidata.j, sidata.is_wall);
    const double meff = sidata.meff;
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    double kn = pc.kn, kt = pc.kt, gamman = pc.gamman, gammat = pc.gammat;
    if (parameters_ == MATERIAL) {
      const double reff = sidata.is_wall ? sidata.radi : (sidata.radi * sidata.radj / (sidata.radi + sidata.radj));
      const double k = tdem::lsd::stiffness_matching_hertz(pc.kn, reff, meff, char_vel_);
      gamman = end_ == tdem::ContactEnd::zero_overlap
                   ? tdem::lsd::damping_zero_overlap_from_log_restitution(pc.gamman, k, meff)
                   : tdem::lsd::damping_from_ratio(pc.gamman, k, meff);
      gammat = pc.gammat * gamman;
      kn = k / force->nktv2p;  // pressure units -> force/distance, as the stock models
      kt = pc.kt * kn;
    } else if (stiffness_per_mass_) {
      kn = meff * kn;
      kt = meff * kt;
    }
    if (damping_per_mass_) {
      gamman = meff * gamman;
      gammat = meff * gammat;
    }
    // overlap rate = -vn (LIGGGHTS's vn is the approach velocity with the opposite sign);
    // reff is not used by the linear law.
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, meff, 0.0};
    const tdem::lsd::Coefficients<double> co{kn, gamman};
    const tdem::NormalResult<double> r = end_ == tdem::ContactEnd::zero_force
                                             ? tdem::lsd::force<tdem::ContactEnd::zero_force>(co, kin)
                                             : tdem::lsd::force<tdem::ContactEnd::zero_overlap>(co, kin);
    sidata.Fn = r.force;
    sidata.kn = kn;
    sidata.kt = kt;
    sidata.gamman = gamman;
    sidata.gammat = gammat;
    if constexpr (Result) *out = r;
  }
  tdem::ContactEnd contact_end() const { return end_; }
  static constexpr bool linear = true;  // exponents 1 (elastic) and 0 (damping): no probe needed

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The settings and coefficients for fix tdem/timestep (tdem_liggghts_advice.h): k and gamma of a
  // contact formed exactly as in surfacesIntersect.
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    static const char* const words[] = {"stiffness", "restitution", "material"};
    const int mode = parameters_;
    const bool kpm = stiffness_per_mass_, gpm = damping_per_mass_;
    const double vchar = char_vel_, nktv2p = force->nktv2p;
    const tdem::ContactEnd end = end_;
    ad::publish_table(advice_owner_, this, ad::Law::lsd, "tdem/lsd", end_,
                      std::string("parameters ") + words[parameters_] + ", absolute_damping " +
                          ad::on_off(absolute_damping_) + ", limitForce " + ad::on_off(limit_force_),
                      coef_, [=](const PairCoefficients& pc, const ad::PairData& d, ad::Coefficients& c) {
                        double kn = pc.kn, gamman = pc.gamman;
                        if (mode == MATERIAL) {
                          const double k = tdem::lsd::stiffness_matching_hertz(pc.kn, d.reff, d.meff, vchar);
                          gamman = end == tdem::ContactEnd::zero_overlap
                                       ? tdem::lsd::damping_zero_overlap_from_log_restitution(pc.gamman, k, d.meff)
                                       : tdem::lsd::damping_from_ratio(pc.gamman, k, d.meff);
                          kn = k / nktv2p;
                        } else if (kpm) {
                          kn = d.meff * kn;
                        }
                        if (gpm) gamman = d.meff * gamman;
                        c.lsd = {kn, gamman};
                      });
  }

 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    double kn, kt, gamman, gammat;  // per unit m* where the *_per_mass_ flags say so
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  int parameters_ = STIFFNESS;
  bool tangential_damping_ = true;
  bool absolute_damping_ = false;
  bool limit_force_ = false;
  bool stiffness_per_mass_ = false;
  bool damping_per_mass_ = true;
  tdem::ContactEnd end_ = tdem::ContactEnd::zero_overlap;
  double char_vel_ = 0.0;  // characteristicVelocity (parameters material)
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
