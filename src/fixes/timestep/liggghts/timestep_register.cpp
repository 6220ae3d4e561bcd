// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'timestep' (fix tdem/timestep).
#include "fix_tdem_timestep.h"
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_timestep(LAMMPS_NS::LAMMPS* lmp) { register_timestep_fix(lmp); }

}  // namespace liggghts
}  // namespace tdem
