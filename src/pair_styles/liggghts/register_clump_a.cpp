// SPDX-License-Identifier: GPL-2.0-or-later
// surface tdem/clump (multiple-contact correction of fix tdem/clump), part a: tdem/lsd, tdem/hertz,
// tdem/walton_braun, tdem/thornton and stock hooke.
#include "register_combo.h"
#include "surface_model_tdem_clump.h"
namespace tdem::liggghts::detail {
using namespace LIGGGHTS::ContactModels;
namespace {
template <int N, int T>
void reg() {
  register_combo<N, T, COHESION_OFF, ROLLING_OFF, TDEM_CLUMP_SURFACE>();
}
}  // namespace
void register_clump_a() {
  reg<TDEM_LSD, TDEM_CUNDALL_STRACK>();
  reg<TDEM_LSD, TANGENTIAL_HISTORY>();
  reg<TDEM_LSD, TANGENTIAL_NO_HISTORY>();
  reg<TDEM_LSD, TANGENTIAL_OFF>();
  reg<TDEM_HERTZ, TDEM_CUNDALL_STRACK>();
  reg<TDEM_HERTZ, TANGENTIAL_HISTORY>();
  reg<TDEM_HERTZ, TANGENTIAL_OFF>();
  reg<TDEM_WALTON_BRAUN, TDEM_CUNDALL_STRACK>();
  reg<TDEM_WALTON_BRAUN, TANGENTIAL_HISTORY>();
  reg<TDEM_WALTON_BRAUN, TANGENTIAL_OFF>();
  reg<TDEM_THORNTON, TDEM_CUNDALL_STRACK>();
  reg<TDEM_THORNTON, TANGENTIAL_HISTORY>();
  reg<TDEM_THORNTON, TANGENTIAL_OFF>();
  reg<HOOKE, TANGENTIAL_HISTORY>();
  reg<HOOKE, TANGENTIAL_OFF>();
}
}  // namespace tdem::liggghts::detail
