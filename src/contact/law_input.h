// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: reading a law's input words by its Description (law_parameters.h), in one place for every
// host and tool: the positional values (materials expanded), then the keyword groups, with the
// count, number and range checks and their messages.
//
//   normal hertz 2e8 0.3 damping tsuji 0.7          -> E1 NU1 E2 NU2 | choice 2, E, ...
//   normal extended_linear e_fit power 0.3 0.2 tc_fit constant 1e-3 v_max 5
//   normal lsd stiffness 2000 50
//
// The words of a law end at the first word that is a keyword: one of the law's groups or
// refusals, or one the host names (is_keyword: "tangential", "limit_force", its own options).
// Host-free: plain words in, values or a message out.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "law_parameters.h"

namespace tdem {
namespace law {

// The most values a law's input expands to (materials, its own values, its groups).
inline constexpr int MAX_INPUT_VALUES = 16;

struct Reading {
  double v[MAX_INPUT_VALUES] = {};  // the expanded values (all_values(d) of them)
  int next = 0;                     // index of the first word not read
  std::string error;                // "" if the words are a valid input of the law
  bool ok() const { return error.empty(); }
};

namespace detail {

inline bool finite_number(const char* text, double& v) {
  char* end = nullptr;
  errno = 0;
  v = std::strtod(text, &end);
  return end != text && *end == '\0' && errno != ERANGE && std::isfinite(v);
}

// "linear GAMMA, kuwabara_kono GAMMA, tsuji E, general THETA C"
inline std::string choice_list(const Group& g) {
  std::string s;
  for (int c = 0; c < g.choice_count; ++c) {
    s += c ? ", " : "";
    s += g.choices[c].word;
    for (int k = 0; k < g.choices[c].count; ++k) s += std::string(" ") + g.choices[c].params[k].name;
  }
  return s;
}

// "C0 C1"
inline std::string value_names(const Choice& c) {
  std::string s;
  for (int k = 0; k < c.count; ++k) s += (k ? " " : "") + std::string(c.params[k].name);
  return s;
}

class Reader {
 public:
  Reader(const Description& d, int n, const char* const* w, bool (*host_keyword)(const char*))
      : d_(d), n_(n), w_(w), host_keyword_(host_keyword) {}

  bool keyword(const char* word) const {
    for (int g = 0; g < d_.group_count; ++g)
      if (d_.groups[g].keyword[0] && std::strcmp(word, d_.groups[g].keyword) == 0) return true;
    for (int r = 0; r < d_.refusal_count; ++r)
      if (std::strcmp(word, d_.refusals[r].keyword) == 0) return true;
    return host_keyword_ && host_keyword_(word);
  }
  // number of value words from i on: the words before the next keyword or the end, but past the
  // most values the law can take (most) only numbers (a host's own words may follow the law's)
  int available(int i, int most) const {
    int k = 0;
    double x;
    while (i + k < n_ && !keyword(w_[i + k]) && (k < most || finite_number(w_[i + k], x))) ++k;
    return k;
  }
  const char* word_or_end(int i) const { return i < n_ ? w_[i] : "end of line"; }

  // The positional values at word 0; returns the next word index or -1 (error set).
  int positional(Reading& r, const std::string& qualifier) const {
    if (d_.count == 0 && !d_.materials) return 0;
    const int n = available(0, max_words(d_));
    if (!count_ok(d_, n)) return fail(r, count_message(d_, n, qualifier));
    double words[MAX_INPUT_VALUES];
    for (int k = 0; k < n; ++k) {
      const Parameter& p = parameter(d_, value_index(d_, n, k));
      if (!finite_number(w_[k], words[k]))
        return fail(r, std::string(d_.kind) + " " + d_.name + " " + p.name + " expects a finite number, got '" +
                           w_[k] + "'");
    }
    expand(d_, words, n, r.v);
    const std::string bad = check(d_, r.v);
    return bad.empty() ? n : fail(r, bad);
  }

  // Group g at word i (its keyword, or with keyword "" its choice word); returns the next index
  // or -1 (error set).
  int group(Reading& r, int gi, int i) const {
    const Group& g = d_.groups[gi];
    const std::string head = std::string(d_.kind) + " " + d_.name + (g.keyword[0] ? " " : "") + g.keyword;
    if (g.keyword[0]) ++i;
    int c = 0;
    if (g.choice_count > 1 || g.choices[0].word) {
      if (i >= n_ || (g.keyword[0] && keyword(w_[i])))
        return fail(r, head + " needs a " + g.choice_kind + "; allowed: " + choice_list(g));
      for (c = 0; c < g.choice_count; ++c)
        if (std::strcmp(w_[i], g.choices[c].word) == 0) break;
      if (c == g.choice_count)
        return fail(r, head + (g.kind_in_unknown ? std::string(" ") + g.choice_kind : std::string()) + " '" + w_[i] +
                           "' is unknown; allowed: " + choice_list(g));
      ++i;
    }
    const Choice& ch = g.choices[c];
    const std::string what = head + (ch.word ? std::string(" ") + ch.word : std::string());
    const int have = available(i, ch.count);
    if (have < ch.count || (g.exact && have > ch.count))
      return fail(r, what + " needs " + std::to_string(ch.count) + " value" + (ch.count == 1 ? "" : "s") + " (" +
                         (g.values_text ? g.values_text : value_names(ch)) + "), got " + std::to_string(have));
    double* out = r.v + group_offset(d_, gi);
    if (g.choice_count > 1) *out++ = c;
    for (int k = 0; k < ch.count; ++k) {
      if (!finite_number(w_[i + k], out[k]))
        return fail(r, what + " " + ch.params[k].name + " expects a finite number, got '" + w_[i + k] + "'");
      const std::string name = what + " " + ch.params[k].name +
                               (ch.params[k].meaning_in_messages ? std::string(" (") + ch.params[k].meaning + ")" : std::string());
      const std::string bad = check_bound(ch.params[k], name, out[k]);
      if (!bad.empty()) return fail(r, bad);
    }
    if (g.check) {
      try {
        g.check(c, out);
      } catch (const std::exception& ex) {
        std::string vals;
        for (int k = 0; k < ch.count; ++k)
          vals += std::string(k ? ", " : "") + ch.params[k].name + " = " + number_text(out[k]);
        return fail(r, what + " (" + vals + "): " + ex.what());
      }
    }
    return i + ch.count;
  }

  // The whole input: positional values, the required groups in order, then the optional groups
  // in any order (each at most once), then a refused keyword is an error.
  void read(Reading& r, const std::string& qualifier) const {
    for (int gi = 0; gi < d_.group_count; ++gi) {  // fallbacks of every group value
      const Group& g = d_.groups[gi];
      double* out = r.v + group_offset(d_, gi);
      if (g.choice_count > 1) *out++ = 0.0;
      for (int k = 0; k < g.choices[0].count; ++k) out[k] = g.choices[0].params[k].fallback;
    }
    int i = positional(r, qualifier);
    if (i < 0) return;
    int prev = -1;
    bool seen[32] = {};
    for (int gi = 0; gi < d_.group_count && d_.groups[gi].required; ++gi) {
      const Group& g = d_.groups[gi];
      if (g.keyword[0] && (i >= n_ || std::strcmp(w_[i], g.keyword) != 0)) {
        const std::string after = prev >= 0 ? std::string(" after ") + d_.groups[prev].keyword : std::string();
        std::string forms;
        for (int c = 0; c < g.choice_count; ++c) forms += (c ? "|" : "") + std::string(g.choices[c].word);
        fail(r, std::string(d_.kind) + " " + d_.name + " needs '" + g.keyword + " " + forms + " " +
                    g.choices[0].params[0].name + " ..'" + after + ", got '" + word_or_end(i) + "'");
        return;
      }
      if ((i = group(r, gi, i)) < 0) return;
      seen[gi] = true;
      prev = gi;
    }
    for (bool more = true; more && i < n_;) {
      more = false;
      for (int gi = 0; gi < d_.group_count; ++gi) {
        const Group& g = d_.groups[gi];
        if (g.required || seen[gi] || std::strcmp(w_[i], g.keyword) != 0) continue;
        if ((i = group(r, gi, i)) < 0) return;
        seen[gi] = more = true;
        break;
      }
    }
    for (int k = 0; k < d_.refusal_count && i < n_; ++k)
      if (std::strcmp(w_[i], d_.refusals[k].keyword) == 0) {
        fail(r, std::string(d_.kind) + " " + d_.name + " takes no " + d_.refusals[k].keyword + " (" +
                    d_.refusals[k].reason + ")");
        return;
      }
    r.next = i;
  }

 private:
  static int fail(Reading& r, const std::string& m) {
    r.error = m;
    return -1;
  }
  const Description& d_;
  int n_;
  const char* const* w_;
  bool (*host_keyword_)(const char*);
};

}  // namespace detail

// Read the input of law d from words[0 .. n) (the words after its name). qualifier follows the
// law's name in the count message. On success r.v holds all_values(d) values and r.next the index
// of the first word after the law's input.
inline Reading read(const Description& d, int n, const char* const* words, bool (*host_keyword)(const char*),
                    const std::string& qualifier = "") {
  Reading r;
  detail::Reader(d, n, words, host_keyword).read(r, qualifier);
  return r;
}

// The choice index of group g in the expanded values v, and the start of its values.
inline int choice_of(const Description& d, int g, const double* v) {
  return d.groups[g].choice_count > 1 ? static_cast<int>(v[group_offset(d, g)]) : 0;
}
inline const double* group_values(const Description& d, int g, const double* v) {
  return v + group_offset(d, g) + (d.groups[g].choice_count > 1 ? 1 : 0);
}

}  // namespace law
}  // namespace tdem
