// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: rigid-body state and integrators of a multi-sphere clump (physics_reference.md 6.1, 6.2).
//
// State: centre of mass x and velocity v (space frame), unit quaternion q mapping body-frame
// vectors to the space frame (Lambda(q) r_hat; the body frame is the principal-axis frame of the
// template, so the body inertia is diag(I1, I2, I3)), and the angular momentum L in the SPACE frame
// (angular-momentum formulation: dL/dt = torque exactly, the gyroscopic term omega x (I omega) is
// contained in omega = Lambda I^-1 Lambda^T L; no M = I domega/dt pitfall).
//
// A host step is velocity Verlet for translation and angular momentum around a rotation update:
//   initial_integrate:  v += h F/(2M); x += h v; L += h T/2; q <- rotate(q, L, h)
//   (forces and torques at the new positions)
//   final_integrate:    v += h F/(2M); L += h T/2
// The rotation update with L held fixed over the step (Rotation):
//   explicit_rodrigues  q <- dq(omega h) q with omega = Lambda I^-1 Lambda^T L at the START of the
//                       step and dq the exact rotation by the vector omega h (Rodrigues /
//                       quaternion exponential): the incremental rotation matrix Lambda_{n+1} =
//                       dLambda(psi) Lambda_n, psi = omega h. First order; energy drifts.
//   splitting           Dullweber-Leimkuhler-McLachlan (1997) symmetric splitting of the free
//                       rigid body H = sum_i pi_i^2/(2 I_i) (pi = Lambda^T L, body frame): exact
//                       flows of H_1 (h/2), H_2 (h/2), H_3 (h), H_2 (h/2), H_1 (h/2); each is a
//                       rotation of the body about principal axis i by h pi_i/I_i. Symplectic,
//                       time-reversible, second order; L is untouched (conserved exactly in the
//                       space frame), energy error bounded. Same family as NO_SQUISH (Miller et
//                       al. 2002, fix rigid/nve), which composes the same planar rotations.
//   richardson          the quaternion update of LAMMPS `fix rigid` / LIGGGHTS `fix multisphere`:
//                       one full step and two half steps of dq/dt = (1/2) omega(q) * q, each
//                       normalised, combined as 2 q_half - q_full (Richardson extrapolation).
//                       Written here from the method's description.
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixes/clumps/template.h"

namespace tdem {
namespace clumps {

// ------------------------------------------------------------------ quaternions
struct Quat {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

inline Quat qmul(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
inline double qnorm(const Quat& q) { return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z); }
inline Quat qnormalise(const Quat& q) {
  const double n = 1.0 / qnorm(q);
  return {q.w * n, q.x * n, q.y * n, q.z * n};
}

// Quaternion of the rotation by the vector psi (angle |psi| about psi/|psi|): exact, unit.
inline Quat quat_from_rotation_vector(const Vec3& psi) {
  const double a = norm(psi);
  if (a < 1e-8) {  // series: sin(a/2)/a = 1/2 - a^2/48, cos(a/2) = 1 - a^2/8
    const double s = 0.5 - a * a / 48.0;
    return qnormalise({1.0 - a * a / 8.0, s * psi[0], s * psi[1], s * psi[2]});
  }
  const double s = std::sin(0.5 * a) / a;
  return {std::cos(0.5 * a), s * psi[0], s * psi[1], s * psi[2]};
}

// Rotation matrix Lambda(q) (body -> space) of a unit quaternion.
inline Mat3 rotation_matrix(const Quat& q) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  return Mat3{Vec3{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
              Vec3{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
              Vec3{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
}

// Unit quaternion of a proper rotation matrix (Shepperd's method).
inline Quat quat_from_matrix(const Mat3& m) {
  const double tr = m[0][0] + m[1][1] + m[2][2];
  Quat q;
  if (tr > 0.0) {
    const double s = 2.0 * std::sqrt(1.0 + tr);
    q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
    q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
  } else if (m[1][1] > m[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
    q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
    q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
  }
  return qnormalise(q);
}

// ------------------------------------------------------------------ body and state
enum class Rotation { explicit_rodrigues, splitting, richardson };

inline const char* to_string(Rotation r) {
  switch (r) {
    case Rotation::explicit_rodrigues: return "explicit";
    case Rotation::splitting: return "splitting";
    case Rotation::richardson: return "richardson";
  }
  return "?";
}

inline Rotation rotation_from_string(const std::string& s) {
  if (s == "explicit" || s == "rodrigues") return Rotation::explicit_rodrigues;
  if (s == "splitting" || s == "dlm" || s == "symplectic") return Rotation::splitting;
  if (s == "richardson") return Rotation::richardson;
  throw std::invalid_argument("rotation scheme '" + s + "' is not known; allowed: explicit, splitting, richardson");
}

struct Body {
  double mass = 0.0;
  Vec3 inertia{};  // principal moments (body frame = principal axes)

  static Body from(const Template& t) { return {t.mp.mass, t.mp.principal}; }
};

struct State {
  Vec3 x{}, v{};  // centre of mass, velocity (space)
  Quat q{};       // body -> space
  Vec3 L{};       // angular momentum about the com (space)
};

// Angular momentum in the body frame pi = Lambda^T L.
inline Vec3 body_angular_momentum(const State& s) { return mul_t(rotation_matrix(s.q), s.L); }

// Angular velocity in the space frame omega = Lambda I^-1 Lambda^T L.
inline Vec3 angular_velocity(const State& s, const Body& b) {
  const Mat3 R = rotation_matrix(s.q);
  const Vec3 pi = mul_t(R, s.L);
  return mul(R, Vec3{pi[0] / b.inertia[0], pi[1] / b.inertia[1], pi[2] / b.inertia[2]});
}

// Set L from a space-frame angular velocity: L = Lambda I Lambda^T omega.
inline void set_angular_velocity(State& s, const Body& b, const Vec3& omega) {
  const Mat3 R = rotation_matrix(s.q);
  const Vec3 wb = mul_t(R, omega);
  s.L = mul(R, Vec3{b.inertia[0] * wb[0], b.inertia[1] * wb[1], b.inertia[2] * wb[2]});
}

// Inverse inertia tensor in the space frame, Lambda I^-1 Lambda^T.
inline Mat3 inverse_inertia_space(const State& s, const Body& b) {
  const Mat3 R = rotation_matrix(s.q);
  Mat3 D{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D[i][j] = R[i][j] / b.inertia[j];
  return mul(D, transpose(R));
}

// Inverse inertia tensor in the space frame, R diag(1/I) R^T, of the principal moments I along the
// columns of R (body -> space), as a stock rigid-body fix keeps them. A zero moment (an axis the
// fix does not turn about: rods, points) contributes nothing.
inline Mat3 inverse_inertia_space(const Mat3& R, const Vec3& principal) {
  Mat3 D{};
  for (int j = 0; j < 3; ++j) {
    const double inv = principal[j] > 0.0 ? 1.0 / principal[j] : 0.0;
    for (int i = 0; i < 3; ++i) D[i][j] = R[i][j] * inv;
  }
  return mul(D, transpose(R));
}

inline double rotational_energy(const State& s, const Body& b) {
  const Vec3 pi = body_angular_momentum(s);
  return 0.5 * (pi[0] * pi[0] / b.inertia[0] + pi[1] * pi[1] / b.inertia[1] + pi[2] * pi[2] / b.inertia[2]);
}
inline double kinetic_energy(const State& s, const Body& b) {
  return 0.5 * b.mass * dot(s.v, s.v) + rotational_energy(s, b);
}

// Space position of a body-frame offset and the velocity of a space point xp attached to the body.
inline Vec3 body_point(const State& s, const Vec3& r_hat) { return add(s.x, mul(rotation_matrix(s.q), r_hat)); }
inline Vec3 point_velocity(const State& s, const Body& b, const Vec3& xp) {
  return add(s.v, cross(angular_velocity(s, b), sub(xp, s.x)));
}

// Sphere centres of a template in the space frame (body offsets t.body).
inline std::vector<Vec3> sphere_positions(const State& s, const Template& t) {
  const Mat3 R = rotation_matrix(s.q);
  std::vector<Vec3> p;
  p.reserve(t.body.size());
  for (const auto& sp : t.body) p.push_back(add(s.x, mul(R, sp.x)));
  return p;
}

// State of a template placed with its template frame at the given orientation q_template
// (template frame -> space) and its com at x: q = q_template * q(A).
inline State place(const Template& t, const Vec3& x, const Quat& q_template = Quat{}) {
  State s;
  s.x = x;
  s.q = qnormalise(qmul(q_template, quat_from_matrix(t.mp.axes)));
  return s;
}

// ------------------------------------------------------------------ rotation update (L fixed)
namespace detail {
// Rotation of the body about its own principal axis i by the angle phi: q <- q * dq(phi e_i),
// with c = cos(phi/2), sn = sin(phi/2) given (the product written out).
inline Quat rotate_body_axis_cs(const Quat& q, int i, double c, double sn) {
  switch (i) {
    case 0: return {q.w * c - q.x * sn, q.x * c + q.w * sn, q.y * c + q.z * sn, q.z * c - q.y * sn};
    case 1: return {q.w * c - q.y * sn, q.x * c - q.z * sn, q.y * c + q.w * sn, q.z * c + q.x * sn};
    default: return {q.w * c - q.z * sn, q.x * c + q.y * sn, q.y * c - q.x * sn, q.z * c + q.w * sn};
  }
}
inline Quat dqdt(const Quat& q, const Vec3& omega) {  // (1/2) (0, omega) * q
  const Quat d = qmul(Quat{0.0, omega[0], omega[1], omega[2]}, q);
  return {0.5 * d.w, 0.5 * d.x, 0.5 * d.y, 0.5 * d.z};
}
inline Quat axpy(const Quat& q, double h, const Quat& d) {
  return {q.w + h * d.w, q.x + h * d.x, q.y + h * d.y, q.z + h * d.z};
}
// sin and cos of a sub-rotation's half angle. Per step it is a small angle (|x| < 1e-2 up to spins of
// 2e3 rad/s at dt = 1e-5 s): Taylor polynomials to x^7 and x^8, whose truncation (x^9/9!, x^10/10!) is
// below 1e-21 of the value, so that the result is as accurate as the library's (within one rounding);
// larger angles take std::sin and std::cos. Five pairs per body and step: the library calls were the
// largest single cost of fix tdem/clump.
inline void small_angle_sincos(double x, double& s, double& c) {
  const double x2 = x * x;
  if (x2 < 1e-4) {
    s = x - x * x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0)));
    c = 1.0 - x2 * (0.5 - x2 * (1.0 / 24.0 - x2 * (1.0 / 720.0 - x2 * (1.0 / 40320.0))));
  } else {
    s = std::sin(x);
    c = std::cos(x);
  }
}

// One sub-rotation of the splitting scheme: the free rotation about body axis I for the time dt
// (angle phi = dt pi_I / I_I): q <- q dq(phi e_I), pi turned by -phi about e_I.
template <int I>
inline void split_step(Quat& q, Vec3& pi, double dt, const Body& b) {
  constexpr int J = (I + 1) % 3, L = (I + 2) % 3;
  const double half = 0.5 * dt * pi[I] / b.inertia[I];
  double c, sn;
  small_angle_sincos(half, sn, c);
  q = rotate_body_axis_cs(q, I, c, sn);
  const double cphi = c * c - sn * sn, sphi = 2.0 * sn * c;
  const double pj = pi[J], pl = pi[L];
  pi[J] = cphi * pj + sphi * pl;
  pi[L] = cphi * pl - sphi * pj;
}
}  // namespace detail

inline void rotate(State& s, const Body& b, double h, Rotation scheme) {
  switch (scheme) {
    case Rotation::explicit_rodrigues: {
      const Vec3 w = angular_velocity(s, b);
      s.q = qnormalise(qmul(quat_from_rotation_vector(scale(h, w)), s.q));
      return;
    }
    case Rotation::splitting: {
      // The body-frame angular momentum pi = Lambda^T L is formed once; a sub-rotation by phi about
      // body axis i turns it by -phi about that axis (L is fixed in space), so only its two other
      // components change: one sin/cos pair per sub-rotation, no matrix per sub-step. The five
      // sub-rotations (axes 1, 2, 3, 2, 1) are written out (detail::split_step).
      Vec3 pi = body_angular_momentum(s);
      detail::split_step<0>(s.q, pi, 0.5 * h, b);
      detail::split_step<1>(s.q, pi, 0.5 * h, b);
      detail::split_step<2>(s.q, pi, h, b);
      detail::split_step<1>(s.q, pi, 0.5 * h, b);
      detail::split_step<0>(s.q, pi, 0.5 * h, b);
      s.q = qnormalise(s.q);
      return;
    }
    case Rotation::richardson: {
      const Vec3 w0 = angular_velocity(s, b);
      const Quat full = qnormalise(detail::axpy(s.q, h, detail::dqdt(s.q, w0)));
      State half = s;
      half.q = qnormalise(detail::axpy(s.q, 0.5 * h, detail::dqdt(s.q, w0)));
      const Vec3 w1 = angular_velocity(half, b);
      half.q = qnormalise(detail::axpy(half.q, 0.5 * h, detail::dqdt(half.q, w1)));
      s.q = qnormalise(Quat{2.0 * half.q.w - full.w, 2.0 * half.q.x - full.x, 2.0 * half.q.y - full.y,
                            2.0 * half.q.z - full.z});
      return;
    }
  }
}

// ------------------------------------------------------------------ host-style step
// Velocity Verlet for translation and angular momentum (see the header comment). F and T are the
// total force and the torque about the com (space frame) of the last force evaluation.
inline void initial_integrate(State& s, const Body& b, const Vec3& F, const Vec3& T, double h, Rotation scheme) {
  s.v = add(s.v, scale(0.5 * h / b.mass, F));
  s.x = add(s.x, scale(h, s.v));
  s.L = add(s.L, scale(0.5 * h, T));
  rotate(s, b, h, scheme);
}
inline void final_integrate(State& s, const Body& b, const Vec3& F, const Vec3& T, double h) {
  s.v = add(s.v, scale(0.5 * h / b.mass, F));
  s.L = add(s.L, scale(0.5 * h, T));
}

// Apply an impulse J at space point xp: dv = J/M, dL = (xp - x) x J.
inline void apply_impulse(State& s, const Body& b, const Vec3& J, const Vec3& xp) {
  s.v = add(s.v, scale(1.0 / b.mass, J));
  s.L = add(s.L, cross(sub(xp, s.x), J));
}

}  // namespace clumps
}  // namespace tdem
