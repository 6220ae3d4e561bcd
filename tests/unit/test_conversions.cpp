// SPDX-License-Identifier: GPL-2.0-or-later
// Root-search conversions restitution -> damping (src/collision/conversions.h): the general
// damping form with Theta = 1/4 is Tsuji's, so the search must find c = alpha sqrt(m* k~) with
// alpha from Tsuji's closed form; for linear and Kuwabara-Kono damping the coefficient found must
// restitute e in an independent RK4 integration (single_collision.h) of the kernel.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/conversions.h"
#include "single_collision.h"

using tdem::ContactEnd;
namespace hz = tdem::hertz;

namespace {
tdem::collision::Bodies steel_on_wall() {
  tdem::collision::Bodies b;
  b.R1 = 0.005;
  b.m1 = tdem::collision::sphere_mass(b.R1, 7850.0);
  return b;
}
}  // namespace

TEST(Conversions, GeneralDampingWithExponentQuarterFindsTsujisAlpha) {
  const auto b = steel_on_wall();
  const double k = hz::stiffness(hz::effective_modulus(2.1e11, 0.3, 2.1e11, 0.3), b.R1);
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    for (double e : {0.3, 0.7, 0.95}) {
      const double c = tdem::collision::hertz_damping_for_restitution(hz::Damping::general, end, {k, 0.0, 0.25}, b,
                                                                      1.0, e, 4000);
      const double alpha = hz::tsuji_alpha_from_restitution(e, end);
      EXPECT_NEAR(c / (alpha * std::sqrt(b.meff() * k)), 1.0, 2e-5) << "e " << e;
    }
  }
}

TEST(Conversions, LinearAndKuwabaraKonoDampingRestituteTheTarget) {
  const auto b = steel_on_wall();
  const double k = hz::stiffness(hz::effective_modulus(2.1e11, 0.3, 2.1e11, 0.3), b.R1);
  const double m = b.meff(), v0 = 2.0;
  for (hz::Damping d : {hz::Damping::linear, hz::Damping::kuwabara_kono}) {
    for (double e : {0.5, 0.85}) {
      const ContactEnd end = ContactEnd::zero_force;
      const double c = tdem::collision::hertz_damping_for_restitution(d, end, {k, 0.0, 0.0}, b, v0, e);
      const hz::Params<double> p{k, c, 0.0};
      auto force = [&](double xi, double xd) {
        return hz::force(d, end, p, tdem::NormalKinematics<double>{std::max(xi, 0.0), xd, m, b.R1}).force;
      };
      // Ends where the (clipped) force reaches zero while unloading.
      auto ends = [&](double xi, double xd) {
        return xd < 0.0 ? std::min(xi, force(xi, xd)) : 1.0;
      };
      const double tc = hz::contact_time_elastic(k, m, v0);
      const auto out = tdem::testing::integrate_collision(force, ends, m, v0, tc / 20000, 10 * tc);
      EXPECT_NEAR(out.restitution, e, 2e-5) << hz::to_string(d) << " e " << e;
    }
  }
}

TEST(Conversions, RejectsUnreachableOrInvalidRestitution) {
  const auto b = steel_on_wall();
  EXPECT_THROW(tdem::collision::hertz_damping_for_restitution(hz::Damping::linear, ContactEnd::zero_force,
                                                              {1e9, 0.0, 0.0}, b, 1.0, 1.0),
               std::domain_error);
  EXPECT_THROW(tdem::collision::hertz_damping_for_restitution(hz::Damping::tsuji, ContactEnd::zero_force,
                                                              {1e9, 0.0, 0.0}, b, 1.0, 0.5),
               std::invalid_argument);
}
