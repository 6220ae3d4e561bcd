// SPDX-License-Identifier: GPL-2.0-or-later
// Linear stability of the integration schemes (src/integrators/stability.h) against closed forms
// of the damped oscillator x'' = -omega^2 x - 2 zeta omega x'.
#include <gtest/gtest.h>

#include <cmath>

#include "integrators/stability.h"

using namespace tdem::integrators;

// Verlet family and symplectic Euler: h omega < 2 without damping.
TEST(Stability, VerletFamilyUndampedLimitIsTwo) {
  for (Scheme s : {Scheme::symplectic_euler, Scheme::leapfrog, Scheme::position_verlet, Scheme::velocity_verlet,
                   Scheme::velocity_verlet_sync, Scheme::beeman})
    EXPECT_NEAR(critical_step(s, 0.0), 2.0, 1e-7) << info(s).name;
}

// Symplectic Euler (and the Verlet forms whose force sees the lagging velocity) with damping:
// the Jury conditions of lambda^2 - (2 - 2 zeta w - w^2) lambda + (1 - 2 zeta w) give
// w_c = 2 (sqrt(1 + zeta^2) - zeta).
TEST(Stability, SymplecticEulerDampedClosedForm) {
  for (double zeta : {0.01, 0.0709, 0.3, 0.7}) {
    const double wc = 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta);
    for (Scheme s : {Scheme::symplectic_euler, Scheme::leapfrog, Scheme::velocity_verlet})
      EXPECT_NEAR(critical_step(s, zeta), wc, 1e-7) << info(s).name << " zeta " << zeta;
  }
}

// The same closed form over the whole over-damped range: w_c ~ 1/zeta shrinks below any fixed
// scan step (zeta = 158 is e = 1e-5 with the zero-force end; the earlier scan from w = 0.01
// reported "unstable at every step" there).
TEST(Stability, SymplecticEulerOverdampedClosedForm) {
  for (double zeta : {1.0, 3.0, 30.0, 158.0, 1e3, 1e4, 1e5}) {
    const double wc = 2.0 / (std::sqrt(1.0 + zeta * zeta) + zeta);  // = 2 (sqrt(1 + zeta^2) - zeta)
    for (Scheme s : {Scheme::symplectic_euler, Scheme::leapfrog, Scheme::velocity_verlet})
      EXPECT_NEAR(critical_step(s, zeta) / wc, 1.0, 1e-7) << info(s).name << " zeta " << zeta;
  }
}

// Explicit Euler: |1 + i w| > 1 undamped (never stable); damped, the amplification of
// lambda^2 - (2 - 2 zeta w) lambda + (1 - 2 zeta w + w^2) stays <= 1 while w <= 2 zeta
// (for zeta < 1).
TEST(Stability, ExplicitEuler) {
  EXPECT_EQ(critical_step(Scheme::euler, 0.0), 0.0);
  for (double zeta : {0.1, 0.3, 0.7}) EXPECT_NEAR(critical_step(Scheme::euler, zeta), 2.0 * zeta, 1e-7) << zeta;
}

// Adams-Bashforth on the imaginary axis (undamped): AB2 has no stable interval; AB3 and AB4 have
// the classical imaginary-axis intervals of their boundary loci, |h lambda| <= 0.7236 (AB3) and
// 0.4300 (AB4); both follow from the boundary locus h lambda = rho(z)/sigma(z), z = exp(i t).
TEST(Stability, AdamsBashforthImaginaryAxis) {
  EXPECT_LT(critical_step(Scheme::ab2, 0.0), 0.02);
  EXPECT_NEAR(critical_step(Scheme::ab3, 0.0), 0.7236, 2e-4);
  EXPECT_NEAR(critical_step(Scheme::ab4, 0.0), 0.4300, 2e-4);
}

// The amplification at a tiny step tends to 1 for every scheme (consistency) and the
// radius equals the exact decay exp(-zeta w) to first order.
TEST(Stability, ConsistentAtSmallSteps) {
  for (int i = 0; i < static_cast<int>(Scheme::count); ++i) {
    const Scheme s = static_cast<Scheme>(i);
    const double w = 1e-3, zeta = 0.2;
    EXPECT_NEAR(amplification(s, w, zeta), std::exp(-zeta * w), 1e-5) << info(s).name;
  }
}
