// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: measured impact-velocity dependence of the coefficient of restitution e(v0) and of the
// contact time t_c(v0), as used by the extended laws (physics_reference.md section 2.6).
//
// The fit forms are pluggable: a Fit is a form plus up to four coefficients, evaluated once per
// contact (at first touch), never inside the force evaluation of an enduring contact.
//
//   restitution forms                          contact-time forms
//   constant   e = c0                          constant  t_c = c0
//   rational   e = chi1 / (v00 + v0^chi2)      power     t_c = chi3 v0^(-chi4)
//              (c0 = chi1, c1 = v00, c2 = chi2)            (c0 = chi3, c1 = chi4)
//   power      e = min(1, (v0 / v_c)^(-p))
//              (c0 = v_c, c1 = p; Bridges et al. 1984 for ice)
//
// The impact velocity is clamped to [v_min, v_max] before a form is evaluated: v0 -> 0 in an
// enduring contact (a packing at rest) would otherwise give t_c -> infinity (k -> 0), and above
// the fitted range the forms are extrapolations. The restitution is clamped to [e_min, 1].
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "../input_checks.h"

namespace tdem {
namespace fits {

enum class Form { constant, rational, power };

inline const char* to_string(Form f) {
  return f == Form::constant ? "constant" : f == Form::rational ? "rational" : "power";
}

// Parses a form name; returns false for an unknown one.
inline bool parse(const std::string& s, Form& f) {
  if (s == "constant") f = Form::constant;
  else if (s == "rational") f = Form::rational;
  else if (s == "power") f = Form::power;
  else return false;
  return true;
}

// Number of coefficients a form takes, for restitution (what = 'e') or contact time ('t').
inline int coefficient_count(Form f, char what) {
  if (f == Form::constant) return 1;
  if (what == 'e') return f == Form::rational ? 3 : 2;
  return 2;
}

struct Fit {
  Form form = Form::constant;
  double c[3] = {0.0, 0.0, 0.0};
};

struct Range {
  double v_min = 1e-3;  // [m/s] impact velocities below are taken as v_min
  double v_max = 1e3;   // [m/s] ... above as v_max
  double e_min = 1e-3;  // smallest restitution a form may give
  double clamp(double v0) const { return std::min(std::max(v0, v_min), v_max); }
};

// ---------------------------------------------------------------- evaluation
inline double restitution(const Fit& f, const Range& r, double v0) {
  const double v = r.clamp(v0);
  double e;
  switch (f.form) {
    case Form::constant: e = f.c[0]; break;
    case Form::rational: e = f.c[0] / (f.c[1] + std::pow(v, f.c[2])); break;
    default: e = std::pow(v / f.c[0], -f.c[1]); break;
  }
  return std::min(1.0, std::max(e, r.e_min));
}

// Contact-time fits must not be 'rational'.
inline double contact_time(const Fit& f, const Range& r, double v0) {
  const double v = r.clamp(v0);
  return f.form == Form::constant ? f.c[0] : f.c[0] * std::pow(v, -f.c[1]);
}

// ---------------------------------------------------------------- input checks
inline void validate_range(const Range& r) {
  checks::positive("smallest impact velocity v_min", r.v_min);
  checks::positive("largest impact velocity v_max", r.v_max);
  if (r.v_max < r.v_min) checks::fail("largest impact velocity v_max", r.v_max, "[v_min, inf)");
  if (!(r.e_min > 0.0 && r.e_min < 1.0)) checks::fail("smallest restitution e_min", r.e_min, "(0, 1)");
}

inline void validate_restitution(const Fit& f) {
  switch (f.form) {
    case Form::constant: checks::restitution(f.c[0]); break;
    case Form::rational:
      checks::positive("restitution fit chi1", f.c[0]);
      checks::non_negative("restitution fit v00", f.c[1]);
      checks::non_negative("restitution fit chi2", f.c[2]);
      break;
    default:
      checks::positive("restitution fit v_c", f.c[0]);
      checks::non_negative("restitution fit exponent p", f.c[1]);
      break;
  }
}

inline void validate_contact_time(const Fit& f) {
  if (f.form == Form::rational)
    throw std::domain_error("contact-time fit: form 'rational' is for the restitution only "
                            "(allowed: constant, power)");
  checks::positive(f.form == Form::constant ? "contact time t_c" : "contact-time fit chi3", f.c[0]);
  if (f.form == Form::power) {
    if (!std::isfinite(f.c[1])) checks::fail("contact-time fit chi4", f.c[1], "(-inf, inf)");
  }
}

}  // namespace fits
}  // namespace tdem
