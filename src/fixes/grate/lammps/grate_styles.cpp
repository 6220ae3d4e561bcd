// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'grate' (fix tdem/grate).
#include "tdem_lammps_styles.h"

#include "fix_tdem_grate.h"

namespace tdem_lammps {

TDEM_LAMMPS_MODULE(grate_styles, fix_entry<LAMMPS_NS::FixTDEMGrate>("tdem/grate",
                                    "tdem fix style tdem/grate (stepped grate of fixed and moving bar rows, tdem laws)"))

}  // namespace tdem_lammps
