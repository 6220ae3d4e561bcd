// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: motion profiles of the moving bar rows of a grate (physics_reference.md 7.1, docs/grate.md).
//
// A moving row translates along its own bar axis by u(t) (0 = home position, stroke = fully out);
// the geometry (geometry.h) turns u into a displacement along +e_t (forward-acting grate) or -e_t
// (reverse-acting grate). One cycle of period T is split into four segments:
//
//     outward stroke  | dwell out | return stroke  | dwell home
//     0 -> stroke       stroke      stroke -> 0      0
//     duration  s_f·m·T  d_out·T    (1 - s_f)·m·T    d_home·T        m = 1 - d_out - d_home
//
// (s_f = forward_share). The shape of both strokes, with x = s/d the elapsed fraction of a stroke
// of duration d (so f goes 0 -> 1 along a stroke):
//   sinusoidal          f = (1 - cos(pi x))/2 (half-cosine; with no dwells and s_f = 1/2 this is
//                       u = stroke·(1 - cos(2 pi tau))/2, the classic harmonic stroke)
//   trapezoidal         f = x: linear ramps, the POSITION is a trapezoid in time, the velocity a
//                       piecewise constant +-stroke/d (jumps at the segment ends)
//   trapezoidal_accel   acceleration-limited: the VELOCITY is a trapezoid. Constant acceleration
//                       for the first ramp·d, cruise at v_max = stroke/(d - ramp·d), constant
//                       deceleration for the last ramp·d (ramp = 1/2: triangular velocity). The
//                       position and the velocity are continuous, the acceleration is +-v_max/(ramp·d).
//
// Time: tau = (t - t_start)/T - phase. While tau < 0 the row rests at home (u = v = a = 0): each
// phase group starts its first cycle phase·T after t_start, so the motion is continuous at the start.
// Afterwards tau is taken modulo 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "contact/input_checks.h"

namespace tdem {
namespace grate {

enum class Profile { sinusoidal, trapezoidal, trapezoidal_accel };

inline const char* profile_name(Profile p) {
  switch (p) {
    case Profile::sinusoidal: return "sinusoidal";
    case Profile::trapezoidal: return "trapezoidal";
    case Profile::trapezoidal_accel: return "trapezoidal_accel";
  }
  return "?";
}

// Error for a bad keyword value: names the keyword, the value and the allowed values.
[[noreturn]] inline void bad_value(const std::string& context, const std::string& keyword, double v,
                                   const std::string& allowed) {
  throw std::invalid_argument(context + ": keyword '" + keyword + "' = " + checks::number(v) +
                              " is outside the allowed range " + allowed);
}

inline Profile parse_profile(const std::string& s) {
  if (s == "sinusoidal" || s == "sine") return Profile::sinusoidal;
  if (s == "trapezoidal" || s == "trapezoid") return Profile::trapezoidal;
  if (s == "trapezoidal_accel") return Profile::trapezoidal_accel;
  throw std::invalid_argument("grate motion: keyword 'profile' = '" + s +
                              "' is not known; allowed: sinusoidal, trapezoidal, trapezoidal_accel");
}

struct MotionParams {
  Profile profile = Profile::sinusoidal;
  double stroke = 0.0;         // stroke length Delta l [m], >= 0
  double period = 1.0;         // T = 1/frequency [s], > 0
  double t_start = 0.0;        // time of the start of the first cycle of phase group 0 [s]
  double dwell_out = 0.0;      // fraction of T resting at full stroke, [0, 1)
  double dwell_home = 0.0;     // fraction of T resting at home, [0, 1); dwell_out + dwell_home < 1
  double forward_share = 0.5;  // share of the moving time taken by the outward stroke, (0, 1)
  double ramp = 0.25;          // trapezoidal_accel: acceleration time / stroke duration, (0, 0.5]
};

inline void validate(const MotionParams& m) {
  const std::string c = "grate motion";
  if (!(m.stroke >= 0.0) || !std::isfinite(m.stroke)) bad_value(c, "stroke", m.stroke, "[0, inf)");
  if (!(m.period > 0.0) || !std::isfinite(m.period)) bad_value(c, "period", m.period, "(0, inf)");
  if (!std::isfinite(m.t_start)) bad_value(c, "t_start", m.t_start, "(-inf, inf)");
  if (!(m.dwell_out >= 0.0 && m.dwell_out < 1.0)) bad_value(c, "dwell_out", m.dwell_out, "[0, 1)");
  if (!(m.dwell_home >= 0.0 && m.dwell_home < 1.0)) bad_value(c, "dwell_home", m.dwell_home, "[0, 1)");
  if (!(m.dwell_out + m.dwell_home < 1.0))
    bad_value(c, "dwell_out + dwell_home", m.dwell_out + m.dwell_home, "[0, 1)");
  if (!(m.forward_share > 0.0 && m.forward_share < 1.0))
    bad_value(c, "forward_share", m.forward_share, "(0, 1)");
  if (!(m.ramp > 0.0 && m.ramp <= 0.5)) bad_value(c, "ramp", m.ramp, "(0, 0.5]");
}

inline void validate_phase(double phase) {
  if (!(phase >= 0.0 && phase < 1.0)) bad_value("grate motion", "group_phase", phase, "[0, 1)");
}

// Displacement along the stroke direction, its rate and its second derivative.
struct MotionState {
  double u = 0.0;  // [m], 0 .. stroke
  double v = 0.0;  // du/dt [m/s]
  double a = 0.0;  // d2u/dt2 [m/s^2] (at a jump of the linear trapezoid: the one-sided value 0)
};

namespace detail {
// Unit stroke 0 -> 1 of duration d [s] at elapsed time s in [0, d]: f, df/ds, d2f/ds2.
inline MotionState unit_stroke(Profile p, double ramp, double s, double d) {
  MotionState r;
  constexpr double pi = 3.14159265358979323846;
  switch (p) {
    case Profile::sinusoidal: {
      const double w = pi / d;
      r.u = 0.5 * (1.0 - std::cos(w * s));
      r.v = 0.5 * w * std::sin(w * s);
      r.a = 0.5 * w * w * std::cos(w * s);
      break;
    }
    case Profile::trapezoidal:
      r.u = s / d;
      r.v = 1.0 / d;
      r.a = 0.0;
      break;
    case Profile::trapezoidal_accel: {
      const double ta = ramp * d;
      const double vmax = 1.0 / (d - ta);
      const double acc = vmax / ta;
      if (s < ta) {
        r.u = 0.5 * acc * s * s;
        r.v = acc * s;
        r.a = acc;
      } else if (s <= d - ta) {
        r.u = 0.5 * acc * ta * ta + vmax * (s - ta);
        r.v = vmax;
        r.a = 0.0;
      } else {
        const double q = d - s;
        r.u = 1.0 - 0.5 * acc * q * q;
        r.v = acc * q;
        r.a = -acc;
      }
      break;
    }
  }
  return r;
}
}  // namespace detail

// State of a row of phase `phase` (fraction of T, [0, 1)) at time t. Call validate() once first.
inline MotionState evaluate(const MotionParams& m, double t, double phase = 0.0) {
  MotionState r;
  if (m.stroke == 0.0) return r;
  double tau = (t - m.t_start) / m.period - phase;
  if (tau < 0.0) return r;
  tau -= std::floor(tau);
  const double T = m.period;
  const double move = 1.0 - m.dwell_out - m.dwell_home;
  const double d_f = m.forward_share * move * T;
  const double d_o = m.dwell_out * T;
  const double d_r = (1.0 - m.forward_share) * move * T;
  double s = tau * T;
  if (s < d_f) {
    const MotionState f = detail::unit_stroke(m.profile, m.ramp, s, d_f);
    r.u = m.stroke * f.u;
    r.v = m.stroke * f.v;
    r.a = m.stroke * f.a;
    return r;
  }
  s -= d_f;
  if (s < d_o) {
    r.u = m.stroke;
    return r;
  }
  s -= d_o;
  if (s < d_r) {
    const MotionState f = detail::unit_stroke(m.profile, m.ramp, s, d_r);
    r.u = m.stroke * (1.0 - f.u);
    r.v = -m.stroke * f.v;
    r.a = -m.stroke * f.a;
    return r;
  }
  return r;  // dwell at home
}

// Largest |du/dt| of the profile (for time-step and contact checks of the hosts).
inline double max_speed(const MotionParams& m) {
  const double move = 1.0 - m.dwell_out - m.dwell_home;
  const double d = std::min(m.forward_share, 1.0 - m.forward_share) * move * m.period;  // shorter stroke
  constexpr double pi = 3.14159265358979323846;
  switch (m.profile) {
    case Profile::sinusoidal: return m.stroke * 0.5 * pi / d;
    case Profile::trapezoidal: return m.stroke / d;
    case Profile::trapezoidal_accel: return m.stroke / (d - m.ramp * d);
  }
  return 0.0;
}

}  // namespace grate
}  // namespace tdem
