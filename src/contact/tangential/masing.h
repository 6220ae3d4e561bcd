// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the branch mechanics shared by the Mindlin-type laws with loading/unloading memory
// (walton_braun_tangential.h, mindlin_deresiewicz.h).
//
// 1. A branch. Along one branch the tangential load T (a signed scalar along the loading axis u,
//    see 2.) follows
//        dT/dd = K0 (1 - x)^(1/3),   x = s (T - T_ref) / D  in [0, 1],
//    with d the displacement along u, s = +-1 the direction of the branch, T_ref the point where
//    it started and D the distance from T_ref to its asymptote (T_ref + s D). Integrating,
//        (1 - x)^(2/3) = (1 - x_0)^(2/3) - 2 K0 s (d - d_0) / (3 D),
//    i.e. (1 - x)^(2/3) falls linearly with the displacement. branch_advance() uses this exact
//    solution for every step, so a constant-N path is followed without discretisation error
//    whatever the step, and x never passes 1 (|T| never passes the limit of the branch).
//    branch_distance() inverts it: the displacement that takes the branch from x to x_t.
// 2. The 3D state. The history stores the force vector F on particle i and a unit loading axis u
//    (both in the contact plane, both flip sign with the pair order, both carried into the plane
//    with carry_into_plane). T = -F.u is the signed load along the axis (a scalar that does not
//    flip: F and u flip together), F_perp = F + T u the rest. The displacement increment
//    d = v_t dt is split into d.u (drives T along the branches) and d_perp (changes F_perp with
//    the current tangent stiffness). Everything is a rotation-covariant function of vectors
//    in the plane, so a rigid rotation of the pair rotates the force and keeps its magnitude.
//    The axis is taken from the first motion of a fresh contact and re-set to the force
//    direction after gross sliding (then T = F_lim, F_perp = 0).
#pragma once

#include <cmath>

#include "common.h"

namespace tdem {
namespace tangential {

template <class T>
TDEM_KERNEL T clamp01(T x) noexcept {
  return x < T(0) ? T(0) : (x > T(1) ? T(1) : x);
}

// (1 - x)^(2/3)
template <class T>
TDEM_KERNEL T branch_c(T x) noexcept {
  const T r = std::cbrt(T(1) - x);
  return r * r;
}

// Tangent stiffness K0 (1 - x)^(1/3) of the branch.
template <class T>
TDEM_KERNEL T branch_stiffness(T k0, T x) noexcept {
  return k0 * std::cbrt(T(1) - clamp01(x));
}

// Position x of the load t on the branch (T_ref, D, s), clamped to [0, 1]; D <= 0 gives 1.
template <class T>
TDEM_KERNEL T branch_x(T t, T tref, T D, T s) noexcept {
  return D > T(0) ? clamp01(s * (t - tref) / D) : T(1);
}

// Load after a displacement step (>= 0, in the branch direction s) from load t. end: the value
// returned once the branch reaches its asymptote (tref + s D in exact arithmetic; the caller
// passes the exact limit, e.g. s F_lim, so that "at the limit" is an exact comparison).
template <class T>
TDEM_KERNEL T branch_advance(T t, T tref, T D, T s, T k0, T step, T end) noexcept {
  if (!(D > T(0))) return end;
  const T c = branch_c(branch_x(t, tref, D, s)) - T(2) * k0 * step / (T(3) * D);
  return c > T(0) ? tref + s * D * (T(1) - c * std::sqrt(c)) : end;
}

// Displacement along the branch from x to x_t (x <= x_t <= 1).
template <class T>
TDEM_KERNEL T branch_distance(T x, T xt, T D, T k0) noexcept {
  return T(3) * D / (T(2) * k0) * (branch_c(x) - branch_c(xt));
}

// Loads the 3D state (section 2 above) from hist[0..5] = F, u, carried into the current plane.
template <class T>
TDEM_KERNEL void load_axis_state(const TangentialKinematics<T>& k, const T* hist, T* F, T* u) noexcept {
  copy3(hist, F);
  copy3(hist + 3, u);
  carry_into_plane(k, F);
  carry_into_plane(k, u);
}

}  // namespace tangential
}  // namespace tdem
