// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/integrate, the time integrators of src/integrators/schemes.h as a
// replacement of fix nve/sphere (translation and rotation of spheres).
//
//   fix ID group tdem/integrate scheme NAME [rotation yes|no]
//
// NAME is one of tdem::integrators::scheme_names() (euler ... gear6). With `rotation no` only
// x and v are integrated (omega untouched, as fix nve); the default integrates omega with the
// same scheme (angular acceleration torque / (0.4 m r^2), as fix nve/sphere).
//
// Per atom the fix keeps one row of doubles: [0] a "started" flag (0 new, 1 started, 2 to be
// re-started after a change of the time step), then the history of the
// translation channel (Kernel<S, true>::history) and of the rotation channel
// (Kernel<S, false>::history). The row grows with the atom arrays, migrates with its atom
// (pack/unpack_exchange) and is written to and read from restart files (restart_peratom; the
// scheme and the time step of the history are in the fix's global restart record).
// Start-up: an atom without the flag is started (integrators::start, exact for constant
// acceleration) from its first complete force: at the first initial_integrate of a run for
// atoms that exist at the run start (after every fix has added its set-up force, so the start
// does not depend on the order of the fix commands), in final_integrate for atoms that appear
// during a run (fix pour, deposit ...). A later `run` continues the history; a change of the
// time step re-starts every atom with a warning. See docs/lammps/fix_tdem_integrate.md.

#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/integrate,FixTDEMIntegrate);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_INTEGRATE_H
#define TDEM_LMP_FIX_TDEM_INTEGRATE_H

#include "fix.h"
#include "pair_styles/per_atom_rows.h"

#include "integrators/schemes.h"

namespace LAMMPS_NS {

class FixTDEMIntegrate : public tdem::host::PerAtomRows<Fix> {
 public:
  FixTDEMIntegrate(class LAMMPS *, int, char **);
  ~FixTDEMIntegrate() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;
  void post_run() override;
  double memory_usage() override;

  void set_arrays(int) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // doubles of history per atom (without the flag) for a scheme (for docs and tests)
  int history_doubles() const { return nhist_t + nhist_r; }
  // the scheme in use (for fix tdem/timestep)
  tdem::integrators::Scheme scheme_in_use() const { return scheme; }
  // extract("tdem_energy_form", dim) -> int[2] (dim 0), for compute tdem/energy: the scheme's
  // integrators::energy_form, and 1 where its force sees a predicted velocity (velocity_verlet_sync,
  // velocity_verlet_ab2: a pair style then sees that velocity, not the step's drift)
  void *extract(const char *, int &) override;

 private:
  tdem::integrators::Scheme scheme;
  int energy_form_[2];
  int rotation;          // 1: integrate omega as well
  int nhist_t, nhist_r;  // history doubles of the translation / rotation channel
  int nlast;             // 6 (last acceleration and angular acceleration) or 0 (velocity_verlet)
  int olast;             // offset of the last acceleration in a row: 1 + nhist_t + nhist_r
  int stride;            // olast + nlast
  int code;              // scheme and rotation, as stored in restart files
  // rows_ (tdem::host::PerAtomRows, width_ = stride):
                         // [atom][0] flag (0 new, 1 started, 2 re-start, 3 started + last acceleration
                         // kept for the next run), [1 ..] translation history, rotation history, last acceleration
  double dt_hist;        // the time step the histories were built with
  double dt_prev;        // the time step before the last change (re-start of half-step velocities)
  int pending;           // atoms without the flag may exist (final_integrate must start them)
  int restart_mismatch;  // the restart file was written by another scheme: re-start

  void clear_started();
  void accelerations(int, double *) const;
  template <tdem::integrators::Scheme S, bool R> void start_atom(int, const double *, const double *, double);
  template <tdem::integrators::Scheme S, bool R> void loop_initial();
  template <tdem::integrators::Scheme S, bool R> void loop_final();
};

}  // namespace LAMMPS_NS

#endif
#endif
