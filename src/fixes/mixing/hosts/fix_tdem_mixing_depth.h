// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS and LIGGGHTS (one source; the engine differences in src/fixes/<host>/tdem_fix_host.h):
//   fix ID group tdem/mixing/depth every N column C bins AXIS LO HI NB
//                  (grate FIXID | floor H) [normalise yes|no] [up AXIS] [lateral AXIS|none] [file NAME]
// Every N steps the normalised depth D of every atom of the group (mixing.h particle_depths) is
// accumulated along the trajectories (per-atom state that migrates and goes to restarts) and per bin.
// Per-atom array: D now, Dbar, sigma_D, Q'. Global array (NB + 1) x 6 (last row: all bins): count,
// mean D, mean sigma_D, Q'_bin, sigma of the D samples, samples. Scalar: Q' of all bins.
#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/mixing/depth,FixTDEMMixingDepth);
// clang-format on
#else

#ifndef TDEM_FIX_TDEM_MIXING_DEPTH_H
#define TDEM_FIX_TDEM_MIXING_DEPTH_H

#include "fix.h"
#include "tdem_fix_host.h"
#include "fixes/mixing/mixing_host.h"
#include "pair_styles/per_atom_rows.h"

#include <cstdio>

namespace LAMMPS_NS {

class FixTDEMMixingDepth : public tdem::host::PerAtomRows<Fix> {
 public:
  FixTDEMMixingDepth(class LAMMPS *, int, char **);
  ~FixTDEMMixingDepth() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_array(int, int) override;

  double memory_usage() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  tdem::grate::mixing::host::DepthConfig cfg;
  static constexpr int stride = tdem::grate::mixing::host::kPeratomCols + tdem::grate::mixing::host::kStateWidth;
  // rows_ (tdem::host::PerAtomRows): per atom the output (4) + the state (9)
  std::vector<double> table;
  tdem::grate::mixing::host::RegionSums rs;
  tdem::grate::mixing::host::HaloCount held;  // atoms of the last snapshot on this rank
  long snapshot;
  bigint last_step;
  Fix *grate_fix;
  FILE *fp;
  double time_offset;
  int offset_pending;
  double saved_time;
  bigint saved_step;
  double sim_time() const;
  void take_snapshot();
  std::string ctx() const;
};

}  // namespace LAMMPS_NS

#endif
#endif
