// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Luding's (2008) hysteretic linear normal law without adhesion (k_c = 0): the plastic
// law of LIGGGHTS's `model hooke/hysteresis` with its damping and cohesion off. S. Luding,
// "Cohesive, frictional powders: contact models for tension", Granular Matter 10 (2008) 235.
//
//   loading                 F = k1 xi                                 (xi >= xi_max)
//   unloading / reloading   F = k2 (xi - xi_max) + k1 xi_max,  F = min(F, k1 xi),  F >= 0
//   k2 = k1 + (k2_max - k1) xi_max / xi_lim               (xi_max < xi_lim)
//   xi_lim = k2_max / (k2_max - k1) * phi_f * 2 R*        (the plastic flow limit)
//   xi_max >= xi_lim: F = k2_max (xi - xi_lim) + k1 xi_lim on loading and unloading (elastic
//   beyond the limit, the plastic overlap stays xi_lim (1 - k1/k2_max)).
// Where the unloading line would give F < 0 the force is 0 and xi_max moves so that the line
// passes through the current overlap (Luding's rule with k_c = 0, as LIGGGHTS's model applies
// it): xi_max = (xi + sqrt(xi^2 + 4 k1 xi xi_lim / (k2_max - k1))) / 2. No damping: the contact
// ends at zero force (ContactEnd::zero_force).
//
// This law is the worked example of docs/adding_a_law.md: it was added as a unit (struct Law
// below) by this file, its entry in src/contact/laws.h and its LIGGGHTS model id.
//
// Closed forms for a head-on impact at v0 (effective mass m*), A = v0 sqrt(m*/k1):
//   A < xi_lim:  xi_max = A, k2 = k2(xi_max), e = sqrt(k1/k2),
//                t_c = pi/2 (sqrt(m*/k1) + sqrt(m*/k2))                    (as Walton-Braun)
//   A >= xi_lim: beyond xi_lim on the line of k2_max about xi_0 = xi_lim (1 - k1/k2_max):
//                v1^2 = v0^2 - k1 xi_lim^2 / m*, w = sqrt(k2_max/m*),
//                B = sqrt((xi_lim - xi_0)^2 + v1^2/w^2), xi_max = xi_0 + B,
//                e = w B / v0, t_c = sqrt(m*/k1) asin(xi_lim/A) + (pi - asin((xi_lim - xi_0)/B)) / w
#pragma once

#include <algorithm>
#include <cmath>

#include "../input_checks.h"
#include "../kinematics.h"
#include "../law_parameters.h"
#include "../law_unit.h"

namespace tdem {
namespace luding {

template <class T>
struct Params {
  T k1;      // loading stiffness [N/m]
  T k2_max;  // largest unloading stiffness [N/m], > k1
  T phi_f;   // plasticity depth phi_f [-] > 0 (xi_lim = k2_max/(k2_max-k1) phi_f 2 R*)
};

// Per-contact history: the largest overlap (a scalar).
inline constexpr HistorySlot history[] = {{"xi_max", false}};
inline constexpr int history_size = 1;

// The input line `normal luding K1 K2MAX PHIF`.
inline constexpr law::Parameter parameters[] = {
    {"K1", "loading stiffness", "N/m", law::Bound::positive},
    {"K2MAX", "largest unloading stiffness", "N/m", law::Bound::at_least, 0},
    {"PHIF", "plasticity depth", "1", law::Bound::positive},
};
inline constexpr law::Description description =
    law::describe("normal", "luding", false, parameters, history, history_size);

// The overlap beyond which the contact is elastic with k2_max.
template <class T>
TDEM_KERNEL T limit_overlap(const Params<T>& p, T reff) noexcept {
  return p.k2_max / (p.k2_max - p.k1) * p.phi_f * T(2) * reff;
}

// ---------------------------------------------------------------- the force kernel
// hist[0] = xi_max (0 at first touch); update: store its changes.
template <class T>
TDEM_KERNEL NormalResult<T> force(const Params<T>& p, const NormalKinematics<T>& kin, T* hist,
                                  bool update) noexcept {
  const T xi = kin.overlap;
  const T xm = xi > hist[0] ? xi : hist[0];
  if (update) hist[0] = xm;
  const T xl = limit_overlap(p, kin.reff);
  T k2, f;
  if (xm >= xl) {
    k2 = p.k2_max;
    f = k2 * (xi - xl) + p.k1 * xl;
  } else {
    k2 = p.k1 + (p.k2_max - p.k1) * xm / xl;
    f = k2 * (xi - xm) + p.k1 * xm;
    if (f >= p.k1 * xi) return {p.k1 * xi, p.k1 * xi, p.k1, T(0)};  // on the loading line
  }
  if (f > T(0)) return {f, f, k2, T(0)};
  if (update) hist[0] = T(0.5) * (xi + std::sqrt(xi * xi + T(4) * p.k1 * xi * xl / (p.k2_max - p.k1)));
  return {T(0), T(0), T(0), T(0)};
}

// ---------------------------------------------------------------- checks and closed forms
inline void validate(const Params<double>& p) {
  checks::positive("loading stiffness k1", p.k1);
  if (!(p.k2_max > p.k1))
    checks::fail("largest unloading stiffness k2_max", p.k2_max, "(k1, inf) (k2_max = k1 leaves no plastic range)");
  checks::positive("plasticity depth phi_f", p.phi_f);
}

// Unloading stiffness after a largest overlap xi_max.
inline double unloading_stiffness(const Params<double>& p, double reff, double xi_max) {
  const double xl = limit_overlap(p, reff);
  return xi_max >= xl ? p.k2_max : p.k1 + (p.k2_max - p.k1) * xi_max / xl;
}

namespace detail {
struct Impact {
  double xi_max, e, contact_time;
};
inline Impact impact(const Params<double>& p, double meff, double reff, double v0) {
  validate(p);
  checks::positive("effective mass m*", meff);
  checks::positive("effective radius R*", reff);
  checks::positive("impact velocity v0", v0);
  const double a = v0 * std::sqrt(meff / p.k1), xl = limit_overlap(p, reff);
  if (a < xl) {
    const double k2 = unloading_stiffness(p, reff, a);
    return {a, std::sqrt(p.k1 / k2), 0.5 * M_PI * (std::sqrt(meff / p.k1) + std::sqrt(meff / k2))};
  }
  const double x0 = xl * (1.0 - p.k1 / p.k2_max), w = std::sqrt(p.k2_max / meff);
  const double v1sq = v0 * v0 - p.k1 * xl * xl / meff;
  const double b = std::sqrt((xl - x0) * (xl - x0) + v1sq / (w * w));
  return {x0 + b, w * b / v0, std::sqrt(meff / p.k1) * std::asin(xl / a) + (M_PI - std::asin((xl - x0) / b)) / w};
}
}  // namespace detail

inline double max_overlap(const Params<double>& p, double meff, double reff, double v0) {
  return detail::impact(p, meff, reff, v0).xi_max;
}
inline double restitution(const Params<double>& p, double meff, double reff, double v0) {
  return detail::impact(p, meff, reff, v0).e;
}
inline double contact_time(const Params<double>& p, double meff, double reff, double v0) {
  return detail::impact(p, meff, reff, v0).contact_time;
}

// ---------------------------------------------------------------- the law as a unit
// (src/contact/law_unit.h; listed in src/contact/laws.h)
struct Law {
  static constexpr const law::Description& description = luding::description;
  using Params = luding::Params<double>;
  static constexpr bool needs_reff = true;
  static constexpr double stress_strain_exponent = 1.0;
  static constexpr ContactEnd end = ContactEnd::zero_force;
  static constexpr const char* properties[] = {"loadingStiffness", "unloadingStiffnessMax", "plasticityDepth"};
  static constexpr const char* tangential_basis_text = "k1";
  static Params params(const double* v) {
    const Params p{v[0], v[1], v[2]};
    validate(p);
    return p;
  }
  static TDEM_KERNEL NormalResult<double> force(const Params& p, const NormalKinematics<double>& kin, double* hist, bool update) {
    return luding::force(p, kin, hist, update);
  }
  // k_t = KAPPA k1 (the loading stiffness, on every branch; LIGGGHTS's hooke/hysteresis: k_t = k_n)
  static TDEM_KERNEL double tangential_basis(const Params& p, const NormalResult<double>&, const NormalKinematics<double>&) {
    return p.k1;
  }
  // time-step advice: the unloading stiffness k2 reached at xi_max; closed-form contact time
  static const char* family(const Params&) { return "luding"; }
  static double max_overlap(const Params& p, double meff, double reff, double v) {
    return luding::max_overlap(p, meff, reff, v);
  }
  static double stiffness_at(const Params& p, double reff, double xi_max) {
    return unloading_stiffness(p, reff, xi_max);
  }
  static double contact_time(const Params& p, double meff, double reff, double v) {
    return luding::contact_time(p, meff, reff, v);
  }
  static double contact_time_estimate(const Params& p, double meff, double, double) {
    return M_PI * std::sqrt(meff / p.k1);
  }
  // tdem-fit's starting values: k1 from the median contact time (t_c = pi/2 sqrt(m*/k1) (1 + e)
  // below the limit) or, without one, from the Hertz peak overlap at v_ref; k2 = k1/e^2 reached
  // at the median impact below the limit, with k2_max = 2 k2
  static void fit_guess(const law::FitHint& h, double* own) {
    const double e = std::min(std::max(h.e_ref, 0.05), 0.99), m = h.meff, v = h.v_ref;
    double k1;
    if (std::isfinite(h.tc_ref)) {
      k1 = m * std::pow(M_PI * (1.0 + e) / (2.0 * h.tc_ref), 2);
    } else {
      const double xi = std::pow(15.0 * m * v * v / (16.0 * h.estar * std::sqrt(h.reff)), 0.4);
      k1 = m * v * v / (xi * xi);
    }
    const double k2 = k1 / (e * e), k2_max = 2.0 * k2;
    const double xl = v * std::sqrt(m / k1) * (k2_max - k1) / (k2 - k1);  // A / xl = (k2 - k1)/(k2_max - k1)
    own[0] = k1;
    own[1] = k2_max;
    own[2] = xl * (k2_max - k1) / (k2_max * 2.0 * h.reff);
  }
};

}  // namespace luding
}  // namespace tdem
