// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: closed-form (event-driven, no time stepping) solution of the oblique impact of a sphere on
// a wall with the linear spring-dashpot normal law and the Cundall-Strack tangential spring
// (constant k_t, Coulomb limit, spring truncated to the limit while sliding, no tangential
// dashpot): physics_reference.md section 4. Independent of the integrator of oblique.h.
//
// Signs as in oblique.h / rigid_body.h: v_n0 > 0 approach speed, v_t0 tangential CoM velocity,
// omega scalar spin with slip velocity v_s = v_t + R omega (0 for rolling). J is the tangential
// impulse on the sphere: v_t = v_t0 + J/m, omega = omega0 + R J/I, v_s = v_s0 + J/m_t with
// 1/m_t = 1/m + R^2/I (m_t = 2/7 m for a solid sphere).
//
// Normal motion (underdamped, delta = gamma_n/(2m) < omega0 = sqrt(k_n/m)):
//   xi(t) = v_n0/w e^{-delta t} sin(w t),  w = sqrt(omega0^2 - delta^2),
//   F_n(t) = k_n xi + gamma_n xi',   int_0^t F_n = m (v_n0 - xi'(t)).
// End of contact: ContactEnd::zero_overlap at w t = pi (F_n < 0 in the tail: attraction);
// ContactEnd::zero_force where k_n xi + gamma_n xi' = 0 (closed form, w t = pi - atan2(gamma_n w,
// k_n - gamma_n delta)). The Coulomb limit L(t) = mu |F_n| (FrictionLimit::absolute) or
// mu max(F_n, 0) (FrictionLimit::positive_normal); the two differ only in the attractive tail.
//
// Tangential phases (s: spring elongation, F_t = -k_t s):
//   stick: m_t s'' = -k_t s (harmonic, w_t = sqrt(k_t/m_t)), s' = v_s;
//   slip:  F_t = -sigma L(t), sigma = sign of the spring, s = sigma L(t)/k_t (the truncated spring
//          of cundall_strack::SlipRule::spring_cap), J(t) = J_a - sigma (Lambda(t) - Lambda(t_a))
//          with Lambda = int L dt in closed form.
// Switching: stick -> slip at the first root of h = L(t) - k_t |s(t)|; slip -> stick at the first
// root of g = sigma v_s(t) - L'(t)/k_t (the truncated spring would start to shorten by less than
// the cap: the kernel then holds it). Roots: a scan of the closed forms on a grid of
// contact_time/scan_points, then bisection of the bracket to ~1e-15 of the contact time. At
// t = 0 and at the zero of F_n (zero_overlap end: the kink of L) the state is decided from the
// limit: sliding if k_t|s| is at the limit and sigma v_s > L'(t+)/k_t. A pair of roots closer
// together than one grid interval (a phase shorter than contact_time/scan_points) is not seen.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/kinematics.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/normal/input_checks.h"
#include "contact/tangential/common.h"

namespace tdem {
namespace collision {
namespace analytic {

struct Input {
  double m = 0.0;      // sphere mass [kg]
  double R = 0.0;      // radius [m]
  double I = 0.0;      // moment of inertia [kg m^2]; 0: solid sphere 2/5 m R^2
  double kn = 0.0;     // normal stiffness [N/m]
  double gn = 0.0;     // normal damping [kg/s], below critical 2 sqrt(kn m)
  double kt = 0.0;     // tangential stiffness [N/m]
  double mu = 0.0;     // Coulomb coefficient
  ContactEnd end = ContactEnd::zero_force;
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  double vn0 = 0.0;     // approach speed > 0
  double vt0 = 0.0;     // tangential CoM velocity
  double omega0 = 0.0;  // initial spin
  int scan_points = 4000;  // grid for bracketing the switching roots (per contact time)
  int max_switches = 10000;
};

struct Switch {
  double t;      // time of the switch [s]
  bool sliding;  // the new state
};

struct Output {
  double m_t = 0.0, vs0 = 0.0;
  double contact_time = 0.0;
  double t_zero_force = NAN;  // zero of F_n (end for zero_force; start of attraction for zero_overlap)
  double e = 0.0, vn = 0.0;   // restitution and rebound normal speed
  double jt = 0.0;            // tangential impulse
  double vt = 0.0, omega = 0.0, vs = 0.0;
  double beta = NAN, e_t = NAN;
  double rebound_angle_com = 0.0, rebound_angle_contact = 0.0;  // [rad]
  double slip_ratio_in = NAN, slip_ratio_out = NAN;            // v_s/(mu v_n0)
  bool sliding_at_start = false;
  bool sliding_at_end = false;
  std::vector<Switch> switches;
};

inline void validate(const Input& in) {
  checks::positive("mass m", in.m);
  checks::positive("radius R", in.R);
  checks::non_negative("moment of inertia I (0: solid sphere)", in.I);
  checks::positive("normal stiffness k_n", in.kn);
  checks::non_negative("normal damping gamma_n", in.gn);
  const double crit = 2.0 * std::sqrt(in.kn * in.m);
  if (!(in.gn < crit)) {
    const std::string range = "[0, " + checks::number(crit) + ") (underdamped: below 2 sqrt(k_n m))";
    checks::fail("normal damping gamma_n", in.gn, range.c_str());
  }
  checks::positive("tangential stiffness k_t", in.kt);
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
  double impulse(double t) const { return m * (v0 - xi_dot(t)); }  // int_0^t F_n
  // Coulomb limit, its derivative and its integral from 0. At the zero of F_n (the kink of the
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
  double limit_integral(double t) const {
    if (t <= t_zero || !attraction) return mu * impulse(t);
    const double pz = impulse(t_zero);
    return absolute ? mu * (2.0 * pz - impulse(t)) : mu * pz;
  }
};

inline Normal make_normal(const Input& in) {
  Normal n;
  n.m = in.m, n.k = in.kn, n.g = in.gn, n.v0 = in.vn0, n.mu = in.mu;
  n.delta = in.gn / (2.0 * in.m);
  n.w = std::sqrt(in.kn / in.m - n.delta * n.delta);
  // F_n = v0 e^{-delta t} [((k - g delta)/w) sin(wt) + g cos(wt)]: zero at wt = pi - atan2(g w, k - g delta)
  n.t_zero = (M_PI - std::atan2(in.gn * n.w, in.kn - in.gn * n.delta)) / n.w;
  n.attraction = in.end == ContactEnd::zero_overlap;
  n.t_end = n.attraction ? M_PI / n.w : n.t_zero;
  n.absolute = in.limit == tangential::FrictionLimit::absolute;
  return n;
}

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
  const double I = in.I > 0.0 ? in.I : 0.4 * in.m * in.R * in.R;
  const Normal nrm = make_normal(in);
  Output o;
  o.m_t = 1.0 / (1.0 / in.m + in.R * in.R / I);
  o.vs0 = in.vt0 + in.R * in.omega0;
  o.contact_time = nrm.t_end;
  o.t_zero_force = nrm.t_zero;
  const double mt = o.m_t, kt = in.kt, vs0 = o.vs0;
  const double wt = std::sqrt(kt / mt);
  const double step = nrm.t_end / in.scan_points;

  // Phase state at its start t_a: impulse J_a, spring s_a, and for slip the sign sigma.
  double ta = 0.0, Ja = 0.0, sa = 0.0, sigma = 0.0;
  bool slip = false;

  auto vs_at_J = [&](double J) { return vs0 + J / mt; };
  // stick closed forms from (ta, sa, va)
  auto stick_s = [&](double t, double va) {
    const double x = wt * (t - ta);
    return sa * std::cos(x) + va / wt * std::sin(x);
  };
  auto stick_v = [&](double t, double va) {
    const double x = wt * (t - ta);
    return -sa * wt * std::sin(x) + va * std::cos(x);
  };
  auto slip_J = [&](double t) { return Ja - sigma * (nrm.limit_integral(t) - nrm.limit_integral(ta)); };

  // Decide the state at t with spring s and slip velocity v (t = 0 and the kink of L).
  auto decide = [&](double t, double& s, double v) {
    const double L = nrm.limit(t);
    if (kt * std::fabs(s) < L * (1.0 - 1e-12)) return false;
    double sg = detail::sgn(s);
    s = sg * L / kt;  // truncate
    if (s == 0.0) sg = detail::sgn(v);
    if (sg != 0.0 && sg * v > nrm.limit_dot(t) / kt) {
      sigma = sg;
      return true;
    }
    return false;
  };

  // the kink of the limit (attractive tail) is a breakpoint
  std::vector<double> breaks;
  if (nrm.attraction && nrm.t_zero < nrm.t_end) breaks.push_back(nrm.t_zero);
  breaks.push_back(nrm.t_end);

  slip = decide(0.0, sa, vs0);
  o.sliding_at_start = slip;
  if (vs0 == 0.0 && sa == 0.0) slip = false;  // nothing to do: no tangential motion at all
  size_t bi = 0;
  int nsw = 0;
  double J_end = 0.0;
  while (true) {
    const double tb = breaks[bi];
    if (!slip) {
      const double va = vs_at_J(Ja);
      auto h = [&](double t) { return nrm.limit(t, true) - kt * std::fabs(stick_s(t, va)); };
      double tr = NAN;
      if (!(va == 0.0 && sa == 0.0)) tr = detail::first_root(h, ta, tb, step);
      if (std::isnan(tr)) {
        // to the breakpoint in stick
        const double s = stick_s(tb, va), v = stick_v(tb, va);
        const double J = mt * (v - vs0);
        if (bi + 1 == breaks.size()) {
          J_end = J;
          break;
        }
        ta = tb, Ja = J, sa = s;
        ++bi;
        const bool ns = decide(ta, sa, v);
        if (ns != slip) {
          o.switches.push_back({ta, ns});
          slip = ns;
        }
        continue;
      }
      const double s = stick_s(tr, va), v = stick_v(tr, va);
      sigma = detail::sgn(s);
      Ja = mt * (v - vs0);
      ta = tr;
      sa = sigma * nrm.limit(tr) / kt;
      slip = true;
      o.switches.push_back({tr, true});
    } else {
      auto g = [&](double t) { return sigma * vs_at_J(slip_J(t)) - nrm.limit_dot(t, true) / kt; };
      const double tr = detail::first_root(g, ta, tb, step);
      if (std::isnan(tr)) {
        const double J = slip_J(tb);
        if (bi + 1 == breaks.size()) {
          J_end = J;
          break;
        }
        ta = tb, Ja = J, sa = sigma * nrm.limit(tb) / kt;
        ++bi;
        const bool ns = decide(ta, sa, vs_at_J(J));
        if (ns != slip) {
          o.switches.push_back({ta, ns});
          slip = ns;
        }
        continue;
      }
      Ja = slip_J(tr);
      sa = sigma * nrm.limit(tr) / kt;
      ta = tr;
      slip = false;
      o.switches.push_back({tr, false});
    }
    if (++nsw > in.max_switches)
      throw std::runtime_error("analytic oblique impact: more than " + std::to_string(in.max_switches) +
                               " stick/slip switches (chattering); last at t = " + checks::number(ta));
  }
  o.sliding_at_end = slip;
  o.jt = J_end;
  o.vn = -nrm.xi_dot(nrm.t_end);
  o.e = o.vn / in.vn0;
  o.vt = in.vt0 + J_end / in.m;
  o.omega = in.omega0 + in.R * J_end / I;
  o.vs = o.vt + in.R * o.omega;
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

}  // namespace analytic
}  // namespace collision
}  // namespace tdem
