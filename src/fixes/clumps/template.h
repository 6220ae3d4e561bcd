// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: multi-sphere clump templates (physics_reference.md section 6.1), host-independent.
//
// A template is a list of spheres (centre offsets and radii in a "template frame") plus the mass
// properties of the body they represent:
//   * mass M, centre of mass c and the inertia tensor about c, either integrated over the UNION of
//     the spheres with a density rho (the union counts an overlap region once, unlike the sum of
//     sphere masses) or given explicitly (the intended shape when the union is only a stand-in);
//   * principal moments I1 <= I2 <= I3 and principal axes A (columns e1, e2, e3, right-handed),
//     from a cyclic Jacobi eigenvalue routine;
//   * the body frame: sphere offsets relative to c rotated into the principal axes,
//     r_hat_i = A^T (x_i - c). A body placed in the template's own orientation has Lambda = A.
//
// Integration of the union (Integration): the bounding box of the union is cut into cubic cells of
// edge h, `resolution` cells along its longest edge, centred on the box centre;
//   columns      (default) for every (y, z) cell midpoint the column along x meets the union in a
//                set of intervals (merged chords of the spheres), integrated exactly: a 2-D midpoint
//                rule over exact 1-D integrals. Converges monotonically, about second order: for
//                the overlapping dimer of the tests the largest relative error of mass and
//                principal moments is 1.6e-2 / 3.5e-3 / 1.1e-3 / 1.9e-4 at resolution 24/48/96/192.
//   voxel        counts the cells whose midpoint lies in the union (3-D midpoint rule). Simple, but
//                the error fluctuates (lattice points on sphere surfaces): 2.3e-2 / 2.2e-2 / 1.1e-4 /
//                3.8e-4 at the same resolutions.
//   monte_carlo  resolution^3 points uniform in the box from a fixed-seed splitmix64 generator
//                (deterministic; statistical error ~ resolution^-1.5).
// Moments are accumulated about the box centre and shifted to c (parallel-axis theorem), so
// offsets far from the origin do not cost precision.
//
// Text format (parse_template / read_template_file): one item per line, '#' starts a comment,
// blank lines ignored, keywords in any order:
//   sphere  x y z r                    one sphere (at least one line; r > 0)
//   density rho                        (optional) overrides the density passed by the caller
//   resolution n                       (optional) cells along the longest edge, >= 4 (default 64)
//   integration columns|voxel|monte_carlo  (optional, default columns)
//   mass M                             (optional) explicit mass properties: mass, com and inertia
//   com x y z                          must then all three be given; the inertia tensor about the
//   inertia Ixx Iyy Izz Ixy Ixz Iyz    centre of mass in the template frame (Ixy = -sum m x y, ...)
// Errors (std::invalid_argument / std::domain_error) name the keyword, the line and the value.
//
// Built-in shapes (radius r, centre distance d between neighbouring spheres, centred at 0):
//   single(r); rod(n, r, d) along x; tetra(r, d) at the vertices of a regular tetrahedron of
//   edge d; square4(r, d) 2x2 in the xy plane; cube8(r, d) 2x2x2; grid(nx, ny, nz, r, d).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "contact/input_checks.h"
#include "contact/multi_contact/vec3.h"

namespace tdem {
namespace clumps {


// Inertia tensor of a point mass m at offset r about the origin: m (|r|^2 1 - r r^T).
inline Mat3 point_inertia(double m, const Vec3& r) {
  Mat3 I{};
  const double r2 = dot(r, r);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) I[i][j] = m * ((i == j ? r2 : 0.0) - r[i] * r[j]);
  return I;
}

// Cyclic Jacobi eigenvalue routine for a symmetric 3x3 matrix. Returns the eigenvalues in
// ascending order in `values` and the eigenvectors as the COLUMNS of `vectors`, which is made a
// proper rotation (det = +1). Converges quadratically; stops when the off-diagonal part is below
// round-off of the diagonal.
inline void jacobi_eigen(Mat3 a, Vec3& values, Mat3& vectors) {
  Mat3 v = identity();
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-34 * diag || off == 0.0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        // Rotation in the (p, q) plane that zeroes a[p][q] (the smaller of the two angles).
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a <- a J  (columns p, q)
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a <- J^T a  (rows p, q)
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  // Sort ascending (selection sort on 3 entries, swapping columns of v).
  int idx[3] = {0, 1, 2};
  for (int i = 0; i < 2; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (a[idx[j]][idx[j]] < a[idx[i]][idx[i]]) std::swap(idx[i], idx[j]);
  Mat3 out{};
  for (int c = 0; c < 3; ++c) {
    values[c] = a[idx[c]][idx[c]];
    for (int k = 0; k < 3; ++k) out[k][c] = v[k][idx[c]];
  }
  if (det(out) < 0.0)
    for (int k = 0; k < 3; ++k) out[k][2] = -out[k][2];
  vectors = out;
}

// ------------------------------------------------------------------ templates
struct Sphere {
  Vec3 x;    // centre
  double r;  // radius
};

enum class Integration { columns, voxel, monte_carlo };

inline const char* to_string(Integration m) {
  return m == Integration::columns ? "columns" : m == Integration::voxel ? "voxel" : "monte_carlo";
}

struct MassProperties {
  double mass = 0.0;
  double volume = 0.0;       // volume of the union (integrated) or mass/density (explicit)
  Vec3 com{};                // centre of mass, template frame
  Mat3 inertia{};            // inertia tensor about com, template frame
  Vec3 principal{};          // I1 <= I2 <= I3
  Mat3 axes = identity();    // columns: principal axes in the template frame (det +1)
};

struct Template {
  std::string name;
  std::vector<Sphere> spheres;  // template frame
  double density = 0.0;         // 0 if the mass was given explicitly without a density
  MassProperties mp;
  std::vector<Sphere> body;     // offsets in the principal body frame, r_hat_i = A^T (x_i - com)
  double bounding_radius = 0.0; // max |r_hat_i| + r_i

  std::size_t size() const { return spheres.size(); }
};

inline void check_spheres(const std::vector<Sphere>& s) {
  if (s.empty()) throw std::invalid_argument("clump template: no 'sphere' given (need at least one)");
  for (const auto& sp : s) {
    checks::positive("clump template sphere radius", sp.r);
    for (double c : sp.x)
      if (!std::isfinite(c)) checks::fail("clump template sphere coordinate", c, "(-inf, inf)");
  }
}

// Deterministic 64-bit generator (splitmix64) so Monte-Carlo results do not depend on the library.
struct SplitMix64 {
  std::uint64_t s;
  explicit SplitMix64(std::uint64_t seed) : s(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return (next() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
};

// Mass properties of the union of spheres with density rho (see the header comment).
inline MassProperties union_mass_properties(const std::vector<Sphere>& s, double rho, int resolution = 64,
                                            Integration method = Integration::columns,
                                            std::uint64_t seed = 20260101ull) {
  check_spheres(s);
  checks::positive("clump density", rho);
  if (resolution < 4) checks::fail("clump resolution", resolution, "[4, inf)");
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto& sp : s)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], sp.x[k] - sp.r);
      hi[k] = std::max(hi[k], sp.x[k] + sp.r);
    }
  const Vec3 mid = scale(0.5, add(lo, hi));
  const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double h = longest / resolution;
  // Sphere centres and squared radii relative to the box centre.
  std::vector<Vec3> c(s.size());
  std::vector<double> r2(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    c[i] = sub(s[i].x, mid);
    r2[i] = s[i].r * s[i].r;
  }
  auto inside = [&](const Vec3& p) {
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Vec3 d = sub(p, c[i]);
      if (dot(d, d) < r2[i]) return true;
    }
    return false;
  };
  // Moments about the box centre: n, sum p, sum p p^T.
  double n = 0.0;
  Vec3 m1{};
  double m2[3][3] = {};
  auto accumulate = [&](const Vec3& p) {
    n += 1.0;
    for (int a = 0; a < 3; ++a) {
      m1[a] += p[a];
      for (int b = a; b < 3; ++b) m2[a][b] += p[a] * p[b];
    }
  };
  double cell_volume = 0.0;
  if (method == Integration::columns) {
    // Columns along x through the midpoints of a (y, z) grid; along each column the union is a set
    // of intervals, integrated exactly (moments of 1, x, x^2). Weights are lengths in units of h.
    const int ny = std::max(1, static_cast<int>(std::ceil((hi[1] - lo[1]) / h - 1e-9)));
    const int nz = std::max(1, static_cast<int>(std::ceil((hi[2] - lo[2]) / h - 1e-9)));
    std::vector<std::pair<double, double>> iv;
    iv.reserve(c.size());
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const double y = (j - 0.5 * (ny - 1)) * h, z = (k - 0.5 * (nz - 1)) * h;
        iv.clear();
        for (std::size_t i = 0; i < c.size(); ++i) {
          const double q2 = r2[i] - (y - c[i][1]) * (y - c[i][1]) - (z - c[i][2]) * (z - c[i][2]);
          if (q2 > 0.0) {
            const double sq = std::sqrt(q2);
            iv.emplace_back(c[i][0] - sq, c[i][0] + sq);
          }
        }
        if (iv.empty()) continue;
        std::sort(iv.begin(), iv.end());
        auto add_interval = [&](double a, double b) {
          const double l = (b - a) / h, x1 = 0.5 * (b * b - a * a) / h, x2 = (b * b * b - a * a * a) / (3.0 * h);
          n += l;
          m1[0] += x1;
          m1[1] += y * l;
          m1[2] += z * l;
          m2[0][0] += x2;
          m2[0][1] += y * x1;
          m2[0][2] += z * x1;
          m2[1][1] += y * y * l;
          m2[1][2] += y * z * l;
          m2[2][2] += z * z * l;
        };
        double a = iv[0].first, b = iv[0].second;
        for (std::size_t i = 1; i < iv.size(); ++i) {
          if (iv[i].first <= b) {
            b = std::max(b, iv[i].second);
          } else {
            add_interval(a, b);
            a = iv[i].first;
            b = iv[i].second;
          }
        }
        add_interval(a, b);
      }
    cell_volume = h * h * h;
  } else if (method == Integration::voxel) {
    int nc[3];
    for (int k = 0; k < 3; ++k) nc[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / h - 1e-9)));
    // Cells centred on the box centre so symmetric shapes stay symmetric.
    for (int i = 0; i < nc[0]; ++i)
      for (int j = 0; j < nc[1]; ++j)
        for (int k = 0; k < nc[2]; ++k) {
          const Vec3 p{(i - 0.5 * (nc[0] - 1)) * h, (j - 0.5 * (nc[1] - 1)) * h, (k - 0.5 * (nc[2] - 1)) * h};
          if (inside(p)) accumulate(p);
        }
    cell_volume = h * h * h;
  } else {
    SplitMix64 rng(seed);
    const Vec3 ext = sub(hi, lo);
    const double samples = static_cast<double>(resolution) * resolution * resolution;
    const long long ns = static_cast<long long>(samples);
    for (long long q = 0; q < ns; ++q) {
      const Vec3 p{(rng.uniform() - 0.5) * ext[0], (rng.uniform() - 0.5) * ext[1], (rng.uniform() - 0.5) * ext[2]};
      if (inside(p)) accumulate(p);
    }
    cell_volume = ext[0] * ext[1] * ext[2] / samples;
  }
  if (n == 0.0) throw std::domain_error("clump template: resolution too coarse, no cell inside the union");
  MassProperties mp;
  const double dm = rho * cell_volume;
  mp.volume = n * cell_volume;
  mp.mass = n * dm;
  const Vec3 cbox = scale(1.0 / n, m1);  // com relative to the box centre
  mp.com = add(mid, cbox);
  // Second moments about the com: S = sum p p^T - n cbox cbox^T (per unit cell mass).
  double S[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) S[a][b] = S[b][a] = m2[a][b] - n * cbox[a] * cbox[b];
  const double tr = S[0][0] + S[1][1] + S[2][2];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) mp.inertia[a][b] = dm * ((a == b ? tr : 0.0) - S[a][b]);
  return mp;
}

// Principal moments and axes of mp.inertia (fills mp.principal and mp.axes).
inline void principal_axes(MassProperties& mp) { jacobi_eigen(mp.inertia, mp.principal, mp.axes); }

// Body frame of a template whose mp is complete.
inline void build_body_frame(Template& t) {
  principal_axes(t.mp);
  t.body.clear();
  t.bounding_radius = 0.0;
  for (const auto& sp : t.spheres) {
    const Vec3 rb = mul_t(t.mp.axes, sub(sp.x, t.mp.com));
    t.body.push_back({rb, sp.r});
    t.bounding_radius = std::max(t.bounding_radius, norm(rb) + sp.r);
  }
}

// Template from spheres, mass properties integrated over the union.
inline Template make_template(std::string name, std::vector<Sphere> spheres, double rho, int resolution = 64,
                              Integration method = Integration::columns) {
  Template t;
  t.name = std::move(name);
  t.spheres = std::move(spheres);
  t.density = rho;
  t.mp = union_mass_properties(t.spheres, rho, resolution, method);
  build_body_frame(t);
  return t;
}

// Template from spheres with explicit mass properties (mass, com, inertia about com in the
// template frame); the inertia tensor must be symmetric positive definite and satisfy the triangle
// inequalities of principal moments (I_a + I_b >= I_c).
inline Template make_template_explicit(std::string name, std::vector<Sphere> spheres, double mass, const Vec3& com,
                                       const Mat3& inertia) {
  check_spheres(spheres);
  checks::positive("clump mass", mass);
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b)
      if (std::fabs(inertia[a][b] - inertia[b][a]) > 1e-12 * (std::fabs(inertia[a][b]) + std::fabs(inertia[a][a])))
        checks::fail("clump inertia (asymmetric) off-diagonal", inertia[a][b], "symmetric tensor");
  Template t;
  t.name = std::move(name);
  t.spheres = std::move(spheres);
  t.mp.mass = mass;
  t.mp.com = com;
  t.mp.inertia = inertia;
  build_body_frame(t);
  const Vec3& p = t.mp.principal;
  checks::positive("clump principal moment of inertia I1", p[0]);
  if (p[0] + p[1] < p[2] * (1.0 - 1e-12))
    checks::fail("clump principal moments: I1 + I2 - I3", p[0] + p[1] - p[2], "[0, inf) (triangle inequality)");
  return t;
}

// ------------------------------------------------------------------ built-in shapes
inline std::vector<Sphere> shape_grid(int nx, int ny, int nz, double r, double d) {
  if (nx < 1) checks::fail("clump grid nx", nx, "[1, inf)");
  if (ny < 1) checks::fail("clump grid ny", ny, "[1, inf)");
  if (nz < 1) checks::fail("clump grid nz", nz, "[1, inf)");
  checks::positive("clump sphere radius", r);
  checks::non_negative("clump sphere distance", d);
  std::vector<Sphere> s;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s.push_back({Vec3{(i - 0.5 * (nx - 1)) * d, (j - 0.5 * (ny - 1)) * d, (k - 0.5 * (nz - 1)) * d}, r});
  return s;
}
inline std::vector<Sphere> shape_single(double r) { return shape_grid(1, 1, 1, r, 0.0); }
inline std::vector<Sphere> shape_rod(int n, double r, double d) { return shape_grid(n, 1, 1, r, d); }
inline std::vector<Sphere> shape_square4(double r, double d) { return shape_grid(2, 2, 1, r, d); }
inline std::vector<Sphere> shape_cube8(double r, double d) { return shape_grid(2, 2, 2, r, d); }
// Regular tetrahedron of edge d centred at 0: alternate corners of a cube of edge d/sqrt(2).
inline std::vector<Sphere> shape_tetra(double r, double d) {
  checks::positive("clump sphere radius", r);
  checks::positive("clump sphere distance", d);
  const double a = d / (2.0 * std::sqrt(2.0));
  return {{Vec3{a, a, a}, r}, {Vec3{a, -a, -a}, r}, {Vec3{-a, a, -a}, r}, {Vec3{-a, -a, a}, r}};
}

// Built-in shape by name: single | rod | tetra | square4 | cube8 (n only for rod).
inline std::vector<Sphere> builtin_shape(const std::string& name, double r, double d, int n = 2) {
  if (name == "single") return shape_single(r);
  if (name == "rod" || name == "dimer") return shape_rod(name == "dimer" ? 2 : n, r, d);
  if (name == "tetra") return shape_tetra(r, d);
  if (name == "square4") return shape_square4(r, d);
  if (name == "cube8") return shape_cube8(r, d);
  throw std::invalid_argument("clump shape '" + name +
                              "' is not known; allowed: single, dimer, rod, tetra, square4, cube8");
}

// ------------------------------------------------------------------ text format
inline Template parse_template(std::istream& in, const std::string& name, double default_density) {
  std::vector<Sphere> spheres;
  double density = default_density, mass = 0.0;
  int resolution = 64;
  Integration method = Integration::columns;
  bool has_mass = false, has_com = false, has_inertia = false;
  Vec3 com{};
  Mat3 inertia{};
  std::string line;
  int lineno = 0;
  auto bad = [&](const std::string& what) {
    throw std::invalid_argument("clump template '" + name + "' line " + std::to_string(lineno) + ": " + what);
  };
  auto read_numbers = [&](std::istringstream& ls, const std::string& key, int count) {
    std::vector<double> v;
    std::string tok;
    while (ls >> tok) {
      try {
        std::size_t used = 0;
        double x = std::stod(tok, &used);
        if (used != tok.size()) throw std::invalid_argument(tok);
        v.push_back(x);
      } catch (const std::exception&) {
        bad("keyword '" + key + "': value '" + tok + "' is not a number");
      }
    }
    if (static_cast<int>(v.size()) != count)
      bad("keyword '" + key + "' needs " + std::to_string(count) + " numbers, got " + std::to_string(v.size()));
    return v;
  };
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key)) continue;
    if (key == "sphere") {
      auto v = read_numbers(ls, key, 4);
      if (!(v[3] > 0.0)) bad("keyword 'sphere': radius " + checks::number(v[3]) + " is outside (0, inf)");
      spheres.push_back({Vec3{v[0], v[1], v[2]}, v[3]});
    } else if (key == "density") {
      density = read_numbers(ls, key, 1)[0];
      if (!(density > 0.0)) bad("keyword 'density': value " + checks::number(density) + " is outside (0, inf)");
    } else if (key == "resolution") {
      const double r = read_numbers(ls, key, 1)[0];
      if (!(r >= 4.0) || r != std::floor(r) || r > 4096)
        bad("keyword 'resolution': value " + checks::number(r) + " is not an integer in [4, 4096]");
      resolution = static_cast<int>(r);
    } else if (key == "integration") {
      std::string m;
      ls >> m;
      if (m == "columns") method = Integration::columns;
      else if (m == "voxel") method = Integration::voxel;
      else if (m == "monte_carlo") method = Integration::monte_carlo;
      else bad("keyword 'integration': value '" + m + "' is not one of columns, voxel, monte_carlo");
    } else if (key == "mass") {
      mass = read_numbers(ls, key, 1)[0];
      if (!(mass > 0.0)) bad("keyword 'mass': value " + checks::number(mass) + " is outside (0, inf)");
      has_mass = true;
    } else if (key == "com") {
      auto v = read_numbers(ls, key, 3);
      com = {v[0], v[1], v[2]};
      has_com = true;
    } else if (key == "inertia") {
      auto v = read_numbers(ls, key, 6);
      inertia = Mat3{Vec3{v[0], v[3], v[4]}, Vec3{v[3], v[1], v[5]}, Vec3{v[4], v[5], v[2]}};
      has_inertia = true;
    } else {
      bad("unknown keyword '" + key +
          "'; allowed: sphere, density, resolution, integration, mass, com, inertia");
    }
  }
  lineno = 0;
  if (spheres.empty()) bad("no 'sphere' line (need at least one)");
  if (has_mass || has_com || has_inertia) {
    if (!(has_mass && has_com && has_inertia))
      bad("explicit mass properties need all of 'mass', 'com' and 'inertia' (got" +
          std::string(has_mass ? " mass" : "") + (has_com ? " com" : "") + (has_inertia ? " inertia" : "") + ")");
    Template t = make_template_explicit(name, spheres, mass, com, inertia);
    t.density = default_density;
    return t;
  }
  if (!(density > 0.0))
    bad("no density: give 'density rho' in the file or a density > 0 to the reader (got " +
        checks::number(density) + ")");
  return make_template(name, spheres, density, resolution, method);
}

inline Template parse_template_string(const std::string& text, const std::string& name, double density) {
  std::istringstream in(text);
  return parse_template(in, name, density);
}

inline Template read_template_file(const std::string& path, double density) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("clump template file '" + path + "' cannot be opened");
  return parse_template(in, path, density);
}

}  // namespace clumps
}  // namespace tdem
