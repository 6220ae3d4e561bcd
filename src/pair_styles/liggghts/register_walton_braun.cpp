// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_walton_braun() {
  register_combo<TDEM_WALTON_BRAUN, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_WALTON_BRAUN, TANGENTIAL_HISTORY>();
  register_combo<TDEM_WALTON_BRAUN, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
