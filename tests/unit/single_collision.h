// SPDX-License-Identifier: GPL-2.0-or-later
// A head-on collision of a pair with effective mass m*, integrated with classical RK4 and
// event location by bisection of the last step. Used by the kernel tests as an independent
// check of the closed forms: it only calls the force kernel, never the closed forms.
#pragma once

#include <cmath>
#include <functional>

namespace tdem::testing {

struct CollisionOutcome {
  double restitution;   // -xi_dot(end) / xi_dot(0)
  double contact_time;  // time of the end event
  double max_overlap;
};

// force(xi, xi_dot) -> normal force (> 0 repulsive).
// ends(xi, xi_dot) -> value that crosses from > 0 to <= 0 at the end of contact.
inline CollisionOutcome integrate_collision(const std::function<double(double, double)>& force,
                                            const std::function<double(double, double)>& ends,
                                            double meff, double v0, double dt, double t_max) {
  auto rk4 = [&](double x, double v, double h, double& xo, double& vo) {
    const double a1 = -force(x, v) / meff;
    const double x2 = x + 0.5 * h * v, v2 = v + 0.5 * h * a1;
    const double a2 = -force(x2, v2) / meff;
    const double x3 = x + 0.5 * h * v2, v3 = v + 0.5 * h * a2;
    const double a3 = -force(x3, v3) / meff;
    const double x4 = x + h * v3, v4 = v + h * a3;
    const double a4 = -force(x4, v4) / meff;
    xo = x + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
    vo = v + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
  };
  double t = 0.0, x = 0.0, v = v0, xmax = 0.0;
  // First step from touch: the end function is zero or positive at xi = 0 with v0 > 0.
  while (t < t_max) {
    double xn, vn;
    rk4(x, v, dt, xn, vn);
    if (ends(xn, vn) <= 0.0 && t > 0.0) {
      double lo = 0.0, hi = dt;
      for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        rk4(x, v, mid, xn, vn);
        if (ends(xn, vn) > 0.0) lo = mid; else hi = mid;
      }
      const double h = 0.5 * (lo + hi);
      rk4(x, v, h, xn, vn);
      return {-vn / v0, t + h, xmax};
    }
    x = xn;
    v = vn;
    t += dt;
    xmax = std::fmax(xmax, x);
  }
  return {0.0, INFINITY, xmax};
}

}  // namespace tdem::testing
