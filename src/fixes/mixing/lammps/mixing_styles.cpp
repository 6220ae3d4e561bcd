// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'mixing' (compute tdem/mixing/velocity,
// fix tdem/mixing/depth; docs/mixing_hosts.md).
#include "tdem_lammps_styles.h"

#include "compute_tdem_mixing_velocity.h"
#include "fix_tdem_mixing_depth.h"

namespace tdem_lammps {

TDEM_LAMMPS_MODULE(mixing_styles, compute_entry<LAMMPS_NS::ComputeTDEMMixingVelocity>(
                       "tdem/mixing/velocity", "tdem compute style tdem/mixing/velocity (velocity-based mixing P')"),
                   fix_entry<LAMMPS_NS::FixTDEMMixingDepth>(
                       "tdem/mixing/depth", "tdem fix style tdem/mixing/depth (trajectory-based mixing D, Q')"))

}  // namespace tdem_lammps
