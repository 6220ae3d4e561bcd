// SPDX-License-Identifier: GPL-2.0-or-later
// tangential tdem/linear_spring with the normal models tdem/lsd, tdem/hertz, tdem/walton_braun, tdem/thornton, tdem/power_law,
// tdem/extended_linear, tdem/extended_hertz, stock hertz and stock hooke.
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_tangential_linear_spring() {
  register_combo<TDEM_LSD, TDEM_LINEAR_SPRING>();
  register_combo<TDEM_HERTZ, TDEM_LINEAR_SPRING>();
  register_combo<HERTZ, TDEM_LINEAR_SPRING>();
  register_combo<HOOKE, TDEM_LINEAR_SPRING>();
  register_combo<TDEM_WALTON_BRAUN, TDEM_LINEAR_SPRING>();
  register_combo<TDEM_THORNTON, TDEM_LINEAR_SPRING>();
  register_combo<TDEM_POWER_LAW, TDEM_LINEAR_SPRING>();
  register_combo<TDEM_EXTENDED_LINEAR, TDEM_LINEAR_SPRING>();
  register_combo<TDEM_EXTENDED_HERTZ, TDEM_LINEAR_SPRING>();
}
}  // namespace tdem::liggghts::detail
