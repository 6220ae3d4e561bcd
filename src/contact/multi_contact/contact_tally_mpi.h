// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the global contact tally over MPI ranks (contact_tally.h) for the host styles.
//
// merge_over_ranks: every rank packs its entries (int64), MPI_Allgatherv, and merges the OTHER
// ranks' blocks into its own tally: afterwards every pair a rank knows holds the global count and
// the exact overlap sum. Nothing is exchanged on one rank.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

#include "contact/multi_contact/contact_tally.h"

namespace tdem {
namespace clumps {

// Scratch buffers of merge_over_ranks (kept by the caller between steps).
struct TallyExchange {
  std::vector<std::int64_t> own, all;
  std::vector<int> counts, displs;
};

inline void merge_over_ranks(ContactTally& tally, MPI_Comm comm, TallyExchange& buf) {
  int nprocs = 1, me = 0;
  MPI_Comm_size(comm, &nprocs);
  if (nprocs == 1) return;
  MPI_Comm_rank(comm, &me);
  tally.pack(buf.own);
  const int n = static_cast<int>(buf.own.size());
  buf.counts.resize(nprocs);
  buf.displs.resize(nprocs);
  MPI_Allgather(&n, 1, MPI_INT, buf.counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < nprocs; r++) {
    buf.displs[r] = total;
    total += buf.counts[r];
  }
  buf.all.resize(total > 0 ? total : 1);
  MPI_Allgatherv(buf.own.data(), n, MPI_INT64_T, buf.all.data(), buf.counts.data(), buf.displs.data(),
                 MPI_INT64_T, comm);
  for (int r = 0; r < nprocs; r++)
    if (r != me && buf.counts[r] > 0)
      tally.merge_packed(buf.all.data() + buf.displs[r],
                         static_cast<std::size_t>(buf.counts[r] / ContactTally::pack_width));
}

}  // namespace clumps
}  // namespace tdem
