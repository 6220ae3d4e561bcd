// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Walton & Braun (J. Rheol. 30 (1986) 949) tangential law: a simplified Mindlin-Deresiewicz
// law whose stiffness depends on the tangential load relative to its value at the last
// reversal (physics_reference.md section 3.3, law 4).
//
//   T increasing (s = +1):  k_t = k_t0 (1 - (T - T*)/(F_lim - T*))^(1/3)
//   T decreasing (s = -1):  k_t = k_t0 (1 - (T* - T)/(F_lim + T*))^(1/3)
//   i.e. k_t = k_t0 (1 - x)^(1/3), x = s (T - T*)/(F_lim - s T*), and dT = k_t dd.
//
// T is the signed tangential load along the loading axis (masing.h: F = -T u + F_perp), T* its
// value at the last reversal of the displacement (0 at first touch), F_lim the Coulomb limit
// (common.h). k_t0 = kt + kappa k_n (a constant, or kappa times the normal tangent stiffness).
// Every branch runs from T* to the limit s F_lim, where the stiffness vanishes: the load
// approaches the limit and gross sliding follows. Closed form at constant N (masing.h, exact
// integration of each step):
//   T(d) = T* + s (F_lim - s T*) [1 - (1 - 2 k_t0 s (d - d*) / (3 (F_lim - s T*)))^(3/2)].
// Unlike Mindlin-Deresiewicz there is no memory of earlier reversal points: a reversal always
// starts a new branch towards the opposite limit. Hence closed displacement cycles about a loaded
// mean do not close the force loop: the unloading branch (D = F_lim + T*) is stiffer than the
// loading one (D = F_lim - T*), the load decays cycle by cycle, and under a constant load an
// undamped tangential oscillation creeps along the load (e.g. down a slope). That is the law
// itself (issue 4), not a discretisation error.
// Varying N (Walton & Braun's rule as we read it): the current F_lim enters the stiffness; T and
// T* are not rescaled, T* is clamped to [-F_lim, F_lim], a load beyond the limit is capped
// (gross sliding) and a load behind T* (possible after F_lim has dropped) re-anchors T* = T.
// When k_t0 falls (k_t0 = kappa k_n of a shrinking Hertz contact) the stored force and T* are
// scaled by k_t0/k_t0_prev (no energy creation by an incremental spring whose stiffness drops).
// Gross sliding (|F| reaches F_lim): the axis is re-set to the force direction, T = F_lim, T* = 0.
// The perpendicular displacement d_perp changes F_perp with the current k_t. |F| <= F_lim always.
#pragma once

#include "../input_checks.h"
#include "../law_parameters.h"
#include "common.h"
#include "masing.h"

namespace tdem {
namespace walton_braun_tangential {

template <class T>
struct Params {
  T kt;     // constant part of the initial tangential stiffness k_t0 [N/m]
  T kappa;  // part of k_t0 proportional to the normal tangent stiffness, k_t0 = kt + kappa k_n
  T mu;     // Coulomb friction coefficient
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
};

inline constexpr HistorySlot history[] = {{"force_x", true}, {"force_y", true}, {"force_z", true},
                                          {"axis_x", true},  {"axis_y", true},  {"axis_z", true},
                                          {"t_star", false}, {"direction", false}, {"k0_prev", false}};
inline constexpr int history_size = 9;

// The input line `tangential walton_braun ...` (src/contact/law_parameters.h).
inline constexpr law::Parameter parameters[] = {
    {"KT", "constant stiffness, force/length", "N/m", law::Bound::non_negative},
    {"KAPPA", "k_t/k_n", "1", law::Bound::non_negative},
    {"MU", "friction coefficient", "1", law::Bound::non_negative},
};
inline constexpr law::Description description =
    law::describe("tangential", "walton_braun", false, parameters, history, history_size);
enum Slot { force_slot = 0, axis_slot = 3, t_star_slot = 6, direction_slot = 7, k0_slot = 8 };

template <class T>
TDEM_KERNEL bool force(const Params<T>& p, const tangential::TangentialKinematics<T>& k, T* hist, bool update,
                       T* ft) noexcept {
  using namespace tangential;
  const T flim = coulomb_limit(p.limit, p.mu, k.fn);
  const T k0 = p.kt + p.kappa * k.kn;
  if (!(flim > T(0)) || !(k0 > T(0))) {  // no friction possible: no force, forget the contact state
    ft[0] = ft[1] = ft[2] = T(0);
    if (update)
      for (int i = 0; i < history_size; ++i) hist[i] = T(0);
    return !(flim > T(0));
  }
  T F[3], u[3], d[3];
  load_axis_state(k, hist, F, u);
  T ts = hist[t_star_slot], s = hist[direction_slot];
  displacement_increment(k, d);
  if (s == T(0) || dot(u, u) == T(0)) {  // fresh contact: axis from the first motion
    const T dn = norm(d);
    if (dn == T(0)) {
      ft[0] = ft[1] = ft[2] = T(0);
      return false;
    }
    u[0] = d[0] / dn, u[1] = d[1] / dn, u[2] = d[2] / dn;
    F[0] = F[1] = F[2] = T(0);
    ts = T(0), s = T(1);
  } else if (hist[k0_slot] > T(0) && k0 < hist[k0_slot]) {
    // A shrinking contact (k_t0 ~ k_n falls): the stored load follows the stiffness down, so the
    // spring releases its energy instead of creating some (as in mindlin_deresiewicz.h).
    const T g = k0 / hist[k0_slot];
    F[0] *= g, F[1] *= g, F[2] *= g;
    ts *= g;
  }
  T t = -dot(F, u);
  const T Fp[3] = {F[0] + t * u[0], F[1] + t * u[1], F[2] + t * u[2]};
  // Varying load: keep T* within the limit, re-anchor if the load is behind T*.
  if (ts > flim) ts = flim;
  if (ts < -flim) ts = -flim;
  if (s * (t - ts) < T(0)) ts = t;
  const T kperp = branch_stiffness(k0, branch_x(t, ts, flim - s * ts, s));
  const T dpar = dot(d, u);
  if (dpar != T(0)) {
    const T dir = dpar > T(0) ? T(1) : T(-1);
    if (dir != s) ts = t, s = dir;  // reversal
    t = branch_advance(t, ts, flim - s * ts, s, k0, std::fabs(dpar), s * flim);
  } else if (std::fabs(t) > flim) {
    t = t > T(0) ? flim : -flim;
  }
  for (int i = 0; i < 3; ++i) F[i] = -t * u[i] + Fp[i] - kperp * (d[i] - dpar * u[i]);
  bool sliding = cap(F, flim);
  if (sliding) {  // gross sliding: axis along the slip, load at the limit, no reversal memory
    const T inv = T(1) / norm(F);
    u[0] = -F[0] * inv, u[1] = -F[1] * inv, u[2] = -F[2] * inv;
    ts = T(0), s = T(1);
  } else {
    sliding = std::fabs(t) >= flim;
  }
  copy3(F, ft);
  if (update) {
    copy3(F, hist + force_slot);
    copy3(u, hist + axis_slot);
    hist[t_star_slot] = ts;
    hist[direction_slot] = s;
    hist[k0_slot] = k0;
  }
  return sliding;
}

inline void validate(const Params<double>& p) {
  checks::non_negative("initial tangential stiffness k_t0", p.kt);
  checks::non_negative("stiffness ratio kappa = k_t0/k_n", p.kappa);
  if (!(p.kt > 0.0 || p.kappa > 0.0))
    checks::fail("initial tangential stiffness k_t0 = k_t + kappa k_n with k_t", p.kt, "(0, inf) (or give kappa > 0)");
  checks::non_negative("friction coefficient mu", p.mu);
}

}  // namespace walton_braun_tangential
}  // namespace tdem
