// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: non-linear viscoelastic normal laws: Hertz spring plus a damper that scales with a
// power of the overlap (physics_reference.md section 2.2.3).
//
//   F = k~ xi^(3/2) + c xi^Theta xi_dot,     k~ = 4/3 E* sqrt(R*)
//
//   Damping::linear         Theta = 0,   c = gamma [kg/s]  (Hertz with linear damping, Lee & Herrmann)
//                           e rises with v0 (1 - e ~ v0^(-1/5)); F(0+) = gamma v0.
//   Damping::kuwabara_kono  Theta = 1/2, c = gamma~ [kg/(s m^1/2)] (Kuwabara & Kono 1987,
//                           Brilliantov et al. 1996: gamma~ = 3/2 A k~); 1 - e ~ v0^(1/5).
//   Damping::tsuji          Theta = 1/4, c = alpha sqrt(m* k~) with dimensionless alpha
//                           (Tsuji et al. 1992); e depends on alpha only. Exact map onto the
//                           linear law: damping ratio beta = alpha / sqrt(5).
//   Damping::general        any Theta >= 0, c [kg/(s m^Theta)]; 1 - e ~ v0^((4 Theta - 1)/5).
//
// End of contact as in linear_viscoelastic.h: ContactEnd::zero_overlap lets the force become
// attractive near the end (contact ends at xi = 0); ContactEnd::zero_force clips it at 0.
// Precondition of the kernel: xi >= 0 (hosts call it only for overlapping pairs).
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "../kinematics.h"
#include "../input_checks.h"
#include "../law_parameters.h"
#include "../material.h"
#include "linear_viscoelastic.h"

namespace tdem {
namespace hertz {

enum class Damping { linear, kuwabara_kono, tsuji, general };

inline const char* to_string(Damping d) {
  switch (d) {
    case Damping::linear: return "linear";
    case Damping::kuwabara_kono: return "kuwabara_kono";
    case Damping::tsuji: return "tsuji";
    default: return "general";
  }
}

// Exponent Theta of the damping term for the fixed members of the family.
inline constexpr double damping_exponent(Damping d) {
  return d == Damping::linear ? 0.0 : d == Damping::kuwabara_kono ? 0.5 : d == Damping::tsuji ? 0.25 : -1.0;
}

// The exponents in xi of the force's two parts as the time-grid correction models them
// (grid_correction.h: power_impulse): the elastic part 3/2, the damping part Theta (along a straight
// approach, where xi' is constant). Hosts take them in place of probing the law at xi/2. Only for
// ContactEnd::zero_overlap: a force clipped at zero does not scale as its parts (false: probe).
template <class T>
inline constexpr bool power_exponents(Damping d, T theta, ContactEnd end, T& p, T& q) {
  if (end != ContactEnd::zero_overlap) return false;
  p = T(1.5);
  q = d == Damping::general ? theta : T(damping_exponent(d));
  return true;
}

// Per-pair parameters. The adapter computes k~ for the pair (stiffness(E*, R*)).
template <class T>
struct Params {
  T k;      // k~ [N/m^(3/2)]
  T damp;   // Damping::tsuji: alpha [-], c = alpha sqrt(m* k~); otherwise c [kg/(s m^Theta)]
  T theta;  // Damping::general only: the exponent Theta (ignored by the other members)
};

// ---------------------------------------------------------------- the force kernel
template <Damping D, ContactEnd End, class T>
TDEM_KERNEL NormalResult<T> force(const Params<T>& p, const NormalKinematics<T>& kin) noexcept {
  const T xi = kin.overlap;
  const T sqrt_xi = std::sqrt(xi);
  const T elastic = p.k * xi * sqrt_xi;
  T c;
  if constexpr (D == Damping::linear) {
    c = p.damp;
  } else if constexpr (D == Damping::kuwabara_kono) {
    c = p.damp * sqrt_xi;
  } else if constexpr (D == Damping::tsuji) {
    c = p.damp * std::sqrt(kin.meff * p.k * sqrt_xi);
  } else {
    c = p.damp * std::pow(xi, p.theta);
  }
  T f = elastic + c * kin.overlap_rate;
  if constexpr (End == ContactEnd::zero_force) {
    if (f < T(0)) f = T(0);
  }
  return {f, elastic, T(1.5) * p.k * sqrt_xi, c};
}

template <class T>
inline NormalResult<T> force(Damping d, ContactEnd end, const Params<T>& p,
                             const NormalKinematics<T>& kin) noexcept {
  const bool zf = end == ContactEnd::zero_force;
  switch (d) {
    case Damping::linear:
      return zf ? force<Damping::linear, ContactEnd::zero_force>(p, kin)
                : force<Damping::linear, ContactEnd::zero_overlap>(p, kin);
    case Damping::kuwabara_kono:
      return zf ? force<Damping::kuwabara_kono, ContactEnd::zero_force>(p, kin)
                : force<Damping::kuwabara_kono, ContactEnd::zero_overlap>(p, kin);
    case Damping::tsuji:
      return zf ? force<Damping::tsuji, ContactEnd::zero_force>(p, kin)
                : force<Damping::tsuji, ContactEnd::zero_overlap>(p, kin);
    default:
      return zf ? force<Damping::general, ContactEnd::zero_force>(p, kin)
                : force<Damping::general, ContactEnd::zero_overlap>(p, kin);
  }
}

// ---------------------------------------------------------------- input checks
// Checks a parameter set for the member d of the family.
inline void validate(Damping d, const Params<double>& p) {
  checks::positive("Hertz stiffness k~", p.k);
  checks::non_negative(d == Damping::tsuji ? "Tsuji damping alpha" : "damping coefficient", p.damp);
  if (d == Damping::general) checks::non_negative("damping exponent Theta", p.theta);
}

// ---------------------------------------------------------------- pair quantities
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (a rigid partner: E = +infinity): ../material.h
using material::effective_modulus;

// 1/R* = 1/R1 + 1/R2; a plane wall has R2 = +infinity.
inline double effective_radius(double R1, double R2) {
  checks::positive("radius R1", R1);
  if (R2 == INFINITY) return R1;
  checks::positive("radius R2", R2);
  return R1 * R2 / (R1 + R2);
}

// 1/m* = 1/m1 + 1/m2; a wall or frozen partner has m2 = +infinity.
inline double effective_mass(double m1, double m2) {
  checks::positive("mass m1", m1);
  if (m2 == INFINITY) return m1;
  checks::positive("mass m2", m2);
  return m1 * m2 / (m1 + m2);
}

// k~ = 4/3 E* sqrt(R*)  and back.
template <class T>
inline T stiffness(T e_star, T r_eff) noexcept {
  return T(4) / T(3) * e_star * std::sqrt(r_eff);
}

inline double effective_modulus_from_stiffness(double k, double r_eff) {
  checks::positive("Hertz stiffness k~", k);
  checks::positive("effective radius R*", r_eff);
  return 0.75 * k / std::sqrt(r_eff);
}

// Brilliantov et al.: gamma~ = 3/2 A k~ with the material dissipative time A [s], and back.
inline double kuwabara_kono_damping(double dissipative_time, double k) {
  checks::non_negative("dissipative time A", dissipative_time);
  checks::positive("Hertz stiffness k~", k);
  return 1.5 * dissipative_time * k;
}

inline double dissipative_time(double gamma_kk, double k) {
  checks::non_negative("damping coefficient", gamma_kk);
  checks::positive("Hertz stiffness k~", k);
  return gamma_kk / (1.5 * k);
}

// ---------------------------------------------------------------- elastic closed forms
// The constant of t_c = C xi_max / v0: C = 2 int_0^1 (1 - x^(5/2))^(-1/2) dx
//   = 4/5 sqrt(pi) Gamma(2/5) / Gamma(9/10) = 2.94328...
inline double contact_time_constant() {
  return 0.8 * std::sqrt(M_PI) * std::tgamma(0.4) / std::tgamma(0.9);
}

// Largest overlap of an undamped Hertz impact: xi_max = (5 m* v0^2 / (4 k~))^(2/5).
inline double max_overlap_elastic(double k, double meff, double v0) {
  checks::positive("Hertz stiffness k~", k);
  checks::positive("effective mass m*", meff);
  checks::positive("impact velocity v0", v0);
  return std::pow(5.0 * meff * v0 * v0 / (4.0 * k), 0.4);
}

// Contact time of an undamped Hertz impact: t_c = C xi_max / v0.
inline double contact_time_elastic(double k, double meff, double v0) {
  return contact_time_constant() * max_overlap_elastic(k, meff, v0) / v0;
}

// Inverse of contact_time_elastic: the k~ that gives contact time tc at v0.
inline double stiffness_from_contact_time(double tc, double meff, double v0) {
  checks::positive("contact time t_c", tc);
  checks::positive("effective mass m*", meff);
  checks::positive("impact velocity v0", v0);
  const double xi_max = tc * v0 / contact_time_constant();
  return 5.0 * meff * v0 * v0 / (4.0 * std::pow(xi_max, 2.5));
}

// ---------------------------------------------------------------- Tsuji damping
// Exact map onto the linear law: damping ratio beta = alpha / sqrt(5) (physics_reference 2.2.3).
inline double tsuji_alpha_from_restitution(double e, ContactEnd end) {
  return std::sqrt(5.0) * lsd::damping_ratio_from_restitution(e, end);
}

inline double tsuji_restitution(double alpha, ContactEnd end) {
  checks::non_negative("Tsuji damping alpha", alpha);
  return lsd::restitution_from_damping_ratio(alpha / std::sqrt(5.0), end);
}

// Closed form of the zero_overlap case: alpha = -sqrt(5) ln e / sqrt(ln^2 e + pi^2).
template <class T>
inline T tsuji_alpha_zero_overlap(T log_e) noexcept {
  return -std::sqrt(T(5)) * log_e / std::sqrt(log_e * log_e + T(M_PI) * T(M_PI));
}

// ---------------------------------------------------------------- input
// `normal hertz E NU [E2 NU2] [damping linear GAMMA | kuwabara_kono GAMMA | tsuji E | general
// THETA C]` (default: linear 0, the elastic law). The choice index is the Damping member.
inline constexpr law::Parameter damping_gamma[] = {{"GAMMA", "damping coefficient", "", law::Bound::non_negative}};
inline constexpr law::Parameter damping_tsuji[] = {{"E", "coefficient of restitution", "1", law::Bound::restitution}};
inline constexpr law::Parameter damping_general[] = {
    {"THETA", "exponent of the overlap", "1", law::Bound::non_negative},
    {"C", "damping coefficient", "", law::Bound::non_negative},
};
inline constexpr law::Choice damping_members[] = {
    {"linear", damping_gamma, 1}, {"kuwabara_kono", damping_gamma, 1}, {"tsuji", damping_tsuji, 1},
    {"general", damping_general, 2}};
static_assert(static_cast<int>(Damping::general) == 3, "the choices follow Damping");
inline constexpr law::Group groups[] = {
    {"damping", "member", false, false, damping_members, 4, true, nullptr, nullptr}};
inline constexpr law::Description description = law::describe("normal", "hertz", true, groups, nullptr, 0);

}  // namespace hertz
}  // namespace tdem
