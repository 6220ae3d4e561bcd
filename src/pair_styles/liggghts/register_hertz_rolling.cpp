// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
// model tdem/hertz with rolling resistance: the stock epsd2 (its stiffness from sidata.kt, which
// tdem/hertz sets) and tdem/sds, with the Cundall-Strack and the Mindlin-Deresiewicz tangential laws.
void register_hertz_rolling() {
  register_combo<TDEM_HERTZ, TDEM_CUNDALL_STRACK, COHESION_OFF, ROLLING_EPSD2>();
  register_combo<TDEM_HERTZ, TDEM_CUNDALL_STRACK, COHESION_OFF, TDEM_SDS>();
  register_combo<TDEM_HERTZ, TDEM_MINDLIN_DERESIEWICZ, COHESION_OFF, ROLLING_EPSD2>();
  register_combo<TDEM_HERTZ, TDEM_MINDLIN_DERESIEWICZ, COHESION_OFF, TDEM_SDS>();
}
}  // namespace tdem::liggghts::detail
