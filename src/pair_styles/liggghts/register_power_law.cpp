// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_power_law() {
  register_combo<TDEM_POWER_LAW, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_POWER_LAW, TANGENTIAL_HISTORY>();
  register_combo<TDEM_POWER_LAW, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
