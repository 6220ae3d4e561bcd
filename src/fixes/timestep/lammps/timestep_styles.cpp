// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'timestep' (fix tdem/timestep).
#include "tdem_lammps_styles.h"

#include "fix_tdem_timestep.h"

namespace tdem_lammps {

const StyleEntry *timestep_styles()
{
  static const StyleEntry table[] = {
      {StyleKind::fix, "tdem/timestep", "tdem fix style tdem/timestep (time-step advice and check)",
       (void *) &create_fix<LAMMPS_NS::FixTDEMTimestep>},
      {}};
  return table;
}

}  // namespace tdem_lammps
