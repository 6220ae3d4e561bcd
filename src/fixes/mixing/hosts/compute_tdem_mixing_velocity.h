// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS and LIGGGHTS (one source; the engine differences in src/fixes/<host>/tdem_fix_host.h):
//   compute ID group tdem/mixing/velocity radius R_V bins AXIS LO HI N
//                  [periodic AXIS ...] [exclude GROUP]          (docs/mixing_hosts.md)
// Global array (N + 1) x 5: per bin (last row: all bins) count, p_x, p_y, p_z, P' of the current step;
// global scalar: P' of all bins. Neighbours are all atoms of the group; `exclude` leaves a group out
// of the statistics (it still counts as neighbour).
#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(tdem/mixing/velocity,ComputeTDEMMixingVelocity);
// clang-format on
#else

#ifndef TDEM_COMPUTE_TDEM_MIXING_VELOCITY_H
#define TDEM_COMPUTE_TDEM_MIXING_VELOCITY_H

#include "compute.h"
#include "tdem_fix_host.h"
#include "fixes/mixing/mixing_host.h"

namespace LAMMPS_NS {

class ComputeTDEMMixingVelocity : public Compute {
 public:
  ComputeTDEMMixingVelocity(class LAMMPS *, TDEM_COMPUTE_CTOR_DECL);
  ~ComputeTDEMMixingVelocity() override;
  void init() override;
  double compute_scalar() override;
  void compute_array() override;

 private:
  tdem::grate::mixing::host::VelocityConfig cfg;
  int excludebit;
  double **table;
  tdem::grate::mixing::host::HaloCount held;  // atoms of the last evaluation on this rank
  void evaluate();
};

}  // namespace LAMMPS_NS

#endif
#endif
