// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_stock_hertz() {
  register_combo<HERTZ, TDEM_CUNDALL_STRACK>();
  register_combo<HERTZ_STIFFNESS, TDEM_CUNDALL_STRACK>();
}
}  // namespace tdem::liggghts::detail
