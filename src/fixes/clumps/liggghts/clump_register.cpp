// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'clump' (fix tdem/clump, fix tdem/correction).
#include "fix_tdem_clump.h"
#include "fix_tdem_correction.h"
#include "fixes/liggghts/style_maps.h"
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_clump(LAMMPS_NS::LAMMPS* lmp) {
  add_fix_style(lmp, "tdem/clump", &create_fix<LAMMPS_NS::FixTDEMClump>);
  add_fix_style(lmp, "tdem/correction", &create_fix<LAMMPS_NS::FixTDEMCorrection>);
}

}  // namespace liggghts
}  // namespace tdem
