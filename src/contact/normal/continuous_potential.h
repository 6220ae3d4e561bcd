// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: continuous-potential normal law (Langston, Tuzun & Heyes 1994/1995; physics_reference.md
// section 2.2.1): a steep repulsive potential of the centre distance X,
//
//   phi(X) = eps (d/X)^n,   F = -dphi/dX = n eps d^n / X^(n+1)      (n ~ 36 in the literature)
//
// acting for X <= X_cut (X_cut = +infinity: no cut-off; X_cut = d: cut at geometric touch, the
// force then jumps to n eps/d at touch), plus an optional linear dashpot gamma xi_dot acting in
// the same range. Without the dashpot the law is conservative (e = 1). The distance d at which
// phi = eps is a pair parameter (usually R_i + R_j); the kernel takes the overlap measured from
// it, xi = d - X (negative before touch when X_cut > d), and xi_dot = -dX/dt.
// Pitfalls: the force is non-zero before touch unless cut; the stiffness n(n+1) eps d^n/X^(n+2)
// grows steeply inside d, so the time step must resolve the closest approach; no link to E, nu.
// End of contact: ContactEnd::zero_overlap lets the dashpot make the force attractive while the
// pair is within range; ContactEnd::zero_force clips the force at 0.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>

#include "../kinematics.h"
#include "../input_checks.h"
#include "../law_parameters.h"
#include "linear_viscoelastic.h"

namespace tdem {
namespace continuous_potential {

template <class T>
struct Params {
  T eps;    // characteristic energy eps [J]
  T d;      // length of the potential (phi(d) = eps) [m]
  T n;      // exponent n > 0
  T x_cut;  // the law acts for X <= x_cut [m]; +infinity for no cut-off
  T gamma;  // linear dashpot [kg/s], 0 for the conservative law
};

// ---------------------------------------------------------------- the force kernel
template <ContactEnd End, class T>
TDEM_KERNEL NormalResult<T> force(const Params<T>& p, const NormalKinematics<T>& kin) noexcept {
  const T x = p.d - kin.overlap;  // centre distance
  if (!(x <= p.x_cut)) return {T(0), T(0), T(0), T(0)};
  const T inv_x = T(1) / x;
  const T elastic = p.n * p.eps * std::pow(p.d * inv_x, p.n) * inv_x;
  T f = elastic + p.gamma * kin.overlap_rate;
  if constexpr (End == ContactEnd::zero_force) {
    if (f < T(0)) f = T(0);
  }
  return {f, elastic, (p.n + T(1)) * elastic * inv_x, p.gamma};
}

template <class T>
inline NormalResult<T> force(ContactEnd end, const Params<T>& p, const NormalKinematics<T>& kin) noexcept {
  return end == ContactEnd::zero_force ? force<ContactEnd::zero_force>(p, kin)
                                       : force<ContactEnd::zero_overlap>(p, kin);
}

// ---------------------------------------------------------------- checks and closed forms
inline void validate(const Params<double>& p) {
  checks::positive("characteristic energy eps", p.eps);
  checks::positive("potential length d", p.d);
  checks::positive("potential exponent n", p.n);
  if (!(p.x_cut > 0.0)) checks::fail("cut-off distance X_cut", p.x_cut, "(0, inf]");
  checks::non_negative("damping coefficient gamma", p.gamma);
}

// phi(X) with phi(X_cut) subtracted is the energy stored at distance X.
inline double potential(const Params<double>& p, double x) {
  validate(p);
  checks::positive("centre distance X", x);
  return p.eps * std::pow(p.d / x, p.n);
}

inline double potential_at_cut(const Params<double>& p) {
  return std::isinf(p.x_cut) ? 0.0 : potential(p, p.x_cut);
}

// Closest approach of an undamped head-on collision entering the range at v0:
//   (d/X_min)^n = (d/X_cut)^n + m* v0^2 / (2 eps).
inline double closest_approach(const Params<double>& p, double meff, double v0) {
  validate(p);
  checks::positive("effective mass m*", meff);
  checks::positive("impact velocity v0", v0);
  const double q = (potential_at_cut(p) + 0.5 * meff * v0 * v0) / p.eps;
  return p.d * std::pow(q, -1.0 / p.n);
}

// Inverse: the characteristic energy for which the closest approach at v0 is x_min.
inline double energy_for_closest_approach(double x_min, double meff, double v0, double d, double n,
                                          double x_cut) {
  checks::positive("effective mass m*", meff);
  checks::positive("impact velocity v0", v0);
  checks::positive("potential length d", d);
  checks::positive("potential exponent n", n);
  if (!(x_cut > 0.0)) checks::fail("cut-off distance X_cut", x_cut, "(0, inf]");
  if (!(x_min > 0.0 && x_min < x_cut)) checks::fail("closest approach X_min", x_min, "(0, X_cut)");
  const double at_cut = std::isinf(x_cut) ? 0.0 : std::pow(d / x_cut, n);
  return 0.5 * meff * v0 * v0 / (std::pow(d / x_min, n) - at_cut);
}

// ---------------------------------------------------------------- input
// The hosts' contact law `normal continuous_potential EPS N GAMMA`: d = R_i + R_j (R_i for a wall)
// and X_cut = d per contact (the hosts evaluate touching pairs only: the force acts from geometric
// touch on, as LIGGGHTS's model tdem/continuous_potential); LIGGGHTS reads the three values from
// the per-type-pair properties of `properties`.
inline constexpr law::Parameter parameters[] = {
    {"EPS", "characteristic energy", "J", law::Bound::positive},
    {"N", "potential exponent", "1", law::Bound::positive},
    {"GAMMA", "damping coefficient", "kg/s", law::Bound::non_negative},
};
inline constexpr const char* properties[] = {"potentialEnergy", "potentialExponent", "dampingCoefficient"};
inline constexpr law::Description description =
    law::describe("normal", "continuous_potential", false, parameters, nullptr, 0);

// The parameters of a contact at distance d = R_i + R_j (R_i for a wall) from the values EPS N GAMMA.
template <class T>
TDEM_KERNEL Params<T> at_contact(const double* v, T d) noexcept {
  return Params<T>{T(v[0]), d, T(v[1]), d, T(v[2])};
}

}  // namespace continuous_potential
}  // namespace tdem
