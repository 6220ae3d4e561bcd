// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: mechanics shared by the tangential laws (physics_reference.md section 3), written once.
//
// Conventions:
//  * n is the unit normal pointing from j to i; the force computed is the force on particle i
//    (particle j gets the opposite one). Seen from j, n, the slip velocity and every stored
//    tangential vector change sign (HistorySlot::flips_sign), scalars do not.
//  * vt is the slip velocity of i's contact point relative to j's, in the tangent plane.
//  * spin_n = (omega_i + omega_j)/2 . n: the rate at which the pair turns about the normal.
//
// carry_into_plane(): before a stored tangential vector s is used in a new step it is carried
// along with the pair: (1) rotated by (omega_t + spin_n n) dt, the turning of the normal plus the
// twist of the pair about it, (2) any remaining component along the new normal removed and (3)
// rescaled to its old length. Under a rigid rotation of the pair (vt = 0) the stored vector - and
// the force it gives - rotates with the pair and keeps its magnitude (objectivity); a host that
// does not supply omega_t still gets the magnitude exactly and the direction to first order in
// the turning angle per step. Plain projection without (1) and (3) would lose magnitude with
// every step and ignore the twist.
//
// coulomb_limit(): mu max(Fn, 0) (FrictionLimit::positive_normal, no friction while a law allows
// attraction) or mu |Fn| (FrictionLimit::absolute, what LIGGGHTS' and LAMMPS' stock styles do).
#pragma once

#include <cmath>

#include "../kinematics.h"

namespace tdem {
namespace tangential {

enum class FrictionLimit { positive_normal, absolute };

inline const char* to_string(FrictionLimit f) {
  return f == FrictionLimit::positive_normal ? "positive_normal" : "absolute";
}

// What every tangential law receives for one contact and one step.
template <class T>
struct TangentialKinematics {
  T n[3];     // unit normal, from j to i
  T vt[3];    // slip velocity of i's contact point relative to j's, tangential [m/s]
  T spin_n;   // (omega_i + omega_j)/2 . n [1/s]
  T dt;       // time step [s]
  T overlap;  // xi [m] (Mindlin-type stiffness ~ sqrt(R* xi))
  T meff;     // m* [kg]
  T reff;     // R* [m]
  T fn;       // normal force of this contact (> 0 repulsive), from the normal law
  T kn;       // normal tangent stiffness dFn/dxi from the normal law [N/m]
  T gamman;   // normal damping coefficient the normal law used [kg/s]
  // Turning rate of the normal, n x dn/dt [1/s] (in the tangent plane): for two spheres
  // n x (v_i - v_j) / |x_i - x_j|, 0 for a plane wall. Leave 0 if unknown (then only the
  // projection below carries the state, exact to first order in the turning angle per step).
  T omega_t[3] = {T(0), T(0), T(0)};
};

template <class T>
TDEM_KERNEL T coulomb_limit(FrictionLimit f, T mu, T fn) noexcept {
  return f == FrictionLimit::absolute ? mu * std::fabs(fn) : (fn > T(0) ? mu * fn : T(0));
}

template <class T>
TDEM_KERNEL T dot(const T* a, const T* b) noexcept {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Rotates s about the unit vector n by the angle phi (Rodrigues; s need not be perpendicular to n).
template <class T>
TDEM_KERNEL void rotate_about(const T* n, T phi, T* s) noexcept {
  const T c = std::cos(phi), si = std::sin(phi);
  const T nd = dot(n, s);
  const T cx = n[1] * s[2] - n[2] * s[1], cy = n[2] * s[0] - n[0] * s[2], cz = n[0] * s[1] - n[1] * s[0];
  const T r0 = s[0] * c + cx * si + n[0] * nd * (T(1) - c);
  const T r1 = s[1] * c + cy * si + n[1] * nd * (T(1) - c);
  const T r2 = s[2] * c + cz * si + n[2] * nd * (T(1) - c);
  s[0] = r0, s[1] = r1, s[2] = r2;
}

// Carries a stored tangential vector s into the current tangent plane (see the header): rotates
// it with the pair by (omega_t + spin_n n) dt - exactly the rigid rotation of the pair when both
// rates are given - then removes any remaining normal component and restores the length.
template <class T>
TDEM_KERNEL void carry_into_plane(const TangentialKinematics<T>& k, T* s) noexcept {
  const T len2 = dot(s, s);
  if (len2 == T(0)) return;
  const T w[3] = {k.omega_t[0] + k.spin_n * k.n[0], k.omega_t[1] + k.spin_n * k.n[1],
                  k.omega_t[2] + k.spin_n * k.n[2]};
  const T w2 = dot(w, w);
  if (w2 > T(0)) {
    // Rodrigues with the unnormalised rate w and phi = |w| dt:
    //   s' = s cos(phi) + (w x s) sin(phi)/|w| + w (w.s) (1 - cos(phi))/|w|^2.
    // Per step phi is tiny in practice: then the series (error < phi^6/720 < 2e-15 for
    // phi^2 < 1e-4) avoids sin, cos and the square root.
    const T dt2 = k.dt * k.dt, phi2 = w2 * dt2;
    T c, sw, cw;  // cos(phi), sin(phi)/|w|, (1 - cos(phi))/|w|^2
    if (phi2 < T(1e-4)) {
      c = T(1) - phi2 * (T(0.5) - phi2 / T(24));
      sw = k.dt * (T(1) - phi2 * (T(1) / T(6) - phi2 / T(120)));
      cw = dt2 * (T(0.5) - phi2 * (T(1) / T(24) - phi2 / T(720)));
    } else {
      const T wm = std::sqrt(w2), phi = wm * k.dt;
      c = std::cos(phi);
      sw = std::sin(phi) / wm;
      cw = (T(1) - c) / w2;
    }
    const T ws = dot(w, s);
    const T x0 = w[1] * s[2] - w[2] * s[1], x1 = w[2] * s[0] - w[0] * s[2], x2 = w[0] * s[1] - w[1] * s[0];
    s[0] = s[0] * c + x0 * sw + w[0] * ws * cw;
    s[1] = s[1] * c + x1 * sw + w[1] * ws * cw;
    s[2] = s[2] * c + x2 * sw + w[2] * ws * cw;
  }
  const T sn = dot(s, k.n);
  s[0] -= sn * k.n[0], s[1] -= sn * k.n[1], s[2] -= sn * k.n[2];
  const T len2_new = dot(s, s);
  if (len2_new > T(0)) {
    const T scale = std::sqrt(len2 / len2_new);
    s[0] *= scale, s[1] *= scale, s[2] *= scale;
  }
}

// Scales the vector f (3 components) so that |f| <= limit; returns true if it was capped.
template <class T>
TDEM_KERNEL bool cap(T* f, T limit) noexcept {
  const T m2 = dot(f, f);
  if (m2 <= limit * limit) return false;
  const T r = m2 > T(0) ? limit / std::sqrt(m2) : T(0);
  f[0] *= r, f[1] *= r, f[2] *= r;
  return true;
}

// ---------------------------------------------------------------- additions (issue 4 laws)
// Small vector helpers used by the laws.
template <class T>
TDEM_KERNEL T norm(const T* a) noexcept {
  return std::sqrt(dot(a, a));
}

template <class T>
TDEM_KERNEL void copy3(const T* from, T* to) noexcept {
  to[0] = from[0], to[1] = from[1], to[2] = from[2];
}

// The tangential displacement increment of this step, vt dt.
template <class T>
TDEM_KERNEL void displacement_increment(const TangentialKinematics<T>& k, T* d) noexcept {
  d[0] = k.vt[0] * k.dt, d[1] = k.vt[1] * k.dt, d[2] = k.vt[2] * k.dt;
}

// The step every law with a stored spring elongation s does first: carry s into the current
// plane (carry_into_plane), then advance it by vt dt.
template <class T>
TDEM_KERNEL void carry_and_advance(const TangentialKinematics<T>& k, T* s) noexcept {
  carry_into_plane(k, s);
  s[0] += k.vt[0] * k.dt, s[1] += k.vt[1] * k.dt, s[2] += k.vt[2] * k.dt;
}

}  // namespace tangential
}  // namespace tdem
