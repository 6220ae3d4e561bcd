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

#include <cstdio>

namespace LAMMPS_NS {

class FixTDEMMixingDepth : public Fix {
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
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  tdem::grate::mixing::host::DepthConfig cfg;
  static constexpr int stride = tdem::grate::mixing::host::kPeratomCols + tdem::grate::mixing::host::kStateWidth;
  int nmax_rows;
  double **store;  // per atom: output (4) + state (9)
  std::vector<double> table;
  tdem::grate::mixing::host::RegionSums rs;
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
