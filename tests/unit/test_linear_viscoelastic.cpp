// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the linear viscoelastic normal law: closed forms of restitution and contact
// time for both end-of-contact conventions against an independent RK4 integration of the
// kernel, against the numbers of physics_reference.md section 8.1 (derived independently),
// parameter round trips and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "contact/normal/linear_viscoelastic.h"
#include "single_collision.h"

using tdem::ContactEnd;
namespace lsd = tdem::lsd;

namespace {

constexpr double kRel = 1e-6;

tdem::testing::CollisionOutcome simulate(ContactEnd end, const lsd::Coefficients<double>& c,
                                         double meff, double v0, int steps_per_contact = 20000) {
  const double tc_guess = M_PI / std::sqrt(c.k / meff);
  auto force = [&](double xi, double xidot) {
    // Before the end event the clipped and unclipped forces agree; integrate the kernel as is.
    return lsd::force(end, c, tdem::NormalKinematics<double>{xi, xidot, meff, 1.0}).force;
  };
  auto ends = [&](double xi, double xidot) {
    if (end == ContactEnd::zero_overlap) return xi;
    return c.k * xi + c.gamma * xidot;  // unclipped force: contact ends where it reaches zero
  };
  return tdem::testing::integrate_collision(force, ends, meff, v0, tc_guess / steps_per_contact,
                                            100.0 * tc_guess);
}

}  // namespace

// physics_reference.md 8.1: m* = 0.01 kg, k = 1e5 N/m, v0 = 1 m/s.
struct Row {
  double e, gamma, tA, tB, eB;
};
static const Row kTable[] = {
    {0.95, 1.03248, 9.93591e-4, 9.83265e-4, 0.950507},
    {0.80, 4.48097, 9.95962e-4, 9.51001e-4, 0.808099},
    {0.50, 13.6265, 1.017352e-3, 8.76707e-4, 0.550283},
    {0.20, 28.8368, 1.116239e-3, 7.79804e-4, 0.324863},
    {0.05, 43.6462, 1.372735e-3, 7.07133e-4, 0.213700},
};

TEST(LinearViscoelastic, ReferenceTableBothConventions) {
  const double m = 0.01, k = 1e5;
  for (const auto& r : kTable) {
    const auto c = lsd::from_restitution_and_stiffness(r.e, k, m, ContactEnd::zero_overlap);
    EXPECT_NEAR(c.gamma, r.gamma, 6e-6 * r.gamma) << "e=" << r.e;
    const lsd::Coefficients<double> cr{k, r.gamma};
    EXPECT_NEAR(lsd::contact_time(cr, m, ContactEnd::zero_overlap), r.tA, 1e-6 * r.tA);
    EXPECT_NEAR(lsd::contact_time(cr, m, ContactEnd::zero_force), r.tB, 1e-6 * r.tB);
    EXPECT_NEAR(lsd::restitution(cr, m, ContactEnd::zero_force), r.eB, 1e-6);
  }
}

TEST(LinearViscoelastic, InverseFromRestitutionAndTime) {
  // physics_reference.md 8.1: e = 0.8, t_c = 1e-4 s, m* = 0.01 kg.
  const auto c = lsd::from_restitution_and_time(0.8, 1e-4, 0.01, ContactEnd::zero_overlap);
  EXPECT_NEAR(c.k, 9.919397e6, 1e-6 * 9.919397e6);
  EXPECT_NEAR(c.gamma, 44.62871, 1e-6 * 44.62871);
  // The closed form of the text: k = m (pi^2 + ln^2 e)/t^2, gamma = -2 m ln e / t.
  const double le = std::log(0.8);
  EXPECT_DOUBLE_EQ(c.k, 0.01 * (M_PI * M_PI + le * le) / 1e-8);
  EXPECT_NEAR(c.gamma, -2.0 * 0.01 * le / 1e-4, 1e-12);
}

TEST(LinearViscoelastic, DampingRatioNoAttractionTable) {
  // physics_reference.md 8.1: beta needed for zero-force end (and zero-overlap end).
  const double e[] = {0.98, 0.9, 0.8, 0.5, 0.3, 0.2};
  const double bB[] = {0.006457, 0.034265, 0.074355, 0.255276, 0.497239, 0.731247};
  const double bA[] = {0.006431, 0.033518, 0.070850, 0.215454, 0.357857, 0.455950};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(lsd::damping_ratio_from_restitution(e[i], ContactEnd::zero_force), bB[i], 6e-7);
    EXPECT_NEAR(lsd::damping_ratio_from_restitution(e[i], ContactEnd::zero_overlap), bA[i], 6e-7);
  }
}

TEST(LinearViscoelastic, ClosedFormsMatchIntegrationOfKernel) {
  const double m = 0.01, v0 = 1.0, k = 1e5;
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    for (double beta : {0.0, 0.02, 0.1, 0.3, 0.6, 0.9}) {
      const lsd::Coefficients<double> c{k, 2.0 * beta * std::sqrt(k * m)};
      const auto sim = simulate(end, c, m, v0);
      const double e = lsd::restitution(c, m, end), tc = lsd::contact_time(c, m, end);
      EXPECT_NEAR(sim.restitution, e, kRel * e) << to_string(end) << " beta=" << beta;
      EXPECT_NEAR(sim.contact_time, tc, kRel * tc) << to_string(end) << " beta=" << beta;
      EXPECT_NEAR(sim.max_overlap, lsd::max_overlap(c, m, v0), 1e-6 * sim.max_overlap);
    }
  }
}

TEST(LinearViscoelastic, OverdampedNoAttractionStillRebounds) {
  // Zero-force end: e continues below e^-2 into the over-damped range, t_c = 2 atanh(s/d)/s.
  const double m = 0.02, k = 3e4, v0 = 0.5;
  for (double beta : {1.0, 1.5, 3.0}) {
    const lsd::Coefficients<double> c{k, 2.0 * beta * std::sqrt(k * m)};
    const auto sim = simulate(ContactEnd::zero_force, c, m, v0, 40000);
    const double e = lsd::restitution(c, m, ContactEnd::zero_force);
    EXPECT_NEAR(sim.restitution, e, kRel * e) << "beta=" << beta;
    EXPECT_NEAR(sim.contact_time, lsd::contact_time(c, m, ContactEnd::zero_force), 1e-6 * sim.contact_time);
  }
  EXPECT_NEAR(lsd::restitution_from_damping_ratio(1.0, ContactEnd::zero_force), std::exp(-2.0), 1e-15);
  // Continuity across beta = 1.
  EXPECT_NEAR(lsd::restitution_from_damping_ratio(1.0 - 1e-9, ContactEnd::zero_force),
              lsd::restitution_from_damping_ratio(1.0 + 1e-9, ContactEnd::zero_force), 1e-7);
  // Zero-overlap end: an over-damped pair never separates.
  EXPECT_EQ(lsd::restitution_from_damping_ratio(1.2, ContactEnd::zero_overlap), 0.0);
  EXPECT_TRUE(std::isinf(lsd::scaled_contact_time(1.2, ContactEnd::zero_overlap)));
}

TEST(LinearViscoelastic, ParameterRoundTrips) {
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    for (double e : {1.0, 0.99, 0.9, 0.7, 0.5, 0.3, 0.14, 0.1, 0.01}) {
      if (end == ContactEnd::zero_overlap || e > 0.0) {
        for (double m : {1e-6, 0.01, 3.0}) {
          const double tc = 2.5e-5;
          const auto c = lsd::from_restitution_and_time(e, tc, m, end);
          EXPECT_NEAR(lsd::restitution(c, m, end), e, 1e-12) << to_string(end) << " e=" << e;
          EXPECT_NEAR(lsd::contact_time(c, m, end), tc, 1e-12 * tc) << to_string(end) << " e=" << e;
          const auto r = lsd::rates_from_restitution_and_time(e, tc, end).at(m);
          EXPECT_DOUBLE_EQ(r.k, c.k);
          EXPECT_DOUBLE_EQ(r.gamma, c.gamma);
          const auto s = lsd::from_restitution_and_stiffness(e, c.k, m, end);
          EXPECT_NEAR(s.gamma, c.gamma, 1e-12 * (c.gamma + 1.0));
        }
      }
    }
  }
}

TEST(LinearViscoelastic, ConventionsDiffer) {
  // At the same coefficients the zero-force end gives the higher restitution and the shorter
  // contact (physics_reference 2.2.2): 1 % at e = 0.8, ~60 % at e = 0.2.
  const double m = 0.01, k = 1e5;
  const auto c8 = lsd::from_restitution_and_stiffness(0.8, k, m, ContactEnd::zero_overlap);
  EXPECT_GT(lsd::restitution(c8, m, ContactEnd::zero_force), 0.8);
  EXPECT_LT(lsd::contact_time(c8, m, ContactEnd::zero_force), lsd::contact_time(c8, m, ContactEnd::zero_overlap));
  const auto c2 = lsd::from_restitution_and_stiffness(0.2, k, m, ContactEnd::zero_overlap);
  EXPECT_NEAR(lsd::restitution(c2, m, ContactEnd::zero_force) / 0.2, 1.62, 0.01);
}

TEST(LinearViscoelastic, KernelForceValues) {
  const lsd::Coefficients<double> c{2e5, 30.0};
  // Touch: force jumps to gamma v0 (physics_reference 8.8).
  auto r = lsd::force<ContactEnd::zero_overlap>(c, tdem::NormalKinematics<double>{0.0, 0.7, 0.01, 1e-3});
  EXPECT_DOUBLE_EQ(r.force, 30.0 * 0.7);
  // Separating fast at small overlap: attractive unless clipped.
  r = lsd::force<ContactEnd::zero_overlap>(c, tdem::NormalKinematics<double>{1e-6, -1.0, 0.01, 1e-3});
  EXPECT_DOUBLE_EQ(r.force, 2e5 * 1e-6 - 30.0);
  EXPECT_LT(r.force, 0.0);
  r = lsd::force<ContactEnd::zero_force>(c, tdem::NormalKinematics<double>{1e-6, -1.0, 0.01, 1e-3});
  EXPECT_EQ(r.force, 0.0);
  EXPECT_DOUBLE_EQ(r.elastic, 0.2);
  EXPECT_EQ(r.stiffness, 2e5);
  EXPECT_EQ(r.damping, 30.0);
}

TEST(LinearViscoelastic, ForceOverDistanceIsTheSameLaw) {
  const lsd::Coefficients<double> c{3e4, 7.0};
  const double r = 0.0093, xi = 2e-5;
  for (double vnnr : {-0.02, -1e-4, 0.0, 3e-4, 0.05}) {  // vnnr = v_rel . del, < 0 approaching
    const tdem::NormalKinematics<double> kin{xi, -vnnr / r, 0.01, 1e-3};
    for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
      const double f = lsd::force(end, c, kin).force;
      const double ccel = end == ContactEnd::zero_force
                              ? lsd::force_over_distance<ContactEnd::zero_force>(c, xi, vnnr, 1.0 / r, 1.0 / (r * r))
                              : lsd::force_over_distance<ContactEnd::zero_overlap>(c, xi, vnnr, 1.0 / r, 1.0 / (r * r));
      EXPECT_NEAR(ccel * r, f, 1e-14 * (std::fabs(f) + c.k * xi)) << to_string(end) << " vnnr=" << vnnr;
      if (end == ContactEnd::zero_force) {
        EXPECT_GE(ccel, 0.0);
      }
    }
  }
}

TEST(LinearViscoelastic, StiffnessFromMaterialMatchesHertzOverlap) {
  // The undamped linear contact reaches xi_max = v sqrt(m/k); Hertz reaches
  // (5 m v^2 / (4 k_H))^(2/5), k_H = 4/3 E* sqrt(R*) (physics_reference 2.2.3).
  for (double v : {0.1, 1.0, 7.0}) {
    const double E = 7e7, R = 1.5e-3, m = 2e-4;
    const double k = lsd::stiffness_matching_hertz(E, R, m, v);
    const double kH = 4.0 / 3.0 * E * std::sqrt(R);
    EXPECT_NEAR(v * std::sqrt(m / k), std::pow(5.0 * m * v * v / (4.0 * kH), 0.4), 1e-12) << v;
    const double b = lsd::damping_ratio_from_restitution(0.6, ContactEnd::zero_overlap);
    EXPECT_NEAR(lsd::damping_zero_overlap_from_log_restitution(std::log(0.6), k, m),
                lsd::damping_from_ratio(b, k, m), 1e-12 * lsd::damping_from_ratio(b, k, m));
    EXPECT_NEAR(lsd::restitution({k, lsd::damping_from_ratio(b, k, m)}, m, ContactEnd::zero_overlap), 0.6, 1e-12);
  }
}

TEST(LinearViscoelastic, BadInputIsRejected) {
  for (double e : {0.0, -0.1, 1.01, double(NAN)}) {
    EXPECT_THROW(lsd::damping_ratio_from_restitution(e, ContactEnd::zero_force), std::domain_error) << e;
    EXPECT_THROW(lsd::rates_from_restitution_and_time(e, 1e-4, ContactEnd::zero_overlap), std::domain_error) << e;
  }
  for (double tc : {0.0, -1e-4, double(NAN), double(INFINITY)})
    EXPECT_THROW(lsd::rates_from_restitution_and_time(0.5, tc, ContactEnd::zero_force), std::domain_error) << tc;
  EXPECT_THROW(lsd::from_restitution_and_time(0.5, 1e-4, -1.0, ContactEnd::zero_force), std::domain_error);
  EXPECT_THROW(lsd::from_restitution_and_stiffness(0.5, -1.0, 1.0, ContactEnd::zero_force), std::domain_error);
  EXPECT_THROW(lsd::restitution(lsd::Coefficients<double>{1e5, -1.0}, 0.01, ContactEnd::zero_force), std::domain_error);
  try {
    lsd::rates_from_restitution_and_time(1.5, 1e-4, ContactEnd::zero_force);
    FAIL();
  } catch (const std::domain_error& ex) {
    EXPECT_NE(std::string(ex.what()).find("1.5"), std::string::npos) << ex.what();
    EXPECT_NE(std::string(ex.what()).find("(0, 1]"), std::string::npos) << ex.what();
  }
}
