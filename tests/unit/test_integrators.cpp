// SPDX-License-Identifier: GPL-2.0-or-later
// Time-integration schemes (src/integrators/schemes.h) and the whole-step impact harness
// (src/collision/integrate_impact.h):
//  * every scheme reaches its nominal order (SchemeInfo::order / order_damped, MultiSchemeInfo)
//    on a harmonic oscillator x'' = -x - 2 zeta x', undamped and damped, with an exact start-up,
//    and the rotation channel of schemes.h its damped order on w' = -w;
//  * the full impact of physics_reference.md 5.2 (m = 0.01 kg, k = 1e5 N/m, gamma = 4.48097 kg/s,
//    e = 0.8, from free flight, |error of e| averaged over 16 start phases) against the 5.2 table:
//    error levels at N = 20 and 80 steps per contact and the observed order (B) with dt = t_n/N
//    exactly (the table's convention), and first order for every scheme at a generic step;
//  * integrate_impact with velocity_verlet and a touch start follows integrate_oblique step by step
//    (round-off) for a head-on and an oblique impact;
//  * the host rules (free-flight start, whole-step end, flush) against a velocity-Verlet loop
//    written out here, independently of integrate_impact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "collision/analytic.h"
#include "collision/integrate_impact.h"
#include "collision/phase_average.h"
#include "collision/oblique.h"
#include "integrators/schemes.h"

using namespace tdem;
using namespace tdem::collision;
using integrators::Scheme;

namespace {

// ---------------------------------------------------------------- smooth problem
// x'' = -x - 2 zeta x', x(0) = 1, x'(0) = 0, all three components alike; exact solution:
struct Oscillator {
  double zeta;
  double wd() const { return std::sqrt(1.0 - zeta * zeta); }
  double x(double t) const { return std::exp(-zeta * t) * (std::cos(wd() * t) + zeta / wd() * std::sin(wd() * t)); }
  double v(double t) const { return -std::exp(-zeta * t) * std::sin(wd() * t) / wd(); }
  double a(double x_, double v_) const { return -x_ - 2.0 * zeta * v_; }
};

constexpr double kT = 4.0;  // integration time

// Error of x(T) for a one-evaluation scheme with N steps; exact start-up from the derivatives of a.
double one_eval_error(Scheme s, int n, double zeta) {
  const Oscillator o{zeta};
  const double h = kT / n;
  double x[3] = {1.0, 1.0, 1.0}, v[3] = {0.0, 0.0, 0.0}, a[3], hist[64] = {0.0};
  auto acc = [&]() {
    for (int k = 0; k < 3; ++k) a[k] = o.a(x[k], v[k]);
  };
  acc();
  integrators::dispatch(s, [&](auto tag) {
    using K = integrators::Kernel<decltype(tag)::value, true>;
    // a' = -v - 2 zeta a, a^(i) = -a^(i-2) - 2 zeta a^(i-1)
    double d[5][3];
    for (int k = 0; k < 3; ++k) {
      d[0][k] = a[k];
      d[1][k] = -v[k] - 2.0 * zeta * a[k];
      for (int i = 2; i < 5; ++i) d[i][k] = -d[i - 2][k] - 2.0 * zeta * d[i - 1][k];
    }
    integrators::Derivs D;
    D.n = 5;
    for (int i = 0; i < 5; ++i) D.d[i] = d[i];
    K::start(x, v, D, hist, h);
    for (int i = 0; i < n; ++i) {
      K::predict(x, v, a, hist, h);
      acc();
      K::correct(x, v, a, hist, h);
    }
    return 0;
  });
  return std::fabs(x[0] - o.x(kT));
}

// The same for a multi-evaluation scheme (multi_step of integrate_impact.h; abm4_pece with the
// exact history).
double multi_eval_error(MultiScheme ms, int n, double zeta) {
  using impact_detail::Acc;
  using impact_detail::Y;
  const Oscillator o{zeta};
  const double h = kT / n;
  Y y;
  for (int k = 0; k < 3; ++k) y.x()[k] = 1.0;
  auto eval = [&](const Y& yy, Acc& out) {
    for (int k = 0; k < 3; ++k) out.a[k] = o.a(yy.x()[k], yy.v()[k]), out.al[k] = 0.0, out.vt[k] = 0.0;
  };
  Acc acc;
  eval(y, acc);
  MultiState st;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      const double t = -(j + 1) * h;
      st.ha[j][k] = o.a(o.x(t), o.v(t));
      st.hv[j][k] = o.v(t);
    }
  for (int i = 0; i < n; ++i) {
    double vt[3];
    multi_step(ms, y, acc, st, h, [&](const Y& ys, double, const double*, Acc& out) { eval(ys, out); }, vt);
    eval(y, acc);
  }
  return std::fabs(y.x()[0] - o.x(kT));
}

// Observed order from errors at N and 2N: the finest pair whose error is still well above
// round-off (> 1e-10) and already in the asymptotic range (< 1e-2).
template <class F>
double observed_order(F err, double* level = nullptr) {
  const int ns[] = {20, 40, 80, 160, 320, 640, 1280};
  double order = NAN;
  for (int i = 0; i + 1 < 7; ++i) {
    const double e1 = err(ns[i]), e2 = err(ns[i + 1]);
    if (e1 < 1e-2 && e2 > 1e-10) {
      order = std::log2(e1 / e2);
      if (level) *level = e2;
    }
  }
  return order;
}

TEST(Integrators, OneEvaluationSchemesReachNominalOrderOnOscillator) {
  for (int i = 0; i < static_cast<int>(Scheme::count); ++i) {
    const Scheme s = static_cast<Scheme>(i);
    for (double zeta : {0.0, 0.1}) {
      double level = NAN;
      const double p = observed_order([&](int n) { return one_eval_error(s, n, zeta); }, &level);
      const int nominal = zeta == 0.0 ? integrators::info(s).order : integrators::info(s).order_damped;
      std::printf("%-22s zeta %.1f: observed order %.2f (nominal %d), error %.1e\n", integrators::info(s).name, zeta,
                  p, nominal, level);
      // reaches the nominal order (0.15: the next term of the error expansion at these N);
      // gear4 is one order better than nominal on the undamped problem (observed 4.0)
      EXPECT_GE(p, nominal - 0.15) << integrators::info(s).name << " zeta " << zeta;
      EXPECT_LE(p, nominal + 1.15) << integrators::info(s).name << " zeta " << zeta;
    }
  }
}

// The rotation channel (no position): w' = -w, a purely velocity-dependent "force", so the
// damped order applies; exact start-up (alpha^(i) = (-1)^(i+1) w).
double rotation_error(Scheme s, int n) {
  const double h = kT / n;
  double w[3] = {1.0, 1.0, 1.0}, a[3], hist[64] = {0.0};
  auto acc = [&]() {
    for (int k = 0; k < 3; ++k) a[k] = -w[k];
  };
  acc();
  integrators::dispatch(s, [&](auto tag) {
    using K = integrators::Kernel<decltype(tag)::value, false>;
    double d[5][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 5; ++i) d[i][k] = (i % 2 == 0 ? -1.0 : 1.0) * w[k];
    integrators::Derivs D;
    D.n = 5;
    for (int i = 0; i < 5; ++i) D.d[i] = d[i];
    K::start(nullptr, w, D, hist, h);
    for (int i = 0; i < n; ++i) {
      K::predict(nullptr, w, a, hist, h);
      acc();
      K::correct(nullptr, w, a, hist, h);
    }
    return 0;
  });
  return std::fabs(w[0] - std::exp(-kT));
}

TEST(Integrators, RotationChannelReachesDampedOrder) {
  for (int i = 0; i < static_cast<int>(Scheme::count); ++i) {
    const Scheme s = static_cast<Scheme>(i);
    double level = NAN;
    const double p = observed_order([&](int n) { return rotation_error(s, n); }, &level);
    std::printf("%-22s rotation: observed order %.2f (nominal %d), error %.1e\n", integrators::info(s).name, p,
                integrators::info(s).order_damped, level);
    // reaches the nominal order; abm4 approaches its 4 from above (4.32, 4.18, ... 4.39 at the
    // finest pair above round-off)
    EXPECT_GE(p, integrators::info(s).order_damped - 0.15) << integrators::info(s).name;
    EXPECT_LE(p, integrators::info(s).order_damped + 0.5) << integrators::info(s).name;
  }
}

TEST(Integrators, MultiEvaluationSchemesReachNominalOrderOnOscillator) {
  for (int i = 0; i < static_cast<int>(MultiScheme::count); ++i) {
    const MultiScheme s = static_cast<MultiScheme>(i);
    for (double zeta : {0.0, 0.1}) {
      double level = NAN;
      const double p = observed_order([&](int n) { return multi_eval_error(s, n, zeta); }, &level);
      const int nominal = zeta == 0.0 ? info(s).order : info(s).order_damped;
      std::printf("%-10s zeta %.1f: observed order %.2f (nominal %d), error %.1e\n", info(s).name, zeta, p, nominal,
                  level);
      EXPECT_NEAR(p, nominal, 0.15) << info(s).name << " zeta " << zeta;
    }
  }
}

// ---------------------------------------------------------------- the full impact (5.2 (B))
struct Case52 {
  double m = 0.01, k = 1e5, g = 4.48097;
  double delta() const { return g / (2.0 * m); }
  double w() const { return std::sqrt(k / m - delta() * delta()); }
  double tn() const { return M_PI / w(); }                 // variant A contact time (closed form)
  double e() const { return std::exp(-delta() * tn()); }  // closed form
};

double impact_error(const ImpactScheme& s, double n) {
  const Case52 c;
  LsdLaw law;
  law.c = {c.k, c.g};
  Frictionless none;
  ImpactSetup su;
  su.m = c.m, su.R = 0.01, su.speed = 1.0;
  ImpactOptions o;
  o.dt = c.tn() / n;
  ImpactReference ref;
  ref.e = c.e();
  const PhaseAverage pa = phase_averaged(law, none, s, su, o, 16, ref);
  EXPECT_EQ(pa.ended, 16);
  return pa.e;
}

// physics_reference.md 5.2 table: scheme, |error of e| at N = 20 and 80, order (B) low/high
// (3 -> 2 given as 2..3).
struct Row52 {
  const char* scheme;
  double e20, e80;
  double order_lo, order_hi;
};
const Row52 kTable52[] = {
    {"euler", 2.2e-1, 5.1e-2, 1, 1},          {"symplectic_euler", 4.7e-3, 1.1e-3, 1, 1},
    {"velocity_verlet", 4.7e-3, 1.1e-3, 1, 1}, {"vv2", 1.4e-3, 8.5e-5, 2, 2},
    {"beeman", 1.0e-3, 6.1e-5, 2, 2},          {"heun", 2.7e-3, 1.7e-4, 2, 2},
    {"rk4", 1.1e-5, 6.9e-7, 2, 2},             {"ab3", 3.8e-3, 6.4e-5, 3, 3},
    {"ab4", 2.9e-4, 2.6e-6, 2, 3},             {"abm4_pece", 1.5e-5, 2.0e-6, 2, 2},
    {"gear4", 1.8e-4, 3.4e-6, 2, 3},           {"gear5", 1.5e-5, 1.9e-6, 2, 2},
    {"gear6", 2.7e-5, 2.1e-6, 2, 2},
};

TEST(Integrators, FullImpactMatchesTable52) {
  for (const Row52& row : kTable52) {
    ImpactScheme s;
    ASSERT_TRUE(parse_impact_scheme(row.scheme, s)) << row.scheme;
    const double e20 = impact_error(s, 20), e80 = impact_error(s, 80), e320 = impact_error(s, 320);
    const double p = std::log(e20 / e80) / std::log(4.0);        // the table's order (B) range
    const double p_asym = std::log(e80 / e320) / std::log(4.0);  // N = 80 -> 320
    const double p_table = std::log(row.e20 / row.e80) / std::log(4.0);  // implied by the table's levels
    std::printf("%-17s |de| N=20 %.2e (table %.1e)  N=80 %.2e (table %.1e)  order 20->80 %.2f (table column %g..%g, "
                "table levels %.2f)  80->320 %.2f\n",
                row.scheme, e20, row.e20, e80, row.e80, p, row.order_lo, row.order_hi, p_table, p_asym);
    // levels: the table gives two digits (rounding <= 5 %) and is itself a phase average over 16
    // phases at N = t_n/dt exactly, as here: a factor 1.2 allows the rounding and nothing else of
    // substance (observed: within 6 %)
    EXPECT_LT(std::fabs(std::log(e20 / row.e20)), std::log(1.2)) << row.scheme << " N=20";
    EXPECT_LT(std::fabs(std::log(e80 / row.e80)), std::log(1.2)) << row.scheme << " N=80";
    // order between N = 20 and 80: within 0.3 of the column (0.3 = the two-digit rounding of the
    // levels, up to 0.07, plus the pre-asymptotic drift seen between 20->80 and 80->320 in the
    // clean second-order schemes, <= 0.1, with margin), or, where the column disagrees with the
    // table's own levels (abm4, gear5: column 2, levels 1.45/1.49; ab4: column 3->2, levels 3.40),
    // within 0.15 of the order the levels imply (the disagreement is reported, not tested away).
    const bool column_consistent = p_table >= row.order_lo - 0.3 && p_table <= row.order_hi + 0.3;
    if (column_consistent) {
      EXPECT_GE(p, row.order_lo - 0.3) << row.scheme;
      EXPECT_LE(p, row.order_hi + 0.3) << row.scheme;
    } else {
      EXPECT_NEAR(p, p_table, 0.15) << row.scheme;
    }
    // asymptotic order (80 -> 320): first-order schemes 1; "every scheme of nominal order >= 2
    // drops to order 2" (column 2 or 3->2: 2, with 0.3 for the 3->2 transition still under way at
    // N = 80: ab4 2.16, gear4 2.27); ab3 (column 3) keeps its 3 up to N = 320
    if (row.order_hi == 1) {
      EXPECT_NEAR(p_asym, 1.0, 0.15) << row.scheme;
    } else if (row.order_lo == 2) {
      EXPECT_NEAR(p_asym, 2.0, row.order_hi > 2 ? 0.3 : 0.15) << row.scheme;
    } else {
      EXPECT_NEAR(p_asym, 3.0, 0.3) << row.scheme;
    }
  }
}

// At a step that is not a whole fraction of the contact time the force jumps of the LSD law at
// touch (gamma v0) and at separation no longer cancel: every scheme is first order in e, at about
// the same level (a finding of validation/integrators; the 5.2 table uses dt = t_n/N exactly).
double impact_error_generic(const ImpactScheme& s, double n) {
  double sum = 0.0;
  for (double f : {0.125, 0.375, 0.625, 0.875}) sum += impact_error(s, n + f);
  return sum / 4.0;
}

TEST(Integrators, FullImpactAtGenericStepIsFirstOrder) {
  for (const char* name : {"velocity_verlet", "gear5", "rk4", "vv2", "abm4_pece"}) {
    ImpactScheme s;
    ASSERT_TRUE(parse_impact_scheme(name, s));
    const double e20 = impact_error_generic(s, 20), e80 = impact_error_generic(s, 80);
    const double p = std::log(e20 / e80) / std::log(4.0);
    std::printf("%-16s generic dt: |de| N=20 %.2e  N=80 %.2e  order %.2f\n", name, e20, e80, p);
    EXPECT_NEAR(p, 1.0, 0.15) << name;
    // the level is set by the force jump, gamma v0 dt/m = 5.6e-3 at N = 80: between 0.1 and 0.5 of it
    const Case52 c;
    const double jump = c.g * 1.0 * (c.tn() / 80.0) / c.m;
    EXPECT_GT(e80, 0.1 * jump) << name;
    EXPECT_LT(e80, 0.5 * jump) << name;
  }
}

// ---------------------------------------------------------------- against integrate_oblique
void compare_with_oblique(double angle_deg, double spin, bool friction) {
  const Case52 c;
  LsdLaw law;
  law.c = {c.k, c.g};
  CundallStrackTangential cs;
  cs.p = {2.0 / 7.0 * c.k, 0.0, friction ? 0.3 : 0.0};
  ImpactScheme vv;
  ASSERT_TRUE(parse_impact_scheme("velocity_verlet", vv));
  ImpactSetup su;
  su.m = c.m, su.R = 0.01, su.speed = 1.0, su.angle = angle_deg * M_PI / 180.0, su.omega0 = spin, su.gap = 0.0;
  ImpactOptions o;
  o.dt = c.tn() / 47.3;
  o.record = true;
  const ImpactResult a = integrate_impact(law, cs, vv, su, o);
  ObliqueBodies b;
  b.m1 = c.m, b.R1 = 0.01;
  ObliqueImpact im;
  im.speed = 1.0, im.angle = su.angle, im.omega1 = spin;
  ObliqueOptions oo;
  oo.dt = o.dt;
  oo.record = true;
  const ObliqueResult r = integrate_oblique(law, cs, b, im, oo);
  ASSERT_TRUE(a.ended);
  ASSERT_TRUE(r.ended);
  // integrate_oblique cuts its last step at the end of contact; every whole step before it must agree
  EXPECT_EQ(a.contact_steps, r.steps - 1);
  ASSERT_EQ(a.samples.size() + 1, r.samples.size());
  double worst = 0.0;
  for (size_t i = 0; i < a.samples.size(); ++i) {
    const auto &p = a.samples[i], &q = r.samples[i];
    EXPECT_NEAR(p.t, q.t, 1e-12 * c.tn());
    worst = std::max({worst, std::fabs(p.xi - q.xi) / 3e-4, std::fabs(p.xi_dot - q.xi_dot), std::fabs(p.fn - q.fn) / 30.0,
                      std::fabs(p.ft - q.ft) / 30.0, std::fabs(p.vs - q.vs)});
    EXPECT_EQ(p.sliding, q.sliding) << "step " << i;
  }
  std::printf("angle %g spin %g: largest relative difference over %zu steps %.2e\n", angle_deg, spin,
              a.samples.size(), worst);
  EXPECT_LT(worst, 1e-12);
  // the whole-step end and the located end differ by less than one step's worth of the force
  EXPECT_NEAR(a.e, r.e, 3.0 * c.g * o.dt / c.m + 0.05);
}

TEST(Integrators, VelocityVerletTouchStartEqualsIntegrateOblique) {
  compare_with_oblique(0.0, 0.0, false);   // head-on
  compare_with_oblique(30.0, 50.0, true);  // oblique, friction (stick and slip), initial spin
}

// ---------------------------------------------------------------- host rules, written out
// Head-on LSD from free flight with velocity Verlet as fix nve/sphere + a wall (contact iff
// overlap > 0), v read 10 steps after the first step out of contact.
double host_loop_e(double gap, double dt) {
  const Case52 c;
  const double R = 0.01;
  double z = R + gap, v = -1.0, f = 0.0;
  auto force = [&]() {
    const double xi = R - z;
    return xi > 0.0 ? c.k * xi + c.g * (-v) : 0.0;
  };
  f = force();
  bool was = false;
  int after = -1;
  for (long i = 0; i < 10000000; ++i) {
    v += 0.5 * dt * f / c.m;
    z += dt * v;
    f = force();
    v += 0.5 * dt * f / c.m;
    const bool in = R - z > 0.0;
    if (was && !in && after < 0) after = 10;
    was = in;
    if (after >= 0 && after-- == 0) break;
  }
  return v / 1.0;
}

TEST(Integrators, HostRulesAgainstWrittenOutLoop) {
  const Case52 c;
  LsdLaw law;
  law.c = {c.k, c.g};
  Frictionless none;
  ImpactScheme vv;
  ASSERT_TRUE(parse_impact_scheme("velocity_verlet", vv));
  for (double phase : {0.05, 0.37, 0.93}) {
    const double dt = c.tn() / 33.0;
    ImpactSetup su;
    su.m = c.m, su.R = 0.01, su.speed = 1.0, su.gap = (7.0 + phase) * dt;
    ImpactOptions o;
    o.dt = dt;
    const ImpactResult r = integrate_impact(law, none, vv, su, o);
    ASSERT_TRUE(r.ended);
    const double e_loop = host_loop_e(su.gap, dt);
    EXPECT_NEAR(r.e, e_loop, 1e-14) << "phase " << phase;
    EXPECT_NEAR(r.e, c.e(), 0.02);  // and it is the impact (first order, 33 steps)
  }
}

// Multi-step histories are flushed: the result does not change with more free-flight steps.
TEST(Integrators, FlushStepsSuffice) {
  const Case52 c;
  LsdLaw law;
  law.c = {c.k, c.g};
  CundallStrackTangential cs;
  cs.p = {2.0 / 7.0 * c.k, 0.0, 0.3};
  for (const auto& s : all_impact_schemes()) {
    ImpactSetup su;
    su.m = c.m, su.R = 0.01, su.speed = 1.0, su.angle = 0.4, su.gap = 0.3 * c.tn() / 40.0;
    ImpactOptions o;
    o.dt = c.tn() / 40.0;
    const ImpactResult a = integrate_impact(law, cs, s, su, o);
    o.flush_steps = 40;
    const ImpactResult b = integrate_impact(law, cs, s, su, o);
    ASSERT_TRUE(a.ended && b.ended) << s.name();
    EXPECT_NEAR(a.e, b.e, 1e-13) << s.name();
    EXPECT_NEAR(a.beta, b.beta, 1e-12) << s.name();
    EXPECT_EQ(a.evaluations, 1 + a.steps * s.evaluations()) << s.name();
  }
}

// Tangential part: every scheme converges onto the closed form of analytic.h (8.5 set-up,
// intermediate angle with stick-slip switches), error shrinking with N.
TEST(Integrators, ObliqueImpactConvergesToAnalytic) {
  const double R = 2.5e-3, m = 4.0 / 3.0 * M_PI * R * R * R * 4000.0;
  const double le = std::log(0.98), tc = 1e-5;
  LsdLaw law;
  law.c = {m * (M_PI * M_PI + le * le) / (tc * tc), -2.0 * m * le / tc};
  law.end_mode = ContactEnd::zero_force;
  CundallStrackTangential cs;
  cs.p = {2.0 / 7.0 * law.c.k, 0.0, 0.092};
  analytic::Input in;
  in.m = m, in.R = R, in.kn = law.c.k, in.gn = law.c.gamma, in.kt = cs.p.kt, in.mu = 0.092;
  in.end = ContactEnd::zero_force;
  in.vn0 = 3.9 * std::cos(25 * M_PI / 180), in.vt0 = 3.9 * std::sin(25 * M_PI / 180);
  const analytic::Output x = analytic::impact(in);
  ImpactReference ref;
  ref.e = x.e, ref.beta = x.beta;
  for (const char* name : {"velocity_verlet", "gear5", "rk4", "abm4_pece"}) {
    ImpactScheme s;
    ASSERT_TRUE(parse_impact_scheme(name, s));
    ImpactSetup su;
    su.m = m, su.R = R, su.speed = 3.9, su.angle = 25 * M_PI / 180;
    double prev = INFINITY;
    for (int n : {50, 200, 800}) {
      ImpactOptions o;
      o.dt = x.contact_time / n;
      const PhaseAverage pa = phase_averaged(law, cs, s, su, o, 8, ref);
      std::printf("%-16s N=%d |de| %.2e |dbeta| %.2e\n", name, n, pa.e, pa.beta);
      EXPECT_LT(pa.beta, prev) << name << " N=" << n;
      prev = pa.beta;
      if (n == 800) {
        EXPECT_LT(pa.beta, 5e-3) << name;
      }
    }
  }
}

TEST(Integrators, SchemeNames) {
  ImpactScheme s;
  EXPECT_TRUE(parse_impact_scheme("gear6", s));
  EXPECT_FALSE(s.multi);
  EXPECT_TRUE(parse_impact_scheme("abm4_pece", s));
  EXPECT_TRUE(s.multi);
  EXPECT_EQ(s.evaluations(), 2);
  EXPECT_FALSE(parse_impact_scheme("rk5", s));
  EXPECT_EQ(all_impact_schemes().size(), static_cast<size_t>(Scheme::count) + 4);
}

}  // namespace
