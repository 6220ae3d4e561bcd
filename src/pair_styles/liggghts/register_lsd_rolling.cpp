// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
// The stock rolling friction models read sidata.kn / sidata.kt, which model tdem/lsd provides;
// rolling_friction tdem/sds (rolling_model_tdem_sds.h) has its own properties.
void register_lsd_rolling() {
  register_combo<TDEM_LSD, TDEM_CUNDALL_STRACK, COHESION_OFF, ROLLING_CDT>();
  register_combo<TDEM_LSD, TDEM_CUNDALL_STRACK, COHESION_OFF, ROLLING_EPSD2>();
  register_combo<TDEM_LSD, TDEM_CUNDALL_STRACK, COHESION_OFF, TDEM_SDS>();
}
}  // namespace tdem::liggghts::detail
