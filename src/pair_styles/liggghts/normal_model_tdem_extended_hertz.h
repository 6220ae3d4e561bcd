// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: `model tdem/extended_hertz` -- the Hertz spring with Tsuji damping whose alpha follows a
// measured e(v0) (src/contact/normal/extended.h, physics_reference.md 2.6) as a LIGGGHTS
// NormalModel. Adapter only.
//
//   pair_style gran model tdem/extended_hertz [tangential ...] [restitutionFit constant|rational|power]
//              [limitForce off|on]                                     (defaults rational, off)
//
// F = k~ xi^(3/2) + alpha(v0) sqrt(m* k~) xi^(1/4) xi', k~ = 4/3 Y* sqrt(R*) (Y* = LIGGGHTS's Yeff
// from youngsModulus / poissonsRatio, peratomtype; R* = R_i for a wall), alpha(v0) the Tsuji
// damping that gives e(v0) in the convention of limitForce. Properties: restitutionFitC0 [C1 [C2]]
// (peratomtypepair, tdem_liggghts_fits.h), tangentialStiffnessRatio kappa (kt = kappa dF/dxi),
// optional scalars impactVelocityMin, impactVelocityMax. Per-contact history: v0, alpha (scalars,
// no sign flip), reset when the particles separate.
#pragma once

#include <cmath>
#include <stdexcept>

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "atom.h"
#include "error.h"
#include "update.h"

#include "tdem_liggghts_apply.h"
#include "contact/normal/extended.h"
#include "tdem_liggghts_fits.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_ids.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace LIGGGHTS {
namespace ContactModels {

template <>
class NormalModel<TDEM_EXTENDED_HERTZ> : public NormalModelBase {
 public:
  NormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {
    history_offset_ = hsetup->add_history_value("ext_v0", "0");
    const int a = hsetup->add_history_value("ext_alpha", "0");
    if (a != history_offset_ + 1)
      error->all(FLERR, "model tdem/extended_hertz: history values v0, alpha are not adjacent");
    stamp_offset_ = hsetup->add_history_value("tdem_step", "0");  // last step evaluated + 1
  }

  ~NormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings& settings) {
    tdem::liggghts::register_enum(lmp, settings, "model tdem/extended_hertz", "restitutionFit", e_form_,
                                  tdem::liggghts::restitution_fit_words(), 1);
    tdem::liggghts::register_on_off(lmp, settings, "model tdem/extended_hertz", "limitForce", limit_force_, false);
  }
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    static const char* caller = "model tdem/extended_hertz";
    if (force->cg_active())
      error->all(FLERR, "model tdem/extended_hertz does not support coarse-graining (cg factor != 1)");
    end_ = limit_force_ ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;
    const tdem::fits::Form ef = tdem::liggghts::restitution_form(e_form_);
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    double **yeff = nullptr, **kappa = nullptr;
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff);
    registry.connect("Yeff", yeff, caller);
    const tdem::liggghts::FitMatrices em = tdem::liggghts::connect_restitution_fit(registry, ef, caller);
    const tdem::fits::Range range = tdem::liggghts::connect_range(lmp, registry, caller);
    tdem::liggghts::check_range(lmp, range, caller);
    registry.registerProperty(tdem::liggghts::kPropStiffnessRatio, &tdem::liggghts::create_stiffness_ratio);
    registry.connect(tdem::liggghts::kPropStiffnessRatio, kappa, caller);
    tdem::liggghts::check_matrix(lmp, yeff, n, "youngsModulus (effective modulus Yeff)", caller, 0);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j) {
        PairCoefficients& pc = coef_(i, j);
        pc.k_per_sqrt_r = 4.0 / 3.0 * yeff[i][j] / force->nktv2p;  // k~ / sqrt(R*)
        pc.p.k = pc.k_per_sqrt_r;  // the R* of a contact is applied per contact
        pc.p.e_fit = tdem::liggghts::fit_of(ef, em, i, j);
        pc.p.range = range;
        pc.kappa = kappa[i][j];
        try {
          tdem::extended::validate(pc.p);
        } catch (const std::exception& ex) {
          tdem::liggghts::fail_fit(lmp, caller, i, j, ex);
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
      tdem::liggghts::zero_distance(lmp, "model tdem/extended_hertz", sidata.i, sidata.j, sidata.is_wall);
    const PairCoefficients& pc = coef_(sidata.itype, sidata.jtype);
    const double reff = sidata.is_wall ? sidata.radi : (sidata.radi * sidata.radj / (sidata.radi + sidata.radj));
    tdem::extended::HertzParams p = pc.p;
    p.k = pc.k_per_sqrt_r * std::sqrt(reff);
    double* const hist = &sidata.contact_history[history_offset_];
    tdem::liggghts::clear_history_of_new_contact(sidata.contact_history[stamp_offset_], hist, 2,
                                                 static_cast<double>(update->ntimestep),
                                                 sidata.computeflag && sidata.shearupdate);
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, reff};
    const bool update = sidata.computeflag && sidata.shearupdate;
    const tdem::NormalResult<double> r =
        end_ == tdem::ContactEnd::zero_force
            ? tdem::extended::hertz_force<tdem::ContactEnd::zero_force>(p, kin, hist, update)
            : tdem::extended::hertz_force<tdem::ContactEnd::zero_overlap>(p, kin, hist, update);
    tdem::liggghts::publish_normal_result(sidata, r.force, r.stiffness, pc.kappa * r.stiffness, r.damping);
    if constexpr (Result) *out = r;
  }
  tdem::ContactEnd contact_end() const { return end_; }
  static constexpr bool linear = false;

  void surfacesClose(SurfacesCloseData& scdata, ForceData&, ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (scdata.contact_history) {  // contact over: the next touch takes a new alpha
      scdata.contact_history[history_offset_] = 0.0;
      scdata.contact_history[history_offset_ + 1] = 0.0;
    }
  }
  void beginPass(SurfacesIntersectData&, ForceData&, ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&, ForceData&) {}

  // The settings and coefficients for fix tdem/timestep (tdem_liggghts_advice.h): k~ formed with
  // the pair's R* as in surfacesIntersect.
  void publish_advice() {
    namespace ad = tdem::liggghts::advice;
    ad::publish_table(advice_owner_, this, ad::Law::extended_hertz, "tdem/extended_hertz", end_,
                      "restitutionFit " + tdem::liggghts::restitution_fit_words()[e_form_] + ", limitForce " +
                          ad::on_off(limit_force_),
                      coef_, [](const PairCoefficients& pc, const ad::PairData& d, ad::Coefficients& c) {
                        c.extended_hertz = pc.p;
                        c.extended_hertz.k = pc.k_per_sqrt_r * std::sqrt(d.reff);
                      });
  }


 private:
  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  struct PairCoefficients {
    tdem::extended::HertzParams p;  // p.k holds k~ / sqrt(R*)
    double k_per_sqrt_r, kappa;
  };
  tdem::liggghts::PairTable<PairCoefficients> coef_;
  int history_offset_ = 0;
  int stamp_offset_ = 0;
  int e_form_ = 1;  // rational
  bool limit_force_ = false;
  tdem::ContactEnd end_ = tdem::ContactEnd::zero_overlap;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
