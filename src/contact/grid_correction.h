// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the time-grid correction of the step in which a contact starts and of the step in which
// it ends (issue 22; validation/integrators/README.md, "Time-grid correction").
//
// Why. A host integrates with one force evaluation per step: the force F_n at grid time t_n acts
// as the momentum kick h F_n of the window W_n = [t_n - h/2, t_n + h/2] (velocity Verlet is the
// leap-frog v(n+1/2) = v(n-1/2) + h F_n / m; every one-step scheme integrates its force samples
// with a rule that is exact for linear forces). Inside a contact the force is smooth and this is
// second order. But the contact starts at a touch time t0 and ends at a time te between grid
// points, where the force jumps (the dashpot force gamma xi' of a linear law, the Coulomb limit of
// the tangential force) or has a kink; sampled on the grid, each of the two events costs an
// impulse error O(F h), and the restitution coefficient is first order at any step that does not
// divide the contact time (the integrator study, finding 2).
//
// What. Write F_s(t) for the force the law would give if the contact went on (before t0 and
// after te). The kicks of the windows around an event then equal the true impulse up to the
// part of a window outside the contact, which is removed (or added) as one extra impulse:
//   start, at the first step with contact (t0 in (t_{n-1}, t_n]), time since the touch
//          tau = t_n - t0:
//          true  = int_{t0}^{t_n + h/2} F_s = h F_n + int_{t0}^{t_n - h/2} F_s        (signed)
//   end,   at the first step m without contact (te in (t_{m-1}, t_m]), s = te - t_{m-1}:
//          true  = int_{t_{m-1} - h/2}^{te} F_s = h F_{m-1} + int_{t_{m-1} + h/2}^{te} F_s
// F_s is taken linear through the two values that bracket the event: (t0, F(0+)) and (t_n, F_n)
// at the start, (t_{m-1}, F_{m-1}) and (te, F(te)) at the end, where F(0+) and F(te) are the law
// itself at the event (the dashpot force at zero overlap, zero for a force that ends at zero).
// The extra impulse is then exact for a force linear in time over the step, O(h^3) for a smooth
// one; it is applied as the extra force (impulse / h) at step n, or at step m where the contact
// force is otherwise zero. The tangential force takes the same two formulas component by
// component, with its spring started at the touch: the history increment of the first step is
// v_t tau instead of v_t h.
//
// The event times come from the overlap and its rate, which the law has anyway:
//   tau = xi_n / xi'_n (linear; O(h^2) in time), accepted only for a touch inside the last
//         step (0 <= tau <= h, up to a tolerance for a rate that changed over the step); a
//         contact that is new to the host but not to the pair (an initial overlap, an insertion
//         overlap, a pair that approaches with xi' <= 0) is not corrected;
//   s   = h xi_{m-1} / (xi_{m-1} - xi_m) for the zero-overlap end, and
//         h F_{m-1} / (F_{m-1} - F_u,m) for the zero-force end (F_u the law's force before its
//         clip at zero: the end is where it crosses zero).
// Nothing here depends on the law: any normal law (linear, Hertz, hysteretic, extended) and any
// tangential law plug in through their values at the bracketing points.
#pragma once

#include <cmath>

#include "kinematics.h"

namespace tdem {
namespace grid {

// Time since the touch, tau = xi / xi' in [0, h], or -1 when the contact did not start within
// the last step: xi' <= 0, or xi / xi' > kTouchTolerance h (a rate that fell over the step may
// put the linear estimate a little beyond h; up to the tolerance it is clipped to h).
inline constexpr double kTouchTolerance = 2.0;

template <class T>
TDEM_KERNEL T touch_age(T xi, T xi_dot, T h) noexcept {
  if (!(xi_dot > T(0)) || !(xi >= T(0))) return T(-1);
  if (xi > kTouchTolerance * h * xi_dot) return T(-1);
  const T tau = xi / xi_dot;
  return tau < h ? tau : h;
}

// r^x (r > 0) without pow for a multiple of 1/4 in [-4, 4]: the exponents of the common laws
// (Hertz 3/2, Tsuji's 1/4, Kuwabara-Kono's 1/2) and those of their near-window sums (x + 1, x + 2,
// x - 3); a start or an end of a Hertz + Tsuji contact takes about 30 powers. Whole r factors times
// sqrt(sqrt(r)), sqrt(r) or both (so 1, r, r r, sqrt(r) and r sqrt(r) are those expressions
// exactly).
template <class T>
TDEM_KERNEL T power(T r, T x) noexcept {
  const T x4 = T(4) * x;
  if (!(x4 == std::floor(x4) && std::fabs(x) <= T(4))) return std::pow(r, x);
  const int n = static_cast<int>(std::fabs(x4));
  T result = T(1);
  for (int k = 0; k < n / 4; ++k) result *= r;
  if (n % 4 == 2) {
    result *= std::sqrt(r);
  } else if (n % 4 != 0) {
    const T s = std::sqrt(r), q = std::sqrt(s);
    result *= n % 4 == 1 ? q : s * q;
  }
  return x < T(0) ? T(1) / result : result;
}

// The correction acts on resolved contacts only: at coarser steps (a few steps per contact, up to
// the critical step) the models above, extrapolated over a window as long as the contact, can put
// energy in where the uncorrected step does not. At its first step a contact is counted as
// resolved when its elastic contact time, estimated from the law's elastic part there
// (F = c xi^p, c = elastic / xi^p: t_c = 2 I(p) xi_max / v with xi_max = ((p+1) m* v^2 / (2c))^(1/(p+1))
// and I(p) = sqrt(pi) Gamma(1 + 1/(p+1)) / Gamma(1/2 + 1/(p+1)), pi sqrt(m*/k) for p = 1), is at
// least kMinSteps steps and its damping time m* / gamma (gamma the law's damping coefficient
// there) at least kMinDampingSteps steps (a strongly damped contact ends within a step or two of
// a zero-force end, whatever its elastic time); otherwise neither its start nor its end is
// corrected (the contact is integrated as without the correction).
inline constexpr double kMinSteps = 8.0;
inline constexpr double kMinDampingSteps = 2.0;

template <class T>
inline bool resolved(T elastic, T p, T damping, T xi, T xi_dot, T meff, T h) noexcept {
  if (!(elastic > T(0) && xi > T(0) && xi_dot > T(0) && meff > T(0))) return false;
  if (damping * kMinDampingSteps * h > meff) return false;
  if (p == T(1)) return T(M_PI) * std::sqrt(meff * xi / elastic) >= kMinSteps * h;  // pi sqrt(m*/k)
  // 2 xi_max / xi' shape >= kMinSteps h, with xi_max^(p+1) = (p + 1) m* xi'^2 / (2 c): compared
  // as powers p + 1 (a multiple of 1/4 for the common laws: no pow)
  const T c = elastic / power(xi, p);
  const T a = T(1) / (p + T(1));
  const T shape = p == T(1.5) ? T(1.471637592162353) : std::sqrt(T(M_PI)) * std::tgamma(T(1) + a) / std::tgamma(T(0.5) + a);
  return (p + T(1)) * meff * xi_dot * xi_dot / (T(2) * c) >= power(kMinSteps * h * xi_dot / (T(2) * shape), p + T(1));
}

// The force near an event as a sum of two powers of the time t' from the event (the touch, or
// the end backwards in time):
//     F(t') = e (t'/t_ref)^p + d (t'/t_ref)^q,
// e and d the force's two parts at the sample t' = t_ref (the elastic part and the rest, for a
// normal law; the slope part and the value at the event for a linear model), p and q their
// exponents. Exact for the linear law (p = 1, q = 0), for Hertz (p = 3/2) with linear (q = 0),
// Kuwabara-Kono (q = 1/2) or Tsuji (q = 1/4) damping along a straight approach: a linear model
// in time cannot follow xi^(1/4) near the touch and does worse than no correction at all there.
// Returns int_0^length F(t') dt'.
template <class T>
TDEM_KERNEL T power_impulse(T e, T p, T d, T q, T t_ref, T length) noexcept {
  const T floor = T(1e-12) * length;
  const T r = length / (t_ref > floor ? t_ref : floor);
  return length * (e * power(r, p) / (p + T(1)) + d * power(r, q) / (q + T(1)));
}

// The exponent x of a part that scales as xi^x, from its values at xi and at xi / 2 (a law
// evaluated twice at an event); `fallback` where the part is zero or changes sign. Clipped to
// [0, 4]; within 1e-9 of a multiple of 1/4, that multiple (the exponents of the common laws, which
// power() then takes without pow).
template <class T>
TDEM_KERNEL T power_exponent(T f, T f_half, T fallback) noexcept {
  if (!(f * f_half > T(0))) return fallback;
  if (f == T(2) * f_half) return T(1);  // the linear law: exact in binary, no log
  if (f == f_half) return T(0);
  T x = std::log2(f / f_half);
  const T quarter = std::round(T(4) * x) / T(4);
  if (std::fabs(x - quarter) < T(1e-9)) x = quarter;  // 1 and 0 exactly for the linear law
  return x < T(0) ? T(0) : (x > T(4) ? T(4) : x);
}

// Time from t_{m-1} to the end in [0, h]: where the linear interpolation of a quantity that
// was positive at t_{m-1} (q_prev > 0: the overlap, or the unclipped force) reaches zero at
// q_now <= 0.
template <class T>
TDEM_KERNEL T end_time(T q_prev, T q_now, T h) noexcept {
  if (!(q_prev > T(0))) return T(0);
  if (!(q_now < T(0))) return h;
  return h * q_prev / (q_prev - q_now);
}

// The kicks after the start (and before the end) sample the force on the grid too. Where a part
// of the force grows like t'^x with 0 < x < 1 (Tsuji damping, x = 1/4), its curvature ~ t'^(x-2)
// is not bounded near the event, and the sampling errors of the next windows add up to
// O(h^(1+x)): order 1.25 with Tsuji damping however well the event step is treated. They are
// known from the model: the window centred u h after the event (u = event offset / h + k) has
// the error (midpoint sample minus integral) h c (h/t_ref)^x D(u), with
//     D(u) = u^x - ((u + 1/2)^(x+1) - (u - 1/2)^(x+1)) / (x + 1),
// summed for the next kNearWindows windows exactly and beyond them as the integral of D (below;
// D(u) ~ x (1 - x) u^(x-2) / 24, the sum converges for x < 1). The sum is
// added to the event step's kick (as a force: / h), which moves an impulse of O(h^(1+x)) by a few
// steps: O(h^(2+x)). Parts with exponent 0, >= 1 (bounded or integrable curvature, second order
// anyway) add nothing.
inline constexpr int kNearWindows = 3;

template <class T>
TDEM_KERNEL T near_windows(T c, T x, T t_ref, T u0, T h) noexcept {
  if (!(x > T(0) && x < T(1)) || c == T(0)) return T(0);
  const T floor = T(1e-12) * h;
  const T scale = c * power(h / (t_ref > floor ? t_ref : floor), x);
  T sum = T(0);
  for (int k = 1; k <= kNearWindows; ++k) {
    const T u = u0 + T(k);
    sum += power(u, x) - (power(u + T(0.5), x + T(1)) - power(u - T(0.5), x + T(1))) / (x + T(1));
  }
  // beyond: the sum is the integral of D from v = u0 + K + 1/2, which has the closed form
  // ((v + 1/2)^(x+2) - (v - 1/2)^(x+2)) / ((x+1)(x+2)) - v^(x+1) / (x+1), plus the midpoint-rule
  // term D'(v)/24, D'(v) ~ x (1 - x)(x - 2) v^(x-3) / 24 (Euler-Maclaurin; then good to ~1e-5 of
  // the sum)
  const T v = u0 + T(kNearWindows) + T(0.5);
  sum += (power(v + T(0.5), x + T(2)) - power(v - T(0.5), x + T(2))) / ((x + T(1)) * (x + T(2))) -
         power(v, x + T(1)) / (x + T(1)) + x * (T(1) - x) * (x - T(2)) * power(v, x - T(3)) / T(576);
  return -scale * sum;  // the extra force: minus the sampling excess of those windows
}

// The tangential force of the two events, for any tangential law from its samples:
//   sliding (|F_t| at the friction limit mu F_n, F_n > 0) it follows the normal force: the
//   corrected tangential kick is F_t / F_n times the corrected normal kick;
//   sticking it is linear in time, from the law's value at the touch (spring 0) to its sample,
//   and at the end from the last sample to that sample capped by the limit at the end,
//   mu |F_n(end)| (0 for a zero-force end).
template <class T>
TDEM_KERNEL bool sliding(T ft_squared, T mu, T fn) noexcept {
  return fn > T(0) && ft_squared >= mu * mu * fn * fn * T(1.0 - 1e-9);
}
// The factor that caps a tangential force of squared size ft_squared to the limit.
template <class T>
TDEM_KERNEL T cap_factor(T ft_squared, T limit) noexcept {
  return ft_squared > limit * limit ? limit / std::sqrt(ft_squared) : T(1);
}

// The end step needs the last contact step's values. A host does not keep them (that would cost
// stores at every step of every contact): it reconstructs them at the end from the law's history,
// which still holds that step, at the overlap one step back along the rate now. For the position
// update of velocity Verlet (x+ = x + h v_half, the rate the force of plain velocity Verlet sees)
// this is the last overlap up to the turn of the normal; for the other schemes it is O(h^2).
// With a predicted velocity the estimate of a contact that ended just after its last step can come
// out at or below zero; it is then taken as a millionth of the step's travel (the end at the last
// step, where the model of the end stays regular: its elastic part over s is finite).
template <class T>
TDEM_KERNEL T previous_overlap(T xi, T xi_dot, T h) noexcept {
  const T x = xi - h * xi_dot;
  const T floor = T(1e-6) * h * std::fabs(xi_dot);
  return x > floor ? x : floor;
}

// Is the reconstructed last step a contact step whose end can be corrected? Its overlap must be
// positive and, for a zero-overlap end, above the overlap now (a contact still approaching when it
// is found ended was a graze seen through a predicted velocity), and for a zero-force end its force
// positive. Otherwise the end model would be singular (s = 0 with a finite force); that end is left
// alone.
template <class T>
TDEM_KERNEL bool end_usable(T xi_prev, T f_prev, T xi_now, bool at_zero_force) noexcept {
  if (!(xi_prev > T(0)) || !std::isfinite(f_prev)) return false;
  return at_zero_force ? f_prev > T(0) : xi_prev > xi_now;
}

// The one value a host keeps per contact with the correction on (after the law's own history):
// 0 no contact at the last step; kFlagOn a corrected contact (its start was seen and resolved);
// kFlagEnded a corrected contact whose force has ended at zero (a zero-force law whose overlap
// lasts longer); kFlagSeen a contact that is not corrected. A scalar: it does not change sign
// with the pair order.
inline constexpr int history_size = 1;
inline constexpr double kFlagOn = 1.0, kFlagEnded = 2.0, kFlagSeen = 4.0;

// The two corrected kicks, as forces (impulse / h):
//   at the first contact step n (touch tau before t_n): the whole kick of the contact up to the
//   end of the window, int_0^{tau + h/2} F(t') dt' / h, in place of F_n;
//   at the first step m after the end (s after t_{m-1}, where F_{m-1} was applied): the part of
//   the contact in the windows m-1 and m minus what the kick of m-1 gave,
//   int_0^{s + h/2} F(t') dt' / h - F_{m-1}, t' counted back from the end.
template <class T>
TDEM_KERNEL T start_force(T e, T p, T d, T q, T tau, T h) noexcept {
  return power_impulse(e, p, d, q, tau, tau + T(0.5) * h) / h + near_windows(e, p, tau, tau / h, h) +
         near_windows(d, q, tau, tau / h, h);
}
template <class T>
TDEM_KERNEL T end_extra(T f_prev_applied, T e, T p, T d, T q, T s, T h) noexcept {
  return power_impulse(e, p, d, q, s, s + T(0.5) * h) / h - f_prev_applied + near_windows(e, p, s, s / h, h) +
         near_windows(d, q, s, s / h, h);
}

}  // namespace grid
}  // namespace tdem
