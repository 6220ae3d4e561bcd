// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the dispatcher from a contact's law to the compile-time path of a contact loop
// (pair tdem/gran, fix tdem/wall/gran, fix tdem/grate); see tdem_lammps_law.h (which includes this
// header at its end).
#pragma once

#include "tdem_lammps_law.h"

#include <utility>

namespace tdem_lammps {

// The path of the k-th unit: run<MODE_UNIT + k, -1, -1>().
template <class F, int... K>
inline void dispatch_unit(int k, F &f, std::integer_sequence<int, K...>) {
  static_cast<void>(((k == K ? (f.template run<MODE_UNIT + K, -1, -1>(), true) : false) || ...));
}

// Dispatch helper: calls F.template run<M,E,S>() for the combination (all compile-time; the
// laws other than lsd with the law fixed at compile time and end, slip read at run time) or
// the run-time fallback run<-1,-1,-1>() when `uniform` is false.
// The tangential laws other than cundall_strack (one law for all type pairs) are fixed at
// compile time with the normal law read at run time: run<-1, -1, -1, TL>().
template <class F>
inline void dispatch(bool uniform, int mode, int end, int slip, int tlaw, F &&f) {
  if (tlaw != TLAW_CUNDALL_STRACK) {
    // the normal law fixed too for the most common ones: lsd stiffness (damping mass) and hertz
#define TDEM_LMP_TCASE(t)                                                                   \
  if (tlaw == t) {                                                                          \
    if (uniform && mode == MODE_STIFFNESS_MASS) return f.template run<MODE_STIFFNESS_MASS, -1, -1, t>(); \
    if (uniform && mode == MODE_HERTZ) return f.template run<MODE_HERTZ, -1, -1, t>();    \
    return f.template run<-1, -1, -1, t>();                                                 \
  }
    TDEM_LMP_TCASE(TLAW_HAFF_WERNER) TDEM_LMP_TCASE(TLAW_LINEAR_SPRING)
    TDEM_LMP_TCASE(TLAW_WALTON_BRAUN) TDEM_LMP_TCASE(TLAW_MINDLIN_DERESIEWICZ)
    TDEM_LMP_TCASE(TLAW_MINDLIN_NO_SLIP) TDEM_LMP_TCASE(TLAW_DI_RENZO)
#undef TDEM_LMP_TCASE
    return;  // not reached: tlaw is one of the laws above
  }
  if (!uniform) return f.template run<-1, -1, -1>();
#define TDEM_LMP_CASE(m, e, s) \
  if (mode == m && end == e && slip == s) return f.template run<m, e, s>();
  TDEM_LMP_CASE(0, 0, 0) TDEM_LMP_CASE(0, 0, 1) TDEM_LMP_CASE(0, 1, 0) TDEM_LMP_CASE(0, 1, 1)
  TDEM_LMP_CASE(1, 0, 0) TDEM_LMP_CASE(1, 0, 1) TDEM_LMP_CASE(1, 1, 0) TDEM_LMP_CASE(1, 1, 1)
  TDEM_LMP_CASE(2, 0, 0) TDEM_LMP_CASE(2, 0, 1) TDEM_LMP_CASE(2, 1, 0) TDEM_LMP_CASE(2, 1, 1)
#undef TDEM_LMP_CASE
#define TDEM_LMP_CASE(m) \
  if (mode == m) return f.template run<m, -1, -1>();
  TDEM_LMP_CASE(MODE_HERTZ) TDEM_LMP_CASE(MODE_EXT_LINEAR) TDEM_LMP_CASE(MODE_EXT_HERTZ)
  TDEM_LMP_CASE(MODE_CONT_POT)
#undef TDEM_LMP_CASE
  if (is_unit(mode)) return dispatch_unit(mode - MODE_UNIT, f, std::make_integer_sequence<int, NormalUnits::size>());
  f.template run<-1, -1, -1>();
}

}  // namespace tdem_lammps
