// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Cundall-Strack tangential law: a linear tangential spring (elongation kept in the
// contact history), an optional tangential dashpot, and a Coulomb limit mu |F_n|.
//
//   F_t = -(k_t s + gamma_t v_t)   while sticking,      |F_t| <= mu |F_n|
//
// Every step the spring elongation s is advanced by v_t dt and projected into the current
// tangent plane (the normal component is removed). Two rules say what happens on sliding:
//
//   SlipRule::spring_cap          the Coulomb limit caps the spring force k_t|s|; while
//                                 sliding the dashpot is off and the spring is truncated to
//                                 s = -F_t/k_t (so |k_t s| = mu|F_n|). LIGGGHTS `tangential history`.
//   SlipRule::spring_dashpot_cap  the limit caps the whole force |k_t s + gamma_t v_t|; the
//                                 spring is set so that the spring-plus-dashpot force equals the
//                                 capped force. LAMMPS `gran/hooke/history`. This truncation is
//                                 applied even when the history is not advanced (set-up passes),
//                                 as LAMMPS does.
#pragma once

#include <cmath>

#include "../kinematics.h"
#include "../law_parameters.h"

namespace tdem {
namespace cundall_strack {

enum class SlipRule { spring_cap, spring_dashpot_cap };

inline const char* to_string(SlipRule r) {
  return r == SlipRule::spring_cap ? "spring" : "spring_dashpot";
}

template <class T>
struct Params {
  T kt;      // tangential stiffness [N/m]
  T gammat;  // tangential damping coefficient of this contact [kg/s]
  T mu;      // Coulomb friction coefficient
};

template <class T>
struct Kinematics {
  T d[3];     // normal direction, any length (unit normal, or the centre distance vector)
  T d_scale;  // 1/|d|^2 (1 for a unit normal)
  T vt[3];    // tangential velocity of the contact point of i relative to j
  T dt;       // time step
};

// The spring elongation, a vector in the contact plane: flips sign with the pair order.
inline constexpr HistorySlot history[] = {{"shear_x", true}, {"shear_y", true}, {"shear_z", true}};
inline constexpr int history_size = 3;

// fn: the normal force of this contact (from the normal law). update: advance the history
// (false during set-up passes that must not change the state). Writes the tangential force
// on particle i into ft.
template <SlipRule Rule, class T>
TDEM_KERNEL void force(const Params<T>& p, const Kinematics<T>& kin, T fn, bool update, T* shear,
                  T* ft) noexcept {
  if (update) {
    shear[0] += kin.vt[0] * kin.dt;
    shear[1] += kin.vt[1] * kin.dt;
    shear[2] += kin.vt[2] * kin.dt;
    T rsht = shear[0] * kin.d[0] + shear[1] * kin.d[1] + shear[2] * kin.d[2];
    rsht *= kin.d_scale;
    shear[0] -= rsht * kin.d[0];
    shear[1] -= rsht * kin.d[1];
    shear[2] -= rsht * kin.d[2];
  }
  const T shrmag = std::sqrt(shear[0] * shear[0] + shear[1] * shear[1] + shear[2] * shear[2]);
  const T limit = p.mu * std::fabs(fn);

  if constexpr (Rule == SlipRule::spring_cap) {
    ft[0] = -(p.kt * shear[0]);
    ft[1] = -(p.kt * shear[1]);
    ft[2] = -(p.kt * shear[2]);
    const T spring = p.kt * shrmag;
    if (spring > limit) {
      if (shrmag != T(0)) {
        const T ratio = limit / spring;
        ft[0] *= ratio;
        ft[1] *= ratio;
        ft[2] *= ratio;
        if (update) {
          shear[0] = -ft[0] / p.kt;
          shear[1] = -ft[1] / p.kt;
          shear[2] = -ft[2] / p.kt;
        }
      } else {
        ft[0] = ft[1] = ft[2] = T(0);
      }
    } else {
      ft[0] -= p.gammat * kin.vt[0];
      ft[1] -= p.gammat * kin.vt[1];
      ft[2] -= p.gammat * kin.vt[2];
    }
  } else {
    ft[0] = -(p.kt * shear[0] + p.gammat * kin.vt[0]);
    ft[1] = -(p.kt * shear[1] + p.gammat * kin.vt[1]);
    ft[2] = -(p.kt * shear[2] + p.gammat * kin.vt[2]);
    const T fs = std::sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]);
    if (fs > limit) {
      if (shrmag != T(0)) {
        // written out per component: as a loop, hosts that inline the kernel (pair
        // tdem/gran) kept it rolled and ft[] in memory (~25 more instructions per slip)
        const T ratio = limit / fs;
        const T dash0 = p.gammat * kin.vt[0] / p.kt;
        const T dash1 = p.gammat * kin.vt[1] / p.kt;
        const T dash2 = p.gammat * kin.vt[2] / p.kt;
        shear[0] = ratio * (shear[0] + dash0) - dash0;
        shear[1] = ratio * (shear[1] + dash1) - dash1;
        shear[2] = ratio * (shear[2] + dash2) - dash2;
        ft[0] *= ratio;
        ft[1] *= ratio;
        ft[2] *= ratio;
      } else {
        ft[0] = ft[1] = ft[2] = T(0);
      }
    }
  }
}

template <class T>
inline void force(SlipRule rule, const Params<T>& p, const Kinematics<T>& kin, T fn, bool update,
                  T* shear, T* ft) noexcept {
  if (rule == SlipRule::spring_cap)
    force<SlipRule::spring_cap>(p, kin, fn, update, shear, ft);
  else
    force<SlipRule::spring_dashpot_cap>(p, kin, fn, update, shear, ft);
}

// ---------------------------------------------------------------- input
// Two forms, chosen by the normal law: `KT GAMMAT MU` with normal lsd stiffness (the values of
// gran/hooke/history), `KAPPA MU` (k_t = KAPPA times the normal law's tangential basis) with
// every other normal law.
inline constexpr law::Parameter stiffness_values[] = {
    {"KT", "tangential stiffness", "N/m", law::Bound::positive},
    {"GAMMAT", "tangential damping (as GAMMAN)", "1/s", law::Bound::non_negative},
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Parameter ratio_values[] = {
    {"KAPPA", "kt/kn", "1", law::Bound::positive, -1, false, 0.0, true},  // tangential/normal stiffness
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description stiffness_description = {
    "tangential", "cundall_strack", false, stiffness_values, 3, history, history_size, false,
    nullptr,      0,                nullptr, 0,            true};
inline constexpr law::Description ratio_description = {
    "tangential", "cundall_strack", false, ratio_values, 2, history, history_size, false,
    nullptr,      0,                nullptr, 0,         true};

}  // namespace cundall_strack
}  // namespace tdem
