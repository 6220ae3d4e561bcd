// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: a single oblique collision (a sphere on a plane wall, or two spheres) with translation and
// rotation in 3D, any normal law object of head_on.h and any tangential law, without a host engine.
//
// Set-up. Sphere 2 (or the wall, the plane z = 0) sits at the origin, sphere 1 touches it from
// +z (overlap xi_start, 0 for every law but a cut-off potential). n is the unit normal from sphere 2
// (the wall) to sphere 1, initially +z. The relative velocity v1 - v2 has speed |v| and makes the
// angle theta with -n: v1 - v2 = |v| (sin theta, 0, -cos theta), sphere 2 at rest. The impact plane
// is x-z; t = +x is the direction of the incoming tangential velocity, and a = t x n = -y is the
// axis of the scalar spins: omega_i = omega_vec_i . a, so that the slip velocity of sphere 1's
// contact point relative to sphere 2's is
//     v_s = v_t + R1 omega_1 + R2 omega_2          (physics_reference.md 3.1; no R2 term on a wall)
// (pure rolling on a wall: v_s = 0, i.e. omega_1 = -v_t/R1). Bodies are solid spheres
// (I = 2/5 m R^2) unless a moment of inertia is given; a wall has m2 = I2 = R2 = infinity.
//
// Integrator: velocity Verlet in the form the hosts use (LIGGGHTS/LAMMPS fix nve/sphere): half kick
// of v and omega with the old force and torque, drift, force evaluation at the new positions with
// the half-step velocities, second half kick. The tangential laws keep incremental history
// (s += v_t dt with the half-step slip velocity: the midpoint rule), the normal law commits its
// history after every accepted step (update = true). The contact starts at touch with the forces
// evaluated at t = 0 (normal law with update = true, which lets the extended laws take v0;
// tangential law with update = false, so the first step adds v_t dt once). The end of contact is
// located inside the last step: the step length h in (0, dt] at which the end condition first holds
// (zero_overlap: xi <= xi_start; zero_force: the normal force <= 0 while xi' < 0) is found by
// bisection of a partial step (to 1e-15 dt), and that partial step is taken. The scheme is first
// order in dt for velocity-dependent forces (like the hosts' scheme), so fine steps are the default:
// 1e5 per estimated contact time (a single contact takes a few milliseconds).
//
// Forces: F_1 = F_n n + F_t, F_2 = -F_1; torques tau_1 = -c_1 n x F_t, tau_2 = -c_2 n x F_t with
// the lever arm c_i = R_i (LeverArm::radius, the model of physics_reference.md 4 and 8.5) or
// c_i = R_i - xi/2 (LeverArm::contact_point, what LIGGGHTS' surface model uses); the same c_i
// enter the slip velocity v_t = tangential part of (v1 - v2 - (c_1 omega_1 + c_2 omega_2) x n).
//
// Results are given in the contact frame at separation (for a wall the frame never turns; for two
// spheres n is the line of centres at separation, t = n x a): e = v_n'/v_n0, v_t', the slip
// velocity v_s' = v_t' + R1 omega_1' + R2 omega_2', beta = -v_s'/v_s0, e_t = v_t'/v_t0, spins after,
// rebound angles atan2(v_t', v_n') (centre of mass) and atan2(v_s', v_n') (contact point), and
// Maw-Barber-Fawcett's dimensionless angles with the normalisation kappa/mu:
//     psi_1 = kappa v_s0/(mu v_n0),   psi_2 = kappa v_s'/(mu v_n0)
// (kappa = k_t/k_n for linear laws, 2(1-nu)/(2-nu) for Hertz-Mindlin; NaN if not given). The
// un-scaled slip ratios v_s0/(mu v_n0), v_s'/(mu v_n0) (the columns of physics_reference 8.5) are
// given too.
//
// Tangential law objects (interface used by integrate_oblique()):
//   bool force(const tangential::TangentialKinematics<double>& k, bool update, double* ft);
//                      tangential force on sphere 1 into ft; returns true while sliding
//   double friction() const;   Coulomb coefficient mu (for psi; 0 if none)
//   void reset();              clears the per-contact history
// TangentialKernelLaw<> wraps any kernel of src/contact/tangential written to the interface of
// common.h (Params<T>, history_size, force(p, k, hist, update, ft)); CundallStrackTangential adapts
// the older cundall_strack kernel; Frictionless gives F_t = 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision/head_on.h"
#include "collision/rigid_body.h"
#include "contact/tangential/common.h"
#include "contact/tangential/cundall_strack.h"

namespace tdem {
namespace collision {

// ---------------------------------------------------------------- tangential law objects
using TangentialKin = tangential::TangentialKinematics<double>;

struct Frictionless {
  bool force(const TangentialKin&, bool, double* ft) {
    ft[0] = ft[1] = ft[2] = 0.0;
    return false;
  }
  double friction() const { return 0.0; }
  void reset() {}
};

// Any kernel with the common.h interface:
//   template <class T> bool force(const Params<T>&, const TangentialKinematics<T>&, T* hist, bool update, T* ft)
// e.g. TangentialKernelLaw<law::Params<double>, law::history_size, &law::force<double>>.
template <class P, int N, bool (*F)(const P&, const TangentialKin&, double*, bool, double*) noexcept>
struct TangentialKernelLaw {
  P p{};
  double hist[N > 0 ? N : 1] = {0.0};
  bool force(const TangentialKin& k, bool update, double* ft) { return F(p, k, hist, update, ft); }
  double friction() const { return p.mu; }
  void reset() { std::fill(std::begin(hist), std::end(hist), 0.0); }
};

// The Cundall-Strack kernel (src/contact/tangential/cundall_strack.h) behind the same interface.
// Its limit is mu |F_n|; FrictionLimit::positive_normal hands it max(F_n, 0) instead. Sliding is
// reported when the cap acts (the spring force, or spring plus dashpot for spring_dashpot_cap,
// exceeds the limit).
struct CundallStrackTangential {
  cundall_strack::Params<double> p{0.0, 0.0, 0.0};  // k_t [N/m], gamma_t [kg/s], mu
  cundall_strack::SlipRule rule = cundall_strack::SlipRule::spring_cap;
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  double hist[cundall_strack::history_size] = {0.0, 0.0, 0.0};

  bool force(const TangentialKin& k, bool update, double* ft) {
    const cundall_strack::Kinematics<double> kin{{k.n[0], k.n[1], k.n[2]}, 1.0, {k.vt[0], k.vt[1], k.vt[2]}, k.dt};
    const double fn = limit == tangential::FrictionLimit::absolute ? k.fn : std::max(k.fn, 0.0);
    // The kernel's own trial state, to tell whether the cap acts.
    double s[3] = {hist[0], hist[1], hist[2]};
    if (update) {
      for (int i = 0; i < 3; ++i) s[i] += k.vt[i] * k.dt;
      const double sn = tangential::dot(s, k.n);
      for (int i = 0; i < 3; ++i) s[i] -= sn * k.n[i];
    }
    double trial[3];
    const bool dash = rule == cundall_strack::SlipRule::spring_dashpot_cap;
    for (int i = 0; i < 3; ++i) trial[i] = p.kt * s[i] + (dash ? p.gammat * k.vt[i] : 0.0);
    const double lim = p.mu * std::fabs(fn);
    const bool sliding = tangential::dot(trial, trial) > lim * lim;
    cundall_strack::force(rule, p, kin, fn, update, hist, ft);
    return sliding;
  }
  double friction() const { return p.mu; }
  void reset() { std::fill(std::begin(hist), std::end(hist), 0.0); }
};

// ---------------------------------------------------------------- set-up and results
enum class LeverArm { radius, contact_point };

inline const char* to_string(LeverArm l) { return l == LeverArm::radius ? "radius" : "contact_point"; }

struct ObliqueBodies {
  double m1 = 0.0, R1 = 0.0, I1 = 0.0;                 // I1 = 0: solid sphere 2/5 m1 R1^2
  double m2 = INFINITY, R2 = INFINITY, I2 = 0.0;        // m2 = R2 = inf: a plane wall
  bool wall() const { return std::isinf(m2) && std::isinf(R2); }
  double inertia1() const { return I1 > 0.0 ? I1 : rigid_body::solid_sphere_inertia(m1, R1); }
  double inertia2() const { return wall() ? INFINITY : (I2 > 0.0 ? I2 : rigid_body::solid_sphere_inertia(m2, R2)); }
  double meff() const { return hertz::effective_mass(m1, m2); }
  double reff() const { return hertz::effective_radius(R1, R2); }
};

struct ObliqueImpact {
  double speed = 0.0;   // |v1 - v2| [m/s] > 0
  double angle = 0.0;   // theta from the normal [rad], [0, pi/2)
  double omega1 = 0.0;  // initial scalar spins [1/s] (convention: see the header)
  double omega2 = 0.0;
};

struct ObliqueOptions {
  long steps_per_contact = 100000;   // dt = t_c(estimate)/steps_per_contact when dt <= 0
  double dt = 0.0;                   // fixed step [s]
  double max_contact_times = 100.0;  // give up after this many estimated contact times
  long max_steps = 400000000;
  LeverArm lever = LeverArm::radius;
  double kappa = NAN;                // for psi_1, psi_2 (NaN: not given)
  bool record = false;               // keep the samples
  int max_switches = 1000;           // stick/slip switches kept
};

struct ObliqueSample {
  double t, xi, xi_dot, fn, ft, vs;  // ft, vs: components along t = n x a
  bool sliding;
};

struct StickSlipSwitch {
  double t;      // time of the first step in the new state [s]
  bool sliding;  // the new state
};

struct ObliqueResult {
  bool ended = false;
  // before (t = 0)
  double vn0 = 0.0, vt0 = 0.0, vs0 = 0.0, omega1_0 = 0.0, omega2_0 = 0.0;
  double impact_angle = 0.0, impact_angle_contact = 0.0;  // atan2(v_t0, v_n0), atan2(v_s0, v_n0) [rad]
  // after, in the contact frame at separation
  double e = NAN, vn = NAN, vt = NAN, vs = NAN, omega1 = NAN, omega2 = NAN;
  double beta = NAN, e_t = NAN;
  double rebound_angle_com = NAN, rebound_angle_contact = NAN;  // [rad]
  double mu = 0.0, kappa = NAN;
  double slip_ratio_in = NAN, slip_ratio_out = NAN;  // v_s0/(mu v_n0), v_s'/(mu v_n0)
  double psi1 = NAN, psi2 = NAN;                     // kappa times the slip ratios
  double normal_turn = 0.0;  // angle between the normal at touch and at separation [rad]
  // the contact
  double contact_time = NAN, max_overlap = 0.0, max_normal_force = 0.0, max_tangential_force = 0.0;
  double residual_overlap = NAN;   // xi at separation [m] (xi_start for the zero_overlap end)
  double dissipated_energy = NAN;  // kinetic energy (translation and rotation) lost [J]
  double m_n = 0.0, m_t = 0.0;  // normal and tangential effective masses
  bool sliding_at_start = false;
  std::vector<StickSlipSwitch> switches;
  long n_switches = 0;  // all of them (switches keeps the first max_switches)
  double dt = 0.0, contact_time_estimate = 0.0;
  long steps = 0;
  std::vector<ObliqueSample> samples;
};

// The ratios of a result whose velocities before (vn0, vt0, vs0) and after (vn, vt, vs) are set:
// e, beta, e_t, the rebound angles, the slip ratios (mu > 0) and psi = kappa times them.
inline void set_ratios(ObliqueResult& r) {
  r.e = r.vn / r.vn0;
  r.beta = r.vs0 != 0.0 ? -r.vs / r.vs0 : NAN;
  r.e_t = r.vt0 != 0.0 ? r.vt / r.vt0 : NAN;
  r.rebound_angle_com = std::atan2(r.vt, r.vn);
  r.rebound_angle_contact = std::atan2(r.vs, r.vn);
  if (r.mu > 0.0) {
    r.slip_ratio_in = r.vs0 / (r.mu * r.vn0);
    r.slip_ratio_out = r.vs / (r.mu * r.vn0);
    r.psi1 = r.kappa * r.slip_ratio_in;
    r.psi2 = r.kappa * r.slip_ratio_out;
  }
}

inline void validate(const ObliqueBodies& b) {
  checks::positive("mass m1", b.m1);
  checks::positive("radius R1", b.R1);
  if (!(b.I1 >= 0.0) || !std::isfinite(b.I1)) checks::fail("moment of inertia I1", b.I1, "[0, inf) (0: solid sphere)");
  if (!b.wall()) {
    if (!(b.m2 > 0.0)) checks::fail("mass m2", b.m2, "(0, inf]");
    checks::positive("radius R2", b.R2);
    if (!(b.I2 >= 0.0)) checks::fail("moment of inertia I2", b.I2, "[0, inf] (0: solid sphere)");
  }
}

inline void validate(const ObliqueImpact& i) {
  checks::positive("impact speed |v|", i.speed);
  if (!(i.angle >= 0.0 && i.angle < 0.5 * M_PI))
    throw std::domain_error("impact angle theta = " + checks::number(i.angle * 180.0 / M_PI) +
                            " deg is outside the allowed range [0, 90) deg");
  if (!std::isfinite(i.omega1)) checks::fail("spin omega1", i.omega1, "(-inf, inf)");
  if (!std::isfinite(i.omega2)) checks::fail("spin omega2", i.omega2, "(-inf, inf)");
}

inline void validate(const ObliqueOptions& o) {
  if (!(o.dt >= 0.0) || !std::isfinite(o.dt)) checks::fail("time step dt", o.dt, "[0, inf)");
  if (o.dt == 0.0 && o.steps_per_contact < 1) checks::fail("steps per contact", o.steps_per_contact, "[1, inf)");
}

// The rigid-body (Walton) prediction for the same bodies and impact, with e and mu given.
inline rigid_body::Output rigid_body_prediction(const ObliqueBodies& b, const ObliqueImpact& i, double e, double mu,
                                                double beta0) {
  rigid_body::Input in;
  in.e = e;
  in.mu = mu;
  in.beta0 = beta0;
  in.m1 = b.m1, in.R1 = b.R1, in.I1 = b.inertia1();
  in.m2 = b.m2, in.R2 = b.R2, in.I2 = b.inertia2();
  in.vn0 = i.speed * std::cos(i.angle);
  in.vt0 = i.speed * std::sin(i.angle);
  in.omega1 = i.omega1;
  in.omega2 = i.omega2;
  return rigid_body::impact(in);
}

namespace detail {
struct V3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(V3 a) { return std::sqrt(dot(a, a)); }

// The state of the pair; forces and torques are those of the last evaluation.
struct State {
  V3 x1, x2, v1, v2, w1, w2;
  V3 f1, tq1, tq2;  // force on 1 (2 gets -f1), torques
};
}  // namespace detail

// ---------------------------------------------------------------- the integrator
template <class NormalLaw, class TangentialLaw>
ObliqueResult integrate_oblique(NormalLaw& normal, TangentialLaw& tang, const ObliqueBodies& bodies,
                                const ObliqueImpact& impact, const ObliqueOptions& opt = ObliqueOptions()) {
  using detail::V3;
  validate(bodies);
  validate(impact);
  validate(opt);
  const bool wall = bodies.wall();
  const double m1 = bodies.m1, R1 = bodies.R1, I1 = bodies.inertia1();
  const double m2 = bodies.m2, R2 = bodies.R2, I2 = bodies.inertia2();
  const double meff = bodies.meff();
  const double reff = bodies.reff();
  const double inv_m2 = wall ? 0.0 : 1.0 / m2, inv_I2 = wall || std::isinf(I2) ? 0.0 : 1.0 / I2;
  normal.reset();
  tang.reset();

  ObliqueResult r;
  r.m_n = meff;
  r.m_t = rigid_body::tangential_mass(m1, R1, I1, m2, R2, I2);
  r.vn0 = impact.speed * std::cos(impact.angle);
  r.vt0 = impact.speed * std::sin(impact.angle);
  r.omega1_0 = impact.omega1;
  r.omega2_0 = wall ? 0.0 : impact.omega2;
  r.vs0 = r.vt0 + R1 * r.omega1_0 + (wall ? 0.0 : R2 * r.omega2_0);
  r.impact_angle = std::atan2(r.vt0, r.vn0);
  r.impact_angle_contact = std::atan2(r.vs0, r.vn0);
  r.mu = tang.friction();
  r.kappa = opt.kappa;
  r.contact_time_estimate = normal.contact_time_estimate(meff, reff, r.vn0);
  if (!(r.contact_time_estimate > 0.0) || !std::isfinite(r.contact_time_estimate))
    throw std::domain_error("estimated contact time = " + checks::number(r.contact_time_estimate) +
                            " is not a positive finite number; give a time step dt");
  const double dt = opt.dt > 0.0 ? opt.dt : r.contact_time_estimate / static_cast<double>(opt.steps_per_contact);
  r.dt = dt;
  const double t_max = std::max(opt.max_contact_times * r.contact_time_estimate, 10.0 * dt);
  const double xi_start = normal.start_overlap();
  const bool zero_force = normal.end() == ContactEnd::zero_force;
  const double lever_f = opt.lever == LeverArm::contact_point ? 0.5 : 0.0;

  const V3 axis{0.0, -1.0, 0.0};  // a = t x n with t = +x, n = +z
  detail::State s;
  s.x2 = {0.0, 0.0, 0.0};
  s.x1 = {0.0, 0.0, (wall ? R1 : R1 + R2) - xi_start};
  s.v1 = {r.vt0, 0.0, -r.vn0};
  s.v2 = {0.0, 0.0, 0.0};
  s.w1 = impact.omega1 * axis;
  s.w2 = wall ? V3{} : impact.omega2 * axis;

  // Geometry at positions (x1, x2): unit normal from 2 to 1 and overlap.
  auto geometry = [&](const V3& x1, const V3& x2, V3& n, double& xi) {
    if (wall) {
      n = {0.0, 0.0, 1.0};
      xi = R1 - x1.z;
    } else {
      const V3 d = x1 - x2;
      const double dist = detail::norm(d);
      n = (1.0 / dist) * d;
      xi = R1 + R2 - dist;
    }
  };
  auto overlap_rate = [&](const V3& v1, const V3& v2, const V3& n) { return -detail::dot(v1 - v2, n); };

  // Evaluates the forces at state st (positions and the velocities to use), step h; returns the
  // normal result and sets st.f1, st.tq1, st.tq2 and the sliding flag.
  struct Eval {
    NormalResult<double> nr;
    double xi, xi_dot, ft_t, vs_t;
    bool sliding;
    V3 n;
  };
  auto evaluate = [&](detail::State& st, double h, bool update_tangential) {
    Eval ev;
    geometry(st.x1, st.x2, ev.n, ev.xi);
    const V3& n = ev.n;
    ev.xi_dot = overlap_rate(st.v1, st.v2, n);
    ev.nr = normal.force(ev.xi, ev.xi_dot, meff, reff, true);
    const double xi_pos = std::max(ev.xi, 0.0);
    const double c1 = R1 - lever_f * xi_pos, c2 = wall ? 0.0 : R2 - lever_f * xi_pos;
    const V3 vr = st.v1 - st.v2 - detail::cross(c1 * st.w1 + c2 * st.w2, n);
    const V3 vt = vr - detail::dot(vr, n) * n;
    TangentialKin k;
    k.n[0] = n.x, k.n[1] = n.y, k.n[2] = n.z;
    k.vt[0] = vt.x, k.vt[1] = vt.y, k.vt[2] = vt.z;
    k.spin_n = 0.5 * detail::dot(st.w1 + st.w2, n);
    k.dt = h;
    k.overlap = xi_pos;
    k.meff = meff;
    k.reff = reff;
    k.fn = ev.nr.force;
    k.kn = ev.nr.stiffness;
    k.gamman = ev.nr.damping;
    if (!wall) {  // the turning rate of the line of centres, n x dn/dt = n x (v1 - v2) / |x1 - x2|
      const V3 dx = st.x1 - st.x2;
      const V3 wt = (1.0 / std::sqrt(detail::dot(dx, dx))) * detail::cross(n, st.v1 - st.v2);
      k.omega_t[0] = wt.x, k.omega_t[1] = wt.y, k.omega_t[2] = wt.z;
    }
    double ft[3] = {0.0, 0.0, 0.0};
    ev.sliding = tang.force(k, update_tangential, ft);
    const V3 Ft{ft[0], ft[1], ft[2]};
    st.f1 = ev.nr.force * n + Ft;
    const V3 nxf = detail::cross(n, Ft);
    st.tq1 = (-c1) * nxf;
    st.tq2 = (-c2) * nxf;
    const V3 tdir = detail::cross(n, axis);
    ev.ft_t = detail::dot(Ft, tdir);
    ev.vs_t = detail::dot(vt, tdir);
    return ev;
  };
  // Half kick with the stored forces and drift: the state of a partial step of length h before the
  // force evaluation.
  auto kick_drift = [&](const detail::State& st, double h) {
    detail::State o = st;
    o.v1 = st.v1 + (0.5 * h / m1) * st.f1;
    o.v2 = st.v2 - (0.5 * h * inv_m2) * st.f1;
    o.w1 = st.w1 + (0.5 * h / I1) * st.tq1;
    o.w2 = st.w2 + (0.5 * h * inv_I2) * st.tq2;
    o.x1 = st.x1 + h * o.v1;
    o.x2 = st.x2 + h * o.v2;
    return o;
  };
  auto kick = [&](detail::State& st, double h) {
    st.v1 = st.v1 + (0.5 * h / m1) * st.f1;
    st.v2 = st.v2 - (0.5 * h * inv_m2) * st.f1;
    st.w1 = st.w1 + (0.5 * h / I1) * st.tq1;
    st.w2 = st.w2 + (0.5 * h * inv_I2) * st.tq2;
  };
  // End of contact after a partial step of length h from st (normal law not committed).
  auto ended_after = [&](const detail::State& st, double h) {
    const detail::State o = kick_drift(st, h);
    V3 n;
    double xi;
    geometry(o.x1, o.x2, n, xi);
    if (xi <= xi_start) return true;
    if (!zero_force) return false;
    const double xd = overlap_rate(o.v1, o.v2, n);
    return xd < 0.0 && normal.force(xi, xd, meff, reff, false).force <= 0.0;
  };
  auto record = [&](double t, const Eval& ev) {
    r.max_overlap = std::max(r.max_overlap, ev.xi);
    r.max_normal_force = std::max(r.max_normal_force, ev.nr.force);
    r.max_tangential_force = std::max(r.max_tangential_force, std::fabs(ev.ft_t));
    if (opt.record) r.samples.push_back({t, ev.xi, ev.xi_dot, ev.nr.force, ev.ft_t, ev.vs_t, ev.sliding});
  };

  auto kinetic_energy = [&](const detail::State& st) {
    double ke = 0.5 * m1 * detail::dot(st.v1, st.v1) + 0.5 * I1 * detail::dot(st.w1, st.w1);
    if (!wall) {
      if (std::isfinite(m2)) ke += 0.5 * m2 * detail::dot(st.v2, st.v2);
      if (std::isfinite(I2)) ke += 0.5 * I2 * detail::dot(st.w2, st.w2);
    }
    return ke;
  };
  const double ke0 = kinetic_energy(s);

  // t = 0: forces at touch (a zero step: the tangential history is not advanced).
  double t = 0.0;
  Eval ev = evaluate(s, 0.0, false);
  r.sliding_at_start = ev.sliding;
  bool sliding = ev.sliding;
  record(t, ev);

  bool end_here = false;
  while (t < t_max && r.steps < opt.max_steps) {
    double h = dt;
    if (ended_after(s, dt)) {
      double lo = 0.0, hi = dt;
      for (int i = 0; i < 200 && hi - lo > 1e-15 * dt; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (ended_after(s, mid)) hi = mid; else lo = mid;
      }
      h = hi;
      end_here = true;
    }
    detail::State next = kick_drift(s, h);
    ev = evaluate(next, h, true);
    kick(next, h);
    if (!std::isfinite(next.v1.x) || !std::isfinite(next.v1.z) || !std::isfinite(next.w1.y)) break;
    s = next;
    t += h;
    ++r.steps;
    record(t, ev);
    if (ev.sliding != sliding) {
      sliding = ev.sliding;
      if (static_cast<int>(r.switches.size()) < opt.max_switches) r.switches.push_back({t, sliding});
      ++r.n_switches;
    }
    if (end_here) break;
  }
  if (!end_here) return r;

  // Outcome in the contact frame at separation.
  r.ended = true;
  r.contact_time = t;
  V3 n;
  double xi;
  geometry(s.x1, s.x2, n, xi);
  const V3 tdir = detail::cross(n, axis);
  const V3 vrel = s.v1 - s.v2;
  r.normal_turn = std::atan2(detail::norm(detail::cross(n, V3{0.0, 0.0, 1.0})), n.z);
  r.vn = detail::dot(vrel, n);
  r.vt = detail::dot(vrel, tdir);
  r.omega1 = detail::dot(s.w1, axis);
  r.omega2 = wall ? 0.0 : detail::dot(s.w2, axis);
  r.vs = r.vt + R1 * r.omega1 + (wall ? 0.0 : R2 * r.omega2);
  r.residual_overlap = std::max(xi, xi_start);
  r.dissipated_energy = ke0 - kinetic_energy(s);
  set_ratios(r);
  return r;
}

}  // namespace collision
}  // namespace tdem
