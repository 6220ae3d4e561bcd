// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the host-independent part of the mixing styles of LAMMPS and LIGGGHTS (docs/mixing_hosts.md):
//   compute ID group tdem/mixing/velocity radius R_V bins AXIS LO HI N [periodic AXIS ...] [exclude GROUP]
//   fix ID group tdem/mixing/depth every N column C bins AXIS LO HI NB (grate FIXID | floor H)
//       [normalise yes|no] [up AXIS] [lateral AXIS|none] [file NAME]
// Argument parsing (std::invalid_argument naming keyword, value and allowed values) and the parallel
// evaluation: each rank evaluates the atoms it owns with the core of mixing.h and a halo of the
// atoms of other ranks (mixing_parallel.h); the region sums are reduced independently of the order,
// so the output is bitwise the same for any domain decomposition.
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
#include "fixes/mixing/mixing_parallel.h"

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

// ------------------------------------------------------------------ velocity based
// Row layout of a rank's atoms: id, x, y, z, vx, vy, vz, include (1/0)
constexpr int kVelocityWidth = 8;
constexpr int kVelocityCols = 5;  // count, p_x, p_y, p_z, P'

// Table of (bins + 1) rows x 5 columns, row-major (the last row pools all bins), from the rows of
// the atoms this rank owns; each rank evaluates its own atoms with a halo (mixing_parallel.h).
// Collective; the table is the same on every rank and for any number of ranks.
inline std::vector<double> velocity_table(MPI_Comm comm, const std::vector<double>& owned, const VelocityConfig& c,
                                          const Periodic& per, HaloCount& hc) {
  const int W = kVelocityWidth;
  const std::size_t n = owned.size() / W;
  // the evaluated atoms (included, inside the bins) first
  std::vector<double> rows;
  rows.reserve(owned.size());
  std::size_t n_eval = 0;
  for (int pass = 1; pass >= 0; --pass)
    for (std::size_t j = 0; j < n; ++j) {
      const double* r = &owned[j * W];
      const bool eval = r[7] != 0.0 && c.bins.index(r + 1) >= 0;
      if (eval != (pass == 1)) continue;
      rows.insert(rows.end(), r, r + W);
      n_eval += eval;
    }
  std::vector<double> xe(3 * n_eval);
  for (std::size_t j = 0; j < n_eval; ++j) std::copy_n(&rows[j * W + 1], 3, &xe[3 * j]);
  const std::vector<RankBox> boxes = gather_boxes(comm, n_eval, xe.data());
  const bool use[3] = {true, true, true};
  const Halo halo = exchange_halo(comm, rows, W, boxes, per, c.radius * (1.0 + 1e-9), use, true,
                                  [](std::size_t, int) { return true; });
  const std::size_t m = n + halo.image.size();
  std::vector<double> x(3 * m), v(3 * m), id(m);
  std::vector<int> image(m, kNoShift);
  for (std::size_t q = 0; q < m; ++q) {
    const double* r = q < n ? &rows[q * W] : &halo.rows[(q - n) * W];
    id[q] = r[0];
    std::copy_n(r + 1, 3, &x[3 * q]);
    std::copy_n(r + 4, 3, &v[3 * q]);
    if (q >= n) image[q] = halo.image[q - n];
  }
  hc.owned = static_cast<long>(n);
  hc.halo = static_cast<long>(m - n);
  // the scale of the fixed-point neighbour sums: the largest velocity of all ranks; a non-finite one
  // stops every rank with the same message
  int scale[2] = {velocity_exponent(3 * n, v.data()), 0};
  for (std::size_t q = 0; q < 3 * n; ++q)
    if (!std::isfinite(v[q])) scale[1] = 1;
  MPI_Allreduce(MPI_IN_PLACE, scale, 2, MPI_INT, MPI_MAX, comm);
  if (scale[1]) throw std::invalid_argument("an atom of the group has a velocity that is not a finite number");
  const LocalVelocity lv =
      local_velocity(Cloud{m, n_eval, x.data(), image.data(), id.data()}, v.data(), c.radius, per, scale[0]);
  // region sums: per bin the sums of vtil_k and vtil_k^2 (groups 6 b + k, 6 b + 3 + k) and the count
  const int nb = c.bins.count;
  WindowSums ws(6 * static_cast<std::size_t>(nb));
  std::vector<long long> count(nb, 0);
  std::vector<int> bin(n_eval);
  for (std::size_t i = 0; i < n_eval; ++i) {
    bin[i] = c.bins.index(&x[3 * i]);
    ++count[bin[i]];
  }
  auto each = [&](auto&& f) {
    for (std::size_t i = 0; i < n_eval; ++i)
      for (int k = 0; k < 3; ++k) {
        const double vt = lv.fluct[3 * i + k];
        f(6 * bin[i] + k, vt);
        f(6 * bin[i] + 3 + k, vt * vt);
      }
  };
  reduce_window_sums(
      comm, ws, [&] { each([&](std::size_t g, double val) { ws.note(g, val); }); },
      [&] { each([&](std::size_t g, double val) { ws.add(g, val); }); });
  MPI_Allreduce(MPI_IN_PLACE, count.data(), nb, MPI_LONG_LONG, MPI_SUM, comm);
  VelocityStats all;
  std::vector<double> out((nb + 1) * kVelocityCols);
  auto put = [&](int row, const VelocityStats& s) {
    double* o = &out[row * kVelocityCols];
    o[0] = static_cast<double>(s.n);
    for (int k = 0; k < 3; ++k) o[1 + k] = s.p(k);
    o[4] = s.P();
  };
  for (int b = 0; b < nb; ++b) {
    VelocityStats s;
    s.n = static_cast<long>(count[b]);
    for (int k = 0; k < 3; ++k) {
      s.sum[k] = ws.value(6 * b + k);
      s.sumsq[k] = ws.value(6 * b + 3 + k);
    }
    put(b, s);
    all.merge(s);
  }
  put(nb, all);
  return out;
}

// ------------------------------------------------------------------ trajectory based
// Per-atom state (kStateWidth doubles), the fields of DepthTrajectories::Particle:
//   samples, sum D, sum D^2, last D, last time, sum |dD|, sum dt, last region (-1 none), last snapshot (0 never)
constexpr int kStateWidth = 9;
enum State { S_SAMPLES, S_SUM_D, S_SUM_D2, S_LAST_D, S_LAST_T, S_SUM_ABS, S_SUM_DT, S_LAST_REGION, S_LAST_SNAP };
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

// One snapshot at time t (snapshot index k >= 1) of the n atoms of the group this rank owns: ids,
// positions (n x 3), radii and their state (n x kStateWidth, updated as DepthTrajectories::add
// does); D of each atom into depth; the region sums rs get the global sums of the snapshot.
// Collective; each rank evaluates its own atoms with a thinned halo (mixing_parallel.h).
inline void depth_snapshot(MPI_Comm comm, std::size_t n, const double* id, const double* x, const double* radius,
                           double* state, const DepthOptions& o, const Bins& bins, double t, long k, RegionSums& rs,
                           std::vector<double>& depth, HaloCount& hc) {
  check_depth_options(o);
  bool use[3];
  depth_axes(o, use);
  const Periodic per = depth_periodic(o);
  const int u = o.up_axis;
  const std::vector<RankBox> boxes = gather_boxes(comm, n, x);
  const std::vector<unsigned char> top = column_candidates(n, x, o, per);
  std::vector<double> rows(4 * n);
  for (std::size_t j = 0; j < n; ++j) {
    rows[4 * j] = id[j];
    std::copy_n(x + 3 * j, 3, &rows[4 * j + 1]);
  }
  const Halo halo = exchange_halo(comm, rows, 4, boxes, per, 0.5 * o.column_width * (1.0 + 1e-9), use, false,
                                  [&](std::size_t j, int q) { return top[j] && x[3 * j + u] > boxes[q].lo[u]; });
  const std::size_t m = n + halo.image.size();
  std::vector<double> xc(x, x + 3 * n), idc(id, id + n);
  std::vector<int> image(n, kNoShift);
  for (std::size_t q = 0; q < halo.image.size(); ++q) {
    idc.push_back(halo.rows[4 * q]);
    xc.insert(xc.end(), &halo.rows[4 * q + 1], &halo.rows[4 * q + 4]);
    image.push_back(halo.image[q]);
  }
  hc.owned = static_cast<long>(n);
  hc.halo = static_cast<long>(m - n);
  depth = particle_depths(Cloud{m, n, xc.data(), image.data(), idc.data()}, radius, o).depth;

  // the state of every atom; the contributions of this snapshot to the regions
  const int nb = bins.count;
  std::vector<int> from(n, -1), region(n);
  std::vector<double> inc_abs(n, 0.0), inc_dt(n, 0.0), sigma(n);
  for (std::size_t i = 0; i < n; ++i) {
    double* s = state + i * kStateWidth;
    region[i] = bins.index(x + 3 * i);
    const double d = depth[i];
    if (s[S_LAST_SNAP] == static_cast<double>(k - 1) && k > 1) {
      inc_abs[i] = std::fabs(d - s[S_LAST_D]);
      inc_dt[i] = t - s[S_LAST_T];
      s[S_SUM_ABS] += inc_abs[i];
      s[S_SUM_DT] += inc_dt[i];
      const int lr = static_cast<int>(s[S_LAST_REGION]);
      if (lr >= 0 && lr < nb) from[i] = lr;
    }
    s[S_SAMPLES] += 1.0;
    s[S_SUM_D] += d;
    s[S_SUM_D2] += d * d;
    sigma[i] = state_sigma(s);
    s[S_LAST_T] = t;
    s[S_LAST_D] = d;
    s[S_LAST_REGION] = region[i];
    s[S_LAST_SNAP] = static_cast<double>(k);
  }
  // per bin: sum |dD|, sum dt (groups 5 b, 5 b + 1: increments starting there), sum D, sum D^2,
  // sum sigma_D (5 b + 2 .. 4: atoms there now), and the count of atoms there now
  WindowSums ws(5 * static_cast<std::size_t>(nb));
  std::vector<long long> count(nb, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (region[i] >= 0) ++count[region[i]];
  auto each = [&](auto&& f) {
    for (std::size_t i = 0; i < n; ++i) {
      if (from[i] >= 0) {
        f(5 * from[i], inc_abs[i]);
        f(5 * from[i] + 1, inc_dt[i]);
      }
      if (region[i] >= 0) {
        f(5 * region[i] + 2, depth[i]);
        f(5 * region[i] + 3, depth[i] * depth[i]);
        f(5 * region[i] + 4, sigma[i]);
      }
    }
  };
  reduce_window_sums(
      comm, ws, [&] { each([&](std::size_t g, double val) { ws.note(g, val); }); },
      [&] { each([&](std::size_t g, double val) { ws.add(g, val); }); });
  MPI_Allreduce(MPI_IN_PLACE, count.data(), nb, MPI_LONG_LONG, MPI_SUM, comm);
  rs.region.resize(nb);
  rs.count_now.assign(nb, 0);
  rs.sigma_now.assign(nb, 0.0);
  for (int b = 0; b < nb; ++b) {
    auto& g = rs.region[b];
    g.total_abs += ws.value(5 * b);
    g.total_dt += ws.value(5 * b + 1);
    g.samples += static_cast<long>(count[b]);
    g.sum_d += ws.value(5 * b + 2);
    g.sum_d2 += ws.value(5 * b + 3);
    rs.count_now[b] = static_cast<long>(count[b]);
    rs.sigma_now[b] = ws.value(5 * b + 4);
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
