// SPDX-License-Identifier: GPL-2.0-or-later
// Moving grate core (src/fixes/grate): bar kinematics against closed forms, grate geometry, VTK output,
// and the mixing measures of physics_reference.md 7.2 on constructed beds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fixes/grate/geometry.h"
#include "fixes/grate/kinematics.h"
#include "fixes/mixing/mixing.h"

using namespace tdem::grate;
using namespace tdem;
namespace mx = tdem::grate::mixing;

namespace {
constexpr double kPi = 3.14159265358979323846;

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
}  // namespace

// ------------------------------------------------------------------------------------ kinematics

TEST(GrateKinematics, SinusoidalFollowsClosedForm) {
  MotionParams m;
  m.stroke = 0.12;
  m.period = 2.5;
  m.t_start = 0.3;
  validate(m);
  for (int i = 0; i <= 200; ++i) {
    const double t = 0.3 + 0.0371 * i;
    const double w = 2.0 * kPi / m.period;
    const MotionState s = evaluate(m, t);
    EXPECT_NEAR(s.u, 0.5 * m.stroke * (1.0 - std::cos(w * (t - 0.3))), 1e-14) << t;
    EXPECT_NEAR(s.v, 0.5 * m.stroke * w * std::sin(w * (t - 0.3)), 1e-13) << t;
    EXPECT_NEAR(s.a, 0.5 * m.stroke * w * w * std::cos(w * (t - 0.3)), 1e-12) << t;
  }
  // before the start: at home and at rest
  const MotionState s0 = evaluate(m, 0.2);
  EXPECT_EQ(s0.u, 0.0);
  EXPECT_EQ(s0.v, 0.0);
  EXPECT_NEAR(max_speed(m), 0.5 * m.stroke * 2.0 * kPi / m.period, 1e-14);
}

TEST(GrateKinematics, PhaseGroupLagsByPhaseTimesPeriod) {
  MotionParams m;
  m.profile = Profile::trapezoidal_accel;
  m.stroke = 0.1;
  m.period = 1.3;
  m.dwell_out = 0.1;
  m.dwell_home = 0.2;
  validate(m);
  const double phase = 0.35;
  for (int i = 0; i < 300; ++i) {
    const double t = 0.011 * i;
    const MotionState a = evaluate(m, t, phase);
    if (t < phase * m.period) {
      EXPECT_EQ(a.u, 0.0);
      EXPECT_EQ(a.v, 0.0);
    } else {
      const MotionState b = evaluate(m, t - phase * m.period, 0.0);
      EXPECT_NEAR(a.u, b.u, 1e-14);
      EXPECT_NEAR(a.v, b.v, 1e-12);
    }
  }
}

// Linear ramps with dwells: the position is the trapezoid written out piece by piece.
TEST(GrateKinematics, TrapezoidalLinearClosedForm) {
  MotionParams m;
  m.profile = Profile::trapezoidal;
  m.stroke = 0.08;
  m.period = 2.0;
  m.dwell_out = 0.2;   // 0.4 s
  m.dwell_home = 0.1;  // 0.2 s
  m.forward_share = 0.6;  // moving 1.4 s: out 0.84 s, back 0.56 s
  validate(m);
  auto expect = [&](double t, double u, double v) {
    const MotionState s = evaluate(m, t);
    EXPECT_NEAR(s.u, u, 1e-14) << t;
    EXPECT_NEAR(s.v, v, 1e-13) << t;
  };
  for (int cyc = 0; cyc < 3; ++cyc) {
    const double t0 = 2.0 * cyc;
    for (double s : {0.0, 0.1, 0.42, 0.8}) expect(t0 + s, 0.08 * s / 0.84, 0.08 / 0.84);
    for (double s : {0.85, 1.0, 1.2}) expect(t0 + s, 0.08, 0.0);
    for (double s : {1.25, 1.5, 1.75}) expect(t0 + s, 0.08 * (1.0 - (s - 1.24) / 0.56), -0.08 / 0.56);
    for (double s : {1.81, 1.9, 1.99}) expect(t0 + s, 0.0, 0.0);
  }
  EXPECT_NEAR(max_speed(m), 0.08 / 0.56, 1e-14);
}

// Acceleration-limited trapezoid: closed forms of a trapezoidal velocity (area = stroke).
TEST(GrateKinematics, TrapezoidalAccelClosedForm) {
  MotionParams m;
  m.profile = Profile::trapezoidal_accel;
  m.stroke = 0.15;
  m.period = 1.0;
  m.dwell_out = 0.25;
  m.dwell_home = 0.25;
  m.ramp = 0.2;  // each stroke 0.25 s, ramps 0.05 s
  validate(m);
  const double d = 0.25, ta = 0.05;
  const double vmax = m.stroke / (d - ta);  // area of the trapezoid = stroke
  const double acc = vmax / ta;
  // acceleration phase: u = a t^2 / 2
  for (double t : {0.0, 0.01, 0.03, 0.0499}) {
    EXPECT_NEAR(evaluate(m, t).u, 0.5 * acc * t * t, 1e-14);
    EXPECT_NEAR(evaluate(m, t).v, acc * t, 1e-12);
    EXPECT_NEAR(evaluate(m, t).a, acc, 1e-9);
  }
  // cruise: constant vmax, half stroke at mid-stroke by symmetry
  for (double t : {0.06, 0.1, 0.19}) EXPECT_NEAR(evaluate(m, t).v, vmax, 1e-12);
  EXPECT_NEAR(evaluate(m, 0.125).u, 0.5 * m.stroke, 1e-14);
  // deceleration ends at the full stroke with zero velocity
  EXPECT_NEAR(evaluate(m, 0.2499999).u, m.stroke, 1e-10);
  EXPECT_NEAR(evaluate(m, 0.2499999).v, 0.0, 1e-4);
  EXPECT_NEAR(evaluate(m, 0.3).u, m.stroke, 0.0);
  // return stroke mirrors the outward one
  for (double s : {0.01, 0.07, 0.125, 0.2, 0.24})
    EXPECT_NEAR(evaluate(m, 0.5 + s).u, m.stroke - evaluate(m, s).u, 1e-14);
  EXPECT_NEAR(max_speed(m), vmax, 1e-14);
}

// For every profile: continuity of u, v = du/dt (central differences), stroke and period respected.
TEST(GrateKinematics, ContinuityDerivativeStrokeAndPeriod) {
  for (Profile pr : {Profile::sinusoidal, Profile::trapezoidal, Profile::trapezoidal_accel}) {
    MotionParams m;
    m.profile = pr;
    m.stroke = 0.1;
    m.period = 0.8;
    m.dwell_out = pr == Profile::sinusoidal ? 0.0 : 0.15;
    m.dwell_home = pr == Profile::sinusoidal ? 0.0 : 0.1;
    m.forward_share = 0.4;
    m.ramp = 0.3;
    validate(m);
    double umax = -1.0, umin = 1.0, vmax = 0.0;
    const double h = 1e-6;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(0.0, 4.0 * m.period);
    for (int i = 0; i < 4000; ++i) {
      const double t = U(rng);
      const MotionState s = evaluate(m, t);
      umax = std::max(umax, s.u);
      umin = std::min(umin, s.u);
      vmax = std::max(vmax, std::fabs(s.v));
      // periodicity
      EXPECT_NEAR(evaluate(m, t + m.period).u, s.u, 1e-13);
      // continuity: |du| over 2h bounded by the largest speed
      const double du = std::fabs(evaluate(m, t + h).u - evaluate(m, t - h).u);
      EXPECT_LE(du, 2.0 * h * max_speed(m) * (1.0 + 1e-6) + 1e-15) << profile_name(pr) << " t " << t;
      // derivative (skip the velocity jumps of the linear trapezoid)
      const MotionState a = evaluate(m, t - h), b = evaluate(m, t + h);
      if (pr == Profile::trapezoidal && a.v != b.v) continue;
      const double fd = (b.u - a.u) / (2.0 * h);
      EXPECT_NEAR(fd, s.v, 1e-5 * max_speed(m)) << profile_name(pr) << " t " << t;
    }
    // the sampled range reaches the stroke (dwells) and home
    if (pr != Profile::sinusoidal) {
      EXPECT_EQ(umax, m.stroke) << profile_name(pr);
      EXPECT_EQ(umin, 0.0) << profile_name(pr);
    } else {
      EXPECT_NEAR(umax, m.stroke, 1e-4);
      EXPECT_NEAR(umin, 0.0, 1e-4);
    }
    EXPECT_LE(umax, m.stroke);
    EXPECT_GE(umin, 0.0);
    EXPECT_LE(vmax, max_speed(m) * (1.0 + 1e-12));
    // continuity exactly at the segment boundaries
    const double move = 1.0 - m.dwell_out - m.dwell_home;
    const double tf = m.forward_share * move * m.period, to = tf + m.dwell_out * m.period,
                 tr = to + (1.0 - m.forward_share) * move * m.period;
    for (double tb : {tf, to, tr, m.period}) {
      const double eps = 1e-9;
      EXPECT_NEAR(evaluate(m, tb - eps).u, evaluate(m, tb + eps).u, 1e-8) << profile_name(pr) << " tb " << tb;
      if (pr != Profile::trapezoidal) {
        EXPECT_NEAR(evaluate(m, tb - eps).v, evaluate(m, tb + eps).v, 1e-5) << profile_name(pr) << " tb " << tb;
      }
    }
  }
}

TEST(GrateKinematics, BadInputNamesKeywordValueAndRange) {
  MotionParams m;
  m.ramp = 0.7;
  std::string e = error_of([&] { validate(m); });
  EXPECT_NE(e.find("'ramp'"), std::string::npos) << e;
  EXPECT_NE(e.find("0.7"), std::string::npos) << e;
  EXPECT_NE(e.find("(0, 0.5]"), std::string::npos) << e;
  m = MotionParams{};
  m.period = -1.0;
  e = error_of([&] { validate(m); });
  EXPECT_NE(e.find("'period'"), std::string::npos) << e;
  m = MotionParams{};
  m.dwell_out = 0.6;
  m.dwell_home = 0.5;
  e = error_of([&] { validate(m); });
  EXPECT_NE(e.find("dwell_out + dwell_home"), std::string::npos) << e;
  e = error_of([&] { parse_profile("cosine"); });
  EXPECT_NE(e.find("'profile'"), std::string::npos) << e;
  EXPECT_NE(e.find("cosine"), std::string::npos) << e;
  EXPECT_NE(e.find("trapezoidal_accel"), std::string::npos) << e;
  EXPECT_EQ(parse_profile("trapezoidal"), Profile::trapezoidal);
}

// ------------------------------------------------------------------------------------ geometry

namespace {
GrateParams base_params() {
  GrateParams p;
  p.rows = 5;
  p.bar_length = 0.3;
  p.bar_height = 0.06;
  p.step_height = 0.04;
  p.overlap = 0.05;
  p.declination_deg = 15.0;
  p.width = 0.25;
  p.origin = {1.0, 2.0, 3.0};
  p.motion.stroke = 0.1;
  p.motion.period = 2.0;
  return p;
}
}  // namespace

TEST(GrateGeometry, RestLayoutFollowsConvention) {
  const GrateParams p = base_params();
  const Grate g(p);
  const auto b = g.boxes(0.0);
  ASSERT_EQ(b.size(), 5u);
  const double a = 15.0 * kPi / 180.0;
  const Vec3 et{std::cos(a), 0.0, -std::sin(a)}, en{std::sin(a), 0.0, std::cos(a)};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(b[i].row, i);
    EXPECT_EQ(b[i].kind, i % 2 ? BoxKind::moving_bar : BoxKind::fixed_bar);
    // heel of the top face: centre - L/2 e_t + h/2 e_n
    const Vec3 heel = b[i].centre - 0.15 * et + 0.03 * en;
    EXPECT_NEAR(heel.x, 1.0 + i * 0.25 * std::cos(a), 1e-13);
    EXPECT_NEAR(heel.y, 2.0, 1e-13);
    EXPECT_NEAR(heel.z, 3.0 - i * 0.25 * std::sin(a) - i * 0.04, 1e-13);
    EXPECT_NEAR(b[i].half.x, 0.15, 0);
    EXPECT_NEAR(b[i].half.y, 0.125, 0);
    EXPECT_NEAR(b[i].half.z, 0.03, 0);
    // orthonormal, right-handed axes
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(norm(b[i].axis[k]), 1.0, 1e-15);
      EXPECT_NEAR(dot(b[i].axis[k], b[i].axis[(k + 1) % 3]), 0.0, 1e-15);
    }
    const Vec3 c = cross(b[i].axis[0], b[i].axis[1]);
    EXPECT_NEAR(dot(c, b[i].axis[2]), 1.0, 1e-15);
  }
}

TEST(GrateGeometry, MovingRowsStrokeAlongOrAgainstTransport) {
  for (GrateType type : {GrateType::forward_acting, GrateType::reverse_acting}) {
    GrateParams p = base_params();
    p.type = type;
    const Grate g(p);
    const auto rest = g.boxes(0.0);
    const double sign = type == GrateType::forward_acting ? 1.0 : -1.0;
    const double a = 15.0 * kPi / 180.0;
    for (double t : {0.3, 0.9, 1.0, 1.7}) {
      const auto b = g.boxes(t);
      const double w = kPi;  // 2 pi / T
      const double u = 0.05 * (1.0 - std::cos(w * t)), v = 0.05 * w * std::sin(w * t);
      for (int i = 0; i < 5; ++i) {
        const Vec3 d = b[i].centre - rest[i].centre;
        const double s = i % 2 ? 1.0 : 0.0;
        EXPECT_NEAR(d.x, s * sign * u * std::cos(a), 1e-14);
        EXPECT_NEAR(d.y, 0.0, 1e-14);
        EXPECT_NEAR(d.z, -s * sign * u * std::sin(a), 1e-14);
        EXPECT_NEAR(b[i].velocity.x, s * sign * v * std::cos(a), 1e-13);
        EXPECT_NEAR(b[i].velocity.z, -s * sign * v * std::sin(a), 1e-13);
      }
    }
    // forward-acting strokes down-slope (+x), reverse-acting up-slope
    EXPECT_GT(sign * g.stroke_direction().x, 0.0);
  }
}

TEST(GrateGeometry, PhaseGroupsAndExplicitMovingRows) {
  GrateParams p = base_params();
  p.row_group = {-1, 0, -1, 1, 1};
  p.group_phase = {0.0, 0.5};
  const Grate g(p);
  for (double t : {0.2, 1.1, 2.6}) {
    EXPECT_EQ(g.row_motion(0, t).u, 0.0);
    EXPECT_EQ(g.row_motion(2, t).u, 0.0);
    EXPECT_NEAR(g.row_motion(1, t).u, evaluate(p.motion, t, 0.0).u, 0);
    EXPECT_NEAR(g.row_motion(3, t).u, evaluate(p.motion, t, 0.5).u, 0);
    EXPECT_NEAR(g.row_motion(4, t).u, g.row_motion(3, t).u, 0);
  }
  EXPECT_GT(g.row_motion(3, 2.6).u, 0.0);
  EXPECT_EQ(g.row_motion(3, 0.9).u, 0.0);  // group 1 starts at 0.5 T = 1 s
  // bad phase list / row list
  p.group_phase = {0.0};
  std::string e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("phase"), std::string::npos) << e;
  p.group_phase = {0.0, 0.5, 0.25};  // one more than the groups of row_group
  e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("'group_phase (number of values)' = 3"), std::string::npos) << e;
  p.row_group = {-1, -1, -1, -1, -1};  // no moving row: no phase
  p.group_phase = {0.0};
  e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("{0}"), std::string::npos) << e;
  p.row_group = {-1, 0, -1, 1, 1};
  p = base_params();
  p.row_group = {-1, 0};
  e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("row_group"), std::string::npos) << e;
  p = base_params();
  p.rows = 0;
  e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("'rows'"), std::string::npos) << e;
  p = base_params();
  p.declination_deg = 95.0;
  e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("'declination' = 95"), std::string::npos) << e;
  e = error_of([&] { parse_grate_type("sideways"); });
  EXPECT_NE(e.find("'type'"), std::string::npos) << e;
  EXPECT_NE(e.find("forward, reverse"), std::string::npos) << e;
}

TEST(GrateGeometry, BarsAcrossWidthAndSideWalls) {
  GrateParams p = base_params();
  p.bar_thickness = 0.04;
  p.bar_gap = 0.01;  // floor((0.25 + 0.01)/0.05) = 5 bars, span 0.24
  p.side_walls = true;
  p.wall_height = 0.2;
  p.wall_thickness = 0.02;
  const Grate g(p);
  const auto b = g.boxes(0.0);
  ASSERT_EQ(b.size(), 5u * 5u + 2u);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(b[k].centre.y, 2.0 - 0.12 + 0.02 + k * 0.05, 1e-14);
  const Box& w0 = b[25];
  const Box& w1 = b[26];
  EXPECT_EQ(w0.kind, BoxKind::side_wall);
  EXPECT_NEAR(w0.centre.y + w0.half.y, 2.0 - 0.125, 1e-14);
  EXPECT_NEAR(w1.centre.y - w1.half.y, 2.0 + 0.125, 1e-14);
  // walls reach wall_height above the highest bar top (the heel of row 0 at z = 3)
  EXPECT_NEAR(w0.centre.z + w0.half.z, 3.0 + 0.2, 1e-12);
  // walls cover every bar in x including the stroke
  for (int i = 0; i < 25; ++i) {
    EXPECT_LE(w0.centre.x - w0.half.x, b[i].centre.x - b[i].half.x * std::cos(15 * kPi / 180) - 0.09);
    EXPECT_GE(w0.centre.x + w0.half.x, b[i].centre.x + b[i].half.x * std::cos(15 * kPi / 180) + 0.09);
  }
  p.frame = Frame::xy;
  const std::string e = error_of([&] { Grate bad(p); });
  EXPECT_NE(e.find("side_walls"), std::string::npos) << e;
}

TEST(GrateGeometry, TwoDimensionalFrame) {
  GrateParams p = base_params();
  p.frame = Frame::xy;
  p.origin = {0.0, 0.5, 0.0};
  p.bar_thickness = 0.01;  // ignored in 2D: one bar spans the layer
  const Grate g(p);
  EXPECT_EQ(g.up_axis(), 1);
  const auto b = g.boxes(0.7);
  ASSERT_EQ(b.size(), 5u);
  const double a = 15.0 * kPi / 180.0;
  for (const Box& x : b) {
    EXPECT_NEAR(x.centre.z, 0.0, 1e-15);
    EXPECT_NEAR(x.half.y, 0.125, 0);  // lateral half extent, along global z
    EXPECT_NEAR(std::fabs(x.axis[1].z), 1.0, 0);
    EXPECT_NEAR(x.axis[2].y, std::cos(a), 1e-15);  // top normal points up (+y)
    EXPECT_NEAR(x.velocity.z, 0.0, 0);
    EXPECT_NEAR(dot(cross(x.axis[0], x.axis[1]), x.axis[2]), 1.0, 1e-15);
  }
  // heel of row 0 at the origin, rows descend in y
  const Vec3 heel = b[0].centre - b[0].half.x * b[0].axis[0] + b[0].half.z * b[0].axis[2];
  EXPECT_NEAR(heel.x, 0.0, 1e-14);
  EXPECT_NEAR(heel.y, 0.5, 1e-14);
  EXPECT_LT(b[4].centre.y, b[0].centre.y);
}

TEST(GrateGeometry, SurfaceHeightAndClosestPoint) {
  GrateParams p = base_params();
  p.declination_deg = 0.0;
  p.overlap = 0.0;
  p.step_height = 0.02;
  const Grate g(p);
  // flat rows of 0.3 m, each 0.02 lower; row 1 moves +0.1 at t = T/2 = 1 s
  EXPECT_NEAR(g.surface_height(1.05, 2.0, 0.0), 3.0, 1e-14);
  EXPECT_NEAR(g.surface_height(1.35, 2.0, 0.0), 2.98, 1e-14);
  EXPECT_NEAR(g.surface_height(1.95, 2.0, 0.0), 2.94, 1e-14);
  // at t = 1 s row 1 covers [1.4, 1.7] and lies above row 2 there
  EXPECT_NEAR(g.surface_height(1.65, 2.0, 1.0), 2.98, 1e-14);
  EXPECT_TRUE(std::isnan(g.surface_height(0.9, 2.0, 0.0)));
  EXPECT_TRUE(std::isnan(g.surface_height(1.05, 2.2, 0.0)));  // beyond the width
  // closest point on an inclined bar
  const Grate gi(base_params());
  const Box b = gi.boxes(0.0)[2];
  const Vec3 above = b.centre + 0.5 * b.axis[2] + 0.05 * b.axis[0];
  const Vec3 q = closest_point(b, above);
  const Vec3 expect = b.centre + b.half.z * b.axis[2] + 0.05 * b.axis[0];
  EXPECT_NEAR(norm(q - expect), 0.0, 1e-14);
  EXPECT_NEAR(norm(closest_point(b, b.centre) - b.centre), 0.0, 0);
  const Vec3 corner_out = b.centre + 1.0 * b.axis[0] + 1.0 * b.axis[1] + 1.0 * b.axis[2];
  const Vec3 corner = b.centre + b.half.x * b.axis[0] + b.half.y * b.axis[1] + b.half.z * b.axis[2];
  EXPECT_NEAR(norm(closest_point(b, corner_out) - corner), 0.0, 1e-14);
}

// The mesh is closed with outward normals: the divergence theorem gives the box volume, and every
// triangle's normal points away from its box centre.
TEST(GrateGeometry, MeshIsClosedAndOutward) {
  GrateParams p = base_params();
  p.side_walls = true;
  const Grate g(p);
  const auto boxes = g.boxes(0.55);
  const Mesh m = box_mesh(boxes);
  ASSERT_EQ(m.triangles.size(), 12 * boxes.size());
  std::vector<double> vol(boxes.size(), 0.0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Vec3 a = m.points[m.triangles[t][0]], b = m.points[m.triangles[t][1]], c = m.points[m.triangles[t][2]];
    const Vec3 n = cross(b - a, c - a);
    const Box& bx = boxes[m.triangle_box[t]];
    const Vec3 cen = (1.0 / 3.0) * (a + b + c);
    EXPECT_GT(dot(n, cen - bx.centre), 0.0);
    vol[m.triangle_box[t]] += dot(a, cross(b, c)) / 6.0;
  }
  for (std::size_t k = 0; k < boxes.size(); ++k)
    EXPECT_NEAR(vol[k], 8.0 * boxes[k].half.x * boxes[k].half.y * boxes[k].half.z, 1e-12) << k;
}

TEST(GrateGeometry, BarsDatasetIsTheMeshWithBoxData) {
  const Grate g(base_params());
  const auto boxes = g.boxes(0.5);
  const vtkio::Dataset d = bars_dataset(boxes, 0.5);
  EXPECT_EQ(d.time, 0.5);
  ASSERT_EQ(d.npoints(), 8 * boxes.size());
  ASSERT_EQ(d.ncells(), 12 * boxes.size());
  for (std::size_t c = 0; c < d.ncells(); ++c) {
    EXPECT_EQ(d.offsets[c + 1] - d.offsets[c], 3);
    EXPECT_EQ(d.types[c], vtkio::kTriangle);
  }
  // moving row 1: points of box 1 are the rest points shifted by the displacement
  const auto rest = g.boxes(0.0);
  const Vec3 disp = boxes[1].centre - rest[1].centre;
  EXPECT_GT(norm(disp), 0.01);
  const Mesh mr = box_mesh(rest);
  for (int k = 8; k < 16; ++k) EXPECT_NEAR(d.points[3 * k] - mr.points[k].x, disp.x, 1e-8);
  ASSERT_EQ(d.cell_data.size(), 4u);
  EXPECT_EQ(d.cell_data[0].name, "box");
  EXPECT_EQ(d.cell_data[3].name, "velocity");
  for (std::size_t c = 0; c < d.ncells(); ++c) {
    const int b = static_cast<int>(d.cell_data[0].ints[c]);
    EXPECT_EQ(d.cell_data[1].ints[c], boxes[b].row);
    EXPECT_EQ(d.cell_data[2].ints[c], boxes[b].group);
    EXPECT_EQ(d.cell_data[3].real[3 * c], boxes[b].velocity.x);
  }
}

// ------------------------------------------------------------------------------------ mixing

namespace {
// simple cubic lattice n^3 with spacing a, starting at (a/2, a/2, a/2)
std::vector<double> lattice(int nx, int ny, int nz, double a) {
  std::vector<double> x;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        x.push_back((i + 0.5) * a);
        x.push_back((j + 0.5) * a);
        x.push_back((k + 0.5) * a);
      }
  return x;
}
}  // namespace

TEST(GrateMixing, BedAtRestAndUniformTranslationGiveZero) {
  const auto x = lattice(12, 8, 6, 0.01);
  const std::size_t n = x.size() / 3;
  mx::Bins bins;
  bins.axis = 0;
  bins.lo = 0.0;
  bins.hi = 0.12;
  bins.count = 4;
  std::vector<double> v(3 * n, 0.0);
  auto st = mx::velocity_mixing(n, x.data(), v.data(), 0.025, bins);
  long total = 0;
  for (const auto& s : st) {
    EXPECT_EQ(s.P(), 0.0);
    total += s.n;
  }
  EXPECT_EQ(total, static_cast<long>(n));
  for (std::size_t i = 0; i < n; ++i) {
    v[3 * i] = 0.37;
    v[3 * i + 1] = -0.11;
    v[3 * i + 2] = 1.3e-3;
  }
  st = mx::velocity_mixing(n, x.data(), v.data(), 0.025, bins);
  for (const auto& s : st) EXPECT_LT(s.P(), 1e-14);
}

// The cell list finds exactly the neighbours of a brute-force search, with and without periodicity.
TEST(GrateMixing, LocalMeanMatchesBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const std::size_t n = 1500;
  std::vector<double> x(3 * n), v(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    x[3 * i] = 2.0 * U(rng);
    x[3 * i + 1] = 0.5 * U(rng);
    x[3 * i + 2] = 0.3 * U(rng) * U(rng);
    for (int k = 0; k < 3; ++k) v[3 * i + k] = U(rng) - 0.5;
  }
  for (bool periodic : {false, true}) {
    mx::Periodic per;
    per.on[1] = periodic;
    per.lo[1] = 0.0;
    per.hi[1] = 0.5;
    const double r = 0.07;
    const auto lv = mx::local_velocity(n, x.data(), v.data(), r, per);
    for (std::size_t i = 0; i < n; i += 7) {
      double s[3] = {0, 0, 0};
      int cnt = 0;
      for (std::size_t j = 0; j < n; ++j) {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) {
          double d = x[3 * j + k] - x[3 * i + k];
          if (periodic && k == 1) d -= 0.5 * std::round(d / 0.5);
          d2 += d * d;
        }
        if (d2 <= r * r) {
          ++cnt;
          for (int k = 0; k < 3; ++k) s[k] += v[3 * j + k];
        }
      }
      ASSERT_EQ(lv.neighbours[i], cnt) << i << " periodic " << periodic;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(lv.mean[3 * i + k], s[k] / cnt, 1e-14);
    }
  }
}

// Independent Gaussian velocity fluctuations of variance sigma^2 around a common drift: with |N_i|
// neighbours (self included) Var(vtil_i) = sigma^2 (1 - 1/|N_i|). On a periodic simple cubic lattice
// with r_v = 1.5 a every particle has 1 + 6 + 12 = 19 neighbours.
TEST(GrateMixing, RandomFluctuationsOfKnownVariance) {
  const int m = 20;
  const double a = 0.01;
  const auto x = lattice(m, m, m, a);
  const std::size_t n = x.size() / 3;
  const double sigma[3] = {0.02, 0.05, 0.01};
  std::mt19937 rng(2024);
  std::normal_distribution<double> N(0.0, 1.0);
  std::vector<double> v(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = (k == 0 ? 0.3 : 0.0) + sigma[k] * N(rng);
  mx::Periodic per;
  for (int k = 0; k < 3; ++k) {
    per.on[k] = true;
    per.lo[k] = 0.0;
    per.hi[k] = m * a;
  }
  mx::Bins bins;
  bins.lo = 0.0;
  bins.hi = m * a;
  bins.count = 1;
  mx::LocalVelocity field;
  const auto st = mx::velocity_mixing(n, x.data(), v.data(), 1.5 * a, bins, per, nullptr, &field);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(field.neighbours[i], 19);
  const double f = std::sqrt(1.0 - 1.0 / 19.0);
  // relative standard error of a standard deviation from 8000 (correlated) samples is ~1-2 %
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(st[0].p(k), sigma[k] * f, 0.05 * sigma[k] * f) << k;
  const double P = f * std::sqrt(sigma[0] * sigma[0] + sigma[1] * sigma[1] + sigma[2] * sigma[2]);
  EXPECT_NEAR(st[0].P(), P, 0.04 * P);
  // regions and the include mask: left half still, right half fluctuating
  bins.count = 2;
  std::vector<double> v2(3 * n, 0.0);
  std::vector<unsigned char> inc(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (x[3 * i] > 0.5 * m * a + 2.0 * a)
      for (int k = 0; k < 3; ++k) v2[3 * i + k] = sigma[1] * N(rng);
    if (x[3 * i] > 0.5 * m * a && x[3 * i] < 0.5 * m * a + 2.0 * a) inc[i] = 0;  // border layer left out
  }
  per.on[0] = false;  // no wrap-around of the fluctuating half onto the still half
  const auto st2 = mx::velocity_mixing(n, x.data(), v2.data(), 1.5 * a, bins, per, inc.data());
  EXPECT_EQ(st2[0].P(), 0.0);
  EXPECT_EQ(st2[0].n, static_cast<long>(n / 2));
  EXPECT_EQ(st2[1].n, static_cast<long>(n / 2 - 2 * m * m));
  EXPECT_GT(st2[1].p(1), 0.8 * sigma[1]);
  // accumulation over snapshots: merging two identical snapshots changes nothing
  mx::VelocityStats acc = st[0];
  acc.merge(st[0]);
  EXPECT_NEAR(acc.P(), st[0].P(), 1e-15);
  // bad radius
  const std::string e = error_of([&] { mx::local_velocity(n, x.data(), v.data(), -1.0); });
  EXPECT_NE(e.find("radius"), std::string::npos) << e;
  EXPECT_NE(e.find("-1"), std::string::npos) << e;
  // a velocity that is not a finite number is named (the fixed-point neighbour sums cannot hold it)
  std::vector<double> vbad(v);
  vbad[7] = std::nan("");
  const std::string eb = error_of([&] { mx::local_velocity(n, x.data(), vbad.data(), 1.5 * a, per); });
  EXPECT_NE(eb.find("velocity"), std::string::npos) << eb;
}

// Columns of particles stacked on a flat grate at height zg: the top particle has D = 0, the one
// resting on the grate D = 1, layer k from the bottom D = (K-1-k)/(K-1).
TEST(GrateMixing, ConstructedBedDepth) {
  const double r = 0.005, zg = 0.2;
  const int K = 6;
  std::vector<double> x, rad;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 4; ++j) {
      const int layers = i < 5 ? K : 3;  // a lower bed downstream
      for (int k = 0; k < layers; ++k) {
        x.push_back((2 * i + 1) * r);
        x.push_back((2 * j + 1) * r);
        x.push_back(zg + r + 2 * r * k);
        rad.push_back(r);
      }
    }
  const std::size_t n = rad.size();
  mx::DepthOptions o;
  o.column_width = 2.0 * r;  // one column of particles (|dx| <= r)
  o.grate_height = [&](double, double) { return zg; };
  const auto d = mx::particle_depths(n, x.data(), rad.data(), o);
  for (std::size_t i = 0; i < n; ++i) {
    const int layers = x[3 * i] < 10 * r ? K : 3;
    const int k = static_cast<int>(std::lround((x[3 * i + 2] - zg - r) / (2 * r)));
    EXPECT_NEAR(d.depth[i], double(layers - 1 - k) / (layers - 1), 1e-12) << i;
    if (k == layers - 1) {
      EXPECT_EQ(d.depth[i], 0.0);
    }
    if (k == 0) {
      EXPECT_NEAR(d.depth[i], 1.0, 1e-12);
    }
  }
  o.normalise = false;
  const auto du = mx::particle_depths(n, x.data(), rad.data(), o);
  for (std::size_t i = 0; i < n; ++i) {
    const int layers = x[3 * i] < 10 * r ? K : 3;
    EXPECT_NEAR(du.depth[i], zg + r + 2 * r * (layers - 1) - x[3 * i + 2], 1e-14);
  }
  // 2D (lateral axis none, up = y), using the grate geometry for the height: a flat grate
  GrateParams gp;
  gp.rows = 2;
  gp.bar_length = 0.5;
  gp.declination_deg = 0.0;
  gp.frame = Frame::xy;
  gp.origin = {0.0, zg, 0.0};
  const Grate g(gp);
  std::vector<double> x2;
  std::vector<double> r2;
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k < K; ++k) {
      x2.insert(x2.end(), {(2 * i + 1) * r, zg + r + 2 * r * k, 0.0});
      r2.push_back(r);
    }
  mx::DepthOptions o2;
  o2.up_axis = 1;
  o2.lateral_axis = -1;
  o2.column_width = 2.0 * r;
  o2.grate_height = [&](double xt, double) { return g.surface_height(xt, 0.0, 0.0); };
  const auto d2 = mx::particle_depths(r2.size(), x2.data(), r2.data(), o2);
  for (std::size_t i = 0; i < r2.size(); ++i) {
    const int k = static_cast<int>(i % K);
    EXPECT_NEAR(d2.depth[i], double(K - 1 - k) / (K - 1), 1e-12);
  }
}

// Q' of a tracer whose depth changes at a constant rate equals that rate; for an oscillating depth
// D = A sin(2 pi t / T) sampled at the extremes, Q' = 4 A / T, Dbar = 0, sigma_D = A / sqrt 2.
TEST(GrateMixing, DepthChangeRate) {
  mx::Bins bins;
  bins.lo = 0.0;
  bins.hi = 1.0;
  bins.count = 2;
  // end to end: a column of 8 particles, the tracer (id 99) beside it sinks at w = 0.01 m/s
  const double r = 0.005, w = 0.01;
  mx::DepthTrajectories tr(bins);
  mx::DepthOptions o;
  o.column_width = 6.0 * r;
  o.grate_height = [](double, double) { return 0.0; };
  o.normalise = false;
  for (int s = 0; s <= 50; ++s) {
    const double t = 0.02 * s;
    std::vector<double> x, rad;
    std::vector<long> id;
    for (int k = 0; k < 8; ++k) {
      x.insert(x.end(), {0.2, 0.0, r + 2 * r * k});
      rad.push_back(r);
      id.push_back(k);
    }
    x.insert(x.end(), {0.2 + 2 * r, 0.0, 0.07 - w * t});
    rad.push_back(r);
    id.push_back(99);
    const auto d = mx::particle_depths(rad.size(), x.data(), rad.data(), o);
    tr.add(t, rad.size(), id.data(), d.depth.data(), x.data());
  }
  EXPECT_NEAR(tr.particle(99).q(), w, 1e-12);
  EXPECT_NEAR(tr.particle(3).q(), 0.0, 0.0);
  EXPECT_NEAR(tr.particle(99).mean(), 0.075 - 0.07 + 0.5 * w, 1e-12);  // surface 0.075, mean t = 0.5
  EXPECT_NEAR(tr.regions()[0].q(), w / 9.0, 1e-12);  // one of 9 particles moves, all in region 0
  // oscillating depth
  const double A = 0.3, T = 2.0;
  mx::DepthTrajectories osc(bins);
  const int per = 400;
  for (int s = 0; s <= 3 * per; ++s) {
    const double t = T * s / per;
    const long id = 5;
    const double D = 0.5 + A * std::sin(2.0 * kPi * s / per);
    const double xx[3] = {0.75, 0.0, 0.0};
    osc.add(t, 1, &id, &D, xx);
  }
  EXPECT_NEAR(osc.particle(5).q(), 4.0 * A / T, 1e-12);
  EXPECT_NEAR(osc.regions()[1].q(), 4.0 * A / T, 1e-12);
  EXPECT_EQ(osc.regions()[0].total_dt, 0.0);
  // samples 0..3 per: 3 full periods plus the first sample again
  const double mean_expect = 0.5 + 0.0 / (3 * per + 1);
  EXPECT_NEAR(osc.particle(5).mean(), mean_expect, 1e-12);
  EXPECT_NEAR(osc.particle(5).sigma(), A * std::sqrt(0.5 * 3 * per / (3 * per + 1.0)), 1e-9);
  // a particle missing from a snapshot gets no increment across the gap
  mx::DepthTrajectories gap(bins);
  const long id = 1;
  double D = 0.0;
  const double xx[3] = {0.1, 0, 0};
  gap.add(0.0, 1, &id, &D, xx);
  gap.add(1.0, 0, nullptr, nullptr, nullptr);
  D = 1.0;
  gap.add(2.0, 1, &id, &D, xx);
  D = 1.5;
  gap.add(3.0, 1, &id, &D, xx);
  EXPECT_NEAR(gap.particle(1).q(), 0.5, 1e-15);
  // time must increase
  const std::string e = error_of([&] { gap.add(3.0, 1, &id, &D, xx); });
  EXPECT_NE(e.find("time of snapshot"), std::string::npos) << e;
}

// Touching boxes (the bars of a row without a gap): exactly the two triangles of each shared face,
// on both boxes, are marked, also in a mesh of huge bars; boxes apart have none.
TEST(GrateGeometry, SharedFacesOfTouchingBoxes) {
  GrateParams p = base_params();
  p.rows = 1;
  p.width = 0.12;
  p.bar_thickness = 0.04;  // three bars side by side
  p.bar_gap = 0.0;
  const Grate g(p);
  const std::vector<Box> boxes = g.boxes(0.0);
  ASSERT_EQ(boxes.size(), 3u);
  const Mesh m = box_mesh(boxes);
  const std::vector<bool> shared = shared_faces(m);
  std::vector<int> per_box(3, 0);
  for (std::size_t i = 0; i < shared.size(); ++i)
    if (shared[i]) ++per_box[m.triangle_box[i]];
  EXPECT_EQ(per_box[0], 2);  // the outer bars share one face each, the middle bar two
  EXPECT_EQ(per_box[1], 4);
  EXPECT_EQ(per_box[2], 2);
  for (std::size_t i = 0; i < shared.size(); ++i)
    if (shared[i]) {  // a shared face is lateral: its normal is along the width axis y
      const auto& t = m.triangles[i];
      const Vec3 n = cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]);
      EXPECT_NEAR(std::fabs(n.y), norm(n), 1e-12 * norm(n));
    }
  p.bar_gap = 0.001;
  p.bar_thickness = 0.039;
  const Mesh apart = box_mesh(Grate(p).boxes(0.0));
  for (bool s : shared_faces(apart)) EXPECT_FALSE(s);
  p.bar_gap = 0.0;
  p.bar_thickness = 0.04;
  p.bar_length = 1e300;
  const Mesh huge = box_mesh(Grate(p).boxes(0.0));  // the same two shared faces, nothing merged
  const std::vector<bool> sh = shared_faces(huge);
  EXPECT_EQ(std::count(sh.begin(), sh.end(), true), 8);
}
