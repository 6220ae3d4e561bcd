// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the Hertz + damping family: the elastic closed forms against the steel-sphere
// table of physics_reference.md 8.2 and against an independent RK4 integration of the kernel,
// Tsuji's alpha -> e table (both end-of-contact conventions) and the alpha(e) round trip,
// the velocity dependence of e for the different damping exponents (section 8.4), force values
// at touch (section 8.8), parameter conversions and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/normal/hertz_damped.h"
#include "single_collision.h"

using tdem::ContactEnd;
namespace hertz = tdem::hertz;
using hertz::Damping;

namespace {

// Steel sphere R = 5 mm, rho = 7850, E = 210 GPa, nu = 0.3 on a steel half-space (section 8.2).
constexpr double kR = 5e-3, kRho = 7850.0, kE = 210e9, kNu = 0.3;

double steel_mass() { return 4.0 / 3.0 * M_PI * kR * kR * kR * kRho; }
double steel_k() {
  return hertz::stiffness(hertz::effective_modulus(kE, kNu, kE, kNu), hertz::effective_radius(kR, INFINITY));
}

// Contact time estimate for the step size only: t ~ 3.2 (m/k)^(2/5) v0^(-1/5).
double tc_estimate(double k, double m, double v0) { return 3.2 * std::pow(m / k, 0.4) * std::pow(v0, -0.2); }

tdem::testing::CollisionOutcome simulate(Damping d, ContactEnd end, const hertz::Params<double>& p,
                                         double meff, double v0, int steps = 20000) {
  auto raw = [&](double xi, double xidot) {
    // RK4 stages of the last step may look just past xi = 0: free flight there.
    if (xi <= 0.0) return 0.0;
    return hertz::force(d, ContactEnd::zero_overlap, p, tdem::NormalKinematics<double>{xi, xidot, meff, 1.0}).force;
  };
  auto force = [&](double xi, double xidot) {
    if (xi <= 0.0) return 0.0;
    return hertz::force(d, end, p, tdem::NormalKinematics<double>{xi, xidot, meff, 1.0}).force;
  };
  auto ends = [&](double xi, double xidot) {
    if (end == ContactEnd::zero_overlap) return xi;
    return raw(xi, xidot);  // unclipped force reaches zero
  };
  const double tc = tc_estimate(p.k, meff, v0);
  return tdem::testing::integrate_collision(force, ends, meff, v0, tc / steps, 100.0 * tc);
}

// 2 int_0^1 (1 - x^(5/2))^(-1/2) dx with x = 1 - s^2 (removes the end-point singularity), Simpson.
double hertz_time_constant_numerically() {
  auto g = [](double s) {
    if (s == 0.0) return 2.0 / std::sqrt(2.5);
    const double x = 1.0 - s * s;
    return 2.0 * s / std::sqrt(1.0 - std::pow(x, 2.5));
  };
  const int n = 200000;
  const double h = 1.0 / n;
  double sum = g(0.0) + g(1.0);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(i * h);
  return 2.0 * sum * h / 3.0;
}

}  // namespace

TEST(HertzDamped, PairQuantitiesOfTheSteelSphere) {
  EXPECT_NEAR(hertz::effective_modulus(kE, kNu, kE, kNu), 1.153846e11, 1e-6 * 1.153846e11);
  EXPECT_NEAR(steel_mass(), 4.110250e-3, 1e-6 * 4.110250e-3);
  EXPECT_NEAR(steel_k(), 1.087857e10, 1e-6 * 1.087857e10);
  // Wall = infinite radius and mass; a rigid partner = infinite modulus.
  EXPECT_DOUBLE_EQ(hertz::effective_radius(2e-3, 2e-3), 1e-3);
  EXPECT_DOUBLE_EQ(hertz::effective_mass(0.3, INFINITY), 0.3);
  EXPECT_DOUBLE_EQ(hertz::effective_mass(0.3, 0.6), 0.2);
  EXPECT_DOUBLE_EQ(hertz::effective_modulus(kE, kNu, INFINITY, 0.2), kE / (1.0 - kNu * kNu));
  // Round trip k~ <-> E*.
  const double es = hertz::effective_modulus(7e7, 0.25, 3e8, 0.4);
  EXPECT_NEAR(hertz::effective_modulus_from_stiffness(hertz::stiffness(es, 1.3e-3), 1.3e-3), es, 1e-12 * es);
}

TEST(HertzDamped, TimeConstantMatchesQuadrature) {
  const double c = hertz_time_constant_numerically();
  EXPECT_NEAR(c, 2.94328, 5e-6);
  EXPECT_NEAR(hertz::contact_time_constant(), c, 1e-9);
}

TEST(HertzDamped, ElasticImpactMatchesSteelTable) {
  // physics_reference.md 8.2: v0, xi_max, t_c.
  const double table[3][3] = {{0.1, 1.860727e-6, 5.4766e-5}, {1.0, 1.174039e-5, 3.4555e-5}, {10.0, 7.407688e-5, 2.1803e-5}};
  const double m = steel_mass(), k = steel_k();
  const double C = hertz_time_constant_numerically();
  const hertz::Params<double> p{k, 0.0, 0.0};
  for (const auto& row : table) {
    const double v0 = row[0];
    // Closed forms (xi_max typed from the text, t_c with the constant from the quadrature above).
    const double xi_cf = std::pow(5.0 * m * v0 * v0 / (4.0 * k), 0.4);
    EXPECT_NEAR(xi_cf, row[1], 1e-6 * row[1]) << v0;
    EXPECT_NEAR(C * xi_cf / v0, row[2], 1e-5 * row[2]) << v0;
    EXPECT_NEAR(hertz::max_overlap_elastic(k, m, v0), xi_cf, 1e-12 * xi_cf);
    EXPECT_NEAR(hertz::contact_time_elastic(k, m, v0), C * xi_cf / v0, 1e-9 * row[2]);
    // Integration of the kernel, both conventions (identical without damping).
    for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
      const auto sim = simulate(Damping::linear, end, p, m, v0, 40000);
      EXPECT_NEAR(sim.max_overlap, row[1], 1e-6 * row[1]) << v0;
      EXPECT_NEAR(sim.contact_time, row[2], 1e-5 * row[2]) << v0;
      EXPECT_NEAR(sim.contact_time, C * xi_cf / v0, 1e-7 * sim.contact_time) << v0;
      EXPECT_NEAR(sim.restitution, 1.0, 1e-8) << v0;
    }
  }
}

TEST(HertzDamped, TsujiTableBothConventions) {
  // physics_reference.md 8.2: alpha, e (F = 0 end), e (xi = 0 end); independent of v0.
  const double table[8][3] = {{0.05, 0.93308, 0.93215}, {0.1, 0.87229, 0.86880}, {0.2, 0.76641, 0.75418},
                              {0.3, 0.67780, 0.65355},  {0.5, 0.53942, 0.48640}, {0.75, 0.41688, 0.32676},
                              {1.0, 0.33050, 0.20788},  {1.5, 0.22059, 0.05833}};
  const double m = steel_mass(), k = steel_k();
  for (const auto& row : table) {
    const hertz::Params<double> p{k, row[0], 0.0};
    for (double v0 : {1.0, 5.0}) {
      const auto zf = simulate(Damping::tsuji, ContactEnd::zero_force, p, m, v0, 40000);
      const auto zo = simulate(Damping::tsuji, ContactEnd::zero_overlap, p, m, v0, 40000);
      // The exact map onto the linear law (closed form), to integrator accuracy.
      EXPECT_NEAR(zf.restitution, hertz::tsuji_restitution(row[0], ContactEnd::zero_force), 1e-6);
      EXPECT_NEAR(zo.restitution, hertz::tsuji_restitution(row[0], ContactEnd::zero_overlap), 1e-6);
      EXPECT_NEAR(zf.restitution, row[1], 6e-6) << "alpha=" << row[0] << " v0=" << v0;
      EXPECT_NEAR(zo.restitution, row[2], 6e-6) << "alpha=" << row[0] << " v0=" << v0;
    }
    EXPECT_NEAR(hertz::tsuji_restitution(row[0], ContactEnd::zero_force), row[1], 6e-6) << row[0];
    EXPECT_NEAR(hertz::tsuji_restitution(row[0], ContactEnd::zero_overlap), row[2], 6e-6) << row[0];
  }
}

TEST(HertzDamped, TsujiAlphaFromRestitutionRoundTrip) {
  // Section 8.2 values of the zero_overlap closed form.
  EXPECT_NEAR(hertz::tsuji_alpha_from_restitution(0.5, ContactEnd::zero_overlap), 0.481769, 6e-7);
  EXPECT_NEAR(hertz::tsuji_alpha_from_restitution(0.9, ContactEnd::zero_overlap), 0.074950, 6e-7);
  EXPECT_NEAR(hertz::tsuji_alpha_from_restitution(0.98, ContactEnd::zero_overlap), 0.014379, 6e-7);
  for (double e : {0.5, 0.9}) {
    const double le = std::log(e);
    EXPECT_NEAR(hertz::tsuji_alpha_zero_overlap(le), -std::sqrt(5.0) * le / std::sqrt(le * le + M_PI * M_PI), 1e-15);
  }
  const double m = 2.3e-4, k = 3.1e8;
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    for (double e : {0.99, 0.9, 0.7, 0.5, 0.3, 0.15}) {
      const double alpha = hertz::tsuji_alpha_from_restitution(e, end);
      const auto sim = simulate(Damping::tsuji, end, hertz::Params<double>{k, alpha, 0.0}, m, 0.7, 40000);
      EXPECT_NEAR(sim.restitution, e, 1e-6) << tdem::to_string(end) << " e=" << e;
      EXPECT_NEAR(hertz::tsuji_restitution(alpha, end), e, 1e-12);
    }
  }
}

TEST(HertzDamped, GeneralisedExponentLogSlope) {
  // Weak damping: d ln(1 - e) / d ln v0 = (4 Theta - 1)/5 (section 8.4).
  const double m = steel_mass(), k = steel_k();
  for (double theta : {0.0, 0.25, 0.5, 0.75}) {
    const double xi1 = std::pow(5.0 * m / (4.0 * k), 0.4);  // elastic xi_max at 1 m/s
    const double c = 0.004 * k * std::pow(xi1, 1.5 - theta);  // 1 - e ~ 1e-2
    const hertz::Params<double> p{k, c, theta};
    const double va = 0.8, vb = 1.25;
    const double ea = simulate(Damping::general, ContactEnd::zero_overlap, p, m, va).restitution;
    const double eb = simulate(Damping::general, ContactEnd::zero_overlap, p, m, vb).restitution;
    ASSERT_LT(ea, 0.999);
    ASSERT_GT(ea, 0.97);
    const double slope = std::log((1.0 - eb) / (1.0 - ea)) / std::log(vb / va);
    EXPECT_NEAR(slope, (4.0 * theta - 1.0) / 5.0, 0.01) << "Theta=" << theta;
  }
}

TEST(HertzDamped, KuwabaraKonoWeakDampingSeries) {
  // physics_reference.md 2.2.3: e = 1 - C1 b + C2 b^2 - ..., b = (gamma~/k~)(k~/m*)^(2/5) v0^(1/5),
  // C1 = 1.15344 (Ramirez et al. 1999; the text's own quadrature gives 1.15338), C2 ~ 0.8.
  // Richardson extrapolation of (1 - e)/b to b -> 0 from the integrated kernel, both conventions.
  const double k = 1e10, m = 4e-3, v0 = 1.3;
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
    double ratio[2];
    for (int i = 0; i < 2; ++i) {
      const double b = 1e-3 * (i + 1);
      const double gamma = b * k / (std::pow(k / m, 0.4) * std::pow(v0, 0.2));
      const double e = simulate(Damping::kuwabara_kono, end, hertz::Params<double>{k, gamma, 0.0}, m, v0).restitution;
      ratio[i] = (1.0 - e) / b;
    }
    const double c1 = 2.0 * ratio[0] - ratio[1];
    const double c2 = (ratio[0] - ratio[1]) / 1e-3;
    EXPECT_NEAR(c1, 1.15344, 1e-4) << tdem::to_string(end);
    EXPECT_NEAR(c2, 0.8, 0.05) << tdem::to_string(end);
  }
}

TEST(HertzDamped, VelocityDependenceOfRestitution) {
  const double m = steel_mass(), k = steel_k();
  // Kuwabara-Kono: e falls with v0. Hertz + linear damping: e rises with v0. Tsuji: constant.
  const hertz::Params<double> kk{k, 2e4, 0.0}, lin{k, 20.0, 0.0}, ts{k, 0.3, 0.0};
  double prev_kk = 2.0, prev_lin = -1.0;
  const double e_ts = simulate(Damping::tsuji, ContactEnd::zero_force, ts, m, 0.1).restitution;
  for (double v0 : {0.1, 1.0, 10.0}) {
    const double ekk = simulate(Damping::kuwabara_kono, ContactEnd::zero_force, kk, m, v0).restitution;
    const double elin = simulate(Damping::linear, ContactEnd::zero_force, lin, m, v0).restitution;
    EXPECT_LT(ekk, prev_kk) << v0;
    EXPECT_GT(elin, prev_lin) << v0;
    EXPECT_LT(ekk, 1.0);
    EXPECT_LT(elin, 1.0);
    EXPECT_NEAR(simulate(Damping::tsuji, ContactEnd::zero_force, ts, m, v0).restitution, e_ts, 1e-7) << v0;
    prev_kk = ekk;
    prev_lin = elin;
  }
}

TEST(HertzDamped, ForceAtTouchAndKernelValues) {
  const double k = 2e9, m = 0.01, v0 = 0.7;
  const tdem::NormalKinematics<double> touch{0.0, v0, m, 1e-3};
  // Section 8.8: Hertz + linear damping jumps to gamma v0; KK, Tsuji, Theta > 0 start at 0.
  EXPECT_DOUBLE_EQ((hertz::force<Damping::linear, ContactEnd::zero_overlap>(hertz::Params<double>{k, 3.0, 0.0}, touch).force), 3.0 * v0);
  EXPECT_EQ((hertz::force<Damping::kuwabara_kono, ContactEnd::zero_overlap>(hertz::Params<double>{k, 3e4, 0.0}, touch).force), 0.0);
  EXPECT_EQ((hertz::force<Damping::tsuji, ContactEnd::zero_overlap>(hertz::Params<double>{k, 0.4, 0.0}, touch).force), 0.0);
  EXPECT_EQ((hertz::force<Damping::general, ContactEnd::zero_overlap>(hertz::Params<double>{k, 3e4, 0.3}, touch).force), 0.0);
  EXPECT_DOUBLE_EQ((hertz::force<Damping::general, ContactEnd::zero_overlap>(hertz::Params<double>{k, 3.0, 0.0}, touch).force), 3.0 * v0);

  // Values at an overlap, written out from the formula.
  const double xi = 4e-6, xd = -0.3;
  const tdem::NormalKinematics<double> kin{xi, xd, m, 1e-3};
  const double el = k * std::pow(xi, 1.5);
  auto r = hertz::force<Damping::kuwabara_kono, ContactEnd::zero_overlap>(hertz::Params<double>{k, 5e4, 0.0}, kin);
  EXPECT_NEAR(r.elastic, el, 1e-14 * el);
  EXPECT_NEAR(r.force, el + 5e4 * std::sqrt(xi) * xd, 1e-12 * el);
  EXPECT_NEAR(r.stiffness, 1.5 * k * std::sqrt(xi), 1e-12 * r.stiffness);
  // Tangent stiffness = 2 E* a with a = sqrt(R* xi).
  const double es = 7e10, rr = 2e-3;
  r = hertz::force<Damping::linear, ContactEnd::zero_overlap>(hertz::Params<double>{hertz::stiffness(es, rr), 0.0, 0.0}, kin);
  EXPECT_NEAR(r.stiffness, 2.0 * es * std::sqrt(rr * xi), 1e-12 * r.stiffness);
  r = hertz::force<Damping::tsuji, ContactEnd::zero_overlap>(hertz::Params<double>{k, 0.4, 0.0}, kin);
  EXPECT_NEAR(r.damping, 0.4 * std::sqrt(m * k) * std::pow(xi, 0.25), 1e-12 * r.damping);
  // General Theta reproduces the named members.
  for (auto [d, th] : {std::pair{Damping::linear, 0.0}, std::pair{Damping::kuwabara_kono, 0.5}}) {
    const hertz::Params<double> p{k, 5e3, th};
    EXPECT_NEAR(hertz::force(d, ContactEnd::zero_overlap, p, kin).force,
                hertz::force(Damping::general, ContactEnd::zero_overlap, p, kin).force, 1e-12 * el);
  }
  // Strongly separating: attraction unless clipped.
  const tdem::NormalKinematics<double> sep{1e-9, -5.0, m, 1e-3};
  EXPECT_LT((hertz::force<Damping::kuwabara_kono, ContactEnd::zero_overlap>(hertz::Params<double>{k, 5e4, 0.0}, sep).force), 0.0);
  r = hertz::force<Damping::kuwabara_kono, ContactEnd::zero_force>(hertz::Params<double>{k, 5e4, 0.0}, sep);
  EXPECT_EQ(r.force, 0.0);
  EXPECT_GT(r.elastic, 0.0);
  // float instantiation compiles and agrees.
  const auto rf = hertz::force<Damping::tsuji, ContactEnd::zero_force>(hertz::Params<float>{2e9f, 0.4f, 0.0f},
                                                                       tdem::NormalKinematics<float>{4e-6f, -0.3f, 0.01f, 1e-3f});
  const auto rd = hertz::force<Damping::tsuji, ContactEnd::zero_force>(hertz::Params<double>{2e9, 0.4, 0.0}, kin);
  EXPECT_NEAR(rf.force, rd.force, 1e-5 * std::fabs(rd.elastic));
}

TEST(HertzDamped, ParameterRoundTrips) {
  for (double v0 : {0.05, 1.0, 20.0}) {
    const double m = 3e-3, tc = 4e-5;
    const double k = hertz::stiffness_from_contact_time(tc, m, v0);
    EXPECT_NEAR(hertz::contact_time_elastic(k, m, v0), tc, 1e-12 * tc) << v0;
  }
  EXPECT_NEAR(hertz::dissipative_time(hertz::kuwabara_kono_damping(2e-7, 3e9), 3e9), 2e-7, 1e-20);
  for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force})
    for (double e : {1.0, 0.95, 0.6, 0.2})
      EXPECT_NEAR(hertz::tsuji_restitution(hertz::tsuji_alpha_from_restitution(e, end), end), e, 1e-12);
  // The zero-force end reaches e < e^-2 (over-damped linear equivalent) as well.
  EXPECT_NEAR(hertz::tsuji_restitution(hertz::tsuji_alpha_from_restitution(0.05, ContactEnd::zero_force),
                                       ContactEnd::zero_force), 0.05, 1e-12);
  EXPECT_EQ(hertz::damping_exponent(Damping::tsuji), 0.25);
}

TEST(HertzDamped, BadInputIsRejected) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::domain_error& ex) {
      return std::string(ex.what());
    }
    return std::string("no exception");
  };
  std::string msg = message([] { hertz::effective_modulus(-2e9, 0.3, 2e9, 0.3); });
  EXPECT_NE(msg.find("Young's modulus E1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-2e+09"), std::string::npos) << msg;
  msg = message([] { hertz::effective_modulus(2e9, 0.7, 2e9, 0.3); });
  EXPECT_NE(msg.find("Poisson ratio"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0.7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(-1, 0.5]"), std::string::npos) << msg;
  EXPECT_THROW(hertz::effective_modulus(INFINITY, 0.3, INFINITY, 0.3), std::domain_error);
  EXPECT_THROW(hertz::effective_radius(0.0, 1.0), std::domain_error);
  EXPECT_THROW(hertz::effective_mass(1.0, -1.0), std::domain_error);
  msg = message([] { hertz::tsuji_alpha_from_restitution(1.2, ContactEnd::zero_force); });
  EXPECT_NE(msg.find("1.2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, 1]"), std::string::npos) << msg;
  EXPECT_THROW(hertz::tsuji_restitution(-0.1, ContactEnd::zero_force), std::domain_error);
  EXPECT_THROW(hertz::max_overlap_elastic(1e9, 0.01, 0.0), std::domain_error);
  EXPECT_THROW(hertz::stiffness_from_contact_time(-1e-5, 0.01, 1.0), std::domain_error);
  EXPECT_THROW(hertz::validate(Damping::general, hertz::Params<double>{1e9, 1.0, -0.5}), std::domain_error);
  EXPECT_THROW(hertz::validate(Damping::linear, hertz::Params<double>{NAN, 1.0, 0.0}), std::domain_error);
  EXPECT_NO_THROW(hertz::validate(Damping::kuwabara_kono, hertz::Params<double>{1e9, 0.0, 0.0}));
  msg = message([] { hertz::validate(Damping::tsuji, hertz::Params<double>{1e9, -0.2, 0.0}); });
  EXPECT_NE(msg.find("Tsuji damping alpha = -0.2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[0, inf)"), std::string::npos) << msg;
}
