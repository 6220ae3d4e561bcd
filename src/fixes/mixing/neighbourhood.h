// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the neighbourhoods of the mixing measures (mixing.h), host-independent: periodic boxes, a
// uniform cell list, periodic images and the point clouds (a rank's particles, their images and a
// halo of other ranks' particles) on which the measures are evaluated.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "fixes/grate/kinematics.h"  // bad_value

namespace tdem {
namespace grate {
namespace mixing {

struct Periodic {
  bool on[3] = {false, false, false};
  double lo[3] = {0.0, 0.0, 0.0};
  double hi[3] = {0.0, 0.0, 0.0};
  double length(int k) const { return hi[k] - lo[k]; }
};

// Uniform cell list over the axes with use[k] = true (other axes: one cell), on the bounding box of
// the points. The cells are at least `cell` wide, so all points within `cell` (per axis) of a query
// point lie in the 3^d neighbouring cells. The positions are kept in cell order (contiguous scans);
// with `height` the points of a cell are ordered by height[j], highest first. Periodicity is handled
// by the caller with images.
class CellList {
 public:
  CellList(std::size_t n, const double* x, double cell, const bool use[3], const double* height = nullptr) {
    if (!(cell > 0.0) || !std::isfinite(cell)) bad_value("mixing cell list", "radius", cell, "(0, inf)");
    long total = 1;
    for (int k = 0; k < 3; ++k) {
      use_[k] = use[k];
      if (!use[k]) continue;
      double a = std::numeric_limits<double>::infinity(), b = -a;
      for (std::size_t i = 0; i < n; ++i) {
        a = std::min(a, x[3 * i + k]);
        b = std::max(b, x[3 * i + k]);
      }
      if (n == 0) a = b = 0.0;
      lo_[k] = a;
      len_[k] = b - a;
      nc_[k] = std::max(1L, static_cast<long>(std::floor(len_[k] / cell)));
      total *= nc_[k];
    }
    // keep the grid at most a few cells per particle (sparse beds in a large domain)
    const long cap = 4 * static_cast<long>(n) + 64;
    while (total > cap) {
      total = 1;
      for (int k = 0; k < 3; ++k) {
        if (use_[k]) nc_[k] = std::max(1L, nc_[k] / 2);
        total *= nc_[k];
      }
    }
    for (int k = 0; k < 3; ++k)
      if (use_[k]) size_[k] = len_[k] > 0.0 ? len_[k] / nc_[k] : 1.0;
    start_.assign(total + 1, 0);
    std::vector<long> cell_of(n);
    for (std::size_t i = 0; i < n; ++i) {
      cell_of[i] = cell_index(x + 3 * i);
      ++start_[cell_of[i] + 1];
    }
    for (long c = 0; c < total; ++c) start_[c + 1] += start_[c];
    items_.resize(n);
    std::vector<long> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) items_[fill[cell_of[i]]++] = i;
    if (height)
      for (long c = 0; c < total; ++c)
        std::sort(items_.begin() + start_[c], items_.begin() + start_[c + 1],
                  [&](std::size_t a, std::size_t b) { return height[a] > height[b] || (height[a] == height[b] && a < b); });
    xs_.resize(3 * n);
    for (std::size_t q = 0; q < n; ++q) std::copy_n(x + 3 * items_[q], 3, &xs_[3 * q]);
  }

  // f(q, xq) for the candidates near the point p: q = slot in cell order (point items()[q]), xq its
  // position; in each cell, in cell order, until f returns false (the rest of that cell is skipped)
  template <class F>
  void for_each_candidate(const double* p, F&& f) const {
    long from[3], to[3];
    for (int k = 0; k < 3; ++k) {
      const long c = axis_cell(p[k], k);
      from[k] = std::max(0L, c - 1);
      to[k] = std::min(nc_[k] - 1, c + 1);
    }
    for (long a = from[0]; a <= to[0]; ++a)
      for (long b = from[1]; b <= to[1]; ++b)
        for (long c = from[2]; c <= to[2]; ++c) {
          const long cell = (a * nc_[1] + b) * nc_[2] + c;
          for (long q = start_[cell]; q < start_[cell + 1]; ++q)
            if (!f(static_cast<std::size_t>(q), &xs_[3 * q])) break;
        }
  }

 // the point in each slot
  const std::vector<std::size_t>& items() const { return items_; }

 private:
  long axis_cell(double v, int k) const {
    if (!use_[k]) return 0;
    const long c = static_cast<long>(std::floor((v - lo_[k]) / size_[k]));
    return std::max(0L, std::min(nc_[k] - 1, c));
  }
  long cell_index(const double* p) const {
    return (axis_cell(p[0], 0) * nc_[1] + axis_cell(p[1], 1)) * nc_[2] + axis_cell(p[2], 2);
  }

  bool use_[3] = {true, true, true};
  long nc_[3] = {1, 1, 1};
  double lo_[3] = {0, 0, 0}, len_[3] = {0, 0, 0}, size_[3] = {1, 1, 1};
  std::vector<long> start_;
  std::vector<std::size_t> items_;
  std::vector<double> xs_;
};

// ---------------------------------------------------------------- periodic images, point clouds
// A periodic image of a point is named by a code: (s0 + 1) + 3 (s1 + 1) + 9 (s2 + 1), where s_k in
// {-1, 0, 1} box lengths are added along axis k; kNoShift = the point itself.
constexpr int kNoShift = 13;

inline void image_position(const double* x, int code, const Periodic& per, double* out) {
  for (int k = 0; k < 3; ++k) {
    const int s = code % 3 - 1;
    code /= 3;
    out[k] = s ? x[k] + s * per.length(k) : x[k];
  }
}

// Is the image `code` of p (shifts along periodic axes only) within r of the box [lo, hi] over the
// axes with use[k]: Euclidean distance (euclid) or per axis?
inline bool image_near(const double* p, int code, const Periodic& per, const double* lo, const double* hi, double r,
                       const bool use[3], bool euclid) {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k, code /= 3) {
    const int s = code % 3 - 1;
    if (s != 0 && !per.on[k]) return false;
    if (!use[k]) continue;
    const double q = s ? p[k] + s * per.length(k) : p[k];
    const double gap = q < lo[k] ? lo[k] - q : (q > hi[k] ? q - hi[k] : 0.0);
    if (euclid) sum += gap * gap;
    else if (gap > r) return false;
  }
  return !euclid || sum <= r * r;
}

// f(code) for every image of p (the point itself included) within r of the box [lo, hi]
template <class F>
void for_each_image_near(const double* p, const Periodic& per, const double* lo, const double* hi, double r,
                         const bool use[3], bool euclid, F&& f) {
  for (int code = 0; code < 27; ++code)
    if (image_near(p, code, per, lo, hi, r, use, euclid)) f(code);
}

inline void bounding_box(std::size_t n, const double* x, double* lo, double* hi) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[3 * i + k]);
      hi[k] = std::max(hi[k], x[3 * i + k]);
    }
}

// The points of a neighbourhood evaluation: the first n_eval are evaluated (as themselves), all n
// are neighbours: the particles of this rank, periodic images and the particles of other ranks
// near them (a halo). Positions are as the particles have them; image codes say where a copy sits.
struct Cloud {
  std::size_t n = 0, n_eval = 0;
  const double* x = nullptr;   // n x 3
  const int* image = nullptr;  // n image codes (nullptr: all kNoShift)
  const double* id = nullptr;  // n particle ids: neighbour sums are taken in id order (nullptr: index)
};

// A single set of n particles (all evaluated) with the images of its own particles that lie within
// r of its bounding box, for the serial evaluation of periodic boxes. source[q] = particle of point q.
struct SelfCloud {
  std::vector<double> x, id;
  std::vector<int> image;
  std::vector<std::size_t> source;
  Cloud cloud() const { return Cloud{source.size(), n_eval, x.data(), image.data(), id.data()}; }
  std::size_t n_eval = 0;
};

inline SelfCloud self_cloud(std::size_t n, const double* x, const Periodic& per, double r, const bool use[3],
                            bool euclid) {
  SelfCloud s;
  s.n_eval = n;
  double lo[3], hi[3];
  bounding_box(n, x, lo, hi);
  auto put = [&](std::size_t i, int code) {
    s.x.insert(s.x.end(), x + 3 * i, x + 3 * i + 3);
    s.id.push_back(static_cast<double>(i));
    s.image.push_back(code);
    s.source.push_back(i);
  };
  for (std::size_t i = 0; i < n; ++i) put(i, kNoShift);
  if (per.on[0] || per.on[1] || per.on[2])
    for (std::size_t i = 0; i < n; ++i)
      for_each_image_near(x + 3 * i, per, lo, hi, r, use, euclid, [&](int code) {
        if (code != kNoShift) put(i, code);
      });
  return s;
}

// positions at which the points of the cloud sit (their image positions)
inline std::vector<double> cloud_positions(const Cloud& c, const Periodic& per) {
  std::vector<double> b(c.x, c.x + 3 * c.n);
  if (c.image)
    for (std::size_t q = 0; q < c.n; ++q)
      if (c.image[q] != kNoShift) image_position(c.x + 3 * q, c.image[q], per, &b[3 * q]);
  return b;
}

// d = x_j - x_i with the minimum image along the periodic axes (the same operations for any cloud)
inline void min_image(const double* xj, const double* xi, const Periodic& per, double* d) {
  for (int k = 0; k < 3; ++k) {
    d[k] = xj[k] - xi[k];
    if (per.on[k]) d[k] -= per.length(k) * std::round(d[k] / per.length(k));
  }
}

}  // namespace mixing
}  // namespace grate
}  // namespace tdem
