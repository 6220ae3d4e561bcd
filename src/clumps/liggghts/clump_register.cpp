// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'clump'.
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_clump(LAMMPS_NS::LAMMPS* lmp) { (void)lmp; }

}  // namespace liggghts
}  // namespace tdem
