// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the time-grid correction (src/contact/grid_correction.h) of a contact of pair
// tdem/gran or fix tdem/wall/gran with `grid_correction on`: the step in which it starts and the
// step after it ends. Host glue around evaluate_contact (tdem_lammps_law.h), run-time law only;
// the same rules as the single-collision harness (src/collision/integrate_impact.h), so that a
// host impact equals tdem-collide --grid-correction on.
//
// The one value of grid::history_size is the last of a contact's history (hsize in all): 0 no
// contact at the last step, else the flags of grid_correction.h. A start is a contact whose slot
// is 0; the law is then probed three times on copies of the fresh history (at xi, xi/2 and the
// touch, no update), and the contact is corrected if the touch lies within the last step and the
// contact is resolved (grid::resolved). Between start and end a corrected contact runs the law as
// without the correction. At the first step without contact (gc_separation) or, for a zero-force
// law, at the step where the force is clipped to zero, the last contact step is reconstructed from
// the law's history (grid::previous_overlap) and the end's extra impulse applied.
#pragma once

#include "contact/grid_correction.h"
#include "tdem_lammps_law.h"

#include <cmath>
#include <cstring>

namespace tdem_lammps {

inline constexpr int GC_MAX_HISTORY = 32;
static_assert(MAX_HISTORY + tdem::rolling_sds::history_size + tdem::grid::history_size <= GC_MAX_HISTORY,
              "GC_MAX_HISTORY must hold a contact's history");

// The flags slot, whatever its sign: LAMMPS's default history transfer (pair order reversed)
// negates every value, and pair tdem/gran keeps that default when the flags are its only scalar.
inline double gc_flags(const double *shear, int hsize) { return std::fabs(shear[hsize - 1]); }

inline double gc_friction(const LawCoeffs &c) { return c.tlaw == TLAW_CUNDALL_STRACK ? c.mu : c.t_mu; }
// The friction limit of normal force fn (cundall_strack: mu |fn|; the others by their limit).
inline double gc_limit(const LawCoeffs &c, double fn) {
  const bool positive = c.tlaw != TLAW_CUNDALL_STRACK && c.tlimit;
  return gc_friction(c) * (positive ? (fn > 0.0 ? fn : 0.0) : std::fabs(fn));
}

// The contact's geometry and kinematics, as evaluate_contact takes them.
struct GcContact {
  const LawCoeffs *c;
  double meff, delx, dely, delz, r, rinv, rsqinv, overlap;
  double vr[3], wr[3];
  double dt, radi, radj;
  const double *omega_i, *omega_j;
  double overlap_rate() const { return -(vr[0] * delx + vr[1] * dely + vr[2] * delz) * rinv; }
};

// The normal law at overlap xi (and the tangential force fs) on a copy of the history, no update.
// M, E, S, TL, D: the law's compile-time path (evaluate_contact), -1 run time.
template <int M = -1, int E = -1, int S = -1, int TL = -1, int D = -1>
tdem::NormalResult<double> gc_probe(const GcContact &k, const double *shear, int hsize, double xi,
                                           double *fs = nullptr) {
  double copy[GC_MAX_HISTORY];
  for (int m = 0; m < hsize; ++m) copy[m] = shear[m];
  double ccel, fsl[3], troll[3];
  tdem::NormalResult<double> res{};
  evaluate_contact<M, E, S, TL, D>(*k.c, k.meff, k.delx, k.dely, k.delz, k.r, k.rinv, k.rsqinv, xi, k.vr[0], k.vr[1],
                                   k.vr[2], k.wr[0], k.wr[1], k.wr[2], k.dt, false, copy, ccel, fsl, k.radi, k.radj,
                                   k.omega_i, k.omega_j, troll, &res);
  if (fs) fs[0] = fsl[0], fs[1] = fsl[1], fs[2] = fsl[2];
  return res;
}

// The last contact step's values, reconstructed at an end from the history `prev` (which holds
// that step): the overlap one step back along the rate now, the normal law there, the tangential
// law there with that normal force (no update), and whether it was sliding.
struct GcPrevious {
  double xi, fn, k, ft[3];
  bool sliding;
  tdem::NormalResult<double> normal;  // the normal law there
};
template <int M = -1, int E = -1, int S = -1, int TL = -1, int D = -1>
GcPrevious gc_previous(const GcContact &k, const double *prev, int hsize) {
  GcPrevious p;
  p.xi = tdem::grid::previous_overlap(k.overlap, k.overlap_rate(), k.dt);
  p.normal = gc_probe<M, E, S, TL, D>(k, prev, hsize, p.xi, p.ft);
  p.fn = p.normal.force, p.k = p.normal.stiffness;
  p.sliding = tdem::grid::sliding(p.ft[0] * p.ft[0] + p.ft[1] * p.ft[1] + p.ft[2] * p.ft[2], gc_friction(*k.c), p.fn);
  return p;
}

// The normal law alone at overlap xi on the history `hist` (no update: the history is not changed).
template <int M = -1, int E = -1, int S = -1, int TL = -1, int D = -1>
tdem::NormalResult<double> gc_probe_normal(const GcContact &k, const double *hist, double xi) {
  const LawCoeffs &c = *k.c;
  const int toff = c.tlaw == TLAW_CUNDALL_STRACK ? TANGENTIAL_HISTORY : tangential_history_size(c.tlaw);
  double hn[MAX_NORMAL_HISTORY];
  for (int m = 0; m < normal_history_size(c.mode); ++m) hn[m] = hist[toff + m];
  double ccel, kn, gn;
  tdem::cundall_strack::Params<double> tp;
  tdem::NormalResult<double> res{};
  const double vnnr = k.vr[0] * k.delx + k.vr[1] * k.dely + k.vr[2] * k.delz;
  normal_contact<M, E, D>(c, k.meff, k.r, k.rinv, k.rsqinv, xi, vnnr, k.radi, k.radj, hn, false, ccel, kn, gn, tp, &res);
  return res;
}

// The exponents of the law's two parts (elastic, rest) at overlap xi, given its result r there: a
// second evaluation at xi/2, except for the linear law (lsd modes: 1 and 0, what the evaluation
// gives exactly; skipping it saves a fifth of an event's instructions on the chute) and for normal
// hertz without limit_force (declared by the law: 3/2 and Theta).
template <int M, int E, int S, int TL, int D>
void gc_exponents(const GcContact &k, const double *hist, double xi, const tdem::NormalResult<double> &r,
                  double &p, double &q) {
  const int mode = M >= 0 ? M : k.c->mode;
  if (mode <= MODE_RESTITUTION) {
    p = 1.0, q = 0.0;
    return;
  }
  if (mode == MODE_HERTZ &&
      tdem::hertz::power_exponents(hertz_damping(k.c->hdamp), k.c->htheta,
                                   k.c->end ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap, p, q))
    return;
  const tdem::NormalResult<double> hf = gc_probe_normal<M, E, S, TL, D>(k, hist, 0.5 * xi);
  p = tdem::grid::power_exponent(r.elastic, hf.elastic, 1.0);
  q = tdem::grid::power_exponent(r.force - r.elastic, hf.force - hf.elastic, 0.0);
}

// The extra force of an end s after the last step (normal fn_x along n, tangential ft_x): the
// normal force from the power model through the last step (zero_overlap; the law probed on
// `prev`) or linear to zero (zero_force); the tangential force following the normal one if it
// was sliding, else linear to the last one capped by the limit at the end.
template <int M = -1, int E = -1, int S = -1, int TL = -1, int D = -1>
void gc_end_extra(const GcContact &k, const double *prev, int hsize, const GcPrevious &p, double s,
                         bool at_zero_force, double &fn_x, double *ft_x) {
  const double dt = k.dt;
  double fe = 0.0;
  if (at_zero_force) {
    fn_x = tdem::grid::end_extra(p.fn, p.fn, 1.0, 0.0, 0.0, s, dt);
  } else {
    const tdem::NormalResult<double> &np = p.normal;
    double pe, q;
    gc_exponents<M, E, S, TL, D>(k, prev, p.xi, np, pe, q);
    fe = gc_probe_normal<M, E, S, TL, D>(k, prev, 0.0).force;
    fn_x = tdem::grid::end_extra(p.fn, np.elastic, pe, p.fn - np.elastic, q, s, dt);
  }
  const double cap = tdem::grid::cap_factor(p.ft[0] * p.ft[0] + p.ft[1] * p.ft[1] + p.ft[2] * p.ft[2],
                                            gc_limit(*k.c, fe));
  for (int i = 0; i < 3; ++i) {
    const double fte = cap * p.ft[i];
    ft_x[i] = p.sliding ? p.ft[i] / p.fn * (fn_x + p.fn) - p.ft[i]
                        : tdem::grid::end_extra(p.ft[i], p.ft[i] - fte, 1.0, fte, 0.0, s, dt);
  }
}

// The first step of a contact (flags slot 0): if the touch lies within the last step, the law
// with the tangential spring started at the touch, two probes on the fresh history (xi/2 and the
// touch), and the contact's corrected kick if it is resolved; an unresolved one is evaluated
// again from the fresh history as without the correction.
// M, E, S, TL, D: the law's path for the evaluation that commits the history (as evaluate_contact).
template <int M, int E, int S, int TL, int D>
[[gnu::cold, gnu::noinline]] void gc_start(const GcContact &k, double *shear, int hsize, double &ccel, double *fs,
                                           double *troll) {
  using namespace tdem::grid;
  const LawCoeffs &c = *k.c;
  const double xi_dot = k.overlap_rate(), dt = k.dt;
  const double tau = touch_age(k.overlap, xi_dot, dt);
  auto plain = [&](double step, tdem::NormalResult<double> *nr) {
    evaluate_contact<M, E, S, TL, D>(c, k.meff, k.delx, k.dely, k.delz, k.r, k.rinv, k.rsqinv, k.overlap, k.vr[0],
                                     k.vr[1], k.vr[2], k.wr[0], k.wr[1], k.wr[2], step, true, shear, ccel, fs, k.radi,
                                     k.radj, k.omega_i, k.omega_j, troll, nr);
  };
  if (tau < 0.0) {  // an old overlap, or not approaching: not corrected
    plain(dt, nullptr);
    shear[hsize - 1] = kFlagSeen;
    return;
  }
  double fresh[GC_MAX_HISTORY];
  for (int m = 0; m < hsize; ++m) fresh[m] = shear[m];
  tdem::NormalResult<double> nr{};
  plain(tau, &nr);
  double pe, pq;
  gc_exponents<M, E, S, TL, D>(k, fresh, k.overlap, nr, pe, pq);
  if (!resolved(nr.elastic, pe, nr.damping, k.overlap, xi_dot, k.meff, dt)) {
    for (int m = 0; m < hsize; ++m) shear[m] = fresh[m];
    plain(dt, nullptr);
    shear[hsize - 1] = kFlagSeen;
    return;
  }
  const double fn = ccel * k.r;
  const double fn_apply = start_force(nr.elastic, pe, fn - nr.elastic, pq, tau, dt);
  if (sliding(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2], gc_friction(c), fn)) {
    for (int i = 0; i < 3; ++i) fs[i] = fs[i] / fn * fn_apply;
  } else {  // linear from the law at the touch
    double ft0[3];
    gc_probe<M, E, S, TL, D>(k, fresh, hsize, 0.0, ft0);
    for (int i = 0; i < 3; ++i) fs[i] = start_force(fs[i] - ft0[i], 1.0, ft0[i], 0.0, tau, dt);
  }
  ccel = fn_apply * k.rinv;
  shear[hsize - 1] = kFlagOn;
}

// A corrected contact of a zero-force law whose force has just been clipped to zero: the end's
// extra force, with the tangential history of the last step (`tang`, saved before this step's
// update) in place of the updated one.
template <int M, int E, int S, int TL, int D>
[[gnu::cold, gnu::noinline]] void gc_zero_force_end(const GcContact &k, double *shear, int hsize,
                                                            const double *tang, int nt,
                                                            const tdem::NormalResult<double> &nr, double &ccel,
                                                            double *fs) {
  double prev[GC_MAX_HISTORY];
  std::memcpy(prev, shear, sizeof(double) * hsize);
  std::memcpy(prev, tang, sizeof(double) * nt);
  const GcPrevious p = gc_previous<M, E, S, TL, D>(k, prev, hsize);
  shear[hsize - 1] = tdem::grid::kFlagEnded;
  if (!tdem::grid::end_usable(p.xi, p.fn, k.overlap, true)) return;
  const double xi_dot = k.overlap_rate(), dt = k.dt;
  // where the unclipped force crossed zero: the law's parts now, or (a law that reports none
  // when clipped) the tangent of the last step
  const double s = nr.elastic != 0.0 || nr.damping != 0.0
                       ? tdem::grid::end_time(p.fn, nr.elastic + nr.damping * xi_dot, dt)
                       : tdem::grid::end_time(p.fn, p.fn + p.k * xi_dot * dt, dt);
  double fn_x, ft_x[3];
  gc_end_extra<M, E, S, TL, D>(k, prev, hsize, p, s, true, fn_x, ft_x);
  ccel += fn_x * k.rinv;
  for (int i = 0; i < 3; ++i) fs[i] += ft_x[i];
}

// A touching contact with grid_correction on (history update on) that needs more than the plain
// law: its first step (flags 0), or a corrected zero-force contact, whose clip is watched (its
// tangential block kept for the end). gc_needs tells; the plain steps run evaluate_contact.
// first: the contact did not touch at the last step (pair: its touch flag; wall: its flags slot
// is 0).
TDEM_KERNEL bool gc_needs(const LawCoeffs &c, int end, bool first, const double *shear, int hsize) {
  return first || ((end >= 0 ? end != 0 : ends_at_zero_force(c)) && gc_flags(shear, hsize) == tdem::grid::kFlagOn);
}
template <int M = -1, int E = -1, int S = -1, int TL = -1, int D = -1>
[[gnu::cold, gnu::noinline]] void gc_contact(const GcContact &k, double *shear, int hsize, double &ccel, double *fs,
                                             double *troll) {
  if (shear[hsize - 1] == 0.0) return gc_start<M, E, S, TL, D>(k, shear, hsize, ccel, fs, troll);
  const LawCoeffs &c = *k.c;
  const int nt = tangential_history_size(c.tlaw);
  double tang[tdem::mindlin_deresiewicz::history_size];
  std::memcpy(tang, shear, sizeof(double) * nt);
  tdem::NormalResult<double> nr{};
  evaluate_contact<M, E, S, TL, D>(c, k.meff, k.delx, k.dely, k.delz, k.r, k.rinv, k.rsqinv, k.overlap, k.vr[0],
                                   k.vr[1], k.vr[2], k.wr[0], k.wr[1], k.wr[2], k.dt, true, shear, ccel, fs, k.radi,
                                   k.radj, k.omega_i, k.omega_j, troll, &nr);
  if (!(ccel > 0.0)) gc_zero_force_end<M, E, S, TL, D>(k, shear, hsize, tang, nt, nr, ccel, fs);
}

// The first step without contact (k.overlap <= 0) of a corrected contact whose force has not
// ended: true and the extra force (ccel_x along del, fs_x). The caller then clears the history.
template <int M = -1, int E = -1, int S = -1, int TL = -1, int D = -1>
[[gnu::cold, gnu::noinline]] bool gc_separation(const GcContact &k, const double *shear, int hsize,
                                                        double &ccel_x, double *fs_x) {
  if (gc_flags(shear, hsize) != tdem::grid::kFlagOn) return false;
  const GcPrevious p = gc_previous<M, E, S, TL, D>(k, shear, hsize);
  if (!tdem::grid::end_usable(p.xi, p.fn, k.overlap, false)) return false;
  double fn_x;
  gc_end_extra<M, E, S, TL, D>(k, shear, hsize, p, tdem::grid::end_time(p.xi, k.overlap, k.dt), false, fn_x, fs_x);
  ccel_x = fn_x * k.rinv;
  return true;
}

}  // namespace tdem_lammps
