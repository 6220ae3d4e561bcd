// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/integrate, the time integrators of src/integrators/schemes.h as
// a replacement of fix nve/sphere (translation and rotation of spheres).
//
//   fix ID group tdem/integrate scheme NAME [rotation yes|no]
//
// NAME is one of tdem::integrators::scheme_names() (euler ... gear6). `rotation no` integrates x
// and v only (omega untouched); the default integrates omega with the same scheme, with the
// angular acceleration of fix nve/sphere (torque / (0.4 m r^2), 0.5 in 2d).
//
// Per atom the fix keeps one row of doubles (own grow/copy/exchange/restart callbacks, no
// internal fix property/atom: the row layout depends on the scheme and the restart record names
// the scheme it was written with, so a restart with another scheme is detected per atom):
//   [0]           started flag
//   [1 .. 3]      the acceleration of the last force evaluation (final_integrate),
//   [4 .. 6]      and the angular one (rotation yes)
//   then          Kernel<S, true>::history doubles (translation), Kernel<S, false>::history
//                 doubles (rotation yes).
// predict() takes the stored acceleration, not the force LIGGGHTS re-evaluates when a run
// starts: that set-up force differs from the last force of the previous run (schemes with a
// corrector have moved x or v since; and LIGGGHTS's tangential contact history gives a different
// force in set-up even at the same state), so only the stored value makes `run N; run M` and
// `run N; write_restart` + `read_restart; run M` continue exactly as one `run N+M`. Exception:
// velocity_verlet takes the force present, as fix nve/sphere does (the set-up force at the first
// step of a run; within a run the stored value is f / m of the same force anyway).
//
// Start-up: an atom without the flag is started (integrators::start, exact for constant
// acceleration) from its first complete force, at the next initial_integrate: for atoms present
// at the run start that is the set-up force after every fix has added its part (fix gravity
// and wall/gran add theirs in their own setup(), which may come after this fix's), for atoms
// inserted during a run (fix insert/pack ...) the force of the step they appeared in (atom->f
// is not cleared before initial_integrate). A change of the time step re-starts every atom with
// a warning. See docs/liggghts/fix_tdem_integrate.md.
#pragma once

#include <cstdio>

#include "fix.h"
#include "pair_styles/per_atom_rows.h"

#include "integrators/schemes.h"

namespace LAMMPS_NS {

class FixTDEMIntegrate : public tdem::host::PerAtomRows<Fix> {
 public:
  FixTDEMIntegrate(class LAMMPS*, int, char**);
  ~FixTDEMIntegrate();
  int setmask();
  void init();
  void setup(int);
  // the scheme in use (for fix tdem/timestep)
  tdem::integrators::Scheme scheme_in_use() const { return scheme_; }
  void initial_integrate(int);
  void final_integrate();
  void reset_dt();
  double memory_usage();

  int pack_restart(int, double*);
  void unpack_restart(int, int);
  void write_restart(FILE*);
  void restart(char*);

  // doubles stored per atom (flag, last accelerations, histories)
  int row_doubles() const { return stride_; }

 private:
  tdem::integrators::Scheme scheme_;
  bool rotation_;
  int nhist_t_, nhist_r_;  // history doubles of the translation / rotation channel
  int off_at_, off_ar_;    // offsets of the stored accelerations (off_ar_ -1: rotation no)
  int off_ht_, off_hr_;    // offsets of the histories
  int stride_;             // doubles per atom
  int code_;               // scheme and rotation, as written to restart files
  // rows_: the per-atom rows (tdem::host::PerAtomRows, width_ = stride_)
  double dt_hist_;         // time step the histories were built with
  bool restart_mismatch_;  // restart file of another scheme: every atom starts again

  double inertia_factor() const;
  // what a loop over the group's atoms reads: positions, velocities, spins, masks, the atoms to
  // visit (nfirst with atom_modify first), the step, ftm2v and the inertia factor
  struct Pass {
    double **x, **v, **omega;
    const int* mask;
    int nlocal;
    double h, ftm2v, inertia;
  };
  Pass pass() const;
  template <bool R> void accelerations(int i, double ftm2v, double inertia, double* at, double* ar) const;
  void restart_all(const char* why);
  template <tdem::integrators::Scheme S, bool R> void loop_initial();
  template <tdem::integrators::Scheme S, bool R> void loop_final();
};

}  // namespace LAMMPS_NS

namespace tdem {
namespace liggghts {
// Adds `fix tdem/integrate` to this LIGGGHTS instance's fix styles (LIGGGHTS 3.8 has no
// registration API; the style map is reached through an explicit template instantiation).
// A `clear` command rebuilds the style map without it.
void register_fixes(LAMMPS_NS::LAMMPS* lmp);
}  // namespace liggghts
}  // namespace tdem
