// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: rolling resistance, spring-dashpot-slider (SDS) on the rolling displacement of a contact.
//
// With the unit normal n pointing from j to i (for a wall: from the wall to the sphere) and the
// effective radius R* = R_i R_j / (R_i + R_j) (a wall: R_i):
//
//   rolling velocity       v_r = R* (omega_i - omega_j) x n          (in the contact plane)
//   rolling displacement   xi_r += v_r dt, projected into the current contact plane (history)
//   rolling "force"        F_r = -(k_r xi_r + gamma_r v_r),  |F_r| <= mu_r |F_n|
//   torques                tau_i = R* n x F_r,  tau_j = -tau_i        (no force on the centres)
//
// On sliding (|F_r| above the limit) the force is scaled to the limit and the spring is set so
// that spring plus dashpot give the capped force: xi_r = -(F_r + gamma_r v_r)/k_r. In gross
// rolling the torque is the constant mu_r R* |F_n| against the relative spin: a sphere of
// inertia 2/5 m R^2 spinning on a wall under N = m g slows down as
// omega(t) = omega0 - 5 mu_r g t / (2 R) (DEM-07, validation/dem_suite). Below the limit the
// spring gives a rotational oscillator of stiffness k_r R*^2.
//
// The spring-dashpot-slider of the granular literature (Luding 2008, Granular Matter 10:235; the
// kind of LAMMPS `pair_style granular ... rolling sds`), written here from the equations above.
#pragma once

#include <cmath>

#include "../kinematics.h"
#include "../law_parameters.h"

namespace tdem {
namespace rolling_sds {

template <class T>
struct Params {
  T kr;      // rolling stiffness [N/m], > 0
  T gammar;  // rolling damping [kg/s], >= 0
  T mur;     // rolling friction coefficient (dimensionless), >= 0
};

// The rolling displacement, a vector in the contact plane. Seen from j (n -> -n, i <-> j) v_r is
// the same vector, so the history does not flip with the pair order; the torque on j is -tau_i.
inline constexpr HistorySlot history[] = {{"roll_x", false}, {"roll_y", false}, {"roll_z", false}};
inline constexpr int history_size = 3;

// n: unit normal from j to i; reff: R*; wi, wj: angular velocities (wj = 0 for a wall); fn: the
// normal force of the contact; update: advance the history (false in set-up passes). Writes the
// torque on i into torque_i (the torque on j is its negative).
template <class T>
TDEM_KERNEL void torque(const Params<T>& p, const T* n, T reff, const T* wi, const T* wj, T fn, T dt, bool update,
                        T* roll, T* torque_i) noexcept {
  const T w0 = wi[0] - wj[0], w1 = wi[1] - wj[1], w2 = wi[2] - wj[2];
  const T vr0 = reff * (w1 * n[2] - w2 * n[1]);
  const T vr1 = reff * (w2 * n[0] - w0 * n[2]);
  const T vr2 = reff * (w0 * n[1] - w1 * n[0]);
  if (update) {
    roll[0] += vr0 * dt;
    roll[1] += vr1 * dt;
    roll[2] += vr2 * dt;
    const T rn = roll[0] * n[0] + roll[1] * n[1] + roll[2] * n[2];
    roll[0] -= rn * n[0];
    roll[1] -= rn * n[1];
    roll[2] -= rn * n[2];
  }
  T f0 = -(p.kr * roll[0] + p.gammar * vr0);
  T f1 = -(p.kr * roll[1] + p.gammar * vr1);
  T f2 = -(p.kr * roll[2] + p.gammar * vr2);
  const T fmag = std::sqrt(f0 * f0 + f1 * f1 + f2 * f2);
  const T limit = p.mur * std::fabs(fn);
  if (fmag > limit) {
    const T ratio = limit / fmag;
    f0 *= ratio;
    f1 *= ratio;
    f2 *= ratio;
    if (update) {
      roll[0] = -(f0 + p.gammar * vr0) / p.kr;
      roll[1] = -(f1 + p.gammar * vr1) / p.kr;
      roll[2] = -(f2 + p.gammar * vr2) / p.kr;
    }
  }
  torque_i[0] = reff * (n[1] * f2 - n[2] * f1);
  torque_i[1] = reff * (n[2] * f0 - n[0] * f2);
  torque_i[2] = reff * (n[0] * f1 - n[1] * f0);
}

// The input `rolling sds KR GAMMAR MUR`.
inline constexpr law::Parameter parameters[] = {
    {"KR", "rolling stiffness", "N/m", law::Bound::positive},
    {"GAMMAR", "rolling damping", "kg/s", law::Bound::non_negative},
    {"MUR", "rolling friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description description = {"rolling", "sds", false, parameters, 3, history, history_size,
                                                 false, nullptr, 0, nullptr, 0, true};

}  // namespace rolling_sds
}  // namespace tdem
