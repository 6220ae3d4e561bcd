// SPDX-License-Identifier: GPL-2.0-or-later
// The thinned depth halo of the parallel mixing evaluation (src/fixes/mixing/mixing_parallel.h):
// a rank that gets, of another rank's particles, only those that column_candidates() keeps finds
// the same column tops, hence bitwise the same D, as an evaluation over the whole bed - for a split
// across the transport axis and for a split along the up axis, with a periodic lateral axis.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "fixes/mixing/mixing_parallel.h"

namespace mx = tdem::grate::mixing;
namespace mh = tdem::grate::mixing::host;

namespace {

struct Bed {
  std::vector<double> x, r;
};

// 4000 spheres under a wavy surface on a floor at z = 0, x in [0, 0.3], y periodic in [0, 0.06]
Bed wavy_bed() {
  std::mt19937_64 rng(123);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Bed b;
  for (int i = 0; i < 4000; ++i) {
    const double x = 0.3 * u(rng), y = 0.06 * u(rng);
    const double top = 0.05 + 0.015 * std::sin(40.0 * x) * std::cos(2.0 * M_PI * y / 0.06);
    b.x.insert(b.x.end(), {x, y, 0.005 + (top - 0.005) * std::sqrt(u(rng))});
    b.r.push_back(0.005);
  }
  return b;
}

mx::DepthOptions options() {
  mx::DepthOptions o;
  o.transport_axis = 0;
  o.up_axis = 2;
  o.lateral_axis = 1;
  o.column_width = 0.025;
  o.periodic.on[1] = true;
  o.periodic.hi[0] = 0.3;
  o.periodic.hi[1] = 0.06;
  o.periodic.hi[2] = 0.1;
  o.grate_height = [](double, double) { return 0.0; };
  return o;
}

}  // namespace

TEST(MixingHalo, ThinnedDepthHaloGivesTheColumnTopsOfTheWholeBed) {
  const Bed bed = wavy_bed();
  const std::size_t n = bed.r.size();
  const mx::DepthOptions o = options();
  const std::vector<double> whole = mx::particle_depths(n, bed.x.data(), bed.r.data(), o).depth;
  const mx::Periodic per = mx::depth_periodic(o);
  const bool use[3] = {true, true, false};
  for (int split = 0; split < 2; ++split) {  // 0: across x at 0.15; 1: along the up axis at z = 0.03
    std::vector<double> xa, xb, rb;
    std::vector<std::size_t> ib;
    for (std::size_t i = 0; i < n; ++i) {
      const bool in_a = split == 0 ? bed.x[3 * i] < 0.15 : bed.x[3 * i + 2] > 0.03;
      std::vector<double>& to = in_a ? xa : xb;
      to.insert(to.end(), &bed.x[3 * i], &bed.x[3 * i + 3]);
      if (!in_a) {
        rb.push_back(bed.r[i]);
        ib.push_back(i);
      }
    }
    const std::size_t na = xa.size() / 3, nb = xb.size() / 3;
    const std::vector<unsigned char> keep = mh::column_candidates(na, xa.data(), o, per);
    std::size_t kept = 0;
    // B's cloud: its own particles, A's kept ones, and the periodic images of both near B's box
    std::vector<double> pts = xb;
    for (std::size_t j = 0; j < na; ++j)
      if (keep[j]) {
        pts.insert(pts.end(), &xa[3 * j], &xa[3 * j + 3]);
        ++kept;
      }
    std::vector<int> image(pts.size() / 3, mx::kNoShift);
    double lo[3], hi[3];
    mx::bounding_box(nb, xb.data(), lo, hi);
    const std::size_t base = pts.size() / 3;
    for (std::size_t q = 0; q < base; ++q)
      mx::for_each_image_near(&pts[3 * q], per, lo, hi, 0.5 * o.column_width * (1 + 1e-9), use, false, [&](int c) {
        if (c == mx::kNoShift) return;
        pts.insert(pts.end(), pts.begin() + 3 * q, pts.begin() + 3 * q + 3);
        image.push_back(c);
      });
    const mx::Cloud cloud{pts.size() / 3, nb, pts.data(), image.data(), nullptr};
    const std::vector<double> got = mx::particle_depths(cloud, rb.data(), o).depth;
    std::size_t differ = 0, deep = 0;
    for (std::size_t q = 0; q < nb; ++q) {
      differ += got[q] != whole[ib[q]];
      deep += whole[ib[q]] > 0.2;
    }
    EXPECT_EQ(differ, 0u) << "split " << split;  // bitwise
    EXPECT_GT(deep, nb / 4) << "split " << split;  // the test bed is not trivially shallow
    // the halo is thinned: most of A (all but about its top layer) is left out
    EXPECT_LT(kept, na / 3) << "split " << split << ": kept " << kept << " of " << na;
    EXPECT_GT(kept, 0u);
    std::printf("split %d: kept %zu of %zu\n", split, kept, na);
  }
}
