// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: a sphere-wall impact (normal + tangential + spin) integrated in whole steps with any scheme
// of src/integrators/schemes.h, exactly as a host engine does it, plus four multi-evaluation
// schemes that only the harness can run (physics_reference.md 5.1, 5.2, 8.6).
//
// Set-up. The wall is the plane z = 0, n = +z. The sphere (mass m, radius R, solid unless I is
// given) starts in free flight at z = R + gap with v = (|v| sin theta, 0, -|v| cos theta) and the
// scalar spin omega0 about a = -y (signs and result meanings as ObliqueResult of oblique.h:
// v_s = v_t + R omega, beta = -v_s'/v_s0, e_t = v_t'/v_t0, e = v_n'/v_n0).
//
// Forces (the same conventions as integrate_oblique with LeverArm::radius): at every evaluation the
// overlap is xi = R - z; contact iff xi > 0, or xi = 0 while approaching (a touch start, gap = 0:
// LAMMPS' wall/gran counts r = R as contact, and so does integrate_oblique). In contact the normal law
// object of head_on.h gives F_n(xi, xi' = -v_z) (update = true once per step, see below), the
// tangential law object of oblique.h gives F_t from the slip velocity v_t = tangential part of
// (v - R w x n); F = F_n n + F_t, torque T = -R n x F_t; a = F/m, alpha = T/I. Out of contact
// F = T = 0 and both laws are reset (the host erases the contact history on separation).
//
// One-evaluation schemes (every Scheme of schemes.h), per step h = dt, the host sequence
//     predict (initial_integrate) -> force evaluation -> correct (final_integrate)
// on the translation channel (x, v, a) and the rotation channel (no position, w, alpha). At t = 0
// the force is evaluated once (the host's set-up, tangential history not advanced; in free flight
// the force is zero, at a touch start it is the normal law at xi = 0, xi' = v_n0) and
// integrators::start<S, kPos>(x, v, a, hist, h) fills the histories from that acceleration alone.
// The tangential law advances its history once per step (update = true, dt = h) with the slip
// velocity of the evaluated (predicted) state, as a host pair style does.
//
// Multi-evaluation schemes (harness only; `F/step` force evaluations per step):
//   heun       (2) y~ = y + h f(y); y+ = y + h/2 (f(y) + f(y~)); f(y+) for the next step
//   rk4        (4) classical Runge-Kutta on y = (x, v, w); k1 = f(y_n) is the last evaluation of
//                  the previous step, stages at h/2, h/2, h, then f(y+)
//   vv2        (2) x+ = x + h v + h^2 a/2, v_p = v + h a; a_p = a(x+, v_p); v+ = v + h (a + a_p)/2;
//                  a(x+, v+) for the next step (velocity Verlet with a second evaluation)
//   abm4_pece  (2) AB4 predictor, evaluation, Adams-Moulton 4 corrector (9, 19, -5, 1)/24, second
//                  evaluation at the corrected state (PECE); start: constant acceleration
//                  (a(n-j) = a0, v(n-j) = v0 - j h a0), exact in free flight
// The last evaluation of a step (at y+) is the only one that commits law histories: the normal
// law is called with update = true only there, and the tangential history is advanced once, by
// h times the scheme's quadrature of the stage slip velocities (heun, vv2: trapezoid of the two
// evaluated states of the step; rk4: (1, 2, 2, 1)/6; abm4_pece: Adams-Moulton (9, 19, -5, 1)/24),
// then the force at y+ is taken with update = false. An intermediate stage evaluates a copy of the
// tangential law whose history is advanced as the scheme advances its state to that stage (by
// c h times the previous stage's slip velocity: RK stage rule; abm4: AB4 combination), never the
// law itself. Without a tangential dashpot this treats the spring elongation as one more
// integrated variable of the scheme.
//
// End of contact: the first whole step whose (final) evaluation has xi <= 0 after a step with
// xi > 0. The results are read after that step plus `flush_steps` (default 10) free-flight
// steps, when the multi-step histories (AB-k: k-1 steps, Gear-q: q-3 steps, ABM4: 3) no longer
// change v and w. contact_steps counts the steps whose final evaluation had xi > 0;
// contact_time = contact_steps * dt.
//
// phase_averaged() (collision/phase_average.h): the start phase of the contact relative to the
// time grid is varied over P phases, gap = gap0 + phi v_n0 dt with phi = (i + 1/2)/P, and the mean
// |error| of e, beta, e_t, spin and rebound angles against given reference values is returned
// (physics_reference 5.2 (B)).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision/head_on.h"
#include "collision/multi_eval.h"
#include "collision/oblique.h"
#include "contact/energy.h"
#include "contact/grid_correction.h"
#include "integrators/schemes.h"

namespace tdem {
namespace collision {

// Any scheme of the harness: one of schemes.h or one of the multi-evaluation schemes.
struct ImpactScheme {
  bool multi = false;
  integrators::Scheme one = integrators::Scheme::velocity_verlet;
  MultiScheme many = MultiScheme::rk4;
  const char* name() const { return multi ? info(many).name : integrators::info(one).name; }
  int evaluations() const { return multi ? info(many).evaluations : 1; }
  int order(bool damped) const {
    if (multi) return damped ? info(many).order_damped : info(many).order;
    return damped ? integrators::info(one).order_damped : integrators::info(one).order;
  }
  // doubles per particle beyond x, v, f, omega, torque (translation + rotation)
  int history() const { return multi ? info(many).history : integrators::history_per_particle(one, true); }
};

inline bool parse_impact_scheme(const std::string& name, ImpactScheme& out) {
  integrators::Scheme s;
  if (integrators::parse_scheme(name, s)) {
    out.multi = false;
    out.one = s;
    return true;
  }
  for (int i = 0; i < static_cast<int>(MultiScheme::count); ++i)
    if (name == info(static_cast<MultiScheme>(i)).name) {
      out.multi = true;
      out.many = static_cast<MultiScheme>(i);
      return true;
    }
  return false;
}

inline std::vector<ImpactScheme> all_impact_schemes() {
  std::vector<ImpactScheme> v;
  for (int i = 0; i < static_cast<int>(integrators::Scheme::count); ++i) {
    ImpactScheme s;
    s.one = static_cast<integrators::Scheme>(i);
    v.push_back(s);
  }
  for (int i = 0; i < static_cast<int>(MultiScheme::count); ++i) {
    ImpactScheme s;
    s.multi = true;
    s.many = static_cast<MultiScheme>(i);
    v.push_back(s);
  }
  return v;
}

inline std::string impact_scheme_names(const char* sep = "|") {
  std::string out;
  for (const auto& s : all_impact_schemes()) out += (out.empty() ? "" : sep) + std::string(s.name());
  return out;
}

// ---------------------------------------------------------------- set-up and result
struct ImpactSetup {
  double m = 0.0, R = 0.0, I = 0.0;  // I = 0: solid sphere 2/5 m R^2
  double speed = 0.0;                // |v| [m/s] > 0
  double angle = 0.0;                // theta from the normal [rad], [0, pi/2)
  double omega0 = 0.0;               // initial scalar spin [1/s]
  double gap = 0.0;                  // z(0) - R >= 0 [m]
};

struct ImpactOptions {
  double dt = 0.0;                 // fixed step [s]; 0: contact_time_estimate / steps_per_contact
  long steps_per_contact = 100;
  int flush_steps = 10;            // free-flight steps after the contact before reading the results
  bool record = false;             // keep a sample (ObliqueSample) of every evaluation in contact
  bool grid_correction = false;    // contact/grid_correction.h at the start and end steps (one-
                                   // evaluation schemes; the multi-evaluation ones ignore it)
  long max_steps = 100000000;      // give up (ended = false)
  double max_contact_times = 100.0;
  // lever arm of the tangential force c = R - lever_factor xi: 0 the radius (default), 0.5 the
  // contact point as LIGGGHTS's surface model (also in the slip velocity; at an end step, where xi
  // < 0, as LIGGGHTS computes it there)
  double lever_factor = 0.0;
  bool energy = false;             // account the work of each part of the contact force (contact/
                                   // energy.h; one-evaluation schemes)
};

struct ImpactResult : ObliqueResult {
  std::string scheme;
  double gap = 0.0;
  long contact_steps = 0;  // steps whose (final) evaluation was in contact
  // with grid_correction, for a corrected contact: end - touch, both times as the correction
  // estimated them (the touch tau before its first step, the end s after its last); NaN otherwise
  double contact_time_interpolated = NAN;
  long evaluations = 0;    // force evaluations in all
  // with ImpactOptions::energy: the work of each part of the contact force over the run (-W: taken
  // out of the motion); the balance K~ - K~(0) - W (energy.h) of every step: largest size, last value
  energy::Work<double> work;
  double energy_residual_max = NAN, energy_residual_end = NAN;
};

inline void validate(const ImpactSetup& s) {
  checks::positive("mass m", s.m);
  checks::positive("radius R", s.R);
  if (!(s.I >= 0.0) || !std::isfinite(s.I)) checks::fail("moment of inertia I", s.I, "[0, inf) (0: solid sphere)");
  checks::positive("impact speed |v|", s.speed);
  if (!(s.angle >= 0.0 && s.angle < 0.5 * M_PI))
    throw std::domain_error("impact angle theta = " + checks::number(s.angle * 180.0 / M_PI) +
                            " deg is outside the allowed range [0, 90) deg");
  if (!std::isfinite(s.omega0)) checks::fail("spin omega0", s.omega0, "(-inf, inf)");
  if (!(s.gap >= 0.0) || !std::isfinite(s.gap)) checks::fail("gap", s.gap, "[0, inf)");
}

// ---------------------------------------------------------------- the integrator
template <class NormalLaw, class TangentialLaw>
ImpactResult integrate_impact(NormalLaw& normal, TangentialLaw& tang, const ImpactScheme& scheme,
                              const ImpactSetup& setup, const ImpactOptions& opt = ImpactOptions()) {
  using impact_detail::Acc;
  using impact_detail::Y;
  validate(setup);
  if (!(opt.dt >= 0.0) || !std::isfinite(opt.dt)) checks::fail("time step dt", opt.dt, "[0, inf)");
  if (opt.dt == 0.0 && opt.steps_per_contact < 1) checks::fail("steps per contact", opt.steps_per_contact, "[1, inf)");
  if (opt.flush_steps < 0) checks::fail("flush steps", opt.flush_steps, "[0, inf)");
  const double m = setup.m, R = setup.R;
  const double I = setup.I > 0.0 ? setup.I : rigid_body::solid_sphere_inertia(m, R);
  normal.reset();
  tang.reset();

  ImpactResult r;
  r.scheme = scheme.name();
  r.gap = setup.gap;
  r.m_n = m;
  r.m_t = rigid_body::tangential_mass(m, R, I, INFINITY, INFINITY, INFINITY);
  r.vn0 = setup.speed * std::cos(setup.angle);
  r.vt0 = setup.speed * std::sin(setup.angle);
  r.omega1_0 = setup.omega0;
  r.vs0 = r.vt0 + R * r.omega1_0;
  r.impact_angle = std::atan2(r.vt0, r.vn0);
  r.impact_angle_contact = std::atan2(r.vs0, r.vn0);
  r.mu = tang.friction();
  r.contact_time_estimate = normal.contact_time_estimate(m, R, r.vn0);
  if (opt.dt == 0.0 && (!(r.contact_time_estimate > 0.0) || !std::isfinite(r.contact_time_estimate)))
    throw std::domain_error("estimated contact time = " + checks::number(r.contact_time_estimate) +
                            " is not a positive finite number; give a time step dt");
  const double h = opt.dt > 0.0 ? opt.dt : r.contact_time_estimate / static_cast<double>(opt.steps_per_contact);
  r.dt = h;
  const double t_free = setup.gap / r.vn0;
  const long max_steps =
      std::min(opt.max_steps, static_cast<long>((t_free + opt.max_contact_times * r.contact_time_estimate) / h) +
                                  opt.flush_steps + 100);

  // ---- force evaluation at state y. law: the tangential law object to use; incr_dt > 0 first
  // advances its history by incr_dt * vt_incr (update = true) and then takes the force with
  // update = false (commit = stage rule); incr_dt < 0: the host rule (one call, update = true,
  // dt = h, the slip velocity of y). commit_normal: the normal law's update flag.
  bool in_contact_prev = false;
  auto lever = [&](double xi) { return R - opt.lever_factor * xi; };
  auto geometry = [&](const Y& y, double& xi, double* vt) {
    xi = R - y.x()[2];
    // v_rel = v - c w x n, n = z: w x n = (w_y, -w_x, 0)
    const double* v = y.v();
    const double* w = y.w();
    const double c = lever(xi);
    vt[0] = v[0] - c * w[1];
    vt[1] = v[1] + c * w[0];
    vt[2] = 0.0;
  };
  struct Last {
    double xi = 0.0, xi_dot = 0.0, fn = 0.0, ft_t = 0.0, vs_t = 0.0;
    bool sliding = false, contact = false;
  } last;
  // grid correction (contact/grid_correction.h): whether the contact is corrected, and the last
  // contact step's overlap, normal force and stiffness, tangential force and sliding state as
  // reconstructed at an end (reconstruct_prev)
  struct GcPrev {
    double xi = 0.0, fn = 0.0, fe = 0.0, k = 0.0, ft[3] = {0.0, 0.0, 0.0};  // (fe: elastic part of fn)
    bool sliding = false;
    bool on = false;     // this contact is corrected (its start was seen and resolved)
    bool ended = false;  // its zero-force end has been corrected
  } gc_prev;
  // The normal law's two parts at (xi, xi_dot) and their exponents in xi (a second evaluation at
  // xi / 2): e = elastic, d = the rest (damping) of `f`.
  struct PowerParts {
    double e, p, d, q;
  };
  auto power_parts = [&](double xi, double xi_dot, double f, const NormalResult<double>& at) {
    const NormalResult<double> hf = normal.force(0.5 * xi, xi_dot, m, R, false);
    PowerParts pp;
    pp.e = at.elastic;
    pp.d = f - at.elastic;
    pp.p = grid::power_exponent(at.elastic, hf.elastic, 1.0);
    pp.q = grid::power_exponent(at.force - at.elastic, hf.force - hf.elastic, 0.0);
    return pp;
  };
  // The extra force (normal fn_out, tangential ft_out) of an end s after the previous step: the normal force from the power
  // model through gc_prev (zero_overlap, at_zero_force = false) or linear to zero (a zero-force
  // end), the tangential force linear from gc_prev.ft to the law's value at the end (its history
  // of the previous step advanced by v_t s, the normal force there fe).
  double gc_touch_time = NAN;
  // The last contact step's values, reconstructed at an end step (the host keeps none of them):
  // the overlap xi - h xi' (the rate now), the normal law there (its history that of the last
  // step) and the tangential law there with that normal force (its history before this step's
  // update, no update).
  auto reconstruct_prev = [&](const Y& y, const TangentialLaw& law_prev, double xi, double xi_dot) {
    gc_prev.xi = grid::previous_overlap(xi, xi_dot, h);
    const NormalResult<double> np = normal.force(gc_prev.xi, xi_dot, m, R, false);
    gc_prev.fn = np.force;
    gc_prev.fe = np.elastic;
    gc_prev.k = np.stiffness;
    double xi_now;
    TangentialKin kp;
    geometry(y, xi_now, kp.vt);
    kp.n[0] = 0.0, kp.n[1] = 0.0, kp.n[2] = 1.0;
    kp.spin_n = 0.5 * y.w()[2];
    kp.dt = h;
    kp.overlap = gc_prev.xi;
    kp.meff = m;
    kp.reff = R;
    kp.fn = np.force;
    kp.kn = np.stiffness;
    kp.gamman = np.damping;
    TangentialLaw copy = law_prev;
    copy.force(kp, false, gc_prev.ft);
    gc_prev.sliding = grid::sliding(gc_prev.ft[0] * gc_prev.ft[0] + gc_prev.ft[1] * gc_prev.ft[1] +
                                        gc_prev.ft[2] * gc_prev.ft[2],
                                    law_prev.friction(), gc_prev.fn);
  };
  // F = F_n n + F_t on the sphere and its torque -c n x F_t, n x F_t = (-F_t,y, F_t,x, 0); as
  // accelerations (to_acceleration), and by part for the energy accounting (set_loads)
  energy::Loads<double> loads;  // of the last evaluation, by part (opt.energy)
  auto load_of = [&](double fn, const double* ft, double xi) {
    energy::Load<double> l;
    const double c = lever(xi);
    l.f[0] = ft[0], l.f[1] = ft[1], l.f[2] = fn + ft[2];
    l.ti[0] = c * ft[1], l.ti[1] = -c * ft[0];
    return l;
  };
  auto set_loads = [&](double fe, double fn, const double* ft, double xi) {  // elastic fe of fn, F_t
    const double none[3] = {0.0, 0.0, 0.0};
    loads.part[energy::normal_elastic] = load_of(fe, none, xi);
    loads.part[energy::normal_damping] = load_of(fn - fe, none, xi);
    loads.part[energy::tangential] = load_of(0.0, ft, xi);
  };
  auto to_acceleration = [&](double fn, const double* ft, double xi, Acc& out) {
    const energy::Load<double> l = load_of(fn, ft, xi);
    for (int k = 0; k < 3; ++k) out.a[k] = l.f[k] / m, out.al[k] = l.ti[k] / I;
  };
  // (fe_out: the elastic part's share of fn_out, for the energy accounting: the power model's e-part,
  // linear in the parts; at a zero-force end in the proportion of the last step's parts)
  auto end_correction = [&](double& fe_out, const TangentialLaw& law, double xi_dot, double s, bool at_zero_force,
                            double& fn_out, double* ft_out) {
    if (std::isfinite(gc_touch_time) && !std::isfinite(r.contact_time_interpolated))
      r.contact_time_interpolated = r.steps * h + s - gc_touch_time;
    double fn_x, fe;
    if (at_zero_force) {
      fe = 0.0;
      fn_x = grid::end_extra(gc_prev.fn, gc_prev.fn, 1.0, 0.0, 0.0, s, h);
      fe_out = gc_prev.fn != 0.0 ? fn_x * gc_prev.fe / gc_prev.fn : 0.0;
    } else {
      const NormalResult<double> np = normal.force(gc_prev.xi, xi_dot, m, R, false);
      const PowerParts pp = power_parts(gc_prev.xi, xi_dot, gc_prev.fn, np);
      fe = normal.force(0.0, xi_dot, m, R, false).force;
      fn_x = grid::end_extra(gc_prev.fn, pp.e, pp.p, pp.d, pp.q, s, h);
      fe_out = grid::end_extra(pp.e, pp.e, pp.p, 0.0, pp.q, s, h);
    }
    // sliding: the tangential force follows the normal force (mu F_n); sticking: linear to the
    // last one capped by the limit at the end
    const double ft2 = gc_prev.ft[0] * gc_prev.ft[0] + gc_prev.ft[1] * gc_prev.ft[1] + gc_prev.ft[2] * gc_prev.ft[2];
    const double cap = grid::cap_factor(ft2, law.friction() * std::fabs(fe));
    double ft_x[3];
    for (int i = 0; i < 3; ++i) {
      const double fte = cap * gc_prev.ft[i];
      ft_x[i] = gc_prev.sliding ? gc_prev.ft[i] / gc_prev.fn * (fn_x + gc_prev.fn) - gc_prev.ft[i]
                                : grid::end_extra(gc_prev.ft[i], gc_prev.ft[i] - fte, 1.0, fte, 0.0, s, h);
    }
    fn_out = fn_x;
    for (int i = 0; i < 3; ++i) ft_out[i] = ft_x[i];
  };
  auto evaluate = [&](const Y& y, TangentialLaw& law, double incr_dt, const double* vt_incr, bool commit_normal,
                      Acc& out) {
    double xi;
    geometry(y, xi, out.vt);
    for (int k = 0; k < 3; ++k) out.a[k] = out.al[k] = 0.0;
    if (opt.energy) loads = energy::Loads<double>{};
    const double xi_dot = -y.v()[2];
    last.contact = xi > 0.0 || (xi == 0.0 && xi_dot > 0.0);
    const bool gc = opt.grid_correction && incr_dt < 0.0;
    if (!last.contact) {
      last.xi = xi, last.xi_dot = -y.v()[2], last.fn = 0.0, last.ft_t = 0.0, last.vs_t = out.vt[0];
      last.sliding = false;
      // (a zero-force law whose force ended before the overlap did has nothing left to correct)
      if (gc && in_contact_prev && gc_prev.on && !gc_prev.ended) {
        // the first step after a zero-overlap end: only the extra impulse of the end acts; the
        // law at the end is its value at xi = 0+ with the rate now (its history still that of
        // the last contact step)
        reconstruct_prev(y, law, xi, xi_dot);
        if (grid::end_usable(gc_prev.xi, gc_prev.fn, xi, false))
        {
          double fn_x, fe_x, ft_x[3];
          end_correction(fe_x, law, xi_dot, grid::end_time(gc_prev.xi, xi, h), false, fn_x, ft_x);
          to_acceleration(fn_x, ft_x, xi, out);
          if (opt.energy) set_loads(fe_x, fn_x, ft_x, xi);
        }
      }
      if (gc) gc_prev = GcPrev{};
      return false;
    }
    TangentialLaw fresh_or_prev = law;  // the tangential law before this step's update
    double tau = -1.0;
    NormalResult<double> half{}, touch{};
    if (gc && !in_contact_prev) {
      gc_prev.on = false;
      tau = grid::touch_age(xi, xi_dot, h);
      if (tau >= 0.0) {
        // the law at xi / 2 and at the touch (xi = 0+), before this step commits its history
        // (a hysteretic law would see xi / 2 as unloading after it)
        half = normal.force(0.5 * xi, xi_dot, m, R, false);
        touch = normal.force(0.0, xi_dot, m, R, false);
      }
    }
    const NormalResult<double> nr = normal.force(xi, xi_dot, m, R, commit_normal);
    double pe = 1.0;
    if (tau >= 0.0) {
      pe = grid::power_exponent(nr.elastic, half.elastic, 1.0);
      if (grid::resolved(nr.elastic, pe, nr.damping, xi, xi_dot, m, h)) gc_prev.on = true;
      else tau = -1.0;  // too coarse: this contact is not corrected
    }
    TangentialKin k;
    k.n[0] = 0.0, k.n[1] = 0.0, k.n[2] = 1.0;
    for (int i = 0; i < 3; ++i) k.vt[i] = out.vt[i];
    k.spin_n = 0.5 * y.w()[2];
    k.dt = tau >= 0.0 ? tau : h;  // corrected: the spring starts at the touch
    k.overlap = xi;
    k.meff = m;
    k.reff = R;
    k.fn = nr.force;
    k.kn = nr.stiffness;
    k.gamman = nr.damping;
    double ft[3] = {0.0, 0.0, 0.0};
    bool sliding;
    if (incr_dt < 0.0) {
      sliding = law.force(k, true, ft);
    } else {
      if (incr_dt > 0.0) {
        TangentialKin ki = k;
        for (int i = 0; i < 3; ++i) ki.vt[i] = vt_incr[i];
        ki.dt = incr_dt;
        double dummy[3];
        law.force(ki, true, dummy);
      }
      sliding = law.force(k, false, ft);
    }
    double fn_apply = nr.force, fe_apply = nr.elastic, ft_apply[3] = {ft[0], ft[1], ft[2]};
    if (gc) {
      if (tau >= 0.0) {
        // the start: the power model through the law now, from the touch tau ago; the
        // tangential force linear from the law at the touch (fresh history, the normal force
        // at xi = 0+) to the law now
        gc_touch_time = (r.steps + 1) * h - tau;
        const double pq = grid::power_exponent(nr.force - nr.elastic, half.force - half.elastic, 0.0);
        fn_apply = grid::start_force(nr.elastic, pe, nr.force - nr.elastic, pq, tau, h);
        if (opt.energy) fe_apply = grid::start_force(nr.elastic, pe, 0.0, pq, tau, h);  // (linear in the parts)
        TangentialKin k0 = k;
        k0.overlap = 0.0;
        k0.fn = touch.force;
        double ft0[3];
        fresh_or_prev.force(k0, false, ft0);
        const bool follows = grid::sliding(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2], law.friction(), nr.force);
        for (int i = 0; i < 3; ++i)
          ft_apply[i] = follows ? ft[i] / nr.force * fn_apply
                                : grid::start_force(ft[i] - ft0[i], 1.0, ft0[i], 0.0, tau, h);
      } else if (gc_prev.on && !gc_prev.ended && in_contact_prev && normal.end() == ContactEnd::zero_force &&
                 nr.force <= 0.0) {
        // a zero-force end inside the last step: where the unclipped force crossed zero (the
        // law's parts now; a law that reports none when clipped: the tangent of the last step)
        reconstruct_prev(y, fresh_or_prev, xi, xi_dot);
        gc_prev.ended = true;
        double s_end;
        if (nr.elastic != 0.0 || nr.damping != 0.0)
          s_end = grid::end_time(gc_prev.fn, nr.elastic + nr.damping * xi_dot, h);
        else
          s_end = grid::end_time(gc_prev.fn, gc_prev.fn + gc_prev.k * xi_dot * h, h);
        if (grid::end_usable(gc_prev.xi, gc_prev.fn, xi, true)) {
          double fn_x, fe_x, ft_x[3];
          end_correction(fe_x, fresh_or_prev, xi_dot, s_end, true, fn_x, ft_x);
          fn_apply += fn_x;
          fe_apply += fe_x;
          for (int i = 0; i < 3; ++i) ft_apply[i] += ft_x[i];
        }
      }
    }
    to_acceleration(fn_apply, ft_apply, xi, out);
    if (opt.energy) set_loads(fe_apply, fn_apply, ft_apply, xi);  // (the correction's extra in its parts)
    last.xi = xi, last.xi_dot = xi_dot, last.fn = nr.force, last.ft_t = ft[0], last.vs_t = out.vt[0];
    last.sliding = sliding;
    return true;
  };
  // After the final evaluation of a step: bookkeeping, reset on separation. Returns true when the
  // run is over.
  long flush_left = -1;
  bool switched_state = false;
  auto record_sample = [&](double t) {
    if (opt.record) r.samples.push_back({t, last.xi, last.xi_dot, last.fn, last.ft_t, last.vs_t, last.sliding});
  };
  auto after_step = [&]() {
    ++r.steps;
    if (last.contact) record_sample(r.steps * h);
    if (last.contact) {
      if (!in_contact_prev && r.contact_steps == 0) {
        r.sliding_at_start = last.sliding;
        switched_state = last.sliding;
      } else if (last.sliding != switched_state) {
        switched_state = last.sliding;
        if (static_cast<int>(r.switches.size()) < 1000) r.switches.push_back({r.steps * h, last.sliding});
        ++r.n_switches;
      }
      ++r.contact_steps;
      r.max_overlap = std::max(r.max_overlap, last.xi);
      r.max_normal_force = std::max(r.max_normal_force, last.fn);
      r.max_tangential_force = std::max(r.max_tangential_force, std::fabs(last.ft_t));
    } else {
      if (in_contact_prev) {  // separation
        normal.reset();
        tang.reset();
        if (flush_left < 0) flush_left = opt.flush_steps;
      }
    }
    in_contact_prev = last.contact;
    if (flush_left >= 0) {
      if (flush_left == 0) return true;
      --flush_left;
    }
    return false;
  };

  Y y;
  y.x()[2] = R + setup.gap;
  y.v()[0] = r.vt0;
  y.v()[2] = -r.vn0;
  y.w()[1] = -setup.omega0;  // omega . a with a = -y
  const double ke0 = 0.5 * m * (r.vt0 * r.vt0 + r.vn0 * r.vn0) + 0.5 * I * setup.omega0 * setup.omega0;

  // t = 0: the set-up evaluation (the host's: the tangential history is not advanced; the normal
  // law commits, so that the extended laws take v0 at a touch start; counts as an evaluation)
  Acc acc;
  evaluate(y, tang, 0.0, nullptr, true, acc);
  in_contact_prev = last.contact;
  if (last.contact) {
    r.sliding_at_start = switched_state = last.sliding;
    record_sample(0.0);
  }
  r.evaluations = 1;
  bool done = false;
  bool finite = true;

  if (!scheme.multi) {
    integrators::dispatch(scheme.one, [&](auto tag) {
      constexpr integrators::Scheme S = decltype(tag)::value;
      using KT = integrators::Kernel<S, true>;
      using KR = integrators::Kernel<S, false>;
      double ht[KT::history > 0 ? KT::history : 1] = {0.0};
      double hr[KR::history > 0 ? KR::history : 1] = {0.0};
      integrators::start<S, true>(y.x(), y.v(), acc.a, ht, h);
      integrators::start<S, false>(nullptr, y.w(), acc.al, hr, h);
      // the energy balance (opt.energy): the scheme's K~ and drift (velocity Verlet's for the others)
      const auto form = static_cast<energy::Form>(std::max(integrators::energy_form(S), 0));
      auto ktilde = [&]() { return energy::kinetic(form, m, I, y.v(), y.w(), acc.a, acc.al, h); };
      const double kt0 = ktilde();
      energy::Loads<double> before = loads;
      if (opt.energy) r.energy_residual_max = 0.0;
      while (!done && r.steps < max_steps) {
        const energy::Motion<double> d = energy::drift(form, y.v(), y.w(), acc.a, acc.al, h);
        KT::predict(y.x(), y.v(), acc.a, ht, h);
        KR::predict(nullptr, y.w(), acc.al, hr, h);
        evaluate(y, tang, -1.0, nullptr, true, acc);
        ++r.evaluations;
        KT::correct(y.x(), y.v(), acc.a, ht, h);
        KR::correct(nullptr, y.w(), acc.al, hr, h);
        if (opt.energy) {
          energy::accumulate(r.work, before, loads, d);
          before = loads;
          r.energy_residual_end = ktilde() - kt0 - r.work.total();
          r.energy_residual_max = std::max(r.energy_residual_max, std::fabs(r.energy_residual_end));
        }
        if (!std::isfinite(y.v()[2]) || !std::isfinite(y.x()[2])) {
          finite = false;
          break;
        }
        done = after_step();
      }
      return 0;
    });
  } else {
    MultiState st;
    multi_start(st, y, acc, h);
    while (!done && r.steps < max_steps) {
      double vt_avg[3];
      r.evaluations += multi_step(scheme.many, y, acc, st, h, [&](const Y& ys, double incr_dt, const double* vt_incr, Acc& out) {
        TangentialLaw trial = tang;
        evaluate(ys, trial, incr_dt, vt_incr, false, out);
      }, vt_avg);
      // the final evaluation of the step: commits the histories
      evaluate(y, tang, h, vt_avg, true, acc);
      ++r.evaluations;
      if (!std::isfinite(y.v()[2]) || !std::isfinite(y.x()[2])) {
        finite = false;
        break;
      }
      done = after_step();
    }
  }
  if (!done || !finite) return r;

  r.ended = true;
  r.contact_time = r.contact_steps * h;
  r.vn = y.v()[2];
  r.vt = y.v()[0];
  r.omega1 = -y.w()[1];
  r.omega2 = 0.0;
  r.vs = r.vt + R * r.omega1;
  r.residual_overlap = 0.0;
  const double ke1 = 0.5 * m * (y.v()[0] * y.v()[0] + y.v()[1] * y.v()[1] + y.v()[2] * y.v()[2]) +
                     0.5 * I * (y.w()[0] * y.w()[0] + y.w()[1] * y.w()[1] + y.w()[2] * y.w()[2]);
  r.dissipated_energy = ke0 - ke1;
  set_ratios(r);
  return r;
}

}  // namespace collision
}  // namespace tdem
