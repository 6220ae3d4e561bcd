// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: energy accounting of a contact (issue 23). Host-free: the harness (src/collision/
// integrate_impact.h) and the hosts' computes use the same rules.
//
// The work each part of a contact's force does on the pair's motion, summed step by step. A part
// is a generalised force, the force on i (j gets the opposite one) and the torques on i and j:
//     Load = (f, t_i, t_j);
// a step's motion is the displacement of i relative to j (a wall's own motion is the wall's work,
// not the contact's) and the two rotations:
//     Motion = (dx, dth_i, dth_j) = h (v_i - v_j, w_i, w_j), the velocities of the step's drift.
// The work of a part over the step is the trapezoid of its loads at the two ends of the step
//     W += (L_n + L_n+1) . d / 2.
// Why this rule: a kick-drift-kick scheme (velocity Verlet, as fix nve/sphere; its variants whose
// force sees a predicted velocity) changes the kinetic energy over a step by exactly
//     K_n+1 - K_n = (F_n + F_n+1) . h v_n+1/2 / 2 + h^2/8 (|F_n+1|^2 - |F_n|^2) / m
// (per particle and per rotation axis with I), so with the discrete kinetic energy
//     K~ = K - h^2/8 |F|^2 / m              (kinetic(), Form::kick_drift_kick)
// the balance K~ + sum over contacts (-W) = const closes to round-off, whatever the force law, its
// history or a time-grid correction does to the force. The symplectic schemes that kick and then
// drift close it with their own K~ (Form::kick_then_drift). Other schemes leave a residual, which
// is their energy error in that sense. In free flight K~ = K.
//
// The parts (Part): a normal law's conservative (or hysteretic) part `elastic` of NormalResult and
// the rest (damping, and a clip at zero force); the tangential force with its torques; a rolling
// torque. The time-grid correction's extra force at a start or an end step belongs to the parts it
// corrects (its power model is linear in them). The energy taken out of the motion by a part is -W. Over a whole contact (loads zero before and after):
//   -W(normal elastic) = hysteresis of a hysteretic law, or the time-grid error of an elastic one
//                        (its spring returns what it took, up to how the grid samples the start
//                        and the end);
//   -W(normal damping) = the energy the normal damper dissipated; and so on.
#pragma once

#include "kinematics.h"

namespace tdem {
namespace energy {

enum Part : int { normal_elastic = 0, normal_damping, tangential, rolling, kParts };

inline constexpr const char* part_names[kParts] = {"normal_elastic", "normal_damping", "tangential", "rolling"};

template <class T>
struct Load {
  T f[3] = {T(0), T(0), T(0)};   // force on i [N]
  T ti[3] = {T(0), T(0), T(0)};  // torque on i [N m]
  T tj[3] = {T(0), T(0), T(0)};  // torque on j [N m]
};

template <class T>
struct Motion {
  T dx[3] = {T(0), T(0), T(0)};   // displacement of i relative to j over the step [m]
  T dti[3] = {T(0), T(0), T(0)};  // rotation of i [rad]
  T dtj[3] = {T(0), T(0), T(0)};  // rotation of j [rad]
};

// The work a load would do over the motion.
template <class T>
TDEM_KERNEL T work(const Load<T>& l, const Motion<T>& d) noexcept {
  T w = T(0);
  for (int k = 0; k < 3; ++k) w += l.f[k] * d.dx[k] + l.ti[k] * d.dti[k] + l.tj[k] * d.dtj[k];
  return w;
}

// The work of one part over a step: the trapezoid of its loads before and after the step.
template <class T>
TDEM_KERNEL T step_work(const Load<T>& before, const Load<T>& after, const Motion<T>& d) noexcept {
  return T(0.5) * (work(before, d) + work(after, d));
}

// How the scheme moves a body over a step, and the kinetic energy its balance closes with:
//   kick_drift_kick  velocity Verlet (fix nve/sphere) and its variants whose force sees a predicted
//                    velocity: drift h (v + h a/2), K~ = K - h^2/8 (|F|^2/m + |T|^2/I) (the header);
//   kick_then_drift  symplectic Euler, leapfrog (v the half-step velocity), position Verlet (v the
//                    differenced one): v+ = v + h a, drift h v+; K_n+1 - K_n = F_n . h (v_n + v_n+1)/2,
//                    which summed is the trapezoid work plus h/2 (F_0 . v_0 - F_n . v_n):
//                    K~ = K + h/2 (F . v + T . w).
// Other schemes close no such balance; their residual against kick_drift_kick is reported.
enum class Form : int { kick_drift_kick = 0, kick_then_drift = 1 };

// K~ of one body (mass m, isotropic inertia I; velocity v, spin w, accelerations a, alpha).
template <class T>
TDEM_KERNEL T kinetic(Form f, T m, T I, const T* v, const T* w, const T* a, const T* alpha, T h) noexcept {
  T k = T(0);
  for (int c = 0; c < 3; ++c) {
    k += T(0.5) * (m * v[c] * v[c] + I * w[c] * w[c]);
    k += f == Form::kick_drift_kick ? -h * h / T(8) * (m * a[c] * a[c] + I * alpha[c] * alpha[c])
                                    : T(0.5) * h * (m * a[c] * v[c] + I * alpha[c] * w[c]);
  }
  return k;
}

// The motion of body i against a body at rest over the step from (v, w) with the accelerations
// (a, alpha): h (v + c h a), c = 1/2 (kick_drift_kick: velocity Verlet's position update) or 1.
template <class T>
TDEM_KERNEL Motion<T> drift(Form f, const T* v, const T* w, const T* a, const T* alpha, T h) noexcept {
  const T c = f == Form::kick_drift_kick ? T(0.5) : T(1);
  Motion<T> d;
  for (int k = 0; k < 3; ++k) {
    d.dx[k] = h * (v[k] + c * h * a[k]);
    d.dti[k] = h * (w[k] + c * h * alpha[k]);
  }
  return d;
}

// A contact's accumulated work per part [J] (> 0: given to the motion).
template <class T>
struct Work {
  T w[kParts] = {};
  T total() const noexcept {
    T s = T(0);
    for (int p = 0; p < kParts; ++p) s += w[p];
    return s;
  }
};

// The loads of all parts of a contact at one step.
template <class T>
struct Loads {
  Load<T> part[kParts];
};

// One step of a contact: every part's trapezoid work over the motion d, from the loads before the
// step to the loads after it.
template <class T>
TDEM_KERNEL void accumulate(Work<T>& acc, const Loads<T>& before, const Loads<T>& after, const Motion<T>& d) noexcept {
  for (int p = 0; p < kParts; ++p) acc.w[p] += step_work(before.part[p], after.part[p], d);
}

// The loads of a contact of two spheres (or a sphere and a wall, j) at one step in the compact form
// a host keeps in the contact history between steps (kCompactSize doubles, in this order):
//   n    unit normal from j to i;
//   fe   the normal force's elastic part, fd the rest (on i along n);
//   ft   the tangential force on i at the contact point (j gets -ft), which lies ci from x_i and cj
//        from x_j along the normal: its torques are -ci n x ft on i and -cj n x ft on j;
//   tr   a rolling-resistance torque on i (j gets -tr).
template <class T>
struct Compact {
  T n[3] = {T(0), T(0), T(0)};
  T fe = T(0), fd = T(0);
  T ft[3] = {T(0), T(0), T(0)};
  T ci = T(0), cj = T(0);
  T tr[3] = {T(0), T(0), T(0)};
};
inline constexpr int kCompactSize = 14;

template <class T>
TDEM_KERNEL Loads<T> loads_of(const Compact<T>& c) noexcept {
  Loads<T> l;
  const T nxf[3] = {c.n[1] * c.ft[2] - c.n[2] * c.ft[1], c.n[2] * c.ft[0] - c.n[0] * c.ft[2],
                    c.n[0] * c.ft[1] - c.n[1] * c.ft[0]};
  for (int k = 0; k < 3; ++k) {
    l.part[normal_elastic].f[k] = c.fe * c.n[k];
    l.part[normal_damping].f[k] = c.fd * c.n[k];
    l.part[tangential].f[k] = c.ft[k];
    l.part[tangential].ti[k] = -c.ci * nxf[k];
    l.part[tangential].tj[k] = -c.cj * nxf[k];
    l.part[rolling].ti[k] = c.tr[k];
    l.part[rolling].tj[k] = -c.tr[k];
  }
  return l;
}

// The per-contact slots a host keeps in its contact history (kSlots doubles): the compact loads of
// the last step (kCompactSize, in the order of Compact) and the accumulated work per part (kParts).
inline constexpr int kSlots = kCompactSize + kParts;
template <class T>
TDEM_KERNEL void save(const Compact<T>& c, T* s) noexcept {
  for (int k = 0; k < 3; ++k) s[k] = c.n[k], s[5 + k] = c.ft[k], s[10 + k] = c.tr[k];
  s[3] = c.fe, s[4] = c.fd, s[8] = c.ci, s[9] = c.cj;
}
template <class T>
TDEM_KERNEL Compact<T> restore(const T* s) noexcept {
  Compact<T> c;
  for (int k = 0; k < 3; ++k) c.n[k] = s[k], c.ft[k] = s[5 + k], c.tr[k] = s[10 + k];
  c.fe = s[3], c.fd = s[4], c.ci = s[8], c.cj = s[9];
  return c;
}
// The slots of the same contact seen from the other side (the pair j-i): the normal, the tangential
// force and the rolling torque flip, the lever arms swap, the force parts and the work stay.
template <class T>
TDEM_KERNEL void reverse(const T* s, T* out) noexcept {
  for (int k = 0; k < 3; ++k) out[k] = -s[k], out[5 + k] = -s[5 + k], out[10 + k] = -s[10 + k];
  out[3] = s[3], out[4] = s[4], out[8] = s[9], out[9] = s[8];
  for (int p = 0; p < kParts; ++p) out[kCompactSize + p] = s[kCompactSize + p];
}
// One step of a contact kept in slots s: the work of every part over the motion d from the saved
// loads to `now`, then `now` saved. A contact's first step starts from zeroed slots (no load), its
// last step (the first without contact) passes now = Compact{} (no load). The same sums as
// accumulate(w, loads_of(restore(s)), loads_of(now), d), written out for the hosts' contact loops:
// the torques -c n x ft do the work -(n x ft) . (ci dth_i + cj dth_j).
template <class T>
TDEM_KERNEL void step(T* s, const Compact<T>& now, const Motion<T>& d) noexcept {
  auto dot = [](const T* a, const T* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto tang = [&](const T* n, const T* ft, T ci, T cj) {
    const T c[3] = {n[1] * ft[2] - n[2] * ft[1], n[2] * ft[0] - n[0] * ft[2], n[0] * ft[1] - n[1] * ft[0]};
    const T g[3] = {ci * d.dti[0] + cj * d.dtj[0], ci * d.dti[1] + cj * d.dtj[1], ci * d.dti[2] + cj * d.dtj[2]};
    return dot(ft, d.dx) - dot(c, g);
  };
  const T roll[3] = {d.dti[0] - d.dtj[0], d.dti[1] - d.dtj[1], d.dti[2] - d.dtj[2]};
  const T n0dx = dot(s, d.dx), n1dx = dot(now.n, d.dx);
  T* w = s + kCompactSize;
  w[normal_elastic] += T(0.5) * (s[3] * n0dx + now.fe * n1dx);
  w[normal_damping] += T(0.5) * (s[4] * n0dx + now.fd * n1dx);
  w[tangential] += T(0.5) * (tang(s, s + 5, s[8], s[9]) + tang(now.n, now.ft, now.ci, now.cj));
  w[rolling] += T(0.5) * (dot(s + 10, roll) + dot(now.tr, roll));
  save(now, s);
}
// One step of a contact with a wall that moves with velocity vw (its points all alike over the
// step): step() over d, the motion of the sphere relative to the wall, and the wall's own work on
// the sphere over h vw, the trapezoid of the whole contact force (F_n + F_n+1) . h vw / 2, added to
// wall. The two add up to the force's work over the sphere's own motion. A contact's last step
// (the first without contact) passes now = Compact{}.
template <class T>
TDEM_KERNEL void wall_step(T* s, const Compact<T>& now, const Motion<T>& d, const T* vw, T h, T& wall) noexcept {
  T f = T(0);
  for (int k = 0; k < 3; ++k)
    f += ((s[3] + s[4]) * s[k] + s[5 + k] + (now.fe + now.fd) * now.n[k] + now.ft[k]) * vw[k];
  wall += T(0.5) * f * h;
  step(s, now, d);
}
// A contact's end: the energy its parts took out of the motion (-W) added to taken[kParts], its
// slots zeroed.
template <class T>
TDEM_KERNEL void close(T* s, T* taken) noexcept {
  for (int p = 0; p < kParts; ++p) taken[p] -= s[kCompactSize + p];
  for (int m = 0; m < kSlots; ++m) s[m] = T(0);
}
// The motion of a pair over a step from the velocities of the step's drift (velocity Verlet: the
// half-step velocities a host's pair style sees): h (v_i - v_j), h w_i, h w_j. A moving wall's
// own displacement is the wall's work, not the contact's: pass the wall's velocity as v_j and
// account F . h v_wall to the wall.
template <class T>
TDEM_KERNEL Motion<T> pair_motion(const T* vi, const T* vj, const T* wi, const T* wj, T h) noexcept {
  Motion<T> d;
  for (int k = 0; k < 3; ++k) {
    d.dx[k] = h * (vi[k] - vj[k]);
    d.dti[k] = h * wi[k];
    d.dtj[k] = h * wj[k];
  }
  return d;
}

}  // namespace energy
}  // namespace tdem
