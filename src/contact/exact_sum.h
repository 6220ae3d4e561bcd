// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: sums of doubles that do not depend on the order of the additions, so that a sum over the
// atoms or bodies of several MPI ranks is bitwise the same on any number of ranks (issue 20).
//
// ExactSum keeps the sum exactly, as a fixed-point integer over the whole double range: limb k
// holds 32 bits of weight 2^(32 k - kBias). add() splits a double's 53-bit significand over the
// three limbs it touches; the limbs are int64, so 2^30 additions (or a merge of 2^30 normalised
// accumulators) cannot overflow before normalise() carries them. value() gives the double of the
// three highest normalised (unique) limbs, so equal sums give equal doubles.
// Infinities and NaNs are not representable: they make the sum NaN.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace tdem {

class ExactSum {
 public:
  static constexpr int kLimbs = 68;   // 68 * 32 bits cover 2^-1074 ... 2^1024 and carries
  static constexpr int kBias = 1074;  // weight of bit 0 of limb 0: 2^-1074 (the smallest subnormal)

  void clear() {
    limbs_.fill(0);
    bad_ = 0;
  }
  void add(double x) {
    if (x == 0.0) return;
    if (!std::isfinite(x)) {
      bad_ = 1;
      return;
    }
    int e = 0;
    const double m = std::frexp(std::fabs(x), &e);  // |x| = m 2^e, m in [0.5, 1)
    // |x| = s 2^(e - 53), s a 53-bit integer; bit position of s's bit 0 above 2^-1074
    std::int64_t s = static_cast<std::int64_t>(std::ldexp(m, 53));
    int pos = e - 53 + kBias;
    if (pos < 0) {  // subnormal range: s has trailing zeros there
      s >>= -pos;
      pos = 0;
    }
    const int k = pos / 32, sh = pos % 32;
    // s << sh spans at most 85 bits: three limbs
    const std::uint64_t lo = static_cast<std::uint64_t>(s) << sh;  // low 64 bits
    const std::uint64_t hi = sh == 0 ? 0 : static_cast<std::uint64_t>(s) >> (64 - sh);
    const std::int64_t p0 = static_cast<std::int64_t>(lo & 0xffffffffu);
    const std::int64_t p1 = static_cast<std::int64_t>(lo >> 32);
    const std::int64_t p2 = static_cast<std::int64_t>(hi);
    const std::int64_t sign = x < 0.0 ? -1 : 1;
    limbs_[k] += sign * p0;
    limbs_[k + 1] += sign * p1;
    limbs_[k + 2] += sign * p2;
  }
  // Carries so that limbs 0 .. kLimbs-2 lie in [0, 2^32) and the top limb holds the sign: the
  // unique form of the sum.
  void normalise() {
    for (int k = 0; k + 1 < kLimbs; k++) {
      const std::int64_t c = floor_div(limbs_[k]);
      limbs_[k] -= c * (std::int64_t(1) << 32);
      limbs_[k + 1] += c;
    }
  }
  // Adds another accumulator (e.g. a rank's, after MPI_Allreduce of the limbs).
  void merge(const ExactSum& o) {
    for (int k = 0; k < kLimbs; k++) limbs_[k] += o.limbs_[k];
    bad_ |= o.bad_;
  }
  // The sum rounded to a double (normalises first).
  double value() {
    if (bad_) return std::numeric_limits<double>::quiet_NaN();
    normalise();
    const bool neg = limbs_[kLimbs - 1] < 0;
    ExactSum mag = *this;  // the magnitude, normalised: every limb in [0, 2^32)
    if (neg) {
      for (auto& l : mag.limbs_) l = -l;
      mag.normalise();
    }
    int top = kLimbs - 1;
    while (top >= 0 && mag.limbs_[top] == 0) top--;
    if (top < 0) return 0.0;
    // the three highest limbs (64 to 96 significant bits) give the double; the normalised limbs
    // are unique, so the result is a function of the exact sum alone
    double r = 0.0;
    for (int k = top; k >= 0 && k >= top - 2; k--) r += std::ldexp(static_cast<double>(mag.limbs_[k]), 32 * k - kBias);
    return neg ? -r : r;
  }
  std::int64_t* limbs() { return limbs_.data(); }
  int* bad() { return &bad_; }

 private:
  std::array<std::int64_t, kLimbs> limbs_{};
  int bad_ = 0;

  static std::int64_t floor_div(std::int64_t v) {  // floor(v / 2^32)
    return v >= 0 ? v >> 32 : -((-v + 0xffffffffLL) >> 32);
  }
};

}  // namespace tdem

namespace tdem {

// Sums of many groups of doubles (e.g. one per region) that do not depend on the order of the
// additions, with a fixed window of kLimbs x 32 bits below the largest magnitude of each group
// instead of ExactSum's whole double range (4 limbs = 32 bytes a group, so that 10^5 regions stay
// small). Two passes: note() every value (or set the maxima directly), make the maxima global
// (MPI_Allreduce MAX of maxima()), start(); then add() every value, make the limbs global
// (MPI_Allreduce SUM of limbs()), value(). Each value is cut to the window before it is added
// (bits below 2^(e_max - 124) of its group, with |value| < 2^e_max, are dropped toward zero), so
// the result is the exact sum of the cut values: a function of the values alone, whatever the order
// and the number of ranks. 2^31 additions per group cannot overflow.
class WindowSums {
 public:
  static constexpr int kLimbs = 4;

  explicit WindowSums(std::size_t groups = 0) { resize(groups); }
  void resize(std::size_t groups) {
    max_.assign(groups, 0.0);
    base_.assign(groups, 0);
    limbs_.assign(groups * kLimbs, 0);
    bad_ = 0;
  }
  std::size_t groups() const { return max_.size(); }
  void note(std::size_t g, double x) {
    const double a = std::fabs(x);
    if (!(a <= max_[g])) max_[g] = a;  // NaN and inf propagate as NaN/inf maxima
  }
  double* maxima() { return max_.data(); }
  // fixes the window of every group from its (global) maximum
  void start() {
    for (std::size_t g = 0; g < max_.size(); ++g) {
      int e = 0;
      if (!std::isfinite(max_[g])) bad_ = 1;
      else if (max_[g] > 0.0) std::frexp(max_[g], &e);  // max < 2^e
      base_[g] = e - 32 * kLimbs + 4;  // the top limb keeps 4 spare bits below its 2^32
    }
  }
  void add(std::size_t g, double x) {
    if (x == 0.0) return;
    if (!std::isfinite(x)) {
      bad_ = 1;
      return;
    }
    double s = std::ldexp(std::fabs(x), -base_[g]);  // < 2^(32 kLimbs - 4); exact unless it underflows
    const std::int64_t sign = x < 0.0 ? -1 : 1;
    std::int64_t* l = &limbs_[g * kLimbs];
    for (int k = kLimbs - 1; k >= 0; --k) {  // s = sum_k q_k 2^(32 k): every step is exact
      const double p = std::ldexp(1.0, 32 * k);
      const double q = std::floor(s / p);
      l[k] += sign * static_cast<std::int64_t>(q);
      s -= q * p;
    }
  }
  std::int64_t* limbs() { return limbs_.data(); }
  std::size_t limb_count() const { return limbs_.size(); }
  int* bad() { return &bad_; }
  // the sum of group g (after the limbs are global): normalised carries, then the limbs from the top
  double value(std::size_t g) const {
    if (bad_) return std::numeric_limits<double>::quiet_NaN();
    std::int64_t l[kLimbs];
    std::copy_n(&limbs_[g * kLimbs], kLimbs, l);
    for (int k = 0; k + 1 < kLimbs; ++k) {  // lower limbs in [0, 2^32), the top one takes the sign
      const std::int64_t c = l[k] >= 0 ? l[k] >> 32 : -((-l[k] + 0xffffffffLL) >> 32);
      l[k] -= c * (std::int64_t(1) << 32);
      l[k + 1] += c;
    }
    double r = 0.0;
    for (int k = kLimbs - 1; k >= 0; --k) r += std::ldexp(static_cast<double>(l[k]), 32 * k + base_[g]);
    return r;
  }

 private:
  std::vector<double> max_;
  std::vector<int> base_;
  std::vector<std::int64_t> limbs_;
  int bad_ = 0;
};

}  // namespace tdem
