// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the LIGGGHTS NormalModel of every tdem normal law that is a unit (src/contact/law_unit.h,
// listed in src/contact/laws.h: walton_braun, thornton, power_law), written once here from the
// unit's description:
//
//   pair_style gran model tdem/<law> [tangential ...]
//
//  - its properties: one `fix property/global NAME peratomtypepair N v11 ..` per parameter, named
//    as the unit's `properties` list says (walton_braun: loadingStiffness unloadingStiffness
//    unloadingStiffnessSlope; power_law: loadingCoefficient loadingExponent unloadingCoefficient
//    unloadingExponentIncrement; thornton: yieldPressure), checked against the parameter's range;
//    a law with materials takes LIGGGHTS's youngsModulus and poissonsRatio (peratomtype, its
//    Yeff = E*); every law takes tangentialStiffnessRatio kappa (peratomtypepair), and passes
//    k_t = kappa * the unit's tangential basis to the tangential model;
//  - the history values, named and ordered as the law's Description lists them (adjacent), and
//    the step stamp that clears them at a new contact (tdem_liggghts_apply.h);
//  - the refusal of coarse-graining, the zero-distance check, the reset on separation;
//  - the per-contact call of the kernel and the publication of its result;
//  - the entry for fix tdem/timestep (tdem_liggghts_advice.h).
// The model of unit U is LIGGGHTS::ContactModels::TdemHistoryNormalModel<U>; the model ids are
// the lines of TDEM_LIGGGHTS_UNITS (tdem_liggghts_ids.h).
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
#include <utility>

#include "contact/laws.h"
#include "global_properties.h"
#include "tdem_liggghts_advice.h"
#include "tdem_liggghts_apply.h"
#include "tdem_liggghts_error.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_ids.h"

namespace tdem {
namespace liggghts {

// The per-type-pair coefficients of a unit law: the kernel's parameters and the ratio
// kappa = k_t / k_n basis that the tangential law receives.
template <class Params>
struct HistoryCoefficients {
  Params p;
  double kappa;
};

// "tdem/walton_braun" and "model tdem/walton_braun" of unit U.
template <class U>
const std::string& unit_model() {
  static const std::string s = std::string("tdem/") + U::description.name;
  return s;
}
template <class U>
const char* unit_caller() {
  static const std::string s = "model " + unit_model<U>();
  return s.c_str();
}

// The property of parameter K of unit U (registry name "tdem_" + its fix property/global name).
template <class U, int K>
MatrixProperty* create_unit_parameter(PropertyRegistry& registry, const char* caller, bool) {
  return create_parameter(registry, U::properties[K], caller, U::description.params[K]);
}

// The properties of unit U -> the per-type-pair coefficients (rows 1..n).
template <class U, int... K>
void connect_unit(LAMMPS_NS::LAMMPS* lmp, ::PropertyRegistry& registry, int n,
                  PairTable<HistoryCoefficients<typename U::Params>>& coef, std::integer_sequence<int, K...>) {
  constexpr const law::Description& d = U::description;
  static_assert(sizeof...(K) == d.count && sizeof(U::properties) / sizeof(U::properties[0]) == d.count,
                "a unit names one property per parameter");
  const char* caller = unit_caller<U>();
  double** yeff = nullptr;
  if (d.materials) {
    registry.registerProperty("Yeff", &::MODEL_PARAMS::createYeff);
    registry.connect("Yeff", yeff, caller);
    check_matrix(lmp, yeff, n, "youngsModulus (effective modulus Yeff)", caller, 0);
  }
  double** m[sizeof...(K) > 0 ? sizeof...(K) : 1] = {};
  ((registry.registerProperty(std::string("tdem_") + U::properties[K], &create_unit_parameter<U, K>),
    registry.connect(std::string("tdem_") + U::properties[K], m[K], caller)),
   ...);
  double** kappa = nullptr;
  registry.registerProperty(kPropStiffnessRatio, &create_stiffness_ratio);
  registry.connect(kPropStiffnessRatio, kappa, caller);
  const double nktv2p = lmp->force->nktv2p;
  const int o = d.materials ? 1 : 0;
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= n; ++j) {
      double v[law::MAX_UNIT_VALUES];
      if (d.materials) v[0] = yeff[i][j] / nktv2p;
      for (int k = 0; k < d.count; ++k) {
        const law::Parameter& p = d.params[k];
        v[o + k] = law::force_units(p) ? m[k][i][j] / nktv2p : m[k][i][j];
        if (p.bound == law::Bound::at_least)
          check_at_least(lmp, caller, U::properties[k], i, j, m[k][i][j], U::properties[p.ref], m[p.ref][i][j]);
      }
      HistoryCoefficients<typename U::Params>& pc = coef(i, j);
      try {
        pc.p = U::params(v);
      } catch (const std::exception& ex) {
        lmp->error->all(FLERR, (std::string(caller) + ": atom types " + std::to_string(i) + " " + std::to_string(j) +
                                ": " + ex.what())
                                   .c_str());
      }
      pc.kappa = kappa[i][j];
    }
}

}  // namespace liggghts
}  // namespace tdem

namespace LIGGGHTS {
namespace ContactModels {

template <class U>
class TdemHistoryNormalModel : public NormalModelBase {
 public:
  using Coefficients = tdem::liggghts::HistoryCoefficients<typename U::Params>;
  static constexpr int slots = U::description.history_size;

  TdemHistoryNormalModel(LAMMPS* lmp, IContactHistorySetup* hsetup,
                     ContactModelBase* c)
      : NormalModelBase(lmp, hsetup, c), advice_owner_(hsetup) {
    history_offset_ = hsetup->add_history_value(U::description.history[0].name, "0");
    for (int s = 1; s < slots; ++s)
      if (hsetup->add_history_value(U::description.history[s].name, "0") != history_offset_ + s)
        error->all(FLERR, (tdem::liggghts::unit_caller<U>() + std::string(": its history values are not adjacent")).c_str());
    stamp_offset_ = hsetup->add_history_value("tdem_step", "0");  // last step evaluated + 1
  }

  ~TdemHistoryNormalModel() { tdem::liggghts::advice::withdraw(advice_owner_, this); }

  void registerSettings(Settings&) {}
  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    if (force->cg_active())
      error->all(FLERR, (tdem::liggghts::unit_caller<U>() + std::string(" does not support coarse-graining (cg factor != 1)")).c_str());
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    coef_.resize(atom->ntypes);
    tdem::liggghts::connect_unit<U>(lmp, registry, n, coef_,
                                    std::make_integer_sequence<int, U::description.count>());
    publish_advice();
  }

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
      tdem::liggghts::zero_distance_of_law(lmp, U::description.name, sidata.i, sidata.j, sidata.is_wall);
    const Coefficients& pc = coef_(sidata.itype, sidata.jtype);
    double reff = 0.0;
    if constexpr (U::needs_reff)
      reff = sidata.is_wall ? sidata.radi : (sidata.radi * sidata.radj / (sidata.radi + sidata.radj));
    double* const hist = &sidata.contact_history[history_offset_];
    const bool store = sidata.computeflag && sidata.shearupdate;
    tdem::liggghts::clear_history_of_new_contact(sidata.contact_history[stamp_offset_], hist, slots,
                                 static_cast<double>(update->ntimestep), store);
    const tdem::NormalKinematics<double> kin{sidata.deltan, -sidata.vn, sidata.meff, reff};
    const tdem::NormalResult<double> r = U::force(pc.p, kin, hist, store);
    tdem::liggghts::publish_normal_result(sidata, r.force, r.stiffness, pc.kappa * U::tangential_basis(pc.p, r, kin), 0.0);
    if constexpr (Result) *out = r;
  }
  tdem::ContactEnd contact_end() const { return U::end; }
  static constexpr bool linear = false;

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

  inline double stressStrainExponent() { return U::stress_strain_exponent; }

 private:
  // The coefficients for fix tdem/timestep (tdem_liggghts_advice.h).
  void publish_advice() {
    namespace advice = tdem::liggghts::advice;
    advice::publish_table(advice_owner_, this, advice::Law::unit, tdem::liggghts::unit_model<U>(), U::end, "", coef_,
                          [](const Coefficients& pc, const advice::PairData&, advice::Coefficients& c) {
                            c.unit.set(pc.p);
                          })
        .unit = tdem::law::index_of<tdem::law::normal_units>(&U::description);
  }

  const void* advice_owner_ = nullptr;  // IContactHistorySetup* of the owner (advice registry key)
  tdem::liggghts::PairTable<Coefficients> coef_;
  int history_offset_ = 0;
  int stamp_offset_ = 0;
};

// The model of each unit under its id (tdem_liggghts_ids.h).
#define TDEM_LIGGGHTS_UNIT_MODEL(constant, id, ns)                                    \
  template <>                                                                         \
  class NormalModel<constant> : public TdemHistoryNormalModel<tdem::ns::Law> {        \
   public:                                                                            \
    using TdemHistoryNormalModel::TdemHistoryNormalModel;                             \
  };
TDEM_LIGGGHTS_UNITS(TDEM_LIGGGHTS_UNIT_MODEL)
#undef TDEM_LIGGGHTS_UNIT_MODEL

}  // namespace ContactModels
}  // namespace LIGGGHTS

// Every unit of src/contact/laws.h has its line in TDEM_LIGGGHTS_UNITS.
#define TDEM_LIGGGHTS_UNIT_COUNT(constant, id, ns) +1
static_assert(0 TDEM_LIGGGHTS_UNITS(TDEM_LIGGGHTS_UNIT_COUNT) == tdem::law::normal_units::size,
              "give every unit of src/contact/laws.h its line in TDEM_LIGGGHTS_UNITS (tdem_liggghts_ids.h)");
#undef TDEM_LIGGGHTS_UNIT_COUNT
