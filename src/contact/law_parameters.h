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
};

template <int N>
constexpr Description describe(const char* kind, const char* name, bool materials, const Parameter (&p)[N],
                               const HistorySlot* history, int history_size, bool bracketed = false) {
  return {kind, name, materials, p, N, history, history_size, bracketed};
}

// The material pair's four values (index 0..3 of a materials law's value list).
inline constexpr Parameter material_pair[4] = {
    {"E", "Young's modulus", "Pa", Bound::positive},
    {"NU", "Poisson ratio", "1", Bound::poisson},
    {"E2", "Young's modulus", "Pa", Bound::positive},
    {"NU2", "Poisson ratio", "1", Bound::poisson},
};
inline constexpr int MATERIAL_VALUES = 4;

// Values of the expanded list (materials first) and the smallest/largest number of input words.
inline int value_count(const Description& d) { return (d.materials ? MATERIAL_VALUES : 0) + d.count; }
inline int required_words(const Description& d) {
  int n = d.materials ? 2 : 0;
  for (int k = 0; k < d.count; ++k) n += d.params[k].optional ? 0 : 1;
  return n;
}
inline int all_words(const Description& d) { return (d.materials ? 2 : 0) + d.count; }
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

// "normal walton_braun needs 2 or 3 values (KL KUL [S]), got 1"
inline std::string count_message(const Description& d, int n) {
  const std::string head = std::string(d.kind) + " " + d.name + " needs ";
  const int a = required_words(d);
  if (d.materials && d.bracketed)
    return head + std::to_string(a) + " or " + std::to_string(a + 2) + " values (" + syntax(d, false, true) +
           "), got " + std::to_string(n);
  if (d.materials)
    return head + std::to_string(a) + " values (" + syntax(d) + ": both partners of one material) or " +
           std::to_string(a + 2) + " values (" + syntax(d, true) + "), got " + std::to_string(n);
  const int b = all_words(d);
  return head + std::to_string(a) + (b != a ? " or " + std::to_string(b) : std::string()) + " value" +
         (b == 1 ? "" : "s") + " (" + syntax(d) + "), got " + std::to_string(n);
}

// The number in messages: 10 significant digits, as the LAMMPS adapters print.
inline std::string number_text(double v) { return checks::number(v, 10); }

// The name of value k in messages: "normal thornton NU (Poisson ratio)".
inline std::string value_name(const Description& d, int k) {
  const Parameter& p = parameter(d, k);
  return std::string(d.kind) + " " + d.name + " " + p.name + " (" + p.meaning + ")";
}

// Is value k of v (the expanded list) inside its range? "" if so, else the message. An at_least
// bound reads the value it refers to, which comes earlier in the list.
inline std::string check_value(const Description& d, const double* v, int k) {
  const Parameter& p = parameter(d, k);
  const std::string what = value_name(d, k) + " = " + number_text(v[k]);
  switch (p.bound) {
    case Bound::any:
      return "";
    case Bound::positive:
      return v[k] > 0.0 ? "" : what + " must be > 0";
    case Bound::non_negative:
      return v[k] >= 0.0 ? "" : what + " must be >= 0";
    case Bound::restitution:
      return checks::restitution_ok(v[k]) ? "" : what + " is outside the allowed range (0, 1]";
    case Bound::poisson:
      return checks::poisson_ok(v[k]) ? "" : what + " is outside the allowed range (-1, 0.5]";
    case Bound::at_least: {
      const int r = (d.materials ? MATERIAL_VALUES : 0) + p.ref;
      return v[k] >= v[r] ? ""
                          : what + " is outside the allowed range [" + parameter(d, r).name + ", inf) = [" +
                                number_text(v[r]) + ", inf)";
    }
  }
  return "";
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
