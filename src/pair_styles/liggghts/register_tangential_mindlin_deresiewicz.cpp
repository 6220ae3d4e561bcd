// SPDX-License-Identifier: GPL-2.0-or-later
// tangential tdem/mindlin_deresiewicz with the normal models tdem/lsd, tdem/hertz, tdem/walton_braun, tdem/thornton, tdem/power_law,
// tdem/extended_linear, tdem/extended_hertz, stock hertz and stock hooke.
#include "register_combo.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_tangential_mindlin_deresiewicz() {
  register_combo<TDEM_LSD, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<TDEM_HERTZ, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<HERTZ, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<HOOKE, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<TDEM_WALTON_BRAUN, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<TDEM_THORNTON, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<TDEM_POWER_LAW, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<TDEM_EXTENDED_LINEAR, TDEM_MINDLIN_DERESIEWICZ>();
  register_combo<TDEM_EXTENDED_HERTZ, TDEM_MINDLIN_DERESIEWICZ>();
}
}  // namespace tdem::liggghts::detail
