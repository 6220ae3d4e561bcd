// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: compute tdem/energy, the energy balance of a scene with pair tdem/gran energy yes
// (docs/lammps/compute_tdem_energy.md, docs/energy.md).
//
//   compute ID group tdem/energy [form kick_drift_kick|kick_then_drift]
//   (default: the form of the scheme of fix tdem/integrate, else kick_drift_kick as fix nve/sphere)
//
// Global vector (extensive, J): 1-4 the energy the contacts (of pair tdem/gran and of the fixes
// with energy yes, e.g. fix tdem/wall/gran) took out of the motion per part (normal_elastic,
// normal_damping, tangential, rolling: src/contact/energy.h), 5 their sum, 6 the discrete kinetic
// energy K~ of the group (translation + rotation), 7 the potential energy of fix gravity, 8 the work
// the walls' own motion did on the spheres, 9 the balance K~ + potential + taken - walls' work, 10
// the balance minus its value at the compute's first evaluation (the residual). Scalar: 5.
// Per-atom array: 1-4 the parts (half of every pair contact to each of its atoms, all of a wall
// contact to its sphere), 5 their sum, 6 K~ of the atom, 7 its potential energy, 8 the walls' work
// on it. Local array, one row per current pair contact (dump local): the two atom IDs, the energy
// taken per part so far, their sum.

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(tdem/energy,ComputeTDEMEnergy);
// clang-format on
#else

#ifndef TDEM_LMP_COMPUTE_TDEM_ENERGY_H
#define TDEM_LMP_COMPUTE_TDEM_ENERGY_H

#include "compute.h"

#include "contact/energy.h"
#include "tdem_lammps_energy.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeTDEMEnergy : public Compute {
 public:
  static constexpr int kVector = 10, kColumns = 8;
  ComputeTDEMEnergy(class LAMMPS *, int, char **);
  ~ComputeTDEMEnergy() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  void compute_local() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  tdem::energy::Form form;
  bool form_given;  // the form keyword (else: from fix tdem/integrate, or kick_drift_kick)
  class PairTDEMGran *pair;
  std::vector<const tdem_lammps::EnergySource *> sources;  // fixes with energy yes
  const double *gvec;  // fix gravity's acceleration vector (nullptr: no gravity)
  int gravity_groupbit;
  bool have_reference;
  double reference;  // the balance at the first evaluation
  double **peratom;
  int nmax;
  std::vector<double> local_rows;
  double **local;  // row pointers into local_rows
  int nlocal_max;
  // K~ and the potential energy of owned atom i of the group
  void body_energy(int i, double &kinetic, double &potential) const;
};

}  // namespace LAMMPS_NS

#endif
#endif
