// SPDX-License-Identifier: GPL-2.0-or-later
// surface tdem/clump (multiple-contact correction of fix tdem/clump), part b: tdem/continuous_potential,
// tdem/power_law, tdem/extended_linear, tdem/extended_hertz and stock hooke/stiffness, hertz.
#include "register_combo.h"
#include "surface_model_tdem_clump.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
namespace {
template <int N, int T>
void reg() {
  register_combo<N, T, COHESION_OFF, ROLLING_OFF, TDEM_CLUMP_SURFACE>();
}
}  // namespace
void register_clump_b() {
  reg<TDEM_CONTINUOUS_POTENTIAL, TDEM_CUNDALL_STRACK>();
  reg<TDEM_CONTINUOUS_POTENTIAL, TANGENTIAL_HISTORY>();
  reg<TDEM_CONTINUOUS_POTENTIAL, TANGENTIAL_OFF>();
  reg<TDEM_POWER_LAW, TDEM_CUNDALL_STRACK>();
  reg<TDEM_POWER_LAW, TANGENTIAL_HISTORY>();
  reg<TDEM_POWER_LAW, TANGENTIAL_OFF>();
  reg<TDEM_EXTENDED_LINEAR, TDEM_CUNDALL_STRACK>();
  reg<TDEM_EXTENDED_LINEAR, TANGENTIAL_HISTORY>();
  reg<TDEM_EXTENDED_LINEAR, TANGENTIAL_OFF>();
  reg<TDEM_EXTENDED_HERTZ, TDEM_CUNDALL_STRACK>();
  reg<TDEM_EXTENDED_HERTZ, TANGENTIAL_HISTORY>();
  reg<TDEM_EXTENDED_HERTZ, TANGENTIAL_OFF>();
  reg<HOOKE_STIFFNESS, TANGENTIAL_HISTORY>();
  reg<HOOKE_STIFFNESS, TANGENTIAL_OFF>();
  reg<HERTZ, TANGENTIAL_HISTORY>();
  reg<HERTZ, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
