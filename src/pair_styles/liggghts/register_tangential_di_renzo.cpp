// SPDX-License-Identifier: GPL-2.0-or-later
// tangential tdem/di_renzo with the normal models tdem/lsd, tdem/hertz, stock hertz and stock hooke.
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_tangential_di_renzo() {
  register_combo<TDEM_LSD, TDEM_DI_RENZO>();
  register_combo<TDEM_HERTZ, TDEM_DI_RENZO>();
  register_combo<HERTZ, TDEM_DI_RENZO>();
  register_combo<HOOKE, TDEM_DI_RENZO>();
}
}  // namespace tdem::liggghts::detail
