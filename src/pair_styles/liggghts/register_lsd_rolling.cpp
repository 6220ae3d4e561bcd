// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
// Rolling friction models read sidata.kn / sidata.kt, which model tdem/lsd provides.
void register_lsd_rolling() {
  register_combo<TDEM_LSD, TDEM_CUNDALL_STRACK, COHESION_OFF, ROLLING_CDT>();
  register_combo<TDEM_LSD, TDEM_CUNDALL_STRACK, COHESION_OFF, ROLLING_EPSD2>();
}
}  // namespace tdem::liggghts::detail
