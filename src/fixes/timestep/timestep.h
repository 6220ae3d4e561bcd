// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: time-step advice for a contact law, a pair and an integration scheme (issue 8; formulas,
// policy and examples in docs/timestep.md).
//
// For the largest expected normal impact velocity v_max of a pair (m*, R*) the advice gives
//   * the largest tangent stiffness k_max = dF/dxi the law reaches and the damping c = dF/dxi'
//     at that point, omega = sqrt(k_max/m*), zeta = c / (2 sqrt(k_max m*));
//   * the critical step of the scheme, dt_c = w_c(scheme, zeta) / omega, with w_c the largest
//     stable h omega of the scheme on the damped linear oscillator (integrators/stability.h,
//     computed from the scheme's step matrix; velocity Verlet: 2 undamped,
//     2 (sqrt(1 + zeta^2) - zeta) damped). w_c = 0: the scheme is unstable at every step
//     (explicit Euler without damping), dt_c = 0;
//   * the largest overlap and the contact time of a head-on impact at v_max, and the steps per
//     contact t_c/dt the chosen step gives;
//   * the Rayleigh time T_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766) of the smallest particle
//     when its material is given (the usual advice is dt = 0.2 ... 0.4 T_R for Hertz-type laws).
//
// Where k_max sits, per law family (src/contact/normal):
//   linear (LSD)            k, gamma (constant): omega = sqrt(k/m*), zeta = gamma/(2 sqrt(k m*))
//   Hertz + damping         at the undamped largest overlap xi_max = (5 m* v^2/(4 k~))^(2/5) (an
//                           upper bound: damping only lowers it): k_t = 3/2 k~ sqrt(xi_max), c as
//                           the kernel gives it there (Tsuji: zeta = alpha / (2 sqrt(3/2)))
//   Walton-Braun            the unloading stiffness k_ul reached at v_max (k_u + s F_max), no damping
//   Thornton                unloading tangent at xi_max: 2 E* sqrt(R* xi_max) (>= every loading slope)
//   power law               max of the loading tangent p a_l xi_max^(p-1) and the unloading tangent
//                           (p+q) F_max / (xi_max - xi_f) at xi_max (p < 1: the loading tangent
//                           diverges at touch; the advice then uses its value at xi_max)
//   continuous potential    (n+1) n eps d^n / X_min^(n+2) at the closest approach X_min, gamma
//   extended linear         k(v0), gamma(v0) of the fits; the smallest dt_c over v0 in
//                           [v_min, min(v_max, fit range v_max)] (log grid)
//   extended non-linear     as Hertz with Tsuji's alpha(v0); the smallest dt_c over the same v0
// The contact time is the closed form where one exists (LSD, elastic Hertz, Walton-Braun, power
// law, extended linear) and otherwise the head-on collision of collision/head_on.h integrated
// with RK4 and event location at v_max (contact_time_source says which).
//
// The linear stability limit is necessary, not sufficient: a single impact at 0.9 dt_c lasts one
// or two steps and gives any restitution (docs/timestep.md, tests/unit/test_timestep.cpp). Hence
// the default policy of check(): stop above dt_c, warn above 0.5 dt_c or below 20 steps per
// contact, optionally warn above a fraction of T_R.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "collision/head_on.h"
#include "contact/normal/continuous_potential.h"
#include "contact/normal/extended.h"
#include "contact/normal/hertz_damped.h"
#include "contact/input_checks.h"
#include "contact/material.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/normal/power_law_hysteresis.h"
#include "contact/normal/thornton.h"
#include "contact/normal/walton_braun.h"
#include "integrators/schemes.h"
#include "integrators/stability.h"

namespace tdem {
namespace advice {

// ---------------------------------------------------------------- input
// Material of the smallest particle, for the Rayleigh time (radius 0: not given).
struct Material {
  double radius = 0.0;   // R [m]
  double density = 0.0;  // rho [kg/m^3]
  double youngs = 0.0;   // E [Pa]
  double poisson = 0.0;  // nu [-]
  bool given() const { return radius > 0.0; }
};

struct Input {
  double meff = 0.0;   // m* of the pair [kg] (the lightest pair is the critical one)
  double reff = 0.0;   // R* of the pair [m] (needed by Hertz-type laws and Thornton)
  double v_max = 0.0;  // largest expected normal impact velocity [m/s]
  integrators::Scheme scheme = integrators::Scheme::velocity_verlet;
  double dt = 0.0;      // the step in use [s]; 0: not chosen yet (steps_per_contact stays NaN)
  Material material{};  // optional
};

// ---------------------------------------------------------------- result
struct Advice {
  std::string law;          // law family
  std::string scheme;       // scheme name
  double meff = 0.0, reff = 0.0, v_max = 0.0;
  double stiffness = 0.0;      // largest tangent stiffness k_max [N/m]
  double damping = 0.0;        // dF/dxi' at k_max [kg/s]
  double omega = 0.0;          // sqrt(k_max / m*) [1/s]
  double damping_ratio = 0.0;  // zeta
  double wc = 0.0;             // critical h omega of the scheme at zeta (0: never stable)
  double dt_critical = 0.0;    // wc / omega [s]
  double velocity_at_critical = 0.0;  // v0 at which dt_c is smallest (extended laws scan v0)
  double max_overlap = 0.0;    // largest overlap at v_max [m]
  double contact_time = 0.0;   // contact time at v_max [s]
  std::string contact_time_source;  // "closed form" | "integrated (head_on.h, RK4)"
  double rayleigh_time = NAN;  // T_R [s] (NaN: no material given)
  double dt = 0.0;             // the step in use (0: none)
  double steps_per_contact = NAN;     // contact_time / dt
  double fraction_of_critical = NAN;  // dt / dt_critical
  double dt_advised = 0.0;  // largest step the default policy accepts without a warning
};

// ---------------------------------------------------------------- formulas
// Shear modulus from Young's modulus and Poisson's ratio (contact/material.h).
using material::shear_modulus;

// Rayleigh time of a sphere: T_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766).
inline double rayleigh_time(double R, double rho, double G, double nu) {
  checks::positive("radius R", R);
  checks::positive("density rho", rho);
  checks::positive("shear modulus G", G);
  checks::poisson("Poisson ratio nu", nu);
  return M_PI * R * std::sqrt(rho / G) / (0.1631 * nu + 0.8766);
}

inline double rayleigh_time(const Material& m) {
  checks::poisson("Poisson ratio nu", m.poisson);
  return rayleigh_time(m.radius, m.density, shear_modulus(m.youngs, m.poisson), m.poisson);
}

// Critical h omega of a scheme at damping ratio zeta (integrators::critical_step).
inline double critical_h_omega(integrators::Scheme s, double zeta) {
  checks::non_negative("damping ratio zeta", zeta);
  return integrators::critical_step(s, zeta);
}

namespace detail {

inline void validate(const Input& in, bool needs_radius) {
  checks::positive("effective mass m*", in.meff);
  if (needs_radius) checks::positive("effective radius R*", in.reff);
  checks::positive("largest impact velocity v_max", in.v_max);
  if (static_cast<int>(in.scheme) < 0 || static_cast<int>(in.scheme) >= static_cast<int>(integrators::Scheme::count))
    checks::fail("integration scheme (index)", static_cast<int>(in.scheme),
                 ("[0, " + std::to_string(static_cast<int>(integrators::Scheme::count) - 1) + "] (" +
                  integrators::scheme_names(", ") + ")").c_str());
  checks::non_negative("time step dt", in.dt);
  if (in.material.given()) (void)rayleigh_time(in.material);
}

// Stiffness, damping -> omega, zeta, w_c, dt_c.
inline void stability(Advice& a, double k, double c, double meff, integrators::Scheme s) {
  checks::positive("largest contact stiffness k_max", k);
  checks::non_negative("contact damping c", c);
  a.stiffness = k;
  a.damping = c;
  a.omega = std::sqrt(k / meff);
  a.damping_ratio = c / (2.0 * std::sqrt(k * meff));
  a.wc = critical_h_omega(s, a.damping_ratio);
  a.dt_critical = a.wc / a.omega;
}

// Contact time of a head-on collision at v, integrated (RK4 with event location).
template <class Law>
double integrated_contact_time(Law& law, double meff, double reff, double v, double* max_overlap = nullptr) {
  collision::Bodies b;
  b.m1 = meff;
  b.R1 = reff > 0.0 ? reff : 0.0;
  collision::Options o;
  o.steps_per_contact = 2000;
  o.max_contact_times = 200.0;
  const collision::Result r = collision::integrate(law, b, v, o);
  if (!r.ended)
    throw std::domain_error("time-step advice: the head-on collision at v_max = " + checks::number(v) +
                            " m/s did not end within 200 estimated contact times (over-damped law?)");
  if (max_overlap) *max_overlap = r.max_overlap;
  return r.contact_time;
}

// The advice's contact time from the integrated head-on collision at its impact velocity.
template <class Law>
void set_integrated_contact_time(Advice& a, Law& law, const Input& in) {
  a.contact_time = integrated_contact_time(law, in.meff, in.reff, in.v_max);
  a.contact_time_source = "integrated (head_on.h, RK4)";
}

}  // namespace detail

// Fills dt, steps_per_contact, fraction_of_critical, dt_advised (default policy), T_R.
inline void finish(Advice& a, const Input& in);

// The step in use changed: recompute the dt-dependent fields.
inline void set_step(Advice& a, double dt) {
  checks::non_negative("time step dt", dt);
  a.dt = dt;
  a.steps_per_contact = dt > 0.0 ? a.contact_time / dt : NAN;
  a.fraction_of_critical = dt > 0.0 ? (a.dt_critical > 0.0 ? dt / a.dt_critical : INFINITY) : NAN;
}

// ---------------------------------------------------------------- per law family
// Any law, from the largest tangent stiffness and the damping there (the run-time check: the
// adapters see both in NormalResult). contact_time is that of a linear contact with this k, c
// (zero_overlap end): a rough estimate.
inline Advice from_stiffness(double k, double c, const Input& in) {
  checks::positive("effective mass m*", in.meff);
  Advice a;
  a.law = "stiffness";
  detail::stability(a, k, c, in.meff, in.scheme);
  const double zeta = a.damping_ratio;
  a.contact_time = zeta < 1.0 ? M_PI / (a.omega * std::sqrt(1.0 - zeta * zeta)) : INFINITY;
  a.contact_time_source = "linear estimate pi/omega_d";
  a.max_overlap = NAN;
  a.v_max = in.v_max;
  a.velocity_at_critical = in.v_max;
  finish(a, in);
  return a;
}

// Linear spring-dashpot (lsd::Coefficients of the pair).
inline Advice for_linear(const lsd::Coefficients<double>& c, ContactEnd end, const Input& in) {
  detail::validate(in, false);
  Advice a;
  a.law = std::string("linear (") + to_string(end) + ")";
  detail::stability(a, c.k, c.gamma, in.meff, in.scheme);
  a.contact_time = lsd::contact_time(c, in.meff, end);
  a.contact_time_source = "closed form";
  a.max_overlap = a.damping_ratio < 1.0 ? lsd::max_overlap(c, in.meff, in.v_max) : in.v_max / a.omega;
  a.velocity_at_critical = in.v_max;
  finish(a, in);
  return a;
}

// Mass-proportional form (k = m* k_per_mass, gamma = m* gamma_per_mass).
inline Advice for_linear(const lsd::MassRates<double>& r, ContactEnd end, const Input& in) {
  checks::positive("effective mass m*", in.meff);
  return for_linear(r.at(in.meff), end, in);
}

// Hertz + damping (hertz::Params of the pair: k~ = 4/3 E* sqrt(R*)).
inline Advice for_hertz(hertz::Damping d, ContactEnd end, const hertz::Params<double>& p, const Input& in) {
  detail::validate(in, false);
  hertz::validate(d, p);
  Advice a;
  a.law = std::string("hertz/") + hertz::to_string(d) + " (" + to_string(end) + ")";
  const double xi_max = hertz::max_overlap_elastic(p.k, in.meff, in.v_max);
  const NormalResult<double> at =
      hertz::force(d, end, p, NormalKinematics<double>{xi_max, 0.0, in.meff, in.reff > 0.0 ? in.reff : 1.0});
  detail::stability(a, at.stiffness, at.damping, in.meff, in.scheme);
  a.max_overlap = xi_max;
  a.velocity_at_critical = in.v_max;
  if (p.damp == 0.0) {
    a.contact_time = hertz::contact_time_elastic(p.k, in.meff, in.v_max);
    a.contact_time_source = "closed form";
  } else {
    collision::HertzLaw law;
    law.damping = d;
    law.p = p;
    law.end_mode = end;
    detail::set_integrated_contact_time(a, law, in);
  }
  finish(a, in);
  return a;
}

// A normal law that is a unit (src/contact/law_unit.h; walton_braun, thornton, power_law): the
// largest tangent stiffness at the largest overlap of v_max, and the contact time in closed form
// or, where the law has none, integrated.
template <class U>
inline Advice for_law(const typename U::Params& p, const Input& in) {
  detail::validate(in, U::needs_reff);
  const double xi_max = U::max_overlap(p, in.meff, in.reff, in.v_max);  // checks p
  Advice a;
  a.law = U::family(p);
  detail::stability(a, U::stiffness_at(p, in.reff, xi_max), 0.0, in.meff, in.scheme);
  a.max_overlap = xi_max;
  a.contact_time = U::contact_time(p, in.meff, in.reff, in.v_max);
  a.contact_time_source = "closed form";
  if (std::isnan(a.contact_time)) {
    collision::UnitLaw<U> law;
    law.p = p;
    detail::set_integrated_contact_time(a, law, in);
  }
  a.velocity_at_critical = in.v_max;
  finish(a, in);
  return a;
}

inline Advice for_walton_braun(const walton_braun::Params<double>& p, const Input& in) {
  return for_law<walton_braun::Law>(p, in);
}
inline Advice for_thornton(const thornton::Params<double>& p, const Input& in) {
  return for_law<thornton::Law>(p, in);
}
inline Advice for_power_law(const power_law::Params<double>& p, const Input& in) {
  return for_law<power_law::Law>(p, in);
}

// Continuous potential (the collision starts where the potential starts to act).
inline Advice for_continuous_potential(ContactEnd end, const continuous_potential::Params<double>& p,
                                       const Input& in) {
  detail::validate(in, false);
  continuous_potential::validate(p);
  collision::ContinuousPotentialLaw law;
  law.p = p;
  law.end_mode = end;
  Advice a;
  a.law = std::string("continuous_potential (") + to_string(end) + ")";
  const double x_start = p.d - law.start_overlap();
  auto from_start = p;
  from_start.x_cut = x_start;
  const double x_min = continuous_potential::closest_approach(from_start, in.meff, in.v_max);
  const double k = (p.n + 1.0) * p.n * p.eps * std::pow(p.d / x_min, p.n) / (x_min * x_min);
  detail::stability(a, k, p.gamma, in.meff, in.scheme);
  a.max_overlap = p.d - x_min;
  detail::set_integrated_contact_time(a, law, in);
  a.velocity_at_critical = in.v_max;
  finish(a, in);
  return a;
}

namespace detail {
// log grid of impact velocities on [lo, hi], both ends included
template <class F>
void scan_velocities(double lo, double hi, int n, F&& f) {
  if (hi <= lo) {
    f(hi);
    return;
  }
  for (int i = 0; i <= n; ++i) f(lo * std::pow(hi / lo, static_cast<double>(i) / n));
}
}  // namespace detail

// Extended linear law: the smallest dt_c over the impact velocities up to v_max.
inline Advice for_extended_linear(ContactEnd end, const extended::LinearParams& p, const Input& in) {
  detail::validate(in, false);
  extended::validate(p);
  Advice a;
  a.law = std::string("extended linear (") + to_string(end) + ")";
  a.dt_critical = INFINITY;
  const double hi = p.range.clamp(in.v_max), lo = std::min(p.range.v_min, hi);
  detail::scan_velocities(lo, hi, 24, [&](double v) {
    Advice t;
    const lsd::Coefficients<double> c = extended::linear_coefficients(end, p, in.meff, v);
    detail::stability(t, c.k, c.gamma, in.meff, in.scheme);
    if (t.dt_critical < a.dt_critical) {
      detail::stability(a, c.k, c.gamma, in.meff, in.scheme);
      a.velocity_at_critical = v;
    }
  });
  const lsd::Coefficients<double> c = extended::linear_coefficients(end, p, in.meff, in.v_max);
  a.contact_time = extended::linear_contact_time(p, in.v_max);
  a.contact_time_source = "closed form";
  const double zeta = c.gamma / (2.0 * std::sqrt(c.k * in.meff));
  a.max_overlap = zeta < 1.0 ? lsd::max_overlap(c, in.meff, in.v_max) : NAN;
  finish(a, in);
  return a;
}

// Extended non-linear law (Hertz + Tsuji damping alpha(v0)).
inline Advice for_extended_hertz(ContactEnd end, const extended::HertzParams& p, const Input& in) {
  detail::validate(in, false);
  extended::validate(p);
  Advice a;
  a.law = std::string("extended hertz (") + to_string(end) + ")";
  a.dt_critical = INFINITY;
  const double hi = p.range.clamp(in.v_max), lo = std::min(p.range.v_min, hi);
  auto at = [&](double v) {
    const double alpha = extended::hertz_alpha(end, p.e_fit, p.range, v);
    // impacts faster than the fit range keep the coefficients of its v_max but overlap more
    const double xi = hertz::max_overlap_elastic(p.k, in.meff, v >= hi ? in.v_max : v);
    return hertz::force<hertz::Damping::tsuji, ContactEnd::zero_overlap>(
        hertz::Params<double>{p.k, alpha, 0.0}, NormalKinematics<double>{xi, 0.0, in.meff, 1.0});
  };
  detail::scan_velocities(lo, hi, 24, [&](double v) {
    Advice t;
    const NormalResult<double> r = at(v);
    detail::stability(t, r.stiffness, r.damping, in.meff, in.scheme);
    if (t.dt_critical < a.dt_critical) {
      detail::stability(a, r.stiffness, r.damping, in.meff, in.scheme);
      a.velocity_at_critical = v;
    }
  });
  a.max_overlap = hertz::max_overlap_elastic(p.k, in.meff, in.v_max);
  collision::ExtendedHertzLaw law;
  law.p = p;
  law.end_mode = end;
  detail::set_integrated_contact_time(a, law, in);
  finish(a, in);
  return a;
}

// ---------------------------------------------------------------- the check
enum class Verdict { ok, warn, stop };

inline const char* to_string(Verdict v) { return v == Verdict::ok ? "ok" : v == Verdict::warn ? "warn" : "stop"; }

// Safety policy. Defaults: stop above dt_c (the scheme is linearly unstable on the stiffest
// contact: energy grows in enduring contacts); warn above 0.5 dt_c (safety factor 2 for stiffer
// contacts than expected: faster impacts, several contacts on one particle, lighter pairs) or below
// 20 steps per contact (accuracy: the restitution error of a binary impact grows as the steps
// per contact fall; velocity Verlet, e = 0.8: 4.7e-3 at 20, 0.11 at 3.4); rayleigh_fraction > 0 also warns above that fraction of
// T_R (usual 0.2 ... 0.4; off by default: for Hertz-type laws it is much smaller than dt_c).
struct Policy {
  double stop_fraction = 1.0;         // stop if dt > stop_fraction * dt_c
  double warn_fraction = 0.5;         // warn if dt > warn_fraction * dt_c
  double min_steps_per_contact = 20;  // warn if t_c / dt < this
  double rayleigh_fraction = 0.0;     // warn if dt > rayleigh_fraction * T_R (0: off)
};

inline void validate(const Policy& p) {
  if (!(p.stop_fraction > 0.0) || !std::isfinite(p.stop_fraction))
    checks::fail("check stop fraction (of dt_c)", p.stop_fraction, "(0, inf)");
  if (!(p.warn_fraction > 0.0 && p.warn_fraction <= p.stop_fraction))
    checks::fail("check warn fraction (of dt_c)", p.warn_fraction, "(0, stop fraction]");
  if (!(p.min_steps_per_contact >= 0.0) || !std::isfinite(p.min_steps_per_contact))
    checks::fail("check minimum steps per contact", p.min_steps_per_contact, "[0, inf)");
  if (!(p.rayleigh_fraction >= 0.0) || !std::isfinite(p.rayleigh_fraction))
    checks::fail("check Rayleigh fraction", p.rayleigh_fraction, "[0, inf) (0: off)");
}

// Largest step the policy accepts without a warning.
inline double advised_step(const Advice& a, const Policy& p = Policy()) {
  validate(p);
  double dt = p.warn_fraction * a.dt_critical;
  if (p.min_steps_per_contact > 0.0 && std::isfinite(a.contact_time))
    dt = std::min(dt, a.contact_time / p.min_steps_per_contact);
  if (p.rayleigh_fraction > 0.0 && std::isfinite(a.rayleigh_time)) dt = std::min(dt, p.rayleigh_fraction * a.rayleigh_time);
  return dt;
}

inline void finish(Advice& a, const Input& in) {
  a.meff = in.meff;
  a.reff = in.reff;
  a.v_max = in.v_max;
  a.scheme = integrators::info(in.scheme).name;
  if (in.material.given()) a.rayleigh_time = rayleigh_time(in.material);
  a.dt_advised = advised_step(a);
  set_step(a, in.dt);
}

struct Check {
  Verdict verdict = Verdict::ok;
  std::string message;
};

// One line describing the advice (for the hosts' run-start print).
inline std::string summary(const Advice& a) {
  using checks::number;
  std::string s = a.law + ", " + a.scheme + ": k_max = " + number(a.stiffness) + " N/m, m* = " + number(a.meff) +
                  " kg, omega = " + number(a.omega) + " 1/s, zeta = " + number(a.damping_ratio) +
                  ", critical h*omega = " + number(a.wc) + " -> dt_c = " + number(a.dt_critical) +
                  " s; contact time at v_max = " + number(a.v_max) + " m/s: " + number(a.contact_time) + " s (" +
                  a.contact_time_source + ")";
  if (std::isfinite(a.rayleigh_time))
    s += "; Rayleigh time T_R = " + number(a.rayleigh_time) + " s (0.2-0.4 T_R = " + number(0.2 * a.rayleigh_time) +
         " - " + number(0.4 * a.rayleigh_time) + " s)";
  s += "; advised dt <= " + number(a.dt_advised) + " s";
  return s;
}

// Is the step dt safe for the law, pair and scheme of the advice?
inline Check check(const Advice& a, double dt, const Policy& p = Policy()) {
  using checks::number;
  validate(p);
  checks::positive("time step dt", dt);
  Check c;
  const std::string head = "time step dt = " + number(dt) + " s";
  const std::string law = " (" + a.law + ", " + a.scheme + ", k_max = " + number(a.stiffness) +
                          " N/m, m* = " + number(a.meff) + " kg, zeta = " + number(a.damping_ratio) +
                          ", v_max = " + number(a.v_max) + " m/s)";
  const double steps = a.contact_time / dt;
  if (!(a.dt_critical > 0.0)) {
    c.verdict = Verdict::stop;
    c.message = head + ": the scheme " + a.scheme + " is unstable at every step for this contact" + law +
                "; choose another scheme";
    return c;
  }
  const double frac = dt / a.dt_critical;
  if (dt > p.stop_fraction * a.dt_critical) {
    c.verdict = Verdict::stop;
    c.message = head + " is " + number(frac) + " x the critical step dt_c = " + number(a.dt_critical) +
                " s (h*omega < " + number(a.wc) + ")" + law + ": the integration is unstable; use dt <= " +
                number(advised_step(a, p)) + " s";
    return c;
  }
  std::string why;
  if (dt > p.warn_fraction * a.dt_critical)
    why += " is " + number(frac) + " x the critical step dt_c = " + number(a.dt_critical) + " s (warn above " +
           number(p.warn_fraction) + " x)";
  if (p.min_steps_per_contact > 0.0 && steps < p.min_steps_per_contact)
    why += std::string(why.empty() ? "" : ";") + " gives " + number(steps) + " steps per contact (contact time " +
           number(a.contact_time) + " s at v_max; warn below " + number(p.min_steps_per_contact) + ")";
  if (p.rayleigh_fraction > 0.0 && std::isfinite(a.rayleigh_time) && dt > p.rayleigh_fraction * a.rayleigh_time)
    why += std::string(why.empty() ? "" : ";") + " is " + number(dt / a.rayleigh_time) +
           " x the Rayleigh time T_R = " + number(a.rayleigh_time) + " s (warn above " + number(p.rayleigh_fraction) +
           " x)";
  if (!why.empty()) {
    c.verdict = Verdict::warn;
    c.message = head + why + law + "; advised dt <= " + number(advised_step(a, p)) + " s";
    return c;
  }
  c.verdict = Verdict::ok;
  c.message = head + " is " + number(frac) + " x dt_c = " + number(a.dt_critical) + " s and gives " + number(steps) +
              " steps per contact" + law;
  return c;
}

}  // namespace advice
}  // namespace tdem
