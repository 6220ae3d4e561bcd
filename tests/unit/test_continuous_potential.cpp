// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the continuous-potential law (Langston type): force values against the
// potential, e = 1 without damping and the closest approach by an independent RK4 integration,
// dissipation with the dashpot, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/normal/continuous_potential.h"
#include "single_collision.h"

using tdem::ContactEnd;
namespace cp = tdem::continuous_potential;

namespace {

// Integrates in y = X_start - X (y = 0 on entry, y > 0 while approaching): the harness's
// "overlap". The collision ends when the pair is back at X_start.
tdem::testing::CollisionOutcome simulate(ContactEnd end, const cp::Params<double>& p, double meff, double v0,
                                         double x_start, int steps = 20000) {
  auto force = [&](double y, double ydot) {
    return cp::force(end, p, tdem::NormalKinematics<double>{p.d - (x_start - y), ydot, meff, 1.0}).force;
  };
  auto ends = [](double y, double) { return y; };
  // Step from the linearised stiffness at the undamped closest approach.
  const double xm = cp::closest_approach(p, meff, v0);
  const double k = p.n * (p.n + 1.0) * p.eps * std::pow(p.d / xm, p.n) / (xm * xm);
  const double t = M_PI * std::sqrt(meff / k) + 2.0 * (x_start - xm) / v0;
  auto out = tdem::testing::integrate_collision(force, ends, meff, v0, t / steps, 100.0 * t);
  out.max_overlap = x_start - out.max_overlap;  // report the closest centre distance instead
  return out;
}

}  // namespace

TEST(ContinuousPotential, ForceFollowsThePotential) {
  const cp::Params<double> p{2e-3, 4e-3, 36.0, INFINITY, 0.0};
  // At X = d: F = n eps / d.
  auto r = cp::force<ContactEnd::zero_overlap>(p, tdem::NormalKinematics<double>{0.0, 0.0, 1e-3, 1e-3});
  EXPECT_NEAR(r.force, 36.0 * 2e-3 / 4e-3, 1e-14);
  EXPECT_NEAR(r.stiffness, 36.0 * 37.0 * 2e-3 / (4e-3 * 4e-3), 1e-9);
  // F = -dphi/dX and k = dF/dxi by central differences, inside and outside d.
  for (double x : {0.97 * p.d, p.d, 1.05 * p.d}) {
    const double h = 1e-7 * p.d;
    const double f_fd = -(cp::potential(p, x + h) - cp::potential(p, x - h)) / (2.0 * h);
    r = cp::force<ContactEnd::zero_overlap>(p, tdem::NormalKinematics<double>{p.d - x, 0.0, 1e-3, 1e-3});
    EXPECT_NEAR(r.force, f_fd, 1e-7 * f_fd) << x / p.d;
    const double k_fd = (cp::force<ContactEnd::zero_overlap>(p, {p.d - x + h, 0.0, 1e-3, 1e-3}).force -
                         cp::force<ContactEnd::zero_overlap>(p, {p.d - x - h, 0.0, 1e-3, 1e-3}).force) / (2.0 * h);
    EXPECT_NEAR(r.stiffness, k_fd, 1e-6 * k_fd) << x / p.d;
  }
  // Before touch the uncut law already pushes; a cut-off at d switches it off there.
  EXPECT_GT((cp::force<ContactEnd::zero_overlap>(p, {-0.01 * p.d, 0.0, 1e-3, 1e-3}).force), 0.0);
  cp::Params<double> cut = p;
  cut.x_cut = p.d;
  EXPECT_EQ((cp::force<ContactEnd::zero_overlap>(cut, {-0.01 * p.d, 0.5, 1e-3, 1e-3}).force), 0.0);
  EXPECT_NEAR((cp::force<ContactEnd::zero_overlap>(cut, {1e-12, 0.0, 1e-3, 1e-3}).force), 18.0, 1e-6);
  // The dashpot acts in range; the zero-force end clips attraction.
  cut.gamma = 3.0;
  r = cp::force<ContactEnd::zero_overlap>(cut, {1e-6, -10.0, 1e-3, 1e-3});
  EXPECT_NEAR(r.force, r.elastic - 30.0, 1e-12);
  EXPECT_LT(r.force, 0.0);
  EXPECT_EQ(r.damping, 3.0);
  EXPECT_EQ((cp::force<ContactEnd::zero_force>(cut, {1e-6, -10.0, 1e-3, 1e-3}).force), 0.0);
  // float instantiation.
  const float ff = cp::force<ContactEnd::zero_overlap>(cp::Params<float>{2e-3f, 4e-3f, 36.0f, INFINITY, 0.0f},
                                                       tdem::NormalKinematics<float>{0.0f, 0.0f, 1e-3f, 1e-3f}).force;
  EXPECT_NEAR(ff, 18.0f, 1e-4f);
}

TEST(ContinuousPotential, ConservativeWithoutDamping) {
  const double m = 1e-3, v0 = 1.0, d = 2e-3, n = 36.0;
  for (double x_cut : {d, 1.02 * d, double(INFINITY)}) {
    const double x_min = 0.99 * d;
    const double eps = cp::energy_for_closest_approach(x_min, m, v0, d, n, x_cut);
    const cp::Params<double> p{eps, d, n, x_cut, 0.0};
    // Without a cut-off the collision starts at 1.3 d, where the potential is not zero yet:
    // the entry speed is then v0 at 1.3 d, and the closest approach follows from energy.
    const double x_start = std::isinf(x_cut) ? 1.3 * d : x_cut;
    const auto sim = simulate(ContactEnd::zero_overlap, p, m, v0, x_start);
    EXPECT_NEAR(sim.restitution, 1.0, 1e-8) << x_cut / d;
    double expect_min = x_min;
    if (std::isinf(x_cut)) {
      const double q = std::pow(d / x_start, n) + 0.5 * m * v0 * v0 / eps;
      expect_min = d * std::pow(q, -1.0 / n);
    }
    EXPECT_NEAR(sim.max_overlap, expect_min, 1e-8 * d) << x_cut / d;
    EXPECT_NEAR(cp::closest_approach(p, m, v0), x_min, 1e-12 * d);
  }
}

TEST(ContinuousPotential, DashpotDissipates) {
  const double m = 1e-3, v0 = 1.0, d = 2e-3, n = 36.0;
  const double eps = cp::energy_for_closest_approach(0.99 * d, m, v0, d, n, d);
  double prev = 1.0;
  for (double gamma : {0.05, 0.2, 0.5}) {
    const cp::Params<double> p{eps, d, n, d, gamma};
    const auto zo = simulate(ContactEnd::zero_overlap, p, m, v0, d);
    const auto zf = simulate(ContactEnd::zero_force, p, m, v0, d);
    EXPECT_LT(zo.restitution, prev) << gamma;
    EXPECT_GT(zo.restitution, 0.0);
    EXPECT_GE(zf.restitution, zo.restitution - 1e-12) << gamma;  // clipping removes attraction
    prev = zo.restitution;
  }
}

TEST(ContinuousPotential, BadInputIsRejected) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::domain_error& ex) {
      return std::string(ex.what());
    }
    return std::string("no exception");
  };
  std::string msg = message([] { cp::validate(cp::Params<double>{1e-3, 2e-3, -4.0, INFINITY, 0.0}); });
  EXPECT_NE(msg.find("potential exponent n = -4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, inf)"), std::string::npos) << msg;
  msg = message([] { cp::validate(cp::Params<double>{1e-3, 2e-3, 36.0, 0.0, 0.0}); });
  EXPECT_NE(msg.find("cut-off distance X_cut = 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, inf]"), std::string::npos) << msg;
  EXPECT_THROW(cp::validate(cp::Params<double>{0.0, 2e-3, 36.0, INFINITY, 0.0}), std::domain_error);
  EXPECT_THROW(cp::validate(cp::Params<double>{1e-3, 2e-3, 36.0, INFINITY, -1.0}), std::domain_error);
  EXPECT_THROW(cp::validate(cp::Params<double>{1e-3, NAN, 36.0, INFINITY, 0.0}), std::domain_error);
  EXPECT_THROW(cp::energy_for_closest_approach(2.5e-3, 1e-3, 1.0, 2e-3, 36.0, 2e-3), std::domain_error);
  EXPECT_THROW(cp::closest_approach(cp::Params<double>{1e-3, 2e-3, 36.0, INFINITY, 0.0}, 1e-3, 0.0), std::domain_error);
  EXPECT_NO_THROW(cp::validate(cp::Params<double>{1e-3, 2e-3, 36.0, INFINITY, 0.0}));
}
