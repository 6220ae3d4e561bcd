// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the global contact tally over MPI ranks (contact_tally.h) for the host styles.
//
// merge_over_ranks: every rank packs its entries (int64), MPI_Allgatherv, and merges the OTHER
// ranks' blocks into its own tally: afterwards every pair a rank knows holds the global count and
// the exact overlap sum. Nothing is exchanged on one rank. Every rank receives every entry.
//
// merge_with_neighbours: the same result with messages to the neighbouring ranks only. All contacts
// of one pair of sides are counted by ranks owning a sphere of one of the two bodies, and those
// spheres lie within D + 2 r_max of each other (D: the largest distance of two sphere centres in a
// body); owned spheres stay within the skin of their rank's sub-domain between re-neighbourings. So
// a rank needs the entries of the ranks whose sub-domains are within reach = D + 2 r_max + skin of
// its own (periodic images included): TallyNeighbours::find, from the sub-domain boxes (6 values per
// rank, gathered when the boxes may have changed). Per step a rank sends its entries to, and merges
// those of, its neighbours only: memory and messages in proportion to the contacts near it.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
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

// The neighbours of rank `me` among nprocs sub-domain boxes (lo[3], hi[3] of rank r at boxes[6 r]):
// every other rank whose box comes within `reach` of this rank's box, in a periodic dimension also
// through the images at +-prd. Symmetric (the gap of two boxes is the same seen from either).
inline void neighbour_ranks(const double* boxes, int nprocs, int me, const bool periodic[3], const double prd[3],
                            double reach, std::vector<int>& out) {
  out.clear();
  const double* a = boxes + 6 * me;
  for (int r = 0; r < nprocs; r++) {
    if (r == me) continue;
    const double* b = boxes + 6 * r;
    double gap2 = 0.0;
    for (int d = 0; d < 3; d++) {
      double best = -1.0;
      const int images = periodic[d] ? 1 : 0;
      for (int s = -images; s <= images; s++) {
        const double lo = b[d] + s * prd[d], hi = b[3 + d] + s * prd[d];
        const double g = std::max(0.0, std::max(lo - a[3 + d], a[d] - hi));
        if (best < 0.0 || g < best) best = g;
      }
      gap2 += best * best;
    }
    if (gap2 <= reach * reach) out.push_back(r);
  }
}

// The neighbouring ranks of this rank's tally and the scratch of their exchange (kept by the caller).
struct TallyNeighbours {
  std::vector<double> boxes;
  std::vector<int> ranks;
  std::vector<std::int64_t> counts;               // entries' values to / from each neighbour
  std::vector<std::vector<std::int64_t>> inbox;  // per neighbour
  std::vector<MPI_Request> requests;
  bool known = false;

  // at the first call and after a re-neighbouring (collective): the neighbours of the host's
  // sub-domain, reach = 3 x the largest ghost cutoff + skin (the body fixes keep the ghost cutoff at
  // least a body's extent; the cutoff covers a contact; the skin the drift of owned atoms)
  void refresh(MPI_Comm comm, bool reneighboured, const double lo[3], const double hi[3], const bool periodic[3],
               const double prd[3], const double cutghost[3], double skin) {
    if (known && !reneighboured) return;
    find(comm, lo, hi, periodic, prd, 3.0 * std::max(cutghost[0], std::max(cutghost[1], cutghost[2])) + skin);
  }

  // gathers the sub-domain boxes (collective) and keeps the ranks within reach
  void find(MPI_Comm comm, const double lo[3], const double hi[3], const bool periodic[3], const double prd[3],
            double reach) {
    int nprocs = 1, me = 0;
    MPI_Comm_size(comm, &nprocs);
    MPI_Comm_rank(comm, &me);
    const double mine[6] = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
    boxes.resize(6 * static_cast<std::size_t>(nprocs));
    MPI_Allgather(mine, 6, MPI_DOUBLE, boxes.data(), 6, MPI_DOUBLE, comm);
    neighbour_ranks(boxes.data(), nprocs, me, periodic, prd, reach, ranks);
    known = true;
    if (const char* rep = std::getenv("TDEM_TALLY_REPORT")) {  // a check for tests: who merges with whom
      if (rep[0] == '1') {
        std::string line = "tdem tally: rank " + std::to_string(me) + " of " + std::to_string(nprocs) +
                           " merges with ranks [";
        for (std::size_t i = 0; i < ranks.size(); i++) line += (i ? "," : "") + std::to_string(ranks[i]);
        std::printf("%s] (reach %.6g)\n", line.c_str(), reach);
        std::fflush(stdout);
      }
    }
  }
};

inline void merge_with_neighbours(ContactTally& tally, MPI_Comm comm, TallyNeighbours& nb, TallyExchange& buf) {
  const std::size_t k = nb.ranks.size();
  if (k == 0) return;
  constexpr int kTagSize = 7301, kTagData = 7302;
  tally.pack(buf.own);
  const std::int64_t n = static_cast<std::int64_t>(buf.own.size());
  nb.counts.assign(k, 0);
  nb.inbox.resize(k);
  nb.requests.resize(2 * k);
  for (std::size_t i = 0; i < k; i++) {
    MPI_Irecv(&nb.counts[i], 1, MPI_INT64_T, nb.ranks[i], kTagSize, comm, &nb.requests[i]);
    MPI_Isend(&n, 1, MPI_INT64_T, nb.ranks[i], kTagSize, comm, &nb.requests[k + i]);
  }
  MPI_Waitall(static_cast<int>(2 * k), nb.requests.data(), MPI_STATUSES_IGNORE);
  int nreq = 0;
  for (std::size_t i = 0; i < k; i++) {
    nb.inbox[i].resize(static_cast<std::size_t>(nb.counts[i]));
    if (nb.counts[i] > 0)
      MPI_Irecv(nb.inbox[i].data(), static_cast<int>(nb.counts[i]), MPI_INT64_T, nb.ranks[i], kTagData, comm,
                &nb.requests[nreq++]);
    if (n > 0)
      MPI_Isend(buf.own.data(), static_cast<int>(n), MPI_INT64_T, nb.ranks[i], kTagData, comm, &nb.requests[nreq++]);
  }
  MPI_Waitall(nreq, nb.requests.data(), MPI_STATUSES_IGNORE);
  for (std::size_t i = 0; i < k; i++)
    if (nb.counts[i] > 0)
      tally.merge_packed(nb.inbox[i].data(), static_cast<std::size_t>(nb.counts[i] / ContactTally::pack_width));
}

}  // namespace clumps
}  // namespace tdem
