// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: Mindlin & Deresiewicz (J. Appl. Mech. 20 (1953) 327) tangential law with loading,
// unloading and reloading branches, Masing's memory rules for the reversal points, and the
// incremental rule of Thornton & Yin (Powder Technol. 65 (1991) 153) for a varying normal load
// (physics_reference.md section 3.3, law 5).
//
// Variant implemented. Constant N (F_lim = mu N, K0 = 8 G* a, a = sqrt(R* xi)):
//   loading (virgin curve, from 0):     k_t = K0 (1 - |T|/F_lim)^(1/3)
//   unloading from T* (reloading from T**, and every later branch from its reversal point r):
//                                        k_t = K0 (1 - |T - r|/(2 F_lim))^(1/3)
// T is the signed load along the loading axis (masing.h: F = -T u + F_perp). Closed forms (each
// step is integrated exactly, masing.h):
//   virgin:    T = F_lim [1 - (1 - d/d_c)^(3/2)],  d_c = 3 F_lim/(2 K0) = 3 mu N/(16 G* a)
//   unloading: T = T*  - 2 F_lim [1 - (1 - (d* - d)/(2 d_c))^(3/2)]
//   reloading: T = T** + 2 F_lim [1 - (1 - (d - d**)/(2 d_c))^(3/2)]
// (Masing: every branch after a reversal is the virgin curve scaled by 2 about its reversal point.)
// Memory (Masing/Madelung rules), kept as a stack r_1..r_m of reversal loads (m <= 4):
//   * a reversal pushes the current load;
//   * a branch that reaches the reversal point before its own start (r_(m-1)) closes the inner
//     loop: r_m and r_(m-1) are popped and the outer branch continues (reloading that reaches
//     T* continues on the virgin curve, an inner loop during unloading resumes the unloading);
//   * the first branch (m = 1, from T*) that reaches -T* meets the mirrored virgin curve (equal
//     stiffness there) and continues on it: r_1 is popped;
//   * with a full stack a reversal forgets the oldest inner loop (r_2, r_3; r_1 and the newest
//     points are kept: r_1 r_4 t), so the current, innermost loops stay exact Masing loops and
//     only a later excursion beyond r_4 towards r_3 / r_2 is approximated (it closes at r_1).
//     (Until issue 4 the newest loop was forgotten instead: pop r_4 and resume the branch from
//     r_3. A decaying oscillation - nested loops that never close - then ran every branch on a
//     softened stiffness, and a sphere on a slope with an undamped tangential oscillation
//     ratcheted up the slope by 1.7e-7 m in 0.2 s at constant N.)
// So small oscillations (also numerical jitter of v_t) leave the outer path unchanged, and a
// step that crosses a switching point is split there: constant-N paths follow the closed forms
// to rounding for any step size.
//
// Varying N (after Thornton & Yin 1991): before the displacement of a step is applied, the change
// of the limit dF_lim = mu dN (of F_lim, so the FrictionLimit choice is respected) moves the load
// by s dF_lim (1 - theta), theta = (1 - x)^(1/3) the current stiffness factor and s the branch
// direction: the slipped annulus carries mu times the change of pressure, the stuck core
// nothing. The reversal loads r_j are scaled with the limit (r_j F_lim/F_lim_prev), so that every
// branch keeps its place x relative to the new limit. (Thornton & Yin shift T*, T** by +-mu dN
// instead; with a load T << mu N that moves the branch origin far from T and drives T with the
// normal load alone - at grazing impacts it made |beta| > 1, i.e. created tangential energy.)
// A shrinking contact (K0 = 8 G* a falls with the overlap): the stored force and the reversal
// loads are scaled by K0/K0_prev, so the tangential spring releases its energy with the stiffness
// instead of creating some (cf. LAMMPS `mindlin_rescale`, Agnolin & Roux 2007).
// Why it is consistent:
//   * dN = 0 gives exactly the constant-N branches above (the closed forms);
//   * on the virgin branch x stays in [0, 1] for any increase of N and for decreases down to
//     dN >= -N theta^2; larger drops would push |T| above the new limit: there, and in every
//     other case, the force is capped at F_lim (gross sliding). |F| <= F_lim always holds;
//   * clamps: |r_j| <= F_lim; a load that a drop of N leaves behind the start of its branch
//     re-anchors the branch there (x = 0, full stiffness).
// Gross sliding (|F| at the limit): axis re-set to the force direction, T = F_lim on the virgin
// branch and the stack is cleared, so a reversal unloads along the full Mindlin-Deresiewicz
// unloading curve from T* = F_lim.
// No contact (xi <= 0, K0 = 0) or F_lim <= 0: no force and the history is cleared.
// Known limits at varying N (issue 4, not changed): the K0 rescale acts only when K0 falls, so an
// overlap that oscillates at fixed tangential displacement lets the load decay (one-way); the
// Thornton-Yin step uses theta at the start of the step; and right after a reversal while N
// falls, the limit scaling of r_m overtakes the load, which re-anchors the branch every step
// (the cause of the irregular time-step convergence of beta at nearly cancelled slip).
// G* from effective_shear_modulus() in parameters.h.
#pragma once

#include "../normal/input_checks.h"
#include "common.h"
#include "masing.h"

namespace tdem {
namespace mindlin_deresiewicz {

template <class T>
struct Params {
  T gstar;  // effective shear modulus G* [Pa]
  T mu;     // Coulomb friction coefficient
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
};

inline constexpr int max_reversals = 4;
inline constexpr HistorySlot history[] = {
    {"force_x", true},      {"force_y", true},      {"force_z", true},      {"axis_x", true},
    {"axis_y", true},       {"axis_z", true},       {"direction", false},   {"reversals", false},
    {"reversal_1", false},  {"reversal_2", false},  {"reversal_3", false},  {"reversal_4", false},
    {"limit_prev", false},  {"k0_prev", false}};
inline constexpr int history_size = 14;
// direction: s = +-1 of the current branch (0: fresh contact); reversals: m = 0..4 (stored as a
// real); reversal_j: the loads r_j; limit_prev: F_lim of the previous step.
enum Slot {
  force_slot = 0, axis_slot = 3, direction_slot = 6, count_slot = 7, reversal_slot = 8, limit_slot = 12, k0_slot = 13
};

template <class T>
TDEM_KERNEL T no_slip_stiffness(const Params<T>& p, const tangential::TangentialKinematics<T>& k) noexcept {
  return k.overlap > T(0) ? T(8) * p.gstar * std::sqrt(k.reff * k.overlap) : T(0);
}

// Start T_ref and width D of the current branch (m reversal points r, limit flim).
template <class T>
TDEM_KERNEL void branch_geometry(int m, const T* r, T flim, T& tref, T& D) noexcept {
  if (m == 0) tref = T(0), D = flim;
  else tref = r[m - 1], D = T(2) * flim;
}

template <class T>
TDEM_KERNEL bool force(const Params<T>& p, const tangential::TangentialKinematics<T>& k, T* hist, bool update,
                       T* ft) noexcept {
  using namespace tangential;
  const T flim = coulomb_limit(p.limit, p.mu, k.fn);
  const T k0 = no_slip_stiffness(p, k);
  if (!(flim > T(0)) || !(k0 > T(0))) {
    ft[0] = ft[1] = ft[2] = T(0);
    if (update)
      for (int i = 0; i < history_size; ++i) hist[i] = T(0);
    return !(flim > T(0));
  }
  T F[3], u[3], d[3], r[max_reversals];
  load_axis_state(k, hist, F, u);
  T s = hist[direction_slot], lp = hist[limit_slot], k0p = hist[k0_slot];
  int m = int(hist[count_slot] + T(0.5));
  m = m < 0 ? 0 : (m > max_reversals ? max_reversals : m);
  for (int j = 0; j < max_reversals; ++j) r[j] = hist[reversal_slot + j];
  displacement_increment(k, d);
  if (s == T(0) || dot(u, u) == T(0)) {  // fresh contact: axis from the first motion
    const T dn = norm(d);
    if (dn == T(0)) {
      ft[0] = ft[1] = ft[2] = T(0);
      return false;
    }
    u[0] = d[0] / dn, u[1] = d[1] / dn, u[2] = d[2] / dn;
    F[0] = F[1] = F[2] = T(0);
    s = T(1), m = 0, lp = flim, k0p = k0;
  }
  // 0. A shrinking contact (K0 falls): scale the stored force and the reversal loads by K0/K0_prev.
  if (k0p > T(0) && k0 < k0p) {
    const T g = k0 / k0p;
    F[0] *= g, F[1] *= g, F[2] *= g;
    for (int j = 0; j < m; ++j) r[j] *= g;
  }
  T t = -dot(F, u);
  const T Fp[3] = {F[0] + t * u[0], F[1] + t * u[1], F[2] + t * u[2]};
  T tref, D;

  // 1. Change of the normal load (Thornton & Yin).
  const T dl = flim - lp;
  if (dl != T(0) && lp > T(0)) {
    branch_geometry(m, r, lp, tref, D);
    const T theta = std::cbrt(T(1) - branch_x(t, tref, D, s));
    t += s * dl * (T(1) - theta);
    const T scale = flim / lp;  // the memory of the reversal points scales with the limit
    for (int j = 0; j < m; ++j) r[j] *= scale;
  }
  for (int j = 0; j < m; ++j) r[j] = r[j] > flim ? flim : (r[j] < -flim ? -flim : r[j]);
  if (m > 0 && s * (t - r[m - 1]) < T(0)) r[m - 1] = t;  // load behind the start: re-anchor
  branch_geometry(m, r, flim, tref, D);
  const T kperp = branch_stiffness(k0, branch_x(t, tref, D, s));

  // 2. Displacement along the axis, split at reversals and at the ends of branches.
  const T dpar = dot(d, u);
  T rem = dpar;
  for (int pass = 0; pass < 2 * max_reversals + 4 && rem != T(0); ++pass) {
    const T dir = rem > T(0) ? T(1) : T(-1);
    if (dir != s) {  // reversal
      if (m == max_reversals) {  // full: forget the oldest inner loop (r_2, r_3), keep r_1
        for (int j = 1; j + 2 < m; ++j) r[j] = r[j + 2];
        m -= 2;
      }
      r[m++] = t;
      s = dir;
    }
    branch_geometry(m, r, flim, tref, D);
    if (m > 0) {
      // End of this branch: the start of the enclosing one (closes the loop), or for the first
      // branch the mirrored virgin curve at -T*.
      const T target = m >= 2 ? r[m - 2] : -r[0];
      const T x = branch_x(t, tref, D, s);
      T xt = s * (target - tref) / D;
      if (xt <= x) {  // already there
        m = m >= 2 ? m - 2 : 0;
        continue;
      }
      if (xt > T(1)) xt = T(1);
      const T need = branch_distance(x, xt, D, k0);
      if (std::fabs(rem) >= need) {
        t = target;
        rem -= s * need;
        m = m >= 2 ? m - 2 : 0;
        continue;
      }
    }
    t = branch_advance(t, tref, D, s, k0, std::fabs(rem), tref + s * D);
    rem = T(0);
  }
  if (m == 0 && std::fabs(t) > flim) t = t > T(0) ? flim : -flim;

  // 3. Force, Coulomb cap, gross sliding.
  for (int i = 0; i < 3; ++i) F[i] = -t * u[i] + Fp[i] - kperp * (d[i] - dpar * u[i]);
  bool sliding = cap(F, flim);
  if (sliding) {
    const T inv = T(1) / norm(F);
    u[0] = -F[0] * inv, u[1] = -F[1] * inv, u[2] = -F[2] * inv;
    s = T(1), m = 0;
  } else {
    sliding = m == 0 && std::fabs(t) >= flim;
  }
  copy3(F, ft);
  if (update) {
    copy3(F, hist + force_slot);
    copy3(u, hist + axis_slot);
    hist[direction_slot] = s;
    hist[count_slot] = T(m);
    for (int j = 0; j < max_reversals; ++j) hist[reversal_slot + j] = j < m ? r[j] : T(0);
    hist[limit_slot] = flim;
    hist[k0_slot] = k0;
  }
  return sliding;
}

inline void validate(const Params<double>& p) {
  checks::positive("effective shear modulus G*", p.gstar);
  checks::non_negative("friction coefficient mu", p.mu);
}

}  // namespace mindlin_deresiewicz
}  // namespace tdem
