// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: input checks shared by the normal laws. Messages name the quantity, the value and the
// allowed range; the adapters forward them to the host's error path.
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tdem {
namespace checks {

inline std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

[[noreturn]] inline void fail(const char* what, double v, const char* range) {
  throw std::domain_error(std::string(what) + " = " + number(v) + " is outside the allowed range " + range);
}

inline void positive(const char* what, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) fail(what, v, "(0, inf)");
}

inline void non_negative(const char* what, double v) {
  if (!(v >= 0.0) || !std::isfinite(v)) fail(what, v, "[0, inf)");
}

inline void restitution(double e) {
  if (!(e > 0.0 && e <= 1.0)) fail("coefficient of restitution e", e, "(0, 1]");
}

}  // namespace checks
}  // namespace tdem
