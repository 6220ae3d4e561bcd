// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: explicit time-integration schemes for DEM particles (physics_reference.md 5.1), written once
// for the host fixes (LIGGGHTS and LAMMPS `fix tdem/integrate`) and the single-collision harness.
//
// Every scheme here needs ONE force evaluation per step, so it fits the host step
//     initial_integrate  ->  force computation (pairs, walls, gravity ...)  ->  final_integrate.
// A scheme is applied per particle to "channels" of three components:
//   translation: position x, velocity v, acceleration a = F/m;
//   rotation:    no position (x == nullptr), angular velocity w, angular acceleration a = T/I.
// The kernel of scheme S offers (all static, all inline, no allocation):
//   Kernel<S, kPos>::history       doubles of per-particle history this channel needs beyond
//                                  x, v and the host's force (kPos: the channel has a position)
//   start(x, v, d, hist, h)        fills the history from the current state, the acceleration
//                                  d.d[0] and, where known, its time derivatives (Derivs); hosts
//                                  call integrators::start<S, kPos>(x, v, a, hist, h) after the
//                                  set-up force evaluation or for a new particle: exact for
//                                  constant acceleration (free flight), so a particle that starts
//                                  in free flight has a consistent multi-step history
//   predict(x, v, a, hist, h)      initial_integrate: a is the acceleration of the last force
//                                  evaluation; leaves in x and v the state at which the next force
//                                  is evaluated (positions and the velocities that the velocity-
//                                  dependent forces see)
//   correct(x, v, a, hist, h)      final_integrate: a is the new acceleration; corrects x and v
//   has_correct                    false if correct() does nothing (hosts may skip the loop)
// Schemes and the velocity the force sees (h = dt, n -> n+1):
//   euler               x+ = x + h v,  v+ = v + h a                                   force at (x+, v+)
//   symplectic_euler    v+ = v + h a,  x+ = x + h v+                                  (x+, v+)
//   taylor2             x+ = x + h v + h^2 a/2,  v+ = v + h a                         (x+, v+)
//   taylor3             b = (a - a_old)/h;  x+ = x + h v + h^2 a/2 + h^3 b/6;
//                       v+ = v + h a + h^2 b/2                                        (x+, v+)
//   leapfrog            v(n+1/2) = v(n-1/2) + h a, x+ = x + h v(n+1/2); the particle carries the
//                       half-step velocity (start: v(-1/2) = v0 - h a0/2). Positions equal the
//                       engines' velocity Verlet; only the velocity shown differs.     (x+, v(n+1/2))
//   position_verlet     x+ = 2x - x- + h^2 a (kept as d = x - x-: d+ = d + h^2 a, x+ = x + d+);
//                       v+ = d+/h, the backward difference (start: d = h v0 - h^2 a0/2).
//                       In exact arithmetic this is symplectic Euler with v = backward difference.
//   velocity_verlet     v(1/2) = v + h a/2, x+ = x + h v(1/2); correct v+ = v(1/2) + h a+/2:
//                       the engines' fix nve/sphere                                   (x+, v(1/2))
//   velocity_verlet_sync  as velocity_verlet, but the force sees the synchronous Euler predictor
//                       v_p = v + h a instead of the half-step velocity               (x+, v_p)
//   velocity_verlet_ab2 as velocity_verlet, but the force sees the Adams-Bashforth 2 predictor
//                       v_p = v + h (3a - a-)/2 (third order in v: with a damping force the
//                       scheme keeps the small error constant of velocity Verlet with the exact
//                       velocity; issue 22)                                          (x+, v_p)
//   beeman              x+ = x + h v + h^2 (4a - a-)/6; predictor v_p = v + h (3a - a-)/2;
//                       correct v+ = v + h (2a+ + 5a - a-)/6                          (x+, v_p)
//   ab2 .. ab5          Adams-Bashforth k: x+ = x + h sum b_j v(n-j), v+ = v + h sum b_j a(n-j)
//                       (start: v(n-j) = v0 - j h a0, a(n-j) = a0)                     (x+, v+)
//   abm4                Adams-Bashforth-Moulton 4 in PEC form (one evaluation): AB4 predictor,
//                       force at the predicted state, Adams-Moulton corrector
//                       v+ = v + h (9a+ + 19a - 5a(n-1) + a(n-2))/24, then x+ with the corrected
//                       velocity; the evaluated (predicted-state) accelerations form the history
//   gear4 .. gear6      Gear predictor-corrector with q = 4..6 Nordsieck values r_i = h^i x^(i)/i!
//                       (Allen & Tildesley, second-order ODE coefficients); predictor: Pascal
//                       triangle; force at the predicted (x, v); corrector r_i += c_i (h^2 a+/2 - r2p).
//                       The host force keeps r2 (c_2 = 1); the history holds r3 .. r_{q-1} and r2p.
// The harness adds multi-evaluation schemes (Heun, RK4, two-evaluation velocity Verlet, ABM4 PECE)
// in src/collision/integrate_impact.h; they cannot run inside a host's one-force step.
#pragma once

#include <string>
#include <type_traits>

namespace tdem {
namespace integrators {

enum class Scheme : int {
  euler,
  symplectic_euler,
  taylor2,
  taylor3,
  leapfrog,
  position_verlet,
  velocity_verlet,
  velocity_verlet_sync,
  beeman,
  ab2,
  ab3,
  ab4,
  ab5,
  abm4,
  gear4,
  gear5,
  gear6,
  velocity_verlet_ab2,  // appended: the restart records of fix tdem/integrate keep the code
  count
};

struct SchemeInfo {
  Scheme id;
  const char* name;
  int order;          // nominal global order on a smooth problem with conservative forces
  int order_damped;   // nominal order with velocity-dependent (damping) forces
  const char* summary;
};

inline const SchemeInfo& info(Scheme s) {
  static const SchemeInfo table[] = {
      {Scheme::euler, "euler", 1, 1, "explicit Euler"},
      {Scheme::symplectic_euler, "symplectic_euler", 1, 1, "semi-implicit (symplectic) Euler"},
      {Scheme::taylor2, "taylor2", 1, 1, "Taylor, 2nd-order position update"},
      {Scheme::taylor3, "taylor3", 2, 2, "Taylor, 3rd-order, da/dt by differencing"},
      {Scheme::leapfrog, "leapfrog", 2, 1, "leap-frog, half-step velocities"},
      {Scheme::position_verlet, "position_verlet", 2, 1, "position (Stormer) Verlet, differenced velocity"},
      {Scheme::velocity_verlet, "velocity_verlet", 2, 1, "velocity Verlet as fix nve/sphere"},
      {Scheme::velocity_verlet_sync, "velocity_verlet_sync", 2, 2, "velocity Verlet, force with v + h a"},
      {Scheme::beeman, "beeman", 2, 2, "Beeman with velocity predictor"},
      {Scheme::ab2, "ab2", 2, 2, "Adams-Bashforth 2"},
      {Scheme::ab3, "ab3", 3, 3, "Adams-Bashforth 3"},
      {Scheme::ab4, "ab4", 4, 4, "Adams-Bashforth 4"},
      {Scheme::ab5, "ab5", 5, 5, "Adams-Bashforth 5"},
      {Scheme::abm4, "abm4", 4, 4, "Adams-Bashforth-Moulton 4, PEC"},
      {Scheme::gear4, "gear4", 3, 3, "Gear predictor-corrector, 4 values"},
      {Scheme::gear5, "gear5", 4, 4, "Gear predictor-corrector, 5 values"},
      {Scheme::gear6, "gear6", 5, 5, "Gear predictor-corrector, 6 values"},
      {Scheme::velocity_verlet_ab2, "velocity_verlet_ab2", 2, 2, "velocity Verlet, force with v + h (3a - a-)/2"},
  };
  return table[static_cast<int>(s)];
}

// How a scheme moves a body over a step, for the energy balance of contact/energy.h (whose Form
// values these are): 0 kick-drift-kick (velocity Verlet and its variants whose force sees a
// predicted velocity: drift h (v + h a/2)); 1 kick then drift (symplectic Euler, leapfrog with its
// half-step velocity, position Verlet with its differenced one: drift h (v + h a)); -1 neither (no
// balance closes: the residual of form 0 is the scheme's energy error in that sense).
inline int energy_form(Scheme s) {
  switch (s) {
    case Scheme::velocity_verlet:
    case Scheme::velocity_verlet_sync:
    case Scheme::velocity_verlet_ab2: return 0;
    case Scheme::symplectic_euler:
    case Scheme::leapfrog:
    case Scheme::position_verlet: return 1;
    default: return -1;
  }
}

inline bool parse_scheme(const std::string& name, Scheme& out) {
  for (int i = 0; i < static_cast<int>(Scheme::count); ++i) {
    const Scheme s = static_cast<Scheme>(i);
    if (name == info(s).name) {
      out = s;
      return true;
    }
  }
  return false;
}

inline std::string scheme_names(const char* sep = "|") {
  std::string out;
  for (int i = 0; i < static_cast<int>(Scheme::count); ++i) {
    if (i) out += sep;
    out += info(static_cast<Scheme>(i)).name;
  }
  return out;
}

namespace detail {
// Adams-Bashforth weights (times their denominators), newest first.
template <int K> struct AB;
template <> struct AB<2> { static constexpr double w[2] = {3.0, -1.0}; static constexpr double d = 2.0; };
template <> struct AB<3> { static constexpr double w[3] = {23.0, -16.0, 5.0}; static constexpr double d = 12.0; };
template <> struct AB<4> { static constexpr double w[4] = {55.0, -59.0, 37.0, -9.0}; static constexpr double d = 24.0; };
template <> struct AB<5> {
  static constexpr double w[5] = {1901.0, -2774.0, 2616.0, -1274.0, 251.0};
  static constexpr double d = 720.0;
};
// Gear corrector coefficients for a second-order ODE (Allen & Tildesley), c_0 .. c_{q-1}.
template <int Q> struct GearC;
template <> struct GearC<4> { static constexpr double c[4] = {1.0 / 6.0, 5.0 / 6.0, 1.0, 1.0 / 3.0}; };
template <> struct GearC<5> {
  static constexpr double c[5] = {19.0 / 120.0, 3.0 / 4.0, 1.0, 1.0 / 2.0, 1.0 / 12.0};
};
template <> struct GearC<6> {
  static constexpr double c[6] = {3.0 / 20.0, 251.0 / 360.0, 1.0, 11.0 / 18.0, 1.0 / 6.0, 1.0 / 60.0};
};
// Pascal's triangle C(n, k) for n < 7 (the Gear predictor), a table so that the loops use constants
struct Pascal {
  static constexpr double c[7][7] = {{1, 0, 0, 0, 0, 0, 0},   {1, 1, 0, 0, 0, 0, 0},    {1, 2, 1, 0, 0, 0, 0},
                                     {1, 3, 3, 1, 0, 0, 0},   {1, 4, 6, 4, 1, 0, 0},    {1, 5, 10, 10, 5, 1, 0},
                                     {1, 6, 15, 20, 15, 6, 1}};
};
}  // namespace detail

// What start() knows of the motion at the start time t0: the acceleration and, optionally, its
// time derivatives d[1] = da/dt, d[2], ... (up to 4). Hosts know only a (n = 1), which makes the
// start exact for constant acceleration; tests give the exact derivatives for a consistent
// high-order start.
struct Derivs {
  int n = 1;
  const double* d[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
  // a(t0 + t), component k, from the truncated Taylor series
  double a(double t, int k) const {
    double s = 0.0, f = 1.0;
    for (int i = 0; i < n; ++i) {
      s += f * d[i][k];
      f *= t / (i + 1);
    }
    return s;
  }
  // v(t0 + t) - v(t0)
  double dv(double t, int k) const {
    double s = 0.0, f = t;
    for (int i = 0; i < n; ++i) {
      s += f * d[i][k];
      f *= t / (i + 2);
    }
    return s;
  }
  // x(t0 + t) - x(t0) - v(t0) t
  double dx(double t, int k) const {
    double s = 0.0, f = 0.5 * t * t;
    for (int i = 0; i < n; ++i) {
      s += f * d[i][k];
      f *= t / (i + 3);
    }
    return s;
  }
  // i-th derivative of a (0 beyond n)
  double deriv(int i, int k) const { return i < n ? d[i][k] : 0.0; }
};

template <Scheme S, bool kPos> struct Kernel;

// ---------------------------------------------------------------- one-step schemes
template <bool kPos> struct Kernel<Scheme::euler, kPos> {
  static constexpr int history = 0;
  static constexpr bool has_correct = false;
  static void start(double*, double*, const Derivs&, double*, double) {}
  static void predict(double* x, double* v, const double* a, double*, double h) {
    for (int k = 0; k < 3; ++k) {
      if (kPos) x[k] += h * v[k];
      v[k] += h * a[k];
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};

template <bool kPos> struct Kernel<Scheme::symplectic_euler, kPos> {
  static constexpr int history = 0;
  static constexpr bool has_correct = false;
  static void start(double*, double*, const Derivs&, double*, double) {}
  static void predict(double* x, double* v, const double* a, double*, double h) {
    for (int k = 0; k < 3; ++k) {
      v[k] += h * a[k];
      if (kPos) x[k] += h * v[k];
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};

template <bool kPos> struct Kernel<Scheme::taylor2, kPos> {
  static constexpr int history = 0;
  static constexpr bool has_correct = false;
  static void start(double*, double*, const Derivs&, double*, double) {}
  static void predict(double* x, double* v, const double* a, double*, double h) {
    for (int k = 0; k < 3; ++k) {
      if (kPos) x[k] += h * v[k] + 0.5 * h * h * a[k];
      v[k] += h * a[k];
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};

// history: a(n-1)
template <bool kPos> struct Kernel<Scheme::taylor3, kPos> {
  static constexpr int history = 3;
  static constexpr bool has_correct = false;
  static void start(double*, double*, const Derivs& d, double* hist, double h) {
    for (int k = 0; k < 3; ++k) hist[k] = d.a(-h, k);
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      const double b = (a[k] - hist[k]) / h;
      if (kPos) x[k] += h * v[k] + 0.5 * h * h * a[k] + h * h * h * b / 6.0;
      v[k] += h * a[k] + 0.5 * h * h * b;
      hist[k] = a[k];
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};

template <bool kPos> struct Kernel<Scheme::leapfrog, kPos> {
  static constexpr int history = 0;
  static constexpr bool has_correct = false;
  static void start(double*, double* v, const Derivs& d, double*, double h) {
    for (int k = 0; k < 3; ++k) v[k] += d.dv(-0.5 * h, k);
  }
  static void predict(double* x, double* v, const double* a, double*, double h) {
    for (int k = 0; k < 3; ++k) {
      v[k] += h * a[k];
      if (kPos) x[k] += h * v[k];
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};

// history: d = x(n) - x(n-1)
template <bool kPos> struct Kernel<Scheme::position_verlet, kPos> {
  static constexpr int history = 3;
  static constexpr bool has_correct = false;
  static void start(double*, double* v, const Derivs& d, double* hist, double h) {
    for (int k = 0; k < 3; ++k) hist[k] = h * v[k] - d.dx(-h, k);
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      hist[k] += h * h * a[k];
      if (kPos) x[k] += hist[k];
      v[k] = hist[k] / h;
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};

template <bool kPos> struct Kernel<Scheme::velocity_verlet, kPos> {
  static constexpr int history = 0;
  static constexpr bool has_correct = true;
  static void start(double*, double*, const Derivs&, double*, double) {}
  static void predict(double* x, double* v, const double* a, double*, double h) {
    const double hh = 0.5 * h;
    for (int k = 0; k < 3; ++k) {
      v[k] += hh * a[k];
      if (kPos) x[k] += h * v[k];
    }
  }
  static void correct(double*, double* v, const double* a, double*, double h) {
    const double hh = 0.5 * h;
    for (int k = 0; k < 3; ++k) v[k] += hh * a[k];
  }
};

// history: the half-step velocity
template <bool kPos> struct Kernel<Scheme::velocity_verlet_sync, kPos> {
  static constexpr int history = 3;
  static constexpr bool has_correct = true;
  static void start(double*, double*, const Derivs&, double*, double) {}
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      hist[k] = v[k] + 0.5 * h * a[k];
      if (kPos) x[k] += h * hist[k];
      v[k] += h * a[k];
    }
  }
  static void correct(double*, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) v[k] = hist[k] + 0.5 * h * a[k];
  }
};

// history: the half-step velocity, a(n-1)
template <bool kPos> struct Kernel<Scheme::velocity_verlet_ab2, kPos> {
  static constexpr int history = 6;
  static constexpr bool has_correct = true;
  static void start(double*, double*, const Derivs& d, double* hist, double h) {
    for (int k = 0; k < 3; ++k) hist[3 + k] = d.a(-h, k);
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      hist[k] = v[k] + 0.5 * h * a[k];
      if (kPos) x[k] += h * hist[k];
      v[k] += 0.5 * h * (3.0 * a[k] - hist[3 + k]);
      hist[3 + k] = a[k];
    }
  }
  static void correct(double*, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) v[k] = hist[k] + 0.5 * h * a[k];
  }
};

// history: a(n-1), a(n), v(n)
template <bool kPos> struct Kernel<Scheme::beeman, kPos> {
  static constexpr int history = 9;
  static constexpr bool has_correct = true;
  static void start(double*, double*, const Derivs& d, double* hist, double h) {
    for (int k = 0; k < 3; ++k) hist[k] = d.a(-h, k);
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      const double am = hist[k];
      if (kPos) x[k] += h * v[k] + h * h * (4.0 * a[k] - am) / 6.0;
      hist[3 + k] = a[k];
      hist[6 + k] = v[k];
      v[k] += 0.5 * h * (3.0 * a[k] - am);
    }
  }
  static void correct(double*, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      const double am = hist[k], an = hist[3 + k];
      v[k] = hist[6 + k] + h * (2.0 * a[k] + 5.0 * an - am) / 6.0;
      hist[k] = an;
    }
  }
};

// ---------------------------------------------------------------- Adams-Bashforth k
// history: a(n-1) .. a(n-k+1), then (with a position) v(n-1) .. v(n-k+1)
template <int K, bool kPos> struct AdamsBashforth {
  static constexpr int history = 3 * (K - 1) * (kPos ? 2 : 1);
  static constexpr bool has_correct = false;
  static void start(double*, double* v, const Derivs& d, double* hist, double h) {
    for (int j = 1; j < K; ++j)
      for (int k = 0; k < 3; ++k) {
        hist[3 * (j - 1) + k] = d.a(-j * h, k);
        if (kPos) hist[3 * (K - 1) + 3 * (j - 1) + k] = v[k] + d.dv(-j * h, k);
      }
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    using W = detail::AB<K>;
    double* ah = hist;
    double* vh = hist + 3 * (K - 1);
    for (int k = 0; k < 3; ++k) {
      double sa = W::w[0] * a[k], sv = W::w[0] * v[k];
      for (int j = 1; j < K; ++j) {
        sa += W::w[j] * ah[3 * (j - 1) + k];
        if (kPos) sv += W::w[j] * vh[3 * (j - 1) + k];
      }
      for (int j = K - 1; j > 1; --j) {
        ah[3 * (j - 1) + k] = ah[3 * (j - 2) + k];
        if (kPos) vh[3 * (j - 1) + k] = vh[3 * (j - 2) + k];
      }
      ah[k] = a[k];
      if (kPos) {
        vh[k] = v[k];
        x[k] += h * sv / W::d;
      }
      v[k] += h * sa / W::d;
    }
  }
  static void correct(double*, double*, const double*, double*, double) {}
};
template <bool kPos> struct Kernel<Scheme::ab2, kPos> : AdamsBashforth<2, kPos> {};
template <bool kPos> struct Kernel<Scheme::ab3, kPos> : AdamsBashforth<3, kPos> {};
template <bool kPos> struct Kernel<Scheme::ab4, kPos> : AdamsBashforth<4, kPos> {};
template <bool kPos> struct Kernel<Scheme::ab5, kPos> : AdamsBashforth<5, kPos> {};

// ---------------------------------------------------------------- Adams-Bashforth-Moulton 4, PEC
// history (with a position): a(n-1..n-3) [9], v(n-1..n-3) [9], a(n) [3], v(n) [3], x(n) [3] = 27;
// without: a(n-1..n-3) [9], a(n) [3], v(n) [3] = 15.
template <bool kPos> struct Kernel<Scheme::abm4, kPos> {
  static constexpr int history = kPos ? 27 : 15;
  static constexpr bool has_correct = true;
  static constexpr int VH = 9, AN = kPos ? 18 : 9, VN = AN + 3, XN = VN + 3;
  static void start(double*, double* v, const Derivs& d, double* hist, double h) {
    for (int j = 1; j < 4; ++j)
      for (int k = 0; k < 3; ++k) {
        hist[3 * (j - 1) + k] = d.a(-j * h, k);
        if (kPos) hist[VH + 3 * (j - 1) + k] = v[k] + d.dv(-j * h, k);
      }
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      const double* ah = hist;
      const double sa = 55.0 * a[k] - 59.0 * ah[k] + 37.0 * ah[3 + k] - 9.0 * ah[6 + k];
      hist[AN + k] = a[k];
      hist[VN + k] = v[k];
      if (kPos) {
        const double* vh = hist + VH;
        const double sv = 55.0 * v[k] - 59.0 * vh[k] + 37.0 * vh[3 + k] - 9.0 * vh[6 + k];
        hist[XN + k] = x[k];
        x[k] += h * sv / 24.0;
      }
      v[k] += h * sa / 24.0;
    }
  }
  static void correct(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      double* ah = hist;
      const double an = hist[AN + k], vn = hist[VN + k];
      v[k] = vn + h * (9.0 * a[k] + 19.0 * an - 5.0 * ah[k] + ah[3 + k]) / 24.0;
      if (kPos) {
        double* vh = hist + VH;
        x[k] = hist[XN + k] + h * (9.0 * v[k] + 19.0 * vn - 5.0 * vh[k] + vh[3 + k]) / 24.0;
        vh[6 + k] = vh[3 + k];
        vh[3 + k] = vh[k];
        vh[k] = vn;
      }
      ah[6 + k] = ah[3 + k];
      ah[3 + k] = ah[k];
      ah[k] = an;
    }
  }
};

// ---------------------------------------------------------------- Gear predictor-corrector
// history: r3 .. r_{Q-1} [3 ], then the predicted r2 [3].
template <int Q, bool kPos> struct Gear {
  static constexpr int history = 3 * (Q - 2);
  static constexpr bool has_correct = true;
  static void start(double*, double*, const Derivs& d, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      double f = h * h * h / 6.0;  // r_i = h^i x^(i) / i!, x^(i) = d[i-2]
      for (int i = 3; i < Q; ++i) {
        hist[3 * (i - 3) + k] = f * d.deriv(i - 2, k);
        f *= h / (i + 1);
      }
      hist[3 * (Q - 3) + k] = 0.5 * h * h * d.deriv(0, k);
    }
  }
  static void predict(double* x, double* v, const double* a, double* hist, double h) {
    for (int k = 0; k < 3; ++k) {
      double r[Q];
      r[0] = kPos ? x[k] : 0.0;
      r[1] = h * v[k];
      r[2] = 0.5 * h * h * a[k];
      for (int i = 3; i < Q; ++i) r[i] = hist[3 * (i - 3) + k];
      for (int i = kPos ? 0 : 1; i < Q - 1; ++i)
        for (int j = i + 1; j < Q; ++j) r[i] += detail::Pascal::c[j][i] * r[j];
      if (kPos) x[k] = r[0];
      v[k] = r[1] / h;
      for (int i = 3; i < Q; ++i) hist[3 * (i - 3) + k] = r[i];
      hist[3 * (Q - 3) + k] = r[2];
    }
  }
  static void correct(double* x, double* v, const double* a, double* hist, double h) {
    using C = detail::GearC<Q>;
    for (int k = 0; k < 3; ++k) {
      const double delta = 0.5 * h * h * a[k] - hist[3 * (Q - 3) + k];
      if (kPos) x[k] += C::c[0] * delta;
      v[k] += C::c[1] * delta / h;
      for (int i = 3; i < Q; ++i) hist[3 * (i - 3) + k] += C::c[i] * delta;
    }
  }
};
template <bool kPos> struct Kernel<Scheme::gear4, kPos> : Gear<4, kPos> {};
template <bool kPos> struct Kernel<Scheme::gear5, kPos> : Gear<5, kPos> {};
template <bool kPos> struct Kernel<Scheme::gear6, kPos> : Gear<6, kPos> {};

// Start from the acceleration alone (what a host knows): exact for constant acceleration.
template <Scheme S, bool kPos> void start(double* x, double* v, const double* a, double* hist, double h) {
  Derivs d;
  d.d[0] = a;
  Kernel<S, kPos>::start(x, v, d, hist, h);
}

// ---------------------------------------------------------------- run-time dispatch
// dispatch(s, f) calls f(std::integral_constant<Scheme, S>()) for the scheme s, so that a host
// instantiates one loop per scheme: dispatch(s, [&](auto tag) { loop<decltype(tag)::value>(); }).
template <class F> decltype(auto) dispatch(Scheme s, F&& f) {
  switch (s) {
#define TDEM_SCHEME_CASE(N) \
  case Scheme::N: return f(std::integral_constant<Scheme, Scheme::N>());
    TDEM_SCHEME_CASE(euler)
    TDEM_SCHEME_CASE(symplectic_euler)
    TDEM_SCHEME_CASE(taylor2)
    TDEM_SCHEME_CASE(taylor3)
    TDEM_SCHEME_CASE(leapfrog)
    TDEM_SCHEME_CASE(position_verlet)
    TDEM_SCHEME_CASE(velocity_verlet)
    TDEM_SCHEME_CASE(velocity_verlet_sync)
    TDEM_SCHEME_CASE(beeman)
    TDEM_SCHEME_CASE(ab2)
    TDEM_SCHEME_CASE(ab3)
    TDEM_SCHEME_CASE(ab4)
    TDEM_SCHEME_CASE(ab5)
    TDEM_SCHEME_CASE(abm4)
    TDEM_SCHEME_CASE(gear4)
    TDEM_SCHEME_CASE(gear5)
    TDEM_SCHEME_CASE(gear6)
    TDEM_SCHEME_CASE(velocity_verlet_ab2)
#undef TDEM_SCHEME_CASE
    default: break;
  }
  return f(std::integral_constant<Scheme, Scheme::velocity_verlet>());
}

// Per-particle history (doubles) of a scheme: translation channel + rotation channel.
inline int history_per_particle(Scheme s, bool rotation = true) {
  return dispatch(s, [&](auto tag) {
    constexpr Scheme S = decltype(tag)::value;
    return Kernel<S, true>::history + (rotation ? Kernel<S, false>::history : 0);
  });
}
inline bool has_correct(Scheme s) {
  return dispatch(s, [](auto tag) { return Kernel<decltype(tag)::value, true>::has_correct; });
}

}  // namespace integrators
}  // namespace tdem
