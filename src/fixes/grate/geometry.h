// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: geometry of a stepped grate of fixed and moving bar rows (physics_reference.md 7.1,
// docs/grate.md), host-independent. The host fixes ask for the bars as oriented boxes (or as a
// triangle mesh) at a time t, and as a VTK dataset (fixes/vtk/dataset.h).
//
// Coordinate convention. The grate is built in a local frame (x, w, u):
//   x  horizontal transport direction (the bed moves towards +x, the grate descends towards +x),
//   w  lateral (across the width), u  vertical, up (against gravity).
// and placed in the global frame by
//   frame xyz (3D):  global = origin + (x, w, u)   -> transport +x, width along y, up +z
//   frame xy  (2D):  global = origin + (x, u, -w)  -> transport +x, up +y, width along z
// (both are proper rotations, so outward normals stay outward). The width is centred on the origin:
// w in [-width/2, width/2].
// Bar rows, i = 0 .. rows-1 from the inlet (upstream) to the outlet. With the declination alpha,
//   bar axis     e_t = ( cos a, 0, -sin a)   (along the bar, pointing down-slope),
//   bar normal   e_n = ( sin a, 0,  cos a)   (out of the top face),   e_w = (0, 1, 0),
// the heel of row i (upstream end of its top face, lateral centre) sits at
//   H_i = i (bar_length - overlap) e_t - i step_height u_hat       (local, relative to the origin)
// so every row starts where the previous one ends (minus `overlap`, the roof-tile overlap along the
// bar) and lies step_height lower. A row is one box of bar_length x bar_thickness x bar_height
// (along e_t, e_w, e_n) or, if bar_thickness < width, several bars of that thickness side by side
// with `bar_gap` between them, centred on the width. Box centre at rest:
//   C_i = H_i + (bar_length/2) e_t - (bar_height/2) e_n  (+ lateral offset of the bar).
// The overall slope of the grate surface is atan((p sin a + s)/(p cos a)) with p = bar_length - overlap,
// s = step_height. A moving row of phase group g is displaced by u_g(t) (kinematics.h) along
//   +e_t  forward-acting grate (stroking down-slope, along the transport),
//   -e_t  reverse-acting grate (stroking up-slope, against the transport; usually steeper alpha).
// Moving bars may overlap the volume of their neighbours (a roof-tile grate slides over the next
// row); bars are walls, so only their exposed faces matter.
// Side walls (3D only): two plates of wall_thickness outside w = +-width/2, spanning the grate
// length (plus the stroke) and from the lowest bar bottom to wall_height above the highest bar top.
// Otherwise the host makes the width periodic.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixes/grate/kinematics.h"
#include "fixes/vtk/dataset.h"

namespace tdem {
namespace grate {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
  double operator[](int k) const { return k == 0 ? x : (k == 1 ? y : z); }
  double& operator[](int k) { return k == 0 ? x : (k == 1 ? y : z); }
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

enum class GrateType { forward_acting, reverse_acting };
enum class Frame { xyz, xy };  // 3D (up = z) or 2D (up = y, width along z)

inline GrateType parse_grate_type(const std::string& s) {
  if (s == "forward" || s == "forward_acting") return GrateType::forward_acting;
  if (s == "reverse" || s == "reverse_acting") return GrateType::reverse_acting;
  throw std::invalid_argument("grate: keyword 'type' = '" + s + "' is not known; allowed: forward, reverse");
}

enum class BoxKind { fixed_bar, moving_bar, side_wall };

// Oriented box: the points centre + sum_k s_k axis[k], |s_k| <= half[k]. axis[] is orthonormal and
// right-handed: axis[0] along the bar (e_t), axis[1] lateral (e_w), axis[2] out of the top face (e_n).
struct Box {
  Vec3 centre;
  std::array<Vec3, 3> axis;
  Vec3 half;
  Vec3 velocity;  // translation velocity of the box [m/s]
  BoxKind kind = BoxKind::fixed_bar;
  int row = -1;    // bar row (-1 for side walls)
  int group = -1;  // phase group of a moving row, -1 fixed bar, -2 side wall
  int bar = 0;     // index of the bar within its row
};

// Point of the (solid) box closest to p (p itself if inside).
inline Vec3 closest_point(const Box& b, Vec3 p) {
  const Vec3 d = p - b.centre;
  Vec3 q = b.centre;
  for (int k = 0; k < 3; ++k) {
    double s = dot(d, b.axis[k]);
    s = std::max(-b.half[k], std::min(b.half[k], s));
    q = q + s * b.axis[k];
  }
  return q;
}

// Size limit of the input (docs/limits.md): a grate of the dissertation has 5-20 rows; 1000 rows
// already give about 1.2 MB of STL per bar mesh in LIGGGHTS. Both hosts refuse more.
inline constexpr int kMaxRows = 1000;

struct GrateParams {
  int rows = 6;                  // number of bar rows, 1 .. kMaxRows
  double bar_length = 0.2;       // along the bar axis e_t [m], > 0
  double bar_height = 0.05;      // along e_n [m], > 0
  double bar_thickness = 0.0;    // lateral size of one bar [m]; 0 or >= width: one bar spans the width
  double bar_gap = 0.0;          // lateral gap between neighbouring bars of a row [m], >= 0
  double step_height = 0.0;      // vertical drop between consecutive rows [m], >= 0
  double overlap = 0.0;          // roof-tile overlap along e_t [m], [0, bar_length)
  double declination_deg = 12.0; // alpha [deg], [0, 80]
  double width = 0.2;            // lateral extent [m], > 0 (2D: thickness of the disk layer)
  bool side_walls = false;       // 3D only; false: periodic width (host)
  double wall_height = 0.3;      // side walls reach this far above the highest bar top [m], > 0
  double wall_thickness = 0.01;  // [m], > 0
  GrateType type = GrateType::forward_acting;
  Frame frame = Frame::xyz;
  Vec3 origin;                   // global position of the heel of row 0 (lateral centre)
  std::vector<int> row_group;    // per row: -1 fixed, g >= 0 moving in phase group g; empty: odd rows move (group 0)
  std::vector<double> group_phase;  // phase of group g as a fraction of the period, [0, 1); empty: all 0
  MotionParams motion;
};

// Triangle mesh of a set of boxes (8 points and 12 outward-oriented triangles per box).
struct Mesh {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_box;  // index of the box each triangle belongs to
};

inline Mesh box_mesh(const std::vector<Box>& boxes) {
  Mesh m;
  m.points.reserve(8 * boxes.size());
  m.triangles.reserve(12 * boxes.size());
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const Box& bx = boxes[b];
    const int base = static_cast<int>(m.points.size());
    // corner c: sign of axis k is + if bit k of c is set
    for (int c = 0; c < 8; ++c) {
      Vec3 p = bx.centre;
      for (int k = 0; k < 3; ++k) p = p + (((c >> k) & 1) ? bx.half[k] : -bx.half[k]) * bx.axis[k];
      m.points.push_back(p);
    }
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      for (int s = 0; s < 2; ++s) {
        auto corner = [&](int si, int sj) { return base + ((s << k) | (si << i) | (sj << j)); };
        // counter-clockwise seen from +axis[k] because axis[i] x axis[j] = axis[k]
        std::array<int, 4> q = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
        if (s == 0) std::swap(q[1], q[3]);
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
        m.triangle_box.push_back(static_cast<int>(b));
        m.triangle_box.push_back(static_cast<int>(b));
      }
    }
  }
  return m;
}

// Triangles of a mesh that coincide with another triangle of it (the same three corners within
// 1e-9 of the shortest edge): the touching faces of two boxes, e.g. the bars of a row without a gap.
// They lie inside the union of the boxes, and box_mesh triangulates opposite faces along the same
// diagonal, so both triangles of a shared face are found. A wall mesh leaves them out (LIGGGHTS
// refuses duplicate elements).
inline std::vector<bool> shared_faces(const Mesh& m) {
  const std::size_t n = m.triangles.size();
  std::vector<bool> shared(n, false);
  if (m.points.empty()) return shared;
  // distinct faces differ by at least the shortest box edge: match corners to 1e-9 of it (a
  // tolerance relative to the mesh size would merge everything in a mesh of huge boxes)
  double edge = std::numeric_limits<double>::infinity();
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) edge = std::min(edge, norm(m.points[t[k]] - m.points[t[(k + 1) % 3]]));
  const double tol = 1e-9 * edge;
  std::vector<Vec3> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = m.triangles[i];
    c[i] = (1.0 / 3.0) * (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]);
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c[a].x < c[b].x; });
  auto same_corners = [&](std::size_t i, std::size_t j) {
    for (int a : m.triangles[i]) {
      bool found = false;
      for (int b : m.triangles[j]) found = found || norm(m.points[a] - m.points[b]) <= tol;
      if (!found) return false;
    }
    return true;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n && c[order[b]].x - c[order[a]].x <= tol; ++b) {
      const std::size_t i = order[a], j = order[b];
      if (norm(c[i] - c[j]) <= tol && same_corners(i, j)) shared[i] = shared[j] = true;
    }
  return shared;
}

// The boxes as a VTK dataset (fixes/vtk): the triangles of box_mesh with cell data box, row,
// group (-1 fixed bar, -2 side wall) and velocity, at time t.
inline vtkio::Dataset bars_dataset(const std::vector<Box>& boxes, double t) {
  const Mesh m = box_mesh(boxes);
  vtkio::Dataset d;
  d.time = t;
  for (const Vec3& p : m.points) d.add_point(p.x, p.y, p.z);
  for (const auto& tr : m.triangles) d.add_cell(tr.begin(), tr.end(), vtkio::kTriangle);
  vtkio::Array &box = d.cell_array("box", 1, true), &row = d.cell_array("row", 1, true),
             &group = d.cell_array("group", 1, true), &vel = d.cell_array("velocity", 3, false);
  for (int b : m.triangle_box) {
    box.ints.push_back(b);
    row.ints.push_back(boxes[b].row);
    group.ints.push_back(boxes[b].group);
    vel.real.insert(vel.real.end(), {boxes[b].velocity.x, boxes[b].velocity.y, boxes[b].velocity.z});
  }
  return d;
}

class Grate {
 public:
  explicit Grate(const GrateParams& p) : p_(p) {
    validate_params();
    const double a = p_.declination_deg * 3.14159265358979323846 / 180.0;
    sin_a_ = std::sin(a);
    cos_a_ = std::cos(a);
    e_t_ = {cos_a_, 0.0, -sin_a_};
    e_n_ = {sin_a_, 0.0, cos_a_};
    if (p_.row_group.empty()) {
      p_.row_group.resize(p_.rows);
      for (int i = 0; i < p_.rows; ++i) p_.row_group[i] = (i % 2 == 1) ? 0 : -1;
    }
    int ngroups = 0;
    for (int g : p_.row_group) ngroups = std::max(ngroups, g + 1);
    if (p_.group_phase.empty()) p_.group_phase.assign(ngroups, 0.0);
    // exactly one phase per group: a surplus value means that row_group and group_phase disagree
    if (static_cast<int>(p_.group_phase.size()) != ngroups)
      bad_value("grate", "group_phase (number of values)", static_cast<double>(p_.group_phase.size()),
                "{" + std::to_string(ngroups) + "} - one phase per phase group of row_group");
    for (double ph : p_.group_phase) validate_phase(ph);
    build_rest();
  }

  const GrateParams& params() const { return p_; }
  int up_axis() const { return p_.frame == Frame::xyz ? 2 : 1; }
  int width_axis() const { return p_.frame == Frame::xyz ? 1 : 2; }
  // +e_t for forward-acting, -e_t for reverse-acting, in global coordinates
  Vec3 stroke_direction() const { return dir_to_global(stroke_sign() * e_t_); }
  Vec3 bar_axis() const { return dir_to_global(e_t_); }
  Vec3 bar_normal() const { return dir_to_global(e_n_); }
  int bar_count() const { return static_cast<int>(bars_.size()); }

  Vec3 dir_to_global(Vec3 l) const {
    return p_.frame == Frame::xyz ? l : Vec3{l.x, l.z, -l.y};
  }
  Vec3 to_global(Vec3 l) const { return p_.origin + dir_to_global(l); }

  // Motion of row i at time t (zero for a fixed row): u along the stroke direction.
  MotionState row_motion(int row, double t) const {
    const int g = p_.row_group.at(row);
    if (g < 0) return MotionState{};
    return evaluate(p_.motion, t, p_.group_phase[g]);
  }

  // All bars (rows in order, bars of a row by lateral position), then the side walls, at time t.
  std::vector<Box> boxes(double t) const {
    std::vector<Box> out;
    out.reserve(bars_.size() + walls_.size());
    const Vec3 dir = stroke_sign() * e_t_;
    std::vector<MotionState> ms(p_.rows);
    for (int i = 0; i < p_.rows; ++i) ms[i] = row_motion(i, t);
    for (const Box& local : bars_) {
      const MotionState& m = ms[local.row];
      Box b = local;
      b.centre = to_global(local.centre + m.u * dir);
      for (int k = 0; k < 3; ++k) b.axis[k] = dir_to_global(local.axis[k]);
      b.velocity = dir_to_global(m.v * dir);
      out.push_back(b);
    }
    for (const Box& local : walls_) {
      Box b = local;
      b.centre = to_global(local.centre);
      for (int k = 0; k < 3; ++k) b.axis[k] = dir_to_global(local.axis[k]);
      out.push_back(b);
    }
    return out;
  }

  // Height (global up coordinate) of the highest bar top face above the horizontal position
  // x (global transport coordinate) and lateral (global coordinate along the width axis) at time t;
  // NaN if no bar covers that point (outside the grate or in a gap between bars).
  double surface_height(double x, double lateral, double t) const {
    const double xl = x - p_.origin.x;
    const double wl = p_.frame == Frame::xyz ? lateral - p_.origin.y : -(lateral - p_.origin.z);
    const double u0 = p_.frame == Frame::xyz ? p_.origin.z : p_.origin.y;
    const Vec3 dir = stroke_sign() * e_t_;
    double best = std::numeric_limits<double>::quiet_NaN();
    for (const Box& b : bars_) {
      const double u = row_motion(b.row, t).u;
      const Vec3 top = b.centre + u * dir + b.half.z * e_n_;
      const double s = (xl - top.x) / cos_a_;
      if (std::fabs(s) > b.half.x || std::fabs(wl - top.y) > b.half.y) continue;
      const double h = top.z - s * sin_a_;
      if (!(h <= best)) best = h;  // also replaces NaN
    }
    return u0 + best;
  }

 private:
  double stroke_sign() const { return p_.type == GrateType::forward_acting ? 1.0 : -1.0; }

  void validate_params() {
    const std::string c = "grate";
    if (!(p_.rows >= 1)) bad_value(c, "rows", p_.rows, "[1, inf)");
    if (!(p_.bar_length > 0.0) || !std::isfinite(p_.bar_length)) bad_value(c, "bar_length", p_.bar_length, "(0, inf)");
    if (!(p_.bar_height > 0.0) || !std::isfinite(p_.bar_height)) bad_value(c, "bar_height", p_.bar_height, "(0, inf)");
    if (!(p_.width > 0.0) || !std::isfinite(p_.width)) bad_value(c, "width", p_.width, "(0, inf)");
    if (!(p_.bar_thickness >= 0.0) || !std::isfinite(p_.bar_thickness))
      bad_value(c, "bar_thickness", p_.bar_thickness, "[0, inf) (0 = whole width)");
    if (!(p_.bar_gap >= 0.0) || !std::isfinite(p_.bar_gap)) bad_value(c, "bar_gap", p_.bar_gap, "[0, inf)");
    if (!(p_.step_height >= 0.0) || !std::isfinite(p_.step_height))
      bad_value(c, "step_height", p_.step_height, "[0, inf)");
    if (!(p_.overlap >= 0.0 && p_.overlap < p_.bar_length))
      bad_value(c, "overlap", p_.overlap, "[0, bar_length)");
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(p_.origin[k])) bad_value(c, "origin", p_.origin[k], "(-inf, inf)");
    if (!(p_.declination_deg >= 0.0 && p_.declination_deg <= 80.0))
      bad_value(c, "declination", p_.declination_deg, "[0, 80] degrees");
    if (p_.side_walls) {
      if (p_.frame == Frame::xy)
        throw std::invalid_argument("grate: keyword 'side_walls' is not allowed with frame xy (2D); allowed: 3D frame xyz");
      if (!(p_.wall_height > 0.0) || !std::isfinite(p_.wall_height))
        bad_value(c, "wall_height", p_.wall_height, "(0, inf)");
      if (!(p_.wall_thickness > 0.0) || !std::isfinite(p_.wall_thickness))
        bad_value(c, "wall_thickness", p_.wall_thickness, "(0, inf)");
    }
    if (!p_.row_group.empty()) {
      if (static_cast<int>(p_.row_group.size()) != p_.rows)
        bad_value(c, "row_group (number of row entries)", static_cast<double>(p_.row_group.size()),
                  "{" + std::to_string(p_.rows) + "} - one entry per row");
      for (int g : p_.row_group)
        if (g < -1) bad_value(c, "row_group (phase group of a row)", g, "{-1 (fixed), 0, 1, ...}");
    }
    validate(p_.motion);
  }

  void build_rest() {
    // lateral layout of the bars of a row
    double th = p_.bar_thickness;
    int nb = 1;
    if (p_.frame == Frame::xy || th <= 0.0 || th >= p_.width) {
      th = p_.width;
    } else {
      nb = static_cast<int>(std::floor((p_.width + p_.bar_gap) / (th + p_.bar_gap) + 1e-12));
      nb = std::max(nb, 1);
    }
    const double span = nb * th + (nb - 1) * p_.bar_gap;
    const double pitch = p_.bar_length - p_.overlap;
    const Vec3 up{0.0, 0.0, 1.0};
    const Vec3 e_w{0.0, 1.0, 0.0};
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, umin = xmin, umax = -xmin;
    for (int i = 0; i < p_.rows; ++i) {
      const Vec3 heel = (i * pitch) * e_t_ - (i * p_.step_height) * up;
      const Vec3 c = heel + (0.5 * p_.bar_length) * e_t_ - (0.5 * p_.bar_height) * e_n_;
      for (int k = 0; k < nb; ++k) {
        Box b;
        b.centre = c + (-0.5 * span + 0.5 * th + k * (th + p_.bar_gap)) * e_w;
        b.axis = {e_t_, e_w, e_n_};
        b.half = {0.5 * p_.bar_length, 0.5 * th, 0.5 * p_.bar_height};
        b.row = i;
        b.group = p_.row_group[i];
        b.kind = b.group >= 0 ? BoxKind::moving_bar : BoxKind::fixed_bar;
        b.bar = k;
        bars_.push_back(b);
        for (int cc = 0; cc < 8; ++cc) {
          Vec3 q = b.centre;
          for (int a = 0; a < 3; ++a) q = q + (((cc >> a) & 1) ? b.half[a] : -b.half[a]) * b.axis[a];
          xmin = std::min(xmin, q.x);
          xmax = std::max(xmax, q.x);
          umin = std::min(umin, q.z);
          umax = std::max(umax, q.z);
        }
      }
    }
    if (p_.side_walls) {
      const double reach = p_.motion.stroke * cos_a_;
      xmin -= reach;
      xmax += reach;
      umax += p_.wall_height;
      for (int s = -1; s <= 1; s += 2) {
        Box w;
        w.centre = {0.5 * (xmin + xmax), s * (0.5 * p_.width + 0.5 * p_.wall_thickness), 0.5 * (umin + umax)};
        w.axis = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
        w.half = {0.5 * (xmax - xmin), 0.5 * p_.wall_thickness, 0.5 * (umax - umin)};
        w.kind = BoxKind::side_wall;
        w.row = -1;
        w.group = -2;
        w.bar = s < 0 ? 0 : 1;
        walls_.push_back(w);
      }
    }
  }

  GrateParams p_;
  double sin_a_ = 0.0, cos_a_ = 1.0;
  Vec3 e_t_, e_n_;
  std::vector<Box> bars_;   // local frame, at rest
  std::vector<Box> walls_;  // local frame
};

}  // namespace grate
}  // namespace tdem
