// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: linear viscoelastic normal law (linear spring-dashpot, Cundall & Strack 1979).
//
//   F = k xi + gamma xi_dot
//
// Two end-of-contact conventions (physics_reference.md section 2.2.2):
//   ContactEnd::zero_overlap  contact lasts until xi = 0; F may become attractive near the end.
//                             e = exp(-pi beta / sqrt(1 - beta^2)), t_c = pi / omega.
//   ContactEnd::zero_force    F is clipped at 0 (no attraction); the contact ends when
//                             k xi + gamma xi_dot = 0.  t_c = 2 atan(omega/delta)/omega,
//                             e = exp(-delta t_c), and the same form continues into the
//                             over-damped range (t_c = 2 atanh(s/delta)/s, s^2 = delta^2 - omega0^2).
// with omega0^2 = k/m*, delta = gamma/(2 m*), omega^2 = omega0^2 - delta^2, beta = delta/omega0.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "../kinematics.h"
#include "../law_parameters.h"

namespace tdem {

// ContactEnd: kinematics.h

namespace lsd {

template <class T>
struct Coefficients {
  T k;      // normal stiffness [N/m]
  T gamma;  // normal damping coefficient [kg/s]
};

// Stiffness and damping per unit effective mass: k = m* k_per_mass, gamma = m* gamma_per_mass.
// This is how (e, t_c) parameters act on pairs of different mass.
template <class T>
struct MassRates {
  T k_per_mass;      // omega0^2 [1/s^2]
  T gamma_per_mass;  // 2 delta  [1/s]
  Coefficients<T> at(T meff) const { return {meff * k_per_mass, meff * gamma_per_mass}; }
};

// ---------------------------------------------------------------- the force kernel
template <ContactEnd End, class T>
TDEM_KERNEL NormalResult<T> force(const Coefficients<T>& c, const NormalKinematics<T>& kin) noexcept {
  const T elastic = c.k * kin.overlap;
  const T dissipative = c.gamma * kin.overlap_rate;
  T f = dissipative + elastic;
  if constexpr (End == ContactEnd::zero_force) {
    if (f < T(0)) f = T(0);
  }
  return {f, elastic, c.k, c.gamma};
}

// The same law for hosts that apply the normal force along the unnormalised centre vector
// del = x_i - x_j (LAMMPS): returns F/r = k xi / r + gamma xi_dot / r with xi_dot = -vnnr / r,
// vnnr = (v_i - v_j) . del, evaluated in the order LAMMPS's granular styles use, so that a
// host adapter reproduces them bit for bit. Clipped at 0 for the zero-force end.
template <ContactEnd End, class T>
TDEM_KERNEL T force_over_distance(const Coefficients<T>& c, T overlap, T vnnr, T rinv,
                                  T rsqinv) noexcept {
  T ccel = c.k * overlap * rinv - c.gamma * vnnr * rsqinv;
  if constexpr (End == ContactEnd::zero_force) {
    if (ccel < T(0)) ccel = T(0);
  }
  return ccel;
}

template <class T>
inline NormalResult<T> force(ContactEnd end, const Coefficients<T>& c,
                             const NormalKinematics<T>& kin) noexcept {
  return end == ContactEnd::zero_force ? force<ContactEnd::zero_force>(c, kin)
                                       : force<ContactEnd::zero_overlap>(c, kin);
}

// ---------------------------------------------------------------- closed forms
// Dimensionless: time in units of 1/omega0, damping ratio beta = delta/omega0.

// omega0 * t_c for damping ratio beta (infinite if the contact never ends).
inline double scaled_contact_time(double beta, ContactEnd end) {
  if (!(beta >= 0.0)) throw std::domain_error("damping ratio must be >= 0, got " + std::to_string(beta));
  if (end == ContactEnd::zero_overlap) {
    if (beta >= 1.0) return std::numeric_limits<double>::infinity();
    return M_PI / std::sqrt(1.0 - beta * beta);
  }
  if (beta < 1.0) {
    const double w = std::sqrt(1.0 - beta * beta);
    return 2.0 * std::atan2(w, beta) / w;
  }
  if (beta == 1.0) return 2.0;
  const double s = std::sqrt(beta * beta - 1.0);
  return 2.0 * std::atanh(s / beta) / s;
}

// Coefficient of normal restitution for damping ratio beta.
inline double restitution_from_damping_ratio(double beta, ContactEnd end) {
  const double tau = scaled_contact_time(beta, end);
  if (end == ContactEnd::zero_overlap) {
    if (!std::isfinite(tau)) return 0.0;
    return std::exp(-M_PI * beta / std::sqrt(1.0 - beta * beta));
  }
  return std::exp(-beta * tau);
}

inline void check_restitution(double e) {
  if (!(e > 0.0 && e <= 1.0))
    throw std::domain_error("coefficient of restitution " + std::to_string(e) +
                            " is outside the allowed range (0, 1]");
}

// Damping ratio that gives restitution e. zero_overlap: closed form; zero_force: bisection
// (e(beta) is monotone), valid for every e in (0, 1].
inline double damping_ratio_from_restitution(double e, ContactEnd end) {
  check_restitution(e);
  if (e == 1.0) return 0.0;
  const double le = std::log(e);
  if (end == ContactEnd::zero_overlap) return -le / std::sqrt(le * le + M_PI * M_PI);
  double lo = 0.0, hi = 1.0;
  while (restitution_from_damping_ratio(hi, end) > e) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e150) throw std::domain_error("restitution " + std::to_string(e) + " cannot be reached");
  }
  for (int it = 0; it < 200 && hi - lo > 1e-16 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (restitution_from_damping_ratio(mid, end) > e) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

inline void check_positive(const char* what, double v) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::domain_error(std::string(what) + " " + std::to_string(v) + " must be > 0");
}

// From measured restitution and contact time, per unit effective mass.
inline MassRates<double> rates_from_restitution_and_time(double e, double tc, ContactEnd end) {
  check_positive("contact time", tc);
  const double beta = damping_ratio_from_restitution(e, end);
  const double omega0 = scaled_contact_time(beta, end) / tc;
  return {omega0 * omega0, 2.0 * beta * omega0};
}

inline Coefficients<double> from_restitution_and_time(double e, double tc, double meff, ContactEnd end) {
  check_positive("effective mass", meff);
  return rates_from_restitution_and_time(e, tc, end).at(meff);
}

// From restitution and a chosen stiffness.
inline Coefficients<double> from_restitution_and_stiffness(double e, double k, double meff, ContactEnd end) {
  check_positive("stiffness", k);
  check_positive("effective mass", meff);
  const double beta = damping_ratio_from_restitution(e, end);
  return {k, 2.0 * beta * std::sqrt(k * meff)};
}

// Stiffness from material data: the linear k whose undamped maximum overlap at the
// characteristic impact velocity v_char equals Hertz's, xi_max = (5 m* v^2/(4 k_H))^(2/5) with
// k_H = 4/3 E* sqrt(R*):  k = 16/15 sqrt(R*) E* (15 m* v^2 / (16 sqrt(R*) E*))^(1/5).
// (This is the stiffness of LIGGGHTS `model hooke`; evaluated in the same order.)
template <class T>
inline T stiffness_matching_hertz(T e_eff, T r_eff, T meff, T v_char) noexcept {
  const T sqrt_r = std::sqrt(r_eff);
  return T(16.) / T(15.) * sqrt_r * e_eff *
         std::pow(T(15.) * meff * v_char * v_char / (T(16.) * sqrt_r * e_eff), T(0.2));
}

// Per-contact damping for a stiffness that varies from contact to contact, given ln e
// (zero_overlap convention): gamma = sqrt(4 m* k ln^2 e / (ln^2 e + pi^2)) = 2 beta sqrt(k m*).
template <class T>
inline T damping_zero_overlap_from_log_restitution(T log_e, T k, T meff) noexcept {
  const T l2 = log_e * log_e;
  return std::sqrt(T(4.) * meff * k * l2 / (l2 + T(M_PI) * T(M_PI)));
}

// Same for any convention, from the damping ratio beta (damping_ratio_from_restitution).
template <class T>
inline T damping_from_ratio(T beta, T k, T meff) noexcept {
  return T(2.) * beta * std::sqrt(k * meff);
}

inline double damping_ratio(const Coefficients<double>& c, double meff) {
  check_positive("stiffness", c.k);
  check_positive("effective mass", meff);
  if (!(c.gamma >= 0.0)) throw std::domain_error("damping " + std::to_string(c.gamma) + " must be >= 0");
  return c.gamma / (2.0 * std::sqrt(c.k * meff));
}

// Back: what a pair of effective mass meff does with these coefficients.
inline double restitution(const Coefficients<double>& c, double meff, ContactEnd end) {
  return restitution_from_damping_ratio(damping_ratio(c, meff), end);
}

inline double contact_time(const Coefficients<double>& c, double meff, ContactEnd end) {
  return scaled_contact_time(damping_ratio(c, meff), end) / std::sqrt(c.k / meff);
}

// Largest overlap of a head-on impact at relative normal velocity v0 (closed form):
// xi(t) = v0 e^{-delta t} sin(omega t)/omega, maximum where tan(omega t) = omega/delta.
inline double max_overlap(const Coefficients<double>& c, double meff, double v0) {
  const double beta = damping_ratio(c, meff);
  const double w0 = std::sqrt(c.k / meff);
  if (beta < 1.0) {
    const double w = w0 * std::sqrt(1.0 - beta * beta), d = beta * w0;
    const double t = std::atan2(w, d) / w;
    return v0 * std::exp(-d * t) * std::sin(w * t) / w;
  }
  throw std::domain_error("max_overlap: only the under-damped case is implemented");
}

// ---------------------------------------------------------------- input
// `normal lsd stiffness KN GAMMAN | restitution E TC`: the first word chooses the form (the
// expanded values: the choice, then its two values). The stiffness form's GAMMAN is per unit
// effective mass unless the host's `damping absolute` says otherwise (gran/hooke/history).
inline constexpr law::Parameter stiffness_values[] = {
    {"KN", "normal stiffness", "N/m", law::Bound::positive},
    {"GAMMAN", "normal damping (per unit effective mass, 1/s; with damping absolute kg/s)", "1/s",
     law::Bound::non_negative},
};
inline constexpr law::Parameter restitution_values[] = {
    {"E", "coefficient of restitution", "1", law::Bound::restitution},
    {"TC", "contact time", "s", law::Bound::positive, -1, false, 0.0, true},
};
inline constexpr law::Choice forms[] = {{"stiffness", stiffness_values, 2}, {"restitution", restitution_values, 2}};
enum Form { form_stiffness = 0, form_restitution = 1 };
inline constexpr law::Group groups[] = {
    {"", "parametrisation", true, true, forms, 2, false, nullptr, nullptr}};
inline constexpr law::Description description = law::describe("normal", "lsd", false, groups, nullptr, 0);

}  // namespace lsd
}  // namespace tdem
