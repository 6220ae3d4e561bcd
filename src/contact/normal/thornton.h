// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Thornton (1997) elastic-perfectly-plastic normal law (physics_reference.md section 2.2.4).
//
// With the limiting contact pressure p_y, k~ = 4/3 E* sqrt(R*) and a^2 = R* xi:
//   yield         xi_y = R* (pi p_y / (2 E*))^2,  F_y = k~ xi_y^(3/2) = 2/3 pi p_y R* xi_y
//   loading       F = k~ xi^(3/2)                       xi <= xi_y   (Hertz)
//                 F = F_y + pi p_y R* (xi - xi_y)       xi >  xi_y   (slope continuous at xi_y)
//   unloading     Hertz with the enlarged radius R_p = 4 E* a_p^3 / (3 F_max), a_p^2 = R* xi_max:
//                 F = 4/3 E* sqrt(R_p) (xi - xi_res)^(3/2) = F_max ((xi - xi_res)/delta_p)^(3/2),
//                 delta_p = xi_max - xi_res = 3 F_max / (4 E* a_p)
//   reloading     along the unloading curve up to xi_max, then on the loading curve.
// Below yield the unloading curve is the loading curve (R_p = R*, xi_res = 0): e = 1.
// No damping and no attraction; the force ends where it reaches zero (xi = xi_res).
//
// Closed form of a head-on impact (Thornton 1997), r = v_y / v0 < 1:
//   e = [6 sqrt(3)/5 (1 - r^2/6)]^(1/2) [r / (r + 2 sqrt(6/5 - r^2/5))]^(1/4),
//   v_y^2 = 4 k~ xi_y^(5/2) / (5 m*)  (v_y = pi^2/sqrt(40) sqrt(p_y^5/(E*^4 rho)) = 1.56... for a
//   sphere of density rho on a wall). This is the exact energy balance of the law above.
#pragma once

#include <cmath>
#include <stdexcept>

#include "../kinematics.h"
#include "../input_checks.h"
#include "../law_parameters.h"
#include "../law_unit.h"
#include "../material.h"
#include "hertz_damped.h"

namespace tdem {
namespace thornton {

template <class T>
struct Params {
  T e_star;  // effective modulus E* [Pa]
  T p_y;     // limiting contact pressure p_y [Pa]
};

// Per-contact history: largest overlap and the force reached there (both scalars).
inline constexpr HistorySlot history[] = {{"xi_max", false}, {"f_max", false}};
inline constexpr int history_size = 2;
enum Slot { xi_max_slot = 0, f_max_slot = 1 };

// The input line `normal thornton E NU [E2 NU2] PY` (src/contact/law_parameters.h); the values
// are E1 NU1 E2 NU2 PY.
inline constexpr law::Parameter parameters[] = {
    {"PY", "limiting contact pressure", "Pa", law::Bound::positive},
};
inline constexpr law::Description description =
    law::describe("normal", "thornton", true, parameters, history, history_size);
inline Params<double> from_values(const double* v) {
  return {material::effective_modulus(v[0], v[1], v[2], v[3]), v[4]};
}

// Loading curve F(xi) with its slope; R* from the contact.
template <class T>
TDEM_KERNEL void loading_curve(const Params<T>& p, T reff, T xi, T& f, T& slope) noexcept {
  const T a_y = reff * T(M_PI) * p.p_y / (T(2) * p.e_star);  // contact radius at yield
  const T xi_y = a_y * a_y / reff;
  if (xi <= xi_y) {
    const T a = std::sqrt(reff * xi);
    f = T(4) / T(3) * p.e_star * a * xi;  // 4/3 E* sqrt(R*) xi^(3/2)
    slope = T(2) * p.e_star * a;
  } else {
    slope = T(M_PI) * p.p_y * reff;
    f = slope * (T(2) / T(3) * xi_y + (xi - xi_y));
  }
}

// ---------------------------------------------------------------- the force kernel
// hist[xi_max_slot], hist[f_max_slot]: zero at first touch. update: store a new maximum (false
// during set-up passes that must not change the state). The result does not depend on update.
template <class T>
TDEM_KERNEL NormalResult<T> force(const Params<T>& p, const NormalKinematics<T>& kin, T* hist,
                                  bool update) noexcept {
  const T xi = kin.overlap;
  const T xi_max = hist[xi_max_slot];
  if (xi >= xi_max) {
    T f, slope;
    loading_curve(p, kin.reff, xi, f, slope);
    if (update) {
      hist[xi_max_slot] = xi;
      hist[f_max_slot] = f;
    }
    return {f, f, slope, T(0)};
  }
  const T f_max = hist[f_max_slot];
  const T delta_p = T(3) * f_max / (T(4) * p.e_star * std::sqrt(kin.reff * xi_max));
  const T u = xi - xi_max + delta_p;  // xi - xi_res
  if (u <= T(0)) return {T(0), T(0), T(0), T(0)};
  const T s = std::sqrt(u / delta_p);
  const T f = f_max * s * s * s;
  return {f, f, T(1.5) * f_max * s / delta_p, T(0)};
}

// Overlap where the unloading curve from (xi_max, F_max) reaches zero force (0 below yield).
template <class T>
inline T zero_force_overlap(const Params<T>& p, T reff, const T* hist) noexcept {
  if (hist[xi_max_slot] <= T(0)) return T(0);
  const T delta_p = T(3) * hist[f_max_slot] / (T(4) * p.e_star * std::sqrt(reff * hist[xi_max_slot]));
  const T res = hist[xi_max_slot] - delta_p;
  return res > T(0) ? res : T(0);
}

// ---------------------------------------------------------------- checks and closed forms
inline void validate(const Params<double>& p) {
  checks::positive("effective modulus E*", p.e_star);
  checks::positive("limiting contact pressure p_y", p.p_y);
}

inline void validate_pair(const Params<double>& p, double reff, double meff) {
  validate(p);
  checks::positive("effective radius R*", reff);
  checks::positive("effective mass m*", meff);
}

inline double yield_overlap(const Params<double>& p, double reff) {
  validate_pair(p, reff, 1.0);
  const double q = M_PI * p.p_y / (2.0 * p.e_star);
  return reff * q * q;
}

inline double yield_force(const Params<double>& p, double reff) {
  return 2.0 / 3.0 * M_PI * p.p_y * reff * yield_overlap(p, reff);
}

// Impact velocity at which the yield point is just reached: 1/2 m* v_y^2 = 2/5 F_y xi_y.
inline double yield_velocity(const Params<double>& p, double reff, double meff) {
  validate_pair(p, reff, meff);
  return std::sqrt(0.8 * yield_force(p, reff) * yield_overlap(p, reff) / meff);
}

// The same for a sphere of density rho on a wall: pi^2/sqrt(40) sqrt(p_y^5 / (E*^4 rho)).
inline double yield_velocity_sphere_on_wall(const Params<double>& p, double rho) {
  validate(p);
  checks::positive("density rho", rho);
  return M_PI * M_PI / std::sqrt(40.0) * std::sqrt(std::pow(p.p_y, 5) / (std::pow(p.e_star, 4) * rho));
}

// Thornton's closed form of e as a function of r = v_y / v0 (e = 1 for r >= 1).
inline double restitution_from_velocity_ratio(double r) {
  checks::non_negative("velocity ratio v_y/v0", r);
  if (r >= 1.0) return 1.0;
  const double r2 = r * r;
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0 * (1.0 - r2 / 6.0)) *
         std::pow(r / (r + 2.0 * std::sqrt(6.0 / 5.0 - r2 / 5.0)), 0.25);
}

inline double restitution(const Params<double>& p, double reff, double meff, double v0) {
  checks::positive("impact velocity v0", v0);
  return restitution_from_velocity_ratio(yield_velocity(p, reff, meff) / v0);
}

// Largest overlap of a head-on impact at v0 (energy balance on the loading curve).
inline double max_overlap(const Params<double>& p, double reff, double meff, double v0) {
  checks::positive("impact velocity v0", v0);
  const double vy = yield_velocity(p, reff, meff);
  const double xi_y = yield_overlap(p, reff);
  if (v0 <= vy) return xi_y * std::pow(v0 / vy, 0.8);
  const double K = M_PI * p.p_y * reff, fy = yield_force(p, reff);
  const double excess = 0.5 * meff * (v0 * v0 - vy * vy);  // energy beyond yield
  return xi_y + 2.0 * excess / (fy + std::sqrt(fy * fy + 2.0 * K * excess));
}

// Inverse of restitution_from_velocity_ratio on (0, 1] (bisection; e(r) increases with r).
inline double velocity_ratio_from_restitution(double e) {
  checks::restitution(e);
  if (e == 1.0) return 1.0;
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (restitution_from_velocity_ratio(mid) < e) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// Limiting pressure that gives yield velocity v_y for the pair:
// v_y^2 = 16/15 E* R*^3 (pi p_y/(2 E*))^5 / m*.
inline double yield_pressure_from_yield_velocity(double vy, double e_star, double reff, double meff) {
  checks::positive("yield velocity v_y", vy);
  checks::positive("effective modulus E*", e_star);
  checks::positive("effective radius R*", reff);
  checks::positive("effective mass m*", meff);
  return 2.0 * e_star / M_PI * std::pow(15.0 * meff * vy * vy / (16.0 * e_star * reff * reff * reff), 0.2);
}

// Limiting pressure that gives restitution e < 1 at impact velocity v0.
inline double yield_pressure_from_restitution(double e, double v0, double e_star, double reff, double meff) {
  checks::restitution(e);
  if (e == 1.0) checks::fail("coefficient of restitution e", e, "(0, 1) (e = 1 means no yield at any p_y >= p_y(v0))");
  checks::positive("impact velocity v0", v0);
  return yield_pressure_from_yield_velocity(velocity_ratio_from_restitution(e) * v0, e_star, reff, meff);
}

// ---------------------------------------------------------------- the law as a unit
// (src/contact/law_unit.h; listed in src/contact/laws.h)
struct Law {
  static constexpr const law::Description& description = thornton::description;
  using Params = thornton::Params<double>;
  static constexpr bool needs_reff = true;
  static constexpr double stress_strain_exponent = 1.5;
  static constexpr ContactEnd end = ContactEnd::zero_force;
  static constexpr const char* properties[] = {"yieldPressure"};
  static constexpr const char* tangential_basis_text = "2 E* a";
  static Params params(const double* v) {  // E* PY (law::unit_values)
    const Params p{v[0], v[1]};
    validate(p);
    return p;
  }
  static TDEM_KERNEL NormalResult<double> force(const Params& p, const NormalKinematics<double>& kin, double* hist, bool update) {
    return thornton::force(p, kin, hist, update);
  }
  // k_t = KAPPA 2 E* a with the contact radius a = sqrt(R* xi) (the Hertz tangent; it follows the
  // contact radius, not the plastic branch of the normal law)
  static TDEM_KERNEL double tangential_basis(const Params& p, const NormalResult<double>&, const NormalKinematics<double>& kin) {
    return 2.0 * p.e_star * std::sqrt(kin.reff * kin.overlap);
  }
  // time-step advice: the unloading tangent at xi_max, 2 E* sqrt(R* xi_max) (>= every loading
  // slope); no closed-form contact time (the advice integrates the impact)
  static const char* family(const Params&) { return "thornton"; }
  static double max_overlap(const Params& p, double meff, double reff, double v) {
    return thornton::max_overlap(p, reff, meff, v);
  }
  static double stiffness_at(const Params& p, double reff, double xi_max) {
    return 2.0 * p.e_star * std::sqrt(reff * xi_max);
  }
  static double contact_time(const Params&, double, double, double) { return NAN; }
  // Hertz's t_c = 2.943 xi_max / v0 with the elastic-plastic largest overlap
  static double contact_time_estimate(const Params& p, double meff, double reff, double v0) {
    return hertz::contact_time_constant() * thornton::max_overlap(p, reff, meff, v0) / v0;
  }
};

}  // namespace thornton
}  // namespace tdem
