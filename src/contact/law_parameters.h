// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: how a contact law describes its input parameters, and the one set of checks and
// messages built from that description.
//
// A law's file declares, next to its kernel, a `Description`: its name, the values of its input
// line in order (name, meaning, SI unit, allowed range, optional tail values with their default),
// whether the line starts with the material pair E NU [E2 NU2], and its history slots. The hosts
// and tools read the description for the syntax ("KL KUL [S]"), the value count, the range checks
// and their messages, so that every law reports bad input in the same words in every host:
//
//   normal walton_braun needs 2 or 3 values (KL KUL [S]), got 1
//   normal walton_braun KL (loading stiffness) = -100000 must be > 0
//   normal walton_braun KUL (unloading stiffness) = 50000 is outside the allowed range [KL, inf) = [100000, inf)
//   normal thornton NU (Poisson ratio) = -1.5 is outside the allowed range (-1, 0.5]
//
// Host-free: plain data, std::string messages, no host headers.
#pragma once

#include "input_checks.h"
#include "kinematics.h"

#include <cstdio>
#include <string>

namespace tdem {
namespace law {

// The allowed range of one value.
enum class Bound : int {
  any,           // any finite number
  positive,      // > 0
  non_negative,  // >= 0
  restitution,   // (0, 1]
  poisson,       // (-1, 0.5]
  at_least       // >= the value of parameter `ref` (which is checked first)
};

struct Parameter {
  const char* name;      // the word of the syntax line: "KL"
  const char* meaning;   // "loading stiffness" (in messages and docs)
  const char* unit;      // SI unit of the value ("N/m", "Pa", "1" for a number)
  Bound bound;
  int ref = -1;          // Bound::at_least: index of the lower limit among the law's values
  bool optional = false; // may be left out at the end of the line; then `fallback` is used
  double fallback = 0.0;
  bool meaning_in_messages = false;  // in a group or a terse law: "restitution TC (contact time) = 0"
};

// One choice of a keyword group: its word ("tsuji", "power"; nullptr in a group without choices,
// as `v_min V`) and the values that follow it.
struct Choice {
  const char* word;
  const Parameter* params;
  int count;
};

// Values after the positional ones, introduced by a keyword: `damping tsuji E`, `e_fit power C0
// C1`, `v_min V`. With keyword "" the choice word itself comes first (lsd's `stiffness KN GAMMAN |
// restitution E TC`). In the expanded value list a group takes width(g) values: the index of its
// choice (groups of more than one choice), then the values of the choice (the values a choice
// leaves out, and an optional group that is left out, take the fallback of their parameter).
struct Group {
  const char* keyword;
  const char* choice_kind;  // the choice word in messages: "form" ("e_fit needs a form; allowed: ...")
  bool kind_in_unknown;     // "e_fit form 'x' is unknown" (true) or "damping 'x' is unknown" (false)
  bool required;            // must come, in the order of the list, before the optional groups
  const Choice* choices;
  int choice_count;
  bool exact;               // false: numbers after the choice's values end the law's input (the host
                            // reports them); true: they are a count error
  const char* values_text;  // the count message's name of the values ("impact velocity"); nullptr:
                            // their words ("C0 C1")
  // the law's own check of a choice's values (they passed their ranges); throws std::exception
  void (*check)(int choice, const double* values);
};

// A keyword a law refuses, with the reason ("tc_fit", "its contact time follows from Hertz").
struct Refusal {
  const char* keyword;
  const char* reason;
};

// A law's description. With materials = true the input starts with E NU (one material for both
// partners) or E1 NU1 E2 NU2, expanded to four values before the law's own `params`.
struct Description {
  const char* kind;  // "normal" or "tangential"
  const char* name;  // the law's input name: "walton_braun"
  bool materials;
  const Parameter* params;
  int count;  // entries of params
  const HistorySlot* history;
  int history_size;
  // the count message of a materials law: false "needs 3 values (E NU MU: both partners of one
  // material) or 5 values (E1 NU1 E2 NU2 MU)", true "needs 3 or 5 values (E NU [E2 NU2] MU)"
  bool bracketed = false;
  // keyword groups after the positional values, and refused keywords
  const Group* groups = nullptr;
  int group_count = 0;
  const Refusal* refusals = nullptr;
  int refusal_count = 0;
  // messages name a value by its word alone ("KT = 0 must be > 0"), not with its meaning
  bool terse = false;
};

template <int N>
constexpr Description describe(const char* kind, const char* name, bool materials, const Parameter (&p)[N],
                               const HistorySlot* history, int history_size, bool bracketed = false) {
  return {kind, name, materials, p, N, history, history_size, bracketed};
}

// A description with keyword groups (and refused keywords).
template <int N, int G>
constexpr Description describe(const char* kind, const char* name, bool materials, const Parameter (&p)[N],
                               const Group (&g)[G], const HistorySlot* history, int history_size,
                               const Refusal* refusals = nullptr, int refusal_count = 0) {
  return {kind, name, materials, p, N, history, history_size, false, g, G, refusals, refusal_count, false};
}
template <int G>
constexpr Description describe(const char* kind, const char* name, bool materials, const Group (&g)[G],
                               const HistorySlot* history, int history_size, const Refusal* refusals = nullptr,
                               int refusal_count = 0) {
  return {kind, name, materials, nullptr, 0, history, history_size, false, g, G, refusals, refusal_count, false};
}

// The material pair's four values (index 0..3 of a materials law's value list).
inline constexpr Parameter material_pair[4] = {
    {"E", "Young's modulus", "Pa", Bound::positive},
    {"NU", "Poisson ratio", "1", Bound::poisson},
    {"E2", "Young's modulus", "Pa", Bound::positive},
    {"NU2", "Poisson ratio", "1", Bound::poisson},
};
inline constexpr int MATERIAL_VALUES = 4;

// Values of the expanded list before the groups (materials first) and the smallest/largest
// number of positional input words.
inline int value_count(const Description& d) { return (d.materials ? MATERIAL_VALUES : 0) + d.count; }

// The values of group g in the expanded list: its choice index (more than one choice), then the
// most values of a choice.
inline int width(const Group& g) {
  int w = 0;
  for (int c = 0; c < g.choice_count; ++c) w = g.choices[c].count > w ? g.choices[c].count : w;
  return (g.choice_count > 1 ? 1 : 0) + w;
}
// Where group k starts in the expanded list, and the length of the whole list.
inline int group_offset(const Description& d, int k) {
  int o = value_count(d);
  for (int j = 0; j < k; ++j) o += width(d.groups[j]);
  return o;
}
inline int all_values(const Description& d) { return group_offset(d, d.group_count); }
inline int required_words(const Description& d) {
  int n = d.materials ? 2 : 0;
  for (int k = 0; k < d.count; ++k) n += d.params[k].optional ? 0 : 1;
  return n;
}
inline int all_words(const Description& d) { return (d.materials ? 2 : 0) + d.count; }
inline int max_words(const Description& d) { return d.materials ? required_words(d) + 2 : all_words(d); }
// Is n input words a valid count? (materials laws: n or n + 2, with one or two materials)
inline bool count_ok(const Description& d, int n) {
  if (d.materials) return n == required_words(d) || n == required_words(d) + 2;
  return n >= required_words(d) && n <= all_words(d);
}

// The expanded value k: its parameter record.
inline const Parameter& parameter(const Description& d, int k) {
  if (d.materials) return k < MATERIAL_VALUES ? material_pair[k] : d.params[k - MATERIAL_VALUES];
  return d.params[k];
}

// Word k of an input line of n words: its index in the expanded value list.
inline int value_index(const Description& d, int n, int k) {
  if (!d.materials) return k;
  if (n == required_words(d)) return k < 2 ? k : k + 2;  // one material: E NU, then the law's own
  return k;
}

// "KL KUL [S]", "E NU PY"; with materials and two = true: "E1 NU1 E2 NU2 PY"; bracketed:
// "E NU [E2 NU2] MU".
inline std::string syntax(const Description& d, bool two = false, bool bracketed = false) {
  std::string s = d.materials ? (bracketed ? "E NU [E2 NU2]" : two ? "E1 NU1 E2 NU2" : "E NU") : "";
  for (int k = 0; k < d.count; ++k) {
    if (!s.empty()) s += ' ';
    s += d.params[k].optional ? std::string("[") + d.params[k].name + "]" : d.params[k].name;
  }
  return s;
}

// "normal walton_braun needs 2 or 3 values (KL KUL [S]), got 1"; qualifier follows the name
// ("tangential cundall_strack (with normal hertz) needs ..."). A law whose first group is required
// says what comes next: "... (E1 NU1 E2 NU2) before e_fit, got 3".
inline std::string count_message(const Description& d, int n, const std::string& qualifier = "") {
  const std::string head = std::string(d.kind) + " " + d.name + qualifier + " needs ";
  const std::string got = (d.group_count > 0 && d.groups[0].required && d.groups[0].keyword[0]
                               ? std::string(" before ") + d.groups[0].keyword
                               : std::string()) +
                          ", got " + std::to_string(n);
  const int a = required_words(d);
  if (d.materials && d.bracketed)
    return head + std::to_string(a) + " or " + std::to_string(a + 2) + " values (" + syntax(d, false, true) + ")" +
           got;
  if (d.materials)
    return head + std::to_string(a) + " values (" + syntax(d) + ": both partners of one material) or " +
           std::to_string(a + 2) + " values (" + syntax(d, true) + ")" + got;
  const int b = all_words(d);
  return head + std::to_string(a) + (b != a ? " or " + std::to_string(b) : std::string()) + " value" +
         (b == 1 ? "" : "s") + " (" + syntax(d) + ")" + got;
}

// The number in messages: 10 significant digits, as the LAMMPS adapters print.
inline std::string number_text(double v) { return checks::number(v, 10); }

// The name of value k in messages: "normal thornton NU (Poisson ratio)".
inline std::string value_name(const Description& d, int k) {
  const Parameter& p = parameter(d, k);
  const bool m = !d.terse || p.meaning_in_messages;
  return std::string(d.kind) + " " + d.name + " " + p.name + (m ? std::string(" (") + p.meaning + ")" : "");
}

// Is value v of parameter p, named `what` in messages, inside its range (bounds other than
// at_least)? "" if so, else the message.
inline std::string check_bound(const Parameter& p, const std::string& what, double v) {
  const std::string w = what + " = " + number_text(v);
  switch (p.bound) {
    case Bound::positive:
      return v > 0.0 ? "" : w + " must be > 0";
    case Bound::non_negative:
      return v >= 0.0 ? "" : w + " must be >= 0";
    case Bound::restitution:
      return checks::restitution_ok(v) ? "" : w + " is outside the allowed range (0, 1]";
    case Bound::poisson:
      return checks::poisson_ok(v) ? "" : w + " is outside the allowed range (-1, 0.5]";
    default:
      return "";
  }
}

// Is value k of v (the expanded list) inside its range? "" if so, else the message. An at_least
// bound reads the value it refers to, which comes earlier in the list.
inline std::string check_value(const Description& d, const double* v, int k) {
  const Parameter& p = parameter(d, k);
  if (p.bound != Bound::at_least) return check_bound(p, value_name(d, k), v[k]);
  const int r = (d.materials ? MATERIAL_VALUES : 0) + p.ref;
  return v[k] >= v[r] ? ""
                      : value_name(d, k) + " = " + number_text(v[k]) + " is outside the allowed range [" +
                            parameter(d, r).name + ", inf) = [" + number_text(v[r]) + ", inf)";
}

// The first value of v[0 .. value_count) outside its range, as a message; "" if all are allowed.
inline std::string check(const Description& d, const double* v) {
  for (int k = 0; k < value_count(d); ++k) {
    std::string m = check_value(d, v, k);
    if (!m.empty()) return m;
  }
  return "";
}

// Expand n input words (already numbers) to the value list: the second material copies the first
// when only one is given; left-out optional values take their fallback. out has value_count(d).
inline void expand(const Description& d, const double* words, int n, double* out) {
  for (int k = 0; k < value_count(d); ++k) out[k] = parameter(d, k).fallback;
  for (int k = 0; k < n; ++k) out[value_index(d, n, k)] = words[k];
  if (d.materials && n == required_words(d)) out[2] = out[0], out[3] = out[1];
}

}  // namespace law
}  // namespace tdem
