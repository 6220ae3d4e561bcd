// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the multiple-contact problem of multi-sphere clumps (physics_reference.md 6.3, 6.4).
//
// N identical linear spring-dashpot (LSD) contacts act in parallel when a flat face of a clump
// meets a wall (or a flat face of another clump): the body sees stiffness N k and damping N gamma.
// With per-contact (k, gamma) derived from a single-contact (e, t_c) with the body mass M
// (omega0^2 = k/M, beta = gamma/(2 sqrt(k M))):
//   zero-overlap end:  e_N = exp(-pi sqrt(N) beta / sqrt(1 - N beta^2)),
//                      t_N = pi / (omega0 sqrt(N) sqrt(1 - N beta^2)),
// i.e. omega0 -> sqrt(N) omega0 and beta -> sqrt(N) beta (n_contacts_* give both conventions
// through the LSD closed forms of contact/normal/linear_viscoelastic.h).
//
// Corrections (Correction), applied as a factor s_i on the per-contact k AND gamma of contact i
// between the same two bodies:
//   none             s_i = 1
//   count            s_i = 1/N_c (N_c: contacts in the same body pair at this step). Recovers e
//                    and t_c exactly for flat impacts; the force jumps when N_c changes.
//   overlap_share    s_i = xi_i / sum_j xi_j (overlap-weighted share): the same as count for
//                    equal overlaps, continuous when a contact opens or closes (xi = 0 -> s = 0).
//                    Note sum_i s_i k xi_i = k sum xi_i^2 / sum xi_i: the pair is softer than one
//                    contact carrying the largest overlap only while the overlaps differ.
//   local_mass       damping (and, with (e, t_c) parameters, stiffness) from the locally reduced
//                    mass at the contact point, m_loc = [1/M + (r x n).I^-1 (r x n)]^-1 (one body;
//                    for two bodies the inverse masses add), Berry, Zhang & Haeri (2023).
//                    Provided here as local_reduced_mass(); hosts use it in place of M.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/input_checks.h"
#include "contact/multi_contact/vec3.h"
#include "contact/normal/linear_viscoelastic.h"

namespace tdem {
namespace clumps {

enum class Correction { none, count, overlap_share, local_mass };

inline const char* to_string(Correction c) {
  switch (c) {
    case Correction::none: return "none";
    case Correction::count: return "count";
    case Correction::overlap_share: return "overlap";
    case Correction::local_mass: return "local_mass";
  }
  return "?";
}

inline Correction correction_from_string(const std::string& s) {
  if (s == "none") return Correction::none;
  if (s == "count") return Correction::count;
  if (s == "overlap") return Correction::overlap_share;
  if (s == "local_mass") return Correction::local_mass;
  throw std::invalid_argument("multiple-contact correction '" + s +
                              "' is not known; allowed: none, count, overlap, local_mass");
}

// ------------------------------------------------------------------ closed forms, N parallel contacts
// Zero-overlap convention, from the single-contact damping ratio beta and omega0 (sqrt(k/M)).
inline double n_contacts_restitution_zero_overlap(double beta, int n) {
  const double nb2 = n * beta * beta;
  if (nb2 >= 1.0) return 0.0;
  return std::exp(-M_PI * std::sqrt(double(n)) * beta / std::sqrt(1.0 - nb2));
}
inline double n_contacts_time_zero_overlap(double beta, double omega0, int n) {
  const double nb2 = n * beta * beta;
  if (nb2 >= 1.0) return INFINITY;
  return M_PI / (omega0 * std::sqrt(double(n)) * std::sqrt(1.0 - nb2));
}

struct NContactOutcome {
  double e = 0.0;   // restitution of the body
  double tc = 0.0;  // contact duration
};

// From the single-contact (e1, t1) the per-contact parameters were derived from (with the body
// mass), the outcome of N simultaneous identical contacts, either end convention.
inline NContactOutcome n_contacts_outcome(double e1, double t1, int n, ContactEnd end) {
  if (n < 1) checks::fail("number of contacts N", n, "[1, inf)");
  const auto rates = lsd::rates_from_restitution_and_time(e1, t1, end);
  const lsd::Coefficients<double> c{n * rates.k_per_mass, n * rates.gamma_per_mass};  // unit mass
  return {lsd::restitution(c, 1.0, end), lsd::contact_time(c, 1.0, end)};
}

// ------------------------------------------------------------------ corrections
// Factor on per-contact k and gamma; n_c >= 1 contacts in this body pair, xi this contact's overlap,
// xi_sum the sum over the pair's contacts (both > 0 for a touching contact).
inline double correction_factor(Correction c, int n_c, double xi, double xi_sum) {
  switch (c) {
    case Correction::count: return n_c > 0 ? 1.0 / n_c : 1.0;
    case Correction::overlap_share: return xi_sum > 0.0 ? std::max(0.0, xi) / xi_sum : 1.0;
    case Correction::none:
    case Correction::local_mass: return 1.0;
  }
  return 1.0;
}

// Inverse effective mass of one body at contact offset r (contact point minus com) along the unit
// normal n: 1/M + (r x n) . I^-1 (r x n), I^-1 in the space frame.
inline double inverse_local_mass(double M, const Mat3& inv_inertia_space, const Vec3& r, const Vec3& n) {
  const Vec3 rn = cross(r, n);
  return 1.0 / M + dot(rn, mul(inv_inertia_space, rn));
}

// Locally reduced mass of one body against a wall, m_loc = [1/M + (r x n).I^-1 (r x n)]^-1.
inline double local_reduced_mass(double M, const Mat3& inv_inertia_space, const Vec3& r, const Vec3& n) {
  return 1.0 / inverse_local_mass(M, inv_inertia_space, r, n);
}

// Two bodies: the inverse local masses add.
inline double local_reduced_mass(double M1, const Mat3& Iinv1, const Vec3& r1, double M2, const Mat3& Iinv2,
                                 const Vec3& r2, const Vec3& n) {
  return 1.0 / (inverse_local_mass(M1, Iinv1, r1, n) + inverse_local_mass(M2, Iinv2, r2, n));
}

}  // namespace clumps
}  // namespace tdem
