// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'clump' (fix tdem/clump).
#include "tdem_lammps_styles.h"

#include "fix_tdem_clump.h"

namespace tdem_lammps {

const StyleEntry *clump_styles()
{
  static const StyleEntry table[] = {
      {StyleKind::fix, "tdem/clump", "tdem fix style tdem/clump (rigid multi-sphere clumps)",
       (void *) &create_fix<LAMMPS_NS::FixTDEMClump>},
      {}};
  return table;
}

}  // namespace tdem_lammps
