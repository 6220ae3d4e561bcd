// SPDX-License-Identifier: GPL-2.0-or-later
// ExactSum (src/contact/exact_sum.h): the sum does not depend on the order of the additions nor on
// how they are split into accumulators that are merged (the MPI ranks of the clump output); it is
// the exact sum where that is a double, and within an ulp of a long double reference otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "contact/exact_sum.h"

using tdem::ExactSum;

namespace {

double sum_of(const std::vector<double>& v) {
  ExactSum s;
  for (double x : v) s.add(x);
  return s.value();
}

std::vector<double> mixed_values(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-60, 60);
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(std::ldexp(u(rng), e(rng)));
  return v;
}

}  // namespace

TEST(ExactSum, SumsThatAreDoublesComeOutExactly) {
  EXPECT_EQ(sum_of({}), 0.0);
  EXPECT_EQ(sum_of({1.0, 2.0, 3.5}), 6.5);
  // 1e16 + 1 - 1e16: a double sum gives 0 (or 2), the exact sum 1
  EXPECT_EQ(sum_of({1e16, 1.0, -1e16}), 1.0);
  EXPECT_EQ(sum_of({-2.5, -0.25}), -2.75);
  EXPECT_EQ(sum_of({0.1, -0.1}), 0.0);
  EXPECT_EQ(sum_of({std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::denorm_min()}),
            2 * std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(sum_of({1e300, 1e300}), 2e300);
  EXPECT_TRUE(std::isnan(sum_of({1.0, std::numeric_limits<double>::infinity()})));
}

TEST(ExactSum, IndependentOfOrderAndOfTheSplitIntoMergedParts) {
  std::vector<double> v = mixed_values(5000, 3);
  const double ref = sum_of(v);
  long double ld = 0.0L;
  for (double x : v) ld += x;
  EXPECT_NEAR(ref, static_cast<double>(ld), 4e-16 * std::fabs(ref) + 1e-300);
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(v.begin(), v.end(), rng);
    EXPECT_EQ(sum_of(v), ref);  // bitwise
    // split into 1..8 parts, each normalised (as each rank does before the reduction), merged
    const int parts = 1 + trial;
    std::vector<ExactSum> acc(parts);
    for (std::size_t i = 0; i < v.size(); ++i) acc[i % parts].add(v[i]);
    ExactSum total;
    for (auto& a : acc) {
      a.normalise();
      total.merge(a);
    }
    EXPECT_EQ(total.value(), ref);
  }
  // a plain double sum of the same values does depend on the order
  double fwd = 0.0, back = 0.0;
  for (double x : v) fwd += x;
  for (auto it = v.rbegin(); it != v.rend(); ++it) back += *it;
  EXPECT_NE(fwd, back);
}

// WindowSums (the region sums of the mixing measures): the result does not depend on the order nor
// on the split into parts whose limbs are added (the MPI ranks), and it is the exact sum to far
// below a double's precision (values cut 124 bits below the group maximum).
TEST(WindowSums, IndependentOfOrderAndSplitAndCloseToTheExactSum) {
  std::vector<double> v = mixed_values(5000, 5);
  auto window_sum = [](const std::vector<std::vector<double>>& parts) {
    const std::size_t groups = 2;  // group 0: the values, group 1: their squares
    std::vector<tdem::WindowSums> ws(parts.size(), tdem::WindowSums(groups));
    std::vector<double> mx(groups, 0.0);
    for (std::size_t p = 0; p < parts.size(); ++p)
      for (double x : parts[p]) {
        ws[p].note(0, x);
        ws[p].note(1, x * x);
      }
    for (auto& w : ws)  // MPI_Allreduce MAX
      for (std::size_t g = 0; g < groups; ++g) mx[g] = std::max(mx[g], w.maxima()[g]);
    tdem::WindowSums total(groups);
    std::copy(mx.begin(), mx.end(), total.maxima());
    total.start();
    for (std::size_t p = 0; p < parts.size(); ++p) {
      std::copy(mx.begin(), mx.end(), ws[p].maxima());
      ws[p].start();
      for (double x : parts[p]) {
        ws[p].add(0, x);
        ws[p].add(1, x * x);
      }
      for (std::size_t l = 0; l < total.limb_count(); ++l) total.limbs()[l] += ws[p].limbs()[l];  // MPI_SUM
    }
    return std::make_pair(total.value(0), total.value(1));
  };
  const auto ref = window_sum({v});
  ExactSum e0, e1;
  for (double x : v) {
    e0.add(x);
    e1.add(x * x);
  }
  EXPECT_NEAR(ref.first, e0.value(), 2e-16 * std::fabs(e0.value()));
  EXPECT_NEAR(ref.second, e1.value(), 2e-16 * e1.value());
  std::mt19937_64 rng(17);
  for (int parts = 1; parts <= 8; ++parts) {
    std::shuffle(v.begin(), v.end(), rng);
    std::vector<std::vector<double>> split(parts);
    for (std::size_t i = 0; i < v.size(); ++i) split[(i * 7919) % parts].push_back(v[i]);
    const auto got = window_sum(split);
    EXPECT_EQ(got.first, ref.first) << parts;  // bitwise
    EXPECT_EQ(got.second, ref.second) << parts;
  }
  // an empty group is 0, a NaN makes the sum NaN
  tdem::WindowSums w(1);
  w.start();
  EXPECT_EQ(w.value(0), 0.0);
  w.note(0, std::nan(""));
  w.start();
  EXPECT_TRUE(std::isnan(w.value(0)));
}
