// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/timestep, the time-step advice of src/fixes/timestep/timestep.h for the
// normal laws of pair gran and fix wall/gran (issue 8).
//
//   fix ID group tdem/timestep [vmax V] [check off|warn|stop] [every N] [fraction F] [scheme NAME]
//
// The law of pair gran / each fix wall/gran is found with contact_match("normal", NAME); its
// parameters are read from the fix property/global the law reads (kn, gamman, gamman_abs,
// youngsModulus, poissonsRatio, coefficientRestitution, contactTime, characteristicVelocity,
// dampingCoefficient, dampingExponent) for the stock laws hooke, hooke/stiffness and hertz. The
// tdem normal laws (tdem/lsd, tdem/hertz, tdem/walton_braun, tdem/thornton, tdem/power_law,
// tdem/continuous_potential, tdem/extended_linear, tdem/extended_hertz) publish their settings and
// per-type-pair coefficients through src/pair_styles/liggghts/tdem_liggghts_advice.h, keyed by the
// pair gran / fix wall/gran that owns them: the advice is that of the setting in use, from the
// coefficients exactly as the model forms them. Other laws: a warning naming the law. Rows, table,
// check and run-time check: as in LAMMPS (src/fixes/timestep/host_table.h). See docs/timestep.md.
#ifdef FIX_CLASS
FixStyle(tdem/timestep, FixTDEMTimestep)
#else

#ifndef TDEM_LIG_FIX_TDEM_TIMESTEP_H
#define TDEM_LIG_FIX_TDEM_TIMESTEP_H

#include <string>
#include <vector>

#include "fix.h"

#include "fixes/timestep/host_table.h"

namespace LAMMPS_NS {

class FixTDEMTimestep : public Fix {
 public:
  FixTDEMTimestep(class LAMMPS*, int, char**);
  int setmask();
  void init();
  void setup(int);
  void end_of_step();
  double compute_vector(int);

 private:
  tdem::advice::host::FixState st_;  // options, scheme, rows, vector (shared with LAMMPS)
  // LIGGGHTS deletes atoms that leave the box without an error (thermo_modify lost ignore): the
  // fix counts the group at set-up and, when the step is beyond the stop fraction of dt_c, every
  // step (else at the run-time check), and stops with the advice once atoms are gone
  bigint natoms_;
  bool watch_every_step_;
  std::string unstable_;
  void lost_check();

  void build_rows(double v_setup);
  void run_check(const char* when);
  std::string where() const;
  void say(const std::string& s);
  void law_row(const std::string& model, int i, int j, tdem::advice::host::Row& r);
  // the law of a tdem normal model, from the settings and coefficients it published
  // (src/pair_styles/liggghts/tdem_liggghts_advice.h); false: the owner has no tdem model
  bool published_row(const void* owner, int i, int j, bool wall, tdem::advice::host::Row& r);
  // fix property/global values (found = false: no such property)
  double pair_prop(const char* name, int i, int j, bool& found);
  double type_prop(const char* name, int i, bool& found);
  double scalar_prop(const char* name, bool& found);
};

}  // namespace LAMMPS_NS

namespace tdem {
namespace liggghts {
// Adds `fix tdem/timestep` to this LIGGGHTS instance's fix styles (timestep_register.cpp).
void register_timestep_fix(LAMMPS_NS::LAMMPS* lmp);
}  // namespace liggghts
}  // namespace tdem

#endif
#endif
