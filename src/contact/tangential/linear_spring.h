// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: linear tangential spring (Cundall & Strack 1979) and spring-dashpot, both with a Coulomb
// limit, on the common tangential interface (physics_reference.md section 3.3, laws 2 and 3).
//
//   s   <- carry_into_plane(s) + v_t dt             (spring elongation xi', history)
//   F_t  = -(k_t s + gamma_t v_t)                    while sticking
//   |F_t| <= F_lim = coulomb_limit(limit, mu, F_n)   (mu max(F_n,0) or mu |F_n|, see common.h)
//
// k_t = kt + kappa k_n: a constant stiffness, or kappa times the normal tangent stiffness that
// the normal law reports this step (kappa = k_t/k_n, physics_reference.md 3.4), or a sum of both.
// Cundall-Strack is gamma_t = 0 (then the two reset rules below coincide).
//
// Reset of the spring on sliding (the issue asks to document it). Two rules, chosen per pair:
//   SlipReset::spring_only (default)  The spring alone is tested: if k_t |s| > F_lim the spring
//       is truncated to k_t |s| = F_lim along s and the force is the spring force -k_t s (the
//       dashpot is off while sliding; LIGGGHTS `tangential history`). If the spring holds but
//       spring plus dashpot exceed F_lim, the force is capped to F_lim and the spring is kept
//       (LIGGGHTS would not cap here; we do, so |F_t| <= F_lim always holds).
//       After sliding the spring stores exactly the force it transmits: a reversal of v_t starts
//       from F_lim and unloads elastically with k_t (the classical elastic-perfectly-plastic
//       Coulomb loop: closed loop of area 4 F_lim (A - F_lim/k_t) for a displacement cycle +-A).
//   SlipReset::spring_and_dashpot     The whole force is capped: F_t = F_lim F_trial/|F_trial| and
//       the spring is set so that spring plus dashpot give the capped force,
//       s = -(F_t + gamma_t v_t)/k_t (LAMMPS `gran/hooke/history`). With a strong dashpot the
//       reset spring can end up smaller than F_lim/k_t or even point against the slip.
// Both rules act on the local copy also when update == false, so the force is the same.
#pragma once

#include "../input_checks.h"
#include "../law_parameters.h"
#include "common.h"

namespace tdem {
namespace tangential {

enum class SlipReset { spring_only, spring_and_dashpot };

inline const char* to_string(SlipReset r) {
  return r == SlipReset::spring_only ? "spring_only" : "spring_and_dashpot";
}

// One step of a spring(-dashpot) with a Coulomb limit: shared by linear_spring, mindlin_no_slip
// (Tsuji) and di_renzo. s: the spring elongation (3 values, already carried into the plane and
// advanced); changed in place by the reset. kt may vary from step to step (total formulation:
// F = -k_t(xi) s). Returns true while sliding.
template <class T>
TDEM_KERNEL bool spring_dashpot_cap(T kt, T gammat, T flim, SlipReset reset, const T* vt, T* s, T* ft) noexcept {
  if (reset == SlipReset::spring_only) {
    const T s2 = dot(s, s);
    if (kt * kt * s2 > flim * flim) {
      const T r = flim / (kt * std::sqrt(s2));  // s2 > 0 here
      s[0] *= r, s[1] *= r, s[2] *= r;
      ft[0] = -kt * s[0], ft[1] = -kt * s[1], ft[2] = -kt * s[2];
      return true;
    }
    ft[0] = -(kt * s[0] + gammat * vt[0]);
    ft[1] = -(kt * s[1] + gammat * vt[1]);
    ft[2] = -(kt * s[2] + gammat * vt[2]);
    return cap(ft, flim);
  }
  ft[0] = -(kt * s[0] + gammat * vt[0]);
  ft[1] = -(kt * s[1] + gammat * vt[1]);
  ft[2] = -(kt * s[2] + gammat * vt[2]);
  if (!cap(ft, flim)) return false;
  if (kt > T(0)) {
    const T ik = T(1) / kt;
    s[0] = -(ft[0] + gammat * vt[0]) * ik;
    s[1] = -(ft[1] + gammat * vt[1]) * ik;
    s[2] = -(ft[2] + gammat * vt[2]) * ik;
  }
  return true;
}

// The history of a law with a spring elongation: its 3 components (flip with the pair order).
// carry + advance + cap + write back (if update) for a given stiffness and damping.
template <class T>
TDEM_KERNEL bool spring_law_step(T kt, T gammat, T flim, SlipReset reset, const TangentialKinematics<T>& k,
                                 T* hist, bool update, T* ft) noexcept {
  T s[3] = {hist[0], hist[1], hist[2]};
  carry_and_advance(k, s);
  const bool sliding = spring_dashpot_cap(kt, gammat, flim, reset, k.vt, s, ft);
  if (update) copy3(s, hist);
  return sliding;
}

}  // namespace tangential

namespace linear_spring {

template <class T>
struct Params {
  T kt;      // constant part of the tangential stiffness [N/m]
  T kappa;   // k_t/k_n: part proportional to the normal tangent stiffness [-]
  T gammat;  // tangential damping coefficient [kg/s] (0: Cundall-Strack)
  T mu;      // Coulomb friction coefficient
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  tangential::SlipReset reset = tangential::SlipReset::spring_only;
};

// Cundall-Strack: spring and Coulomb slider.
inline Params<double> cundall_strack(double kt, double mu,
                                     tangential::FrictionLimit limit = tangential::FrictionLimit::absolute) {
  return {kt, 0.0, 0.0, mu, limit, tangential::SlipReset::spring_only};
}
// Spring-dashpot with Coulomb limit.
inline Params<double> spring_dashpot(double kt, double gammat, double mu,
                                     tangential::SlipReset reset = tangential::SlipReset::spring_only,
                                     tangential::FrictionLimit limit = tangential::FrictionLimit::absolute) {
  return {kt, 0.0, gammat, mu, limit, reset};
}

inline constexpr HistorySlot history[] = {{"spring_x", true}, {"spring_y", true}, {"spring_z", true}};
inline constexpr int history_size = 3;

// The input line `tangential linear_spring ...` (src/contact/law_parameters.h).
inline constexpr law::Parameter parameters[] = {
    {"KT", "constant stiffness, force/length", "N/m", law::Bound::non_negative},
    {"KAPPA", "k_t/k_n", "1", law::Bound::non_negative},
    {"GAMMAT", "damping coefficient, mass/time", "kg/s", law::Bound::non_negative},
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description description =
    law::describe("tangential", "linear_spring", false, parameters, history, history_size);

template <class T>
TDEM_KERNEL T stiffness(const Params<T>& p, const tangential::TangentialKinematics<T>& k) noexcept {
  return p.kt + p.kappa * k.kn;
}

template <class T>
TDEM_KERNEL bool force(const Params<T>& p, const tangential::TangentialKinematics<T>& k, T* hist, bool update,
                       T* ft) noexcept {
  return tangential::spring_law_step(stiffness(p, k), p.gammat, tangential::coulomb_limit(p.limit, p.mu, k.fn),
                                     p.reset, k, hist, update, ft);
}

inline void validate(const Params<double>& p) {
  checks::non_negative("tangential stiffness k_t", p.kt);
  checks::non_negative("stiffness ratio kappa = k_t/k_n", p.kappa);
  if (!(p.kt > 0.0 || p.kappa > 0.0))
    checks::fail("tangential stiffness k_t + kappa k_n with k_t", p.kt, "(0, inf) (or give kappa > 0)");
  checks::non_negative("tangential damping coefficient gamma_t", p.gammat);
  checks::non_negative("friction coefficient mu", p.mu);
}

}  // namespace linear_spring
}  // namespace tdem
