// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'clump' (fix tdem/clump).
#include "tdem_lammps_styles.h"

#include "fix_tdem_clump.h"

namespace tdem_lammps {

TDEM_LAMMPS_MODULE(clump_styles, fix_entry<LAMMPS_NS::FixTDEMClump>("tdem/clump", "tdem fix style tdem/clump (rigid multi-sphere clumps)"))

}  // namespace tdem_lammps
