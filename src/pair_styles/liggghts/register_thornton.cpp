// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_thornton() {
  register_combo<TDEM_THORNTON, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_THORNTON, TANGENTIAL_HISTORY>();
  register_combo<TDEM_THORNTON, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
