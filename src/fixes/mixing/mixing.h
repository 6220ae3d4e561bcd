// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: mixing measures of a particle bed on a grate (physics_reference.md 7.2, docs/grate.md),
// on plain arrays, host-independent. Positions x and velocities v are n x 3 doubles, interleaved
// (x[3 i + k]); radii r are n doubles.
//
// Velocity-based (7.2.1), evaluation radius r_v:
//   N_i   = { j : |x_j - x_i| <= r_v }        (includes i itself; minimum image on periodic axes)
//   vbar_i = (1/|N_i|) sum_{j in N_i} v_j,    vtil_i = v_i - vbar_i
//   p_k   = standard deviation (population, 1/N) of vtil_{i,k} over the particles i of a region
//           (and, when snapshots are accumulated, over time),   P' = sqrt(p_x^2 + p_y^2 + p_z^2).
//   All particles count as neighbours; an optional mask selects the particles that are evaluated
//   (e.g. to leave out the ones touching the moving bars).
// Trajectory-based (7.2.2), column width c:
//   s_i = highest particle centre (up coordinate) among the particles j whose horizontal offset from
//         i is within the column, |dx_transport| <= c/2 (and |dx_lateral| <= c/2 in 3D) - includes i,
//   b_i = grate_height(x_i) + r_i, the centre height of a particle of radius r_i resting on the grate,
//   D_i = (s_i - z_i)/(s_i - b_i) clipped to [0, 1] (normalised: surface 0, grate 1), or
//   D_i = s_i - z_i [m] (normalise = false). A one-layer column (s_i - b_i <= 0) gives D = 0.
//   Along the trajectory of each particle (snapshots at times t_k, by particle id):
//   Dbar = mean of the samples, Dtil(t) = D(t) - Dbar, sigma_D = rms of Dtil,
//   Q' = <|dDtil/dt|>_t = sum_k |D_{k+1} - D_k| / sum_k (t_{k+1} - t_k) (finite-difference time average;
//   only consecutive snapshots in which the particle is present count). Per region, an increment
//   belongs to the region of the particle at the earlier snapshot, and Q'_region = sum |dD| / sum dt
//   over all increments of the region.
// Regions: `count` equal bins of the transport coordinate (axis) between lo and hi; particles outside
// belong to no region.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

#include "fixes/grate/kinematics.h"  // bad_value
#include "fixes/mixing/neighbourhood.h"

namespace tdem {
namespace grate {
namespace mixing {

inline void check_periodic(const Periodic& per, double r, const char* what) {
  for (int k = 0; k < 3; ++k)
    if (per.on[k] && !(per.hi[k] - per.lo[k] >= 2.0 * r))
      bad_value("mixing", std::string("periodic length of axis ") + "xyz"[k] + " (must be >= 2 " + what + ")",
                per.hi[k] - per.lo[k], "[2 " + std::string(what) + ", inf)");
}

// Equal bins of one coordinate (the transport direction) = regions along the grate.
struct Bins {
  int axis = 0;
  double lo = 0.0, hi = 1.0;
  int count = 1;
  void validate() const {
    if (axis < 0 || axis > 2) bad_value("mixing regions", "axis", axis, "{0, 1, 2}");
    if (count < 1) bad_value("mixing regions", "count", count, "[1, inf)");
    if (!(hi > lo)) bad_value("mixing regions", "hi - lo", hi - lo, "(0, inf)");
  }
  int index(const double* p) const {
    const double f = (p[axis] - lo) / (hi - lo);
    if (!(f >= 0.0 && f <= 1.0)) return -1;
    return std::min(count - 1, static_cast<int>(f * count));
  }
};

// ---------------------------------------------------------------- velocity based
struct LocalVelocity {
  std::vector<double> mean;   // vbar, n x 3
  std::vector<double> fluct;  // vtil = v - vbar, n x 3
  std::vector<int> neighbours;  // |N_i| (>= 1)
};

// The exponent e with |v| < 2^e for all the velocities given (0 when all are 0): the scale of the
// fixed-point neighbour sums of local_velocity (the same on every rank: take the maximum over ranks).
inline int velocity_exponent(std::size_t n3, const double* v) {
  double m = 0.0;
  for (std::size_t q = 0; q < n3; ++q) m = std::max(m, std::fabs(v[q]));
  int e = 0;
  if (m > 0.0 && std::isfinite(m)) std::frexp(m, &e);
  return e;
}

// vbar, vtil of the first c.n_eval points of the cloud; v holds the velocities of all c.n points,
// all below 2^v_exp in magnitude (velocity_exponent). A particle present as several copies (images)
// counts once: the copy that sits at its minimum image. The neighbour velocities are summed as
// integers (v 2^(62 - v_exp) rounded, 128-bit sums): exact, so the mean depends only on the
// neighbours, not on their order or on how the particles are spread over ranks.
inline LocalVelocity local_velocity(const Cloud& c, const double* v, double r_v, const Periodic& per, int v_exp) {
  if (!(r_v > 0.0) || !std::isfinite(r_v)) bad_value("mixing", "radius (evaluation radius r_v)", r_v, "(0, inf)");
  check_periodic(per, r_v, "r_v");
  for (std::size_t q = 0; q < 3 * c.n; ++q)
    if (!std::isfinite(v[q])) bad_value("mixing", "velocity", v[q], "a finite number");
  const std::vector<double> b = cloud_positions(c, per);
  const bool use[3] = {true, true, true};
  CellList cl(c.n, b.data(), r_v * (1.0 + 1e-9), use);  // margin for the round-off of image positions
  // positions as the particles have them and fixed-point velocities, in the list's (cell) order
  std::vector<double> xs(3 * c.n);
  std::vector<std::int64_t> vq(3 * c.n);
  for (std::size_t q = 0; q < c.n; ++q) {
    const std::size_t j = cl.items()[q];
    for (int k = 0; k < 3; ++k) {
      xs[3 * q + k] = c.x[3 * j + k];
      vq[3 * q + k] = std::llrint(std::ldexp(v[3 * j + k], 62 - v_exp));
    }
  }
  LocalVelocity out;
  out.mean.assign(3 * c.n_eval, 0.0);
  out.fluct.assign(3 * c.n_eval, 0.0);
  out.neighbours.assign(c.n_eval, 0);
  const double r2 = r_v * r_v;
  const double pre2 = r2 * (1.0 + 1e-6);  // the position of the right copy differs from x_i + d by round-off
  const bool any_periodic = per.on[0] || per.on[1] || per.on[2];
  for (std::size_t i = 0; i < c.n_eval; ++i) {
    const double* p = c.x + 3 * i;
    __int128 s0 = 0, s1 = 0, s2 = 0;
    int cnt = 0;
    cl.for_each_candidate(p, [&](std::size_t j, const double* bj) {
      const double e0 = bj[0] - p[0], e1 = bj[1] - p[1], e2 = bj[2] - p[2];
      if (e0 * e0 + e1 * e1 + e2 * e2 > pre2) return true;  // far where it sits: no neighbour, or another copy
      double d[3];
      min_image(&xs[3 * j], p, per, d);
      if (any_periodic)
        for (int k = 0; k < 3; ++k)
          if (per.on[k] && std::fabs(bj[k] - p[k] - d[k]) > 0.5 * per.length(k)) return true;  // another copy
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= r2) {
        s0 += vq[3 * j];
        s1 += vq[3 * j + 1];
        s2 += vq[3 * j + 2];
        ++cnt;
      }
      return true;
    });
    out.neighbours[i] = cnt;
    const __int128 s[3] = {s0, s1, s2};
    for (int k = 0; k < 3; ++k) {
      out.mean[3 * i + k] = std::ldexp(static_cast<double>(s[k]), v_exp - 62) / cnt;
      out.fluct[3 * i + k] = v[3 * i + k] - out.mean[3 * i + k];
    }
  }
  return out;
}

// all n particles evaluated; periodic axes by the images of the particles themselves
inline LocalVelocity local_velocity(std::size_t n, const double* x, const double* v, double r_v,
                                    const Periodic& per = Periodic{}) {
  const bool use[3] = {true, true, true};
  const SelfCloud s = self_cloud(n, x, per, r_v * (1.0 + 1e-9), use, true);
  std::vector<double> vs(3 * s.source.size());
  for (std::size_t q = 0; q < s.source.size(); ++q) std::copy_n(v + 3 * s.source[q], 3, &vs[3 * q]);
  return local_velocity(s.cloud(), vs.data(), r_v, per, velocity_exponent(3 * n, v));
}

// Running sums of the fluctuations of one region; merge() adds snapshots or processors.
struct VelocityStats {
  long n = 0;
  double sum[3] = {0.0, 0.0, 0.0};
  double sumsq[3] = {0.0, 0.0, 0.0};
  void add(const double* vt) {
    ++n;
    for (int k = 0; k < 3; ++k) {
      sum[k] += vt[k];
      sumsq[k] += vt[k] * vt[k];
    }
  }
  void merge(const VelocityStats& o) {
    n += o.n;
    for (int k = 0; k < 3; ++k) {
      sum[k] += o.sum[k];
      sumsq[k] += o.sumsq[k];
    }
  }
  // p_k: population standard deviation of vtil_k; 0 for an empty region
  double p(int k) const {
    if (n == 0) return 0.0;
    const double m = sum[k] / n;
    return std::sqrt(std::max(0.0, sumsq[k] / n - m * m));
  }
  double P() const { return std::sqrt(p(0) * p(0) + p(1) * p(1) + p(2) * p(2)); }
};

// One snapshot: per-region statistics of vtil. include[i] == 0 leaves particle i out of the
// statistics (it still counts as a neighbour); nullptr = all. field (optional) receives vbar, vtil.
inline std::vector<VelocityStats> velocity_mixing(std::size_t n, const double* x, const double* v, double r_v,
                                                  const Bins& bins, const Periodic& per = Periodic{},
                                                  const unsigned char* include = nullptr,
                                                  LocalVelocity* field = nullptr) {
  bins.validate();
  LocalVelocity lv = local_velocity(n, x, v, r_v, per);
  std::vector<VelocityStats> out(bins.count);
  for (std::size_t i = 0; i < n; ++i) {
    if (include && !include[i]) continue;
    const int r = bins.index(x + 3 * i);
    if (r >= 0) out[r].add(&lv.fluct[3 * i]);
  }
  if (field) *field = std::move(lv);
  return out;
}

// ---------------------------------------------------------------- trajectory based
struct DepthOptions {
  int transport_axis = 0;
  int up_axis = 2;
  int lateral_axis = 1;        // -1: 2D, the column is a strip |dx_transport| <= c/2
  double column_width = 0.0;   // c [m], > 0 (a few particle diameters)
  bool normalise = true;
  Periodic periodic;           // periodic transport/lateral axes (minimum image)
  // height of the grate surface (up coordinate) under the point (transport, lateral); required
  std::function<double(double transport, double lateral)> grate_height;
};

struct Depths {
  std::vector<double> depth;    // D (normalised) or depth [m]
  std::vector<double> surface;  // s_i
  std::vector<double> bottom;   // b_i
};

// the column of the depth evaluation: transport and lateral axes
inline void depth_axes(const DepthOptions& o, bool use[3]) {
  use[0] = use[1] = use[2] = false;
  use[o.transport_axis] = true;
  if (o.lateral_axis >= 0) use[o.lateral_axis] = true;
}

inline void check_depth_options(const DepthOptions& o) {
  const std::string c = "mixing depth";
  for (int a : {o.transport_axis, o.up_axis})
    if (a < 0 || a > 2) bad_value(c, "axis", a, "{0, 1, 2}");
  if (o.lateral_axis < -1 || o.lateral_axis > 2) bad_value(c, "lateral axis", o.lateral_axis, "{-1 (2D), 0, 1, 2}");
  if (o.transport_axis == o.up_axis || o.lateral_axis == o.up_axis || o.lateral_axis == o.transport_axis)
    throw std::invalid_argument("mixing depth: transport, lateral and up axes must differ");
  if (!(o.column_width > 0.0) || !std::isfinite(o.column_width))
    bad_value(c, "column (column width)", o.column_width, "(0, inf)");
  if (!o.grate_height) throw std::invalid_argument("mixing depth: no grate height function given");
  check_periodic(o.periodic, 0.5 * o.column_width, "c/2");
}

// the periodic axes of the depth evaluation (never the up axis)
inline Periodic depth_periodic(const DepthOptions& o) {
  Periodic per = o.periodic;
  per.on[o.up_axis] = false;
  return per;
}

// D of the first c.n_eval points of the cloud (radius: their radii); the surface s_i is the highest
// centre of all points of the cloud in the column of i (a maximum: any copy, any order gives the same).
inline Depths particle_depths(const Cloud& c, const double* radius, const DepthOptions& o) {
  check_depth_options(o);
  bool use[3];
  depth_axes(o, use);
  const Periodic per = depth_periodic(o);
  const double h = 0.5 * o.column_width;
  const std::vector<double> b = cloud_positions(c, per);
  std::vector<double> up(c.n);
  for (std::size_t q = 0; q < c.n; ++q) up[q] = c.x[3 * q + o.up_axis];
  CellList cl(c.n, b.data(), h * (1.0 + 1e-9), use, up.data());  // each cell from its highest point down
  std::vector<double> xs(3 * c.n), height(c.n);  // in the list's order
  for (std::size_t q = 0; q < c.n; ++q) {
    std::copy_n(c.x + 3 * cl.items()[q], 3, &xs[3 * q]);
    height[q] = up[cl.items()[q]];
  }
  Depths out;
  out.depth.resize(c.n_eval);
  out.surface.resize(c.n_eval);
  out.bottom.resize(c.n_eval);
  const int t = o.transport_axis, u = o.up_axis, l = o.lateral_axis;
  for (std::size_t i = 0; i < c.n_eval; ++i) {
    const double* p = c.x + 3 * i;
    double s = p[u];
    cl.for_each_candidate(p, [&](std::size_t j, const double*) {
      if (!(height[j] > s)) return false;  // nothing higher below in this cell
      double d[3];
      min_image(&xs[3 * j], p, per, d);
      if (std::fabs(d[t]) <= h && (l < 0 || std::fabs(d[l]) <= h)) {
        s = height[j];  // the highest of this cell in the column
        return false;
      }
      return true;
    });
    const double bot = o.grate_height(p[t], l >= 0 ? p[l] : 0.0) + radius[i];
    out.surface[i] = s;
    out.bottom[i] = bot;
    const double depth = s - p[u];
    if (!o.normalise) {
      out.depth[i] = depth;
    } else {
      const double bed = s - bot;
      out.depth[i] = bed > 0.0 ? std::max(0.0, std::min(1.0, depth / bed)) : 0.0;
    }
  }
  return out;
}

// all n particles evaluated; periodic axes by the images of the particles themselves
inline Depths particle_depths(std::size_t n, const double* x, const double* radius, const DepthOptions& o) {
  check_depth_options(o);
  bool use[3];
  depth_axes(o, use);
  const SelfCloud s = self_cloud(n, x, depth_periodic(o), 0.5 * o.column_width * (1.0 + 1e-9), use, false);
  return particle_depths(s.cloud(), radius, o);
}

// Accumulates depth trajectories over snapshots (by particle id) and per region.
class DepthTrajectories {
 public:
  struct Particle {
    long samples = 0;
    double sum_d = 0.0, sum_d2 = 0.0;    // sums of the samples D and D^2
    double total_abs = 0.0, total_dt = 0.0;  // sum |dD|, sum dt over consecutive snapshots
    double last_t = 0.0, last_d = 0.0;
    int last_region = -1;
    long last_snapshot = -2;
    double mean() const { return samples ? sum_d / samples : 0.0; }
    double sigma() const {  // rms of Dtil = D - Dbar
      if (!samples) return 0.0;
      const double m = mean();
      return std::sqrt(std::max(0.0, sum_d2 / samples - m * m));
    }
    double q() const { return total_dt > 0.0 ? total_abs / total_dt : 0.0; }  // Q'
  };
  struct Region {
    double total_abs = 0.0, total_dt = 0.0;  // increments starting in this region
    long samples = 0;
    double sum_d = 0.0, sum_d2 = 0.0;        // the D samples taken in this region
    double q() const { return total_dt > 0.0 ? total_abs / total_dt : 0.0; }
    double mean() const { return samples ? sum_d / samples : 0.0; }
    double sigma() const {
      if (!samples) return 0.0;
      const double m = mean();
      return std::sqrt(std::max(0.0, sum_d2 / samples - m * m));
    }
  };

  explicit DepthTrajectories(const Bins& bins) : bins_(bins), regions_(bins.count) { bins.validate(); }

  // One snapshot at time t: ids, depths D, positions (for the region; may be nullptr = no region).
  void add(double t, std::size_t n, const long* id, const double* depth, const double* x) {
    if (snapshot_ >= 0 && !(t > last_t_))
      bad_value("mixing trajectories", "time of snapshot", t, "(" + std::to_string(last_t_) + ", inf)");
    ++snapshot_;
    for (std::size_t i = 0; i < n; ++i) {
      Particle& p = particles_[id[i]];
      const int r = x ? bins_.index(x + 3 * i) : -1;
      const double d = depth[i];
      if (p.last_snapshot == snapshot_ - 1) {
        const double a = std::fabs(d - p.last_d), dt = t - p.last_t;
        p.total_abs += a;
        p.total_dt += dt;
        if (p.last_region >= 0) {
          regions_[p.last_region].total_abs += a;
          regions_[p.last_region].total_dt += dt;
        }
      }
      ++p.samples;
      p.sum_d += d;
      p.sum_d2 += d * d;
      if (r >= 0) {
        ++regions_[r].samples;
        regions_[r].sum_d += d;
        regions_[r].sum_d2 += d * d;
      }
      p.last_t = t;
      p.last_d = d;
      p.last_region = r;
      p.last_snapshot = snapshot_;
    }
    last_t_ = t;
  }

  // Start a new averaging window: clears all sums, keeps the last sample of every particle so the
  // next snapshot still gives increments (time series of Q').
  void reset_sums() {
    for (auto& kv : particles_) {
      Particle& p = kv.second;
      p.samples = 0;
      p.sum_d = p.sum_d2 = p.total_abs = p.total_dt = 0.0;
    }
    for (Region& r : regions_) r = Region{};
  }

  const std::unordered_map<long, Particle>& particles() const { return particles_; }
  const Particle& particle(long id) const { return particles_.at(id); }
  const std::vector<Region>& regions() const { return regions_; }
  // Q' over all particles: sum |dD| / sum dt of all increments
  double q_all() const {
    double a = 0.0, dt = 0.0;
    for (const auto& kv : particles_) {
      a += kv.second.total_abs;
      dt += kv.second.total_dt;
    }
    return dt > 0.0 ? a / dt : 0.0;
  }

 private:
  Bins bins_;
  std::vector<Region> regions_;
  std::unordered_map<long, Particle> particles_;
  long snapshot_ = -1;
  double last_t_ = 0.0;
};

}  // namespace mixing
}  // namespace grate
}  // namespace tdem
