// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the Cundall-Strack tangential law: sticking spring-dashpot, Coulomb cap and
// spring truncation for both slip rules, stick-slip switching under a prescribed tangential
// displacement, projection into the tangent plane, rigid rotation of a loaded contact and the
// sign flip when the pair is seen from the other particle.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "contact/tangential/cundall_strack.h"

namespace cs = tdem::cundall_strack;
using cs::SlipRule;
using V3 = std::array<double, 3>;

namespace {
double norm(const V3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

cs::Kinematics<double> kin_unit(const V3& n, const V3& vt, double dt) {
  return {{n[0], n[1], n[2]}, 1.0, {vt[0], vt[1], vt[2]}, dt};
}
}  // namespace

TEST(CundallStrack, SticksAsSpringPlusDashpot) {
  const cs::Params<double> p{1e4, 2.0, 0.5};
  for (SlipRule rule : {SlipRule::spring_cap, SlipRule::spring_dashpot_cap}) {
    V3 s{0, 0, 0}, f{};
    const double dt = 1e-5;
    const V3 vt{0.1, -0.2, 0.0};
    cs::force(rule, p, kin_unit({0, 0, 1}, vt, dt), 100.0, true, s.data(), f.data());
    for (int k = 0; k < 3; ++k) {
      EXPECT_DOUBLE_EQ(s[k], vt[k] * dt);
      EXPECT_DOUBLE_EQ(f[k], -(p.kt * vt[k] * dt + p.gammat * vt[k]));
    }
  }
}

TEST(CundallStrack, CoulombCapAndSpringTruncation) {
  const cs::Params<double> p{1e4, 3.0, 0.4};
  const double fn = 10.0, dt = 1e-4;
  const V3 vt{2.0, 1.0, 0.0};
  // spring cap: |F| = mu Fn, spring truncated so that k|s| = mu Fn, dashpot off while sliding.
  {
    V3 s{0.01, 0.0, 0.0}, f{};
    cs::force<SlipRule::spring_cap>(p, kin_unit({0, 0, 1}, vt, dt), fn, true, s.data(), f.data());
    EXPECT_NEAR(norm(f), p.mu * fn, 1e-12);
    EXPECT_NEAR(p.kt * norm(s), p.mu * fn, 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], -p.kt * s[k], 1e-12);
  }
  // spring-dashpot cap: |F| = mu Fn and F = -(k s + gamma v).
  {
    V3 s{0.01, 0.0, 0.0}, f{};
    cs::force<SlipRule::spring_dashpot_cap>(p, kin_unit({0, 0, 1}, vt, dt), fn, true, s.data(), f.data());
    EXPECT_NEAR(norm(f), p.mu * fn, 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], -(p.kt * s[k] + p.gammat * vt[k]), 1e-12);
  }
  // Attractive normal force: the limit uses |Fn|.
  {
    V3 s{0.01, 0.0, 0.0}, f{};
    cs::force<SlipRule::spring_cap>(p, kin_unit({0, 0, 1}, {0, 0, 0}, dt), -fn, true, s.data(), f.data());
    EXPECT_NEAR(norm(f), p.mu * fn, 1e-12);
  }
}

TEST(CundallStrackSwitching, PrescribedDisplacementCycle) {
  // Constant normal force, tangential velocity +v for T then -v: the force grows as k v t until
  // mu Fn (stick -> slip at t1 = mu Fn /(k v)), stays at mu Fn, and on reversal falls with slope
  // k v through zero to -mu Fn (slip -> stick -> slip). No dashpot.
  const cs::Params<double> p{2e4, 0.0, 0.3};
  const double fn = 5.0, v = 0.01, dt = 1e-6;
  const double t1 = p.mu * fn / (p.kt * v);
  V3 s{0, 0, 0}, f{};
  const int n_load = static_cast<int>(3.0 * t1 / dt);
  for (SlipRule rule : {SlipRule::spring_cap, SlipRule::spring_dashpot_cap}) {
    s = {0, 0, 0};
    for (int i = 1; i <= n_load; ++i) {
      cs::force(rule, p, kin_unit({0, 0, 1}, {v, 0, 0}, dt), fn, true, s.data(), f.data());
      const double t = i * dt;
      const double expect = t < t1 ? -p.kt * v * t : -p.mu * fn;
      ASSERT_NEAR(f[0], expect, 1e-9 * p.mu * fn + 1e-12) << "loading step " << i;
    }
    for (int i = 1; i <= n_load; ++i) {
      cs::force(rule, p, kin_unit({0, 0, 1}, {-v, 0, 0}, dt), fn, true, s.data(), f.data());
      const double t = i * dt;
      const double expect = t < 2.0 * t1 ? -p.mu * fn + p.kt * v * t : p.mu * fn;
      ASSERT_NEAR(f[0], expect, 1e-9 * p.mu * fn + 1e-12) << "unloading step " << i;
    }
  }
}

TEST(CundallStrack, ProjectionIntoCurrentTangentPlane) {
  const cs::Params<double> p{1e4, 0.0, 10.0};
  V3 s{1e-4, 0.0, 2e-5}, f{};
  const V3 n{0.0, 0.6, 0.8};
  cs::force<SlipRule::spring_cap>(p, kin_unit(n, {0, 0, 0}, 1e-5), 100.0, true, s.data(), f.data());
  EXPECT_NEAR(dot(s, n), 0.0, 1e-20);
  EXPECT_NEAR(dot(f, n), 0.0, 1e-16);
  // Non-unit normal with d_scale = 1/|d|^2 gives the same projection (LAMMPS form).
  V3 s2{1e-4, 0.0, 2e-5}, f2{};
  const double L = 3.7;
  cs::Kinematics<double> k2{{0.0, 0.6 * L, 0.8 * L}, 1.0 / (L * L), {0, 0, 0}, 1e-5};
  cs::force<SlipRule::spring_dashpot_cap>(p, k2, 100.0, true, s2.data(), f2.data());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s2[k], s[k], 1e-18);
}

TEST(CundallStrack, RigidRotationCarriesTheForce) {
  // Load a sticking contact, then rotate the pair rigidly by 90 degrees about an axis in the
  // contact plane in N small steps: the spring follows the tangent plane, the force direction
  // follows the rotation. The projection rule loses magnitude at second order in the step
  // angle: |F|/|F0| = prod cos(dtheta) ~ exp(-theta^2/(2N)).
  const cs::Params<double> p{1e4, 0.0, 10.0};
  V3 s{0, 0, 0}, f{};
  cs::force<SlipRule::spring_cap>(p, kin_unit({0, 0, 1}, {1.0, 0, 0}, 1e-6), 100.0, true, s.data(), f.data());
  const double f0 = norm(f);
  const int N = 20000;
  const double theta = M_PI / 2.0;
  for (int i = 1; i <= N; ++i) {
    const double a = theta * i / N;
    const V3 n{std::sin(a), 0.0, std::cos(a)};  // rotation about y: x -> -z, z -> x
    cs::force<SlipRule::spring_cap>(p, kin_unit(n, {0, 0, 0}, 1e-6), 100.0, true, s.data(), f.data());
  }
  const V3 expected_dir{0.0, 0.0, 1.0};  // -x rotated by 90 deg about y -> +z
  EXPECT_NEAR(dot(f, expected_dir) / norm(f), 1.0, 1e-12);
  const double predicted = std::pow(std::cos(theta / N), N);
  EXPECT_NEAR(norm(f) / f0, predicted, 1e-9);
  EXPECT_GT(norm(f) / f0, 1.0 - 1e-4);
}

TEST(CundallStrack, SignFlipWithPairOrder) {
  const cs::Params<double> p{1e4, 1.5, 0.3};
  for (SlipRule rule : {SlipRule::spring_cap, SlipRule::spring_dashpot_cap}) {
    V3 si{0, 0, 0}, sj{0, 0, 0}, fi{}, fj{};
    const V3 n{0.0, 0.6, 0.8}, vt{0.3, -0.24, 0.18};
    for (int step = 0; step < 500; ++step) {
      cs::force(rule, p, kin_unit(n, vt, 1e-5), 20.0, true, si.data(), fi.data());
      cs::force(rule, p, kin_unit({-n[0], -n[1], -n[2]}, {-vt[0], -vt[1], -vt[2]}, 1e-5), 20.0, true,
                sj.data(), fj.data());
      for (int k = 0; k < 3; ++k) {
        ASSERT_DOUBLE_EQ(sj[k], -si[k]);
        ASSERT_DOUBLE_EQ(fj[k], -fi[k]);
      }
    }
    EXPECT_NEAR(norm(fi), p.mu * 20.0, 1e-9);  // it ended up sliding
  }
  for (const auto& slot : cs::history) EXPECT_TRUE(slot.flips_sign) << slot.name;
}

TEST(CundallStrack, NoHistoryUpdateLeavesStateForSpringCap) {
  const cs::Params<double> p{1e4, 1.0, 0.1};
  V3 s{0.01, 0.0, 0.0}, f{};
  const V3 s0 = s;
  cs::force<SlipRule::spring_cap>(p, kin_unit({0, 0, 1}, {1, 0, 0}, 1e-3), 1.0, false, s.data(), f.data());
  EXPECT_EQ(s, s0);
  EXPECT_NEAR(norm(f), 0.1, 1e-12);
}
