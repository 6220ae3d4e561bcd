// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the SDS rolling resistance (src/contact/rolling/sds.h): gross rolling of a
// spinning sphere on a wall against omega(t) = omega0 - 5 mu_r g t/(2R) (DEM-07), the rotational
// oscillator of the spring below the limit against its period 2 pi sqrt(I/(k_r R^2)), the limit
// at zero normal force, the projection into the contact plane and the pair symmetry (the torque
// on j is -tau_i, the history is the same from both sides).
#include <gtest/gtest.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/rolling/sds.h"

namespace rs = tdem::rolling_sds;
using V3 = std::array<double, 3>;

namespace {
constexpr double kPi = 3.14159265358979323846;
double norm(const V3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// A sphere (radius r, mass m, inertia 2/5 m r^2) spinning about y on a wall under a constant
// normal force fn, advanced with the kernel's torque (symplectic Euler on omega); returns omega_y
// after each step.
std::vector<double> spin_down(const rs::Params<double>& p, double r, double m, double fn, double w0, double dt,
                              int steps) {
  const double inertia = 0.4 * m * r * r;
  const V3 n{0, 0, 1}, wj{0, 0, 0};
  V3 w{0, w0, 0}, roll{0, 0, 0}, tq{};
  std::vector<double> out;
  for (int k = 0; k < steps; ++k) {
    rs::torque(p, n.data(), r, w.data(), wj.data(), fn, dt, true, roll.data(), tq.data());
    for (int c = 0; c < 3; ++c) w[c] += tq[c] / inertia * dt;
    out.push_back(w[1]);
  }
  return out;
}
}  // namespace

TEST(RollingSds, GrossRollingDecaysLinearly) {
  const double r = 0.5, rho = 1.0, g = 10.0, w0 = 5.0, dt = 5e-4;
  const double m = rho * 4.0 / 3.0 * kPi * r * r * r;
  for (double mur : {0.05, 0.1, 0.2}) {
    const rs::Params<double> p{1000.0, 0.0, mur};
    const std::vector<double> w = spin_down(p, r, m, m * g, w0, dt, 400);
    // the spring reaches the limit after k_r R xi = mu_r N: within the first steps; from then on
    // the torque is constant and omega falls by 5 mu_r g dt / (2 R) per step
    const double rate = 5.0 * mur * g / (2.0 * r);
    for (int k = 50; k < 400; ++k) {
      const double t = (k + 1) * dt;
      if (w0 - rate * t < 0.1 * w0) break;
      EXPECT_NEAR(w[k] - w[k - 1], -rate * dt, 1e-12 * w0) << "mu_r " << mur << " step " << k;
    }
    EXPECT_LT(w[0], w0);  // it slows down from the first step (spring, then the limit)
  }
}

TEST(RollingSds, SpringIsARotationalOscillatorBelowTheLimit) {
  // a slow spin that never reaches the limit: omega(t) = w0 cos(W t), W = sqrt(k_r R^2 / I)
  const double r = 0.01, m = 1e-2, kr = 50.0, w0 = 1e-3, fn = 100.0;
  const rs::Params<double> p{kr, 0.0, 0.5};
  const double inertia = 0.4 * m * r * r, big_w = std::sqrt(kr * r * r / inertia);
  const double period = 2 * kPi / big_w, dt = period / 20000;
  const std::vector<double> w = spin_down(p, r, m, fn, w0, dt, 20000);
  double err = 0.0;
  for (int k = 0; k < 20000; k += 97) err = std::max(err, std::fabs(w[k] - w0 * std::cos(big_w * (k + 1) * dt)));
  EXPECT_LT(err, 1e-3 * w0);
  EXPECT_NEAR(w.back(), w0, 1e-3 * w0);  // one full period
}

TEST(RollingSds, NoNormalForceNoTorque) {
  const rs::Params<double> p{1000.0, 5.0, 0.3};
  const V3 n{0, 0, 1}, wi{0, 3, 0}, wj{0, 0, 0};
  V3 roll{0, 0, 0}, tq{};
  rs::torque(p, n.data(), 0.5, wi.data(), wj.data(), 0.0, 1e-4, true, roll.data(), tq.data());
  EXPECT_EQ(norm(tq), 0.0);
  // the spring is set so that spring plus dashpot give the (zero) capped force: xi = -gamma v_r / k
  const double vr = 0.5 * 3.0;  // R* (omega_i x n)_x
  EXPECT_NEAR(roll[0], -p.gammar * vr / p.kr, 1e-17);
  EXPECT_EQ(roll[1], 0.0);
  EXPECT_EQ(roll[2], 0.0);
}

TEST(RollingSds, DisplacementStaysInTheContactPlaneAndAtTheLimit) {
  const rs::Params<double> p{200.0, 1.0, 0.1};
  const double fn = 10.0, reff = 0.25, dt = 1e-3;
  V3 roll{0, 0, 0}, tq{};
  const V3 wi{1.0, 2.0, -0.5}, wj{-0.3, 0.1, 0.2};
  for (int k = 0; k < 200; ++k) {
    const double a = 0.01 * k;  // the normal turns slowly
    const V3 n{std::sin(a), 0.0, std::cos(a)};
    rs::torque(p, n.data(), reff, wi.data(), wj.data(), fn, dt, true, roll.data(), tq.data());
    EXPECT_NEAR(roll[0] * n[0] + roll[1] * n[1] + roll[2] * n[2], 0.0, 1e-15);
    // the torque lies in the contact plane and is at most mu_r R* |F_n|
    EXPECT_NEAR(tq[0] * n[0] + tq[1] * n[1] + tq[2] * n[2], 0.0, 1e-14);
    EXPECT_LE(norm(tq), p.mur * fn * reff * (1 + 1e-14));
  }
  EXPECT_NEAR(norm(tq), p.mur * fn * reff, 1e-12);  // a steady relative spin: at the limit
}

TEST(RollingSds, PairSeenFromTheOtherSideGivesTheOppositeTorque) {
  const rs::Params<double> p{300.0, 2.0, 0.2};
  const V3 n{0.6, 0.0, 0.8}, m_n{-0.6, 0.0, -0.8};
  const V3 wi{0.5, -1.0, 2.0}, wj{0.1, 0.4, -0.2};
  V3 ri{0, 0, 0}, rj{0, 0, 0}, ti{}, tj{};
  for (int k = 0; k < 50; ++k) {
    rs::torque(p, n.data(), 0.3, wi.data(), wj.data(), 5.0, 1e-3, true, ri.data(), ti.data());
    rs::torque(p, m_n.data(), 0.3, wj.data(), wi.data(), 5.0, 1e-3, true, rj.data(), tj.data());
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(tj[c], -ti[c], 1e-14);
      EXPECT_NEAR(rj[c], ri[c], 1e-14);  // the same history from both sides (no sign flip)
    }
  }
}
