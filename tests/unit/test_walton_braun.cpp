// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the Walton-Braun hysteretic law: the numbers of physics_reference.md 8.3 by an
// independent RK4 integration of the kernel, the dissipated energy along a prescribed load/unload
// path, the reload path and the update of xi_max, the force-dependent unloading stiffness,
// parameter round trips and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/normal/walton_braun.h"
#include "single_collision.h"

namespace wb = tdem::walton_braun;

namespace {

struct Impact {
  tdem::testing::CollisionOutcome out;
  double xi_max;   // history after the impact
  double xi_zero;  // overlap where the force reached zero
};

Impact simulate(const wb::Params<double>& p, double meff, double v0, int steps = 20000) {
  double hist[wb::history_size] = {0.0};
  auto force = [&](double xi, double xidot) {
    return wb::force(p, tdem::NormalKinematics<double>{xi, xidot, meff, 1.0}, hist, true).force;
  };
  // Contact ends where the unloading branch reaches zero force.
  auto ends = [&](double xi, double) { return xi - wb::zero_force_overlap(p, hist[wb::xi_max_slot]); };
  const double tc = M_PI * std::sqrt(meff / p.k_load);  // step size only
  Impact r;
  r.out = tdem::testing::integrate_collision(force, ends, meff, v0, tc / steps, 100.0 * tc);
  r.xi_max = hist[wb::xi_max_slot];
  r.xi_zero = wb::zero_force_overlap(p, r.xi_max);
  return r;
}

double kernel_force(const wb::Params<double>& p, double xi, double* hist, bool update = true) {
  return wb::force(p, tdem::NormalKinematics<double>{xi, 0.0, 1.0, 1.0}, hist, update).force;
}

// Work done on the contact along a prescribed overlap path (trapezoid rule on a fine grid).
double work_along(const wb::Params<double>& p, double* hist, double from, double to, int n = 200000) {
  double w = 0.0, f0 = kernel_force(p, from, hist);
  for (int i = 1; i <= n; ++i) {
    const double x0 = from + (to - from) * (i - 1) / n, x1 = from + (to - from) * double(i) / n;
    const double f1 = kernel_force(p, x1, hist);
    w += 0.5 * (f0 + f1) * (x1 - x0);
    f0 = f1;
  }
  return w;
}

}  // namespace

TEST(WaltonBraun, ReferenceNumbersByIntegration) {
  // physics_reference.md 8.3: k_l = 1e5, k_ul = 1.5625e5, m = 0.01 -> e = 0.8, t_c = 8.94113e-4 s.
  const auto p = wb::constant(1e5, 1.5625e5);
  const double m = 0.01;
  for (double v0 : {0.1, 1.0, 3.0}) {
    const Impact r = simulate(p, m, v0);
    EXPECT_NEAR(r.out.restitution, 0.8, 1e-7) << v0;
    EXPECT_NEAR(r.out.contact_time, 8.94113e-4, 6e-10) << v0;
    EXPECT_NEAR(r.out.max_overlap, v0 * std::sqrt(m / 1e5), 1e-8 * r.out.max_overlap) << v0;
    EXPECT_NEAR(r.xi_max, v0 * std::sqrt(m / 1e5), 1e-8 * r.xi_max) << v0;
    // Residual overlap xi_f / xi_max = 1 - e^2 with the integrated e.
    EXPECT_NEAR(r.xi_zero / r.xi_max, 1.0 - r.out.restitution * r.out.restitution, 1e-7) << v0;
  }
  EXPECT_NEAR(wb::restitution(p, m, 1.0), 0.8, 1e-15);
  EXPECT_NEAR(wb::contact_time(p, m, 1.0), 8.94113e-4, 6e-10);
  EXPECT_NEAR(wb::residual_overlap_ratio(p, m, 1.0), 0.36, 1e-15);
}

TEST(WaltonBraun, DissipatedEnergyIsHalfMv2TimesOneMinusE2) {
  const double m = 0.02, v0 = 0.9;
  for (const auto& p : {wb::constant(2e5, 5e5), wb::constant(1e5, 1.5625e5), wb::force_dependent(1e5, 3e2)}) {
    double hist[1] = {0.0};
    const double xi_max = v0 * std::sqrt(m / p.k_load);  // all kinetic energy stored on k_l
    const double w_in = work_along(p, hist, 0.0, xi_max);
    EXPECT_NEAR(w_in, 0.5 * m * v0 * v0, 1e-9 * w_in);
    const double w_back = -work_along(p, hist, xi_max, 0.0);  // unloading returns this much
    const Impact r = simulate(p, m, v0);
    const double e = r.out.restitution;
    EXPECT_NEAR(w_in - w_back, 0.5 * m * v0 * v0 * (1.0 - e * e), 1e-7 * w_in) << p.k_unload;
    EXPECT_NEAR(e, wb::restitution(p, m, v0), 1e-7);
    EXPECT_NEAR(r.out.contact_time, wb::contact_time(p, m, v0), 1e-6 * r.out.contact_time);
  }
}

TEST(WaltonBraun, ReloadReturnsToTheLoadingLine) {
  const auto p = wb::constant(1e5, 4e5);
  double hist[1] = {0.0};
  // Load to 1e-3: on the loading line.
  EXPECT_DOUBLE_EQ(kernel_force(p, 1e-3, hist), 100.0);
  EXPECT_DOUBLE_EQ(hist[0], 1e-3);
  // Unload to 0.9e-3: k_ul line through (1e-3, 100 N), xi_F0 = 0.75e-3.
  EXPECT_NEAR(kernel_force(p, 0.9e-3, hist), 4e5 * (0.9e-3 - 0.75e-3), 1e-10);
  EXPECT_DOUBLE_EQ(hist[0], 1e-3);
  EXPECT_EQ(kernel_force(p, 0.7e-3, hist), 0.0);  // below xi_F0: no force, no attraction
  // Reload: back along the same k_ul line, meets the loading line at xi_max ...
  EXPECT_NEAR(kernel_force(p, 0.95e-3, hist), 4e5 * (0.95e-3 - 0.75e-3), 1e-10);
  EXPECT_NEAR(kernel_force(p, 1e-3, hist), 100.0, 1e-10);
  // ... and continues on k_l with a new maximum.
  EXPECT_NEAR(kernel_force(p, 1.2e-3, hist), 120.0, 1e-10);
  EXPECT_DOUBLE_EQ(hist[0], 1.2e-3);
  // Unloading now follows the new line: xi_F0 = 1.2e-3 * (1 - 1/4) = 0.9e-3.
  EXPECT_NEAR(wb::zero_force_overlap(p, hist[0]), 0.9e-3, 1e-15);
  EXPECT_NEAR(kernel_force(p, 1.0e-3, hist), 4e5 * (1.0e-3 - 0.9e-3), 1e-10);
  EXPECT_EQ(kernel_force(p, 0.85e-3, hist), 0.0);
  const auto r = wb::force(p, tdem::NormalKinematics<double>{1.1e-3, -0.1, 0.01, 1e-3}, hist, true);
  EXPECT_EQ(r.stiffness, 4e5);
  EXPECT_EQ(r.damping, 0.0);
  EXPECT_EQ(r.elastic, r.force);
  // float instantiation.
  float hf[1] = {1e-3f};
  const auto rf = wb::force(wb::Params<float>{1e5f, 4e5f, 0.0f}, tdem::NormalKinematics<float>{0.9e-3f, -0.1f, 0.01f, 1e-3f}, hf, true);
  EXPECT_NEAR(rf.force, 60.0f, 1e-3f);  // 4e5 (0.9e-3 - 0.75e-3)
  EXPECT_EQ(hf[0], 1e-3f);
}

TEST(WaltonBraun, SetUpPassesDoNotChangeTheHistory) {
  const auto p = wb::constant(1e5, 2e5);
  double hist[1] = {1e-3};
  const double f_setup = kernel_force(p, 1.5e-3, hist, false);
  EXPECT_DOUBLE_EQ(hist[0], 1e-3);
  const double f_step = kernel_force(p, 1.5e-3, hist, true);
  EXPECT_DOUBLE_EQ(f_setup, f_step);
  EXPECT_DOUBLE_EQ(hist[0], 1.5e-3);
  EXPECT_FALSE(wb::history[0].flips_sign);
  EXPECT_STREQ(wb::history[0].name, "xi_max");
}

TEST(WaltonBraun, ForceDependentUnloadingStiffness) {
  // k_ul = k_l + s F_max: e(v0) = [1 + s v0 sqrt(m*/k_l)]^(-1/2).
  const double m = 0.01, kl = 1e5, s = 500.0;
  const auto p = wb::force_dependent(kl, s);
  double prev = 1.0;
  for (double v0 : {0.05, 0.5, 2.0, 8.0}) {
    const double e_formula = 1.0 / std::sqrt(1.0 + s * v0 * std::sqrt(m / kl));
    const Impact r = simulate(p, m, v0);
    EXPECT_NEAR(r.out.restitution, e_formula, 1e-7) << v0;
    EXPECT_NEAR(wb::restitution(p, m, v0), e_formula, 1e-14) << v0;
    const double kul = kl + s * v0 * std::sqrt(m * kl);
    EXPECT_NEAR(r.out.contact_time, 0.5 * M_PI * (std::sqrt(m / kl) + std::sqrt(m / kul)), 1e-6 * r.out.contact_time);
    EXPECT_LT(r.out.restitution, prev);
    prev = r.out.restitution;
  }
  // High-velocity trend: e ~ v0^(-1/2).
  const double e1 = wb::restitution(p, m, 1e5), e2 = wb::restitution(p, m, 4e5);
  EXPECT_NEAR(std::log(e2 / e1) / std::log(4.0), -0.5, 1e-3);
}

TEST(WaltonBraun, ParameterRoundTrips) {
  for (double e : {1.0, 0.95, 0.8, 0.5, 0.1}) {
    for (double m : {1e-5, 0.01, 2.0}) {
      const double tc = 3e-4;
      const auto p = wb::from_restitution_and_time(e, tc, m);
      EXPECT_NEAR(wb::restitution(p, m, 1.7), e, 1e-14) << e;
      EXPECT_NEAR(wb::contact_time(p, m, 1.7), tc, 1e-14 * tc) << e;
      const auto q = wb::from_restitution_and_stiffness(e, p.k_load);
      EXPECT_DOUBLE_EQ(q.k_unload, p.k_unload);
      const auto f = wb::force_dependent_from_restitution(e, 2.5, 3e4, m);
      EXPECT_NEAR(wb::restitution(f, m, 2.5), e, 1e-14) << e;
    }
  }
  // 8.3 inverted: e = 0.8, t_c = 8.94113e-4, m = 0.01 -> k_l = 1e5, k_ul = 1.5625e5.
  const auto p = wb::from_restitution_and_time(0.8, 8.94113e-4, 0.01);
  EXPECT_NEAR(p.k_load, 1e5, 1e-6 * 1e5);
  EXPECT_NEAR(p.k_unload, 1.5625e5, 1e-6 * 1.5625e5);
}

TEST(WaltonBraun, BadInputIsRejected) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::domain_error& ex) {
      return std::string(ex.what());
    }
    return std::string("no exception");
  };
  std::string msg = message([] { wb::validate(wb::constant(1e5, 5e4)); });
  EXPECT_NE(msg.find("unloading stiffness k_u = 50000"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[k_l, inf)"), std::string::npos) << msg;
  msg = message([] { wb::from_restitution_and_time(0.8, -1e-4, 0.01); });
  EXPECT_NE(msg.find("contact time t_c = -0.0001"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, inf)"), std::string::npos) << msg;
  msg = message([] { wb::from_restitution_and_stiffness(0.0, 1e5); });
  EXPECT_NE(msg.find("coefficient of restitution e = 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, 1]"), std::string::npos) << msg;
  EXPECT_THROW(wb::validate(wb::force_dependent(1e5, -1.0)), std::domain_error);
  EXPECT_THROW(wb::validate(wb::constant(0.0, 1e5)), std::domain_error);
  EXPECT_THROW(wb::restitution(wb::constant(1e5, 2e5), -0.01, 1.0), std::domain_error);
  EXPECT_THROW(wb::restitution(wb::constant(1e5, 2e5), 0.01, NAN), std::domain_error);
  EXPECT_THROW(wb::force_dependent_from_restitution(0.5, 0.0, 1e5, 0.01), std::domain_error);
}
