// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_stock_hooke() {
  register_combo<HOOKE, TDEM_CUNDALL_STRACK>();
  register_combo<HOOKE_STIFFNESS, TDEM_CUNDALL_STRACK>();
}
}  // namespace tdem::liggghts::detail
