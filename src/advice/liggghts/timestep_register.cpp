// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'timestep'.
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_timestep(LAMMPS_NS::LAMMPS* lmp) { (void)lmp; }

}  // namespace liggghts
}  // namespace tdem
