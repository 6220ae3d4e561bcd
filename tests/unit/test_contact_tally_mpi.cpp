// SPDX-License-Identifier: GPL-2.0-or-later
// The neighbourhood of the contact tally's exchange (src/contact/multi_contact/contact_tally_mpi.h):
// which sub-domains are within reach, through periodic images, symmetric; a rank with no
// neighbours keeps its own tally.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "contact/multi_contact/contact_tally_mpi.h"

namespace cl = tdem::clumps;

namespace {
// nx x ny x nz sub-domains of a box [0, L]^3, rank = i + nx (j + ny k)
std::vector<double> grid_boxes(int nx, int ny, int nz, const double L[3]) {
  std::vector<double> b;
  for (int k = 0; k < nz; k++)
    for (int j = 0; j < ny; j++)
      for (int i = 0; i < nx; i++) {
        const int ijk[3] = {i, j, k}, n[3] = {nx, ny, nz};
        for (int d = 0; d < 3; d++) b.push_back(L[d] * ijk[d] / n[d]);
        for (int d = 0; d < 3; d++) b.push_back(L[d] * (ijk[d] + 1) / n[d]);
      }
  return b;
}
}  // namespace

TEST(ContactTallyExchange, NeighboursWithinReachAndThroughPeriodicImages) {
  const double L[3] = {8.0, 1.0, 1.0};
  const std::vector<double> boxes = grid_boxes(8, 1, 1, L);  // slabs of width 1 along x
  std::vector<int> out;
  const bool open[3] = {false, false, false}, px[3] = {true, false, false};
  cl::neighbour_ranks(boxes.data(), 8, 0, open, L, 0.5, out);
  EXPECT_EQ(out, std::vector<int>({1}));  // touching only
  cl::neighbour_ranks(boxes.data(), 8, 0, px, L, 0.5, out);
  EXPECT_EQ(out, std::vector<int>({1, 7}));  // and the image of the last slab
  cl::neighbour_ranks(boxes.data(), 8, 3, px, L, 1.0, out);
  EXPECT_EQ(out, std::vector<int>({1, 2, 4, 5}));  // a gap of exactly the reach is within it
  cl::neighbour_ranks(boxes.data(), 8, 3, px, L, 0.999, out);
  EXPECT_EQ(out, std::vector<int>({2, 4}));
  cl::neighbour_ranks(boxes.data(), 8, 0, px, L, 3.5, out);
  EXPECT_EQ(out, std::vector<int>({1, 2, 3, 4, 5, 6, 7}));  // half the period: all
}

TEST(ContactTallyExchange, NeighbourhoodIsSymmetricAndUsesTheDiagonalGap) {
  const double L[3] = {3.0, 2.0, 2.0};
  const std::vector<double> boxes = grid_boxes(3, 2, 2, L);  // unit cubes
  const bool per[3] = {true, false, true};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.6);
  for (int t = 0; t < 50; t++) {
    const double reach = u(rng);
    for (int a = 0; a < 12; a++) {
      std::vector<int> na;
      cl::neighbour_ranks(boxes.data(), 12, a, per, L, reach, na);
      for (int b = 0; b < 12; b++) {
        std::vector<int> nb;
        cl::neighbour_ranks(boxes.data(), 12, b, per, L, reach, nb);
        const bool ab = std::count(na.begin(), na.end(), b) > 0, ba = std::count(nb.begin(), nb.end(), a) > 0;
        EXPECT_EQ(ab, ba) << a << " " << b << " reach " << reach;
      }
    }
  }
  // cubes meeting at an edge only (y and z both one cube apart, not periodic in y): gap 0;
  // rank 0 = (0,0,0), rank 4 = (1,1,0) touch along an edge, rank 10 = (1,1,1) at a corner
  std::vector<int> out;
  cl::neighbour_ranks(boxes.data(), 12, 0, per, L, 1e-12, out);
  EXPECT_TRUE(std::count(out.begin(), out.end(), 4) && std::count(out.begin(), out.end(), 10));
  // the same cube one further along x without the periodic image: gap 1 in x only
  const bool none[3] = {false, false, false};
  cl::neighbour_ranks(boxes.data(), 12, 0, none, L, 0.9, out);
  EXPECT_EQ(std::count(out.begin(), out.end(), 2), 0);
  cl::neighbour_ranks(boxes.data(), 12, 0, per, L, 0.9, out);
  EXPECT_EQ(std::count(out.begin(), out.end(), 2), 1);  // x periodic: rank 2 is adjacent through it
}

TEST(ContactTallyExchange, NoNeighboursKeepsTheOwnTally) {
  cl::ContactTally t(1.0);
  t.add(1, 2, 0.25);
  t.add(1, 2, 0.5);
  cl::TallyNeighbours nb;  // no ranks within reach: nothing is sent or received
  cl::TallyExchange buf;
  cl::merge_with_neighbours(t, MPI_COMM_WORLD, nb, buf);
  EXPECT_EQ(t.count_of(0), 2);
  EXPECT_EQ(t.overlap_sum_of(1), 0.75);
}
