// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: power-law loading/unloading hysteresis (after Sadd, Tai & Shukla 1993; the form is the
// reconstruction of physics_reference.md section 2.2.4).
//
//   loading      F = a_l xi^p                               (xi >= xi_max: new maximum)
//   unloading    F = a_ul (xi - xi_f)^(p+q),   xi_f = xi_max - (a_l xi_max^p / a_ul)^(1/(p+q))
//   reloading    along the unloading curve until it meets the loading curve, then on loading.
//
// xi_f is fixed by continuity at (xi_max, F_max). No attraction: the force is 0 below xi_f and
// the contact ends there (ContactEnd::zero_force). With q > 0 the plastic residual xi_f is
// negative for small maxima (xi_max^q < a_l/a_ul): such a contact is elastic (unloads on the
// loading curve, e = 1); above that threshold it dissipates. The restitution is discontinuous
// there: just above the threshold (xi_f = 0) e = sqrt((p+1)/(p+q+1)) < 1, because the unloading
// curve a_ul xi^(p+q) meets the loading curve only at xi_max. Fits near the threshold should use
// the integrated collision, not the closed forms (tdem-fit does). p = 1, q = 0 is Walton-Braun with
// constant k_ul = a_ul.
//
// Closed forms for a head-on impact at v0 (n = p + q, d = xi_max - xi_f):
//   xi_max = ((p+1) m* v0^2 / (2 a_l))^(1/(p+1)),   F_max = a_l xi_max^p
//   e^2 = W_unload / W_load = (d / xi_max) (p+1)/(n+1)        (1 if xi_f < 0)
//   t_c = (xi_max / v0) I(p) + (d / (e v0)) I(n),  I(a) = sqrt(pi) G(1 + 1/(a+1)) / G(1/2 + 1/(a+1))
//   q = 0: e = (a_l / a_ul)^(1/(2p)) for every v0.
#pragma once

#include <algorithm>
#include <cmath>

#include "../kinematics.h"
#include "../input_checks.h"
#include "../law_parameters.h"
#include "../law_unit.h"

namespace tdem {
namespace power_law {

template <class T>
struct Params {
  T a_load;    // a_l  [N/m^p]
  T p;         // loading exponent > 0
  T a_unload;  // a_ul [N/m^(p+q)]
  T q;         // extra unloading exponent >= 0
};

// Per-contact history: the largest overlap and the force-zero overlap of its unloading curve
// (stored when the maximum grows, so that unloading costs one pow()). Scalars: no sign flip.
// xi_f < 0 marks a maximum below the plastic threshold (elastic unloading on the loading curve).
inline constexpr HistorySlot history[] = {{"xi_max", false}, {"xi_f", false}};
inline constexpr int history_size = 2;
enum Slot { xi_max_slot = 0, xi_f_slot = 1 };

// The input line `normal power_law AL P AUL [Q]` (src/contact/law_parameters.h).
inline constexpr law::Parameter parameters[] = {
    {"AL", "loading coefficient a_l", "N/m^P", law::Bound::positive},
    {"P", "loading exponent", "1", law::Bound::positive},
    {"AUL", "unloading coefficient a_ul", "N/m^(P+Q)", law::Bound::positive},
    {"Q", "extra unloading exponent", "1", law::Bound::non_negative, -1, true, 0.0},
};
inline constexpr law::Description description =
    law::describe("normal", "power_law", false, parameters, history, history_size);
inline Params<double> from_values(const double* v) { return {v[0], v[1], v[2], v[3]}; }

// x^a with the common exponents of this law (1, 3/2, 2) without pow(); predictable branches.
template <class T>
TDEM_KERNEL T power(T x, T a) noexcept {
  if (a == T(1.5)) return x * std::sqrt(x);
  if (a == T(1)) return x;
  if (a == T(2)) return x * x;
  return std::pow(x, a);
}

// x^(1/a) for the same exponents.
template <class T>
TDEM_KERNEL T root(T x, T a) noexcept {
  if (a == T(1.5)) return std::cbrt(x * x);
  if (a == T(1)) return x;
  if (a == T(2)) return std::sqrt(x);
  return std::pow(x, T(1) / a);
}

template <class T>
TDEM_KERNEL NormalResult<T> force(const Params<T>& p, const NormalKinematics<T>& kin, T* hist,
                                  bool update) noexcept {
  const T xi = kin.overlap;
  if (xi <= T(0)) return {T(0), T(0), T(0), T(0)};
  const T n = p.p + p.q;
  if (xi >= hist[xi_max_slot]) {  // loading: a new maximum
    const T loading = p.a_load * power(xi, p.p);
    if (update) {
      hist[xi_max_slot] = xi;
      hist[xi_f_slot] = xi - root(loading / p.a_unload, n);
    }
    return {loading, loading, p.p * loading / xi, T(0)};
  }
  const T xi_f = hist[xi_f_slot];
  if (xi_f < T(0)) {  // below the plastic threshold: elastic
    const T loading = p.a_load * power(xi, p.p);
    return {loading, loading, p.p * loading / xi, T(0)};
  }
  if (xi <= xi_f) return {T(0), T(0), T(0), T(0)};
  // With xi_f >= 0 and n >= p the unloading curve lies below the loading one on (xi_f, xi_max).
  const T unloading = p.a_unload * power(xi - xi_f, n);
  return {unloading, unloading, n * unloading / (xi - xi_f), T(0)};
}

// ---------------------------------------------------------------- checks and closed forms
inline void validate(const Params<double>& p) {
  checks::positive("loading coefficient a_l", p.a_load);
  checks::positive("loading exponent p", p.p);
  checks::positive("unloading coefficient a_ul", p.a_unload);
  checks::non_negative("extra unloading exponent q", p.q);
}

inline double shape_integral(double a) {  // I(a) = int_0^1 (1 - x^(a+1))^(-1/2) dx
  const double b = 1.0 / (a + 1.0);
  return std::sqrt(M_PI) * std::tgamma(1.0 + b) / std::tgamma(0.5 + b);
}

inline double max_overlap(const Params<double>& p, double meff, double v0) {
  validate(p);
  checks::positive("effective mass m*", meff);
  checks::positive("impact velocity v0", v0);
  return std::pow((p.p + 1.0) * meff * v0 * v0 / (2.0 * p.a_load), 1.0 / (p.p + 1.0));
}

// Unloading amplitude d = xi_max - xi_f (> xi_max: elastic contact).
inline double unloading_amplitude(const Params<double>& p, double xi_max) {
  return std::pow(p.a_load * std::pow(xi_max, p.p) / p.a_unload, 1.0 / (p.p + p.q));
}

inline double restitution(const Params<double>& p, double meff, double v0) {
  const double xm = max_overlap(p, meff, v0);
  const double d = unloading_amplitude(p, xm);
  if (d > xm) return 1.0;
  return std::sqrt(d / xm * (p.p + 1.0) / (p.p + p.q + 1.0));
}

inline double contact_time(const Params<double>& p, double meff, double v0) {
  const double xm = max_overlap(p, meff, v0);
  const double d = unloading_amplitude(p, xm);
  const double t_load = xm / v0 * shape_integral(p.p);
  if (d > xm) return 2.0 * t_load;
  return t_load + d / (restitution(p, meff, v0) * v0) * shape_integral(p.p + p.q);
}

inline double residual_overlap(const Params<double>& p, double meff, double v0) {
  const double xm = max_overlap(p, meff, v0);
  const double d = unloading_amplitude(p, xm);
  return d > xm ? 0.0 : xm - d;
}

// q = 0: a_ul for restitution e (independent of v0).
inline Params<double> from_restitution(double a_l, double p, double e) {
  checks::restitution(e);
  return {a_l, p, a_l / std::pow(e, 2.0 * p), 0.0};
}

// ---------------------------------------------------------------- the law as a unit
// (src/contact/law_unit.h; listed in src/contact/laws.h)
struct Law {
  static constexpr const law::Description& description = power_law::description;
  using Params = power_law::Params<double>;
  static constexpr bool needs_reff = false;
  static constexpr double stress_strain_exponent = 1.0;
  static constexpr ContactEnd end = ContactEnd::zero_force;
  static constexpr const char* properties[] = {"loadingCoefficient", "loadingExponent", "unloadingCoefficient",
                                               "unloadingExponentIncrement"};
  static constexpr const char* tangential_basis_text = "dF/dxi";
  static Params params(const double* v) {
    const Params p = from_values(v);
    validate(p);
    return p;
  }
  static TDEM_KERNEL NormalResult<double> force(const Params& p, const NormalKinematics<double>& kin, double* hist, bool update) {
    return power_law::force(p, kin, hist, update);
  }
  // k_t = KAPPA dF/dxi of the branch in use
  static TDEM_KERNEL double tangential_basis(const Params&, const NormalResult<double>& r, const NormalKinematics<double>&) {
    return r.stiffness;
  }
  // time-step advice: the larger of the loading tangent p F_max / xi_max and the unloading tangent
  // (p+q) F_max / (xi_max - xi_f) at xi_max; closed-form contact time
  static const char* family(const Params&) { return "power_law"; }
  static double max_overlap(const Params& p, double meff, double, double v) {
    return power_law::max_overlap(p, meff, v);
  }
  static double stiffness_at(const Params& p, double, double xi_max) {
    const double f_max = p.a_load * std::pow(xi_max, p.p);
    const double d = unloading_amplitude(p, xi_max);
    double k = p.p * f_max / xi_max;
    if (d <= xi_max) k = std::max(k, (p.p + p.q) * f_max / d);
    return k;
  }
  static double contact_time(const Params& p, double meff, double, double v) {
    return power_law::contact_time(p, meff, v);
  }
  static double contact_time_estimate(const Params& p, double meff, double, double v0) {
    return 2.0 * power_law::max_overlap(p, meff, v0) / v0 * shape_integral(p.p);
  }
};

}  // namespace power_law
}  // namespace tdem
