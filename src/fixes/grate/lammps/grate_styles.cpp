// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'grate' (fix tdem/grate).
#include "tdem_lammps_styles.h"

#include "fix_tdem_grate.h"

namespace tdem_lammps {

const StyleEntry *grate_styles()
{
  static const StyleEntry table[] = {
      {StyleKind::fix, "tdem/grate",
       "tdem fix style tdem/grate (stepped grate of fixed and moving bar rows, tdem laws)",
       (void *) &create_fix<LAMMPS_NS::FixTDEMGrate>},
      {}};
  return table;
}

}  // namespace tdem_lammps
