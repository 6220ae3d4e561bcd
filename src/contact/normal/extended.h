// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the extended laws of physics_reference.md section 2.6, whose restitution (and contact
// time) follow a measured impact-velocity dependence e(v0), t_c(v0) (fit forms: velocity_fits.h).
//
// At first touch the impact velocity v0 = xi'(0), clamped to [v_min, v_max], is stored in the
// per-contact history together with the coefficients it gives; the enduring contact then keeps
// them (a packing at rest keeps the coefficients of its v_min: k(v0 -> 0) -> 0 is avoided).
//
//   extended linear      F = k(v0) xi + gamma(v0) xi'
//     k, gamma from e(v0), t_c(v0) exactly (lsd::from_restitution_and_time): ContactEnd
//     zero_overlap closed form, zero_force a 1-D root search (once per contact).
//     History: v0, k, gamma.
//   extended non-linear  F = k~ xi^(3/2) + alpha(v0) sqrt(m* k~) xi^(1/4) xi'
//     the Hertz spring k~ = 4/3 E* sqrt(R*) (gives t_c ~ v0^(-1/5) by itself), Tsuji's damping
//     with alpha(v0) = sqrt(5) beta(e(v0)) (the exact map onto the linear law, hertz_damped.h).
//     History: v0, alpha.
//
// A binary impact at v0 (inside [v_min, v_max]) reproduces e(v0) exactly in both laws and t_c(v0)
// exactly in the linear one. Time step: the stiffest k(v0) occurs at the largest v0 that is
// expected (for the usual decreasing t_c fits); the adapters print it.
#pragma once

#include <cmath>

#include "../kinematics.h"
#include "hertz_damped.h"
#include "../input_checks.h"
#include "../law_parameters.h"
#include "linear_viscoelastic.h"
#include "velocity_fits.h"

namespace tdem {
namespace extended {

// ---------------------------------------------------------------- extended linear
struct LinearParams {
  fits::Fit e_fit;   // e(v0)
  fits::Fit tc_fit;  // t_c(v0)
  fits::Range range;
};

inline void validate(const LinearParams& p) {
  fits::validate_restitution(p.e_fit);
  fits::validate_contact_time(p.tc_fit);
  fits::validate_range(p.range);
}

inline constexpr HistorySlot linear_history[] = {{"v0", false}, {"k", false}, {"gamma", false}};
inline constexpr int linear_history_size = 3;
enum LinearSlot { lin_v0 = 0, lin_k = 1, lin_gamma = 2 };

// The coefficients for effective mass m* and impact velocity v0 (clamped).
inline lsd::Coefficients<double> linear_coefficients(ContactEnd end, const LinearParams& p, double meff,
                                                     double v0) {
  const double v = p.range.clamp(v0);
  return lsd::from_restitution_and_time(fits::restitution(p.e_fit, p.range, v),
                                        fits::contact_time(p.tc_fit, p.range, v), meff, end);
}

// Cold path of the kernel: the first evaluation of a contact.
template <ContactEnd End>
[[gnu::noinline]] inline void linear_first_touch(const LinearParams& p, double meff, double v_in,
                                                 double out[linear_history_size]) noexcept {
  const double v = p.range.clamp(v_in);  // a contact created while separating gets v_min
  lsd::Coefficients<double> c{0.0, 0.0};
  try {
    c = linear_coefficients(End, p, meff, v);
  } catch (...) {  // validated parameters cannot fail here; keep the kernel noexcept
  }
  out[lin_v0] = v;
  out[lin_k] = c.k;
  out[lin_gamma] = c.gamma;
}

// hist: zero for a new contact. update: store the first-touch values (the result is the same).
template <ContactEnd End, class T>
TDEM_KERNEL NormalResult<T> linear_force(const LinearParams& p, const NormalKinematics<T>& kin, T* hist,
                                         bool update) noexcept {
  T h[linear_history_size] = {hist[lin_v0], hist[lin_k], hist[lin_gamma]};
  if (h[lin_v0] == T(0)) {
    double tmp[linear_history_size];
    linear_first_touch<End>(p, double(kin.meff), double(kin.overlap_rate), tmp);
    for (int i = 0; i < linear_history_size; ++i) h[i] = T(tmp[i]);
    if (update)
      for (int i = 0; i < linear_history_size; ++i) hist[i] = h[i];
  }
  return lsd::force<End>(lsd::Coefficients<T>{h[lin_k], h[lin_gamma]}, kin);
}

template <class T>
inline NormalResult<T> linear_force(ContactEnd end, const LinearParams& p, const NormalKinematics<T>& kin,
                                    T* hist, bool update) noexcept {
  return end == ContactEnd::zero_force ? linear_force<ContactEnd::zero_force>(p, kin, hist, update)
                                       : linear_force<ContactEnd::zero_overlap>(p, kin, hist, update);
}

// Closed forms for a binary impact at v0: exactly the fits.
inline double linear_restitution(const LinearParams& p, double v0) {
  return fits::restitution(p.e_fit, p.range, v0);
}
inline double linear_contact_time(const LinearParams& p, double v0) {
  return fits::contact_time(p.tc_fit, p.range, v0);
}

// ---------------------------------------------------------------- extended non-linear
struct HertzParams {
  double k;  // k~ = 4/3 E* sqrt(R*) [N/m^1.5] (per pair; the adapter forms it)
  fits::Fit e_fit;
  fits::Range range;
};

inline void validate(const HertzParams& p) {
  checks::positive("Hertz stiffness k~", p.k);
  fits::validate_restitution(p.e_fit);
  fits::validate_range(p.range);
}

inline constexpr HistorySlot hertz_history[] = {{"v0", false}, {"alpha", false}};
inline constexpr int hertz_history_size = 2;
enum HertzSlot { hz_v0 = 0, hz_alpha = 1 };

inline double hertz_alpha(ContactEnd end, const fits::Fit& e_fit, const fits::Range& range, double v0) {
  return hertz::tsuji_alpha_from_restitution(fits::restitution(e_fit, range, v0), end);
}

template <ContactEnd End>
[[gnu::noinline]] inline void hertz_first_touch(const HertzParams& p, double v_in,
                                                double out[hertz_history_size]) noexcept {
  const double v = p.range.clamp(v_in);
  double alpha = 0.0;
  try {
    alpha = hertz_alpha(End, p.e_fit, p.range, v);
  } catch (...) {
  }
  out[hz_v0] = v;
  out[hz_alpha] = alpha;
}

template <ContactEnd End, class T>
TDEM_KERNEL NormalResult<T> hertz_force(const HertzParams& p, const NormalKinematics<T>& kin, T* hist,
                                        bool update) noexcept {
  T v0 = hist[hz_v0], alpha = hist[hz_alpha];
  if (v0 == T(0)) {
    double tmp[hertz_history_size];
    hertz_first_touch<End>(p, double(kin.overlap_rate), tmp);
    v0 = T(tmp[hz_v0]);
    alpha = T(tmp[hz_alpha]);
    if (update) {
      hist[hz_v0] = v0;
      hist[hz_alpha] = alpha;
    }
  }
  return hertz::force<hertz::Damping::tsuji, End>(hertz::Params<T>{T(p.k), alpha, T(0)}, kin);
}

template <class T>
inline NormalResult<T> hertz_force(ContactEnd end, const HertzParams& p, const NormalKinematics<T>& kin,
                                   T* hist, bool update) noexcept {
  return end == ContactEnd::zero_force ? hertz_force<ContactEnd::zero_force>(p, kin, hist, update)
                                       : hertz_force<ContactEnd::zero_overlap>(p, kin, hist, update);
}

inline double hertz_restitution(const HertzParams& p, double v0) {
  return fits::restitution(p.e_fit, p.range, v0);
}

// ---------------------------------------------------------------- input
//   normal extended_linear e_fit FORM C.. tc_fit FORM C.. [v_min V] [v_max V]
//   normal extended_hertz E NU [E2 NU2] e_fit FORM C.. [v_min V] [v_max V]
// (FORM and its coefficients: velocity_fits.h). In the expanded values each fit is its choice
// index and three coefficients; fit_of() turns them back into a fits::Fit.
inline constexpr law::Parameter c0[] = {{"C0", "fit coefficient", "", law::Bound::any}};
inline constexpr law::Parameter c01[] = {{"C0", "fit coefficient", "", law::Bound::any},
                                         {"C1", "fit coefficient", "", law::Bound::any}};
inline constexpr law::Parameter c012[] = {{"C0", "fit coefficient", "", law::Bound::any},
                                          {"C1", "fit coefficient", "", law::Bound::any},
                                          {"C2", "fit coefficient", "", law::Bound::any}};
inline constexpr law::Choice e_forms[] = {{"constant", c0, 1}, {"rational", c012, 3}, {"power", c01, 2}};
inline constexpr law::Choice tc_forms[] = {{"constant", c0, 1}, {"power", c01, 2}};
inline constexpr law::Parameter v_min_value[] = {
    {"V", "smallest impact velocity", "m/s", law::Bound::any, -1, true, fits::Range().v_min}};
inline constexpr law::Parameter v_max_value[] = {
    {"V", "largest impact velocity", "m/s", law::Bound::any, -1, true, fits::Range().v_max}};
inline constexpr law::Choice v_min_choice[] = {{nullptr, v_min_value, 1}};
inline constexpr law::Choice v_max_choice[] = {{nullptr, v_max_value, 1}};

// The fit of a group's values (choice index, C0, C1, C2) of the form list `forms`.
template <int N>
inline fits::Fit fit_of(const law::Choice (&forms)[N], const double* v) {
  fits::Fit f;
  const int c = static_cast<int>(v[0]);
  fits::parse(forms[c >= 0 && c < N ? c : 0].word, f.form);
  for (int k = 0; k < forms[c >= 0 && c < N ? c : 0].count; ++k) f.c[k] = v[1 + k];
  return f;
}
inline void check_e_fit(int c, const double* v) {
  fits::Fit f;
  fits::parse(e_forms[c].word, f.form);
  for (int k = 0; k < e_forms[c].count; ++k) f.c[k] = v[k];
  fits::validate_restitution(f);
}
inline void check_tc_fit(int c, const double* v) {
  fits::Fit f;
  fits::parse(tc_forms[c].word, f.form);
  for (int k = 0; k < tc_forms[c].count; ++k) f.c[k] = v[k];
  fits::validate_contact_time(f);
}

inline constexpr law::Group e_fit_group = {"e_fit", "form", true, true, e_forms, 3, true, nullptr, check_e_fit};
inline constexpr law::Group tc_fit_group = {"tc_fit", "form", true, true, tc_forms, 2, true, nullptr, check_tc_fit};
inline constexpr law::Group v_min_group = {"v_min", "", false, false, v_min_choice, 1, true, "impact velocity", nullptr};
inline constexpr law::Group v_max_group = {"v_max", "", false, false, v_max_choice, 1, true, "impact velocity", nullptr};
inline constexpr law::Group linear_groups[] = {e_fit_group, tc_fit_group, v_min_group, v_max_group};
inline constexpr law::Group hertz_groups[] = {e_fit_group, v_min_group, v_max_group};
inline constexpr law::Refusal hertz_refusals[] = {{"tc_fit", "its contact time follows from Hertz"}};
inline constexpr law::Description linear_description =
    law::describe("normal", "extended_linear", false, linear_groups, linear_history, linear_history_size);
inline constexpr law::Description hertz_description = law::describe(
    "normal", "extended_hertz", true, hertz_groups, hertz_history, hertz_history_size, hertz_refusals, 1);

// The parameters of extended_linear from its expanded values, and the fits and range of
// extended_hertz from its values after the four materials.
inline LinearParams linear_params(const double* v) {
  LinearParams p;
  p.e_fit = fit_of(e_forms, v);
  p.tc_fit = fit_of(tc_forms, v + 4);
  p.range.v_min = v[7];
  p.range.v_max = v[8];
  return p;
}
inline LinearParams hertz_fits(const double* v) {
  LinearParams p;
  p.e_fit = fit_of(e_forms, v);
  p.tc_fit.form = fits::Form::constant;  // no contact-time fit: a valid placeholder
  p.tc_fit.c[0] = 1.0;
  p.range.v_min = v[4];
  p.range.v_max = v[5];
  return p;
}

}  // namespace extended
}  // namespace tdem
