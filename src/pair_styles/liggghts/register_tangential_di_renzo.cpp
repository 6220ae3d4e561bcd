// SPDX-License-Identifier: GPL-2.0-or-later
// tangential tdem/di_renzo with the normal models tdem/lsd, tdem/hertz, tdem/walton_braun, tdem/thornton, tdem/power_law,
// tdem/extended_linear, tdem/extended_hertz, stock hertz and stock hooke.
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_tangential_di_renzo() {
  register_combo<TDEM_LSD, TDEM_DI_RENZO>();
  register_combo<TDEM_HERTZ, TDEM_DI_RENZO>();
  register_combo<HERTZ, TDEM_DI_RENZO>();
  register_combo<HOOKE, TDEM_DI_RENZO>();
  register_combo<TDEM_WALTON_BRAUN, TDEM_DI_RENZO>();
  register_combo<TDEM_THORNTON, TDEM_DI_RENZO>();
  register_combo<TDEM_POWER_LAW, TDEM_DI_RENZO>();
  register_combo<TDEM_EXTENDED_LINEAR, TDEM_DI_RENZO>();
  register_combo<TDEM_EXTENDED_HERTZ, TDEM_DI_RENZO>();
}
}  // namespace tdem::liggghts::detail
