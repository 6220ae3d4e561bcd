// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the body of a LIGGGHTS NormalModel for a tdem normal law whose state is a set of history
// slots and that has no damping (walton_braun, thornton, power_law). Written once here:
//  - the history values, named and ordered as the law's Description lists them (adjacent), and
//    the step stamp that clears them at a new contact (tdem_liggghts_apply.h);
//  - the refusal of coarse-graining, the zero-distance check, the reset on separation;
//  - the per-contact call of the kernel and the publication of its result;
//  - the entry for fix tdem/timestep (tdem_liggghts_advice.h).
// The model is LIGGGHTS::ContactModels::TdemHistoryNormalModel<B>. A law gives a binding B (in
// its normal_model_tdem_<law>.h) with:
//   static constexpr const tdem::law::Description& description;   // the law's file
//   static constexpr const char* model;                             // "tdem/walton_braun"
//   static constexpr const char* caller;                            // "model tdem/walton_braun"
//   static constexpr double stress_strain_exponent;                 // LIGGGHTS's F ~ xi^x (1, 1.5)
//   using Params;                                                   // the kernel's parameters
//   static constexpr tdem::liggghts::advice::Law advice;            // its advice kind
//   static constexpr bool needs_reff;                               // kernel reads R*
//   static void connect(LAMMPS*, PropertyRegistry&, const char* caller, int n,
//                       PairTable<Coefficients<Params>>&);          // properties -> table
//   static NormalResult<double> force(const Params&, const NormalKinematics<double>&, double* hist,
//                                     bool update);
//   static double tangential_stiffness(const Coefficients<Params>&, const NormalResult<double>&);
//   static void advise(advice::Coefficients&, const Params&);
#pragma once

#include "contact_interface.h"
#include "contact_models.h"
#include "normal_model_base.h"
#include "property_registry.h"
#include "settings.h"
#include "force.h"
#include "atom.h"
#include "error.h"
#include "update.h"

#include <string>

#include "contact/law_parameters.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_apply.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_properties.h"

namespace tdem {
namespace liggghts {

// The per-type-pair coefficients of a history law: the kernel's parameters and the ratio
// kappa = k_t / k_n that the tangential law receives.
template <class Params>
struct HistoryCoefficients {
  Params p;
  double kappa;
};

}  // namespace liggghts
}  // namespace tdem

namespace LIGGGHTS {
namespace ContactModels {

template <class B>
class TdemHistoryNormalModel : public NormalModelBase {
 public:
  using Coefficients = tdem::liggghts::HistoryCoefficients<typename B::Params>;
  static constexpr int slots = B::description.history_size;

  TdemHistoryNormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup,
                     ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {
    history_offset_ = hsetup->add_history_value(B::description.history[0].name, "0");
    for (int s = 1; s < slots; ++s)
      if (hsetup->add_history_value(B::description.history[s].name, "0") != history_offset_ + s)
        error->all(FLERR, (std::string("model ") + B::model + ": its history values are not adjacent").c_str());
    stamp_offset_ = hsetup->add_history_value("tdem_step", "0");  // last step evaluated + 1
  }

  ~TdemHistoryNormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings&) {}
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    if (force->cg_active())
      error->all(FLERR, (std::string(B::caller) + " does not support coarse-graining (cg factor != 1)").c_str());
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    B::connect(lmp, registry, B::caller, n, coef_);
    publish_advice();
  }

  inline void surfacesIntersect(SurfacesIntersectData& sidata,
                                ForceData& i_forces,
                                ForceData& j_forces) {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (__builtin_expect(!(sidata.r > 0.0), 0))  // coincident centres: no normal
      tdem::liggghts::zero_distance(lmp, B::caller, sidata.i, sidata.j, sidata.is_wall);
    const Coefficients& pc = coef_(sidata.itype, sidata.jtype);
    double reff = 0.0;
    if constexpr (B::needs_reff)
      reff = sidata.is_wall ? sidata.radi : (sidata.radi * sidata.radj / (sidata.radi + sidata.radj));
    double* const hist = &sidata.contact_history[history_offset_];
    const bool store = sidata.computeflag && sidata.shearupdate;
    tdem::liggghts::clear_history_of_new_contact(sidata.contact_history[stamp_offset_], hist, slots,
                                 static_cast<double>(update->ntimestep), store);
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, reff};
    const tdem::NormalResult<double> r = B::force(pc.p, kin, hist, store);
    tdem::liggghts::apply_normal_result(sidata, r.force, r.stiffness, B::tangential_stiffness(pc, r), 0.0, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&,
                     ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (scdata.contact_history)  // contact over
      for (int s = 0; s < slots; ++s) scdata.contact_history[history_offset_ + s] = 0.0;
  }
  void beginPass(SurfacesIntersectData&, ForceData&,
                 ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&,
               ForceData&) {}

  inline double stressStrainExponent() { return B::stress_strain_exponent; }

 private:
  // The coefficients for fix tdem/timestep (tdem_liggghts_advice.h).
  void publish_advice() {
    namespace advice = tdem::liggghts::advice;
    advice::Entry e;
    e.model = this;
    e.law = B::advice;
    e.name = B::model;
    e.end = tdem::ContactEnd::zero_force;
    const auto coef = coef_;
    e.coefficients = [coef](const advice::PairData& d) {
      advice::Coefficients c;
      B::advise(c, coef(d.itype, d.jtype).p);
      return c;
    };
    advice::publish(advice_owner_, std::move(e));
  }

  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  tdem::liggghts::PairTable<Coefficients> coef_;
  int history_offset_ = 0;
  int stamp_offset_ = 0;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
