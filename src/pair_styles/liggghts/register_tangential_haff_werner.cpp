// SPDX-License-Identifier: GPL-2.0-or-later
// tangential tdem/haff_werner with the normal models tdem/lsd, tdem/hertz, tdem/walton_braun, tdem/thornton, tdem/power_law,
// tdem/extended_linear, tdem/extended_hertz, stock hertz and stock hooke.
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_tangential_haff_werner() {
  register_combo<TDEM_LSD, TDEM_HAFF_WERNER>();
  register_combo<TDEM_HERTZ, TDEM_HAFF_WERNER>();
  register_combo<HERTZ, TDEM_HAFF_WERNER>();
  register_combo<HOOKE, TDEM_HAFF_WERNER>();
  register_combo<TDEM_WALTON_BRAUN, TDEM_HAFF_WERNER>();
  register_combo<TDEM_THORNTON, TDEM_HAFF_WERNER>();
  register_combo<TDEM_POWER_LAW, TDEM_HAFF_WERNER>();
  register_combo<TDEM_EXTENDED_LINEAR, TDEM_HAFF_WERNER>();
  register_combo<TDEM_EXTENDED_HERTZ, TDEM_HAFF_WERNER>();
}
}  // namespace tdem::liggghts::detail
