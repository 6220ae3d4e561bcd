// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_extended_hertz() {
  register_combo<TDEM_EXTENDED_HERTZ, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_EXTENDED_HERTZ, TANGENTIAL_HISTORY>();
  register_combo<TDEM_EXTENDED_HERTZ, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
