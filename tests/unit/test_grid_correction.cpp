// SPDX-License-Identifier: GPL-2.0-or-later
// The time-grid correction of the contact start and end steps (src/contact/grid_correction.h,
// issue 22): its kernels against quadrature, and whole impacts of the single-collision harness
// (collision/integrate_impact.h) against the closed forms (LSD: collision/analytic.h) and an
// independent integrator (head_on.h: RK4 with the end located by bisection, 2e5 steps).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "collision/analytic.h"
#include "collision/integrate_impact.h"
#include "collision/phase_average.h"
#include "contact/grid_correction.h"

using namespace tdem;
using namespace tdem::collision;

namespace {

// int_a^b f by composite Gauss-Legendre (3 points) on n panels, with the substitution
// t = a + (b - a) u^4 that removes an end-point singularity t^x (x > -1) at a.
template <class F>
double quad(F f, double a, double b, int n = 4000) {
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 3; ++j) {
      const double u = (i + 0.5 + 0.5 * g[j]) / n;
      const double t = a + (b - a) * u * u * u * u;
      s += 0.5 * w[j] / n * f(t) * 4.0 * (b - a) * u * u * u;
    }
  return s;
}

}  // namespace

// ---------------------------------------------------------------- kernels
TEST(GridCorrection, TouchAge) {
  const double h = 1e-5, v = 2.0;
  EXPECT_DOUBLE_EQ(grid::touch_age(0.3 * h * v, v, h), 0.3 * h);
  EXPECT_DOUBLE_EQ(grid::touch_age(0.0, v, h), 0.0);
  EXPECT_DOUBLE_EQ(grid::touch_age(1.5 * h * v, v, h), h);  // rate fell over the step: clipped
  EXPECT_LT(grid::touch_age(2.5 * h * v, v, h), 0.0);       // an old overlap: not a touch
  EXPECT_LT(grid::touch_age(0.3 * h * v, 0.0, h), 0.0);     // not approaching
  EXPECT_LT(grid::touch_age(0.3 * h * v, -v, h), 0.0);
}

TEST(GridCorrection, PowerImpulseAgainstQuadrature) {
  for (double p : {1.0, 1.5, 0.25, 2.0})
    for (double q : {0.0, 0.25, 0.5}) {
      const double e = 3.0, d = -1.7, T = 0.37, L = 0.91;
      const double want = quad([&](double t) { return e * std::pow(t / T, p) + d * std::pow(t / T, q); }, 0.0, L);
      EXPECT_NEAR(grid::power_impulse(e, p, d, q, T, L), want, 1e-11 * std::fabs(want)) << p << " " << q;
    }
}

TEST(GridCorrection, PowerExponent) {
  EXPECT_EQ(grid::power_exponent(2.0, 1.0, 7.0), 1.0);
  EXPECT_EQ(grid::power_exponent(3.0 * 1e-3, 3.0 * 0.5e-3, 7.0), 1.0);  // snapped
  EXPECT_EQ(grid::power_exponent(std::pow(0.2, 1.5), std::pow(0.1, 1.5), 7.0), 1.5);  // snapped to 1/4s
  EXPECT_EQ(grid::power_exponent(-std::pow(0.2, 0.25), -std::pow(0.1, 0.25), 7.0), 0.25);
  EXPECT_NEAR(grid::power_exponent(std::pow(0.2, 1.3), std::pow(0.1, 1.3), 7.0), 1.3, 1e-14);  // not snapped
  EXPECT_EQ(grid::power(16.0, 0.25), 2.0);
  for (double x = -4.0; x <= 4.0; x += 0.25)  // the quarter multiples without pow
    for (double r : {1e-6, 0.3, 0.7, 1.0, 2.5, 40.0})
      EXPECT_NEAR(grid::power(r, x), std::pow(r, x), 4e-16 * std::pow(r, x)) << r << "^" << x;
  EXPECT_EQ(grid::power(0.3, 1.5), 0.3 * std::sqrt(0.3));
  EXPECT_EQ(grid::power(0.3, 1.3), std::pow(0.3, 1.3));
  EXPECT_EQ(grid::power_exponent(0.0, 0.0, 7.0), 7.0);
  EXPECT_EQ(grid::power_exponent(1.0, -1.0, 7.0), 7.0);
}

// The exponents normal hertz declares to the hosts (in place of their probe at xi/2) are what the
// probe of the law gives, for every damping member, approaching and receding; none with a force
// clipped at zero.
TEST(GridCorrection, HertzDeclaredExponentsEqualTheProbe) {
  using hertz::Damping;
  for (Damping d : {Damping::linear, Damping::kuwabara_kono, Damping::tsuji, Damping::general}) {
    const hertz::Params<double> par{2.0e7, d == Damping::tsuji ? 0.8 : 3.0, 0.3};
    double p = -1.0, q = -1.0;
    ASSERT_TRUE(hertz::power_exponents(d, par.theta, ContactEnd::zero_overlap, p, q));
    for (double rate : {0.7, -0.4})
      for (double xi : {1e-7, 3e-5}) {
        const NormalKinematics<double> at{xi, rate, 0.01, 1e-3}, half{0.5 * xi, rate, 0.01, 1e-3};
        const NormalResult<double> a = hertz::force(d, ContactEnd::zero_overlap, par, at),
                                   b = hertz::force(d, ContactEnd::zero_overlap, par, half);
        EXPECT_EQ(p, grid::power_exponent(a.elastic, b.elastic, 1.0)) << hertz::to_string(d);
        EXPECT_NEAR(q, grid::power_exponent(a.force - a.elastic, b.force - b.elastic, 0.0), 1e-12)
            << hertz::to_string(d);
      }
  }
  double p, q;
  EXPECT_FALSE(hertz::power_exponents(Damping::tsuji, 0.0, ContactEnd::zero_force, p, q));
}

// The start force is the whole kick of the contact up to the end of the window, and the sum of
// the next windows' sampling errors of a t'^x part (x < 1): against the direct sum over 20000
// windows of (integral - h sample), each by quadrature, plus the integral of the first window.
TEST(GridCorrection, StartForceEqualsIntegralPlusNearWindowErrors) {
  const double h = 1.0, x = 0.25, c = 2.0;
  for (double tau : {0.05, 0.37, 0.5, 0.93}) {
    auto f = [&](double t) { return c * std::pow(t / tau, x); };
    double want = quad(f, 0.0, tau + 0.5 * h) / h;
    double defects = 0.0;
    for (int k = 1; k <= 2000; ++k) {
      const double mid = tau + k * h;
      defects += (quad(f, mid - 0.5 * h, mid + 0.5 * h, 8) - h * f(mid)) / h;
    }
    // beyond 2000 windows: the leading term of the window error, c (h/tau)^x x (x - 1) u^(x-2) / 24,
    // integrated from u = tau + 2000.5
    defects += c * std::pow(h / tau, x) * x / 24.0 * std::pow(2000.5 + tau, x - 1.0) * -1.0;
    want += defects;
    const double got = grid::start_force(0.0, 1.0, c, x, tau, h);
    EXPECT_NEAR(got, want, 1e-4 * std::fabs(defects)) << tau;
    EXPECT_GT(std::fabs(defects), 1e-3 * std::fabs(want)) << tau;  // the windows' term matters
  }
  // linear model: exact integral, no near-window term
  const double tau = 0.3, fn = 5.0, f0 = 2.0;
  EXPECT_NEAR(grid::start_force(fn - f0, 1.0, f0, 0.0, tau, h),
              quad([&](double t) { return f0 + (fn - f0) * t / tau; }, 0.0, tau + 0.5 * h) / h, 1e-13);
}

TEST(GridCorrection, EndExtraAndEndTime) {
  const double h = 2.0;
  EXPECT_DOUBLE_EQ(grid::end_time(3.0, -1.0, h), 1.5);
  EXPECT_DOUBLE_EQ(grid::end_time(3.0, 0.5, h), h);
  EXPECT_DOUBLE_EQ(grid::end_time(0.0, -1.0, h), 0.0);
  // linear force from 4 at t_{m-1} to 0 at s = 0.6: the contact's impulse in [t_{m-1} - h/2, te]
  // minus the applied h * 4
  const double s = 0.6, fp = 4.0;
  const double want = (quad([&](double t) { return fp * (s - t) / s; }, -0.5 * h, s) - h * fp) / h;
  EXPECT_NEAR(grid::end_extra(fp, fp, 1.0, 0.0, 0.0, s, h), want, 1e-13);
}

// ---------------------------------------------------------------- whole impacts
namespace {

struct GenericError {
  double mean = 0.0;
  bool ok = true;
};

// Phase-averaged |de| (16 phases) over dt = t_c/(N + f), f = 1/8, 3/8, 5/8, 7/8.
template <class Law, class Tang>
GenericError generic(Law law, Tang tang, const char* scheme, const ImpactSetup& su, double tc, double ref_e, int N,
                     bool gc, bool beta = false, double ref_beta = 0.0) {
  ImpactScheme s;
  EXPECT_TRUE(parse_impact_scheme(scheme, s));
  ImpactReference ref;
  ref.e = ref_e;
  if (beta) ref.beta = ref_beta;
  GenericError g;
  for (double f : {0.125, 0.375, 0.625, 0.875}) {
    ImpactOptions o;
    o.dt = tc / (N + f);
    o.grid_correction = gc;
    const PhaseAverage pa = phase_averaged(law, tang, s, su, o, 16, ref);
    if (pa.ended != 16) g.ok = false;
    g.mean += (beta ? pa.beta : pa.e) / 4.0;
  }
  return g;
}

double order(double coarse, double fine, double ratio) { return std::log(coarse / fine) / std::log(ratio); }

struct Lsd52 {
  LsdLaw law;
  ImpactSetup su;
  double tc = 0.0, e = 0.0;
  explicit Lsd52(ContactEnd end) {
    law.c = {1e5, 4.48097};
    law.end_mode = end;
    su.m = 0.01, su.R = 0.01, su.speed = 1.0;
    analytic::Input in;
    in.m = 0.01, in.R = 0.01, in.kn = 1e5, in.gn = 4.48097, in.kt = 1.0, in.mu = 0.0, in.end = end, in.vn0 = 1.0;
    const analytic::Output x = analytic::impact(in);
    tc = x.contact_time;
    e = x.e;
  }
};

// Hertz + Tsuji damping (alpha = 0.2, the physics_reference 8.2 steel sphere at 1 m/s); reference
// from head_on.h's RK4 with the located end at 2e5 steps.
struct HertzTsuji {
  HertzLaw law;
  ImpactSetup su;
  double tc = 0.0, e = 0.0;
  explicit HertzTsuji(ContactEnd end) {
    law.damping = hertz::Damping::tsuji;
    law.p.k = 1.087857e10;
    law.p.damp = 0.2;
    law.end_mode = end;
    su.m = 4.110250e-3, su.R = 5e-3, su.speed = 1.0;
    Bodies b;
    b.m1 = su.m, b.R1 = su.R;
    Options o;
    o.steps_per_contact = 200000;
    const Result r = integrate(law, b, 1.0, o);
    tc = r.contact_time;
    e = r.restitution;
  }
};

}  // namespace

// The done-when of issue 22: with the correction and the velocity-consistent velocity Verlet
// (velocity_verlet_ab2), |de| <= 1e-3 at 25 and <= 1e-4 at 80 steps per contact, at a generic
// step, for LSD (both ends) and Hertz + Tsuji; order >= 1.8 (80 -> 320) against ~1 without.
template <class Case>
void check_targets(const Case& c, const char* name, double max_order_off) {
  Frictionless none;
  const char* vv = "velocity_verlet_ab2";
  const double on25 = generic(c.law, none, vv, c.su, c.tc, c.e, 25, true).mean;
  const double on80 = generic(c.law, none, vv, c.su, c.tc, c.e, 80, true).mean;
  const double on320 = generic(c.law, none, vv, c.su, c.tc, c.e, 320, true).mean;
  const double off80 = generic(c.law, none, vv, c.su, c.tc, c.e, 80, false).mean;
  const double off320 = generic(c.law, none, vv, c.su, c.tc, c.e, 320, false).mean;
  std::printf("%-18s |de| on: N=25 %.2e N=80 %.2e N=320 %.2e (order %.2f); off: N=80 %.2e N=320 %.2e (order %.2f)\n",
              name, on25, on80, on320, order(on80, on320, 4.0), off80, off320, order(off80, off320, 4.0));
  EXPECT_LE(on25, 1e-3) << name;
  EXPECT_LE(on80, 1e-4) << name;
  EXPECT_GE(order(on80, on320, 4.0), 1.8) << name;
  EXPECT_LE(order(off80, off320, 4.0), max_order_off) << name;
}

TEST(GridCorrection, TargetsLsdZeroOverlap) { check_targets(Lsd52(ContactEnd::zero_overlap), "lsd zero_overlap", 1.1); }
TEST(GridCorrection, TargetsLsdZeroForce) { check_targets(Lsd52(ContactEnd::zero_force), "lsd zero_force", 1.1); }
// Hertz + Tsuji converges with order 1.25 without the correction (the t^(1/4) onset)
TEST(GridCorrection, TargetsHertzTsuji) { check_targets(HertzTsuji(ContactEnd::zero_overlap), "hertz tsuji", 1.3); }

// Plain velocity Verlet (nve/sphere) and velocity_verlet_sync with the correction: second order
// too, at a larger constant (the half-step velocity in the damping force: the Euler predictor of
// _sync has |de| = 1.45e-4 at N = 80 even with both events on the grid).
TEST(GridCorrection, OtherVerletForms) {
  const Lsd52 c(ContactEnd::zero_overlap);
  Frictionless none;
  for (const char* s : {"velocity_verlet", "velocity_verlet_sync", "beeman"}) {
    const double on80 = generic(c.law, none, s, c.su, c.tc, c.e, 80, true).mean;
    const double on320 = generic(c.law, none, s, c.su, c.tc, c.e, 320, true).mean;
    const double off80 = generic(c.law, none, s, c.su, c.tc, c.e, 80, false).mean;
    std::printf("%-22s |de| on: N=80 %.2e N=320 %.2e (order %.2f); off N=80 %.2e\n", s, on80, on320,
                order(on80, on320, 4.0), off80);
    EXPECT_LT(on80, 0.25 * off80) << s;
    if (std::string(s) != "velocity_verlet") {
      EXPECT_GE(order(on80, on320, 4.0), 1.8) << s;
    }
  }
}

// The 25-degree oblique case (physics_reference 8.5(a): LSD e = 0.98 zero-force end,
// Cundall-Strack kappa = 2/7, mu = 0.092): |d beta| with the correction at most half of the
// uncorrected error at every step from 10 to 320 per contact.
TEST(GridCorrection, Oblique25BetaHalved) {
  const double R = 2.5e-3, m = 4.0 / 3.0 * M_PI * R * R * R * 4000.0, le = std::log(0.98), tn = 1e-5;
  const double kn = m * (M_PI * M_PI + le * le) / (tn * tn), gn = -2.0 * m * le / tn;
  LsdLaw law;
  law.c = {kn, gn};
  law.end_mode = ContactEnd::zero_force;
  CundallStrackTangential cs;
  cs.p = {2.0 / 7.0 * kn, 0.0, 0.092};
  ImpactSetup su;
  su.m = m, su.R = R, su.speed = 3.9, su.angle = 25.0 * M_PI / 180.0;
  analytic::Input in;
  in.m = m, in.R = R, in.kn = kn, in.gn = gn, in.kt = 2.0 / 7.0 * kn, in.mu = 0.092, in.end = ContactEnd::zero_force;
  in.vn0 = 3.9 * std::cos(su.angle), in.vt0 = 3.9 * std::sin(su.angle);
  const analytic::Output x = analytic::impact(in);
  for (const char* s : {"velocity_verlet", "velocity_verlet_ab2"})
    for (int N : {10, 25, 40, 80, 160, 320}) {
      const double on = generic(law, cs, s, su, x.contact_time, x.e, N, true, true, x.beta).mean;
      const double off = generic(law, cs, s, su, x.contact_time, x.e, N, false, true, x.beta).mean;
      std::printf("%-20s N=%3d |d beta| on %.2e off %.2e (%.2f)\n", s, N, on, off, on / off);
      EXPECT_LE(on, 0.5 * off) << s << " N=" << N;
    }
}

// Every normal law: the correction keeps second order where the law is already second order
// (force continuous at touch and end) and makes it second order where it is not; never worse
// than 1.25 times the uncorrected error at N = 80, and second order from 80 to 320.
TEST(GridCorrection, EveryNormalLaw) {
  auto check = [](const char* name, auto law, double m, double R) {
    Bodies b;
    b.m1 = m, b.R1 = R;
    Options o;
    o.steps_per_contact = 200000;
    const Result r = integrate(law, b, 1.0, o);
    ASSERT_TRUE(r.ended) << name;
    ImpactSetup su;
    su.m = m, su.R = R, su.speed = 1.0;
    Frictionless none;
    const char* vv = "velocity_verlet_ab2";
    const double on80 = generic(law, none, vv, su, r.contact_time, r.restitution, 80, true).mean;
    const double on320 = generic(law, none, vv, su, r.contact_time, r.restitution, 320, true).mean;
    const double off80 = generic(law, none, vv, su, r.contact_time, r.restitution, 80, false).mean;
    std::printf("%-16s e %.4f |de| on N=80 %.2e N=320 %.2e (order %.2f), off N=80 %.2e\n", name, r.restitution, on80,
                on320, order(on80, on320, 4.0), off80);
    EXPECT_LE(on80, 1.25 * off80) << name;
    EXPECT_GE(order(on80, on320, 4.0), 1.8) << name;
  };
  const double ms = 4.110250e-3, Rs = 5e-3;
  HertzLaw h;
  h.p.k = 1.087857e10;
  h.damping = hertz::Damping::linear;
  h.p.damp = 5.0;
  check("hertz linear", h, ms, Rs);
  h.end_mode = ContactEnd::zero_force;
  h.damping = hertz::Damping::tsuji;
  h.p.damp = 0.2;
  check("hertz tsuji zf", h, ms, Rs);
  WaltonBraunLaw w;
  w.p = {1e5, 1.5625e5, 0.0};
  check("walton_braun", w, 0.01, 0.01);
  ThorntonLaw t;
  t.p = {210e9 / (2.0 * 0.91), 1e9};
  check("thornton", t, 4.0 / 3.0 * M_PI * Rs * Rs * Rs * 7850.0, Rs);
  PowerLawLaw pl;
  pl.p = {2e8, 1.5, 5e10, 0.5};
  check("power_law", pl, 0.01, 0.01);
  fits::Fit ef, tf;
  ef.form = fits::Form::rational, ef.c[0] = 0.9, ef.c[1] = 1.0, ef.c[2] = 0.6;  // e = 0.9/(1 + v^0.6)
  tf.form = fits::Form::power, tf.c[0] = 2e-4, tf.c[1] = 0.2;                  // t_c = 2e-4 v^-0.2
  ExtendedLinearLaw el;
  el.p = {ef, tf, fits::Range{}};
  check("extended_linear", el, 0.01, 0.01);
  ExtendedHertzLaw eh;
  eh.p = {2e9, ef, fits::Range{}};
  check("extended_hertz", eh, 1e-3, 5e-3);
}

// Only the steps where a contact starts and ends change: a contact that exists from the first
// step (touch at t = 0 on the grid, gap 0: the host's set-up sees it, no step saw it start) is
// integrated bitwise as without the correction, to its end (whose correction needs the start's).
TEST(GridCorrection, EnduringContactUnchanged) {
  const Lsd52 c(ContactEnd::zero_overlap);
  CundallStrackTangential cs;
  cs.p = {2.0 / 7.0 * 1e5, 0.0, 0.3};
  ImpactScheme s;
  ASSERT_TRUE(parse_impact_scheme("velocity_verlet", s));
  ImpactSetup su = c.su;
  su.angle = 30.0 * M_PI / 180.0;
  ImpactOptions o;
  o.dt = c.tc / 47.3;
  o.record = true;
  LsdLaw l1 = c.law, l2 = c.law;
  CundallStrackTangential c1 = cs, c2 = cs;
  const ImpactResult off = integrate_impact(l1, c1, s, su, o);
  o.grid_correction = true;
  const ImpactResult on = integrate_impact(l2, c2, s, su, o);
  ASSERT_EQ(off.samples.size(), on.samples.size());
  ASSERT_GT(off.samples.size(), 40u);
  for (size_t i = 0; i < off.samples.size(); ++i) {
    EXPECT_EQ(off.samples[i].xi, on.samples[i].xi) << i;
    EXPECT_EQ(off.samples[i].fn, on.samples[i].fn) << i;
    EXPECT_EQ(off.samples[i].ft, on.samples[i].ft) << i;
  }
  EXPECT_EQ(off.e, on.e);
  EXPECT_EQ(off.beta, on.beta);
  // the same impact from a gap: both events corrected, every contact step but the first unchanged
  // ... up to the trajectory change the first step's kick makes: e differs
  su.gap = 0.37 * o.dt * su.speed;
  LsdLaw l3 = c.law, l4 = c.law;
  CundallStrackTangential c3 = cs, c4 = cs;
  o.grid_correction = false;
  const ImpactResult off2 = integrate_impact(l3, c3, s, su, o);
  o.grid_correction = true;
  const ImpactResult on2 = integrate_impact(l4, c4, s, su, o);
  EXPECT_EQ(off2.samples[0].fn, on2.samples[0].fn);  // samples are the law's values, not the kicks
  EXPECT_GT(std::fabs(on2.e - off2.e), 1e-4);
}

// Energy: the correction never adds energy where the uncorrected step does not, at any step up to
// the critical step of velocity Verlet (dt_c = 2 (sqrt(1 + zeta^2) - zeta) / omega, test_stability),
// from elastic (zeta = 0, where velocity Verlet itself returns up to 0.6 % more energy at 0.1
// dt_c) to over-damped contacts (zeta = 2.4), both ends, with friction. At 0.5 dt_c and beyond
// (3 steps per contact and fewer) it does not act at all: the results are bitwise those without it.
TEST(GridCorrection, NoEnergyGainUpToTheCriticalStep) {
  for (double g : {0.0, 4.48097, 40.0, 150.0}) {
    LsdLaw law;
    law.c = {1e5, g};
    for (ContactEnd end : {ContactEnd::zero_overlap, ContactEnd::zero_force}) {
      law.end_mode = end;
      ImpactSetup su;
      su.m = 0.01, su.R = 0.01, su.speed = 1.0, su.angle = 0.4;
      CundallStrackTangential cs;
      cs.p = {2.0 / 7.0 * 1e5, 0.0, 0.3};
      const double w = std::sqrt(1e5 / 0.01), zeta = g / (2.0 * std::sqrt(1e5 * 0.01));
      const double hc = 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / w;
      for (double frac : {0.02, 0.1, 0.3, 0.5, 0.9, 0.99}) {
        ImpactScheme s;
        ASSERT_TRUE(parse_impact_scheme("velocity_verlet", s));
        ImpactReference ref;
        ImpactOptions o;
        o.dt = frac * hc;
        const PhaseAverage off = phase_averaged(law, cs, s, su, o, 8, ref, true);
        o.grid_correction = true;
        const PhaseAverage on = phase_averaged(law, cs, s, su, o, 8, ref, true);
        const double ke0 = 0.5 * su.m * su.speed * su.speed;
        double gain_off = -INFINITY, gain_on = -INFINITY;
        for (int i = 0; i < 8; ++i) {
          ASSERT_EQ(on.runs[i].ended, off.runs[i].ended) << g << " " << frac;
          if (!on.runs[i].ended) continue;  // zeta = 2.4, zero overlap: the attraction holds the sphere
          gain_off = std::max(gain_off, -off.runs[i].dissipated_energy / ke0);
          gain_on = std::max(gain_on, -on.runs[i].dissipated_energy / ke0);
          if (frac >= 0.5 && zeta < 1.0) {
            EXPECT_EQ(on.runs[i].e, off.runs[i].e) << g << " " << frac;
          }
        }
        EXPECT_LE(gain_on, std::max(gain_off, 0.0) + 1e-12)
            << "gamma " << g << " dt/dt_c " << frac << " " << to_string(end);
      }
    }
  }
}
