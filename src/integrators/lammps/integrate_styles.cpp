// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the fix tdem/integrate (always built).
#include "tdem_lammps_styles.h"

#include "fix_tdem_integrate.h"

namespace tdem_lammps {

TDEM_LAMMPS_MODULE(integrate_styles, fix_entry<LAMMPS_NS::FixTDEMIntegrate>("tdem/integrate", "tdem fix style tdem/integrate (time integration schemes)"))

}  // namespace tdem_lammps
