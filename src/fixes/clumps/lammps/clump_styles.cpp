// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'clump' (fix tdem/clump, fix tdem/correction).
#include "tdem_lammps_styles.h"

#include "fix_tdem_clump.h"
#include "fix_tdem_correction.h"

namespace tdem_lammps {

TDEM_LAMMPS_MODULE(clump_styles,
                   fix_entry<LAMMPS_NS::FixTDEMClump>("tdem/clump", "tdem fix style tdem/clump (rigid multi-sphere clumps)"),
                   fix_entry<LAMMPS_NS::FixTDEMCorrection>(
                       "tdem/correction", "tdem fix style tdem/correction (multiple-contact correction of other body fixes)"))

}  // namespace tdem_lammps
