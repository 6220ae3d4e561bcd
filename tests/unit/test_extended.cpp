// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the extended laws (velocity-dependent restitution and contact time): a binary
// impact at v0 reproduces the fitted e(v0) and t_c(v0) (integrated with the RK4 harness, compared
// with the fit formulas written out here), the clamp of v0, the first-touch history, Tsuji's
// v0^(-1/5) scaling of the extended non-linear law, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "collision/head_on.h"
#include "contact/normal/extended.h"

namespace ex = tdem::extended;
namespace fits = tdem::fits;
using tdem::ContactEnd;

namespace {

fits::Fit rational_e() {  // e = 0.9 / (1 + v0^0.6): 0.45 at 1 m/s
  fits::Fit f;
  f.form = fits::Form::rational;
  f.c[0] = 0.9, f.c[1] = 1.0, f.c[2] = 0.6;
  return f;
}
fits::Fit power_tc() {  // t_c = 2e-4 v0^(-0.2)
  fits::Fit f;
  f.form = fits::Form::power;
  f.c[0] = 2e-4, f.c[1] = 0.2;
  return f;
}

tdem::collision::Result impact(ex::LinearParams p, ContactEnd end, double v0, double m = 0.01) {
  tdem::collision::ExtendedLinearLaw law;
  law.p = p;
  law.end_mode = end;
  tdem::collision::Bodies b;
  b.m1 = m;
  tdem::collision::Options o;
  o.steps_per_contact = 4000;
  return tdem::collision::integrate(law, b, v0, o);
}

}  // namespace

TEST(ExtendedLinear, ReproducesFittedRestitutionAndContactTimeInBothConventions) {
  ex::LinearParams p{rational_e(), power_tc(), fits::Range{}};
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    for (double v0 : {0.01, 0.3, 1.0, 4.0, 20.0}) {
      const double e_fit = 0.9 / (1.0 + std::pow(v0, 0.6));
      const double tc_fit = 2e-4 * std::pow(v0, -0.2);
      const auto r = impact(p, end, v0);
      ASSERT_TRUE(r.ended);
      EXPECT_NEAR(r.restitution, e_fit, 1e-9) << "v0 " << v0 << " end " << tdem::to_string(end);
      EXPECT_NEAR(r.contact_time / tc_fit, 1.0, 1e-9) << "v0 " << v0;
    }
  }
}

TEST(ExtendedLinear, ImpactVelocityIsClampedToTheFittedRange) {
  ex::LinearParams p{rational_e(), power_tc(), fits::Range{0.1, 2.0, 1e-3}};
  const auto slow = impact(p, ContactEnd::zero_overlap, 0.01);
  const auto fast = impact(p, ContactEnd::zero_overlap, 50.0);
  EXPECT_NEAR(slow.restitution, 0.9 / (1.0 + std::pow(0.1, 0.6)), 1e-9);
  EXPECT_NEAR(slow.contact_time, 2e-4 * std::pow(0.1, -0.2), 1e-9 * slow.contact_time);
  EXPECT_NEAR(fast.restitution, 0.9 / (1.0 + std::pow(2.0, 0.6)), 1e-9);
  EXPECT_NEAR(fast.contact_time, 2e-4 * std::pow(2.0, -0.2), 1e-9 * fast.contact_time);
}

TEST(ExtendedLinear, CoefficientsAreTakenAtFirstTouchAndKeptForTheEnduringContact) {
  ex::LinearParams p{rational_e(), power_tc(), fits::Range{}};
  const double m = 0.02;
  double hist[ex::linear_history_size] = {0.0, 0.0, 0.0};
  // A set-up pass (update = false) must not store anything.
  ex::linear_force<ContactEnd::zero_overlap>(p, tdem::NormalKinematics<double>{0.0, 1.5, m, 1.0}, hist, false);
  EXPECT_EQ(hist[ex::lin_v0], 0.0);
  const auto f0 =
      ex::linear_force<ContactEnd::zero_overlap>(p, tdem::NormalKinematics<double>{0.0, 1.5, m, 1.0}, hist, true);
  EXPECT_EQ(hist[ex::lin_v0], 1.5);
  // Independent: k = m (pi^2 + ln^2 e)/t_c^2, gamma = -2 m ln e / t_c (attraction allowed).
  const double e = 0.9 / (1.0 + std::pow(1.5, 0.6)), tc = 2e-4 * std::pow(1.5, -0.2), le = std::log(e);
  EXPECT_NEAR(hist[ex::lin_k] / (m * (M_PI * M_PI + le * le) / (tc * tc)), 1.0, 1e-12);
  EXPECT_NEAR(hist[ex::lin_gamma] / (-2.0 * m * le / tc), 1.0, 1e-12);
  EXPECT_NEAR(f0.force, hist[ex::lin_gamma] * 1.5, 1e-9 * f0.force);
  // Later the contact slows down: the coefficients stay.
  const double k = hist[ex::lin_k];
  const auto f1 =
      ex::linear_force<ContactEnd::zero_overlap>(p, tdem::NormalKinematics<double>{1e-5, 1e-4, m, 1.0}, hist, true);
  EXPECT_EQ(hist[ex::lin_k], k);
  EXPECT_DOUBLE_EQ(f1.force, k * 1e-5 + hist[ex::lin_gamma] * 1e-4);
}

TEST(ExtendedLinear, ContactCreatedWhileSeparatingTakesTheSmallestVelocity) {
  ex::LinearParams p{rational_e(), power_tc(), fits::Range{0.05, 10.0, 1e-3}};
  double hist[ex::linear_history_size] = {0.0, 0.0, 0.0};
  ex::linear_force<ContactEnd::zero_force>(p, tdem::NormalKinematics<double>{1e-6, -0.3, 0.01, 1.0}, hist, true);
  EXPECT_EQ(hist[ex::lin_v0], 0.05);
  EXPECT_GT(hist[ex::lin_k], 0.0);
}

TEST(ExtendedLinear, RejectsBadFits) {
  ex::LinearParams p{rational_e(), power_tc(), fits::Range{}};
  p.tc_fit.form = fits::Form::rational;
  EXPECT_THROW(ex::validate(p), std::domain_error);
  p = {rational_e(), power_tc(), fits::Range{2.0, 1.0, 1e-3}};
  EXPECT_THROW(ex::validate(p), std::domain_error);
  p = {rational_e(), power_tc(), fits::Range{}};
  p.e_fit.form = fits::Form::constant;
  p.e_fit.c[0] = 1.2;
  EXPECT_THROW(ex::validate(p), std::domain_error);
  p.e_fit.c[0] = 0.5;
  p.tc_fit.c[0] = -1.0;
  EXPECT_THROW(ex::validate(p), std::domain_error);
}

TEST(VelocityFits, PowerFormIsCappedAtOne) {
  fits::Fit f;
  f.form = fits::Form::power;
  f.c[0] = 0.5, f.c[1] = 0.234;  // Bridges et al.: e = (v/v_c)^(-0.234)
  fits::Range r;
  EXPECT_EQ(fits::restitution(f, r, 0.1), 1.0);
  EXPECT_NEAR(fits::restitution(f, r, 5.0), std::pow(10.0, -0.234), 1e-15);
}

namespace {
tdem::collision::Result hertz_impact(const ex::HertzParams& p, ContactEnd end, double v0) {
  tdem::collision::ExtendedHertzLaw law;
  law.p = p;
  law.end_mode = end;
  tdem::collision::Bodies b;
  b.m1 = 1e-3;
  tdem::collision::Options o;
  o.steps_per_contact = 4000;
  return tdem::collision::integrate(law, b, v0, o);
}
}  // namespace

TEST(ExtendedHertz, ReproducesFittedRestitution) {
  ex::HertzParams p{2e9, rational_e(), fits::Range{}};
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    for (double v0 : {0.05, 1.0, 10.0}) {
      const auto r = hertz_impact(p, end, v0);
      ASSERT_TRUE(r.ended);
      // Tsuji's law maps onto the linear one to ~6 digits (physics_reference 2.2.3).
      EXPECT_NEAR(r.restitution, 0.9 / (1.0 + std::pow(v0, 0.6)), 2e-5) << "v0 " << v0;
    }
  }
}

TEST(ExtendedHertz, ConstantRestitutionKeepsHertzContactTimeScaling) {
  fits::Fit e;
  e.form = fits::Form::constant;
  e.c[0] = 0.6;
  ex::HertzParams p{2e9, e, fits::Range{}};
  const auto a = hertz_impact(p, ContactEnd::zero_force, 0.1);
  const auto b = hertz_impact(p, ContactEnd::zero_force, 10.0);
  // Self-similar: t_c ~ v0^(-1/5) exactly for a constant alpha.
  EXPECT_NEAR(a.contact_time / b.contact_time, std::pow(100.0, 0.2), 1e-7);
  EXPECT_NEAR(a.restitution, b.restitution, 1e-9);
}
