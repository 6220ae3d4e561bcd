// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'mixing' (compute tdem/mixing/velocity,
// fix tdem/mixing/depth; docs/mixing_hosts.md).
#include "compute_tdem_mixing_velocity.h"
#include "fix_tdem_mixing_depth.h"
#include "fixes/liggghts/style_maps.h"
#include "tdem_liggghts.h"

namespace tdem {
namespace liggghts {

void register_mixing(LAMMPS_NS::LAMMPS* lmp)
{
  add_fix_style(lmp, "tdem/mixing/depth", &create_fix<LAMMPS_NS::FixTDEMMixingDepth>);
  add_compute_style(lmp, "tdem/mixing/velocity", &create_compute<LAMMPS_NS::ComputeTDEMMixingVelocity>);
}

}  // namespace liggghts
}  // namespace tdem
