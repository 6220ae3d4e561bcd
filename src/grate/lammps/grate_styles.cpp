// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'grate' (fix tdem/grate).
#include "tdem_lammps_styles.h"

#include "fix_tdem_grate.h"

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {
Fix *create_fix_tdem_grate(LAMMPS *lmp, int narg, char **arg)
{
  return new FixTDEMGrate(lmp, narg, arg);
}

const StyleEntry table[] = {
    {StyleKind::fix, "tdem/grate",
     "tdem fix style tdem/grate (stepped grate of fixed and moving bar rows, tdem laws)",
     (void *) &create_fix_tdem_grate},
    {StyleKind::pair, nullptr, nullptr, nullptr}};
}  // namespace

const StyleEntry *grate_styles()
{
  return table;
}

}  // namespace tdem_lammps
