// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'mixing' (compute tdem/mixing/velocity,
// fix tdem/mixing/depth; docs/mixing_hosts.md).
#include "tdem_lammps_styles.h"

#include "compute_tdem_mixing_velocity.h"
#include "fix_tdem_mixing_depth.h"

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {
Compute *create_compute_mixing_velocity(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeTDEMMixingVelocity(lmp, narg, arg);
}
Fix *create_fix_mixing_depth(LAMMPS *lmp, int narg, char **arg)
{
  return new FixTDEMMixingDepth(lmp, narg, arg);
}
const StyleEntry table[] = {
    {StyleKind::compute, "tdem/mixing/velocity", "tdem compute style tdem/mixing/velocity (velocity-based mixing P')",
     (void *) &create_compute_mixing_velocity},
    {StyleKind::fix, "tdem/mixing/depth", "tdem fix style tdem/mixing/depth (trajectory-based mixing D, Q')",
     (void *) &create_fix_mixing_depth},
    {StyleKind::pair, nullptr, nullptr, nullptr}};
}  // namespace

const StyleEntry *mixing_styles()
{
  return table;
}

}  // namespace tdem_lammps
