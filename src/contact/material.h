// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: elastic pair properties of two isotropic materials, in one place for the normal and
// tangential laws, the advice, the collision solutions and the tools (issue 19: E* was computed
// three ways, and Poisson's ratio had two allowed ranges).
//
//   shear modulus             G = E / (2 (1 + nu))
//   effective modulus         1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2            (Hertz)
//   effective shear modulus   1/G* = (2 - nu1)/G1 + (2 - nu2)/G2                (Mindlin)
//   Hertz-Mindlin ratio       kappa = k_t/k_n = 4 G*/E*; like materials 2 (1 - nu)/(2 - nu)
//
// A rigid partner (a wall) has E = G = +infinity and adds nothing; both rigid is an error.
// Poisson's ratio must be in (-1, 0.5] (checks::poisson).
#pragma once

#include <cmath>
#include <stdexcept>

#include "input_checks.h"

namespace tdem {
namespace material {

inline double shear_modulus(double E, double nu) {
  checks::positive("Young's modulus E", E);
  checks::poisson("Poisson's ratio nu", nu);
  return E / (2.0 * (1.0 + nu));
}

inline double effective_modulus(double E1, double nu1, double E2, double nu2) {
  checks::positive("Young's modulus E1", std::isinf(E1) && E1 > 0.0 ? 1.0 : E1);
  checks::positive("Young's modulus E2", std::isinf(E2) && E2 > 0.0 ? 1.0 : E2);
  checks::poisson("Poisson ratio nu", nu1);
  checks::poisson("Poisson ratio nu", nu2);
  const double c1 = std::isinf(E1) ? 0.0 : (1.0 - nu1 * nu1) / E1;
  const double c2 = std::isinf(E2) ? 0.0 : (1.0 - nu2 * nu2) / E2;
  if (!(c1 + c2 > 0.0)) throw std::domain_error("effective modulus: both partners are rigid (E = inf)");
  return 1.0 / (c1 + c2);
}

inline double effective_shear_modulus(double G1, double nu1, double G2, double nu2) {
  checks::positive("shear modulus G1", std::isinf(G1) && G1 > 0.0 ? 1.0 : G1);
  checks::positive("shear modulus G2", std::isinf(G2) && G2 > 0.0 ? 1.0 : G2);
  checks::poisson("Poisson's ratio nu1", nu1);
  checks::poisson("Poisson's ratio nu2", nu2);
  const double c1 = std::isinf(G1) ? 0.0 : (2.0 - nu1) / G1;
  const double c2 = std::isinf(G2) ? 0.0 : (2.0 - nu2) / G2;
  if (!(c1 + c2 > 0.0)) throw std::domain_error("effective shear modulus: both partners are rigid (G = inf)");
  return 1.0 / (c1 + c2);
}

inline double effective_shear_modulus_from_E(double E1, double nu1, double E2, double nu2) {
  const double G1 = std::isinf(E1) ? E1 : shear_modulus(E1, nu1);
  const double G2 = std::isinf(E2) ? E2 : shear_modulus(E2, nu2);
  return effective_shear_modulus(G1, nu1, G2, nu2);
}

// kappa = k_t/k_n of Hertz-Mindlin (no-slip tangential over Hertz normal tangent stiffness).
inline double kappa_hertz_mindlin(double gstar, double estar) {
  checks::positive("effective shear modulus G*", gstar);
  checks::positive("effective Young's modulus E*", estar);
  return 4.0 * gstar / estar;
}
// Like materials (same E and nu on both sides): 2 (1 - nu)/(2 - nu).
inline double kappa_hertz_mindlin(double nu) {
  checks::poisson("Poisson's ratio nu", nu);
  return 2.0 * (1.0 - nu) / (2.0 - nu);
}

}  // namespace material
}  // namespace tdem
