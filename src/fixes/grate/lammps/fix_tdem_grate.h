// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/grate, a stepped grate of fixed and moving bar rows (issue 7,
// physics_reference.md 7.1, docs/grate.md for the core, docs/lammps/fix_tdem_grate.md for the syntax).
//
//   fix ID group tdem/grate <law: as fix tdem/wall/gran> <grate keywords> <motion keywords>
//       [vtk N prefix] [max_contacts K] [energy no|yes]
//
// The bars (and the optional side walls) are the oriented boxes of tdem::grate::Grate::boxes(t)
// at the grate time t = (step - step of definition) * dt. Every owned atom of the group is tested
// against every box; a touching box acts on the sphere like fix tdem/wall/gran (infinite mass and
// radius, relative velocity against the box's translation velocity). An atom may touch up to K
// boxes at once; each contact keeps its own history slot (box index + the law's history), the
// slots migrate with the atoms and are written to restart files. The grate time is a global
// restart quantity, so a restarted run continues the bar motion.
//
// Interface for other tdem styles (compute tdem/mixing ...): extract("tdem_grate") ->
// const tdem::grate::Grate *, extract("tdem_grate_time") -> double * (grate time of the last
// force evaluation), both dim 0.
//
// energy yes: every contact accounts the work of its force parts over the sphere's motion relative
// to its box, and the box's work on the sphere over the box's own motion, for compute tdem/energy
// (src/contact/energy.h, tdem_lammps_energy.h); each slot then ends with energy::kSlots, and the
// row with the ended contacts' energy per part and the bars' work.

#ifdef FIX_CLASS
// clang-format off
FixStyle(tdem/grate,FixTDEMGrate);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_GRATE_H
#define TDEM_LMP_FIX_TDEM_GRATE_H

#include "fix.h"
#include "pair_styles/per_atom_rows.h"
#include "fixes/grate/geometry.h"
#include "fixes/vtk/vtk_files.h"
#include "tdem_lammps_law.h"
#include "contact_host.h"
#include "tdem_lammps_energy.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

// per-atom contact slots: tdem::host::PerAtomRows (rows_, width_ values per atom)
class FixTDEMGrate : public tdem::host::PerAtomRows<Fix>, public tdem_lammps::EnergySource {
 public:
  FixTDEMGrate(class LAMMPS *, int, char **);
  ~FixTDEMGrate() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void post_force_respa(int, int, int) override;
  double compute_vector(int) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;
  void set_arrays(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void unpack_restart(int, int) override;
  void reset_dt() override;

  // EN: the energy accounting (energy yes)
  template <int M, int E, int S, int TL, bool EN = false> void eval();

  // energy yes (tdem_lammps_energy.h)
  bool energy_enabled() const override { return energy_on != 0; }
  void energy_sums(double *parts, double *work, double **peratom, int wall_column) const override;

  // read-only views for other tdem styles
  const tdem_lammps::LawCoeffs &grate_law() const { return law; }
  const tdem::grate::Grate &grate() const { return *grate_; }
  double grate_time() const { return t_last; }

 protected:
  std::string where;
  tdem_lammps::LawCoeffs law;
  std::unique_ptr<tdem::grate::Grate> grate_;
  std::vector<tdem::grate::Box> boxes_;
  std::vector<double> box_extent;  // half extents of the axis-aligned bounding box of each box
  int per_axis;                   // periodic width axis (minimum image), or -1
  double per_len;

  // grate time t = t_base + (ntimestep - step_base) * dt_cur
  double t_base;
  bigint step_base;
  double dt_cur;
  double t_last;
  double current_time() const;
  void rebase_time();

  int max_contacts;   // K history slots per atom
  int size_history;   // the law's history values per contact
  int slot_size;      // 1 + size_history (box index, history)
  int energy_on;      // energy yes: size_history = the law's + energy::kSlots, and a tail per row
  int law_history;    // the law's history values per contact
  // energy yes: the last step of the contact in slot (box index, history) of atom i, its energy to
  // the row's tail (cold: once per contact)
  [[gnu::cold, gnu::noinline]] void energy_free(int i, double *slot, bool advance);
  // rows_: per atom K x (box index or -1, history), width_ = K * slot_size values

  int vtk_every;
  std::string vtk_prefix;
  std::unique_ptr<tdem::vtkio::StepFiles> vtk_files;  // rank 0: prefix_STEP.vtp and prefix.pvd
  void write_vtk(double t);

  int nlevels_respa;
  int ngroups;
  double fbar[3], fbar_all[3];  // force of the particles on the boxes (this rank / all ranks)
  int force_flag;
  std::vector<int> extlist_store;

  tdem_lammps::RigidMasses rigid;  // body masses of the spheres of rigid bodies
  bigint ndeep;  // evaluations with the sphere centre inside a box (reported once)
};

}  // namespace LAMMPS_NS

#endif
#endif
