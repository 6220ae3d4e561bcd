// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: input checks shared by the contact laws, the collision solutions, the advice and the tools.
// Messages name the quantity, the value and the allowed range; the adapters forward them to the
// host's error path. One rule per quantity: e in (0, 1], Poisson's ratio in (-1, 0.5].
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tdem {
namespace checks {

// A number in messages, with `digits` significant digits (%.9g by default).
inline std::string number(double v, int digits = 9) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
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

inline bool restitution_ok(double e) { return e > 0.0 && e <= 1.0; }
inline void restitution(double e) {
  if (!restitution_ok(e)) fail("coefficient of restitution e", e, "(0, 1]");
}

// Poisson's ratio of an isotropic elastic solid: (-1, 0.5] (0.5: incompressible).
inline bool poisson_ok(double nu) { return nu > -1.0 && nu <= 0.5; }
inline void poisson(const char* what, double nu) {
  if (!poisson_ok(nu)) fail(what, nu, "(-1, 0.5]");
}

}  // namespace checks
}  // namespace tdem
