// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/wall/gran, a frictional wall with the tdem normal laws (lsd,
// hertz, walton_braun, thornton, power_law, extended_linear, extended_hertz) + cundall_strack.
//
//   fix ID group tdem/wall/gran normal LAW ... tangential cundall_strack ... [options]
//       wallstyle args [wiggle dim A T | shear dim V] [energy no|yes]
//   wallstyle: xplane lo hi | yplane lo hi | zplane lo hi (NULL = no wall) | zcylinder R
//
// The wall has infinite mass and radius: m* is the sphere mass (fix rigid body mass if any).
// hertz/thornton/extended_hertz: R* = sphere radius, E* from sphere and wall materials
// (E NU [E2 NU2]). Per-atom history (tangential spring; + xi_max for walton_braun and
// power_law, + xi_max, f_max for thornton, + v0, k, gamma for extended_linear, + v0, alpha for
// extended_hertz; power_law: the slots of tdem::power_law) migrates with the atoms and is
// written to restarts. energy yes: every contact accounts the work of its force parts, and the
// wall's work on the spheres, for compute tdem/energy (src/contact/energy.h; the row then ends with
// the contact's energy::kSlots, the energy of its ended contacts per part and the wall's work).

#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/wall/gran,FixTDEMWallGran);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_WALL_GRAN_H
#define TDEM_LMP_FIX_TDEM_WALL_GRAN_H

#include "fix.h"
#include "pair_styles/per_atom_rows.h"
#include "tdem_lammps_law.h"

#include "clump_correction_host.h"
#include "contact_host.h"
#include "tdem_lammps_energy.h"

namespace LAMMPS_NS {

// per-atom contact history: tdem::host::PerAtomRows (rows_, width_ values per atom)
class FixTDEMWallGran : public tdem::host::PerAtomRows<Fix>, public tdem_lammps::EnergySource {
 public:
  FixTDEMWallGran(class LAMMPS *, int, char **);
  ~FixTDEMWallGran() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void post_force_respa(int, int, int) override;
  double memory_usage() override;
  void reset_dt() override;

  // C = 1: the multiple-contact correction of fix tdem/clump, C = 2: the energy accounting (C = 0:
  // the plain loop)
  template <int M, int E, int S, int TL, int C = 0> void eval();

  // read-only view for other tdem styles (fix tdem/timestep): the wall's law
  const tdem_lammps::LawCoeffs &wall_law() const { return law; }

  // energy yes (tdem_lammps_energy.h)
  bool energy_enabled() const override { return energy_on != 0; }
  void energy_sums(double *parts, double *work, double **peratom, int wall_column) const override;

 protected:
  enum { XPLANE = 0, YPLANE = 1, ZPLANE = 2, ZCYLINDER = 3 };
  // error->one naming the atom whose centre lies on the wall surface (no contact normal)
  [[noreturn, gnu::cold, gnu::noinline]] void centre_on_wall(int i);
  // grid_correction: the end's extra impulse at the first step without contact (grid_host.h)
  [[gnu::cold, gnu::noinline]] void gc_separation_wall(int i, const double *shear, const double *vwall);
  // energy yes: the last step of a contact with the wall (cold: once per contact)
  [[gnu::cold, gnu::noinline]] void energy_end(int i, double *slots, const double *vwall, bool update);
  tdem_lammps::LawCoeffs law;
  int energy_on;
  int law_width;  // the law's history values at the start of each row (width_ without the energy)
  int wallstyle, wiggle, wshear, axis;
  double lo, hi, cylradius;
  double amplitude, period, omega, vshear;
  bigint time_origin;
  double dt;
  int nlevels_respa;

  tdem_lammps::RigidMasses rigid;  // body masses of the spheres of rigid bodies

  // multiple-contact correction of fix tdem/clump (tally sides: body index, wall -1 lo, -2 hi,
  // -3 cylinder)
  tdem_lammps::ClumpCorrection clump;
};

}  // namespace LAMMPS_NS

#endif
#endif
