// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Walton's three-parameter rigid-body model of an oblique impact (e, mu, beta_0), sphere on a
// wall or two spheres, as closed forms (physics_reference.md section 3.1).
//
// Frame and signs (the same as src/collision/oblique.h):
//  * n: unit normal from sphere 2 (or the wall) to sphere 1; t: unit tangent in the impact plane,
//    the direction of the incoming tangential relative velocity (any fixed direction if there is
//    none); a = t x n: the axis perpendicular to the impact plane.
//  * v_n0 > 0: approach speed (-(v1 - v2).n); v_t0 = (v1 - v2).t.
//  * spins are scalars omega_i = omega_vec_i . a, chosen so that the slip velocity of sphere 1's
//    contact point relative to sphere 2's is  v_s = v_t + R1 omega_1 + R2 omega_2  (the convention
//    of section 3.1: v_s = v_t + R omega, zero for pure rolling on a wall).
//
// The model: the normal impulse gives v_n' = -e v_n0 (J_n = m_n (1+e) v_n0, 1/m_n = 1/m1 + 1/m2);
// the tangential impulse J_t acts on the slip velocity through the tangential effective mass
// 1/m_t = 1/m1 + 1/m2 + R1^2/I1 + R2^2/I2 (a solid sphere on a wall: m_t = 2/7 m, two equal
// spheres m/7) and
//   beta = min(beta_0, -1 + mu (1+e) (m_n/m_t) v_n0/|v_s0|),  v_s' = -beta v_s0,
//   J_t  = -m_t (1 + beta) v_s0,
//   v_t' = v_t0 + J_t/m_n,   omega_i' = omega_i + R_i J_t / I_i.
// The second argument of min is taken when the contact slides throughout (gross sliding:
// |J_t| = mu J_n). A wall has m2 = I2 = infinity (R2 does not matter).
#pragma once

#include <algorithm>
#include <cmath>

#include "contact/input_checks.h"

namespace tdem {
namespace rigid_body {

// Moment of inertia of a solid sphere.
inline double solid_sphere_inertia(double m, double R) { return 0.4 * m * R * R; }

struct Input {
  double e = 1.0;      // coefficient of normal restitution (of this impact)
  double mu = 0.0;     // Coulomb friction coefficient
  double beta0 = 1.0;  // tangential restitution of sticking impacts, [-1, 1]
  double m1 = 0.0, R1 = 0.0, I1 = 0.0;                  // sphere 1
  double m2 = INFINITY, R2 = INFINITY, I2 = INFINITY;   // sphere 2 (a wall: all infinite)
  double vn0 = 0.0;    // approach speed > 0
  double vt0 = 0.0;    // tangential relative velocity of the centres
  double omega1 = 0.0, omega2 = 0.0;  // scalar spins (see the header)
};

struct Output {
  double m_n = 0.0, m_t = 0.0;  // normal and tangential effective masses
  double vs0 = 0.0;             // incoming slip velocity
  bool gross_sliding = false;   // the friction limit holds for the whole contact
  double beta = 0.0;            // -v_s'/v_s0 (NaN if v_s0 = 0)
  double vn = 0.0;              // rebound normal velocity (> 0: separating) = e v_n0
  double vt = 0.0;              // tangential relative velocity after
  double vs = 0.0;              // slip velocity after
  double e_t = 0.0;             // v_t'/v_t0 (NaN if v_t0 = 0)
  double omega1 = 0.0, omega2 = 0.0;  // spins after
  double jn = 0.0, jt = 0.0;    // normal and tangential impulses on sphere 1
  double rebound_angle_com = 0.0;      // atan2(v_t', v_n') [rad]
  double rebound_angle_contact = 0.0;  // atan2(v_s', v_n') [rad]
  double psi_slide = 0.0;       // |v_s0|/(mu v_n0) above which the contact slides throughout
};

// Tangential effective mass of the contact point (infinite partner terms drop out).
inline double tangential_mass(double m1, double R1, double I1, double m2, double R2, double I2) {
  double inv = 1.0 / m1 + R1 * R1 / I1;
  if (std::isfinite(m2)) inv += 1.0 / m2;
  if (std::isfinite(I2)) inv += R2 * R2 / I2;
  return 1.0 / inv;
}

inline void validate(const Input& in) {
  if (!(in.e >= 0.0 && in.e <= 1.0)) checks::fail("coefficient of restitution e", in.e, "[0, 1]");
  checks::non_negative("friction coefficient mu", in.mu);
  if (!(in.beta0 >= -1.0 && in.beta0 <= 1.0)) checks::fail("tangential restitution beta_0", in.beta0, "[-1, 1]");
  checks::positive("mass m1", in.m1);
  checks::positive("radius R1", in.R1);
  checks::positive("moment of inertia I1", in.I1);
  if (!(in.m2 > 0.0)) checks::fail("mass m2", in.m2, "(0, inf]");
  if (!(in.I2 > 0.0)) checks::fail("moment of inertia I2", in.I2, "(0, inf]");
  if (std::isfinite(in.I2)) checks::positive("radius R2", in.R2);
  checks::positive("approach speed v_n0", in.vn0);
  if (!std::isfinite(in.vt0)) checks::fail("tangential velocity v_t0", in.vt0, "(-inf, inf)");
}

inline Output impact(const Input& in) {
  validate(in);
  Output o;
  o.m_n = std::isfinite(in.m2) ? 1.0 / (1.0 / in.m1 + 1.0 / in.m2) : in.m1;
  o.m_t = tangential_mass(in.m1, in.R1, in.I1, in.m2, in.R2, in.I2);
  const double r2w2 = std::isfinite(in.I2) ? in.R2 * in.omega2 : 0.0;
  o.vs0 = in.vt0 + in.R1 * in.omega1 + r2w2;
  o.jn = o.m_n * (1.0 + in.e) * in.vn0;
  o.vn = in.e * in.vn0;
  o.psi_slide = (o.m_n / o.m_t) * (1.0 + in.e);
  const double s = std::fabs(o.vs0);
  if (s > 0.0) {
    const double slide = -1.0 + in.mu * (1.0 + in.e) * (o.m_n / o.m_t) * in.vn0 / s;
    o.gross_sliding = slide <= in.beta0;
    o.beta = std::min(in.beta0, slide);
  } else {
    o.beta = NAN;
  }
  o.jt = s > 0.0 ? -o.m_t * (1.0 + o.beta) * o.vs0 : 0.0;
  o.vs = s > 0.0 ? -o.beta * o.vs0 : 0.0;
  o.vt = in.vt0 + o.jt / o.m_n;
  o.omega1 = in.omega1 + in.R1 * o.jt / in.I1;
  o.omega2 = std::isfinite(in.I2) ? in.omega2 + in.R2 * o.jt / in.I2 : 0.0;
  o.e_t = in.vt0 != 0.0 ? o.vt / in.vt0 : NAN;
  o.rebound_angle_com = std::atan2(o.vt, o.vn);
  o.rebound_angle_contact = std::atan2(o.vs, o.vn);
  return o;
}

}  // namespace rigid_body
}  // namespace tdem
