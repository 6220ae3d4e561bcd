// SPDX-License-Identifier: GPL-2.0-or-later
// The elastic pair properties of src/contact/material.h (issue 19: one definition for every law,
// the advice and the tools) against hand-computed closed forms, and the one Poisson rule.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "fixes/timestep/timestep.h"
#include "contact/material.h"
#include "contact/normal/hertz_damped.h"
#include "contact/tangential/parameters.h"

namespace {
namespace mt = tdem::material;

std::string message_of(void (*f)()) {
  try {
    f();
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "";
}

TEST(Material, ClosedForms) {
  // steel (210 GPa, 0.3) on glass (63 GPa, 0.22), by hand:
  // 1/E* = 0.91/210e9 + 0.9516/63e9 = 4.333333e-12 + 1.510476e-11 = 1.943810e-11
  const double estar = mt::effective_modulus(210e9, 0.3, 63e9, 0.22);
  EXPECT_NEAR(estar, 1.0 / (0.91 / 210e9 + 0.9516 / 63e9), 1e-6 * estar);
  EXPECT_NEAR(estar, 5.14454e10, 1e5);
  // G = E / (2 (1 + nu)): 210e9 / 2.6 = 80.769e9
  EXPECT_DOUBLE_EQ(mt::shear_modulus(210e9, 0.3), 210e9 / 2.6);
  // 1/G* = 1.7/G1 + 1.78/G2 with G2 = 63e9/2.44
  const double g1 = 210e9 / 2.6, g2 = 63e9 / 2.44;
  EXPECT_NEAR(mt::effective_shear_modulus_from_E(210e9, 0.3, 63e9, 0.22), 1.0 / (1.7 / g1 + 1.78 / g2), 1.0);
  // like materials: kappa = 4 G*/E* = 2 (1 - nu)/(2 - nu)
  for (double nu : {-0.5, 0.0, 0.25, 0.3, 0.5}) {
    const double e = mt::effective_modulus(1e7, nu, 1e7, nu);
    const double g = mt::effective_shear_modulus_from_E(1e7, nu, 1e7, nu);
    EXPECT_NEAR(mt::kappa_hertz_mindlin(g, e), 2.0 * (1.0 - nu) / (2.0 - nu), 1e-14) << nu;
    EXPECT_NEAR(mt::kappa_hertz_mindlin(nu), 2.0 * (1.0 - nu) / (2.0 - nu), 1e-15) << nu;
  }
  // a rigid wall adds nothing; two rigid partners are an error
  EXPECT_DOUBLE_EQ(mt::effective_modulus(1e7, 0.3, INFINITY, 0.3), 1e7 / 0.91);
  EXPECT_DOUBLE_EQ(mt::effective_modulus(INFINITY, 0.3, 1e7, 0.3), 1e7 / 0.91);
  EXPECT_THROW(mt::effective_modulus(INFINITY, 0.3, INFINITY, 0.3), std::domain_error);
  EXPECT_DOUBLE_EQ(mt::effective_shear_modulus_from_E(1e7, 0.3, INFINITY, 0.3), 1e7 / 2.6 / 1.7);
}

TEST(Material, TheOtherNamesAreTheSameFunctions) {
  // hertz::, tangential:: and advice:: take these from material.h: the same numbers bitwise
  EXPECT_EQ(tdem::hertz::effective_modulus(2e8, 0.3, 7e7, 0.25), mt::effective_modulus(2e8, 0.3, 7e7, 0.25));
  EXPECT_EQ(tdem::tangential::effective_youngs_modulus(2e8, 0.3, 7e7, 0.25), mt::effective_modulus(2e8, 0.3, 7e7, 0.25));
  EXPECT_EQ(tdem::tangential::shear_modulus(2e8, 0.3), mt::shear_modulus(2e8, 0.3));
  EXPECT_EQ(tdem::advice::shear_modulus(2e8, 0.3), mt::shear_modulus(2e8, 0.3));
  EXPECT_EQ(tdem::tangential::kappa_hertz_mindlin(0.3), mt::kappa_hertz_mindlin(0.3));
}

TEST(Material, OnePoissonRule) {
  // (-1, 0.5] everywhere: 0.5 (incompressible) is accepted by the normal and the tangential side
  EXPECT_NO_THROW(mt::effective_modulus(1e7, 0.5, 1e7, 0.5));
  EXPECT_NO_THROW(mt::effective_shear_modulus_from_E(1e7, 0.5, 1e7, 0.5));
  EXPECT_NO_THROW(tdem::tangential::kappa_hertz_mindlin(0.5));
  EXPECT_NO_THROW(tdem::advice::shear_modulus(1e7, 0.5));
  for (double nu : {-1.0, 0.5000001, 0.7, double(NAN), double(INFINITY)}) {
    EXPECT_FALSE(tdem::checks::poisson_ok(nu)) << nu;
    EXPECT_THROW(mt::shear_modulus(1e7, nu), std::domain_error) << nu;
    EXPECT_THROW(mt::effective_modulus(1e7, 0.3, 1e7, nu), std::domain_error) << nu;
    EXPECT_THROW(mt::effective_shear_modulus_from_E(1e7, nu, 1e7, 0.3), std::domain_error) << nu;
  }
  const std::string m = message_of([] { mt::effective_shear_modulus(1e7, 0.3, 1e7, 0.7); });
  EXPECT_NE(m.find("Poisson's ratio nu2 = 0.7 is outside the allowed range (-1, 0.5]"), std::string::npos) << m;
}

}  // namespace
