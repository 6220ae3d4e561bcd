// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'mixing'.
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_mixing(LAMMPS_NS::LAMMPS* lmp) { (void)lmp; }

}  // namespace liggghts
}  // namespace tdem
