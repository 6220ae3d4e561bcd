// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of Thornton's elastic-perfectly-plastic law: an independent RK4 integration of
// the kernel against the closed-form e(v0) of physics_reference.md 2.2.4 (typed here from the
// text), e = 1 below the yield velocity, the shape of the loading/unloading/reloading curves,
// the dissipated energy, parameter round trips and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/normal/thornton.h"
#include "single_collision.h"

namespace th = tdem::thornton;

namespace {

// Steel-like sphere on a wall: R = 5 mm, rho = 7850, E* = 1.153846e11 Pa, p_y = 1.5 GPa.
constexpr double kR = 5e-3, kRho = 7850.0;
const th::Params<double> kSteel{1.153846e11, 1.5e9};
double sphere_mass() { return 4.0 / 3.0 * M_PI * kR * kR * kR * kRho; }

// Independent of the kernel's helpers: yield point from the text, v_y from 1/2 m v_y^2 = int F dxi.
double yield_overlap_text(const th::Params<double>& p, double R) {
  return R * std::pow(M_PI * p.p_y / (2.0 * p.e_star), 2);
}
double yield_velocity_text(const th::Params<double>& p, double R, double m) {
  const double k = 4.0 / 3.0 * p.e_star * std::sqrt(R);
  return std::sqrt(2.0 * (0.4 * k * std::pow(yield_overlap_text(p, R), 2.5)) / m);
}
// physics_reference.md 2.2.4, r = v_y / v0.
double thornton_e_text(double r) {
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0 * (1.0 - r * r / 6.0)) *
         std::pow(r / (r + 2.0 * std::sqrt(6.0 / 5.0 - r * r / 5.0)), 0.25);
}

struct Impact {
  tdem::testing::CollisionOutcome out;
  double hist[th::history_size];
};

Impact simulate(const th::Params<double>& p, double R, double m, double v0, int steps = 20000) {
  Impact r{};
  double* hist = r.hist;
  auto force = [&](double xi, double xidot) {
    if (xi <= 0.0) return 0.0;
    return th::force(p, tdem::NormalKinematics<double>{xi, xidot, m, R}, hist, true).force;
  };
  auto ends = [&](double xi, double) { return xi - th::zero_force_overlap(p, R, hist); };
  const double k = 4.0 / 3.0 * p.e_star * std::sqrt(R);
  const double tc = 3.2 * std::pow(m / k, 0.4) * std::pow(v0, -0.2);  // step size only
  r.out = tdem::testing::integrate_collision(force, ends, m, v0, tc / steps, 100.0 * tc);
  return r;
}

double kernel_force(const th::Params<double>& p, double R, double xi, double* hist, bool update = true) {
  return th::force(p, tdem::NormalKinematics<double>{xi, 0.0, 1.0, R}, hist, update).force;
}

}  // namespace

TEST(Thornton, YieldVelocity) {
  const double m = sphere_mass();
  const double vy = yield_velocity_text(kSteel, kR, m);
  EXPECT_NEAR(th::yield_velocity(kSteel, kR, m), vy, 1e-12 * vy);
  EXPECT_NEAR(th::yield_velocity_sphere_on_wall(kSteel, kRho), vy, 1e-12 * vy);
  // The literature's 1.56 is pi^2/sqrt(40) = 1.5605 rounded.
  EXPECT_NEAR(vy / std::sqrt(std::pow(kSteel.p_y, 5) / (std::pow(kSteel.e_star, 4) * kRho)), 1.56, 1e-3);
  EXPECT_NEAR(th::yield_overlap(kSteel, kR), yield_overlap_text(kSteel, kR), 1e-20);
}

TEST(Thornton, IntegrationReproducesClosedFormAboveYield) {
  const double m = sphere_mass();
  const double vy = yield_velocity_text(kSteel, kR, m);
  double prev = 1.0;
  for (double ratio : {1.2, 2.0, 5.0, 20.0, 100.0}) {
    const double v0 = ratio * vy;
    const Impact r = simulate(kSteel, kR, m, v0);
    const double e_text = thornton_e_text(1.0 / ratio);
    EXPECT_NEAR(r.out.restitution, e_text, 1e-6) << "v0/v_y=" << ratio;
    EXPECT_NEAR(th::restitution(kSteel, kR, m, v0), e_text, 1e-13) << ratio;
    EXPECT_NEAR(r.out.max_overlap, th::max_overlap(kSteel, kR, m, v0), 1e-7 * r.out.max_overlap) << ratio;
    EXPECT_LT(r.out.restitution, prev);
    prev = r.out.restitution;
    // History after the impact: the peak of the loading curve.
    EXPECT_NEAR(r.hist[th::xi_max_slot], r.out.max_overlap, 1e-7 * r.out.max_overlap);
  }
  // High-velocity trend e ~ v0^(-1/4).
  EXPECT_NEAR(std::log(thornton_e_text(1e-6) / thornton_e_text(1e-5)) / std::log(10.0), -0.25, 1e-3);
}

TEST(Thornton, ElasticBelowYield) {
  const double m = sphere_mass();
  const double vy = yield_velocity_text(kSteel, kR, m);
  const double k = 4.0 / 3.0 * kSteel.e_star * std::sqrt(kR);
  for (double ratio : {0.1, 0.5, 0.99}) {
    const double v0 = ratio * vy;
    const Impact r = simulate(kSteel, kR, m, v0);
    EXPECT_NEAR(r.out.restitution, 1.0, 1e-8) << ratio;
    EXPECT_NEAR(r.out.max_overlap, std::pow(5.0 * m * v0 * v0 / (4.0 * k), 0.4), 1e-7 * r.out.max_overlap);
    EXPECT_EQ(th::restitution(kSteel, kR, m, v0), 1.0);
  }
}

TEST(Thornton, LoadUnloadReloadCurves) {
  const double R = 2e-3;
  const th::Params<double> p{7e10, 8e8};
  const double xi_y = yield_overlap_text(p, R);
  const double k = 4.0 / 3.0 * p.e_star * std::sqrt(R);
  const double fy = k * std::pow(xi_y, 1.5);
  EXPECT_NEAR(fy, 2.0 / 3.0 * M_PI * p.p_y * R * xi_y, 1e-12 * fy);
  double hist[2] = {0.0, 0.0};
  // Below yield: Hertz; slope 2 E* a.
  auto r = th::force(p, tdem::NormalKinematics<double>{0.5 * xi_y, 0.0, 1.0, R}, hist, true);
  EXPECT_NEAR(r.force, k * std::pow(0.5 * xi_y, 1.5), 1e-12 * r.force);
  EXPECT_NEAR(r.stiffness, 2.0 * p.e_star * std::sqrt(R * 0.5 * xi_y), 1e-12 * r.stiffness);
  // Elastic unloading below yield follows the loading curve.
  EXPECT_NEAR(kernel_force(p, R, 0.25 * xi_y, hist), k * std::pow(0.25 * xi_y, 1.5), 1e-12 * fy);
  // Slope continuous at the yield point, then linear with slope pi p_y R*.
  const double eps = 1e-9 * xi_y;
  double h0[2] = {0, 0}, h1[2] = {0, 0};
  const auto below = th::force(p, tdem::NormalKinematics<double>{xi_y - eps, 0.0, 1.0, R}, h0, true);
  const auto above = th::force(p, tdem::NormalKinematics<double>{xi_y + eps, 0.0, 1.0, R}, h1, true);
  EXPECT_NEAR(below.stiffness, above.stiffness, 1e-6 * above.stiffness);
  EXPECT_NEAR(above.stiffness, M_PI * p.p_y * R, 1e-12 * above.stiffness);
  EXPECT_NEAR(above.force, below.force, 1e-6 * fy);
  // Plastic loading to xi_max = 6 xi_y.
  const double xm = 6.0 * xi_y;
  const double fm = fy + M_PI * p.p_y * R * (xm - xi_y);
  EXPECT_NEAR(kernel_force(p, R, xm, hist), fm, 1e-12 * fm);
  EXPECT_DOUBLE_EQ(hist[th::xi_max_slot], xm);
  EXPECT_NEAR(hist[th::f_max_slot], fm, 1e-12 * fm);
  // Unloading: Hertz with R_p = 4 E* a_p^3 / (3 F_max), xi_res = xi_max - a_p^2 / R_p.
  const double ap = std::sqrt(R * xm), Rp = 4.0 * p.e_star * ap * ap * ap / (3.0 * fm);
  const double xres = xm - ap * ap / Rp;
  EXPECT_GT(Rp, R);
  EXPECT_NEAR(th::zero_force_overlap(p, R, hist), xres, 1e-12 * xm);
  for (double x : {0.99 * xm, 0.5 * (xm + xres), xres + 0.01 * (xm - xres)}) {
    const double fu = 4.0 / 3.0 * p.e_star * std::sqrt(Rp) * std::pow(x - xres, 1.5);
    EXPECT_NEAR(kernel_force(p, R, x, hist), fu, 1e-10 * fm) << x / xm;
    EXPECT_LT(fu, fy + M_PI * p.p_y * R * (x - xi_y) + 1e-9 * fm);  // below the loading curve
  }
  EXPECT_EQ(kernel_force(p, R, 0.999 * xres, hist), 0.0);
  EXPECT_DOUBLE_EQ(hist[th::xi_max_slot], xm);
  // Reload: up the unloading curve to (xi_max, F_max), then on the loading line again.
  EXPECT_NEAR(kernel_force(p, R, xm, hist), fm, 1e-10 * fm);
  const double x2 = 8.0 * xi_y;
  EXPECT_NEAR(kernel_force(p, R, x2, hist, false), fy + M_PI * p.p_y * R * (x2 - xi_y), 1e-10 * fm);
  EXPECT_DOUBLE_EQ(hist[th::xi_max_slot], xm);  // set-up pass: no change
  kernel_force(p, R, x2, hist, true);
  EXPECT_DOUBLE_EQ(hist[th::xi_max_slot], x2);
  EXPECT_GT(th::zero_force_overlap(p, R, hist), xres);
  EXPECT_FALSE(th::history[0].flips_sign);
  EXPECT_FALSE(th::history[1].flips_sign);
  // float instantiation agrees with double.
  float hf[2] = {0.0f, 0.0f};
  const float ff = th::force(th::Params<float>{7e10f, 8e8f}, tdem::NormalKinematics<float>{float(xm), 0.0f, 1.0f, float(R)}, hf, true).force;
  EXPECT_NEAR(ff, fm, 1e-5 * fm);
}

TEST(Thornton, DissipatedEnergy) {
  // Work along a prescribed load/unload path equals 1/2 m v0^2 (1 - e^2) with the closed-form e.
  const double m = sphere_mass();
  const double vy = yield_velocity_text(kSteel, kR, m);
  for (double ratio : {1.5, 10.0}) {
    const double v0 = ratio * vy;
    const double xm = th::max_overlap(kSteel, kR, m, v0);
    double hist[2] = {0.0, 0.0};
    const int n = 400000;
    double w_in = 0.0, w_out = 0.0, f0 = 0.0;
    for (int i = 1; i <= n; ++i) {
      const double f1 = kernel_force(kSteel, kR, xm * i / n, hist);
      w_in += 0.5 * (f0 + f1) * xm / n;
      f0 = f1;
    }
    for (int i = n - 1; i >= 0; --i) {
      const double f1 = kernel_force(kSteel, kR, xm * i / n, hist);
      w_out += 0.5 * (f0 + f1) * xm / n;
      f0 = f1;
    }
    const double e = thornton_e_text(1.0 / ratio);
    EXPECT_NEAR(w_in, 0.5 * m * v0 * v0, 1e-8 * w_in) << ratio;
    EXPECT_NEAR(w_in - w_out, 0.5 * m * v0 * v0 * (1.0 - e * e), 1e-7 * w_in) << ratio;
  }
}

TEST(Thornton, ParameterRoundTrips) {
  const double m = sphere_mass();
  for (double e : {0.95, 0.8, 0.6, 0.4}) {
    const double v0 = 3.0;
    const double py = th::yield_pressure_from_restitution(e, v0, kSteel.e_star, kR, m);
    EXPECT_NEAR(th::restitution(th::Params<double>{kSteel.e_star, py}, kR, m, v0), e, 1e-12) << e;
    EXPECT_NEAR(th::restitution_from_velocity_ratio(th::velocity_ratio_from_restitution(e)), e, 1e-14);
  }
  const double vy = th::yield_velocity(kSteel, kR, m);
  EXPECT_NEAR(th::yield_pressure_from_yield_velocity(vy, kSteel.e_star, kR, m), kSteel.p_y, 1e-12 * kSteel.p_y);
  EXPECT_EQ(th::restitution_from_velocity_ratio(1.0), 1.0);
  EXPECT_NEAR(th::restitution_from_velocity_ratio(1.0 - 1e-12), 1.0, 1e-6);  // continuous at v_y
}

TEST(Thornton, BadInputIsRejected) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::domain_error& ex) {
      return std::string(ex.what());
    }
    return std::string("no exception");
  };
  std::string msg = message([] { th::validate(th::Params<double>{1e11, -3e8}); });
  EXPECT_NE(msg.find("limiting contact pressure p_y = -300000000"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, inf)"), std::string::npos) << msg;
  msg = message([] { th::yield_velocity(th::Params<double>{1e11, 1e9}, 0.0, 0.01); });
  EXPECT_NE(msg.find("effective radius R* = 0"), std::string::npos) << msg;
  EXPECT_THROW(th::restitution(kSteel, kR, 0.01, -1.0), std::domain_error);
  EXPECT_THROW(th::yield_pressure_from_restitution(1.0, 1.0, 1e11, 1e-3, 1e-3), std::domain_error);
  EXPECT_THROW(th::yield_pressure_from_restitution(1.3, 1.0, 1e11, 1e-3, 1e-3), std::domain_error);
  EXPECT_THROW(th::validate(th::Params<double>{NAN, 1e9}), std::domain_error);
}
