// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the output of fix tdem/clump (both engines): scalar (kinetic energy), vector of 9 sums and
// one array row per body, from the local bodies of every rank (body_set.h). Collective: every
// rank calls them in the same order (the engines evaluate thermo output and variables on every
// rank). Each body is counted once, by the rank owning its sphere 0; the sums are exact
// (contact/exact_sum.h), so the output is bitwise the same on any number of ranks. The array is
// gathered, in molecule ID order, only when it is used (once per change of the bodies).
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "contact/exact_sum.h"
#include "fixes/clumps/body_set.h"

namespace tdem {
namespace clumps {

// Rows of doubles of every rank, in rank order, on every rank (MPI_Allgatherv).
inline std::vector<double> allgather_rows(MPI_Comm comm, const std::vector<double>& mine) {
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  int nme = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Allgather(&nme, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int ntot = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = ntot;
    ntot += counts[p];
  }
  std::vector<double> all(ntot > 0 ? ntot : 1);
  MPI_Allgatherv(const_cast<double*>(mine.data()), nme, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, comm);
  all.resize(ntot);
  return all;
}

class BodyOutput {
 public:
  double kinetic_energy(const BodySet& set, double mvv2e, MPI_Comm world) { return totals(set, world)[9] * mvv2e; }
  // [0] bodies, [1-3] total momentum, [4-6] sum of the bodies' angular momenta about their com,
  // [7] translational, [8] rotational kinetic energy
  double vector(const BodySet& set, int n, double mvv2e, MPI_Comm world) {
    if (n == 0) return static_cast<double>(set.size());
    if (n < 0 || n > 8) return 0.0;
    return totals(set, world)[n] * (n >= 7 ? mvv2e : 1.0);
  }
  // row per body, in molecule ID order: mol, x y z, vx vy vz, qw qx qy qz, Lx Ly Lz, wx wy wz
  static constexpr int kArrayColumns = 17;
  double array(const BodySet& set, int i, int j, MPI_Comm world) {
    if (rows_version_ != set.version()) gather_rows(set, world);
    if (i < 0 || static_cast<std::size_t>(i) * kArrayColumns >= rows_.size() || j < 0 || j >= kArrayColumns)
      return 0.0;
    return rows_[static_cast<std::size_t>(i) * kArrayColumns + j];
  }


  double memory_usage() const { return static_cast<double>(rows_.size() + tot_.size()) * sizeof(double); }

 private:
  std::vector<double> tot_, rows_;
  std::uint64_t tot_version_ = ~std::uint64_t(0), rows_version_ = ~std::uint64_t(0);

  // [0..8] as vector(), [9] kinetic energy; exact sums over the reported bodies of every rank
  const std::vector<double>& totals(const BodySet& set, MPI_Comm world) {
    if (tot_version_ == set.version()) return tot_;
    const Body& body_ = set.body();
    constexpr int kN = 10, kL = ExactSum::kLimbs;
    std::vector<ExactSum> acc(kN);
    for (std::size_t b = 0; b < set.local_size(); b++) {
      if (!set.reported(b)) continue;
      const State& s = set.state(b);
      for (int d = 0; d < 3; d++) acc[1 + d].add(body_.mass * s.v[d]), acc[4 + d].add(s.L[d]);
      const double et = 0.5 * body_.mass * dot(s.v, s.v), er = rotational_energy(s, body_);
      acc[7].add(et), acc[8].add(er), acc[9].add(clumps::kinetic_energy(s, body_));
    }
    std::vector<std::int64_t> limbs(kN * kL + kN);
    for (int n = 0; n < kN; n++) {
      acc[n].normalise();
      std::copy(acc[n].limbs(), acc[n].limbs() + kL, &limbs[n * kL]);
      limbs[kN * kL + n] = *acc[n].bad();
    }
    MPI_Allreduce(MPI_IN_PLACE, limbs.data(), static_cast<int>(limbs.size()), MPI_INT64_T, MPI_SUM, world);
    tot_.assign(kN, 0.0);
    for (int n = 0; n < kN; n++) {
      ExactSum e;
      std::copy(&limbs[n * kL], &limbs[n * kL] + kL, e.limbs());
      *e.bad() = limbs[kN * kL + n] != 0;
      tot_[n] = e.value();
    }
    tot_version_ = set.version();
    return tot_;
  }
 public:
  // the rows of the reported bodies of this rank (array layout, unsorted)
  static std::vector<double> local_rows(const BodySet& set) {
    const Body& body_ = set.body();
    std::vector<double> mine;
    for (std::size_t b = 0; b < set.local_size(); b++) {
      if (!set.reported(b)) continue;
      const State& s = set.state(b);
      const Vec3 w = angular_velocity(s, body_);
      const double row[kArrayColumns] = {static_cast<double>(set.mol(b)), s.x[0], s.x[1], s.x[2], s.v[0], s.v[1],
                                         s.v[2], s.q.w, s.q.x, s.q.y, s.q.z, s.L[0], s.L[1], s.L[2], w[0], w[1], w[2]};
      mine.insert(mine.end(), row, row + kArrayColumns);
    }
    return mine;
  }
  // rows sorted by molecule ID
  static std::vector<double> sorted_rows(const std::vector<double>& all) {
    const std::size_t n = all.size() / kArrayColumns;
    std::vector<std::size_t> order(n);
    for (std::size_t r = 0; r < n; r++) order[r] = r;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return all[a * kArrayColumns] < all[b * kArrayColumns]; });
    std::vector<double> out(n * kArrayColumns);
    for (std::size_t r = 0; r < n; r++)
      std::copy(&all[order[r] * kArrayColumns], &all[order[r] * kArrayColumns] + kArrayColumns, &out[r * kArrayColumns]);
    return out;
  }
  // the rows of every rank on rank 0 only (empty elsewhere), in molecule ID order: one MPI_Gatherv
  static std::vector<double> rows_on_root(const BodySet& set, MPI_Comm world) {
    int me = 0, nprocs = 1;
    MPI_Comm_rank(world, &me);
    MPI_Comm_size(world, &nprocs);
    const std::vector<double> mine = local_rows(set);
    int nme = static_cast<int>(mine.size());
    std::vector<int> counts(me == 0 ? nprocs : 1), displs(me == 0 ? nprocs : 1);
    MPI_Gather(&nme, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
    int ntot = 0;
    if (me == 0)
      for (int p = 0; p < nprocs; p++) displs[p] = ntot, ntot += counts[p];
    std::vector<double> all(ntot > 0 ? ntot : 1);
    MPI_Gatherv(const_cast<double*>(mine.data()), nme, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                MPI_DOUBLE, 0, world);
    all.resize(ntot);
    return me == 0 ? sorted_rows(all) : std::vector<double>();
  }

 private:
  // the rows of the reported bodies of every rank, in molecule ID order
  void gather_rows(const BodySet& set, MPI_Comm world) {
    rows_ = sorted_rows(allgather_rows(world, local_rows(set)));
    rows_version_ = set.version();
  }
};

}  // namespace clumps
}  // namespace tdem
