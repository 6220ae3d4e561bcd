// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'mixing' (compute tdem/mixing/velocity,
// fix tdem/mixing/depth; docs/mixing_hosts.md).
#include "tdem_lammps_styles.h"

#include "compute_tdem_mixing_velocity.h"
#include "fix_tdem_mixing_depth.h"

namespace tdem_lammps {

const StyleEntry *mixing_styles()
{
  static const StyleEntry table[] = {
      {StyleKind::compute, "tdem/mixing/velocity",
       "tdem compute style tdem/mixing/velocity (velocity-based mixing P')",
       (void *) &create_compute<LAMMPS_NS::ComputeTDEMMixingVelocity>},
      {StyleKind::fix, "tdem/mixing/depth", "tdem fix style tdem/mixing/depth (trajectory-based mixing D, Q')",
       (void *) &create_fix<LAMMPS_NS::FixTDEMMixingDepth>},
      {}};
  return table;
}

}  // namespace tdem_lammps
