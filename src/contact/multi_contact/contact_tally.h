// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: per-step tally of the contacts between the same two bodies, for the multiple-contact
// corrections of multi_contact.h (count, overlap_share) in the host pair and wall styles.
//
// A host makes one pass over its touching contacts before the force pass: add(a, b, xi) for every
// contact that has a clump on at least one side (a, b: 64-bit ids of the two sides chosen by the
// host, e.g. the body index for a clump sphere, -(tag+1) for a free sphere, a wall id for a wall;
// the tally only compares them). On several ranks it packs its entries, gathers the other ranks'
// entries and merges them (merge_packed; contact_tally_mpi.h does it with MPI_Allgatherv), so
// every rank sees the global N_c and sum of overlaps of every body pair it touches. In the force pass, factor(k, xi) gives the factor s of the k-th
// added contact (same order), or pair_factor(find(a, b), xi) by the sides of the contact.
//
// The overlap sum is kept in fixed point (128-bit integer units of quantum = length_scale * 2^-80,
// with length_scale >= the largest overlap, e.g. the largest sphere diameter; an overlap of
// 1e-9 length_scale is then resolved to 1e-15): the sum is exact and independent of the order of
// the additions, so the factors - and the run - do not depend on how the contacts are split over
// ranks. One contact in a pair gets s = 1 exactly.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "contact/multi_contact/multi_contact.h"

namespace tdem {
namespace clumps {

class ContactTally {
 public:
  // values per packed entry: a, b, n, fixed-point overlap sum (high and low 64 bits)
  static constexpr int pack_width = 5;

  explicit ContactTally(double length_scale = 1.0) { set_length_scale(length_scale); }

  void set_length_scale(double length_scale) {
    if (!(length_scale > 0.0)) checks::fail("contact tally length scale", length_scale, "(0, inf)");
    inv_quantum_ = std::ldexp(1.0, 80) / length_scale;
    quantum_ = 1.0 / inv_quantum_;
  }
  double quantum() const { return quantum_; }

  void clear() {
    index_.clear();
    entries_.clear();
    slots_.clear();
  }

  // one touching contact between sides a and b (order irrelevant) with overlap xi >= 0.
  // counted = false: a contact that is counted elsewhere (newton off: the copy of a pair with a
  // ghost partner that the other rank, or the other image, counts): it keeps its place in the
  // contact order and makes the pair known here, so merge_packed brings the other ranks' counts
  // to it, but adds nothing to it.
  int add(std::int64_t a, std::int64_t b, double xi, bool counted = true) {
    if (a > b) std::swap(a, b);
    auto ins = index_.try_emplace(Key{a, b}, static_cast<int>(entries_.size()));
    if (ins.second) entries_.push_back(Entry{a, b, 0, 0});
    if (counted) {
      Entry& e = entries_[ins.first->second];
      e.n += 1;
      e.qsum += to_fixed(xi);
    }
    slots_.push_back(ins.first->second);
    return ins.first->second;
  }

  std::size_t contacts() const { return slots_.size(); }
  std::size_t pairs() const { return entries_.size(); }
  // contacts and overlap sum of the pair of the k-th added contact
  int count_of(std::size_t k) const { return static_cast<int>(entries_[slots_[k]].n); }
  double overlap_sum_of(std::size_t k) const { return static_cast<double>(entries_[slots_[k]].qsum) * quantum_; }

  // factor s of the k-th added contact, with overlap xi
  double factor(Correction c, std::size_t k, double xi) const { return pair_factor(c, slots_[k], xi); }

  // pair slot of the sides a, b (order irrelevant), or -1 when they have no contact in the tally
  int find(std::int64_t a, std::int64_t b) const {
    if (a > b) std::swap(a, b);
    auto it = index_.find(Key{a, b});
    return it == index_.end() ? -1 : it->second;
  }

  // factor s of a contact with overlap xi in the pair of slot (from add or find; -1: s = 1)
  double pair_factor(Correction c, int slot, double xi) const {
    if (slot < 0) return 1.0;
    const Entry& e = entries_[slot];
    if (e.n <= 1) return 1.0;
    switch (c) {
      case Correction::count: return 1.0 / static_cast<double>(e.n);
      case Correction::overlap_share: {
        const double sum = static_cast<double>(e.qsum) * quantum_;
        return sum > 0.0 ? std::max(0.0, xi) / sum : 1.0 / static_cast<double>(e.n);
      }
      case Correction::none:
      case Correction::local_mass: return 1.0;
    }
    return 1.0;
  }

  // this rank's entries, pack_width int64 each (for MPI_Allgatherv)
  void pack(std::vector<std::int64_t>& buf) const {
    buf.resize(entries_.size() * pack_width);
    std::size_t o = 0;
    for (const Entry& e : entries_) {
      buf[o++] = e.a;
      buf[o++] = e.b;
      buf[o++] = e.n;
      buf[o++] = static_cast<std::int64_t>(e.qsum >> 64);
      buf[o++] = static_cast<std::int64_t>(static_cast<std::uint64_t>(e.qsum));
    }
  }

  // add entries counted on another rank (never this rank's own block): only pairs present here
  // are kept
  void merge_packed(const std::int64_t* buf, std::size_t nentries) {
    for (std::size_t k = 0; k < nentries; k++) {
      const std::int64_t* p = buf + k * pack_width;
      auto it = index_.find(Key{p[0], p[1]});
      if (it == index_.end()) continue;
      entries_[it->second].n += p[2];
      const Fixed hi = static_cast<Fixed>(p[3]) << 64;
      entries_[it->second].qsum += hi | static_cast<Fixed>(static_cast<std::uint64_t>(p[4]));
    }
  }

 private:
  struct Key {
    std::int64_t a, b;
    bool operator==(const Key& o) const { return a == o.a && b == o.b; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = static_cast<std::uint64_t>(k.a) * 0x9E3779B97F4A7C15ull;
      h ^= static_cast<std::uint64_t>(k.b) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };
  __extension__ typedef __int128 Fixed;  // GCC/Clang 128-bit integer
  struct Entry {
    std::int64_t a, b, n;
    Fixed qsum;
  };

  Fixed to_fixed(double xi) const {
    return xi > 0.0 ? static_cast<Fixed>(std::nearbyint(xi * inv_quantum_)) : 0;
  }

  double inv_quantum_ = 1.0, quantum_ = 1.0;
  std::unordered_map<Key, int, KeyHash> index_;
  std::vector<Entry> entries_;
  std::vector<int> slots_;  // pair slot of each added contact, in the order of add()
};

}  // namespace clumps
}  // namespace tdem
