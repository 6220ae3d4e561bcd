// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the host-independent part of the mixing styles of LAMMPS and LIGGGHTS (docs/mixing_hosts.md):
//   compute ID group tdem/mixing/velocity radius R_V bins AXIS LO HI N [periodic AXIS ...] [exclude GROUP]
//   fix ID group tdem/mixing/depth every N column C bins AXIS LO HI NB (grate FIXID | floor H)
//       [normalise yes|no] [up AXIS] [lateral AXIS|none] [file NAME]
// Argument parsing (std::invalid_argument naming keyword, value and allowed values), the MPI gather
// of the per-particle rows in atom-id order (the same array on every rank, independent of the domain
// decomposition) and the evaluation with the core of mixing.h.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixes/mixing/mixing.h"

namespace tdem {
namespace grate {
namespace mixing {
namespace host {

// ------------------------------------------------------------------ argument parsing
inline std::string quote(const std::string& s) { return "'" + s + "'"; }

// The shortest text that reads back as v (as fmt's "{}" prints it: 0.3, 1e-05, 12.5).
inline std::string number_text(double v) {
  char buf[40];
  for (int p = 1; p <= 17; ++p) {
    std::snprintf(buf, sizeof buf, "%.*g", p, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

[[noreturn]] inline void arg_error(const std::string& ctx, const std::string& keyword, const std::string& value,
                                   const std::string& allowed) {
  throw std::invalid_argument(ctx + ": keyword '" + keyword + "' value " + quote(value) + " is invalid; allowed: " +
                              allowed);
}

inline double parse_number(const std::string& ctx, const std::string& kw, const std::string& s,
                           const std::string& allowed) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    arg_error(ctx, kw, s, allowed);
  return v;
}

inline double parse_positive(const std::string& ctx, const std::string& kw, const std::string& s) {
  const double v = parse_number(ctx, kw, s, "a number > 0");
  if (!(v > 0.0)) arg_error(ctx, kw, s, "a number > 0");
  return v;
}

// Size limits of the input (docs/limits.md). Bins: every rank holds 6 doubles per bin and a
// snapshot writes a row per bin; 1e5 bins resolve a 10 m bed to 0.1 mm.
inline constexpr long kMaxBins = 100000;
inline constexpr long kMaxCount = 100000000L;  // every: steps between snapshots

inline long parse_count(const std::string& ctx, const std::string& kw, const std::string& s, long max = kMaxCount) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE || v < 1 || v > max)
    arg_error(ctx, kw, s, "an integer in [1, " + std::to_string(max) + "]");
  return v;
}

// x|y|z -> 0|1|2; "none" -> -1 when allowed
inline int parse_axis(const std::string& ctx, const std::string& kw, const std::string& s, bool allow_none = false) {
  if (s == "x") return 0;
  if (s == "y") return 1;
  if (s == "z") return 2;
  if (allow_none && s == "none") return -1;
  arg_error(ctx, kw, s, allow_none ? "x, y, z, none" : "x, y, z");
}

inline bool parse_yes_no(const std::string& ctx, const std::string& kw, const std::string& s) {
  if (s == "yes") return true;
  if (s == "no") return false;
  arg_error(ctx, kw, s, "yes, no");
}

inline const std::string& need(const std::vector<std::string>& a, std::size_t i, const std::string& ctx,
                               const std::string& kw, const std::string& what) {
  if (i >= a.size()) throw std::invalid_argument(ctx + ": keyword '" + kw + "' needs " + what);
  return a[i];
}

// `bins AXIS LO HI N` starting at a[i] == "bins"; returns the index after it
inline std::size_t parse_bins(const std::vector<std::string>& a, std::size_t i, const std::string& ctx, Bins& b) {
  const std::string what = "4 values: AXIS (x, y, z) LO HI N";
  b.axis = parse_axis(ctx, "bins", need(a, i + 1, ctx, "bins", what));
  b.lo = parse_number(ctx, "bins", need(a, i + 2, ctx, "bins", what), "a number (LO)");
  b.hi = parse_number(ctx, "bins", need(a, i + 3, ctx, "bins", what), "a number (HI)");
  if (!(b.hi > b.lo)) arg_error(ctx, "bins", a[i + 3], "HI > LO = " + a[i + 2]);
  b.count = static_cast<int>(parse_count(ctx, "bins", need(a, i + 4, ctx, "bins", what), kMaxBins));
  return i + 5;
}

struct VelocityConfig {
  double radius = 0.0;
  Bins bins;
  bool periodic[3] = {false, false, false};
  std::string exclude;  // group name, "" = none
};

inline VelocityConfig parse_velocity(const std::vector<std::string>& a, const std::string& ctx) {
  VelocityConfig c;
  bool have_r = false, have_bins = false;
  std::size_t i = 0;
  while (i < a.size()) {
    const std::string& k = a[i];
    if (k == "radius") {
      c.radius = parse_positive(ctx, "radius", need(a, i + 1, ctx, "radius", "a value R_V > 0"));
      have_r = true;
      i += 2;
    } else if (k == "bins") {
      i = parse_bins(a, i, ctx, c.bins);
      have_bins = true;
    } else if (k == "periodic") {
      const std::size_t i0 = i;
      need(a, i + 1, ctx, "periodic", "one or more axes (x, y, z)");
      ++i;
      while (i < a.size() && (a[i] == "x" || a[i] == "y" || a[i] == "z")) c.periodic[parse_axis(ctx, "periodic", a[i++])] = true;
      if (i == i0 + 1) arg_error(ctx, "periodic", a[i], "x, y, z");
    } else if (k == "exclude") {
      c.exclude = need(a, i + 1, ctx, "exclude", "a group ID");
      i += 2;
    } else {
      throw std::invalid_argument(ctx + ": unknown keyword " + quote(k) + "; allowed: radius, bins, periodic, exclude");
    }
  }
  if (!have_r) throw std::invalid_argument(ctx + ": missing keyword 'radius R_V' (evaluation radius, > 0)");
  if (!have_bins) throw std::invalid_argument(ctx + ": missing keyword 'bins AXIS LO HI N'");
  return c;
}

struct DepthConfig {
  long every = 0;
  double column = 0.0;
  Bins bins;
  bool use_grate = false;
  std::string grate_fix;
  double floor = 0.0;
  bool normalise = true;
  int up = -2;       // -2: default (z in 3D, y in 2D)
  int lateral = -2;  // -2: default (3D: the third axis; 2D: none)
  std::string file;
};

inline DepthConfig parse_depth(const std::vector<std::string>& a, const std::string& ctx, int dimension) {
  DepthConfig c;
  bool have_every = false, have_col = false, have_bins = false, have_ground = false;
  std::size_t i = 0;
  while (i < a.size()) {
    const std::string& k = a[i];
    if (k == "every") {
      c.every = parse_count(ctx, "every", need(a, i + 1, ctx, "every", "a value N >= 1 (steps)"));
      have_every = true;
      i += 2;
    } else if (k == "column") {
      c.column = parse_positive(ctx, "column", need(a, i + 1, ctx, "column", "a value C > 0 (column width)"));
      have_col = true;
      i += 2;
    } else if (k == "bins") {
      i = parse_bins(a, i, ctx, c.bins);
      have_bins = true;
    } else if (k == "grate" || k == "floor") {
      if (have_ground)
        throw std::invalid_argument(ctx + ": keywords 'grate' and 'floor' given twice or both; allowed: one of them");
      have_ground = true;
      if (k == "grate") {
        c.use_grate = true;
        c.grate_fix = need(a, i + 1, ctx, "grate", "a fix ID (a grate fix)");
      } else {
        c.floor = parse_number(ctx, "floor", need(a, i + 1, ctx, "floor", "a height H"), "a number (height H)");
      }
      i += 2;
    } else if (k == "normalise" || k == "normalize") {
      c.normalise = parse_yes_no(ctx, k, need(a, i + 1, ctx, k, "yes or no"));
      i += 2;
    } else if (k == "up") {
      c.up = parse_axis(ctx, "up", need(a, i + 1, ctx, "up", "an axis (x, y, z)"));
      i += 2;
    } else if (k == "lateral") {
      c.lateral = parse_axis(ctx, "lateral", need(a, i + 1, ctx, "lateral", "an axis (x, y, z, none)"), true);
      i += 2;
    } else if (k == "file") {
      c.file = need(a, i + 1, ctx, "file", "a file name");
      i += 2;
    } else {
      throw std::invalid_argument(ctx + ": unknown keyword " + quote(k) +
                                  "; allowed: every, column, bins, grate, floor, normalise, up, lateral, file");
    }
  }
  if (!have_every) throw std::invalid_argument(ctx + ": missing keyword 'every N'");
  if (!have_col) throw std::invalid_argument(ctx + ": missing keyword 'column C' (column width, > 0)");
  if (!have_bins) throw std::invalid_argument(ctx + ": missing keyword 'bins AXIS LO HI NB'");
  if (!have_ground) throw std::invalid_argument(ctx + ": missing keyword 'grate FIXID' or 'floor H'");
  const char* xyz[3] = {"x", "y", "z"};
  if (c.up == -2) c.up = dimension == 2 ? 1 : 2;
  if (c.up == c.bins.axis)
    arg_error(ctx, "up", xyz[c.up], std::string("an axis other than the transport (bins) axis ") + xyz[c.bins.axis]);
  if (c.lateral == -2) c.lateral = dimension == 2 ? -1 : 3 - c.up - c.bins.axis;
  if (c.lateral >= 0 && (c.lateral == c.up || c.lateral == c.bins.axis))
    arg_error(ctx, "lateral", xyz[c.lateral],
              std::string("none or the axis other than up (") + xyz[c.up] + ") and transport (" + xyz[c.bins.axis] + ")");
  if (dimension == 2 && c.lateral >= 0) arg_error(ctx, "lateral", xyz[c.lateral], "none (2D simulation)");
  return c;
}

// ------------------------------------------------------------------ MPI gather
// Rows of `width` doubles with row[0] = atom id, from all ranks; returned sorted by id, identical on
// every rank. Cost: O(N width) memory and communication per call on every rank (MPI_Allgatherv).
inline std::vector<double> allgather_sorted(MPI_Comm comm, const std::vector<double>& local, int width) {
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  int mine = static_cast<int>(local.size());
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  long total = 0;
  for (int p = 0; p < nprocs; ++p) {
    displs[p] = static_cast<int>(total);
    total += counts[p];
  }
  if (total > 2147483647L) throw std::runtime_error("mixing: too many particles for one MPI_Allgatherv");
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(const_cast<double*>(local.data()), mine, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, comm);
  const std::size_t n = all.size() / width;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all[a * width] < all[b * width]; });
  std::vector<double> out(all.size());
  for (std::size_t q = 0; q < n; ++q) std::copy_n(all.begin() + order[q] * width, width, out.begin() + q * width);
  return out;
}

// row of the atom with the given id in the sorted rows (binary search), -1 if absent
inline long find_row(const std::vector<double>& rows, int width, double id) {
  std::size_t lo = 0, hi = rows.size() / width;
  while (lo < hi) {
    const std::size_t m = (lo + hi) / 2;
    if (rows[m * width] < id) lo = m + 1;
    else hi = m;
  }
  if (lo < rows.size() / width && rows[lo * width] == id) return static_cast<long>(lo);
  return -1;
}

// ------------------------------------------------------------------ velocity based
// Row layout: id, x, y, z, vx, vy, vz, include (1/0)
constexpr int kVelocityWidth = 8;
constexpr int kVelocityCols = 5;  // count, p_x, p_y, p_z, P'

// Table of (bins + 1) rows x 5 columns, row-major; the last row pools all bins.
inline std::vector<double> velocity_table(const std::vector<double>& rows, const VelocityConfig& c,
                                          const Periodic& per) {
  const std::size_t n = rows.size() / kVelocityWidth;
  std::vector<double> x(3 * n), v(3 * n);
  std::vector<unsigned char> inc(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* r = &rows[i * kVelocityWidth];
    for (int k = 0; k < 3; ++k) {
      x[3 * i + k] = r[1 + k];
      v[3 * i + k] = r[4 + k];
    }
    inc[i] = r[7] != 0.0;
  }
  const std::vector<VelocityStats> st = velocity_mixing(n, x.data(), v.data(), c.radius, c.bins, per, inc.data());
  VelocityStats all;
  std::vector<double> out((c.bins.count + 1) * kVelocityCols);
  auto put = [&](int row, const VelocityStats& s) {
    double* o = &out[row * kVelocityCols];
    o[0] = static_cast<double>(s.n);
    for (int k = 0; k < 3; ++k) o[1 + k] = s.p(k);
    o[4] = s.P();
  };
  for (int b = 0; b < c.bins.count; ++b) {
    put(b, st[b]);
    all.merge(st[b]);
  }
  put(c.bins.count, all);
  return out;
}

// ------------------------------------------------------------------ trajectory based
// Per-atom state (kStateWidth doubles), the fields of DepthTrajectories::Particle:
//   samples, sum D, sum D^2, last D, last time, sum |dD|, sum dt, last region (-1 none), last snapshot (0 never)
constexpr int kStateWidth = 9;
enum State { S_SAMPLES, S_SUM_D, S_SUM_D2, S_LAST_D, S_LAST_T, S_SUM_ABS, S_SUM_DT, S_LAST_REGION, S_LAST_SNAP };
// Row layout of the gather: id, x, y, z, radius, state[9]
constexpr int kDepthWidth = 5 + kStateWidth;
// Per-atom output: D now, Dbar, sigma_D, Q'
constexpr int kPeratomCols = 4;
// Global output per bin (+ all bins): count, mean D, mean sigma_D, Q', sigma of the D samples, samples
constexpr int kDepthCols = 6;

inline double state_mean(const double* s) { return s[S_SAMPLES] > 0 ? s[S_SUM_D] / s[S_SAMPLES] : 0.0; }
inline double state_sigma(const double* s) {
  if (!(s[S_SAMPLES] > 0)) return 0.0;
  const double m = state_mean(s);
  return std::sqrt(std::max(0.0, s[S_SUM_D2] / s[S_SAMPLES] - m * m));
}
inline double state_q(const double* s) { return s[S_SUM_DT] > 0.0 ? s[S_SUM_ABS] / s[S_SUM_DT] : 0.0; }

// Accumulators of the regions (DepthTrajectories::Region), bins.count + 0 entries
struct RegionSums {
  std::vector<DepthTrajectories::Region> region;
  std::vector<long> count_now;      // particles in the bin at the last snapshot
  std::vector<double> sigma_now;    // sum of the trajectory sigma_D of those particles
  static constexpr int kRestartPerRegion = 5;  // total_abs, total_dt, samples, sum_d, sum_d2
};

// One snapshot at time t (snapshot index k >= 1): D of every row (into depth), the per-particle
// state of every row and the region sums are updated exactly as DepthTrajectories::add does.
inline void depth_snapshot(std::vector<double>& rows, const DepthOptions& o, const Bins& bins, double t, long k,
                           RegionSums& rs, std::vector<double>& depth) {
  const std::size_t n = rows.size() / kDepthWidth;
  std::vector<double> x(3 * n), rad(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int q = 0; q < 3; ++q) x[3 * i + q] = rows[i * kDepthWidth + 1 + q];
    rad[i] = rows[i * kDepthWidth + 4];
  }
  depth = particle_depths(n, x.data(), rad.data(), o).depth;
  rs.region.resize(bins.count);
  rs.count_now.assign(bins.count, 0);
  rs.sigma_now.assign(bins.count, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double* s = &rows[i * kDepthWidth + 5];
    const int r = bins.index(&x[3 * i]);
    const double d = depth[i];
    if (s[S_LAST_SNAP] == static_cast<double>(k - 1) && k > 1) {
      const double a = std::fabs(d - s[S_LAST_D]), dt = t - s[S_LAST_T];
      s[S_SUM_ABS] += a;
      s[S_SUM_DT] += dt;
      const int lr = static_cast<int>(s[S_LAST_REGION]);
      if (lr >= 0 && lr < bins.count) {
        rs.region[lr].total_abs += a;
        rs.region[lr].total_dt += dt;
      }
    }
    s[S_SAMPLES] += 1.0;
    s[S_SUM_D] += d;
    s[S_SUM_D2] += d * d;
    if (r >= 0) {
      ++rs.region[r].samples;
      rs.region[r].sum_d += d;
      rs.region[r].sum_d2 += d * d;
      ++rs.count_now[r];
      rs.sigma_now[r] += state_sigma(s);
    }
    s[S_LAST_T] = t;
    s[S_LAST_D] = d;
    s[S_LAST_REGION] = r;
    s[S_LAST_SNAP] = static_cast<double>(k);
  }
}

// Global table (bins + 1) x kDepthCols, row-major; the last row pools all bins.
inline std::vector<double> depth_table(const RegionSums& rs, int nbins) {
  std::vector<double> out((nbins + 1) * kDepthCols, 0.0);
  DepthTrajectories::Region all;
  long cnt_all = 0;
  double sig_all = 0.0;
  auto put = [&](int row, const DepthTrajectories::Region& g, long cnt, double sig) {
    double* o = &out[row * kDepthCols];
    o[0] = static_cast<double>(cnt);
    o[1] = g.mean();
    o[2] = cnt ? sig / cnt : 0.0;
    o[3] = g.q();
    o[4] = g.sigma();
    o[5] = static_cast<double>(g.samples);
  };
  for (int b = 0; b < nbins && b < static_cast<int>(rs.region.size()); ++b) {
    const long cnt = b < static_cast<int>(rs.count_now.size()) ? rs.count_now[b] : 0;
    const double sig = b < static_cast<int>(rs.sigma_now.size()) ? rs.sigma_now[b] : 0.0;
    put(b, rs.region[b], cnt, sig);
    const auto& g = rs.region[b];
    all.total_abs += g.total_abs;
    all.total_dt += g.total_dt;
    all.samples += g.samples;
    all.sum_d += g.sum_d;
    all.sum_d2 += g.sum_d2;
    cnt_all += cnt;
    sig_all += sig;
  }
  put(nbins, all, cnt_all, sig_all);
  return out;
}

}  // namespace host
}  // namespace mixing
}  // namespace grate
}  // namespace tdem
