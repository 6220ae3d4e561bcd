// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the tangential laws of issue 4 on the common interface (common.h):
//  * for every law: Coulomb cap with both FrictionLimit choices (also F_n < 0), update == false
//    gives the force of the update and leaves the history alone, sign flip when the pair is seen
//    from the other particle, objectivity under large rigid rotations of a loaded contact;
//  * linear laws: Haff-Werner limit, the elastic-perfectly-plastic loop of the Cundall-Strack
//    spring under a displacement cycle (closed form and dissipated energy), stick-slip of the
//    spring-dashpot for both reset rules, stiffness from kappa;
//  * parameters.h: contact-point masses, kappa of Hertz-Mindlin, beta_0 round trips through an
//    independent RK4 integration of the sticking contact-point oscillator, mu from a
//    gross-sliding impact, bad input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/tangential/common.h"
#include "contact/tangential/di_renzo.h"
#include "contact/tangential/haff_werner.h"
#include "contact/tangential/linear_spring.h"
#include "contact/tangential/mindlin_deresiewicz.h"
#include "contact/tangential/mindlin_no_slip.h"
#include "contact/tangential/parameters.h"
#include "contact/tangential/walton_braun_tangential.h"

namespace tg = tdem::tangential;
using FL = tg::FrictionLimit;
using V3 = std::array<double, 3>;
using Kin = tg::TangentialKinematics<double>;

namespace {

double norm(const V3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double dist(const V3& a, const V3& b) { return norm({a[0] - b[0], a[1] - b[1], a[2] - b[2]}); }

Kin kin(const V3& n, const V3& vt, double dt, double fn, double spin = 0.0, const V3& omega_t = {0, 0, 0}) {
  Kin k{};
  for (int i = 0; i < 3; ++i) k.omega_t[i] = omega_t[i];
  for (int i = 0; i < 3; ++i) k.n[i] = n[i], k.vt[i] = vt[i];
  k.spin_n = spin;
  k.dt = dt;
  k.overlap = 1e-5;
  k.meff = 1e-3;
  k.reff = 2e-3;
  k.fn = fn;
  k.kn = 2e5;
  k.gamman = 0.5;
  return k;
}

// A law behind a uniform call, for the tests that every law must pass.
struct Law {
  std::string name;
  int history_size;
  std::vector<bool> flips;
  std::function<bool(const Kin&, double*, bool, double*)> force;
  bool memory;  // has a stored tangential state (objectivity applies)
};

#define TDEM_MAKE_LAW(NS, NAME, ...)                                                           \
  [&] {                                                                                        \
    Law l;                                                                                     \
    l.name = NAME;                                                                             \
    l.history_size = NS::history_size;                                                         \
    for (int i = 0; i < NS::history_size; ++i) l.flips.push_back(NS::history[i].flips_sign);   \
    const auto p = __VA_ARGS__;                                                                \
    l.force = [p](const Kin& k, double* h, bool u, double* f) { return NS::force(p, k, h, u, f); }; \
    l.memory = NS::history_size > 0;                                                           \
    return l;                                                                                  \
  }()

namespace hw = tdem::haff_werner;
namespace ls = tdem::linear_spring;
namespace mns = tdem::mindlin_no_slip;
namespace drm = tdem::di_renzo;
namespace wbt = tdem::walton_braun_tangential;
namespace md = tdem::mindlin_deresiewicz;

std::vector<Law> all_laws(FL limit, double mu = 0.3) {
  std::vector<Law> v;
  {
    Law l;
    l.name = "haff_werner";
    l.history_size = hw::history_size;
    l.memory = false;
    const hw::Params<double> p{50.0, mu, limit};
    l.force = [p](const Kin& k, double* h, bool u, double* f) { return hw::force(p, k, h, u, f); };
    v.push_back(l);
  }
  auto cs = ls::cundall_strack(2e5, mu, limit);
  v.push_back(TDEM_MAKE_LAW(ls, "cundall_strack", cs));
  v.push_back(TDEM_MAKE_LAW(ls, "spring_dashpot/spring_only",
                           ls::spring_dashpot(2e5, 3.0, mu, tg::SlipReset::spring_only, limit)));
  v.push_back(TDEM_MAKE_LAW(ls, "spring_dashpot/spring_and_dashpot",
                           ls::spring_dashpot(2e5, 3.0, mu, tg::SlipReset::spring_and_dashpot, limit)));
  v.push_back(TDEM_MAKE_LAW(mns, "tsuji", mns::Params<double>{3e10, 1.0, mu, limit}));
  v.push_back(TDEM_MAKE_LAW(drm, "di_renzo", drm::Params<double>{3e10, mu, limit}));
  v.push_back(TDEM_MAKE_LAW(wbt, "walton_braun", wbt::Params<double>{0.0, 1.0, mu, limit}));
  v.push_back(TDEM_MAKE_LAW(md, "mindlin_deresiewicz", md::Params<double>{3e10, mu, limit}));
  return v;
}

// Loads a contact along a direction by n_steps steps of velocity v (normal n), returns the force.
V3 load(const Law& l, double* h, const V3& n, const V3& v, int n_steps, double dt, double fn) {
  V3 f{};
  for (int i = 0; i < n_steps; ++i) l.force(kin(n, v, dt, fn), h, true, f.data());
  return f;
}

// Loads with velocity v until |F| passes 0.15 of the limit (mu = 0.3), then returns the force of a
// step with v_t = 0 (no dashpot part): the elastic force that the rotation must carry along.
V3 load_to(const Law& l, double* h, const V3& n, const V3& v, double dt, double fn) {
  V3 f{};
  for (int i = 0; i < 1000000 && norm(f) < 0.15 * 0.3 * fn; ++i) l.force(kin(n, v, dt, fn), h, true, f.data());
  l.force(kin(n, {0, 0, 0}, dt, fn), h, true, f.data());
  return f;
}

V3 rot(const V3& axis, double phi, const V3& s) {
  V3 r = s;
  tg::rotate_about(axis.data(), phi, r.data());
  return r;
}

}  // namespace

TEST(TangentialAllLaws, CoulombCapForBothLimitChoicesAndNegativeNormalForce) {
  const double mu = 0.3, dt = 1e-5;
  const V3 n{0, 0, 1}, v{0.6, -0.8, 0.0};
  for (FL limit : {FL::absolute, FL::positive_normal}) {
    for (double fn : {10.0, -10.0, 0.0}) {
      for (const Law& l : all_laws(limit, mu)) {
        std::vector<double> h(l.history_size + 1, 0.0);
        // Far beyond sticking: 2000 steps of 6 um each.
        V3 f{};
        bool sliding = false;
        double fmax = 0.0;
        for (int i = 0; i < 2000; ++i) {
          sliding = l.force(kin(n, {v[0] * 300, v[1] * 300, 0}, dt, fn), h.data(), true, f.data());
          fmax = std::max(fmax, norm(f));
        }
        const double expected = limit == FL::absolute ? mu * std::fabs(fn) : std::max(fn, 0.0) * mu;
        EXPECT_NEAR(norm(f), expected, 1e-12 * (1.0 + expected)) << l.name << " fn " << fn;
        EXPECT_LE(fmax, expected * (1.0 + 1e-13) + 1e-300) << l.name << " fn " << fn;
        if (expected > 0.0) {
          EXPECT_TRUE(sliding) << l.name << " fn " << fn;
          // The force opposes the slip.
          EXPECT_NEAR(f[0] / norm(f), -v[0], 1e-9) << l.name;
          EXPECT_NEAR(f[1] / norm(f), -v[1], 1e-9) << l.name;
        }
      }
    }
  }
}

TEST(TangentialAllLaws, UpdateFalseGivesTheSameForceAndKeepsTheHistory) {
  const V3 n{0, 0, 1};
  for (const Law& l : all_laws(FL::absolute)) {
    std::vector<double> h(l.history_size + 1, 0.0);
    // A path with a reversal and a change of direction.
    load(l, h.data(), n, {0.1, 0.0, 0}, 30, 1e-5, 10.0);
    load(l, h.data(), n, {-0.05, 0.03, 0}, 10, 1e-5, 12.0);
    for (const V3& v : {V3{0.02, 0.01, 0}, V3{-0.3, 0.0, 0}, V3{0.0, 5.0, 0.0}}) {
      std::vector<double> h1 = h, h2 = h;
      V3 f1{}, f2{};
      const bool s1 = l.force(kin(n, v, 1e-5, 11.0, 30.0), h1.data(), false, f1.data());
      const bool s2 = l.force(kin(n, v, 1e-5, 11.0, 30.0), h2.data(), true, f2.data());
      EXPECT_EQ(h1, h) << l.name;
      EXPECT_EQ(s1, s2) << l.name;
      for (int i = 0; i < 3; ++i) EXPECT_EQ(f1[i], f2[i]) << l.name;
    }
  }
}

TEST(TangentialAllLaws, SeenFromTheOtherParticleTheForceFlips) {
  // Seen from j: n, v_t, spin_n = (w_i + w_j)/2 . n and every flipping history slot change sign.
  const V3 n{0.0, 0.6, 0.8};
  const V3 v1{0.1, 0.08, -0.06}, v2{-0.2, 0.3, -0.225};  // tangential to n
  for (const Law& l : all_laws(FL::positive_normal)) {
    std::vector<double> hi(l.history_size + 1, 0.0);
    load(l, hi.data(), n, v1, 40, 1e-5, 8.0);
    std::vector<double> hj = hi;
    for (int s = 0; s < l.history_size; ++s)
      if (l.flips[s]) hj[s] = -hj[s];
    for (int step = 0; step < 30; ++step) {
      const V3 v = step < 15 ? v2 : v1;
      V3 fi{}, fj{};
      const double fn = 8.0 + 0.1 * step;
      const bool si = l.force(kin(n, v, 1e-5, fn, 20.0), hi.data(), true, fi.data());
      const bool sj = l.force(kin({-n[0], -n[1], -n[2]}, {-v[0], -v[1], -v[2]}, 1e-5, fn, -20.0), hj.data(),
                              true, fj.data());
      EXPECT_EQ(si, sj) << l.name;
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(fj[i], -fi[i], 1e-12 * (1.0 + norm(fi))) << l.name << " step " << step;
      for (int s = 0; s < l.history_size; ++s)
        EXPECT_NEAR(hj[s], l.flips[s] ? -hi[s] : hi[s], 1e-12 * (1.0 + std::fabs(hi[s]))) << l.name << " slot " << s;
    }
  }
}

TEST(TangentialAllLaws, ObjectiveUnderLargeRigidRotations) {
  // Load along x (normal z), then turn the pair rigidly by 90 deg in 10^3 steps with v_t = 0:
  // (a) about y (an axis in the tangent plane, spin_n = 0), (b) about the normal
  // (spin_n = omega), (c) about x (along the force). The force must rotate with the pair and
  // keep its magnitude.
  const int steps = 1000;
  const double dt = 1e-5, phi = 0.5 * M_PI, omega = phi / (steps * dt), fn = 10.0;
  const V3 z{0, 0, 1}, y{0, 1, 0}, x{1, 0, 0};
  for (const Law& l : all_laws(FL::absolute)) {
    if (!l.memory) continue;
    for (int c = 0; c < 3; ++c) {
      std::vector<double> h(l.history_size + 1, 0.0);
      const V3 f0 = load_to(l, h.data(), z, {1e-4, 0.0, 0.0}, dt, fn);  // sticking: |F| < mu Fn
      ASSERT_GT(norm(f0), 0.04 * fn) << l.name;
      ASSERT_LT(norm(f0), 0.1 * fn) << l.name;
      const V3 axis = c == 0 ? y : (c == 1 ? z : x);
      V3 f{};
      for (int i = 1; i <= steps; ++i) {
        const V3 n = rot(axis, phi * i / steps, z);
        l.force(kin(n, {0, 0, 0}, dt, fn, c == 1 ? omega : 0.0), h.data(), true, f.data());
      }
      const V3 expected = rot(axis, phi, f0);
      EXPECT_NEAR(norm(f), norm(f0), 1e-9 * norm(f0)) << l.name << " case " << c;
      EXPECT_LT(dist(f, expected), 1e-9 * norm(f0)) << l.name << " case " << c;
    }
    // A force with components along and across the in-plane axis: without the turning rate of
    // the normal the magnitude is kept to 1e-9 and the direction follows to O(step angle)
    // (projection and rescaling only); with omega_t given the rotation is exact.
    for (bool with_rate : {false, true}) {
      std::vector<double> h(l.history_size + 1, 0.0);
      const V3 f0 = load_to(l, h.data(), z, {0.6e-4, 0.8e-4, 0.0}, dt, fn);
      const V3 rate = with_rate ? V3{0, omega, 0} : V3{0, 0, 0};
      V3 f{};
      for (int i = 1; i <= steps; ++i)
        l.force(kin(rot(y, phi * i / steps, z), {0, 0, 0}, dt, fn, 0.0, rate), h.data(), true, f.data());
      EXPECT_NEAR(norm(f), norm(f0), 1e-9 * norm(f0)) << l.name;
      EXPECT_LT(dist(f, rot(y, phi, f0)), (with_rate ? 1e-9 : 3e-3) * norm(f0)) << l.name << " rate " << with_rate;
    }
    // A general axis (not in the tangent plane, not along the force): turning rate and twist.
    {
      std::vector<double> h(l.history_size + 1, 0.0);
      const V3 f0 = load_to(l, h.data(), z, {0.6e-4, 0.8e-4, 0.0}, dt, fn);
      const double a = 1.0 / std::sqrt(3.0);
      const V3 ax{a, -a, a};
      V3 f{};
      for (int i = 1; i <= steps; ++i) {
        const V3 n = rot(ax, phi * i / steps, z);
        const double wn = omega * (ax[0] * n[0] + ax[1] * n[1] + ax[2] * n[2]);
        const V3 wt{omega * ax[0] - wn * n[0], omega * ax[1] - wn * n[1], omega * ax[2] - wn * n[2]};
        l.force(kin(n, {0, 0, 0}, dt, fn, wn, wt), h.data(), true, f.data());
      }
      EXPECT_NEAR(norm(f), norm(f0), 1e-9 * norm(f0)) << l.name;
      EXPECT_LT(dist(f, rot(ax, phi, f0)), 1e-8 * norm(f0)) << l.name << " general axis";
    }
  }
}

// ------------------------------------------------------------------ linear laws

TEST(TangentialHaffWerner, ForceIsMinOfViscousAndCoulomb) {
  const hw::Params<double> p{40.0, 0.25, FL::absolute};
  hw::validate(p);
  EXPECT_EQ(hw::history_size, 0);
  for (double speed : {0.0, 1e-3, 0.01, 0.1, 0.5, 2.0}) {
    for (double fn : {4.0, -4.0}) {
      const V3 dir{0.28, -0.96, 0.0};
      V3 f{};
      const bool sliding = hw::force(p, kin({0, 0, 1}, {dir[0] * speed, dir[1] * speed, 0}, 1e-5, fn), static_cast<double*>(nullptr),
                                     true, f.data());
      const double expected = std::min(p.gammat * speed, p.mu * std::fabs(fn));
      EXPECT_NEAR(norm(f), expected, 1e-14) << speed;
      if (speed > 0) {
        EXPECT_NEAR(f[0], -expected * dir[0], 1e-14);
        EXPECT_NEAR(f[1], -expected * dir[1], 1e-14);
      }
      EXPECT_EQ(sliding, p.gammat * speed > p.mu * std::fabs(fn)) << speed;
    }
  }
}

TEST(TangentialLinearSpring, CoulombLoopUnderADisplacementCycle) {
  // Cundall-Strack, displacement delta(t) along x: 0 -> A -> -A -> A. Elastic-perfectly-plastic
  // closed form with L = mu F_n:
  //   loading        T = min(k delta, L)
  //   unloading      T = max(L - k (A - delta), -L)
  //   reloading      T = min(-L + k (delta + A), L)
  // Sliding while the elastic trial passes L. Dissipated energy over the closed
  // loop (A -> -A -> A): 2 L (2A - 2L/k) = 4 L (A - L/k).
  const double k = 1e5, mu = 0.4, fn = 5.0, L = mu * fn, A = 3.0 * L / k;
  const auto p = ls::cundall_strack(k, mu);
  ls::validate(p);
  const int n = 3000;
  const double dd = A / n, dt = 1e-6, v = dd / dt;
  double h[3] = {0, 0, 0}, delta = 0.0, work = 0.0, t_prev = 0.0, t_expected_prev = 0.0;
  auto step = [&](double sgn, int phase) {
    V3 f{};
    const bool sliding = ls::force(p, kin({0, 0, 1}, {sgn * v, 0, 0}, dt, fn), h, true, f.data());
    delta += sgn * dd;
    const double t = -f[0];
    double expected;
    if (phase == 0) expected = std::min(k * delta, L);
    else if (phase == 1) expected = std::max(L - k * (A - delta), -L);
    else expected = std::min(-L + k * (delta + A), L);
    EXPECT_NEAR(t, expected, 1e-9 * L) << "phase " << phase << " delta " << delta;
    EXPECT_NEAR(f[1], 0.0, 1e-15);
    // Sliding exactly when the elastic trial T_prev + k d(delta) (closed form) passes the limit.
    const double trial = std::fabs(t_expected_prev + sgn * k * dd);
    if (std::fabs(trial - L) > 1e-9 * L) {
      EXPECT_EQ(sliding, trial > L) << "phase " << phase << " delta " << delta;
    }
    t_expected_prev = expected;
    if (phase > 0) work += 0.5 * (t + t_prev) * sgn * dd;
    t_prev = t;
  };
  for (int i = 0; i < n; ++i) step(1.0, 0);
  for (int i = 0; i < 2 * n; ++i) step(-1.0, 1);
  for (int i = 0; i < 2 * n; ++i) step(1.0, 2);
  EXPECT_NEAR(work, 4.0 * L * (A - L / k), 1e-6 * 4.0 * L * A);
}

TEST(TangentialLinearSpring, SpringDashpotStickSlipForBothResetRules) {
  // Constant slip velocity v for t1, then -v. Sticking: T = k v t + gamma v.
  // spring_only: the force is capped at L as soon as k v t + gamma v > L (spring kept growing)
  //   and the spring is truncated once k s > L, to s = L/k. After the reversal
  //   T = k (L/k - v tau) - gamma v = L - gamma v - k v tau.
  // spring_and_dashpot: while sliding k s + gamma v = L, so s = (L - gamma v)/k, and after the
  //   reversal T = L - 2 gamma v - k v tau.
  const double k = 2e5, g = 20.0, mu = 0.5, fn = 4.0, L = mu * fn, v = 0.05, dt = 1e-6;
  for (auto reset : {tg::SlipReset::spring_only, tg::SlipReset::spring_and_dashpot}) {
    const auto p = ls::spring_dashpot(k, g, mu, reset);
    double h[3] = {0, 0, 0};
    const int n1 = 400;  // k v t1 = 4 > L: ends in sliding
    for (int i = 1; i <= n1; ++i) {
      V3 f{};
      const bool sliding = ls::force(p, kin({0, 0, 1}, {v, 0, 0}, dt, fn), h, true, f.data());
      const double stick = k * v * dt * i + g * v;
      EXPECT_NEAR(-f[0], std::min(stick, L), 1e-10) << i;
      if (std::fabs(stick - L) > 1e-9 * L) {
        EXPECT_EQ(sliding, stick > L) << i;
      }
    }
    const double s_expected = reset == tg::SlipReset::spring_only ? L / k : (L - g * v) / k;
    EXPECT_NEAR(h[0], s_expected, 1e-15);
    for (int i = 1; i <= 50; ++i) {
      V3 f{};
      ls::force(p, kin({0, 0, 1}, {-v, 0, 0}, dt, fn), h, true, f.data());
      const double expected = k * (s_expected - v * dt * i) - g * v;
      EXPECT_NEAR(-f[0], expected, 1e-10) << i;
    }
  }
}

TEST(TangentialLinearSpring, StiffnessFromKappaTimesNormalStiffness) {
  ls::Params<double> p{0.0, 2.0 / 7.0, 0.0, 0.5, FL::absolute, tg::SlipReset::spring_only};
  ls::validate(p);
  double h[3] = {0, 0, 0};
  V3 f{};
  Kin k = kin({0, 0, 1}, {0.0, 0.02, 0}, 1e-5, 100.0);
  k.kn = 7e5;
  ls::force(p, k, h, true, f.data());
  EXPECT_NEAR(f[1], -2e5 * 0.02 * 1e-5, 1e-15);
}

// ------------------------------------------------------------------ parameters

namespace {
// RK4 of the sticking contact-point oscillator m s'' = -k s - g s', s(0) = 0, s'(0) = v0, over t_n;
// returns beta = -s'(t_n)/v0.
double sticking_beta(double m, double k, double g, double tn, int n = 20000) {
  double s = 0.0, v = 1.0;
  const double h = tn / n;
  auto acc = [&](double s_, double v_) { return (-k * s_ - g * v_) / m; };
  for (int i = 0; i < n; ++i) {
    const double k1s = v, k1v = acc(s, v);
    const double k2s = v + 0.5 * h * k1v, k2v = acc(s + 0.5 * h * k1s, v + 0.5 * h * k1v);
    const double k3s = v + 0.5 * h * k2v, k3v = acc(s + 0.5 * h * k2s, v + 0.5 * h * k2v);
    const double k4s = v + h * k3v, k4v = acc(s + h * k3s, v + h * k3v);
    s += h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return -v;
}
}  // namespace

TEST(TangentialParameters, ContactPointMassAndKappa) {
  const double m = 2.617994e-4, R = 2.5e-3, I = tg::solid_sphere_inertia(m, R);
  EXPECT_NEAR(tg::contact_point_mass(m, R, I), 2.0 / 7.0 * m, 1e-15 * m);
  EXPECT_NEAR(tg::contact_point_mass(m, R, I, m, R, I), m / 7.0, 1e-15 * m);
  EXPECT_NEAR(tg::contact_point_mass(m, R, I, m, R, I) / tg::normal_mass(m, m), 2.0 / 7.0, 1e-14);
  EXPECT_NEAR(tg::contact_point_mass(m, R, I) / tg::normal_mass(m), 2.0 / 7.0, 1e-14);
  // G*: 1/G* = (2-nu1)/G1 + (2-nu2)/G2 written out for Al2O3 on glass.
  const double G1 = 380e9 / 2.46, G2 = 70e9 / 2.5;
  EXPECT_NEAR(tg::effective_shear_modulus_from_E(380e9, 0.23, 70e9, 0.25), 1.0 / (1.77 / G1 + 1.75 / G2), 1e-3);
  EXPECT_NEAR(tg::effective_shear_modulus_from_E(380e9, 0.23, std::numeric_limits<double>::infinity(), 0.25),
              G1 / 1.77, 1e-3);
  // Like materials: 4 G*/E* = 2(1-nu)/(2-nu) (Hertz tangent 2 E* a vs Mindlin 8 G* a).
  for (double nu : {0.0, 0.23, 0.3, 0.45}) {
    const double gs = tg::effective_shear_modulus_from_E(2e11, nu, 2e11, nu);
    const double es = tg::effective_youngs_modulus(2e11, nu, 2e11, nu);
    EXPECT_NEAR(tg::kappa_hertz_mindlin(gs, es), 2 * (1 - nu) / (2 - nu), 1e-14);
    EXPECT_NEAR(tg::kappa_hertz_mindlin(nu), 2 * (1 - nu) / (2 - nu), 1e-15);
  }
  EXPECT_NEAR(tg::mindlin_stiffness(1e10, 2e-3, 1e-6), 8e10 * std::sqrt(2e-9), 1e-3);
  EXPECT_DOUBLE_EQ(tg::stiffness_from_kappa(2.0 / 7.0, 7e5), 2e5);
}

TEST(TangentialParameters, Beta0RoundTripThroughAStickingOscillator) {
  const double mt = 2.0 / 7.0 * 2.617994e-4, tn = 1e-5;
  for (double beta0 : {-0.5, 0.0, 0.3, 0.7, 1.0}) {
    const double kt = tg::stiffness_from_beta0(beta0, tn, mt);
    EXPECT_NEAR(sticking_beta(mt, kt, 0.0, tn), beta0, 1e-9) << beta0;
  }
  for (double beta0 : {0.05, 0.3, 0.7, 0.98, 1.0}) {
    const auto sd = tg::spring_dashpot_from_beta0(beta0, tn, mt);
    EXPECT_NEAR(sticking_beta(mt, sd.kt, sd.gammat, tn), beta0, 1e-9) << beta0;
  }
  // kappa = 2/7 and gamma_t = (2/7) gamma_n give beta_0 = e for the normal LSD contact
  // (physics_reference 3.4): k_n, gamma_n of e = 0.8, t_n with m* = m.
  const double m = 2.617994e-4, e = 0.8, l = std::log(e);
  const double kn = m * (M_PI * M_PI + l * l) / (tn * tn), gn = -2 * m * l / tn;
  EXPECT_NEAR(sticking_beta(2.0 / 7.0 * m, 2.0 / 7.0 * kn, 2.0 / 7.0 * gn, tn), e, 1e-9);
}

TEST(TangentialParameters, FrictionFromAGrossSlidingImpact) {
  // Independent integration of a sphere-wall impact: LSD normal (no attraction), friction always
  // at the Coulomb limit (Haff-Werner with a huge gamma_t), symplectic Euler with 2e5 steps.
  // mu recovered from (v_s0 - v_s') and the realised e must be the mu put in.
  const double m = 2.617994e-4, R = 2.5e-3, I = tg::solid_sphere_inertia(m, R), mu = 0.092;
  const double kn = 2.583963e7, gn = 1.057811, vn0 = 1.0, vt0 = 3.0;
  const hw::Params<double> p{1e9, mu, FL::positive_normal};
  double xi = 0.0, xid = vn0, vt = vt0, w = 0.0;
  const double dt = 1e-5 / 2e5;
  for (int i = 0; i < 10000000 && xi >= 0.0; ++i) {
    const double fn = std::max(kn * xi + gn * xid, 0.0);
    const double vs = vt + R * w;
    V3 f{};
    hw::force(p, kin({0, 0, 1}, {vs, 0, 0}, dt, fn), static_cast<double*>(nullptr), true, f.data());
    xid -= fn / m * dt;
    vt += f[0] / m * dt;
    w += R * f[0] / I * dt;
    xi += xid * dt;
  }
  const double e = -xid / vn0, vs1 = vt + R * w;
  const double mu_fit = tg::friction_from_gross_sliding(vt0, vs1, vn0, e, m, tg::contact_point_mass(m, R, I));
  EXPECT_NEAR(mu_fit, mu, 2e-4 * mu);
  EXPECT_GT(vs1, 0.0);  // really sliding throughout
}

TEST(TangentialParameters, BadInputNamesKeywordValueAndRange) {
  auto expect_msg = [](const std::function<void()>& f, const std::string& what, const std::string& value) {
    try {
      f();
      ADD_FAILURE() << "no exception for " << what;
    } catch (const std::domain_error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_NE(m.find(value), std::string::npos) << m;
      EXPECT_NE(m.find("range"), std::string::npos) << m;
    }
  };
  expect_msg([] { hw::validate({-1.0, 0.3, FL::absolute}); }, "gamma_t", "-1");
  expect_msg([] { hw::validate({1.0, -0.3, FL::absolute}); }, "friction coefficient mu", "-0.3");
  expect_msg([] { ls::validate(ls::cundall_strack(-5.0, 0.3)); }, "tangential stiffness k_t", "-5");
  expect_msg([] { ls::validate(ls::cundall_strack(0.0, 0.3)); }, "k_t", "0");
  expect_msg([] { ls::validate(ls::spring_dashpot(1e5, -2.0, 0.3)); }, "gamma_t", "-2");
  expect_msg([] { tg::stiffness_from_beta0(1.5, 1e-5, 1e-4); }, "beta_0", "1.5");
  expect_msg([] { tg::spring_dashpot_from_beta0(-0.2, 1e-5, 1e-4); }, "beta_0", "-0.2");
  expect_msg([] { tg::spring_dashpot_from_beta0(0.5, 0.0, 1e-4); }, "contact time t_n", "0");
  expect_msg([] { tg::shear_modulus(1e9, 0.7); }, "Poisson's ratio nu", "0.7");
  expect_msg([] { tg::contact_point_mass(-1.0, 1e-3, 1e-9); }, "mass m1", "-1");
  expect_msg([] { tg::friction_from_gross_sliding(1.0, 2.0, 1.0, 0.9, 1.0, 0.3); }, "friction coefficient mu", "-");
  expect_msg([] { wbt::validate({0.0, 0.0, 0.3, FL::absolute}); }, "k_t0", "0");
}
