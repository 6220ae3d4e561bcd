// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_continuous_potential() {
  register_combo<TDEM_CONTINUOUS_POTENTIAL, TDEM_CUNDALL_STRACK>();
  register_combo<TDEM_CONTINUOUS_POTENTIAL, TANGENTIAL_HISTORY>();
  register_combo<TDEM_CONTINUOUS_POTENTIAL, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
