// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the laws that can be fitted, each as (fitted parameters, single-collision solution,
// closed form where one exists, coefficients, input lines for LIGGGHTS and LAMMPS).
//
// The prediction of a law at an impact velocity is the single-collision solution of
// src/collision/head_on.h (RK4 with event location). Closed forms (where the kernels provide
// them) are only a speed-up for the minimisation; the driver checks them against the
// integration at the optimum and reports the largest difference.
//
// Fitted parameters are "internal" coordinates chosen so that the minimiser sees a well-scaled
// problem (e.g. the power law's a_ul through the restitution at the reference velocity); the
// law coefficients are derived from them in coefficients().
//
// The laws: fit_lsd_hertz.h, fit_hysteretic.h, fit_extended.h (on fit_law.h); this file is their list,
// followed by every unit of src/contact/laws.h that declares fit_guess (fit_unit.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fit_extended.h"
#include "fit_hysteretic.h"
#include "fit_law.h"
#include "fit_lsd_hertz.h"
#include "fit_unit.h"

namespace tdem {
namespace fitting {

inline const std::vector<std::string>& law_names() {
  static const std::vector<std::string> n = {"lsd",
                                             "hertz_linear",
                                             "hertz_kuwabara_kono",
                                             "hertz_tsuji",
                                             "hertz_general",
                                             "walton_braun_constant",
                                             "walton_braun_force_dependent",
                                             "thornton",
                                             "power_law",
                                             "extended_linear",
                                             "extended_hertz"};
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v = n;
    law::for_each<law::normal_units>([&](auto tag) {
      using U = typename decltype(tag)::type;
      if constexpr (fitted_as_unit<U>) v.push_back(U::description.name);
    });
    return v;
  }();
  return all;
}

// The units of law_names() (fit_unit.h): "  NAME   unit: VALUES fitted" lines of the --help text.
inline std::string unit_help() {
  std::string out;
  law::for_each<law::normal_units>([&](auto tag) {
    using U = typename decltype(tag)::type;
    if constexpr (fitted_as_unit<U>) {
      std::string name = U::description.name;
      name.resize(std::max<std::size_t>(name.size() + 1, 30), ' ');
      std::string what = "unit (src/contact/laws.h)";
      what.resize(40, ' ');
      out += "  " + name + what + "(" + law::syntax(U::description) + ")\n";
    }
  });
  return out;
}

inline std::unique_ptr<FitLaw> make_law(const std::string& name, const Context& c) {
  if (name == "lsd") return std::make_unique<LsdFit>(c);
  if (name == "hertz_linear") return std::make_unique<HertzFit>(c, hertz::Damping::linear);
  if (name == "hertz_kuwabara_kono") return std::make_unique<HertzFit>(c, hertz::Damping::kuwabara_kono);
  if (name == "hertz_tsuji") return std::make_unique<HertzFit>(c, hertz::Damping::tsuji);
  if (name == "hertz_general") return std::make_unique<HertzFit>(c, hertz::Damping::general);
  if (name == "walton_braun_constant") return std::make_unique<WaltonBraunFit>(c, false);
  if (name == "walton_braun_force_dependent") return std::make_unique<WaltonBraunFit>(c, true);
  if (name == "thornton") return std::make_unique<ThorntonFit>(c);
  if (name == "power_law") return std::make_unique<PowerLawFit>(c);
  if (name == "extended_linear") return std::make_unique<ExtendedLinearFit>(c);
  if (name == "extended_hertz") return std::make_unique<ExtendedHertzFit>(c);
  std::unique_ptr<FitLaw> unit;
  law::visit<law::normal_units>(law::index_of<law::normal_units>(name.c_str()), [&](auto tag) {
    using U = typename decltype(tag)::type;
    if constexpr (fitted_as_unit<U>) unit = std::make_unique<UnitFit<U>>(c);
  });
  return unit;
}

}  // namespace fitting
}  // namespace tdem
