// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_lsd_b() {
  register_combo<TDEM_LSD, TANGENTIAL_NO_HISTORY>();
  register_combo<TDEM_LSD, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
