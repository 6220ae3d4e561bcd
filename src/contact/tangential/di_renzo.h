// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Di Renzo & Di Maio (Chem. Eng. Sci. 60 (2005) 1303) improved integral tangential law
// (physics_reference.md section 3.3, law 7).
//
//   F_t = -(2/3) 8 G* a s = -(16/3) G* sqrt(R* xi) s,   |F_t| <= F_lim,  no dashpot
//
// 2/3 of the Mindlin no-slip stiffness (mindlin_no_slip.h) with the same total formulation: the
// spring elongation s is the history (carried into the plane, advanced by v_t dt) and on sliding
// it is truncated to k_t |s| = F_lim (without a dashpot both reset rules coincide). The factor
// makes the linear-in-s integral law follow the Mindlin-Deresiewicz curve on average up to
// gross sliding (Di Renzo & Di Maio's argument). G* from effective_shear_modulus() in parameters.h.
#pragma once

#include "../input_checks.h"
#include "../law_parameters.h"
#include "common.h"
#include "linear_spring.h"
#include "mindlin_no_slip.h"

namespace tdem {
namespace di_renzo {

template <class T>
struct Params {
  T gstar;  // effective shear modulus G* [Pa]
  T mu;     // Coulomb friction coefficient
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
};

inline constexpr HistorySlot history[] = {{"spring_x", true}, {"spring_y", true}, {"spring_z", true}};
inline constexpr int history_size = 3;

// The input line `tangential di_renzo E NU [E2 NU2] ...` (src/contact/law_parameters.h); the values
// are E1 NU1 E2 NU2, then the law's own.
inline constexpr law::Parameter parameters[] = {
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description description =
    law::describe("tangential", "di_renzo", true, parameters, history, history_size, true);

template <class T>
TDEM_KERNEL T stiffness(const Params<T>& p, const tangential::TangentialKinematics<T>& k) noexcept {
  return T(2) / T(3) * mindlin_no_slip::stiffness(p.gstar, k);
}

template <class T>
TDEM_KERNEL bool force(const Params<T>& p, const tangential::TangentialKinematics<T>& k, T* hist, bool update,
                       T* ft) noexcept {
  return tangential::spring_law_step(stiffness(p, k), T(0), tangential::coulomb_limit(p.limit, p.mu, k.fn),
                                     tangential::SlipReset::spring_only, k, hist, update, ft);
}

inline void validate(const Params<double>& p) {
  checks::positive("effective shear modulus G*", p.gstar);
  checks::non_negative("friction coefficient mu", p.mu);
}

}  // namespace di_renzo
}  // namespace tdem
