// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Walton & Braun (1986) hysteretic linear normal law (physics_reference.md section 2.2.4).
//
//   loading                 F = k_l xi                         (xi >= xi_max: new maximum)
//   unloading / reloading   F = k_ul (xi - xi_F0),  xi_F0 = xi_max (1 - k_l / k_ul)
//   F = max(0, min(k_l xi, k_ul (xi - xi_F0)))
//
// The unloading stiffness is k_ul = k_u + s F_max with F_max = k_l xi_max (the largest force so
// far, always on the loading line): s = 0 gives the constant-k_ul law, k_u = k_l and s > 0 the
// force-dependent one (e falls as v0^(-1/2) at high v0). When reloading meets the loading line
// the contact continues on k_l and xi_max grows. No damping and no attraction: the contact
// force ends where it reaches zero (xi = xi_F0), like ContactEnd::zero_force.
//
// Closed forms for a head-on impact at v0 (constant k_ul):
//   xi_max = v0 sqrt(m*/k_l),  e = sqrt(k_l/k_ul),  t_c = pi/2 (sqrt(m*/k_l) + sqrt(m*/k_ul)),
//   residual overlap xi_F0 / xi_max = 1 - e^2,  dissipated energy 1/2 m* v0^2 (1 - e^2).
#pragma once

#include <cmath>
#include <stdexcept>

#include "../kinematics.h"
#include "../input_checks.h"
#include "../law_parameters.h"
#include "../law_unit.h"

namespace tdem {
namespace walton_braun {

template <class T>
struct Params {
  T k_load;    // k_l  [N/m]
  T k_unload;  // k_u  [N/m], >= k_l: unloading stiffness at F_max = 0
  T slope;     // s    [1/m] >= 0: k_ul = k_u + s F_max
};

// Constant unloading stiffness k_ul.
inline Params<double> constant(double k_l, double k_ul) { return {k_l, k_ul, 0.0}; }
// Unloading stiffness that grows with the largest force: k_ul = k_l + s F_max.
inline Params<double> force_dependent(double k_l, double s) { return {k_l, k_l, s}; }

// Per-contact history: the largest overlap so far. A scalar: does not flip with the pair order.
// (F_max = k_l xi_max is not stored: it follows from xi_max.)
inline constexpr HistorySlot history[] = {{"xi_max", false}};
inline constexpr int history_size = 1;
enum Slot { xi_max_slot = 0 };

// The input line `normal walton_braun KL KUL [S]` (src/contact/law_parameters.h).
inline constexpr law::Parameter parameters[] = {
    {"KL", "loading stiffness", "N/m", law::Bound::positive},
    {"KUL", "unloading stiffness", "N/m", law::Bound::at_least, 0},
    {"S", "slope of KUL with F_max", "1/m", law::Bound::non_negative, -1, true, 0.0},
};
inline constexpr law::Description description =
    law::describe("normal", "walton_braun", false, parameters, history, history_size);
inline Params<double> from_values(const double* v) { return {v[0], v[1], v[2]}; }

template <class T>
TDEM_KERNEL T unloading_stiffness(const Params<T>& p, T xi_max) noexcept {
  return p.k_unload + p.slope * p.k_load * xi_max;
}

// ---------------------------------------------------------------- the force kernel
// hist[xi_max_slot] holds xi_max (0 at first touch). update: store a new maximum (false during
// set-up passes that must not change the state). The result does not depend on update.
template <class T>
TDEM_KERNEL NormalResult<T> force(const Params<T>& p, const NormalKinematics<T>& kin, T* hist,
                                  bool update) noexcept {
  const T xi = kin.overlap;
  const T xi_max = hist[xi_max_slot];
  const T loading = p.k_load * xi;
  if (xi >= xi_max) {
    if (update) hist[xi_max_slot] = xi;
    return {loading, loading, p.k_load, T(0)};
  }
  const T k_ul = unloading_stiffness(p, xi_max);
  const T unloading = k_ul * (xi - xi_max) + p.k_load * xi_max;  // = k_ul (xi - xi_F0)
  if (unloading >= loading) return {loading, loading, p.k_load, T(0)};  // not reached for k_ul >= k_l
  if (unloading <= T(0)) return {T(0), T(0), T(0), T(0)};
  return {unloading, unloading, k_ul, T(0)};
}

// Overlap where the unloading branch from xi_max reaches zero force: xi_F0 = xi_max (1 - k_l/k_ul).
template <class T>
inline T zero_force_overlap(const Params<T>& p, T xi_max) noexcept {
  return xi_max * (T(1) - p.k_load / unloading_stiffness(p, xi_max));
}

// ---------------------------------------------------------------- checks and closed forms
inline void validate(const Params<double>& p) {
  checks::positive("loading stiffness k_l", p.k_load);
  checks::positive("unloading stiffness k_u", p.k_unload);
  if (p.k_unload < p.k_load)
    checks::fail("unloading stiffness k_u", p.k_unload, "[k_l, inf) (k_u must not be below the loading stiffness)");
  checks::non_negative("unloading stiffness slope s", p.slope);
}

inline double max_overlap(const Params<double>& p, double meff, double v0) {
  validate(p);
  checks::positive("effective mass m*", meff);
  checks::positive("impact velocity v0", v0);
  return v0 * std::sqrt(meff / p.k_load);
}

// k_ul reached in a head-on impact at v0 (F_max = v0 sqrt(m* k_l)).
inline double unloading_stiffness_at(const Params<double>& p, double meff, double v0) {
  return unloading_stiffness(p, max_overlap(p, meff, v0));
}

inline double restitution(const Params<double>& p, double meff, double v0) {
  return std::sqrt(p.k_load / unloading_stiffness_at(p, meff, v0));
}

inline double contact_time(const Params<double>& p, double meff, double v0) {
  const double k_ul = unloading_stiffness_at(p, meff, v0);
  return 0.5 * M_PI * (std::sqrt(meff / p.k_load) + std::sqrt(meff / k_ul));
}

// xi_f / xi_max = 1 - e^2.
inline double residual_overlap_ratio(const Params<double>& p, double meff, double v0) {
  const double e = restitution(p, meff, v0);
  return 1.0 - e * e;
}

// Constant k_ul from a chosen k_l and restitution e: k_ul = k_l / e^2.
inline Params<double> from_restitution_and_stiffness(double e, double k_l) {
  checks::restitution(e);
  checks::positive("loading stiffness k_l", k_l);
  return constant(k_l, k_l / (e * e));
}

// Constant k_l, k_ul from restitution and contact time: t_c = pi/2 sqrt(m*/k_l) (1 + e).
inline Params<double> from_restitution_and_time(double e, double tc, double meff) {
  checks::restitution(e);
  checks::positive("contact time t_c", tc);
  checks::positive("effective mass m*", meff);
  const double w = 0.5 * M_PI * (1.0 + e) / tc;  // sqrt(k_l/m*)
  return from_restitution_and_stiffness(e, meff * w * w);
}

// Force-dependent law (k_u = k_l) that gives restitution e at impact velocity v0:
// e = [1 + s v0 sqrt(m*/k_l)]^(-1/2)  =>  s = (1/e^2 - 1) / (v0 sqrt(m*/k_l)).
inline Params<double> force_dependent_from_restitution(double e, double v0, double k_l, double meff) {
  checks::restitution(e);
  checks::positive("impact velocity v0", v0);
  checks::positive("loading stiffness k_l", k_l);
  checks::positive("effective mass m*", meff);
  return force_dependent(k_l, (1.0 / (e * e) - 1.0) / (v0 * std::sqrt(meff / k_l)));
}

// ---------------------------------------------------------------- the law as a unit
// (src/contact/law_unit.h; listed in src/contact/laws.h)
struct Law {
  static constexpr const law::Description& description = walton_braun::description;
  using Params = walton_braun::Params<double>;
  static constexpr bool needs_reff = false;
  static constexpr double stress_strain_exponent = 1.0;
  static constexpr ContactEnd end = ContactEnd::zero_force;
  static constexpr const char* properties[] = {"loadingStiffness", "unloadingStiffness", "unloadingStiffnessSlope"};
  static constexpr const char* tangential_basis_text = "kl";
  static Params params(const double* v) {
    const Params p = from_values(v);
    validate(p);
    return p;
  }
  static TDEM_KERNEL NormalResult<double> force(const Params& p, const NormalKinematics<double>& kin, double* hist, bool update) {
    return walton_braun::force(p, kin, hist, update);
  }
  // k_t = KAPPA k_l (the loading stiffness, on every branch)
  static TDEM_KERNEL double tangential_basis(const Params& p, const NormalResult<double>&, const NormalKinematics<double>&) {
    return p.k_load;
  }
  // time-step advice: the unloading stiffness k_ul from xi_max; closed-form contact time
  static const char* family(const Params& p) {
    return p.slope > 0.0 ? "walton_braun (force-dependent k_ul)" : "walton_braun";
  }
  static double max_overlap(const Params& p, double meff, double, double v) {
    return walton_braun::max_overlap(p, meff, v);
  }
  static double stiffness_at(const Params& p, double, double xi_max) { return unloading_stiffness(p, xi_max); }
  static double contact_time(const Params& p, double meff, double, double v) {
    return walton_braun::contact_time(p, meff, v);
  }
  static double contact_time_estimate(const Params& p, double meff, double, double) {
    return M_PI * std::sqrt(meff / p.k_load);
  }
};

}  // namespace walton_braun
}  // namespace tdem
