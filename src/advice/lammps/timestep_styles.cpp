// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'timestep' (fix tdem/timestep).
#include "tdem_lammps_styles.h"

#include "fix_tdem_timestep.h"

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {
Fix *create_fix_tdem_timestep(LAMMPS *lmp, int narg, char **arg)
{
  return new FixTDEMTimestep(lmp, narg, arg);
}
const StyleEntry table[] = {
    {StyleKind::fix, "tdem/timestep", "tdem fix style tdem/timestep (time-step advice and check)",
     (void *) &create_fix_tdem_timestep},
    {StyleKind::pair, nullptr, nullptr, nullptr}};
}  // namespace

const StyleEntry *timestep_styles()
{
  return table;
}

}  // namespace tdem_lammps
