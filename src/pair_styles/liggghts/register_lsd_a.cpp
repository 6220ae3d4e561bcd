// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_lsd_a() {
  register_combo<TDEM_LSD, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_LSD, TANGENTIAL_HISTORY>();
}
}  // namespace tdem::liggghts::detail
