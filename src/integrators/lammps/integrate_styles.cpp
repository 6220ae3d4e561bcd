// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the fix tdem/integrate (always built).
#include "tdem_lammps_styles.h"

#include "fix_tdem_integrate.h"

namespace tdem_lammps {

const StyleEntry *integrate_styles()
{
  static const StyleEntry table[] = {
      {StyleKind::fix, "tdem/integrate", "tdem fix style tdem/integrate (time integration schemes)",
       (void *) &create_fix<LAMMPS_NS::FixTDEMIntegrate>},
      {}};
  return table;
}

}  // namespace tdem_lammps
