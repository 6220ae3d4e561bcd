// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/timestep, the time-step advice of src/fixes/timestep/timestep.h for the laws
// in use (issue 8).
//
//   fix ID group tdem/timestep [vmax V] [check off|warn|stop] [every N] [fraction F] [scheme NAME]
//
// At set-up: one row per type pair of pair tdem/gran (or stock gran/hooke/history,
// gran/hertz/history) and per fix tdem/wall/gran and type, with m* and R* of the lightest and
// smallest particles of those types in the group; the table of k_max, zeta, dt_c of the scheme
// (fix tdem/integrate's or `scheme`; velocity_verlet = nve/sphere by default), Rayleigh time,
// contact time at vmax, steps per contact, dt/dt_c and the advised step; then check() (warn:
// a warning, stop: an error). Every N steps: the same from 2 x the largest particle speed and
// the largest overlap in the pair's neighbour list. Global vector (intensive): dt_c now, steps
// per contact now, dt / dt_c now. See docs/timestep.md.

#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/timestep,FixTDEMTimestep);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_TIMESTEP_H
#define TDEM_LMP_FIX_TDEM_TIMESTEP_H

#include "fix.h"

#include "fixes/timestep/host_table.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixTDEMTimestep : public Fix {
 public:
  FixTDEMTimestep(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_vector(int) override;

 private:
  tdem::advice::host::FixState st;  // options, scheme, rows, vector (shared with LIGGGHTS)

  void build_rows(double v_setup);
  void run_check(const char *when);
  std::string where() const;
};

}  // namespace LAMMPS_NS

#endif
#endif
