// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the multi-evaluation schemes of the single-collision harness (heun, rk4, vv2, abm4_pece;
// collision/integrate_impact.h documents them), which only the harness can run: a host evaluates
// the force once per step. Their step, their history and the state types they step.
#pragma once

namespace tdem {
namespace collision {
// ---------------------------------------------------------------- schemes
enum class MultiScheme : int { heun, rk4, vv2, abm4_pece, count };

struct MultiSchemeInfo {
  MultiScheme id;
  const char* name;
  int order, order_damped, evaluations, history;  // history: doubles per particle beyond x, v, f, w, torque
  const char* summary;
};

inline const MultiSchemeInfo& info(MultiScheme s) {
  // history: heun keeps y_n (x, v, w) and f_n (a, alpha) through the step = 15; rk4 y_n and the
  // weighted stage sum = 18; vv2 v_n, w_n, a_n, alpha_n = 12; abm4_pece a(n-1..n-3), alpha(n-1..n-3),
  // v(n-1..n-3) [27] + x_n, v_n, w_n, a_n, alpha_n [15] = 42 (as abm4 of schemes.h)
  static const MultiSchemeInfo table[] = {
      {MultiScheme::heun, "heun", 2, 2, 2, 15, "Heun (RK2), 2 evaluations"},
      {MultiScheme::rk4, "rk4", 4, 4, 4, 18, "classical Runge-Kutta 4, 4 evaluations"},
      {MultiScheme::vv2, "vv2", 2, 2, 2, 12, "velocity Verlet, second evaluation at (x+, v+)"},
      {MultiScheme::abm4_pece, "abm4_pece", 4, 4, 2, 42, "Adams-Bashforth-Moulton 4, PECE"},
  };
  return table[static_cast<int>(s)];
}

namespace impact_detail {
// y = (x[3], v[3], w[3]); f = (v, a, alpha)
struct Y {
  double q[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  double* x() { return q; }
  double* v() { return q + 3; }
  double* w() { return q + 6; }
  const double* x() const { return q; }
  const double* v() const { return q + 3; }
  const double* w() const { return q + 6; }
};
struct Acc {
  double a[3] = {0, 0, 0}, al[3] = {0, 0, 0}, vt[3] = {0, 0, 0};  // and the slip velocity there
};
}  // namespace impact_detail

// ---------------------------------------------------------------- multi-evaluation steps
// History of abm4_pece (newest first, n-1 .. n-3): accelerations, angular accelerations,
// velocities (for x) and slip velocities (for the tangential history). Public so that a test can
// fill it with an exact start-up.
struct MultiState {
  double ha[3][3] = {}, hal[3][3] = {}, hv[3][3] = {}, hvt[3][3] = {};
};

// Start from the acceleration alone (constant acceleration: exact in free flight).
inline void multi_start(MultiState& st, const impact_detail::Y& y, const impact_detail::Acc& a, double h) {
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      st.ha[j][k] = a.a[k];
      st.hal[j][k] = a.al[k];
      st.hv[j][k] = y.v()[k] - (j + 1) * h * a.a[k];
      st.hvt[j][k] = a.vt[k];
    }
}

// One step of a multi-evaluation scheme from y (with a0, the evaluation at y) to y+, except the
// final evaluation at y+ (the caller's, which commits the law histories with h * vt_avg).
// stage(y_stage, incr_dt, vt_incr, out) evaluates an intermediate stage (a trial: histories
// advanced by incr_dt * vt_incr on a copy). Returns the number of stage evaluations.
template <class Stage>
int multi_step(MultiScheme ms, impact_detail::Y& y, const impact_detail::Acc& a0, MultiState& st, double h,
               Stage&& stage, double* vt_avg) {
  using impact_detail::Acc;
  using impact_detail::Y;
  const Y y0 = y;
  auto deriv = [](const Y& yy, const Acc& ac, double* f) {
    for (int k = 0; k < 3; ++k) {
      f[k] = yy.v()[k];
      f[3 + k] = ac.a[k];
      f[6 + k] = ac.al[k];
    }
  };
  auto axpy = [](const Y& base, double s, const double* f, Y& out) {
    for (int i = 0; i < 9; ++i) out.q[i] = base.q[i] + s * f[i];
  };
  if (ms == MultiScheme::heun) {
    double f1[9], f2[9];
    deriv(y0, a0, f1);
    Y y1;
    axpy(y0, h, f1, y1);
    Acc a1;
    stage(y1, h, a0.vt, a1);
    deriv(y1, a1, f2);
    for (int i = 0; i < 9; ++i) y.q[i] = y0.q[i] + 0.5 * h * (f1[i] + f2[i]);
    for (int k = 0; k < 3; ++k) vt_avg[k] = 0.5 * (a0.vt[k] + a1.vt[k]);
    return 1;
  }
  if (ms == MultiScheme::rk4) {
    double k1[9], k2[9], k3[9], k4[9];
    deriv(y0, a0, k1);
    Y ys;
    Acc s2, s3, s4;
    axpy(y0, 0.5 * h, k1, ys);
    stage(ys, 0.5 * h, a0.vt, s2);
    deriv(ys, s2, k2);
    axpy(y0, 0.5 * h, k2, ys);
    stage(ys, 0.5 * h, s2.vt, s3);
    deriv(ys, s3, k3);
    axpy(y0, h, k3, ys);
    stage(ys, h, s3.vt, s4);
    deriv(ys, s4, k4);
    for (int i = 0; i < 9; ++i) y.q[i] = y0.q[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    for (int k = 0; k < 3; ++k) vt_avg[k] = (a0.vt[k] + 2.0 * s2.vt[k] + 2.0 * s3.vt[k] + s4.vt[k]) / 6.0;
    return 3;
  }
  if (ms == MultiScheme::vv2) {
    Y yp = y0;
    for (int k = 0; k < 3; ++k) {
      yp.x()[k] = y0.x()[k] + h * y0.v()[k] + 0.5 * h * h * a0.a[k];
      yp.v()[k] = y0.v()[k] + h * a0.a[k];
      yp.w()[k] = y0.w()[k] + h * a0.al[k];
    }
    Acc ap;
    stage(yp, h, a0.vt, ap);
    y = yp;
    for (int k = 0; k < 3; ++k) {
      y.v()[k] = y0.v()[k] + 0.5 * h * (a0.a[k] + ap.a[k]);
      y.w()[k] = y0.w()[k] + 0.5 * h * (a0.al[k] + ap.al[k]);
      vt_avg[k] = 0.5 * (a0.vt[k] + ap.vt[k]);
    }
    return 1;
  }
  // abm4_pece
  auto ab = [](double n0, const double (*hh)[3], int k) {
    return (55.0 * n0 - 59.0 * hh[0][k] + 37.0 * hh[1][k] - 9.0 * hh[2][k]) / 24.0;
  };
  auto am = [](double p, double n0, const double (*hh)[3], int k) {
    return (9.0 * p + 19.0 * n0 - 5.0 * hh[0][k] + hh[1][k]) / 24.0;
  };
  Y yp;
  double vt_p_incr[3];
  for (int k = 0; k < 3; ++k) {
    yp.x()[k] = y0.x()[k] + h * ab(y0.v()[k], st.hv, k);
    yp.v()[k] = y0.v()[k] + h * ab(a0.a[k], st.ha, k);
    yp.w()[k] = y0.w()[k] + h * ab(a0.al[k], st.hal, k);
    vt_p_incr[k] = ab(a0.vt[k], st.hvt, k);
  }
  Acc ap;
  stage(yp, h, vt_p_incr, ap);
  for (int k = 0; k < 3; ++k) {
    y.v()[k] = y0.v()[k] + h * am(ap.a[k], a0.a[k], st.ha, k);
    y.w()[k] = y0.w()[k] + h * am(ap.al[k], a0.al[k], st.hal, k);
    y.x()[k] = y0.x()[k] + h * am(yp.v()[k], y0.v()[k], st.hv, k);
    vt_avg[k] = am(ap.vt[k], a0.vt[k], st.hvt, k);
  }
  for (int j = 2; j > 0; --j)
    for (int k = 0; k < 3; ++k) {
      st.ha[j][k] = st.ha[j - 1][k], st.hal[j][k] = st.hal[j - 1][k], st.hv[j][k] = st.hv[j - 1][k];
      st.hvt[j][k] = st.hvt[j - 1][k];
    }
  for (int k = 0; k < 3; ++k) {
    st.ha[0][k] = a0.a[k], st.hal[0][k] = a0.al[k], st.hv[0][k] = y0.v()[k], st.hvt[0][k] = a0.vt[k];
  }
  return 1;
}

}  // namespace collision
}  // namespace tdem
