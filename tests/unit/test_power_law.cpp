// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the power-law loading/unloading hysteresis: the closed forms of e, t_c, the
// largest and the residual overlap (independent formulas written out here), equality with
// Walton-Braun for p = 1, q = 0, the dissipated energy along a prescribed path, the reload path,
// the elastic range below the plastic threshold, no negative force, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "collision/head_on.h"
#include "contact/normal/power_law_hysteresis.h"
#include "contact/normal/walton_braun.h"

namespace pl = tdem::power_law;

namespace {

double F(const pl::Params<double>& p, double xi, double* hist, bool update = true) {
  return pl::force(p, tdem::NormalKinematics<double>{xi, 0.0, 1.0, 1.0}, hist, update).force;
}

tdem::collision::Result impact(const pl::Params<double>& p, double m, double v0) {
  tdem::collision::PowerLawLaw law;
  law.p = p;
  tdem::collision::Bodies b;
  b.m1 = m;
  tdem::collision::Options o;
  o.steps_per_contact = 8000;
  return tdem::collision::integrate(law, b, v0, o);
}

// int_0^1 (1 - x^(a+1))^(-1/2) dx with 1 - x = t^2, which removes the end-point singularity:
// = int_0^1 2 t (1 - x^(a+1))^(-1/2) dt, a smooth integrand; midpoint rule.
double shape_quadrature(double a) {
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    const double one_minus = -std::expm1((a + 1.0) * std::log1p(-t * t));  // 1 - x^(a+1)
    sum += 2.0 * t / std::sqrt(one_minus);
  }
  return sum / n;
}

}  // namespace

TEST(PowerLaw, ShapeIntegralMatchesQuadrature) {
  for (double a : {1.0, 1.5, 2.0, 0.7}) EXPECT_NEAR(pl::shape_integral(a), shape_quadrature(a), 1e-6) << a;
  EXPECT_NEAR(pl::shape_integral(1.0), M_PI / 2.0, 1e-14);
}

TEST(PowerLaw, LinearCaseIsWaltonBraun) {
  const pl::Params<double> p{1e5, 1.0, 4e5, 0.0};
  const auto wbp = tdem::walton_braun::constant(1e5, 4e5);
  double h1[pl::history_size] = {0.0, 0.0}, h2[1] = {0.0};
  for (double xi : {1e-4, 3e-4, 5e-4, 4.5e-4, 3e-4, 4e-4, 6e-4, 2e-4, 1e-4}) {
    const double a = F(p, xi, h1);
    const double b = tdem::walton_braun::force(wbp, tdem::NormalKinematics<double>{xi, 0.0, 1.0, 1.0}, h2, true).force;
    EXPECT_NEAR(a, b, 1e-9 * std::abs(b) + 1e-12) << xi;
  }
}

TEST(PowerLaw, ImpactMatchesClosedForms) {
  const double m = 0.01;
  for (const auto& p : {pl::Params<double>{2e8, 1.5, 8e8, 0.0}, pl::Params<double>{2e8, 1.5, 5e10, 0.5},
                        pl::Params<double>{1e6, 1.2, 2e7, 0.1}}) {
    for (double v0 : {0.2, 1.0, 3.0}) {
      const double n = p.p + p.q;
      const double xm = std::pow((p.p + 1.0) * m * v0 * v0 / (2.0 * p.a_load), 1.0 / (p.p + 1.0));
      const double fmax = p.a_load * std::pow(xm, p.p);
      const double d = std::pow(fmax / p.a_unload, 1.0 / n);
      ASSERT_LT(d, xm) << "choose parameters above the plastic threshold";
      // Energies: W_load = F_max xm/(p+1), W_unload = F_max d/(n+1).
      const double e = std::sqrt((fmax * d / (n + 1.0)) / (fmax * xm / (p.p + 1.0)));
      const double tc = xm / v0 * shape_quadrature(p.p) + d / (e * v0) * shape_quadrature(n);
      const auto r = impact(p, m, v0);
      ASSERT_TRUE(r.ended);
      EXPECT_NEAR(r.restitution, e, 1e-7) << "v0 " << v0;
      EXPECT_NEAR(r.contact_time / tc, 1.0, 1e-5) << "v0 " << v0;
      EXPECT_NEAR(r.max_overlap / xm, 1.0, 1e-9);
      EXPECT_NEAR(r.residual_overlap / (xm - d), 1.0, 1e-6);
      EXPECT_NEAR(r.dissipated_energy, 0.5 * m * v0 * v0 * (1.0 - e * e), 1e-6 * 0.5 * m * v0 * v0);
      EXPECT_NEAR(pl::restitution(p, m, v0), e, 1e-12);
      EXPECT_NEAR(pl::contact_time(p, m, v0) / tc, 1.0, 1e-6);
    }
  }
}

TEST(PowerLaw, RestitutionWithoutExtraExponentIsVelocityIndependent) {
  const auto p = pl::from_restitution(3e8, 1.5, 0.7);
  for (double v0 : {0.01, 1.0, 10.0}) EXPECT_NEAR(impact(p, 0.01, v0).restitution, 0.7, 1e-7);
}

TEST(PowerLaw, ElasticBelowThePlasticThreshold) {
  // q > 0: xi_f < 0 while xi_max^q < a_l / a_ul = 1e-3, i.e. xi_max < 1e-6 m.
  const pl::Params<double> p{1e9, 1.5, 1e12, 1.0};
  const double m = 1e-3;
  const double v_slow = 0.5 * std::sqrt(2.0 * p.a_load * std::pow(1e-6, 2.5) / (2.5 * m));
  const auto r = impact(p, m, v_slow);
  EXPECT_NEAR(r.restitution, 1.0, 1e-9);
  EXPECT_EQ(pl::restitution(p, m, v_slow), 1.0);
}

TEST(PowerLaw, DissipationAlongAPrescribedPathAndReload) {
  const pl::Params<double> p{2e8, 1.5, 5e10, 0.5};
  double hist[pl::history_size] = {0.0, 0.0};
  auto work = [&](double from, double to) {
    const int n = 400000;
    double w = 0.0, f0 = F(p, from, hist);
    for (int i = 1; i <= n; ++i) {
      const double f1 = F(p, from + (to - from) * i / n, hist);
      w += 0.5 * (f0 + f1) * (to - from) / n;
      f0 = f1;
    }
    return w;
  };
  const double xm = 1e-4;
  const double w_in = work(0.0, xm);
  EXPECT_NEAR(w_in, p.a_load * std::pow(xm, 2.5) / 2.5, 1e-6 * w_in);
  // Unload half way and reload: the same curve (no energy change), then continue loading.
  const double d = std::pow(p.a_load * std::pow(xm, 1.5) / p.a_unload, 1.0 / 2.0);
  const double w_half = work(xm, xm - 0.5 * d);
  const double w_back = work(xm - 0.5 * d, xm);
  EXPECT_NEAR(w_half + w_back, 0.0, 1e-7 * w_in);
  EXPECT_EQ(hist[0], xm);
  work(xm, 1.2 * xm);
  EXPECT_EQ(hist[0], 1.2 * xm);
  // Full unload: returned energy is F_max d/(n+1) of the new maximum.
  const double xm2 = 1.2 * xm, fmax2 = p.a_load * std::pow(xm2, 1.5);
  const double d2 = std::pow(fmax2 / p.a_unload, 1.0 / 2.0);
  EXPECT_NEAR(-work(xm2, 0.0), fmax2 * d2 / 3.0, 1e-5 * fmax2 * d2);
}

TEST(PowerLaw, ForceIsNeverNegativeOnARandomPath) {
  const pl::Params<double> p{2e8, 1.5, 5e10, 0.5};
  double hist[pl::history_size] = {0.0, 0.0};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 2e-4);
  for (int i = 0; i < 100000; ++i) {
    const double f = F(p, u(rng), hist);
    ASSERT_GE(f, 0.0);
    ASSERT_TRUE(std::isfinite(f));
  }
}

TEST(PowerLaw, RejectsBadParameters) {
  EXPECT_THROW(pl::validate({0.0, 1.5, 1.0, 0.0}), std::domain_error);
  EXPECT_THROW(pl::validate({1.0, -1.0, 1.0, 0.0}), std::domain_error);
  EXPECT_THROW(pl::validate({1.0, 1.5, 0.0, 0.0}), std::domain_error);
  EXPECT_THROW(pl::validate({1.0, 1.5, 1.0, -0.1}), std::domain_error);
  EXPECT_THROW(pl::from_restitution(1.0, 1.5, 1.5), std::domain_error);
}
