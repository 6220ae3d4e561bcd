// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: a single head-on collision, integrated without a host engine.
//
//   m* xi'' = -F(xi, xi'),   xi(0) = xi_start (0: touch),   xi'(0) = v0 > 0
//
// for a sphere-sphere pair (m*, R* from m1, m2, R1, R2) or a sphere hitting a wall (m2, R2 =
// +infinity). Classical RK4 with a fixed step (a number of steps per estimated contact time, or a
// given dt), with two events located by bisection of the step that contains them:
//   * the turning point xi' = 0: the step is cut there, so the largest overlap (and the history of
//     hysteretic laws, which is committed after every accepted step) is exact to round-off;
//   * the end of contact: ContactEnd::zero_overlap ends where xi returns to xi_start;
//     ContactEnd::zero_force (laws that forbid attraction, hysteretic laws) ends where the force
//     reaches zero while unloading (xi' < 0); the particle then flies off with the velocity it has
//     there, and the overlap at that moment is the residual overlap.
// Outputs: e = -xi'(end)/v0, contact time, largest overlap and force, residual overlap, steps, and
// optionally the samples (t, xi, xi', F) of every accepted step.
//
// A law object (LsdLaw ... below) wraps one kernel of src/contact/normal with its parameters and
// its per-contact history. RK4 stages evaluate the kernel with update = false against the history
// of the start of the step (the kernels return the same force either way); the accepted state is
// evaluated once more with update = true, which commits new maxima. Contact laws are defined for
// xi >= 0 only: a stage that overshoots the end of contact sees the law at xi = 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/kinematics.h"
#include "contact/normal/continuous_potential.h"
#include "contact/normal/extended.h"
#include "contact/normal/hertz_damped.h"
#include "contact/input_checks.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/normal/power_law_hysteresis.h"
#include "contact/normal/thornton.h"
#include "contact/normal/walton_braun.h"

namespace tdem {
namespace collision {

// ---------------------------------------------------------------- the pair
// A wall (or a frozen partner) has m2 = R2 = +infinity.
struct Bodies {
  double m1 = 0.0, m2 = INFINITY;  // [kg]
  double R1 = 0.0, R2 = INFINITY;  // [m]; 0 if not given (the law must not need R*)
  double meff() const { return hertz::effective_mass(m1, m2); }
  double reff() const { return hertz::effective_radius(R1, R2); }
};

// Mass of a solid sphere of radius R and density rho.
inline double sphere_mass(double R, double rho) {
  checks::positive("radius R", R);
  checks::positive("density rho", rho);
  return 4.0 / 3.0 * M_PI * R * R * R * rho;
}

// ---------------------------------------------------------------- law objects
// Interface used by integrate():
//   NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool update);
//   ContactEnd end() const;                      how the contact ends
//   double start_overlap() const;                xi at the start (0: touch)
//   double contact_time_estimate(meff, reff, v0) sets the step size (need not be exact)
//   void reset();                                clears the per-contact history

struct LsdLaw {
  lsd::Coefficients<double> c{};
  ContactEnd end_mode = ContactEnd::zero_overlap;

  NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool) const {
    return lsd::force(end_mode, c, NormalKinematics<double>{std::max(xi, 0.0), xi_dot, meff, reff});
  }
  ContactEnd end() const { return end_mode; }
  double start_overlap() const { return 0.0; }
  double contact_time_estimate(double meff, double, double) const {
    return M_PI / std::sqrt(c.k / meff);
  }
  void reset() {}
};

struct HertzLaw {
  hertz::Damping damping = hertz::Damping::linear;
  hertz::Params<double> p{};
  ContactEnd end_mode = ContactEnd::zero_overlap;

  NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool) const {
    return hertz::force(damping, end_mode, p, NormalKinematics<double>{std::max(xi, 0.0), xi_dot, meff, reff});
  }
  ContactEnd end() const { return end_mode; }
  double start_overlap() const { return 0.0; }
  double contact_time_estimate(double meff, double, double v0) const {
    return hertz::contact_time_elastic(p.k, meff, v0);
  }
  void reset() {}
};

// A normal law that is a unit (src/contact/law_unit.h): its kernel with a history of its own.
template <class U>
struct UnitLaw {
  typename U::Params p{};
  double hist[U::description.history_size] = {};

  NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool update) {
    return U::force(p, NormalKinematics<double>{std::max(xi, 0.0), xi_dot, meff, reff}, hist, update);
  }
  ContactEnd end() const { return U::end; }
  double start_overlap() const { return 0.0; }
  double contact_time_estimate(double meff, double reff, double v0) const {
    return U::contact_time_estimate(p, meff, reff, v0);
  }
  void reset() { std::fill(std::begin(hist), std::end(hist), 0.0); }
};

using WaltonBraunLaw = UnitLaw<walton_braun::Law>;
using ThorntonLaw = UnitLaw<thornton::Law>;
using PowerLawLaw = UnitLaw<power_law::Law>;

// The extended laws take their coefficients at the first evaluation (the touch, xi' = v0),
// which integrate() makes with update = true.
struct ExtendedLinearLaw {
  extended::LinearParams p{};
  ContactEnd end_mode = ContactEnd::zero_overlap;
  double hist[extended::linear_history_size] = {0.0, 0.0, 0.0};

  NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool update) {
    return extended::linear_force(end_mode, p, NormalKinematics<double>{std::max(xi, 0.0), xi_dot, meff, reff},
                                  hist, update);
  }
  ContactEnd end() const { return end_mode; }
  double start_overlap() const { return 0.0; }
  double contact_time_estimate(double, double, double v0) const {
    return extended::linear_contact_time(p, v0);
  }
  void reset() { std::fill(std::begin(hist), std::end(hist), 0.0); }
};

struct ExtendedHertzLaw {
  extended::HertzParams p{};
  ContactEnd end_mode = ContactEnd::zero_overlap;
  double hist[extended::hertz_history_size] = {0.0, 0.0};

  NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool update) {
    return extended::hertz_force(end_mode, p, NormalKinematics<double>{std::max(xi, 0.0), xi_dot, meff, reff},
                                 hist, update);
  }
  ContactEnd end() const { return end_mode; }
  double start_overlap() const { return 0.0; }
  double contact_time_estimate(double meff, double, double v0) const {
    return hertz::contact_time_elastic(p.k, meff, v0);
  }
  void reset() { std::fill(std::begin(hist), std::end(hist), 0.0); }
};

// The collision starts where the potential starts to act: X = X_cut (or X = d without a cut-off).
struct ContinuousPotentialLaw {
  continuous_potential::Params<double> p{};
  ContactEnd end_mode = ContactEnd::zero_overlap;

  NormalResult<double> force(double xi, double xi_dot, double meff, double reff, bool) const {
    return continuous_potential::force(end_mode, p, NormalKinematics<double>{xi, xi_dot, meff, reff});
  }
  ContactEnd end() const { return end_mode; }
  double start_overlap() const { return std::isinf(p.x_cut) ? 0.0 : p.d - p.x_cut; }
  // The shorter of the travel time to the closest approach and back, and the half-period of the
  // linearised spring there (which sets the accuracy near the turning point).
  double contact_time_estimate(double meff, double, double v0) const {
    const double x_start = p.d - start_overlap();
    auto from_start = p;  // the energy balance counts from the start X_start, not from infinity
    from_start.x_cut = x_start;
    const double x_min = continuous_potential::closest_approach(from_start, meff, v0);
    const double k = (p.n + 1.0) * p.n * p.eps * std::pow(p.d / x_min, p.n) / (x_min * x_min);
    return std::min(2.0 * (x_start - x_min) / v0, M_PI * std::sqrt(meff / k));
  }
  void reset() {}
};

// ---------------------------------------------------------------- the integrator
struct Options {
  int steps_per_contact = 4000;  // used when dt <= 0: dt = t_c(estimate) / steps_per_contact
  double dt = 0.0;               // fixed step [s]; > 0 overrides steps_per_contact
  double max_contact_times = 1000.0;  // give up after this many estimated contact times
  long max_steps = 100000000;         // ... or this many steps
  bool record = false;                // keep the samples (t, xi, xi', F)
};

struct Sample {
  double t, xi, xi_dot, force;
};

struct Result {
  bool ended = false;              // false: the contact did not end within the limits
  double v0 = 0.0;                 // impact velocity (xi'(0))
  double restitution = 0.0;        // e = -xi'(end) / v0
  double rebound_velocity = 0.0;   // -xi'(end)
  double contact_time = 0.0;       // t(end) [s]
  double max_overlap = 0.0;        // [m]
  double max_force = 0.0;          // [N]
  double residual_overlap = 0.0;   // xi(end) [m] (0 or xi_start for the zero_overlap end)
  double dissipated_energy = 0.0;  // 1/2 m* (v0^2 - xi'(end)^2) [J]
  double dt = 0.0;                 // step used [s]
  double contact_time_estimate = 0.0;
  long steps = 0;                  // accepted RK4 steps (including the cut ones at the events)
  std::vector<Sample> samples;
};

inline void validate(const Options& o) {
  if (!(o.dt >= 0.0) || !std::isfinite(o.dt)) checks::fail("time step dt", o.dt, "[0, inf)");
  if (o.dt == 0.0 && o.steps_per_contact < 1)
    checks::fail("steps per contact", o.steps_per_contact, "[1, inf)");
}

template <class Law>
Result integrate(Law& law, const Bodies& bodies, double v0, const Options& opt = Options()) {
  checks::positive("impact velocity v0", v0);
  validate(opt);
  const double meff = bodies.meff();
  // R* is NaN when a radius is not given: the laws that need it then refuse (lsd, hertz with a
  // given k~, walton_braun and continuous_potential do not use it).
  const double reff = bodies.R1 > 0.0 && bodies.R2 > 0.0 ? bodies.reff() : NAN;
  law.reset();

  Result r;
  r.v0 = v0;
  r.contact_time_estimate = law.contact_time_estimate(meff, reff, v0);
  if (!(r.contact_time_estimate > 0.0) || !std::isfinite(r.contact_time_estimate))
    throw std::domain_error("estimated contact time = " + checks::number(r.contact_time_estimate) +
                            " is not a positive finite number; give a time step dt");
  const double dt = opt.dt > 0.0 ? opt.dt : r.contact_time_estimate / opt.steps_per_contact;
  r.dt = dt;
  const double t_max = std::max(opt.max_contact_times * r.contact_time_estimate, 10.0 * dt);
  const double xi_start = law.start_overlap();
  const bool zero_force = law.end() == ContactEnd::zero_force;

  auto accel = [&](double x, double v) { return -law.force(x, v, meff, reff, false).force / meff; };
  auto rk4 = [&](double x, double v, double h, double& xo, double& vo) {
    const double a1 = accel(x, v);
    const double x2 = x + 0.5 * h * v, v2 = v + 0.5 * h * a1;
    const double a2 = accel(x2, v2);
    const double x3 = x + 0.5 * h * v2, v3 = v + 0.5 * h * a2;
    const double a3 = accel(x3, v3);
    const double x4 = x + h * v3, v4 = v + h * a3;
    const double a4 = accel(x4, v4);
    xo = x + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
    vo = v + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
  };
  // End of contact at state (x, v), with the history of the current step.
  auto ended = [&](double x, double v) {
    if (x <= xi_start) return true;
    return zero_force && v < 0.0 && law.force(x, v, meff, reff, false).force <= 0.0;
  };
  // Smallest h in (0, hi] where pred(state after a step h) holds, to 1e-15 hi (bisection; pred is
  // false at h = 0 and true at h = hi).
  auto locate = [&](double x, double v, double hi, auto pred) {
    double lo = 0.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      double xm, vm;
      rk4(x, v, mid, xm, vm);
      if (pred(xm, vm)) hi = mid; else lo = mid;
    }
    return hi;
  };

  double t = 0.0, x = xi_start, v = v0;
  auto record = [&](double f) {
    r.max_overlap = std::max(r.max_overlap, x);
    r.max_force = std::max(r.max_force, f);
    if (opt.record) r.samples.push_back({t, x, v, f});
  };
  record(law.force(x, v, meff, reff, true).force);

  while (t < t_max && r.steps < opt.max_steps) {
    double xn, vn, h = dt;
    rk4(x, v, h, xn, vn);
    bool end_here = false;
    if (ended(xn, vn)) {
      h = locate(x, v, dt, ended);
      rk4(x, v, h, xn, vn);
      end_here = true;
    } else if (v > 0.0 && vn <= 0.0) {  // turning point inside the step: cut the step there
      h = locate(x, v, dt, [](double, double vm) { return vm <= 0.0; });
      rk4(x, v, h, xn, vn);
    }
    if (!std::isfinite(xn) || !std::isfinite(vn)) break;  // blown up (time step far too large)
    x = xn;
    v = vn;
    t += h;
    ++r.steps;
    // The force at the end of a zero_force contact is zero (up to the bisection tolerance).
    const double f = end_here && zero_force ? 0.0 : law.force(x, v, meff, reff, true).force;
    record(f);
    if (end_here) {
      r.ended = true;
      r.contact_time = t;
      r.rebound_velocity = -v;
      r.restitution = -v / v0;
      r.residual_overlap = x <= xi_start ? xi_start : x;  // the zero_overlap end: exactly xi_start
      r.dissipated_energy = 0.5 * meff * (v0 * v0 - v * v);
      return r;
    }
  }
  return r;
}

}  // namespace collision
}  // namespace tdem
