// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: usual physical ranges of law parameters, shared by both hosts' adapters.
//
// A value outside them is allowed (the law is defined there) but is far more often a units or
// argument-order mistake than a material. The adapters print the returned text as a host warning;
// an empty text means the value is usual. The impossible values (e <= 0, mu < 0, ...) are errors
// and are checked where the laws read their parameters, not here.
#pragma once

#include <string>

#include "input_checks.h"

namespace tdem {
namespace usual {

using checks::number;

inline std::string friction(double mu) {
  if (mu > 2.0)
    return "friction coefficient MU = " + number(mu) +
           " is unusually large (granular materials: 0 .. 1.5; above 2 a contact practically never slides)";
  return {};
}

inline std::string stiffness_ratio(double kappa) {
  if (kappa > 2.0)
    return "tangential-to-normal stiffness ratio KAPPA = kt/kn = " + number(kappa) +
           " is unusually large (elastic spheres: 2 (1 - nu)/(2 - nu) = 0.67 .. 1 for nu in [0, 0.5]; usual "
           "0.2 .. 1.5); a stiffer tangential spring also shortens the critical time step";
  return {};
}

inline std::string poisson(double nu) {
  if (nu < 0.0)
    return "Poisson ratio NU = " + number(nu) + " is negative (an auxetic material; granular solids: 0.1 .. 0.45)";
  return {};
}

}  // namespace usual
}  // namespace tdem
