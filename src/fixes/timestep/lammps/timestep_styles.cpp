// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'timestep' (fix tdem/timestep).
#include "tdem_lammps_styles.h"

#include "fix_tdem_timestep.h"

namespace tdem_lammps {

TDEM_LAMMPS_MODULE(timestep_styles, fix_entry<LAMMPS_NS::FixTDEMTimestep>("tdem/timestep", "tdem fix style tdem/timestep (time-step advice and check)"))

}  // namespace tdem_lammps
