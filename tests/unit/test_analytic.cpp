// SPDX-License-Identifier: GPL-2.0-or-later
// Closed-form oblique impact (src/collision/analytic.h, physics_reference.md 4):
//  * the table of physics_reference 8.5 (fine-step reference integration, ~1e-5);
//  * the velocity-Verlet harness integrate_oblique (oblique.h) at 1e5 steps per contact, for both
//    end conventions and both friction limits, with and without initial spin;
//  * the gross-sliding branch against the rigid-body closed form (rigid_body.h);
//  * the normal closed forms (e and contact time of the two LSD end conventions, 8.1) and the
//    switching-time structure of the three collision modes; input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "collision/analytic.h"
#include "collision/oblique.h"
#include "collision/rigid_body.h"

using namespace tdem;
using namespace tdem::collision;

namespace {

constexpr double kDeg = M_PI / 180.0;

// physics_reference 8.5(a): R = 2.5 mm, rho = 4000, e = 0.98, t_n = 1e-5 s (variant-A formulas).
struct AnaSetup {
  double R = 2.5e-3;
  double m = 4.0 / 3.0 * M_PI * R * R * R * 4000.0;
  double kn, gn;
  double mu = 0.092, speed = 3.9;
  AnaSetup() {
    const double le = std::log(0.98), tc = 1e-5;
    kn = m * (M_PI * M_PI + le * le) / (tc * tc);
    gn = -2.0 * m * le / tc;
  }
  analytic::Input input(double theta_deg, ContactEnd end = ContactEnd::zero_force,
                        tangential::FrictionLimit lim = tangential::FrictionLimit::absolute, double omega0 = 0.0,
                        double kappa = 2.0 / 7.0) const {
    analytic::Input in;
    in.m = m, in.R = R, in.kn = kn, in.gn = gn, in.kt = kappa * kn, in.mu = mu;
    in.end = end, in.limit = lim;
    in.vn0 = speed * std::cos(theta_deg * kDeg);
    in.vt0 = speed * std::sin(theta_deg * kDeg);
    in.omega0 = omega0;
    return in;
  }
  ObliqueResult harness(double theta_deg, ContactEnd end, tangential::FrictionLimit lim, double omega0 = 0.0,
                        long steps = 100000, double kappa = 2.0 / 7.0) const {
    LsdLaw n;
    n.c = {kn, gn};
    n.end_mode = end;
    CundallStrackTangential t;
    t.p = {kappa * kn, 0.0, mu};
    t.limit = lim;
    ObliqueBodies b;
    b.m1 = m, b.R1 = R;
    ObliqueImpact im;
    im.speed = speed;
    im.angle = theta_deg * kDeg;
    im.omega1 = omega0;
    ObliqueOptions o;
    o.steps_per_contact = steps;
    return integrate_oblique(n, t, b, im, o);
  }
};

struct Row {
  double theta, beta, e_t, omega, rebound, slip_in, slip_out;
};
// physics_reference.md 8.5, kappa = 2/7 (independent fine-step reference).
const Row kTable[] = {
    {5, +0.99989, 0.42860, -194.22, -5.101, 0.9510, -0.9509},
    {10, +0.99982, 0.42862, -386.95, -10.197, 1.9166, -1.9163},
    {15, +0.99947, 0.42872, -576.64, -15.283, 2.9125, -2.9110},
    {20, +0.75121, 0.49965, -667.40, -15.588, 3.9562, -2.9719},
    {25, +0.36718, 0.60938, -643.83, -9.910, 5.0686, -1.8611},
    {30, +0.10427, 0.68449, -615.24, -3.515, 6.2755, -0.6544},
    {40, -0.24017, 0.78291, -544.23, +11.620, 9.1206, +2.1905},
    {60, -0.63189, 0.89483, -355.22, +48.156, 18.8266, +11.8964},
    {80, -0.88758, 0.96788, -123.37, +78.982, 61.6444, +54.7141},
};

void expect_table(const char* what, double theta, double got, double table, double last_digit, double rel_ref) {
  const double tol = 0.5 * last_digit + rel_ref * std::max(1.0, std::fabs(table));
  EXPECT_NEAR(got, table, tol) << what << " at theta = " << theta << " deg";
}

}  // namespace

TEST(Analytic, Table85Reproduced) {
  const AnaSetup s;
  std::printf("theta  beta        e_t       omega'    rebound(cp)  rebound(com)  t_c          switches\n");
  for (const Row& row : kTable) {
    const analytic::Output a = analytic::impact(s.input(row.theta));
    EXPECT_NEAR(a.e, 0.98008, 0.5e-5);
    std::printf("%5.0f  %+.7f  %.7f  %9.4f  %+9.5f  %+9.5f  %.6e ", row.theta, a.beta, a.e_t, a.omega,
                a.rebound_angle_contact / kDeg, a.rebound_angle_com / kDeg, a.contact_time);
    for (const auto& w : a.switches) std::printf(" %s@%.4f", w.sliding ? "slip" : "stick", w.t / a.contact_time);
    std::printf("\n");
    expect_table("beta", row.theta, a.beta, row.beta, 1e-5, 1.5e-5);
    expect_table("e_t", row.theta, a.e_t, row.e_t, 1e-5, 1.5e-5);
    expect_table("omega'", row.theta, a.omega, row.omega, 1e-2, 1.5e-5);
    expect_table("rebound angle (contact point)", row.theta, a.rebound_angle_contact / kDeg, row.rebound, 1e-3,
                 1.5e-5);
    expect_table("v_s0/(mu v_n0)", row.theta, a.slip_ratio_in, row.slip_in, 1e-4, 1e-12);
    expect_table("v_s'/(mu v_n0)", row.theta, a.slip_ratio_out, row.slip_out, 1e-4, 1.5e-5);
    EXPECT_NEAR(std::tan(a.rebound_angle_com), a.e_t * std::tan(row.theta * kDeg) / a.e, 1e-12);
    // stick at the start (F_n(0+) = gamma_n v_n0 > 0), slip at the end (F_n -> 0)
    EXPECT_FALSE(a.sliding_at_start);
    EXPECT_TRUE(a.sliding_at_end);
    ASSERT_FALSE(a.switches.empty());
    for (size_t i = 1; i < a.switches.size(); ++i) {
      EXPECT_GT(a.switches[i].t, a.switches[i - 1].t);
      EXPECT_NE(a.switches[i].sliding, a.switches[i - 1].sliding);
    }
    EXPECT_LT(a.switches.back().t, a.contact_time);
  }
}

// Collision modes (physics_reference 4.3): small angles stick until a final slip, larger angles
// slip after a short initial stick, the earlier the larger the angle. The switching times agree
// with the state changes the harness reports (1e5 steps per contact: within a few steps), in all
// configurations, with and without spin.
TEST(Analytic, SwitchingTimesAgreeWithHarness) {
  const AnaSetup s;
  const analytic::Output small = analytic::impact(s.input(10));
  ASSERT_EQ(small.switches.size(), 1u);
  EXPECT_TRUE(small.switches[0].sliding);
  EXPECT_GT(small.switches[0].t, 0.9 * small.contact_time);
  double prev = 1.0;
  for (double theta : {20.0, 25.0, 30.0, 40.0, 60.0, 80.0}) {
    const analytic::Output a = analytic::impact(s.input(theta));
    ASSERT_GE(a.switches.size(), 1u);
    EXPECT_TRUE(a.switches[0].sliding);
    EXPECT_LT(a.switches[0].t, prev) << theta;
    prev = a.switches[0].t;
  }
  std::printf("end           limit            theta omega0  switches (analytic | harness) [t/t_c]\n");
  for (ContactEnd end : {ContactEnd::zero_force, ContactEnd::zero_overlap}) {
    for (tangential::FrictionLimit lim : {tangential::FrictionLimit::absolute, tangential::FrictionLimit::positive_normal}) {
      if (end == ContactEnd::zero_force && lim == tangential::FrictionLimit::positive_normal) continue;
      for (double theta : {5.0, 15.0, 20.0, 25.0, 45.0, 80.0}) {
        for (double omega0 : {0.0, -600.0, 900.0}) {
          const analytic::Output a = analytic::impact(s.input(theta, end, lim, omega0));
          const ObliqueResult h = s.harness(theta, end, lim, omega0);
          std::printf("%-13s %-16s %5.0f %6.0f ", to_string(end), tangential::to_string(lim), theta, omega0);
          for (const auto& w : a.switches) std::printf(" %s@%.6f", w.sliding ? "slip" : "stick", w.t / a.contact_time);
          std::printf(" |");
          for (const auto& w : h.switches) std::printf(" %s@%.6f", w.sliding ? "slip" : "stick", w.t / a.contact_time);
          std::printf("\n");
          EXPECT_EQ(a.sliding_at_start, h.sliding_at_start);
          ASSERT_EQ(a.switches.size(), h.switches.size()) << theta << " " << omega0;
          for (size_t i = 0; i < a.switches.size(); ++i) {
            EXPECT_EQ(a.switches[i].sliding, h.switches[i].sliding);
            EXPECT_NEAR(a.switches[i].t, h.switches[i].t, 3.0 * h.dt) << theta << " " << omega0 << " switch " << i;
          }
        }
      }
    }
  }
}

// Normal closed forms: the two end conventions of physics_reference 8.1 (e = 0.8 row,
// m = 0.01, k = 1e5, gamma = 4.48097).
TEST(Analytic, NormalEndConventions81) {
  analytic::Input in;
  in.m = 0.01, in.R = 0.01, in.kn = 1e5, in.gn = 4.48097, in.kt = 1e4, in.mu = 0.3, in.vn0 = 1.0;
  in.end = ContactEnd::zero_overlap;
  analytic::Output a = analytic::impact(in);
  EXPECT_NEAR(a.e, 0.800000, 1e-6);
  EXPECT_NEAR(a.contact_time, 9.95962e-4, 1e-9);
  EXPECT_TRUE(a.switches.empty());  // no tangential motion
  EXPECT_EQ(a.vt, 0.0);
  in.end = ContactEnd::zero_force;
  a = analytic::impact(in);
  EXPECT_NEAR(a.e, 0.808099, 1e-6);
  EXPECT_NEAR(a.contact_time, 9.51001e-4, 1e-9);
}

// Against the harness (velocity Verlet, 1e5 steps per contact: first order, ~1e-7 from converged)
// in all four end/limit configurations, with and without initial spin.
TEST(Analytic, AgreesWithHarness) {
  const AnaSetup s;
  struct Case {
    ContactEnd end;
    tangential::FrictionLimit lim;
  };
  const Case cases[] = {{ContactEnd::zero_force, tangential::FrictionLimit::absolute},
                        {ContactEnd::zero_overlap, tangential::FrictionLimit::absolute},
                        {ContactEnd::zero_overlap, tangential::FrictionLimit::positive_normal}};
  std::printf("end           limit            theta omega0   beta(analytic) beta(harness)  |d beta|  |d e_t|  "
              "|d R omega'|/v  |d t_c|/t_c\n");
  double worst = 0.0;
  for (const Case& c : cases) {
    for (double theta : {5.0, 15.0, 20.0, 25.0, 30.0, 45.0, 80.0}) {
      for (double omega0 : {0.0, -600.0, 900.0}) {
        const analytic::Output a = analytic::impact(s.input(theta, c.end, c.lim, omega0));
        const ObliqueResult h = s.harness(theta, c.end, c.lim, omega0);
        ASSERT_TRUE(h.ended);
        const double db = std::fabs(a.beta - h.beta), det = std::fabs(a.e_t - h.e_t);
        const double dw = std::fabs(s.R * (a.omega - h.omega1)) / s.speed;
        const double dtc = std::fabs(a.contact_time - h.contact_time) / a.contact_time;
        std::printf("%-13s %-16s %5.0f %6.0f   %+.8f    %+.8f    %.1e  %.1e  %.1e  %.1e\n", to_string(c.end),
                    tangential::to_string(c.lim), theta, omega0, a.beta, h.beta, db, det, dw, dtc);
        EXPECT_NEAR(a.e, h.e, 1e-6);
        EXPECT_NEAR(a.beta, h.beta, 2e-6) << theta << " " << omega0;
        EXPECT_NEAR(a.e_t, h.e_t, 2e-6) << theta << " " << omega0;
        EXPECT_LT(dw, 2e-6) << theta << " " << omega0;
        EXPECT_NEAR(a.rebound_angle_contact, h.rebound_angle_contact, 2e-6);
        EXPECT_NEAR(a.rebound_angle_com, h.rebound_angle_com, 2e-6);
        EXPECT_LT(dtc, 2e-5);
        worst = std::max({worst, db, det, dw});
      }
    }
  }
  std::printf("worst difference: %.2e\n", worst);
}

// The attractive tail matters: with mu |F_n| it adds friction impulse, with mu max(F_n, 0) none.
TEST(Analytic, AttractionVariantsDiffer) {
  const AnaSetup s;
  const analytic::Output abs_ = analytic::impact(s.input(80, ContactEnd::zero_overlap));
  const analytic::Output pos = analytic::impact(s.input(80, ContactEnd::zero_overlap,
                                                         tangential::FrictionLimit::positive_normal));
  // gross sliding: |J_t| = int L dt; with max(F_n,0) that is mu * (impulse up to the zero of F_n)
  EXPECT_LT(std::fabs(pos.jt), std::fabs(abs_.jt));
  EXPECT_NEAR(abs_.e, 0.98, 1e-12);  // variant-A formulas give e exactly for zero_overlap
  EXPECT_GT(abs_.contact_time, abs_.t_zero_force);
}

// Gross sliding (v_s0/(mu v_n0) >= 3.5 (1+e)) and, to the short initial stick, the rigid-body
// closed form of rigid_body.h with the e of the normal law.
TEST(Analytic, GrossSlidingEqualsRigidBody) {
  const AnaSetup s;
  for (ContactEnd end : {ContactEnd::zero_force, ContactEnd::zero_overlap}) {
    for (double theta : {40.0, 50.0, 60.0, 70.0, 80.0, 85.0}) {
      const analytic::Input in = s.input(theta, end, tangential::FrictionLimit::positive_normal);
      const analytic::Output a = analytic::impact(in);
      rigid_body::Input rb;
      rb.e = a.e, rb.mu = s.mu, rb.beta0 = 1.0;
      rb.m1 = s.m, rb.R1 = s.R, rb.I1 = rigid_body::solid_sphere_inertia(s.m, s.R);
      rb.vn0 = in.vn0, rb.vt0 = in.vt0;
      const rigid_body::Output r = rigid_body::impact(rb);
      ASSERT_TRUE(r.gross_sliding);
      // the initial stick lasts ~1e-3 t_c: the friction impulse lost in it is of that order
      // relative; with positive_normal (zero_overlap) the friction impulse is mu * int max(F_n,0)
      // = mu m (v_n0 - xi'(t_zero)), which is not m (1+e) v_n0: compare with that impulse.
      const analytic::Normal nrm = analytic::make_normal(in);
      const double jn = end == ContactEnd::zero_force ? s.m * (1 + a.e) * in.vn0 : nrm.impulse(nrm.t_zero);
      if (end == ContactEnd::zero_force) {
        EXPECT_NEAR(a.vt, r.vt, 2e-5 * in.vt0) << theta;
        EXPECT_NEAR(s.R * a.omega, s.R * r.omega1, 2e-5 * in.vt0) << theta;
        EXPECT_NEAR(a.beta, r.beta, 3e-5) << theta;
        EXPECT_NEAR(a.e_t, r.e_t, 2e-5) << theta;
        EXPECT_NEAR(a.rebound_angle_contact, r.rebound_angle_contact, 2e-5) << theta;
        EXPECT_NEAR(a.rebound_angle_com, r.rebound_angle_com, 2e-5) << theta;
      }
      EXPECT_NEAR(a.jt, -s.mu * jn, 5e-5 * s.mu * jn) << theta;
      EXPECT_TRUE(a.sliding_at_end);
    }
  }
  // zero_force with gamma = 0: F_n(0) = 0, so the contact slides from the start and matches
  // the rigid body exactly (e = 1).
  analytic::Input in = s.input(60);
  in.gn = 0.0;
  const analytic::Output a = analytic::impact(in);
  EXPECT_TRUE(a.sliding_at_start);
  EXPECT_TRUE(a.switches.empty());
  EXPECT_NEAR(a.e, 1.0, 1e-14);
  EXPECT_NEAR(a.vt, in.vt0 - 2.0 * s.mu * in.vn0, 1e-12);
  EXPECT_NEAR(s.R * a.omega, -2.5 * 2.0 * s.mu * in.vn0, 1e-12);
}

// With damping the contact always slips before the end (F_n -> 0). Without damping, kappa = 2/7
// and the zero_overlap end, s(t) and F_n(t) are proportional sinusoids: below
// v_s0/(mu v_n0) = 1/kappa the contact sticks to the end and v_s' = -v_s0 (beta = 1, e_t = 3/7).
TEST(Analytic, UndampedStickThroughout) {
  const AnaSetup s;
  analytic::Input in = s.input(10, ContactEnd::zero_overlap);
  in.gn = 0.0;
  const analytic::Output a = analytic::impact(in);
  EXPECT_NEAR(a.beta, 1.0, 1e-9);
  EXPECT_NEAR(a.e_t, 3.0 / 7.0, 1e-9);
  EXPECT_NEAR(a.e, 1.0, 1e-14);
}

TEST(Analytic, BadInput) {
  const AnaSetup s;
  analytic::Input in = s.input(10);
  in.gn = 3.0 * std::sqrt(in.kn * in.m);
  try {
    analytic::impact(in);
    FAIL() << "overdamped input accepted";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("normal damping gamma_n"), std::string::npos) << e.what();
  }
  in = s.input(10);
  in.vn0 = -1.0;
  EXPECT_THROW(analytic::impact(in), std::domain_error);
  in = s.input(10);
  in.kt = 0.0;
  EXPECT_THROW(analytic::impact(in), std::domain_error);
}

// The harness converges to the closed form at first order (its velocity-Verlet scheme with
// velocity-dependent forces): the difference shrinks ~4x per 4x steps, in the attractive-tail
// case with spin where it is largest at 1e5 steps.
TEST(Analytic, HarnessConvergesToClosedForm) {
  const AnaSetup s;
  for (double omega0 : {0.0, -600.0}) {
    const analytic::Output a =
        analytic::impact(s.input(25, ContactEnd::zero_overlap, tangential::FrictionLimit::absolute, omega0));
    double prev = NAN;
    for (long n : {100000L, 400000L, 1600000L}) {
      const ObliqueResult h = s.harness(25, ContactEnd::zero_overlap, tangential::FrictionLimit::absolute, omega0, n);
      const double d = std::fabs(h.beta - a.beta) + std::fabs(h.e_t - a.e_t);
      std::printf("omega0 %6.0f steps %7ld  |d beta| + |d e_t| = %.3e\n", omega0, n, d);
      if (!std::isnan(prev)) {
        EXPECT_LT(d, prev / 3.0) << n;
        EXPECT_GT(d, prev / 8.0) << n;  // first order (second would give 1/16)
      }
      prev = d;
    }
  }
}

// Frictionless (mu = 0): no tangential impulse at all, in both end conventions.
TEST(Analytic, Frictionless) {
  AnaSetup s;
  s.mu = 0.0;
  for (ContactEnd end : {ContactEnd::zero_force, ContactEnd::zero_overlap}) {
    const analytic::Input in = s.input(30, end, tangential::FrictionLimit::absolute, 500.0);
    const analytic::Output a = analytic::impact(in);
    EXPECT_EQ(a.jt, 0.0);
    EXPECT_EQ(a.vt, in.vt0);
    EXPECT_EQ(a.omega, 500.0);
    EXPECT_NEAR(a.beta, -1.0, 1e-15);
  }
}
