// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'grate' (fix tdem/grate).
#include "fix_tdem_grate.h"
#include "fixes/liggghts/style_maps.h"
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_grate(LAMMPS_NS::LAMMPS* lmp) { add_fix_style(lmp, "tdem/grate", &create_fix<LAMMPS_NS::FixTDEMGrate>); }

}  // namespace liggghts
}  // namespace tdem
