// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: fix ID group tdem/mixing/depth every N column C bins AXIS LO HI NB
//                  (grate FIXID | floor H) [normalise yes|no] [up AXIS] [lateral AXIS|none] [file NAME]
// Every N steps the normalised depth D of every atom of the group (mixing.h particle_depths) is
// accumulated along the trajectories (per-atom state that migrates and goes to restarts) and per bin.
// Per-atom array: D now, Dbar, sigma_D, Q'. Global array (NB + 1) x 6 (last row: all bins): count,
// mean D, mean sigma_D, Q'_bin, sigma of the D samples, samples. Scalar: Q' of all bins.
#pragma once

#include "fix.h"
#include "grate/mixing_host.h"

#include <cstdio>

namespace LAMMPS_NS {

class FixTdemMixingDepth : public Fix {
 public:
  FixTdemMixingDepth(class LAMMPS *, int, char **);
  virtual ~FixTdemMixingDepth();
  virtual int setmask();
  virtual void init();
  virtual void setup(int);
  virtual void end_of_step();
  virtual double compute_scalar();
  virtual double compute_array(int, int);

  virtual double memory_usage();
  virtual void grow_arrays(int);
  virtual void copy_arrays(int, int, int);
  virtual void set_arrays(int);
  virtual int pack_exchange(int, double *);
  virtual int unpack_exchange(int, double *);
  virtual int pack_restart(int, double *);
  virtual void unpack_restart(int, int);
  virtual int maxsize_restart();
  virtual int size_restart(int);
  virtual void write_restart(FILE *);
  virtual void restart(char *);

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
