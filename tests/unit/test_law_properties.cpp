// SPDX-License-Identifier: GPL-2.0-or-later
// Properties every normal law must have, checked across the laws:
//  * with damping off the collision conserves energy: along the recorded trajectory
//    1/2 m* xi'^2 + U(xi) stays at 1/2 m* v0^2 (U written out here for each elastic law), e = 1;
//  * a law that forbids attraction (ContactEnd::zero_force, and the hysteretic laws) never returns
//    a negative force, for random overlaps and overlap rates, with the history evolving.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "collision/head_on.h"

using namespace tdem;
using tdem::collision::Bodies;

namespace {

template <class Law>
double energy_drift(Law& law, const std::function<double(double)>& potential, double meff, double v0) {
  Bodies b;
  b.m1 = meff;
  collision::Options o;
  o.steps_per_contact = 4000;
  o.record = true;
  const auto r = collision::integrate(law, b, v0, o);
  EXPECT_TRUE(r.ended);
  EXPECT_NEAR(r.restitution, 1.0, 1e-10);
  const double e0 = 0.5 * meff * v0 * v0;
  double worst = 0.0;
  for (const auto& s : r.samples)
    worst = std::max(worst, std::abs(0.5 * meff * s.xi_dot * s.xi_dot + potential(s.xi) - e0) / e0);
  return worst;
}

}  // namespace

TEST(LawProperties, UndampedLinearConservesEnergy) {
  collision::LsdLaw law;
  law.c = {1e5, 0.0};
  EXPECT_LT(energy_drift(law, [](double x) { return 0.5 * 1e5 * x * x; }, 0.01, 1.0), 1e-11);
}

TEST(LawProperties, UndampedHertzConservesEnergy) {
  collision::HertzLaw law;
  law.p = {1e9, 0.0, 0.0};
  EXPECT_LT(energy_drift(law, [](double x) { return 0.4 * 1e9 * std::pow(x, 2.5); }, 1e-3, 1.0), 1e-10);
}

TEST(LawProperties, ExtendedLinearWithUnitRestitutionConservesEnergy) {
  collision::ExtendedLinearLaw law;
  law.p.e_fit.form = fits::Form::constant;
  law.p.e_fit.c[0] = 1.0;
  law.p.tc_fit.form = fits::Form::power;
  law.p.tc_fit.c[0] = 1e-4, law.p.tc_fit.c[1] = 0.2;
  const double m = 0.01, v0 = 2.0, tc = 1e-4 * std::pow(v0, -0.2);
  const double k = m * M_PI * M_PI / (tc * tc);  // independent: e = 1 -> k = m* pi^2 / t_c^2
  EXPECT_LT(energy_drift(law, [&](double x) { return 0.5 * k * x * x; }, m, v0), 1e-10);
}

TEST(LawProperties, PowerLawBelowThresholdIsElasticAndConservesEnergy) {
  collision::PowerLawLaw law;
  law.p = {1e9, 1.5, 1e12, 1.0};  // elastic while xi_max < 1e-6 m
  const double m = 1e-3, v0 = 0.5 * std::sqrt(2.0 * 1e9 * std::pow(1e-6, 2.5) / (2.5 * m));
  EXPECT_LT(energy_drift(law, [](double x) { return 1e9 * std::pow(x, 2.5) / 2.5; }, m, v0), 1e-10);
}

TEST(LawProperties, NoAttractionLawsNeverPull) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> xi(0.0, 1e-4), rate(-5.0, 5.0);
  const double m = 0.01, R = 0.005;
  hertz::Params<double> hp{1e9, 50.0, 0.3};
  walton_braun::Params<double> wb{1e5, 2e5, 10.0};
  thornton::Params<double> th{1e9, 5e7};
  power_law::Params<double> pl{1e9, 1.5, 1e11, 0.4};
  extended::LinearParams el;
  el.e_fit.form = fits::Form::rational;
  el.e_fit.c[0] = 0.9, el.e_fit.c[1] = 1.0, el.e_fit.c[2] = 0.6;
  el.tc_fit.form = fits::Form::constant;
  el.tc_fit.c[0] = 1e-4;
  extended::HertzParams eh{1e9, el.e_fit, fits::Range{}};
  double h_wb[1] = {0}, h_th[2] = {0, 0}, h_pl[2] = {0, 0}, h_el[3] = {0, 0, 0}, h_eh[2] = {0, 0};
  for (int i = 0; i < 200000; ++i) {
    if (i % 1000 == 0) {  // a new contact now and then
      h_el[0] = h_el[1] = h_el[2] = 0.0;
      h_eh[0] = h_eh[1] = 0.0;
    }
    const NormalKinematics<double> k{xi(rng), rate(rng), m, R};
    ASSERT_GE((lsd::force<ContactEnd::zero_force>(lsd::Coefficients<double>{1e5, 20.0}, k).force), 0.0);
    for (auto d : {hertz::Damping::linear, hertz::Damping::kuwabara_kono, hertz::Damping::tsuji,
                   hertz::Damping::general})
      ASSERT_GE(hertz::force(d, ContactEnd::zero_force, hp, k).force, 0.0);
    ASSERT_GE(walton_braun::force(wb, k, h_wb, true).force, 0.0);
    ASSERT_GE(thornton::force(th, k, h_th, true).force, 0.0);
    ASSERT_GE(power_law::force(pl, k, h_pl, true).force, 0.0);
    ASSERT_GE(extended::linear_force<ContactEnd::zero_force>(el, k, h_el, true).force, 0.0);
    ASSERT_GE(extended::hertz_force<ContactEnd::zero_force>(eh, k, h_eh, true).force, 0.0);
  }
}
