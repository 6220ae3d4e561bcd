// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the parallel evaluation of the mixing measures (issue 20, docs/mixing_hosts.md "Parallel
// evaluation"): every rank evaluates the particles it owns, with a halo of the particles of other
// ranks (and periodic images) that its particles can see, and the region sums are reduced so that
// the output is bitwise the same on any number of ranks.
//   - Rank boxes: each rank's bounding box of the particles it evaluates (6 doubles per rank,
//     MPI_Allgather); a particle goes to every rank (or image) whose box is within the reach: r_v
//     (velocity, Euclidean) or c/2 along the transport and lateral axes (depth, any height).
//   - Depth halo, thinned: a particle is sent only if it is higher than the lowest particle of the
//     receiver and if it can be a column top for a point near it: it is left out when a higher
//     particle of the sender lies in the window of every such point (column_candidates). A rank
//     below another one in the up direction thus gets only the sender's top layers, not its column.
//   - Order: the neighbour sums of the velocity measure are taken in atom-id order (mixing.h), the
//     column top is a maximum, and the region sums are WindowSums (contact/exact_sum.h) with the
//     limbs summed by MPI_Allreduce: none of them depends on the decomposition.
// Rows of a rank's particles: [id, x, y, z, payload...] doubles.
#pragma once

#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "contact/exact_sum.h"
#include "fixes/mixing/mixing.h"

namespace tdem {
namespace grate {
namespace mixing {
namespace host {

// What the last evaluation held on this rank (memory, the test that no rank holds the whole group).
struct HaloCount {
  long owned = 0;  // particles of the group this rank owns
  long halo = 0;   // rows received from other ranks and periodic images
  long group = 0;  // the whole group (sum over ranks)
};

struct RankBox {
  double lo[3], hi[3];
  bool any;
};

// every rank's bounding box of its n points x (n x 3), on every rank
inline std::vector<RankBox> gather_boxes(MPI_Comm comm, std::size_t n, const double* x) {
  double mine[7];
  bounding_box(n, x, mine, mine + 3);
  mine[6] = n > 0 ? 1.0 : 0.0;
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  std::vector<double> all(7 * static_cast<std::size_t>(nprocs));
  MPI_Allgather(mine, 7, MPI_DOUBLE, all.data(), 7, MPI_DOUBLE, comm);
  std::vector<RankBox> boxes(nprocs);
  for (int p = 0; p < nprocs; ++p) {
    for (int k = 0; k < 3; ++k) {
      boxes[p].lo[k] = all[7 * p + k];
      boxes[p].hi[k] = all[7 * p + 3 + k];
    }
    boxes[p].any = all[7 * p + 6] != 0.0;
  }
  return boxes;
}

// The halo of this rank: rows (width doubles each, [id, x, y, z, ...]) of other ranks and periodic
// images of any rank that lie within r of this rank's box (rows arrive with their image code in
// `image`). send(j, q) may refuse row j for rank q. Collective.
struct Halo {
  std::vector<double> rows;
  std::vector<int> image;
};

template <class Send>
Halo exchange_halo(MPI_Comm comm, const std::vector<double>& rows, int width, const std::vector<RankBox>& boxes,
                   const Periodic& per, double r, const bool use[3], bool euclid, Send&& send) {
  int me = 0, nprocs = 1;
  MPI_Comm_rank(comm, &me);
  MPI_Comm_size(comm, &nprocs);
  const std::size_t n = rows.size() / width;
  // ranks this rank's rows can reach at all: the box of all its rows against theirs
  std::vector<double> x(3 * n);
  for (std::size_t j = 0; j < n; ++j)
    for (int k = 0; k < 3; ++k) x[3 * j + k] = rows[j * width + 1 + k];
  double lo[3], hi[3];
  bounding_box(n, x.data(), lo, hi);
  // (rank, image) pairs this rank's rows can reach at all: its box against theirs
  std::vector<std::pair<int, int>> reach;
  for (int q = 0; q < nprocs && n > 0; ++q) {
    if (!boxes[q].any) continue;
    double grown_lo[3], grown_hi[3], mid[3];
    for (int k = 0; k < 3; ++k) {  // q's box grown by half this rank's extent, against its centre
      mid[k] = 0.5 * (lo[k] + hi[k]);
      grown_lo[k] = boxes[q].lo[k] - 0.5 * (hi[k] - lo[k]);
      grown_hi[k] = boxes[q].hi[k] + 0.5 * (hi[k] - lo[k]);
    }
    for_each_image_near(mid, per, grown_lo, grown_hi, r * (1.0 + 1e-9), use, false, [&](int code) {
      if (q != me || code != kNoShift) reach.emplace_back(q, code);
    });
  }
  std::vector<std::vector<double>> out(nprocs);
  for (std::size_t j = 0; j < n; ++j)
    for (const auto& qc : reach) {
      const int q = qc.first, code = qc.second;
      if (!image_near(&x[3 * j], code, per, boxes[q].lo, boxes[q].hi, r, use, euclid) || !send(j, q)) continue;
      out[q].insert(out[q].end(), rows.begin() + j * width, rows.begin() + (j + 1) * width);
      out[q].push_back(static_cast<double>(code));
    }
  std::vector<int> scount(nprocs), rcount(nprocs), sdisp(nprocs, 0), rdisp(nprocs, 0);
  for (int q = 0; q < nprocs; ++q) scount[q] = static_cast<int>(out[q].size());
  MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm);
  std::vector<double> sbuf;
  long stot = 0, rtot = 0;
  for (int q = 0; q < nprocs; ++q) {
    sdisp[q] = static_cast<int>(stot);
    rdisp[q] = static_cast<int>(rtot);
    stot += scount[q];
    rtot += rcount[q];
    sbuf.insert(sbuf.end(), out[q].begin(), out[q].end());
  }
  std::vector<double> rbuf(rtot > 0 ? rtot : 1);
  MPI_Alltoallv(sbuf.empty() ? rbuf.data() : sbuf.data(), scount.data(), sdisp.data(), MPI_DOUBLE, rbuf.data(),
                rcount.data(), rdisp.data(), MPI_DOUBLE, comm);
  Halo h;
  const std::size_t m = static_cast<std::size_t>(rtot) / (width + 1);
  h.rows.reserve(m * width);
  for (std::size_t q = 0; q < m; ++q) {
    const double* row = &rbuf[q * (width + 1)];
    h.rows.insert(h.rows.end(), row, row + width);
    h.image.push_back(static_cast<int>(row[width]));
  }
  return h;
}

// WindowSums made global: maxima (MPI_MAX), then the limbs (MPI_SUM). note() every value before,
// add() every value in between (the callbacks), then value() is the same on every rank.
template <class Note, class Add>
void reduce_window_sums(MPI_Comm comm, WindowSums& ws, Note&& note, Add&& add) {
  note();
  MPI_Allreduce(MPI_IN_PLACE, ws.maxima(), static_cast<int>(ws.groups()), MPI_DOUBLE, MPI_MAX, comm);
  ws.start();
  add();
  MPI_Allreduce(MPI_IN_PLACE, ws.limbs(), static_cast<int>(ws.limb_count()), MPI_INT64_T, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, ws.bad(), 1, MPI_INT, MPI_MAX, comm);
}

// The particles of this rank (n, x) that can be the highest centre in the column window of a point
// of another rank. Grid fixed to the box, cells of width w <= c/(2 m) along the transport and
// lateral axes (m = 3); the (2m - 1)-cell block around the cell of any point x lies inside the
// window of x, so B_c = the highest particle of this rank in the block around cell c is a lower bound
// of the top of every window whose point lies in c. A particle j is left out when B_c > z_j for
// every cell c within c/2 of it. Sound: for a point i within c/2 of j, the highest particle k* of
// this rank in the window of i is kept (B_c(i) <= z_k*), and z_k* >= B_c(i) > z_j.
inline std::vector<unsigned char> column_candidates(std::size_t n, const double* x, const DepthOptions& o,
                                                    const Periodic& per) {
  constexpr int m = 3;
  const double h = 0.5 * o.column_width, reach = h * (1.0 + 1e-9);
  const int ax[2] = {o.transport_axis, o.lateral_axis};
  const int na = o.lateral_axis >= 0 ? 2 : 1;
  double lo[3], hi[3];
  bounding_box(n, x, lo, hi);
  double w[2] = {1.0, 1.0}, origin[2] = {0.0, 0.0};
  long first[2] = {0, 0}, size[2] = {1, 1};
  bool wraps[2] = {false, false};
  for (int a = 0; a < na; ++a) {
    const int k = ax[a];
    origin[a] = per.lo[k];
    w[a] = h * (1.0 - 1e-9) / m;  // strictly narrower, so round-off cannot widen a block
    if (per.on[k]) {
      wraps[a] = true;
      size[a] = static_cast<long>(std::ceil(per.length(k) / w[a]));
      w[a] = per.length(k) / size[a];
    } else if (n > 0) {
      first[a] = static_cast<long>(std::floor((lo[k] - reach - origin[a]) / w[a])) - 1;
      size[a] = static_cast<long>(std::floor((hi[k] + reach - origin[a]) / w[a])) + 2 - first[a];
    }
  }
  auto index = [&](int a, long c) {  // grid index of cell c along a
    if (wraps[a]) return ((c % size[a]) + size[a]) % size[a];
    return c - first[a];
  };
  auto cell = [&](int a, double v) { return static_cast<long>(std::floor((v - origin[a]) / w[a])); };
  const int u = o.up_axis;
  const double none = -std::numeric_limits<double>::infinity();
  std::vector<double> top(static_cast<std::size_t>(size[0] * size[1]), none);
  for (std::size_t j = 0; j < n; ++j) {
    const long c0 = index(0, cell(0, x[3 * j + ax[0]])), c1 = na > 1 ? index(1, cell(1, x[3 * j + ax[1]])) : 0;
    double& t = top[c0 * size[1] + c1];
    t = std::max(t, x[3 * j + u]);
  }
  // B: the maximum over the (2m - 1) block, one axis after the other
  for (int a = 0; a < na; ++a) {
    std::vector<double> b(top.size(), none);
    for (long c0 = 0; c0 < size[0]; ++c0)
      for (long c1 = 0; c1 < size[1]; ++c1) {
        double mx = none;
        for (long q = -(m - 1); q <= m - 1; ++q) {
          long d0 = c0, d1 = c1;
          (a == 0 ? d0 : d1) += q;
          long& d = a == 0 ? d0 : d1;
          if (wraps[a]) d = ((d % size[a]) + size[a]) % size[a];
          else if (d < 0 || d >= size[a]) continue;
          mx = std::max(mx, top[d0 * size[1] + d1]);
        }
        b[c0 * size[1] + c1] = mx;
      }
    top.swap(b);
  }
  std::vector<unsigned char> keep(n, 0);
  for (std::size_t j = 0; j < n; ++j) {
    long from[2] = {0, 0}, to[2] = {0, 0};
    for (int a = 0; a < na; ++a) {
      const double v = x[3 * j + ax[a]];
      from[a] = cell(a, v - reach);
      to[a] = cell(a, v + reach);
      if (wraps[a] && to[a] - from[a] + 1 >= size[a]) from[a] = 0, to[a] = size[a] - 1;
    }
    bool candidate = false;
    for (long c0 = from[0]; c0 <= to[0] && !candidate; ++c0)
      for (long c1 = from[1]; c1 <= to[1] && !candidate; ++c1)
        if (!(top[index(0, c0) * size[1] + (na > 1 ? index(1, c1) : 0)] > x[3 * j + u])) candidate = true;
    keep[j] = candidate;
  }
  return keep;
}

// TDEM_MIXING_REPORT=1: every rank prints what it held in each evaluation (tests, bench/)
inline void report(MPI_Comm comm, const char* what, HaloCount& hc) {
  long mine = hc.owned;
  MPI_Allreduce(&mine, &hc.group, 1, MPI_LONG, MPI_SUM, comm);
  static const bool on = [] {
    const char* e = std::getenv("TDEM_MIXING_REPORT");
    return e && e[0] == '1';
  }();
  if (!on) return;
  int me = 0, nprocs = 1;
  MPI_Comm_rank(comm, &me);
  MPI_Comm_size(comm, &nprocs);
  std::printf("tdem mixing report: %s rank %d of %d owned %ld halo %ld group %ld\n", what, me, nprocs, hc.owned,
              hc.halo, hc.group);
  std::fflush(stdout);
}

}  // namespace host
}  // namespace mixing
}  // namespace grate
}  // namespace tdem
