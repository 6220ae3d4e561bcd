// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: conversions from a measured restitution to law coefficients where no closed form exists,
// by a root search over the single-collision solution (head_on.h).
//
//   hertz_damping_for_restitution   c of F = k~ xi^1.5 + c xi^Theta xi' (linear, Kuwabara-Kono,
//                                   general) that gives e at impact velocity v0
//
// e(c) falls monotonically from 1 (c = 0); the search brackets c on a log scale and bisects to a
// relative width of 1e-12. Each evaluation is one RK4 collision (steps_per_contact steps).
// Tsuji damping has the closed form hertz::tsuji_alpha_from_restitution; Walton-Braun and Thornton
// have theirs in their headers.
#pragma once

#include <cmath>
#include <stdexcept>

#include "collision/head_on.h"

namespace tdem {
namespace collision {

inline double hertz_restitution(hertz::Damping d, ContactEnd end, const hertz::Params<double>& p,
                                const Bodies& b, double v0, int steps_per_contact = 2000) {
  HertzLaw law;
  law.damping = d;
  law.p = p;
  law.end_mode = end;
  Options o;
  o.steps_per_contact = steps_per_contact;
  o.max_contact_times = 50.0;
  const Result r = integrate(law, b, v0, o);
  return r.ended ? r.restitution : 0.0;  // an over-damped contact that does not end: no rebound
}

// Damping coefficient c [kg/(s m^Theta)] for restitution e in (0, 1) at v0. k~ in p.k; p.theta
// for Damping::general. Throws if e cannot be reached (e.g. below the over-damped limit).
inline double hertz_damping_for_restitution(hertz::Damping d, ContactEnd end, hertz::Params<double> p,
                                            const Bodies& b, double v0, double e,
                                            int steps_per_contact = 2000) {
  if (d == hertz::Damping::tsuji)
    throw std::invalid_argument("hertz_damping_for_restitution: use hertz::tsuji_alpha_from_restitution");
  if (!(e > 0.0 && e < 1.0)) checks::fail("coefficient of restitution e", e, "(0, 1)");
  checks::positive("Hertz stiffness k~", p.k);
  checks::positive("impact velocity v0", v0);
  auto e_of = [&](double c) {
    p.damp = c;
    return hertz_restitution(d, end, p, b, v0, steps_per_contact);
  };
  // Scale: the damping ratio of the linearised contact at the largest elastic overlap.
  const double meff = b.meff();
  const double xi = hertz::max_overlap_elastic(p.k, meff, v0);
  const double theta = d == hertz::Damping::general ? p.theta : hertz::damping_exponent(d);
  const double c_scale = 2.0 * std::sqrt(1.5 * p.k * std::sqrt(xi) * meff) / std::pow(xi, theta);
  double lo = 0.0, hi = c_scale * 1e-3;
  while (e_of(hi) > e) {
    lo = hi;
    hi *= 4.0;
    if (hi > c_scale * 1e6)
      throw std::domain_error("restitution e = " + checks::number(e) + " cannot be reached with this damping form");
  }
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (e_of(mid) > e) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace collision
}  // namespace tdem
