// SPDX-License-Identifier: GPL-2.0-or-later
// Tests of the single-collision integrator src/collision/head_on.h (used by tdem-collide):
// expected values are closed forms re-typed here or the numbers of physics_reference.md 8.1-8.3,
// never the integrator's own output.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "collision/head_on.h"

namespace col = tdem::collision;
using tdem::ContactEnd;

namespace {

col::Bodies wall(double m1, double R1 = 0.0) {
  col::Bodies b;
  b.m1 = m1;
  b.R1 = R1;
  return b;
}

col::LsdLaw lsd_law(double k, double gamma, ContactEnd end) {
  col::LsdLaw l;
  l.c = {k, gamma};
  l.end_mode = end;
  return l;
}

// Work done on the contact along the recorded path, W = int F dxi (trapezoid rule).
double loop_work(const std::vector<col::Sample>& s) {
  double w = 0.0;
  for (size_t i = 1; i < s.size(); ++i) w += 0.5 * (s[i].force + s[i - 1].force) * (s[i].xi - s[i - 1].xi);
  return w;
}

// Closed forms of the linear spring-dashpot, re-typed (physics_reference.md 2.2.2).
struct LsdClosed {
  double e, tc;
};
LsdClosed lsd_closed(double k, double gamma, double m, ContactEnd end) {
  const double w0 = std::sqrt(k / m), d = gamma / (2.0 * m), w = std::sqrt(w0 * w0 - d * d);
  if (end == ContactEnd::zero_overlap) return {std::exp(-d * M_PI / w), M_PI / w};
  const double tc = 2.0 * std::atan(w / d) / w;
  return {std::exp(-d * tc), tc};
}

}  // namespace

// physics_reference.md 8.1: m* = 0.01 kg, k = 1e5 N/m, v0 = 1 m/s.
TEST(Collide, LsdTableBothEnds) {
  struct Row {
    double gamma, tA, eA, tB, eB;
  };
  const Row rows[] = {{1.03248, 9.93591e-4, 0.950000, 9.83265e-4, 0.950507},
                      {4.48097, 9.95962e-4, 0.800000, 9.51001e-4, 0.808099},
                      {13.6265, 1.017352e-3, 0.500000, 8.76707e-4, 0.550283},
                      {28.8368, 1.116239e-3, 0.200000, 7.79804e-4, 0.324863},
                      {43.6462, 1.372735e-3, 0.050000, 7.07133e-4, 0.213700}};
  for (const Row& r : rows) {
    for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
      auto law = lsd_law(1e5, r.gamma, end);
      const auto res = col::integrate(law, wall(0.01), 1.0);
      ASSERT_TRUE(res.ended);
      const LsdClosed c = lsd_closed(1e5, r.gamma, 0.01, end);
      EXPECT_NEAR(res.restitution, c.e, 1e-6 * c.e) << r.gamma;
      EXPECT_NEAR(res.contact_time, c.tc, 1e-6 * c.tc) << r.gamma;
      const bool a = end == ContactEnd::zero_overlap;
      // Table values are rounded to 6-7 digits.
      EXPECT_NEAR(res.restitution, a ? r.eA : r.eB, 2e-6) << r.gamma;
      EXPECT_NEAR(res.contact_time, a ? r.tA : r.tB, 1e-5 * r.tA) << r.gamma;
      if (a) {
        EXPECT_EQ(res.residual_overlap, 0.0);
      } else {
        EXPECT_GT(res.residual_overlap, 0.0);  // the force reaches zero before the overlap
        // there F = k xi + gamma xi' = 0
        EXPECT_NEAR(1e5 * res.residual_overlap - r.gamma * res.rebound_velocity, 0.0, 1e-6 * r.gamma);
      }
      // Largest overlap of the damped oscillator, re-typed: xi = v0 e^{-d t} sin(w t)/w at tan(w t) = w/d.
      const double w0 = std::sqrt(1e7), d = r.gamma / 0.02, w = std::sqrt(w0 * w0 - d * d);
      const double tm = std::atan2(w, d) / w;
      EXPECT_NEAR(res.max_overlap, std::exp(-d * tm) * std::sin(w * tm) / w, 1e-9 * res.max_overlap);
    }
  }
}

TEST(Collide, LsdFromRestitutionAndTime) {
  // physics_reference.md 8.1: e = 0.8, t_c = 1e-4 s, m* = 0.01 -> k = 9.919397e6, gamma = 44.62871.
  col::LsdLaw law;
  law.c = tdem::lsd::from_restitution_and_time(0.8, 1e-4, 0.01, ContactEnd::zero_overlap);
  EXPECT_NEAR(law.c.k, 9.919397e6, 1.0);
  EXPECT_NEAR(law.c.gamma, 44.62871, 1e-5);
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    law.c = tdem::lsd::from_restitution_and_time(0.8, 1e-4, 0.01, end);
    law.end_mode = end;
    const auto res = col::integrate(law, wall(0.01), 1.0);
    EXPECT_NEAR(res.restitution, 0.8, 1e-6);
    EXPECT_NEAR(res.contact_time, 1e-4, 1e-10);
  }
}

TEST(Collide, SphereSphereEqualsWallWithSameEffectiveMass) {
  auto law = lsd_law(1e5, 4.48097, ContactEnd::zero_force);
  col::Bodies pair;
  pair.m1 = 0.02;
  pair.m2 = 0.02;  // m* = 0.01
  const auto a = col::integrate(law, pair, 1.0);
  const auto b = col::integrate(law, wall(0.01), 1.0);
  EXPECT_NEAR(a.restitution, b.restitution, 1e-12);
  EXPECT_NEAR(a.contact_time, b.contact_time, 1e-15);
}

// physics_reference.md 8.2: steel sphere R = 5 mm on a steel half-space.
TEST(Collide, HertzSteelSphere) {
  const double E = 210e9, nu = 0.3, R = 0.005, rho = 7850.0;
  const double e_star = E / (2.0 * (1.0 - nu * nu));
  const double m = 4.0 / 3.0 * M_PI * R * R * R * rho;
  EXPECT_NEAR(m, 4.110250e-3, 1e-9);
  col::HertzLaw law;
  law.damping = tdem::hertz::Damping::linear;
  law.p = {4.0 / 3.0 * e_star * std::sqrt(R), 0.0, 0.0};
  EXPECT_NEAR(law.p.k, 1.087857e10, 1e4);
  const double C = 0.8 * std::sqrt(M_PI) * std::tgamma(0.4) / std::tgamma(0.9);  // 2.94328
  struct Row {
    double v0, xi_max, tc;
  };
  for (const Row& r : {Row{0.1, 1.860727e-6, 5.4766e-5}, Row{1.0, 1.174039e-5, 3.4555e-5},
                       Row{10.0, 7.407688e-5, 2.1803e-5}}) {
    const auto res = col::integrate(law, wall(m, R), r.v0);
    ASSERT_TRUE(res.ended);
    const double xi_max = std::pow(5.0 * m * r.v0 * r.v0 / (4.0 * law.p.k), 0.4);
    EXPECT_NEAR(res.max_overlap, xi_max, 1e-9 * xi_max);
    EXPECT_NEAR(res.contact_time, C * xi_max / r.v0, 1e-6 * C * xi_max / r.v0);
    EXPECT_NEAR(res.max_overlap, r.xi_max, 1e-5 * r.xi_max);
    EXPECT_NEAR(res.contact_time, r.tc, 2e-5 * r.tc);  // table: 5 digits
    EXPECT_NEAR(res.restitution, 1.0, 1e-9);
    EXPECT_NEAR(res.max_force, law.p.k * std::pow(xi_max, 1.5), 1e-8 * res.max_force);
  }
}

TEST(Collide, TsujiAlphaToRestitution) {
  // physics_reference.md 8.2: e does not depend on v0.
  struct Row {
    double alpha, e_force, e_overlap;
  };
  const Row rows[] = {{0.05, 0.93308, 0.93215}, {0.2, 0.76641, 0.75418}, {0.5, 0.53942, 0.48640},
                      {1.0, 0.33050, 0.20788}};
  col::HertzLaw law;
  law.damping = tdem::hertz::Damping::tsuji;
  col::Options opt;
  opt.steps_per_contact = 20000;  // the damping ~ xi^(1/4) is not smooth at touch
  for (const Row& r : rows)
    for (double v0 : {1.0, 5.0})
      for (ContactEnd end : {ContactEnd::zero_force, ContactEnd::zero_overlap}) {
        law.p = {1.087857e10, r.alpha, 0.0};
        law.end_mode = end;
        const auto res = col::integrate(law, wall(4.110250e-3, 0.005), v0, opt);
        EXPECT_NEAR(res.restitution, end == ContactEnd::zero_force ? r.e_force : r.e_overlap, 6e-6)
            << r.alpha << " " << v0;
      }
}

// physics_reference.md 8.3: k_l = 1e5, k_ul = 1.5625e5, m = 0.01 -> e = 0.8, t_c = 8.94113e-4 s.
TEST(Collide, WaltonBraun) {
  col::WaltonBraunLaw law;
  law.p = {1e5, 1.5625e5, 0.0};
  col::Options opt;
  opt.record = true;
  const double m = 0.01, v0 = 1.0;
  const auto res = col::integrate(law, wall(m), v0, opt);
  ASSERT_TRUE(res.ended);
  const double e = 0.8;
  EXPECT_NEAR(res.restitution, e, 1e-9);
  EXPECT_NEAR(res.contact_time, 8.94113e-4, 1e-9);
  // re-typed: t_c = pi/2 (sqrt(m/k_l) + sqrt(m/k_ul)), xi_max = v0 sqrt(m/k_l)
  EXPECT_NEAR(res.contact_time, 0.5 * M_PI * (std::sqrt(m / 1e5) + std::sqrt(m / 1.5625e5)), 1e-12);
  const double xi_max = v0 * std::sqrt(m / 1e5);
  EXPECT_NEAR(res.max_overlap, xi_max, 1e-12 * xi_max);
  EXPECT_NEAR(res.residual_overlap / res.max_overlap, 1.0 - e * e, 1e-9);
  EXPECT_NEAR(law.hist[tdem::walton_braun::xi_max_slot], xi_max, 1e-12 * xi_max);
  // Energy: the loop area equals the lost kinetic energy 1/2 m v0^2 (1 - e^2).
  const double lost = 0.5 * m * v0 * v0 * (1.0 - e * e);
  EXPECT_NEAR(res.dissipated_energy, lost, 1e-9 * lost);
  EXPECT_NEAR(loop_work(res.samples), lost, 1e-8 * lost);
  // Force-dependent unloading: e = [1 + s v0 sqrt(m/k_l)]^(-1/2).
  law.p = {1e5, 1e5, 2.0e4};
  const auto fd = col::integrate(law, wall(m), v0);
  EXPECT_NEAR(fd.restitution, 1.0 / std::sqrt(1.0 + 2.0e4 * v0 * std::sqrt(m / 1e5)), 1e-9);
}

TEST(Collide, ThorntonRestitutionAndEnergy) {
  const double e_star = 210e9 / (2.0 * (1.0 - 0.09)), R = 0.005, m = 4.0 / 3.0 * M_PI * R * R * R * 7850.0;
  col::ThorntonLaw law;
  law.p = {e_star, 1e9};
  // yield velocity re-typed: v_y = pi^2/sqrt(40) sqrt(p_y^5/(E*^4 rho))
  const double vy = M_PI * M_PI / std::sqrt(40.0) * std::sqrt(std::pow(1e9, 5) / (std::pow(e_star, 4) * 7850.0));
  EXPECT_THROW(col::integrate(law, wall(m), 1.0), std::domain_error);  // needs R*
  col::Options opt;
  opt.record = true;
  for (double v0 : {0.02, 0.2, 1.0, 5.0}) {
    const auto res = col::integrate(law, wall(m, R), v0, opt);
    ASSERT_TRUE(res.ended);
    const double r = vy / v0;
    const double e = r >= 1.0 ? 1.0
                              : std::sqrt(6.0 * std::sqrt(3.0) / 5.0 * (1.0 - r * r / 6.0)) *
                                    std::pow(r / (r + 2.0 * std::sqrt(6.0 / 5.0 - r * r / 5.0)), 0.25);
    EXPECT_NEAR(res.restitution, e, 1e-7) << v0;
    const double lost = 0.5 * m * v0 * v0 * (1.0 - res.restitution * res.restitution);
    EXPECT_NEAR(loop_work(res.samples), lost, 1e-5 * 0.5 * m * v0 * v0) << v0;
    if (r < 1.0) {
      EXPECT_GT(res.residual_overlap, 0.0);
    }
  }
}

TEST(Collide, ContinuousPotentialConservesEnergy) {
  col::ContinuousPotentialLaw law;
  const double m = 0.01, v0 = 1.0, d = 0.005, n = 36.0;
  const double x_min = 0.00499;
  // Starts at X = d (no cut-off): eps (d/X_min)^n = eps + 1/2 m v0^2.
  const double eps = 0.5 * m * v0 * v0 / (std::pow(d / x_min, n) - 1.0);
  law.p = {eps, d, n, INFINITY, 0.0};
  const auto res = col::integrate(law, wall(m, d), v0);
  ASSERT_TRUE(res.ended);
  EXPECT_NEAR(res.restitution, 1.0, 1e-10);
  EXPECT_NEAR(res.max_overlap, d - x_min, 1e-9 * (d - x_min));
  // with a cut-off beyond touch the collision starts (and ends) at X_cut: xi_start = d - X_cut < 0
  law.p.x_cut = 1.001 * d;
  const auto cut = col::integrate(law, wall(m, d), v0);
  ASSERT_TRUE(cut.ended);
  EXPECT_NEAR(cut.restitution, 1.0, 1e-10);
  EXPECT_NEAR(cut.residual_overlap, d - 1.001 * d, 1e-18);
  // a dashpot dissipates
  law.p.gamma = 1.0;
  EXPECT_LT(col::integrate(law, wall(m, d), v0).restitution, 0.999);
}

TEST(Collide, SamplesAndOptions) {
  auto law = lsd_law(1e5, 4.48097, ContactEnd::zero_overlap);
  col::Options opt;
  opt.record = true;
  opt.dt = 1e-6;
  const auto res = col::integrate(law, wall(0.01), 1.0, opt);
  EXPECT_EQ(res.dt, 1e-6);
  ASSERT_EQ(res.samples.size(), size_t(res.steps + 1));
  EXPECT_EQ(res.samples.front().t, 0.0);
  EXPECT_EQ(res.samples.front().xi, 0.0);
  EXPECT_EQ(res.samples.front().xi_dot, 1.0);
  EXPECT_NEAR(res.samples.front().force, 4.48097, 1e-12);  // F(0+) = gamma v0
  EXPECT_EQ(res.samples.back().t, res.contact_time);
  for (size_t i = 1; i < res.samples.size(); ++i) EXPECT_GT(res.samples[i].t, res.samples[i - 1].t);
  // the contact of an over-damped zero_overlap LSD never ends
  auto over = lsd_law(1e5, 1e3, ContactEnd::zero_overlap);
  col::Options few;
  few.max_contact_times = 5.0;
  const auto never = col::integrate(over, wall(0.01), 1.0, few);
  EXPECT_FALSE(never.ended);
  // bad input
  EXPECT_THROW(col::integrate(law, wall(0.01), 0.0), std::domain_error);
  EXPECT_THROW(col::integrate(law, wall(0.01), -1.0), std::domain_error);
  EXPECT_THROW(col::integrate(law, wall(-1.0), 1.0), std::domain_error);
  col::Options bad;
  bad.dt = -1.0;
  EXPECT_THROW(col::integrate(law, wall(0.01), 1.0, bad), std::domain_error);
  bad.dt = 0.0;
  bad.steps_per_contact = 0;
  EXPECT_THROW(col::integrate(law, wall(0.01), 1.0, bad), std::domain_error);
}
