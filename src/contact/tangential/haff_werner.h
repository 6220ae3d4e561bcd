// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Haff & Werner (Powder Technol. 48 (1986) 239) viscous friction, no memory
// (physics_reference.md section 3.3, law 1).
//
//   F_t = -min(gamma_t |v_t|, F_lim) v_t / |v_t|,   F_lim = coulomb_limit(limit, mu, F_n)
//
// The force opposes the slip velocity and vanishes with it: no static friction (a particle
// creeps on any slope) and no reversal of the tangential velocity (beta <= 0 only). The return
// value says whether the Coulomb limit is active (gamma_t |v_t| > F_lim), i.e. gross sliding.
#pragma once

#include "../input_checks.h"
#include "../law_parameters.h"
#include "common.h"

namespace tdem {
namespace haff_werner {

template <class T>
struct Params {
  T gammat;  // tangential damping coefficient gamma_t [kg/s]
  T mu;      // Coulomb friction coefficient
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
};

inline constexpr HistorySlot history[] = {{"unused", false}};  // no memory: history_size = 0
inline constexpr int history_size = 0;

// The input line `tangential haff_werner ...` (src/contact/law_parameters.h).
inline constexpr law::Parameter parameters[] = {
    {"GAMMAT", "damping coefficient, mass/time", "kg/s", law::Bound::non_negative},
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description description =
    law::describe("tangential", "haff_werner", false, parameters, history, history_size);

template <class T>
TDEM_KERNEL bool force(const Params<T>& p, const tangential::TangentialKinematics<T>& k, T* /*hist*/,
                       bool /*update*/, T* ft) noexcept {
  ft[0] = -p.gammat * k.vt[0], ft[1] = -p.gammat * k.vt[1], ft[2] = -p.gammat * k.vt[2];
  return tangential::cap(ft, tangential::coulomb_limit(p.limit, p.mu, k.fn));
}

inline void validate(const Params<double>& p) {
  checks::non_negative("tangential damping coefficient gamma_t", p.gammat);
  checks::non_negative("friction coefficient mu", p.mu);
}

}  // namespace haff_werner
}  // namespace tdem
