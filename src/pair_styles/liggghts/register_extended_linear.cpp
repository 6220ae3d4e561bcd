// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_extended_linear() {
  register_combo<TDEM_EXTENDED_LINEAR, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_EXTENDED_LINEAR, TANGENTIAL_HISTORY>();
  register_combo<TDEM_EXTENDED_LINEAR, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
