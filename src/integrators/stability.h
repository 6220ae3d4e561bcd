// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: linear stability of the integration schemes of schemes.h on the damped oscillator
//     x'' = -omega^2 x - 2 zeta omega x'
// (a linear spring-dashpot contact of stiffness k = m* omega^2 and damping gamma = 2 zeta m* omega),
// computed from the schemes themselves, not from formulas per scheme: one step of a scheme is a
// linear map of the state (x, v, the acceleration the host keeps from the last force evaluation,
// the scheme's history); its matrix is built by stepping the unit vectors through
// Kernel::predict -> force -> Kernel::correct, and the scheme is stable at the step h while the
// spectral radius of that matrix is <= 1. critical_step() finds the largest h omega of the first
// stable interval by a scan and bisection. Closed forms it reproduces (tests/unit): velocity and
// position Verlet, leap-frog, symplectic Euler undamped 2; symplectic Euler damped
// 2 (sqrt(1 + zeta^2) - zeta); explicit Euler undamped 0 (unstable at every step).
#pragma once

#include <cmath>
#include <algorithm>
#include <complex>
#include <vector>

#include "integrators/schemes.h"

namespace tdem {
namespace integrators {

namespace detail {
// One step of scheme S for one component (component 0 of the 3-vectors) of the oscillator with
// h omega = w and damping ratio zeta (omega = 1, h = w). State: [x, v, a, hist(comp 0)...].
template <Scheme S> struct OscillatorStep {
  static constexpr int H = Kernel<S, true>::history / 3;  // history vectors of a channel with position
  static constexpr int N = 3 + H;
  static void apply(const double* in, double* out, double w, double zeta) {
    double x[3] = {in[0], 0.0, 0.0}, v[3] = {in[1], 0.0, 0.0}, a[3] = {in[2], 0.0, 0.0};
    double hist[Kernel<S, true>::history > 0 ? Kernel<S, true>::history : 1] = {};
    for (int j = 0; j < H; ++j) hist[3 * j] = in[3 + j];
    Kernel<S, true>::predict(x, v, a, hist, w);
    a[0] = -x[0] - 2.0 * zeta * v[0];
    Kernel<S, true>::correct(x, v, a, hist, w);
    out[0] = x[0];
    out[1] = v[0];
    out[2] = a[0];
    for (int j = 0; j < H; ++j) out[3 + j] = hist[3 * j];
  }
};

// Spectral radius of a small dense matrix (row-major, n x n) by the QR-free route: the largest
// |root| of its characteristic polynomial found from the Faddeev-LeVerrier coefficients and
// Durand-Kerner iteration. n <= 12 here; accurate to ~1e-10, ample for a stability boundary.
inline double spectral_radius(const std::vector<double>& A, int n) {
  // Faddeev-LeVerrier: p(l) = l^n + c1 l^(n-1) + ... + cn
  std::vector<double> M(n * n, 0.0), AM(n * n), c(n + 1, 0.0);
  c[0] = 1.0;
  for (int k = 1; k <= n; ++k) {
    // M_k = A M_{k-1} + c_{k-1} I, with M_0 = 0
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        double s = 0.0;
        for (int l = 0; l < n; ++l) s += A[i * n + l] * M[l * n + j];
        AM[i * n + j] = s;
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M[i * n + j] = AM[i * n + j] + (i == j ? c[k - 1] : 0.0);
    double tr = 0.0;
    for (int i = 0; i < n; ++i)
      for (int l = 0; l < n; ++l) tr += A[i * n + l] * M[l * n + i];
    c[k] = -tr / k;
  }
  // Durand-Kerner on the monic polynomial
  using C = std::complex<double>;
  std::vector<C> z(n);
  const C seed(0.4, 0.9);
  double bound = 0.0;
  for (int k = 1; k <= n; ++k) bound = std::max(bound, std::pow(std::fabs(c[k]), 1.0 / k));
  const double scale = 1.0 + 2.0 * bound;
  for (int i = 0; i < n; ++i) z[i] = scale * std::pow(seed, i);
  auto p = [&](C l) {
    C s = 1.0;
    for (int k = 1; k <= n; ++k) s = s * l + c[k];
    return s;
  };
  for (int it = 0; it < 2000; ++it) {
    double change = 0.0;
    for (int i = 0; i < n; ++i) {
      C den = 1.0;
      for (int j = 0; j < n; ++j)
        if (j != i) den *= (z[i] - z[j]);
      if (std::abs(den) == 0.0) den = 1e-300;
      const C dz = p(z[i]) / den;
      z[i] -= dz;
      change = std::max(change, std::abs(dz));
    }
    if (change < 1e-15 * scale) break;
  }
  double r = 0.0;
  for (const C& l : z) r = std::max(r, std::abs(l));
  return r;
}
}  // namespace detail

// Spectral radius of one step of scheme s on the oscillator at h omega = w, damping ratio zeta.
inline double amplification(Scheme s, double w, double zeta) {
  return dispatch(s, [&](auto tag) {
    using Step = detail::OscillatorStep<decltype(tag)::value>;
    constexpr int n = Step::N;
    std::vector<double> A(n * n);
    double e[n], out[n];
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) e[i] = i == j ? 1.0 : 0.0;
      Step::apply(e, out, w, zeta);
      for (int i = 0; i < n; ++i) A[i * n + j] = out[i];
    }
    return detail::spectral_radius(A, n);
  });
}

// Largest h omega of the first stable interval (0, w_c] of scheme s at damping ratio zeta
// (spectral radius <= 1 + tol); 0 if the scheme is unstable at every small step (e.g. explicit
// Euler without damping). Strong damping shrinks w_c like 1/zeta (symplectic Euler:
// 2 (sqrt(1 + zeta^2) - zeta) ~ 1/zeta), so the scan starts at w = 1e-4 / (1 + zeta) and grows
// by 5 % of w, at most 0.01 per step, up to w_max; then bisects to a relative 1e-9.
inline double critical_step(Scheme s, double zeta, double tol = 1e-9, double w_max = 6.0) {
  auto stable = [&](double w) { return amplification(s, w, zeta) <= 1.0 + tol; };
  const double w0 = 1e-4 / (1.0 + zeta);
  if (!stable(w0)) return 0.0;
  double lo = w0, hi = -1.0;
  while (lo < w_max) {
    const double w = std::min(w_max, lo + std::min(0.01, 0.05 * lo));
    if (!stable(w)) {
      hi = w;
      break;
    }
    lo = w;
  }
  if (hi < 0.0) return w_max;
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (stable(mid)) lo = mid; else hi = mid;
  }
  return lo;
}

}  // namespace integrators
}  // namespace tdem
