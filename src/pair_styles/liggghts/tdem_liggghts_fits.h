// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: reading the impact-velocity fits of the extended laws (src/contact/normal/velocity_fits.h)
// from LIGGGHTS properties, shared by `model tdem/extended_linear` and `model tdem/extended_hertz`.
//
//   restitutionFit constant|rational|power   properties restitutionFitC0 [C1 [C2]] (peratomtypepair)
//   contactTimeFit constant|power            properties contactTimeFitC0 [C1]      (peratomtypepair)
//   impactVelocityMin, impactVelocityMax     optional scalars (defaults 1e-3, 1e3 m/s)
//
// Only as many coefficients are read as the form needs. Their ranges depend on the form and are
// checked by the core (tdem::fits::validate_*); the messages are rewritten to name the property.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/normal/extended.h"
#include "contact/normal/velocity_fits.h"
#include "error.h"
#include "lammps.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace tdem {
namespace liggghts {

// Words of the `restitutionFit` / `contactTimeFit` keywords, in the order of their indices: the
// forms of the laws' e_fit and tc_fit groups (src/contact/normal/extended.h), the words of
// pair_coeff ... e_fit FORM in LAMMPS.
inline const std::vector<std::string>& restitution_fit_words() {
  static const std::vector<std::string> w = choice_words(extended::e_fit_group);
  return w;
}
inline const std::vector<std::string>& contact_time_fit_words() {
  static const std::vector<std::string> w = choice_words(extended::tc_fit_group);
  return w;
}
inline fits::Form restitution_form(int index) {
  fits::Form f = fits::Form::constant;
  fits::parse(restitution_fit_words()[index], f);
  return f;
}
inline fits::Form contact_time_form(int index) {
  fits::Form f = fits::Form::constant;
  fits::parse(contact_time_fit_words()[index], f);
  return f;
}

// Per-type-pair coefficient matrices of one fit, connected through the registry.
struct FitMatrices {
  double** c[3] = {nullptr, nullptr, nullptr};
  int n = 0;
};

// The coefficient properties of a fit of e(v0) (which 'e') or t_c(v0) (which 't').
inline FitMatrices connect_fit(PropertyRegistry& registry, fits::Form form, char which, const char* caller) {
  FitMatrices m;
  m.n = fits::coefficient_count(form, which);
  for (int k = 0; k < m.n; ++k) {
    const char* name = which == 'e' ? kPropRestitutionFit[k] : kPropContactTimeFit[k];
    registry.registerProperty(name, which == 'e' ? create_restitution_fit[k] : create_contact_time_fit[k]);
    registry.connect(name, m.c[k], caller);
  }
  return m;
}
inline FitMatrices connect_restitution_fit(PropertyRegistry& registry, fits::Form form, const char* caller) {
  return connect_fit(registry, form, 'e', caller);
}
inline FitMatrices connect_contact_time_fit(PropertyRegistry& registry, fits::Form form, const char* caller) {
  return connect_fit(registry, form, 't', caller);
}

inline fits::Fit fit_of(fits::Form form, const FitMatrices& m, int i, int j) {
  fits::Fit f;
  f.form = form;
  for (int k = 0; k < m.n; ++k) f.c[k] = m.c[k][i][j];
  return f;
}

// impactVelocityMin / impactVelocityMax if given (fix property/global NAME scalar V), else the
// defaults of fits::Range. e_min stays at its default (1e-3).
inline fits::Range connect_range(LAMMPS_NS::LAMMPS* lmp, PropertyRegistry& registry, const char* caller) {
  fits::Range r;
  if (has_scalar_property(lmp, "impactVelocityMin", caller)) {
    registry.registerProperty(kPropImpactVelocityMin, &create_impact_velocity_min);
    registry.connect(kPropImpactVelocityMin, r.v_min, caller);
  }
  if (has_scalar_property(lmp, "impactVelocityMax", caller)) {
    registry.registerProperty(kPropImpactVelocityMax, &create_impact_velocity_max);
    registry.connect(kPropImpactVelocityMax, r.v_max, caller);
  }
  return r;
}

namespace detail {
inline void rename(std::string& s, const char* from, const char* to) {
  const auto pos = s.find(from);
  if (pos != std::string::npos) s.replace(pos, std::string(from).size(), to);
}
}  // namespace detail

// The core's quantity names -> the LIGGGHTS property that holds them.
inline std::string fit_message_with_property_names(std::string s) {
  using detail::rename;
  rename(s, "restitution fit chi1", "restitutionFitC0 (chi1 of restitutionFit rational)");
  rename(s, "restitution fit v00", "restitutionFitC1 (v00 of restitutionFit rational)");
  rename(s, "restitution fit chi2", "restitutionFitC2 (chi2 of restitutionFit rational)");
  rename(s, "restitution fit v_c", "restitutionFitC0 (v_c of restitutionFit power)");
  rename(s, "restitution fit exponent p", "restitutionFitC1 (p of restitutionFit power)");
  rename(s, "coefficient of restitution e", "restitutionFitC0 (e of restitutionFit constant)");
  rename(s, "contact time t_c", "contactTimeFitC0 (t_c of contactTimeFit constant)");
  rename(s, "contact-time fit chi3", "contactTimeFitC0 (chi3 of contactTimeFit power)");
  rename(s, "contact-time fit chi4", "contactTimeFitC1 (chi4 of contactTimeFit power)");
  rename(s, "smallest impact velocity v_min", "impactVelocityMin");
  rename(s, "largest impact velocity v_max", "impactVelocityMax");
  rename(s, "[v_min, inf)", "[impactVelocityMin, inf)");
  return s;
}

// error->all with "<caller>: atom types i j: <core message with property names>".
[[noreturn]] inline void fail_fit(LAMMPS_NS::LAMMPS* lmp, const char* caller, int i, int j, const std::exception& ex) {
  const std::string msg = std::string(caller) + ": atom types " + std::to_string(i) + " " + std::to_string(j) +
                          ": " + fit_message_with_property_names(ex.what());
  lmp->error->all(FLERR, msg.c_str());
  throw std::runtime_error(msg);  // not reached: error->all exits
}

// Scalar range check (the same for every type pair): error->all naming the property.
inline void check_range(LAMMPS_NS::LAMMPS* lmp, const fits::Range& r, const char* caller) {
  try {
    fits::validate_range(r);
  } catch (const std::exception& ex) {
    const std::string msg = std::string(caller) + ": " + fit_message_with_property_names(ex.what()) +
                            " (impactVelocityMin = " + checks::number(r.v_min) + ", impactVelocityMax = " +
                            checks::number(r.v_max) + ")";
    lmp->error->all(FLERR, msg.c_str());
  }
}

}  // namespace liggghts
}  // namespace tdem
