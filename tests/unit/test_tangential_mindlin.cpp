// SPDX-License-Identifier: GPL-2.0-or-later
// Kernel tests of the non-linear tangential laws and of Walton-Braun's tangential law:
//  * Mindlin-Deresiewicz load/unload/reload paths under constant N against the closed forms of
//    physics_reference.md 3.3 (derived below), for fine and coarse steps; the memory rules
//    (loop closure, mirrored virgin curve, small inner loops and jitter); the dissipation per
//    closed cycle against Mindlin & Deresiewicz's closed form; gross sliding and unloading from it;
//  * Walton-Braun tangential load/unload/reload paths and the dissipation of a closed cycle;
//  * varying N (the rule of mindlin_deresiewicz.h): one step of growing / falling N against the
//    closed forms (loads kept; displacements kept, incl. after a reversal), gross sliding under
//    falling and growing N, |F| <= mu N along random paths; no net work over random closed cycles
//    of (xi, N, delta) in stick, micro-slip and gross slip (W >= -1e-12 of the work through the
//    contact); first-order time-step convergence when N falls right after a reversal;
//  * Tsuji and Di Renzo-Di Maio: no-slip stiffness 8 G* a, ratio 2/3, Tsuji damping;
//  * issue 4 (ratcheting): nested decaying loops beyond the 4 stored reversals, no creep of a mass
//    under a constant load with an undamped tangential oscillation, and Walton-Braun's load decay
//    under closed displacement cycles (the law itself);
//  * bad input.
//
// Closed forms (constant N, L = mu N, K0 = 8 G* a, a = sqrt(R* xi)). The virgin curve solves
// dT/dd = K0 (1 - T/L)^(1/3):  d/dT [(1 - T/L)^(2/3)] = -(2/(3L)) (1 - T/L)^(-1/3), so
//   (1 - T/L)^(2/3) = 1 - 2 K0 d/(3L) = 1 - d/d_c,  d_c = 3L/(2 K0) = 3 mu N/(16 G* a),
//   T = L [1 - (1 - d/d_c)^(3/2)],  d = d_c [1 - (1 - T/L)^(2/3)]   (MD's delta_t(T)).
// Unloading from (d*, T*) solves dT/dd = K0 (1 - (T* - T)/(2L))^(1/3) with d decreasing: the same
// equation for (T* - T)/2 in (d* - d)/2, so (T* - T)/2 = virgin((d* - d)/2):
//   T = T* - 2L [1 - (1 - (d* - d)/(2 d_c))^(3/2)],
// and reloading from (d**, T**): T = T** + 2L [1 - (1 - (d - d**)/(2 d_c))^(3/2)].
// Reloading after unloading from (d*, T*) reaches T* exactly at d* (both branches are the scaled
// virgin curve), and unloading from a point of the virgin curve reaches -T* at -d* (the mirrored
// virgin curve), where the stiffnesses agree.
// Dissipation of the loop between +-T* (force-controlled), W = area between unloading and reloading:
//   W = int_{-T*}^{T*} (d_u(T) - d_r(T)) dT = 4 T* d* - 8 int_0^{T*} d(y) dy
//     = (9 L^2/(10 G* a)) [1 - (1 - tau)^(5/3) - (5 tau/6)(1 + (1 - tau)^(2/3))],  tau = T*/L
// (Johnson, Contact Mechanics eq. 7.60, with 8 G* a for the no-slip stiffness).
// Walton-Braun: dT/dd = k0 (1 - x)^(1/3), x = s (T - T*)/D, D = L - s T*, from (d*, T*):
//   T = T* + s D [1 - (1 - 2 k0 s (d - d*)/(3D))^(3/2)]  (T = s L once the bracket is < 0);
// a closed loop between +-T1 (both branches have D = L + T1): with g(y) = (3D/(2k0))[1 - (1 - y/D)^(2/3)]
// the displacement from T1 to -T1 is g(2 T1) and
//   W = 2 T1 g(2 T1) - 2 int_0^{2 T1} g,  int_0^Y g = (3D/(2k0)) [Y - (3D/5)(1 - (1 - Y/D)^(5/3))].
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/tangential/common.h"
#include "contact/tangential/di_renzo.h"
#include "contact/tangential/mindlin_deresiewicz.h"
#include "contact/tangential/mindlin_no_slip.h"
#include "contact/tangential/parameters.h"
#include "contact/tangential/walton_braun_tangential.h"

namespace tg = tdem::tangential;
namespace md = tdem::mindlin_deresiewicz;
namespace wbt = tdem::walton_braun_tangential;
namespace mns = tdem::mindlin_no_slip;
namespace drm = tdem::di_renzo;
using FL = tg::FrictionLimit;
using V3 = std::array<double, 3>;
using Kin = tg::TangentialKinematics<double>;

namespace {

const double kGstar = 3e10, kReff = 2e-3, kXi = 1e-5, kMu = 0.3, kN = 10.0;
const double kA = std::sqrt(kReff * kXi), kK0 = 8.0 * kGstar * kA, kL = kMu * kN, kDc = 1.5 * kL / kK0;

Kin kin(const V3& vt, double dt, double fn, double xi = kXi) {
  Kin k{};
  k.n[2] = 1.0;
  for (int i = 0; i < 3; ++i) k.vt[i] = vt[i];
  k.dt = dt;
  k.overlap = xi;
  k.meff = 1e-3;
  k.reff = kReff;
  k.fn = fn;
  k.kn = 1e6;
  k.gamman = 0.4;
  return k;
}

using ForceFn = std::function<bool(const Kin&, double*, bool, double*)>;

// Moves the contact along x from delta to target in n equal steps (dt = 1); calls check(delta, T, sliding)
// after each step with T = -F_x the load.
void drive(const ForceFn& f, double* h, double& delta, double target, int n,
           const std::function<void(double, double, bool)>& check, double fn = kN) {
  const double dd = (target - delta) / n;
  for (int i = 1; i <= n; ++i) {
    V3 F{};
    const bool sliding = f(kin({dd, 0, 0}, 1.0, fn), h, true, F.data());
    delta = (i == n) ? target : delta + dd;
    check(delta, -F[0], sliding);
  }
}

double md_virgin(double d) {
  const double s = d >= 0 ? 1.0 : -1.0, x = std::fabs(d) / kDc;
  return x >= 1.0 ? s * kL : s * kL * (1.0 - std::pow(1.0 - x, 1.5));
}
double md_unload(double d_star, double t_star, double d) {
  return t_star - 2.0 * kL * (1.0 - std::pow(1.0 - (d_star - d) / (2.0 * kDc), 1.5));
}
double md_reload(double d_2star, double t_2star, double d) {
  return t_2star + 2.0 * kL * (1.0 - std::pow(1.0 - (d - d_2star) / (2.0 * kDc), 1.5));
}

ForceFn md_law(FL limit = FL::absolute) {
  const md::Params<double> p{kGstar, kMu, limit};
  return [p](const Kin& k, double* h, bool u, double* f) { return md::force(p, k, h, u, f); };
}

}  // namespace

TEST(MindlinDeresiewicz, LoadUnloadReloadPathsFollowTheClosedForms) {
  md::validate({kGstar, kMu, FL::absolute});
  for (int n : {1000, 7}) {  // exact integration per step: coarse steps must follow too
    double h[md::history_size] = {0}, delta = 0.0;
    const double tol = 1e-10 * kL;
    const double d1 = 0.6 * kDc, d2 = -0.2 * kDc, d3 = 0.9 * kDc, d4 = -1.5 * kDc, d5 = d4 + 1.2 * kDc;
    const auto f = md_law();
    // virgin loading
    drive(f, h, delta, d1, n, [&](double d, double t, bool sl) {
      EXPECT_NEAR(t, md_virgin(d), tol) << "virgin " << d;
      EXPECT_FALSE(sl);
    });
    const double t1 = md_virgin(d1);
    // unloading from (d1, T1) to d2 (> -d1: stays on the unloading branch)
    drive(f, h, delta, d2, n, [&](double d, double t, bool) { EXPECT_NEAR(t, md_unload(d1, t1, d), tol) << d; });
    const double t2 = md_unload(d1, t1, d2);
    // reloading from (d2, T2): reaches T1 at d1, then the virgin curve
    drive(f, h, delta, d3, n, [&](double d, double t, bool) {
      EXPECT_NEAR(t, d <= d1 ? md_reload(d2, t2, d) : md_virgin(d), tol) << "reload " << d;
    });
    const double t3 = md_virgin(d3);
    // unloading from (d3, T3): reaches -T3 at -d3, then the mirrored virgin curve, then gross sliding at -L
    drive(f, h, delta, d4, n, [&](double d, double t, bool sl) {
      EXPECT_NEAR(t, d >= -d3 ? md_unload(d3, t3, d) : md_virgin(d), tol) << "unload " << d;
      if (d < -kDc * (1 + 1e-9)) {
        EXPECT_TRUE(sl) << d;
      }
    });
    // out of gross sliding: the full unloading curve from T* = -L
    drive(f, h, delta, d5, n, [&](double d, double t, bool) {
      EXPECT_NEAR(t, -md_unload(-d4, kL, -d), tol) << "after sliding " << d;
    });
  }
}

TEST(MindlinDeresiewicz, InnerLoopsAndJitterLeaveTheOuterPathUnchanged) {
  const auto f = md_law();
  double h[md::history_size] = {0}, delta = 0.0;
  const auto none = [](double, double, bool) {};
  const double d1 = 0.8 * kDc;
  drive(f, h, delta, d1, 10, none);
  const double t1 = md_virgin(d1);
  drive(f, h, delta, 0.3 * kDc, 10, none);
  // Jitter: 200 alternating steps of +-1e-4 d_c, then an inner loop 0.3 -> 0.5 -> 0.3 d_c.
  for (int i = 0; i < 200; ++i) drive(f, h, delta, delta + (i % 2 ? -1 : 1) * 1e-4 * kDc, 1, none);
  drive(f, h, delta, 0.5 * kDc, 5, none);
  drive(f, h, delta, 0.3 * kDc, 5, none);
  // ... and the outer unloading branch continues as if nothing had happened.
  drive(f, h, delta, -0.5 * kDc, 20, [&](double d, double t, bool) {
    EXPECT_NEAR(t, md_unload(d1, t1, d), 1e-10 * kL) << d;
  });
  // Reloading now, with an inner unloading loop of its own, still closes at (d1, T1).
  const double d2 = -0.5 * kDc, t2 = md_unload(d1, t1, d2);
  drive(f, h, delta, 0.2 * kDc, 5, none);
  drive(f, h, delta, -0.1 * kDc, 5, none);
  drive(f, h, delta, 0.9 * kDc, 40, [&](double d, double t, bool) {
    if (d > 0.2 * kDc) {
      EXPECT_NEAR(t, d <= d1 ? md_reload(d2, t2, d) : md_virgin(d), 1e-10 * kL) << d;
    }
  });
}

TEST(MindlinDeresiewicz, DissipationPerCycleMatchesTheClosedForm) {
  const auto f = md_law();
  for (double tau : {0.2, 0.5, 0.9}) {
    double h[md::history_size] = {0}, delta = 0.0;
    const double t_star = tau * kL, d_star = kDc * (1.0 - std::pow(1.0 - tau, 2.0 / 3.0));
    drive(f, h, delta, d_star, 3, [](double, double, bool) {});
    double work = 0.0, d_prev = delta, t_prev = t_star;
    const auto acc = [&](double d, double t, bool) {
      work += 0.5 * (t + t_prev) * (d - d_prev);
      d_prev = d, t_prev = t;
    };
    const int n = 20000;
    drive(f, h, delta, -d_star, n, acc);
    EXPECT_NEAR(t_prev, -t_star, 1e-10 * kL);  // the loop turns at -T*
    drive(f, h, delta, d_star, n, acc);
    EXPECT_NEAR(t_prev, t_star, 1e-10 * kL);  // and closes at T*
    const double W = 9.0 * kL * kL / (10.0 * kGstar * kA) *
                     (1.0 - std::pow(1.0 - tau, 5.0 / 3.0) - 5.0 * tau / 6.0 * (1.0 + std::pow(1.0 - tau, 2.0 / 3.0)));
    EXPECT_NEAR(work, W, 1e-6 * W) << tau;
  }
}

TEST(MindlinDeresiewicz, SmallDisplacementStiffnessIsTheNoSlipStiffness) {
  const auto f = md_law();
  double h[md::history_size] = {0};
  V3 F{};
  const double dd = 1e-9 * kDc;
  f(kin({0, dd, 0}, 1.0, kN), h, true, F.data());
  EXPECT_NEAR(-F[1] / dd, 8.0 * kGstar * std::sqrt(kReff * kXi), 1e-6 * kK0);
  EXPECT_NEAR(F[0], 0.0, 1e-30);
}

// Varying N (the rule of mindlin_deresiewicz.h, "Varying N"). Closed forms at (K0, L), d_c = 3L/(2K0):
// a point of the virgin curve at load T has the displacement d = d_c [1 - (1 - T/L)^(2/3)]; a branch
// after a reversal at relative load tau has Delta = 2 d_c [1 - (1 - tau/(2L))^(2/3)]. A decrease of
// K0 and d_c keeps every d and Delta and re-evaluates the loads at the new (K0, L); an increase keeps
// the loads.
namespace {
double hertz_fn(double xi) { return kN * std::pow(xi / kXi, 1.5); }
double k0_of(double xi) { return 8.0 * kGstar * std::sqrt(kReff * xi); }
double virgin_at(double d, double L, double dc) {
  return d >= dc ? L : L * (1.0 - std::pow(1.0 - d / dc, 1.5));
}
double virgin_disp(double t, double L, double dc) { return dc * (1.0 - std::pow(1.0 - t / L, 2.0 / 3.0)); }
}  // namespace

TEST(MindlinDeresiewicz, VaryingNormalLoadOneStepRule) {
  const auto f = md_law();
  const auto none = [](double, double, bool) {};
  // (a) N (and the contact) grows at fixed displacement: the load is kept (no slip, MD 1953), and the
  //     next increment starts on the virgin curve of the new limit at x = T/L'.
  {
    double h[md::history_size] = {0}, delta = 0.0;
    drive(f, h, delta, 0.5 * kDc, 4, none);
    const double t = md_virgin(0.5 * kDc), xi2 = 1.3 * kXi, fn2 = hertz_fn(xi2), L2 = kMu * fn2;
    V3 F{};
    f(kin({0, 0, 0}, 1.0, fn2, xi2), h, true, F.data());
    EXPECT_NEAR(-F[0], t, 1e-12 * kL);
    const double k2 = k0_of(xi2), dc2 = 1.5 * L2 / k2, eps = 0.05 * kDc;
    f(kin({eps, 0, 0}, 1.0, fn2, xi2), h, true, F.data());
    EXPECT_NEAR(-F[0], virgin_at(virgin_disp(t, L2, dc2) + eps, L2, dc2), 1e-12 * kL);
  }
  // (b) Hertzian unloading (xi and N fall, d_c ~ a^2 falls) at fixed displacement: the load is the
  //     virgin curve of the new (K0, L) at the same displacement (exact for the method of
  //     dimensionality reduction: every spring keeps its displacement, the outer ones are capped).
  for (double xi2 : {0.9 * kXi, 0.5 * kXi, 0.2 * kXi}) {
    double h[md::history_size] = {0}, delta = 0.0;
    const double d1 = 0.6 * kDc;
    drive(f, h, delta, d1, 4, none);
    const double fn2 = hertz_fn(xi2), L2 = kMu * fn2, dc2 = 1.5 * L2 / k0_of(xi2);
    V3 F{};
    f(kin({0, 0, 0}, 1.0, fn2, xi2), h, true, F.data());
    EXPECT_NEAR(-F[0], virgin_at(d1, L2, dc2), 1e-12 * kL) << xi2;
  }
  // (c) the same after a reversal: T* and the unloading branch keep their displacements d*, Delta;
  //     then the unloading continues on the new closed form and meets -T*' at -d*.
  {
    double h[md::history_size] = {0}, delta = 0.0;
    const double d1 = 0.7 * kDc, d2 = 0.2 * kDc;
    drive(f, h, delta, d1, 4, none);
    drive(f, h, delta, d2, 4, none);
    const double xi2 = 0.85 * kXi, fn2 = hertz_fn(xi2), L2 = kMu * fn2, dc2 = 1.5 * L2 / k0_of(xi2);
    const double ts2 = virgin_at(d1, L2, dc2);
    const auto unload2 = [&](double d) {
      return ts2 - 2.0 * L2 * (1.0 - std::pow(1.0 - (d1 - d) / (2.0 * dc2), 1.5));
    };
    V3 F{};
    f(kin({0, 0, 0}, 1.0, fn2, xi2), h, true, F.data());
    EXPECT_NEAR(-F[0], unload2(d2), 1e-12 * kL);
    const double dd = (-d1 - d2) / 50.0;
    for (int i = 1; i <= 50; ++i) {
      f(kin({dd, 0, 0}, 1.0, fn2, xi2), h, true, F.data());
      EXPECT_NEAR(-F[0], unload2(d2 + i * dd), 1e-11 * kL) << i;
    }
    EXPECT_NEAR(-F[0], -ts2, 1e-11 * kL);  // the mirror point of the new virgin curve
  }
  // (d) gross sliding: a falling N (d_c falls) keeps the load at mu N; a rising N makes the contact
  //     stick again: from T = L on the virgin curve of L' > L by the step's displacement.
  {
    double h[md::history_size] = {0}, delta = 0.0;
    drive(f, h, delta, 2.0 * kDc, 4, none);
    for (double fn : {8.0, 5.0, 3.0}) {
      V3 F{};
      const bool sl = f(kin({0.01 * kDc, 0, 0}, 1.0, fn), h, true, F.data());
      EXPECT_NEAR(-F[0], kMu * fn, 1e-12 * kL) << fn;
      EXPECT_TRUE(sl) << fn;
    }
    const double L1 = kMu * 3.0, L2 = kMu * 4.0, dc2 = 1.5 * L2 / kK0, eps = 0.01 * kDc;
    V3 F{};
    const bool sl = f(kin({eps, 0, 0}, 1.0, 4.0), h, true, F.data());
    EXPECT_NEAR(-F[0], virgin_at(virgin_disp(L1, L2, dc2) + eps, L2, dc2), 1e-12 * kL);
    EXPECT_FALSE(sl);
  }
  // (e) at constant displacement a falling N caps the load at mu N, and a rising one keeps it.
  {
    double h[md::history_size] = {0}, delta = 0.0;
    drive(f, h, delta, 0.7 * kDc, 4, none);
    double fn = kN;
    bool sl = false;
    V3 F{};
    for (int i = 0; i < 90; ++i) {
      fn -= 0.1;
      sl = f(kin({0, 0, 0}, 1.0, fn), h, true, F.data());
      EXPECT_LE(-F[0], kMu * fn * (1 + 1e-12));
    }
    EXPECT_TRUE(sl);
    EXPECT_NEAR(-F[0], kMu * fn, 1e-12);
    const double t = -F[0];
    f(kin({0, 0, 0}, 1.0, 2.0 * fn), h, true, F.data());
    EXPECT_NEAR(-F[0], t, 1e-15);
  }
}

namespace {
// Exact work of one tangential step from the state h (not changed): the kernel's own load along the
// step, T(theta dd), evaluated from h without update, integrated by adaptive Simpson (the step is
// exact within the kernel, so this is the work of the law, not of a discretisation).
double step_work(const ForceFn& f, const double* h, double dd, double fn, double xi) {
  std::vector<double> hc(h, h + md::history_size);
  const auto T = [&](double th) {
    std::vector<double> tmp = hc;
    V3 F{};
    f(kin({th * dd, 0, 0}, 1.0, fn, xi), tmp.data(), false, F.data());
    return -F[0];
  };
  std::function<double(double, double, double, double, double, double, int)> simpson =
      [&](double a, double b, double fa, double fm, double fb, double whole, int depth) {
        const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
        const double flm = T(lm), frm = T(rm);
        const double left = (b - a) / 12.0 * (fa + 4.0 * flm + fm), right = (b - a) / 12.0 * (fm + 4.0 * frm + fb);
        if (depth <= 0 || std::fabs(left + right - whole) < 1e-15 * kL) return left + right + (left + right - whole) / 15.0;
        return simpson(a, m, fa, flm, fm, left, depth - 1) + simpson(m, b, fm, frm, fb, right, depth - 1);
      };
  const double f0 = T(0.0), f1 = T(1.0), fm = T(0.5);
  return dd * simpson(0.0, 1.0, f0, fm, f1, (f0 + 4.0 * fm + f1) / 6.0, 40);
}
}  // namespace

// (a) Energy: along closed paths in (xi, N, delta), starting from a fresh contact, the work done on
// the contact, W = int T d(delta), is never negative at the return to the start (the law stores
// energy >= 0 and dissipates >= 0; a normal-load change alone does no tangential work and must not
// add stored energy). Random cycles with several waypoints, in stick (amplitude 0.05 d_c), micro-slip
// (0.9 d_c) and through gross sliding (2 d_c); N from xi (Hertz), proportional to xi (a linear normal
// law) or independent of it (damping); each leg alternates normal and tangential sub-steps. Under
// Thornton-Yin's rule (a load term mu dN (1 - theta) also when N grows) some of these cycles return
// more work than they received.
TEST(MindlinDeresiewicz, NoNetWorkOverClosedCyclesWithVaryingNormalLoad) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const auto f = md_law();
  double worst = 1e300;
  for (int relation = 0; relation < 3; ++relation) {
    for (double amp : {0.05, 0.9, 2.0}) {
      for (int rep = 0; rep < 4; ++rep) {
        double h[md::history_size] = {0};
        double W = 0.0, Wabs = 0.0, delta = 0.0, xi = kXi, fn = kN;
        const auto fn_of = [&](double x, double free) {
          return relation == 0 ? hertz_fn(x) : (relation == 1 ? kN * x / kXi : free);
        };
        for (int cycle = 0; cycle < 3; ++cycle) {
          // waypoints (xi, fn, delta); the last one is the start (kXi, kN, 0)
          std::vector<std::array<double, 3>> wp;
          const int n_wp = 3 + int(U(rng) * 4);
          for (int k = 0; k < n_wp; ++k) {
            const double x = kXi * (0.3 + 1.4 * U(rng));
            wp.push_back({x, fn_of(x, kN * (0.3 + 1.7 * U(rng))), amp * kDc * (2.0 * U(rng) - 1.0)});
          }
          wp.push_back({kXi, kN, 0.0});
          for (const auto& w : wp) {
            const int n = 30;
            const double x0 = xi, f0 = fn, d0 = delta;
            for (int i = 1; i <= n; ++i) {
              xi = x0 + (w[0] - x0) * i / n;
              fn = f0 + (w[1] - f0) * i / n;
              V3 F{};
              f(kin({0, 0, 0}, 1.0, fn, xi), h, true, F.data());  // normal change: no tangential work
              const double dd = d0 + (w[2] - d0) * i / n - delta;
              const double dw = step_work(f, h, dd, fn, xi);
              f(kin({dd, 0, 0}, 1.0, fn, xi), h, true, F.data());
              delta += dd;
              W += dw;
              Wabs += std::fabs(dw);
            }
          }
          // back at the start: W >= 0 (relative to the work that went through the contact)
          EXPECT_GE(W, -1e-12 * Wabs) << "relation " << relation << " amplitude " << amp << " rep " << rep
                                      << " cycle " << cycle;
          worst = std::min(worst, W / Wabs);
        }
      }
    }
  }
  RecordProperty("min_W_over_Wabs", std::to_string(worst));
}

namespace {
// The load along a smooth path of duration 1 in n steps, sampled at the 40 times k/40.
std::vector<double> path_loads(int n, int relation) {
  const auto f = md_law();
  double h[md::history_size] = {0};
  std::vector<double> out;
  const int per = n / 40;
  // delta: up to 0.8 d_c, reversal at tau = 0.25 while xi (and N) fall, second reversal at 0.75
  const auto delta = [](double tau) { return 0.8 * kDc * std::sin(2.0 * M_PI * tau); };
  const auto xi = [](double tau) { return kXi * (1.0 + 0.6 * std::cos(2.0 * M_PI * (tau - 0.1))); };
  const auto fn = [&](double tau) {
    const double x = xi(tau);
    return relation == 0 ? hertz_fn(x) : kN * (x / kXi + 0.4 * std::sin(4.0 * M_PI * tau));
  };
  for (int i = 1; i <= n; ++i) {
    const double a = double(i - 1) / n, b = double(i) / n;
    V3 F{};
    f(kin({delta(b) - delta(a), 0, 0}, 1.0, fn(b), xi(b)), h, true, F.data());
    if (i % per == 0) out.push_back(-F[0]);
  }
  return out;
}
}  // namespace

// (b) Time-step convergence along a smooth path with two reversals, the first while N falls: the
// change of the load path when the step is halved, e_n = max_t |T_n(t) - T_2n(t)|, falls like dt
// (first order: the normal-load change is applied before the step's displacement) - uniformly, with
// e_n / e_2n close to 2 for every n.
TEST(MindlinDeresiewicz, TimeStepConvergenceIsFirstOrderWhenNFallsAfterAReversal) {
  for (int relation : {0, 1}) {
    std::vector<std::vector<double>> runs;
    std::vector<int> ns = {400, 800, 1600, 3200, 6400};
    for (int n : ns) runs.push_back(path_loads(n, relation));
    std::vector<double> e;
    for (size_t k = 0; k + 1 < runs.size(); ++k) {
      double m = 0.0;
      for (size_t j = 0; j < runs[k].size(); ++j) m = std::max(m, std::fabs(runs[k][j] - runs[k + 1][j]));
      e.push_back(m);
    }
    std::string es;
    for (double x : e) es += std::to_string(x / kL) + " ";
    RecordProperty("e_over_L_relation_" + std::to_string(relation), es);
    for (size_t k = 0; k + 1 < e.size(); ++k) {
      EXPECT_GT(e[k] / e[k + 1], 1.7) << "relation " << relation << " n = " << ns[k] << ": " << e[k] << " -> " << e[k + 1];
      EXPECT_LT(e[k] / e[k + 1], 2.4) << "relation " << relation << " n = " << ns[k] << ": " << e[k] << " -> " << e[k + 1];
    }
    EXPECT_LT(e[0], 0.05 * kL) << relation;  // and the error is small already at 400 steps
  }
}

TEST(MindlinDeresiewicz, ForceNeverExceedsTheLimitAlongRandomPaths) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (FL limit : {FL::absolute, FL::positive_normal}) {
    const auto f = md_law(limit);
    double h[md::history_size] = {0};
    double fn = kN, xi = kXi;
    for (int i = 0; i < 20000; ++i) {
      fn += 0.8 * U(rng);
      if (fn > 30.0) fn = 30.0;
      if (fn < -5.0) fn = -5.0;
      xi = std::max(1e-7, xi * (1.0 + 0.05 * U(rng)));
      const V3 v{0.3 * kDc * U(rng), 0.3 * kDc * U(rng), 0.0};
      V3 F{};
      f(kin(v, 1.0, fn, xi), h, true, F.data());
      const double lim = limit == FL::absolute ? kMu * std::fabs(fn) : kMu * std::max(fn, 0.0);
      ASSERT_LE(std::hypot(F[0], F[1]), lim * (1.0 + 1e-12) + 1e-300) << i;
      ASSERT_TRUE(std::isfinite(F[0]) && std::isfinite(F[1])) << i;
      ASSERT_EQ(F[2], 0.0);
    }
  }
}

// ------------------------------------------------------------------ Walton-Braun tangential

namespace {
double wb_branch(double k0, double d_star, double t_star, double s, double d) {
  const double D = kL - s * t_star;
  const double c = 1.0 - 2.0 * k0 * s * (d - d_star) / (3.0 * D);
  return c <= 0.0 ? s * kL : t_star + s * D * (1.0 - std::pow(c, 1.5));
}
ForceFn wb_law(double k0) {
  const wbt::Params<double> p{k0, 0.0, kMu, FL::absolute};
  return [p](const Kin& k, double* h, bool u, double* f) { return wbt::force(p, k, h, u, f); };
}
}  // namespace

TEST(MindlinWaltonBraunTangential, LoadUnloadReloadPathsFollowTheClosedForms) {
  const double k0 = 2e7, dcw = 1.5 * kL / k0;  // virgin branch reaches the limit at d = 3L/(2 k0)
  wbt::validate({k0, 0.0, kMu, FL::absolute});
  for (int n : {1000, 9}) {
    const auto f = wb_law(k0);
    double h[wbt::history_size] = {0}, delta = 0.0;
    const double tol = 1e-10 * kL;
    const double d1 = 0.5 * dcw, d2 = -0.3 * dcw, d3 = 2.0 * dcw, d4 = 0.0;
    drive(f, h, delta, d1, n, [&](double d, double t, bool) { EXPECT_NEAR(t, wb_branch(k0, 0, 0, 1, d), tol) << d; });
    const double t1 = wb_branch(k0, 0, 0, 1, d1);
    drive(f, h, delta, d2, n, [&](double d, double t, bool) { EXPECT_NEAR(t, wb_branch(k0, d1, t1, -1, d), tol) << d; });
    const double t2 = wb_branch(k0, d1, t1, -1, d2);
    // reloading: no memory of T1 in Walton-Braun - one branch from T2 to the limit
    drive(f, h, delta, d3, n, [&](double d, double t, bool sl) {
      const double expected = wb_branch(k0, d2, t2, 1, d);
      EXPECT_NEAR(t, expected, tol) << d;
      if (expected >= kL) {
        EXPECT_TRUE(sl) << d;
      }
      if (expected < kL * (1 - 1e-6)) {
        EXPECT_FALSE(sl) << d;
      }
    });
    // out of gross sliding: unloading from T* = L
    drive(f, h, delta, d4, n, [&](double d, double t, bool) { EXPECT_NEAR(t, wb_branch(k0, d3, kL, -1, d), tol) << d; });
  }
}

TEST(MindlinWaltonBraunTangential, DissipationOfAClosedCycle) {
  const double k0 = 2e7;
  for (double tau : {0.3, 0.8}) {
    const auto f = wb_law(k0);
    double h[wbt::history_size] = {0}, delta = 0.0;
    // Load to T1 = tau L on the first branch: d1 = (3L/(2k0)) [1 - (1 - tau)^(2/3)].
    const double t1 = tau * kL, d1 = 1.5 * kL / k0 * (1.0 - std::pow(1.0 - tau, 2.0 / 3.0));
    drive(f, h, delta, d1, 3, [](double, double, bool) {});
    const double D = kL + t1, c = 1.5 * D / k0, Y = 2.0 * t1;
    const double g2 = c * (1.0 - std::pow(1.0 - Y / D, 2.0 / 3.0));
    const double int_g = c * (Y - 0.6 * D * (1.0 - std::pow(1.0 - Y / D, 5.0 / 3.0)));
    const double W = 2.0 * t1 * g2 - 2.0 * int_g;
    double work = 0.0, d_prev = delta, t_prev = t1;
    const auto acc = [&](double d, double t, bool) {
      work += 0.5 * (t + t_prev) * (d - d_prev);
      d_prev = d, t_prev = t;
    };
    drive(f, h, delta, d1 - g2, 20000, acc);
    EXPECT_NEAR(t_prev, -t1, 1e-9 * kL);
    drive(f, h, delta, d1, 20000, acc);
    EXPECT_NEAR(t_prev, t1, 1e-9 * kL);
    EXPECT_NEAR(work, W, 1e-6 * W) << tau;
  }
}

TEST(MindlinWaltonBraunTangential, StiffnessFromKappaTimesNormalStiffness) {
  const wbt::Params<double> p{0.0, 2.0 / 7.0, kMu, FL::absolute};
  double h[wbt::history_size] = {0};
  V3 F{};
  Kin k = kin({1e-9, 0, 0}, 1.0, kN);
  k.kn = 7e6;
  wbt::force(p, k, h, true, F.data());
  EXPECT_NEAR(-F[0], wb_branch(2e6, 0.0, 0.0, 1.0, 1e-9), 1e-12 * kL);  // k0 = kappa k_n = 2e6 N/m
  EXPECT_GT(std::fabs(wb_branch(2e6, 0.0, 0.0, 1.0, 1e-9) - wb_branch(2.1e6, 0.0, 0.0, 1.0, 1e-9)), 1e-5 * kL);
}

// ------------------------------------------------------------------ Tsuji and Di Renzo-Di Maio

TEST(MindlinNoSlip, TsujiAndDiRenzoStiffnessesAndDamping) {
  const double gstar = tg::effective_shear_modulus_from_E(2.1e11, 0.3, 2.1e11, 0.3);
  const mns::Params<double> pt{gstar, 1.0, kMu, FL::absolute, tg::SlipReset::spring_only};
  const mns::Params<double> pt0{gstar, 0.0, kMu, FL::absolute, tg::SlipReset::spring_only};
  const drm::Params<double> pd{gstar, kMu, FL::absolute};
  mns::validate(pt);
  drm::validate(pd);
  for (double xi : {1e-7, 1e-6, 4e-6}) {
    const double kt = 8.0 * gstar * std::sqrt(kReff * xi), s = 1e-9, dt = 1e-6, v = s / dt;
    double ht[3] = {0}, ht0[3] = {0}, hd[3] = {0};
    V3 ft{}, ft0{}, fd{};
    Kin k = kin({v, 0, 0}, dt, 1e3, xi);
    mns::force(pt, k, ht, true, ft.data());
    mns::force(pt0, k, ht0, true, ft0.data());
    drm::force(pd, k, hd, true, fd.data());
    EXPECT_NEAR(-ft0[0], kt * s, 1e-12 * kt * s) << xi;
    EXPECT_NEAR(-ft[0], kt * s + k.gamman * v, 1e-12 * (kt * s + k.gamman * v)) << xi;  // eta_t = gamma_n
    EXPECT_NEAR(fd[0] / ft0[0], 2.0 / 3.0, 1e-14) << xi;
    // Total formulation: the same elongation at a larger overlap gives the larger stiffness.
    Kin k2 = kin({0, 0, 0}, dt, 1e3, 4.0 * xi);
    mns::force(pt0, k2, ht0, true, ft0.data());
    EXPECT_NEAR(-ft0[0], 2.0 * kt * s, 1e-12 * kt * s) << xi;
  }
  // No overlap: no stiffness, no force.
  double h[3] = {1e-6, 0, 0};
  V3 F{};
  drm::force(pd, kin({0, 0, 0}, 1e-6, 10.0, 0.0), h, true, F.data());
  EXPECT_EQ(F[0], 0.0);
}

TEST(MindlinNoSlip, BadInput) {
  auto expect_msg = [](const std::function<void()>& fn, const std::string& what, const std::string& value) {
    try {
      fn();
      ADD_FAILURE() << "no exception for " << what;
    } catch (const std::domain_error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_NE(m.find(value), std::string::npos) << m;
      EXPECT_NE(m.find("range"), std::string::npos) << m;
    }
  };
  expect_msg([] { md::validate({-1e9, 0.3, FL::absolute}); }, "effective shear modulus G*", "-1e+09");
  expect_msg([] { md::validate({1e9, -0.1, FL::absolute}); }, "friction coefficient mu", "-0.1");
  expect_msg([] { mns::validate({1e9, -1.0, 0.3, FL::absolute, tg::SlipReset::spring_only}); }, "eta_t/gamma_n", "-1");
  expect_msg([] { drm::validate({0.0, 0.3, FL::absolute}); }, "effective shear modulus G*", "0");
  expect_msg([] { wbt::validate({-1.0, 0.0, 0.3, FL::absolute}); }, "initial tangential stiffness k_t0", "-1");
  expect_msg([] { tg::effective_shear_modulus(1e9, 0.3, -2e9, 0.3); }, "shear modulus G2", "-2e+09");
}

// Issue 4 (ratcheting). A decaying oscillation at constant N: every reversal lies inside the
// previous loop, so no loop ever closes and the memory holds one more reversal point per half
// cycle. By Masing's rules each branch is the virgin curve scaled by 2 about its own reversal
// point (d_k, T_k) and only depends on it: the chain of closed forms below (T_k from the branch
// before) must hold for all 14 reversals, far beyond the 4 stored points. (Until issue 4 a full
// memory dropped the newest point and ran the branch on from r_3: wrong from the 5th reversal on.)
TEST(MindlinDeresiewicz, DecayingOscillationFollowsNestedMasingLoops) {
  for (int n : {200, 7}) {
    const auto f = md_law();
    double h[md::history_size] = {0}, delta = 0.0;
    double dk = 0.8 * kDc;
    drive(f, h, delta, dk, n, [&](double d, double t, bool) { EXPECT_NEAR(t, md_virgin(d), 1e-10 * kL) << d; });
    double tk = md_virgin(dk);
    for (int k = 1; k <= 14; ++k) {
      const double dn = -0.85 * dk, d0 = dk, t0 = tk;  // next reversal, inside the previous loop
      const bool down = dn < d0;
      const auto branch = [&](double d) { return down ? md_unload(d0, t0, d) : md_reload(d0, t0, d); };
      drive(f, h, delta, dn, n, [&](double d, double t, bool sl) {
        EXPECT_NEAR(t, branch(d), 1e-10 * kL) << "branch " << k << " (n = " << n << ") at d/d_c = " << d / kDc;
        EXPECT_FALSE(sl);
      });
      dk = dn, tk = branch(dn);
    }
    // ... and a large excursion afterwards still ends on the virgin curve and the limit.
    drive(f, h, delta, 1.2 * kDc, n, [](double, double, bool) {});
    V3 F{};
    EXPECT_TRUE(f(kin({1e-3 * kDc, 0, 0}, 1.0, kN), h, true, F.data()));
    EXPECT_NEAR(-F[0], kL, 1e-12 * kL);
  }
}

// Issue 4: a mass on the contact under a constant tangential load P = L/2 applied at once (a
// sphere that cannot roll on a slope with tan(theta) = mu/2, no damping): the tangential
// oscillation decays through the hysteresis loops, which are nested - so the mass must stay
// inside the range of the first loop and its mean position must settle, not creep. (Before the
// fix of the full memory the mean crept against the load by about the amplitude every few
// hundred cycles.)
TEST(MindlinDeresiewicz, NoRatchetingUnderAnUndampedForceControlledOscillation) {
  const auto f = md_law();
  const double m = 1e-3, P = 0.5 * kL, w = std::sqrt(kK0 / m), dt = 2.0 * M_PI / w / 100.0;
  double h[md::history_size] = {0}, x = 0.0, v = 0.0;
  V3 F{};
  const auto force = [&]() {
    f(kin({v, 0, 0}, dt, kN), h, true, F.data());
    return P + F[0];
  };
  double a = force() / m, xmin = 0.0, xmax = 0.0;
  const int per = 100, cycles = 600;
  std::vector<double> mean(cycles, 0.0);
  for (int c = 0; c < cycles; ++c) {
    for (int i = 0; i < per; ++i) {
      v += 0.5 * dt * a;
      x += dt * v;
      a = force() / m;
      v += 0.5 * dt * a;
      mean[c] += x / per;
      if (c < 2) xmin = std::min(xmin, x), xmax = std::max(xmax, x);
      if (c >= 2) {
        ASSERT_GE(x, xmin - 1e-9 * (xmax - xmin)) << "cycle " << c;
        ASSERT_LE(x, xmax + 1e-9 * (xmax - xmin)) << "cycle " << c;
      }
    }
  }
  // the first loading overshoots: the first loop spans more than the static displacement
  EXPECT_GT(xmax, 1.2 * kDc * (1.0 - std::pow(0.5, 2.0 / 3.0)));
  double m1 = 0.0, m2 = 0.0;
  for (int c = 200; c < 400; ++c) m1 += mean[c] / 200.0;
  for (int c = 400; c < 600; ++c) m2 += mean[c] / 200.0;
  EXPECT_LT(std::fabs(m2 - m1), 1e-3 * (xmax - xmin)) << "mean " << m1 << " -> " << m2;
}

// Walton-Braun has no memory of reversal points, so a closed displacement cycle about a loaded
// mean does not close the force loop: the unloading branch (D = L + T*) is stiffer than the
// loading branch (D = L - T*) and the load falls cycle after cycle (under a constant load: the
// contact creeps along the load, e.g. down a slope). This is the law, not a discretisation
// error: the kernel follows the chain of closed-form branches for any step.
TEST(MindlinWaltonBraunTangential, ClosedDisplacementCyclesLetTheLoadDecayAsTheBranchesPredict) {
  const double k0 = 2e7, dcw = 1.5 * kL / k0;
  for (int n : {100, 5}) {
    const auto f = wb_law(k0);
    double h[wbt::history_size] = {0}, delta = 0.0;
    const double dm = 0.3 * dcw, amp = 0.05 * dcw;
    drive(f, h, delta, dm, n, [](double, double, bool) {});
    const double t_start = wb_branch(k0, 0, 0, 1, dm);
    double dr = 0.0, tr = 0.0, s = 1.0, ts = t_start;  // the current branch: reversal point, direction
    for (int c = 0; c < 40; ++c) {
      for (double target : {dm + amp, dm - amp, dm}) {
        const double dir = target > delta ? 1.0 : -1.0;
        if (dir != s) dr = delta, tr = ts, s = dir;  // reversal: a new branch from the current load
        drive(f, h, delta, target, n, [&](double d, double t, bool) {
          EXPECT_NEAR(t, wb_branch(k0, dr, tr, s, d), 1e-9 * kL) << "cycle " << c << " d/d_c " << d / dcw;
        });
        ts = wb_branch(k0, dr, tr, s, target);
      }
    }
    EXPECT_LT(ts, 0.9 * t_start);  // the load at d = dm has decayed
  }
}
