// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: closed-form (event-driven, no time stepping) solution of the oblique impact of a sphere on
// a wall or of two spheres with the linear spring-dashpot normal law and the Cundall-Strack
// tangential spring (constant k_t, Coulomb limit, optional tangential dashpot gamma_t, the spring
// reset of cundall_strack.h on sliding): physics_reference.md section 4. Independent of the
// integrator of oblique.h.
//
// Signs as in oblique.h / rigid_body.h: n from sphere 2 (the wall) to sphere 1, v_n0 > 0 the
// approach speed -(v1 - v2).n, v_t0 = (v1 - v2).t the tangential relative velocity of the centres,
// scalar spins omega_i with the slip velocity v_s = v_t + R1 omega_1 + R2 omega_2 (no R2 term on a
// wall; 0 for rolling). J is the tangential impulse on sphere 1 (sphere 2 gets -J):
//   v_t = v_t0 + J/m_n,  omega_i = omega_i0 + R_i J/I_i,  v_s = v_s0 + J/m_t,
//   1/m_n = 1/m1 + 1/m2,  1/m_t = 1/m1 + 1/m2 + R1^2/I1 + R2^2/I2
// (a wall: m2 = I2 = inf, m_n = m, m_t = 2/7 m for a solid sphere; two equal solid spheres m_n = m/2,
// m_t = m/7). The CoM velocities of both spheres follow from the impulses J_n n + J t on sphere 1
// and -(J_n n + J t) on sphere 2. The contact frame (n, t) is fixed: the turning of the line of
// centres of two spheres during the contact (an angle ~ v_t0 t_c/(R1 + R2)) is neglected, as in
// the reduced two-body problem of physics_reference 3.4 and 4.
//
// Normal motion (underdamped, delta = gamma_n/(2 m_n) < omega0 = sqrt(k_n/m_n)):
//   xi(t) = v_n0/w e^{-delta t} sin(w t),  w = sqrt(omega0^2 - delta^2),
//   F_n(t) = k_n xi + gamma_n xi',   int_0^t F_n = m_n (v_n0 - xi'(t)).
// End of contact: ContactEnd::zero_overlap at w t = pi (F_n < 0 in the tail: attraction);
// ContactEnd::zero_force where k_n xi + gamma_n xi' = 0 (closed form, w t = pi - atan2(gamma_n w,
// k_n - gamma_n delta)). The Coulomb limit L(t) = mu |F_n| (FrictionLimit::absolute) or
// mu max(F_n, 0) (FrictionLimit::positive_normal); the two differ only in the attractive tail.
//
// Tangential phases (s: spring elongation; the force on sphere 1 is F_t = m_t dv_s/dt):
//   stick: F_t = -k_t s - gamma_t v_s, s' = v_s: the damped oscillator m_t s'' + gamma_t s' + k_t s = 0
//          (w_t0 = sqrt(k_t/m_t), d_t = gamma_t/(2 m_t); under-, critically or over-damped), from the
//          state (s_a, v_a) at the phase start;
//   slip:  F_t = -sigma L(t), J(t) = J_a - sigma (Lambda(t) - Lambda(t_a)), Lambda = int L dt in closed
//          form; the spring is reset every instant (cundall_strack::SlipRule):
//            spring_cap (LIGGGHTS `tangential history`, the default): the spring alone is tested,
//              k_t|s| > L -> s = sigma L/k_t, the dashpot is off while sliding;
//            spring_dashpot_cap (LAMMPS gran/hooke/history): the whole force is capped,
//              |k_t s + gamma_t v_s| > L -> s = (sigma L - gamma_t v_s)/k_t.
// Switching: stick -> slip at the first root of h = L(t) - |T(t)| with the trial force T = k_t s
// (spring_cap) or k_t s + gamma_t v_s (spring_dashpot_cap), sigma = sign(T); slip -> stick at the
// first root of g = sigma v_s(t) - (L'(t) + c gamma_t L(t)/m_t)/k_t, c = 0 (spring_cap) or 1
// (spring_dashpot_cap): the reset spring would start to shorten faster than the cap does (the
// kernel then holds it).
// Held at the cap (Mode::hold, spring_cap with gamma_t > 0 only): at a slip -> stick switch the
// force jumps from -sigma L to -sigma L - gamma_t v_s. If the limit is falling there (L' < 0) and
// q = L'' + k_t L/m_t < -gamma_t L'/m_t, neither state persists (stick would break the cap at
// once, slip would stop at once: a step-by-step integration alternates every step). The solution
// is the one with the spring held at the cap, s = sigma L/k_t, s' = v_s = sigma L'/k_t (a
// Filippov sliding mode), the force m_t sigma L''/k_t lying between the two; it ends in stick when
// q >= -gamma_t L'/m_t, in slip when q < 0. With spring_dashpot_cap the force is continuous at the
// switches and this does not occur.
// Roots: a scan of the closed forms on a grid of contact_time/scan_points, then bisection of the
// bracket to ~1e-15 of the contact time. At t = 0 and at the zero of F_n (zero_overlap end: the
// kink of L) the state is decided from the limit: sliding if |T| is at the limit and g(t+) > 0. A
// pair of roots closer together than one grid interval (a phase shorter than
// contact_time/scan_points) is not seen.
//
// The motion during the contact (normal and tangential, contact point and centres) is available
// through sample(input, output, t) from the phases kept in Output::phases.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/kinematics.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/input_checks.h"
#include "contact/tangential/common.h"
#include "contact/tangential/cundall_strack.h"

namespace tdem {
namespace collision {
namespace analytic {

struct Input {
  double m = 0.0;      // sphere (1) mass [kg]
  double R = 0.0;      // radius [m]
  double I = 0.0;      // moment of inertia [kg m^2]; 0: solid sphere 2/5 m R^2
  double kn = 0.0;     // normal stiffness [N/m]
  double gn = 0.0;     // normal damping [kg/s], below critical 2 sqrt(kn m_n)
  double kt = 0.0;     // tangential stiffness [N/m]
  double mu = 0.0;     // Coulomb coefficient
  ContactEnd end = ContactEnd::zero_force;
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  double vn0 = 0.0;     // approach speed > 0 (relative to sphere 2)
  double vt0 = 0.0;     // tangential CoM velocity (relative to sphere 2)
  double omega0 = 0.0;  // initial spin of sphere 1
  int scan_points = 4000;  // grid for bracketing the switching roots (per contact time)
  int max_switches = 10000;
  // Sphere 2: m2 = inf is a plane wall (then R2, I2, omega2 and the velocity of sphere 2 do not
  // enter). I2 = 0: solid sphere 2/5 m2 R2^2.
  double m2 = INFINITY, R2 = INFINITY, I2 = 0.0;
  double omega2 = 0.0;
  double v2n0 = 0.0, v2t0 = 0.0;  // CoM velocity of sphere 2 along n and t (sphere 1: v2 + relative)
  // Tangential dashpot [kg/s] and the spring reset on sliding (see the header).
  double gt = 0.0;
  cundall_strack::SlipRule rule = cundall_strack::SlipRule::spring_cap;
};

// Tangential state of a phase: stick, slip, or held at the cap (see the header).
enum class Mode { stick, slip, hold };

inline const char* to_string(Mode m) {
  return m == Mode::stick ? "stick" : (m == Mode::slip ? "slip" : "hold");
}

struct Switch {
  double t;      // time of the switch [s]
  bool sliding;  // the new state (false for Mode::hold: the spring follows the contact point)
  Mode mode = Mode::stick;
};

// One phase [ta, tb] of the tangential motion and its start state.
struct Phase {
  double ta, tb;
  Mode mode;
  double sigma;  // slip, hold: sign of the spring force
  double Ja;     // tangential impulse at ta
  double sa;     // spring at ta
};

struct Output {
  double m_t = 0.0, vs0 = 0.0;
  double contact_time = 0.0;
  double t_zero_force = NAN;  // zero of F_n (end for zero_force; start of attraction for zero_overlap)
  double e = 0.0, vn = 0.0;   // restitution and rebound normal speed (relative)
  double jt = 0.0;            // tangential impulse on sphere 1
  double vt = 0.0, omega = 0.0, vs = 0.0;  // relative tangential CoM velocity, spin of sphere 1, slip
  double beta = NAN, e_t = NAN;            // -v_s'/v_s0, v_t'/v_t0 (relative)
  double rebound_angle_com = 0.0, rebound_angle_contact = 0.0;  // [rad]
  double slip_ratio_in = NAN, slip_ratio_out = NAN;            // v_s/(mu v_n0)
  bool sliding_at_start = false;
  bool sliding_at_end = false;
  std::vector<Switch> switches;
  // two spheres
  double m_n = 0.0;                  // normal effective mass
  double jn = 0.0;                   // normal impulse on sphere 1
  double omega2 = 0.0;               // spin of sphere 2 after (0 for a wall)
  double v1n = 0.0, v1t = 0.0;       // CoM velocity of sphere 1 after, along n and t
  double v2n = 0.0, v2t = 0.0;       // CoM velocity of sphere 2 after (its initial one for a wall)
  Mode mode_at_start = Mode::stick, mode_at_end = Mode::stick;
  std::vector<Phase> phases;
};

inline bool is_wall(const Input& in) { return in.m2 == INFINITY; }

inline double inertia1(const Input& in) { return in.I > 0.0 ? in.I : 0.4 * in.m * in.R * in.R; }
inline double inertia2(const Input& in) {
  if (is_wall(in)) return INFINITY;
  return in.I2 > 0.0 ? in.I2 : 0.4 * in.m2 * in.R2 * in.R2;
}
inline double normal_mass(const Input& in) { return is_wall(in) ? in.m : 1.0 / (1.0 / in.m + 1.0 / in.m2); }
inline double tangential_mass(const Input& in) {
  double inv = 1.0 / in.m + in.R * in.R / inertia1(in);
  if (!is_wall(in)) {
    inv += 1.0 / in.m2;
    const double I2 = inertia2(in);
    if (std::isfinite(I2)) inv += in.R2 * in.R2 / I2;
  }
  return 1.0 / inv;
}

inline void validate(const Input& in) {
  checks::positive("mass m", in.m);
  checks::positive("radius R", in.R);
  checks::non_negative("moment of inertia I (0: solid sphere)", in.I);
  if (!is_wall(in)) {
    checks::positive("mass m2 (inf: a wall)", in.m2);
    checks::positive("radius R2", in.R2);
    if (!(in.I2 >= 0.0)) checks::fail("moment of inertia I2", in.I2, "[0, inf] (0: solid sphere)");
    if (!std::isfinite(in.omega2)) checks::fail("spin omega2", in.omega2, "(-inf, inf)");
    if (!std::isfinite(in.v2n0)) checks::fail("velocity of sphere 2 v2n0", in.v2n0, "(-inf, inf)");
    if (!std::isfinite(in.v2t0)) checks::fail("velocity of sphere 2 v2t0", in.v2t0, "(-inf, inf)");
  }
  checks::positive("normal stiffness k_n", in.kn);
  checks::non_negative("normal damping gamma_n", in.gn);
  const double crit = 2.0 * std::sqrt(in.kn * normal_mass(in));
  if (!(in.gn < crit)) {
    const std::string range = "[0, " + checks::number(crit) + ") (underdamped: below 2 sqrt(k_n m_n))";
    checks::fail("normal damping gamma_n", in.gn, range.c_str());
  }
  checks::positive("tangential stiffness k_t", in.kt);
  checks::non_negative("tangential damping gamma_t", in.gt);
  checks::non_negative("friction coefficient mu", in.mu);
  checks::positive("approach speed v_n0", in.vn0);
  if (!std::isfinite(in.vt0)) checks::fail("tangential velocity v_t0", in.vt0, "(-inf, inf)");
  if (!std::isfinite(in.omega0)) checks::fail("spin omega0", in.omega0, "(-inf, inf)");
  if (in.scan_points < 10) checks::fail("scan points", in.scan_points, "[10, inf)");
}

// The closed-form normal motion.
struct Normal {
  double m, k, g, v0, delta, w;
  double t_zero;  // zero of F_n after the start
  double t_end;
  bool attraction;  // zero_overlap end: F_n < 0 on (t_zero, t_end)
  bool absolute;    // limit mu |F_n| (else mu max(F_n, 0))
  double mu;

  double xi(double t) const { return v0 / w * std::exp(-delta * t) * std::sin(w * t); }
  double xi_dot(double t) const {
    return v0 * std::exp(-delta * t) * (std::cos(w * t) - delta / w * std::sin(w * t));
  }
  double fn(double t) const { return k * xi(t) + g * xi_dot(t); }
  double fn_dot(double t) const { return k * xi_dot(t) - g * fn(t) / m; }
  double fn_ddot(double t) const { return -(k * fn(t) + g * fn_dot(t)) / m; }
  double impulse(double t) const { return m * (v0 - xi_dot(t)); }  // int_0^t F_n
  // Coulomb limit, its derivatives and its integral from 0. At the zero of F_n (the kink of the
  // limit with the zero_overlap end) left = true takes the value before, else the one after.
  bool before_zero(double t, bool left) const { return !attraction || t < t_zero || (left && t <= t_zero); }
  double limit(double t, bool left = false) const {
    const double f = fn(t);
    if (before_zero(t, left)) return mu * std::max(f, 0.0);
    return absolute ? mu * std::fabs(f) : 0.0;
  }
  double limit_dot(double t, bool left = false) const {
    if (before_zero(t, left)) return mu * fn_dot(t);
    return absolute ? -mu * fn_dot(t) : 0.0;
  }
  double limit_ddot(double t, bool left = false) const {
    if (before_zero(t, left)) return mu * fn_ddot(t);
    return absolute ? -mu * fn_ddot(t) : 0.0;
  }
  double limit_integral(double t) const {
    if (t <= t_zero || !attraction) return mu * impulse(t);
    const double pz = impulse(t_zero);
    return absolute ? mu * (2.0 * pz - impulse(t)) : mu * pz;
  }
};

inline Normal make_normal(const Input& in) {
  Normal n;
  n.m = normal_mass(in), n.k = in.kn, n.g = in.gn, n.v0 = in.vn0, n.mu = in.mu;
  n.delta = in.gn / (2.0 * n.m);
  n.w = std::sqrt(in.kn / n.m - n.delta * n.delta);
  // F_n = v0 e^{-delta t} [((k - g delta)/w) sin(wt) + g cos(wt)]: zero at wt = pi - atan2(g w, k - g delta)
  n.t_zero = (M_PI - std::atan2(in.gn * n.w, in.kn - in.gn * n.delta)) / n.w;
  n.attraction = in.end == ContactEnd::zero_overlap;
  n.t_end = n.attraction ? M_PI / n.w : n.t_zero;
  n.absolute = in.limit == tangential::FrictionLimit::absolute;
  return n;
}

// The closed-form tangential phases (given the normal motion).
struct Tangential {
  const Normal* nrm;
  double mt, kt, gt, vs0;
  bool dash_cap;  // SlipRule::spring_dashpot_cap
  double w0, d, wd2, wd;  // stick oscillator: sqrt(k_t/m_t), gamma_t/(2 m_t), w0^2 - d^2, sqrt(|wd2|)

  Tangential(const Normal& n, const Input& in, double m_t) : nrm(&n), mt(m_t), kt(in.kt), gt(in.gt) {
    vs0 = in.vt0 + in.R * in.omega0;
    if (!is_wall(in) && std::isfinite(inertia2(in))) vs0 += in.R2 * in.omega2;
    dash_cap = in.rule == cundall_strack::SlipRule::spring_dashpot_cap;
    w0 = std::sqrt(kt / mt);
    d = gt / (2.0 * mt);
    wd2 = w0 * w0 - d * d;
    wd = gt == 0.0 ? w0 : std::sqrt(std::fabs(wd2));
  }
  double v_at_J(double J) const { return vs0 + J / mt; }
  // stick from (sa, va) after the time x
  void stick(double x, double sa, double va, double& s, double& v) const {
    if (gt == 0.0) {
      const double c = std::cos(w0 * x), sn = std::sin(w0 * x);
      s = sa * c + va / w0 * sn;
      v = -sa * w0 * sn + va * c;
      return;
    }
    double ec, es;  // e^{-d x} C(x), e^{-d x} S(x) with S = sin(wd x)/wd, x, sinh(wd x)/wd
    if (wd2 > 0.0) {
      const double e = std::exp(-d * x);
      ec = e * std::cos(wd * x);
      es = e * std::sin(wd * x) / wd;
    } else if (wd2 == 0.0) {
      const double e = std::exp(-d * x);
      ec = e;
      es = e * x;
    } else {  // overdamped: e^{-dx} cosh = (e^{-(d-wd)x} + e^{-(d+wd)x})/2, d - wd = w0^2/(d + wd)
      const double slow = std::exp(-w0 * w0 / (d + wd) * x), fast = std::exp(-(d + wd) * x);
      ec = 0.5 * (slow + fast);
      es = 0.5 * (slow - fast) / wd;
    }
    s = sa * ec + (va + d * sa) * es;
    v = va * ec - (w0 * w0 * sa + d * va) * es;
  }
  // the trial force whose magnitude is tested against the limit
  double trial(double s, double v) const { return kt * s + (dash_cap ? gt * v : 0.0); }
  // the spring reset to the cap while sliding
  double reset_spring(double sigma, double L, double v) const {
    return dash_cap ? (sigma * L - gt * v) / kt : sigma * L / kt;
  }
  // g of the header (slip persists while g > 0)
  double slip_g(double sigma, double v, double t, bool left) const {
    const double Ld = nrm->limit_dot(t, left);
    if (!dash_cap) return sigma * v - Ld / kt;
    return sigma * v - (Ld + gt * nrm->limit(t, left) / mt) / kt;
  }
  // held at the cap: q = L'' + k_t L/m_t; stays while 0 <= q < -gamma_t L'/m_t
  double hold_q(double t, bool left) const { return nrm->limit_ddot(t, left) + kt * nrm->limit(t, left) / mt; }
  bool stick_holds_after_slip(double t) const {  // h'' >= 0 in stick after a slip -> stick switch
    if (dash_cap || gt == 0.0) return true;
    return hold_q(t, false) + gt * nrm->limit_dot(t, false) / mt >= 0.0;
  }
};

namespace detail {
// First t in (a, b] where f(t) <= 0, given f > 0 just after a: grid scan, then bisection.
// Returns NAN if none.
template <class F>
double first_root(F f, double a, double b, double step) {
  if (!(b > a)) return NAN;
  const int n = std::max(1, static_cast<int>(std::ceil((b - a) / step)));
  double lo = a;
  for (int i = 1; i <= n; ++i) {
    const double hi = i == n ? b : a + (b - a) * i / n;
    if (f(hi) <= 0.0) {
      double l = lo, h = hi;
      for (int it = 0; it < 200 && h - l > 1e-15 * (b > 0 ? b : 1.0); ++it) {
        const double mid = 0.5 * (l + h);
        if (f(mid) <= 0.0) h = mid; else l = mid;
      }
      return h;
    }
    lo = hi;
  }
  return NAN;
}
inline double sgn(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }
}  // namespace detail

inline Output impact(const Input& in) {
  validate(in);
  const bool wall = is_wall(in);
  const double I1 = inertia1(in), I2 = inertia2(in);
  const Normal nrm = make_normal(in);
  Output o;
  o.m_n = nrm.m;
  o.m_t = tangential_mass(in);
  const Tangential tg(nrm, in, o.m_t);
  o.vs0 = tg.vs0;
  o.contact_time = nrm.t_end;
  o.t_zero_force = nrm.t_zero;
  const double mt = o.m_t, kt = in.kt, vs0 = o.vs0;
  const double step = nrm.t_end / in.scan_points;

  // Phase state at its start t_a: impulse J_a, spring s_a, and for slip and hold the sign sigma.
  double ta = 0.0, Ja = 0.0, sa = 0.0, sigma = 0.0;
  Mode mode = Mode::stick;

  auto stick_at = [&](double t, double va, double& s, double& v) { tg.stick(t - ta, sa, va, s, v); };
  auto slip_J = [&](double t) { return Ja - sigma * (nrm.limit_integral(t) - nrm.limit_integral(ta)); };
  auto hold_J = [&](double t, bool left) { return mt * (sigma * nrm.limit_dot(t, left) / kt - vs0); };
  auto begin_phase = [&](Mode m) {
    if (!o.phases.empty()) o.phases.back().tb = ta;
    o.phases.push_back({ta, NAN, m, sigma, Ja, sa});
  };
  auto switch_to = [&](Mode m) {
    if (m != mode) o.switches.push_back({ta, m == Mode::slip, m});
    mode = m;
    begin_phase(m);
  };

  // Decide the state at t with spring s and slip velocity v (t = 0 and the kink of L). at_cap: the
  // spring comes from a slip phase with the sign sigma (reset to the cap by construction).
  auto decide = [&](double t, double& s, double v, bool at_cap) {
    const double L = nrm.limit(t);
    if (!at_cap && std::fabs(tg.trial(s, v)) < L * (1.0 - 1e-12)) return false;
    double sg = at_cap ? sigma : detail::sgn(tg.trial(s, v));
    s = tg.reset_spring(sg, L, v);  // truncate
    if (sg * L == 0.0) {
      sg = detail::sgn(v);
      s = tg.reset_spring(sg, L, v);
    }
    if (sg != 0.0 && tg.slip_g(sg, v, t, false) > 0.0) {
      sigma = sg;
      return true;
    }
    return false;
  };

  // the kink of the limit (attractive tail) is a breakpoint
  std::vector<double> breaks;
  if (nrm.attraction && nrm.t_zero < nrm.t_end) breaks.push_back(nrm.t_zero);
  breaks.push_back(nrm.t_end);

  mode = decide(0.0, sa, vs0, false) ? Mode::slip : Mode::stick;
  o.sliding_at_start = mode == Mode::slip;
  o.mode_at_start = mode;
  if (vs0 == 0.0 && sa == 0.0) mode = Mode::stick;  // nothing to do: no tangential motion at all
  begin_phase(mode);
  size_t bi = 0;
  int nsw = 0;
  double J_end = 0.0;
  // At a breakpoint tb reached in the current phase with the state (J, s, v): the end, or the
  // decision of the state after the kink.
  auto at_break = [&](double tb, double J, double s, double v) {
    if (bi + 1 == breaks.size()) {
      J_end = J;
      return true;
    }
    ta = tb, Ja = J, sa = s;
    ++bi;
    const bool sl = decide(ta, sa, v, mode != Mode::stick);
    switch_to(sl ? Mode::slip : Mode::stick);
    return false;
  };
  // A root at the breakpoint itself (a tangency there, e.g. T and L both proportional to F_n) is
  // left to the decision at the breakpoint.
  auto root = [&](auto f, double tb) {
    const double tr = detail::first_root(f, ta, tb, step);
    return tr >= tb - 1e-12 * nrm.t_end ? NAN : tr;
  };
  while (true) {
    const double tb = breaks[bi];
    if (mode == Mode::stick) {
      const double va = tg.v_at_J(Ja);
      auto h = [&](double t) {
        double s, v;
        stick_at(t, va, s, v);
        return nrm.limit(t, true) - std::fabs(tg.trial(s, v));
      };
      double tr = NAN;
      if (!(va == 0.0 && sa == 0.0)) tr = root(h, tb);
      if (std::isnan(tr)) {  // to the breakpoint in stick
        double s, v;
        stick_at(tb, va, s, v);
        if (at_break(tb, mt * (v - vs0), s, v)) break;
        continue;
      }
      double s, v;
      stick_at(tr, va, s, v);
      sigma = detail::sgn(tg.trial(s, v));
      Ja = mt * (v - vs0);
      ta = tr;
      sa = tg.reset_spring(sigma, nrm.limit(tr), v);
      switch_to(Mode::slip);
    } else if (mode == Mode::slip) {
      auto g = [&](double t) { return tg.slip_g(sigma, tg.v_at_J(slip_J(t)), t, true); };
      const double tr = root(g, tb);
      if (std::isnan(tr)) {
        const double J = slip_J(tb);
        const double v = tg.v_at_J(J);
        if (at_break(tb, J, tg.reset_spring(sigma, nrm.limit(tb), v), v)) break;
        continue;
      }
      Ja = slip_J(tr);
      sa = tg.reset_spring(sigma, nrm.limit(tr), tg.v_at_J(Ja));
      ta = tr;
      switch_to(tg.stick_holds_after_slip(tr) ? Mode::stick : Mode::hold);
    } else {  // hold: s = sigma L/k_t, v_s = sigma L'/k_t until q < 0 (slip) or stick holds
      auto f = [&](double t) {
        const double q = tg.hold_q(t, true);
        return std::min(q, -(q + in.gt * nrm.limit_dot(t, true) / mt));
      };
      const double tr = root(f, tb);
      if (std::isnan(tr)) {
        const double J = hold_J(tb, true);
        if (at_break(tb, J, sigma * nrm.limit(tb) / kt, tg.v_at_J(J))) break;
        continue;
      }
      Ja = hold_J(tr, false);
      sa = sigma * nrm.limit(tr) / kt;
      ta = tr;
      switch_to(tg.hold_q(tr, false) < 0.0 ? Mode::slip : Mode::stick);
    }
    if (++nsw > in.max_switches)
      throw std::runtime_error("analytic oblique impact: more than " + std::to_string(in.max_switches) +
                               " stick/slip switches (chattering); last at t = " + checks::number(ta));
  }
  o.phases.back().tb = nrm.t_end;
  o.sliding_at_end = mode == Mode::slip;
  o.mode_at_end = mode;
  o.jt = J_end;
  o.vn = -nrm.xi_dot(nrm.t_end);
  o.e = o.vn / in.vn0;
  o.jn = nrm.m * (in.vn0 + o.vn);
  o.vt = in.vt0 + J_end / nrm.m;
  o.omega = in.omega0 + in.R * J_end / I1;
  o.vs = o.vt + in.R * o.omega;
  if (!wall && std::isfinite(I2)) {
    o.omega2 = in.omega2 + in.R2 * J_end / I2;
    o.vs += in.R2 * o.omega2;
  }
  const double v2n0 = wall ? 0.0 : in.v2n0, v2t0 = wall ? 0.0 : in.v2t0;
  o.v1n = v2n0 - in.vn0 + o.jn / in.m;
  o.v1t = v2t0 + in.vt0 + J_end / in.m;
  o.v2n = wall ? 0.0 : v2n0 - o.jn / in.m2;
  o.v2t = wall ? 0.0 : v2t0 - J_end / in.m2;
  o.beta = vs0 != 0.0 ? -o.vs / vs0 : NAN;
  o.e_t = in.vt0 != 0.0 ? o.vt / in.vt0 : NAN;
  o.rebound_angle_com = std::atan2(o.vt, o.vn);
  o.rebound_angle_contact = std::atan2(o.vs, o.vn);
  if (in.mu > 0.0) {
    o.slip_ratio_in = vs0 / (in.mu * in.vn0);
    o.slip_ratio_out = o.vs / (in.mu * in.vn0);
  }
  return o;
}

// The motion at time t in [0, contact_time] (fixed contact frame; relative = sphere 1 - sphere 2).
struct Sample {
  double t;
  double xi, xi_dot, fn;  // overlap, its rate (> 0 approaching), normal force on sphere 1
  double s, vs, ft;       // spring elongation, slip velocity, tangential force on sphere 1
  double jn, jt;          // impulses on sphere 1 so far
  double vn, vt;          // relative CoM velocity (vn = -xi_dot: > 0 separating)
  double v1n, v1t, v2n, v2t, omega1, omega2;  // centres and spins
  Mode mode;
};

inline Sample sample(const Input& in, const Output& o, double t) {
  if (o.phases.empty()) throw std::logic_error("analytic::sample: no phases (call impact() first)");
  if (!(t >= 0.0 && t <= o.contact_time))
    checks::fail("time t", t, ("[0, " + checks::number(o.contact_time) + "] (the contact)").c_str());
  const Normal nrm = make_normal(in);
  const Tangential tg(nrm, in, o.m_t);
  size_t i = 0;
  while (i + 1 < o.phases.size() && t > o.phases[i].tb) ++i;
  const Phase& p = o.phases[i];
  Sample r;
  r.t = t;
  r.mode = p.mode;
  r.xi = nrm.xi(t);
  r.xi_dot = nrm.xi_dot(t);
  r.fn = nrm.fn(t);
  r.jn = nrm.impulse(t);
  const double L = nrm.limit(t), Ld = nrm.limit_dot(t);
  if (p.mode == Mode::stick) {
    const double va = tg.v_at_J(p.Ja);
    tg.stick(t - p.ta, p.sa, va, r.s, r.vs);
    r.jt = o.m_t * (r.vs - tg.vs0);
    r.ft = -in.kt * r.s - in.gt * r.vs;
  } else if (p.mode == Mode::slip) {
    r.jt = p.Ja - p.sigma * (nrm.limit_integral(t) - nrm.limit_integral(p.ta));
    r.vs = tg.v_at_J(r.jt);
    r.s = tg.reset_spring(p.sigma, L, r.vs);
    r.ft = -p.sigma * L;
  } else {
    r.vs = p.sigma * Ld / in.kt;
    r.jt = o.m_t * (r.vs - tg.vs0);
    r.s = p.sigma * L / in.kt;
    r.ft = o.m_t * p.sigma * nrm.limit_ddot(t) / in.kt;
  }
  const bool wall = is_wall(in);
  const double I2 = inertia2(in);
  r.vn = -r.xi_dot;
  r.vt = in.vt0 + r.jt / o.m_n;
  r.omega1 = in.omega0 + in.R * r.jt / inertia1(in);
  r.omega2 = !wall && std::isfinite(I2) ? in.omega2 + in.R2 * r.jt / I2 : 0.0;
  const double v2n0 = wall ? 0.0 : in.v2n0, v2t0 = wall ? 0.0 : in.v2t0;
  r.v1n = v2n0 - in.vn0 + r.jn / in.m;
  r.v1t = v2t0 + in.vt0 + r.jt / in.m;
  r.v2n = wall ? 0.0 : v2n0 - r.jn / in.m2;
  r.v2t = wall ? 0.0 : v2t0 - r.jt / in.m2;
  return r;
}

}  // namespace analytic
}  // namespace collision
}  // namespace tdem
