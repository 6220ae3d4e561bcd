// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'clump' (fix tdem/clump).
#include "tdem_lammps_styles.h"

#include "fix_tdem_clump.h"

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {
Fix *create_fix_tdem_clump(LAMMPS *lmp, int narg, char **arg)
{
  return new FixTDEMClump(lmp, narg, arg);
}

const StyleEntry table[] = {
    {StyleKind::fix, "tdem/clump", "tdem fix style tdem/clump (rigid multi-sphere clumps)",
     (void *) &create_fix_tdem_clump},
    {StyleKind::pair, nullptr, nullptr, nullptr}};
}  // namespace

const StyleEntry *clump_styles()
{
  return table;
}

}  // namespace tdem_lammps
