// SPDX-License-Identifier: GPL-2.0-or-later
// tangential tdem/walton_braun with the normal models tdem/lsd, tdem/hertz, stock hertz and stock hooke.
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_tangential_walton_braun() {
  register_combo<TDEM_LSD, TDEM_WALTON_BRAUN_T>();
  register_combo<TDEM_HERTZ, TDEM_WALTON_BRAUN_T>();
  register_combo<HERTZ, TDEM_WALTON_BRAUN_T>();
  register_combo<HOOKE, TDEM_WALTON_BRAUN_T>();
}
}  // namespace tdem::liggghts::detail
