// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Tsuji, Tanaka & Ishida (Powder Technol. 71 (1992) 239) no-slip Mindlin spring with
// damping and a Coulomb limit (physics_reference.md section 3.3, law 6).
//
//   F_t = -(k_t(xi) s + eta_t v_t),  k_t = 8 G* a,  a = sqrt(R* xi),  |F_t| <= F_lim
//
// Total (integral) formulation: the spring elongation s is the history (carried into the plane
// and advanced by v_t dt each step, common.h) and the current stiffness multiplies all of it.
// eta_t = damping_ratio * gamma_n with gamma_n the normal damping coefficient the normal law
// used this step: Tsuji et al. take eta_t = eta_n (damping_ratio = 1). The reset of the spring
// on sliding follows the SlipReset rule of linear_spring.h (default spring_only).
// G* from effective_shear_modulus() in parameters.h.
#pragma once

#include "../input_checks.h"
#include "../law_parameters.h"
#include "common.h"
#include "linear_spring.h"

namespace tdem {
namespace mindlin_no_slip {

template <class T>
struct Params {
  T gstar;          // effective shear modulus G* [Pa]
  T damping_ratio;  // eta_t / gamma_n [-] (Tsuji: 1)
  T mu;             // Coulomb friction coefficient
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  tangential::SlipReset reset = tangential::SlipReset::spring_only;
};

inline constexpr HistorySlot history[] = {{"spring_x", true}, {"spring_y", true}, {"spring_z", true}};
inline constexpr int history_size = 3;

// The input line `tangential mindlin_no_slip E NU [E2 NU2] ...` (src/contact/law_parameters.h); the values
// are E1 NU1 E2 NU2, then the law's own.
inline constexpr law::Parameter parameters[] = {
    {"RATIO", "eta_t/gamma_n", "1", law::Bound::non_negative},
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description description =
    law::describe("tangential", "mindlin_no_slip", true, parameters, history, history_size, true);

// The no-slip stiffness 8 G* sqrt(R* xi) (0 without overlap).
template <class T>
TDEM_KERNEL T stiffness(T gstar, const tangential::TangentialKinematics<T>& k) noexcept {
  return k.overlap > T(0) ? T(8) * gstar * std::sqrt(k.reff * k.overlap) : T(0);
}

template <class T>
TDEM_KERNEL bool force(const Params<T>& p, const tangential::TangentialKinematics<T>& k, T* hist, bool update,
                       T* ft) noexcept {
  return tangential::spring_law_step(stiffness(p.gstar, k), p.damping_ratio * k.gamman,
                                     tangential::coulomb_limit(p.limit, p.mu, k.fn), p.reset, k, hist, update, ft);
}

inline void validate(const Params<double>& p) {
  checks::positive("effective shear modulus G*", p.gstar);
  checks::non_negative("tangential damping ratio eta_t/gamma_n", p.damping_ratio);
  checks::non_negative("friction coefficient mu", p.mu);
}

}  // namespace mindlin_no_slip
}  // namespace tdem
