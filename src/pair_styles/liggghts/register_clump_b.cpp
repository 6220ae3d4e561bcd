// SPDX-License-Identifier: GPL-2.0-or-later
// surface tdem/clump (multiple-contact correction of fix tdem/clump), part b: tdem/continuous_potential,
// tdem/power_law, tdem/extended_linear, tdem/extended_hertz and stock hooke/stiffness, hertz.
#include "register_combo.h"
#include "surface_model_tdem_clump.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_clump_b() {
  register_clump_combo<TDEM_CONTINUOUS_POTENTIAL, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_CONTINUOUS_POTENTIAL, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_CONTINUOUS_POTENTIAL, TANGENTIAL_OFF>();
  register_clump_combo<TDEM_POWER_LAW, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_POWER_LAW, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_POWER_LAW, TANGENTIAL_OFF>();
  register_clump_combo<TDEM_EXTENDED_LINEAR, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_EXTENDED_LINEAR, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_EXTENDED_LINEAR, TANGENTIAL_OFF>();
  register_clump_combo<TDEM_EXTENDED_HERTZ, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_EXTENDED_HERTZ, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_EXTENDED_HERTZ, TANGENTIAL_OFF>();
  register_clump_combo<HOOKE_STIFFNESS, TANGENTIAL_HISTORY>();
  register_clump_combo<HOOKE_STIFFNESS, TANGENTIAL_OFF>();
  register_clump_combo<HERTZ, TANGENTIAL_HISTORY>();
  register_clump_combo<HERTZ, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
