// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: host-independent pieces of the clump fixes (fix tdem/clump in LIGGGHTS; usable by the LAMMPS
// fix too): exact mass properties of a template of disjoint spheres, the sphere masses, the best-fit
// body state of a set of sphere centres and velocities (bodies formed from molecules), uniformly
// random orientations and the overlap-free random placement of N clumps in a region.
//
// Everything here is deterministic and uses no host type, so that every MPI rank computes the same
// result from the same input (the hosts gather the input on every rank first).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "fixes/clumps/rigid_body.h"
#include "fixes/clumps/template.h"

namespace tdem {
namespace clumps {

// ------------------------------------------------------------------ templates in a host
inline bool spheres_disjoint(const std::vector<Sphere>& s) {
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      if (norm(sub(s[i].x, s[j].x)) < s[i].r + s[j].r) return false;
  return true;
}

// A union of disjoint spheres IS the sum of the spheres: replace the integrated mass properties by
// the exact ones (mass 4/3 pi r^3 rho each, inertia 2/5 m r^2 about each centre plus the parallel
// axis terms), so that e.g. a one-sphere clump has exactly the mass and inertia of the sphere.
// Templates with explicit mass properties (density 0) or overlapping spheres are left unchanged.
inline void exact_if_disjoint(Template& t) {
  if (!(t.density > 0.0) || !(t.mp.volume > 0.0) || !spheres_disjoint(t.spheres)) return;
  if (std::fabs(t.mp.mass / t.mp.volume - t.density) > 1e-9 * t.density) return;  // explicit
  double M = 0.0;
  Vec3 c{0, 0, 0};
  std::vector<double> m;
  for (const auto& s : t.spheres) {
    m.push_back(4.0 * M_PI / 3.0 * s.r * s.r * s.r * t.density);
    M += m.back();
    c = add(c, scale(m.back(), s.x));
  }
  c = scale(1.0 / M, c);
  Mat3 I{};
  for (std::size_t k = 0; k < t.spheres.size(); ++k) {
    const Mat3 P = point_inertia(m[k], sub(t.spheres[k].x, c));
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) I[a][b] += P[a][b] + (a == b ? 0.4 * m[k] * t.spheres[k].r * t.spheres[k].r : 0.0);
  }
  t.mp.mass = M;
  t.mp.volume = M / t.density;
  t.mp.com = c;
  t.mp.inertia = I;
  build_body_frame(t);
}

// Mass given to each sphere (for the contact laws' effective mass and for gravity): the body mass
// shared in proportion to r^3, so the shares add up to M exactly up to round-off (one sphere: M).
inline std::vector<double> sphere_masses(const Template& t) {
  double vsum = 0.0;
  for (const auto& s : t.body) vsum += s.r * s.r * s.r;
  std::vector<double> m;
  for (const auto& s : t.body) m.push_back(t.body.size() == 1 ? t.mp.mass : t.mp.mass * (s.r * s.r * s.r / vsum));
  return m;
}

// ------------------------------------------------------------------ random orientation
// Uniformly distributed unit quaternion from three uniforms (K. Shoemake, Graphics Gems III).
inline Quat random_orientation(SplitMix64& rng) {
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1), tau = 2.0 * M_PI;
  return qnormalise({a * std::sin(tau * u2), a * std::cos(tau * u2), b * std::sin(tau * u3), b * std::cos(tau * u3)});
}

// ------------------------------------------------------------------ fitting a body to its spheres
namespace detail {
// Largest eigenvalue's eigenvector of a symmetric 4x4 matrix (cyclic Jacobi).
inline std::array<double, 4> top_eigenvector4(double a[4][4]) {
  double v[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 60; ++sweep) {
    double off = 0.0, dg = 0.0;
    for (int i = 0; i < 4; ++i) {
      dg += a[i][i] * a[i][i];
      for (int j = i + 1; j < 4; ++j) off += a[i][j] * a[i][j];
    }
    if (off == 0.0 || off <= 1e-32 * dg) break;
    for (int p = 0; p < 3; ++p)
      for (int q = p + 1; q < 4; ++q) {
        if (a[p][q] == 0.0) continue;
        const double th = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (th >= 0.0 ? 1.0 : -1.0) / (std::fabs(th) + std::sqrt(th * th + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 4; ++k) {
          const double x = a[k][p], y = a[k][q];
          a[k][p] = c * x - s * y;
          a[k][q] = s * x + c * y;
        }
        for (int k = 0; k < 4; ++k) {
          const double x = a[p][k], y = a[q][k];
          a[p][k] = c * x - s * y;
          a[q][k] = s * x + c * y;
        }
        for (int k = 0; k < 4; ++k) {
          const double x = v[k][p], y = v[k][q];
          v[k][p] = c * x - s * y;
          v[k][q] = s * x + c * y;
        }
      }
  }
  int best = 0;
  for (int k = 1; k < 4; ++k)
    if (a[k][k] > a[best][best]) best = k;
  return {v[0][best], v[1][best], v[2][best], v[3][best]};
}

// Gaussian elimination with partial pivoting for a 6x6 system; false if singular.
inline bool solve6(double A[6][6], double b[6], double u[6]) {
  for (int c = 0; c < 6; ++c) {
    int p = c;
    for (int r = c + 1; r < 6; ++r)
      if (std::fabs(A[r][c]) > std::fabs(A[p][c])) p = r;
    if (A[p][c] == 0.0) return false;
    if (p != c) {
      for (int k = 0; k < 6; ++k) std::swap(A[p][k], A[c][k]);
      std::swap(b[p], b[c]);
    }
    for (int r = c + 1; r < 6; ++r) {
      const double f = A[r][c] / A[c][c];
      for (int k = c; k < 6; ++k) A[r][k] -= f * A[c][k];
      b[r] -= f * b[c];
    }
  }
  for (int c = 5; c >= 0; --c) {
    double s = b[c];
    for (int k = c + 1; k < 6; ++k) s -= A[c][k] * u[k];
    u[c] = s / A[c][c];
  }
  return true;
}
}  // namespace detail

struct BodyFit {
  State state;
  double residual = 0.0;  // largest distance of a sphere centre from its fitted place
};

// Best rigid placement of the template's body-frame offsets onto the sphere centres p (template order)
// by Horn's quaternion method (least squares), and the body velocity from the sphere velocities
// (least squares v + w x r_k = v_k; for one sphere, or spheres on a line, the spin about the line is
// taken from the mean sphere angular velocity `omega`).
inline BodyFit fit_body(const Template& t, const Body& b, const std::vector<Vec3>& p, const std::vector<Vec3>& v,
                        const std::vector<Vec3>& omega) {
  const int n = static_cast<int>(t.body.size());
  Vec3 abar{0, 0, 0}, ybar{0, 0, 0}, wbar{0, 0, 0};
  for (int k = 0; k < n; ++k) {
    abar = add(abar, t.body[k].x);
    ybar = add(ybar, p[k]);
    wbar = add(wbar, omega[k]);
  }
  abar = scale(1.0 / n, abar);
  ybar = scale(1.0 / n, ybar);
  wbar = scale(1.0 / n, wbar);
  double S[3][3] = {};
  for (int k = 0; k < n; ++k) {
    const Vec3 a = sub(t.body[k].x, abar), y = sub(p[k], ybar);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S[i][j] += a[i] * y[j];
  }
  double N[4][4] = {{S[0][0] + S[1][1] + S[2][2], S[1][2] - S[2][1], S[2][0] - S[0][2], S[0][1] - S[1][0]},
                    {S[1][2] - S[2][1], S[0][0] - S[1][1] - S[2][2], S[0][1] + S[1][0], S[2][0] + S[0][2]},
                    {S[2][0] - S[0][2], S[0][1] + S[1][0], -S[0][0] + S[1][1] - S[2][2], S[1][2] + S[2][1]},
                    {S[0][1] - S[1][0], S[2][0] + S[0][2], S[1][2] + S[2][1], -S[0][0] - S[1][1] + S[2][2]}};
  BodyFit out;
  if (n == 1) {
    out.state.q = Quat{};  // a sphere: any orientation fits; keep the identity
  } else {
    const auto e = detail::top_eigenvector4(N);
    out.state.q = qnormalise({e[0], e[1], e[2], e[3]});
  }
  const Mat3 R = rotation_matrix(out.state.q);
  out.state.x = sub(ybar, mul(R, abar));
  for (int k = 0; k < n; ++k)
    out.residual = std::max(out.residual, norm(sub(add(out.state.x, mul(R, t.body[k].x)), p[k])));
  // velocities
  double A[6][6] = {}, rhs[6] = {}, u[6] = {0, 0, 0, 0, 0, 0};
  double r2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const Vec3 r = mul(R, t.body[k].x);
    r2 += dot(r, r);
    const double J[3][6] = {{1, 0, 0, 0, r[2], -r[1]}, {0, 1, 0, -r[2], 0, r[0]}, {0, 0, 1, r[1], -r[0], 0}};
    for (int a = 0; a < 6; ++a) {
      for (int c = 0; c < 6; ++c)
        for (int i = 0; i < 3; ++i) A[a][c] += J[i][a] * J[i][c];
      for (int i = 0; i < 3; ++i) rhs[a] += J[i][a] * v[k][i];
    }
  }
  if (n == 1) {
    out.state.v = v[0];
    set_angular_velocity(out.state, b, omega[0]);
    return out;
  }
  const double eps = 1e-12 * r2;
  for (int a = 3; a < 6; ++a) {
    A[a][a] += eps;
    rhs[a] += eps * wbar[a - 3];
  }
  if (!detail::solve6(A, rhs, u)) throw std::domain_error("clump: singular velocity fit");
  out.state.v = {u[0], u[1], u[2]};
  set_angular_velocity(out.state, b, Vec3{u[3], u[4], u[5]});
  return out;
}

// ------------------------------------------------------------------ random placement
struct PlacementInput {
  int n = 0;                        // clumps to place
  std::uint64_t seed = 1;
  Vec3 lo{}, hi{};                  // box of candidate centres of mass (the region's bounding box)
  long long max_failures = 10000;   // consecutive failed attempts before giving up
  // true if a sphere of radius r centred at p lies inside the region
  std::function<bool(const Vec3&, double)> inside;
  // distance vector a - b (minimum image in periodic directions)
  std::function<Vec3(const Vec3&, const Vec3&)> delta;
  std::vector<Sphere> existing;     // spheres already in the box (every rank: all of them)
  Vec3 period{0.0, 0.0, 0.0};       // box length of each periodic direction, 0 if not periodic
};

struct PlacementResult {
  std::vector<State> bodies;        // com, orientation (v = L = 0)
  std::vector<Vec3> spheres;        // n * size() sphere centres, template order
  long long attempts = 0;
  bool complete = false;            // false: only bodies.size() of n could be placed
};

// Random sequential placement: centres uniform in [lo, hi], orientations uniform (Shoemake), a
// candidate is accepted if every sphere lies inside the region and overlaps neither an existing
// sphere nor a sphere of a clump placed before. Existing spheres and placed clumps are kept in a
// uniform hash grid of cell size >= the largest interaction distance, so each test costs O(1).
inline PlacementResult place_clumps(const Template& t, const PlacementInput& in) {
  PlacementResult res;
  const int ns = static_cast<int>(t.body.size());
  double rmax_t = 0.0;
  for (const auto& s : t.body) rmax_t = std::max(rmax_t, s.r);
  double rmax_e = 0.0;
  for (const auto& s : in.existing) rmax_e = std::max(rmax_e, s.r);
  const double cell = std::max(2.0 * rmax_t, rmax_t + rmax_e);
  auto key = [&](const Vec3& p) {
    const long long i = static_cast<long long>(std::floor(p[0] / cell)) & 0x1FFFFF;
    const long long j = static_cast<long long>(std::floor(p[1] / cell)) & 0x1FFFFF;
    const long long k = static_cast<long long>(std::floor(p[2] / cell)) & 0x1FFFFF;
    return (i << 42) | (j << 21) | k;
  };
  std::unordered_map<long long, std::vector<int>> grid;  // index into `all`
  std::vector<Sphere> all = in.existing;
  // bounding box of every sphere centre in the grid (the image search skips what lies outside)
  Vec3 bmin{INFINITY, INFINITY, INFINITY}, bmax{-INFINITY, -INFINITY, -INFINITY};
  auto grow = [&](const Vec3& p) {
    for (int d = 0; d < 3; ++d) {
      bmin[d] = std::min(bmin[d], p[d]);
      bmax[d] = std::max(bmax[d], p[d]);
    }
  };
  for (int i = 0; i < static_cast<int>(all.size()); ++i) {
    grid[key(all[i].x)].push_back(i);
    grow(all[i].x);
  }
  SplitMix64 rng(in.seed * 0x9E3779B97F4A7C15ull + 0x5DEECE66Dull);
  long long failures = 0;
  std::vector<Vec3> ps(ns);
  while (static_cast<int>(res.bodies.size()) < in.n) {
    if (failures >= in.max_failures) return res;
    ++res.attempts;
    ++failures;
    Vec3 c;
    for (int k = 0; k < 3; ++k) c[k] = in.lo[k] + rng.uniform() * (in.hi[k] - in.lo[k]);
    const Quat q = random_orientation(rng);
    State s = place(t, c, q);
    const Mat3 R = rotation_matrix(s.q);
    bool ok = true;
    for (int k = 0; ok && k < ns; ++k) {
      ps[k] = add(s.x, mul(R, t.body[k].x));
      ok = in.inside(ps[k], t.body[k].r);
    }
    for (int k = 0; ok && k < ns; ++k) {
      // the 27 cells around the sphere and, in periodic directions, around its images one period
      // away (the grid does not wrap; `delta` applies the minimum image)
      for (int ix = -1; ok && ix <= 1; ++ix)
        for (int iy = -1; ok && iy <= 1; ++iy)
          for (int iz = -1; ok && iz <= 1; ++iz) {
            if ((ix && !(in.period[0] > 0.0)) || (iy && !(in.period[1] > 0.0)) || (iz && !(in.period[2] > 0.0)))
              continue;
            const Vec3 img{ps[k][0] + ix * in.period[0], ps[k][1] + iy * in.period[1], ps[k][2] + iz * in.period[2]};
            // an image whose 27 cells lie outside the box of all placed spheres finds nothing
            bool near = true;
            for (int d = 0; d < 3; ++d) near = near && img[d] + cell >= bmin[d] && img[d] - cell <= bmax[d];
            if (!near) continue;
            for (int dx = -1; ok && dx <= 1; ++dx)
              for (int dy = -1; ok && dy <= 1; ++dy)
                for (int dz = -1; ok && dz <= 1; ++dz) {
                  const Vec3 pp{img[0] + dx * cell, img[1] + dy * cell, img[2] + dz * cell};
                  auto it = grid.find(key(pp));
                  if (it == grid.end()) continue;
                  for (int j : it->second)
                    if (norm(in.delta(ps[k], all[j].x)) < t.body[k].r + all[j].r) {
                      ok = false;
                      break;
                    }
                }
          }
    }
    if (!ok) continue;
    failures = 0;
    res.bodies.push_back(s);
    for (int k = 0; k < ns; ++k) {
      res.spheres.push_back(ps[k]);
      all.push_back({ps[k], t.body[k].r});
      grid[key(ps[k])].push_back(static_cast<int>(all.size()) - 1);
      grow(ps[k]);
    }
  }
  res.complete = true;
  return res;
}

}  // namespace clumps
}  // namespace tdem
