// SPDX-License-Identifier: GPL-2.0-or-later
// surface tdem/clump (multiple-contact correction of fix tdem/clump), part a: tdem/lsd, tdem/hertz,
// tdem/walton_braun, tdem/thornton and stock hooke.
#include "register_combo.h"
#include "surface_model_tdem_clump.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
void register_clump_a() {
  register_clump_combo<TDEM_LSD, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_LSD, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_LSD, TANGENTIAL_NO_HISTORY>();
  register_clump_combo<TDEM_LSD, TANGENTIAL_OFF>();
  register_clump_combo<TDEM_HERTZ, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_HERTZ, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_HERTZ, TANGENTIAL_OFF>();
  register_clump_combo<TDEM_WALTON_BRAUN, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_WALTON_BRAUN, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_WALTON_BRAUN, TANGENTIAL_OFF>();
  register_clump_combo<TDEM_THORNTON, TDEM_CUNDALL_STRACK>();
  register_clump_combo<TDEM_THORNTON, TANGENTIAL_HISTORY>();
  register_clump_combo<TDEM_THORNTON, TANGENTIAL_OFF>();
  register_clump_combo<HOOKE, TANGENTIAL_HISTORY>();
  register_clump_combo<HOOKE, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
