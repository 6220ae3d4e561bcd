// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: what compute tdem/energy asks of a fix whose contacts account their energy
// (fix tdem/wall/gran energy yes; src/contact/energy.h). The compute finds such fixes by this
// interface, so a fix module (a layer above) can take part without the compute knowing it.
#pragma once

namespace tdem_lammps {

class EnergySource {
 public:
  // true when the fix accounts its contacts' energy
  virtual bool energy_enabled() const = 0;
  // this rank's share: parts[p] += the energy its contacts took out of the motion per part
  // (tdem::energy::Part), *work += the work its walls did on the spheres (their own motion);
  // peratom (optional, rows of the owned atoms): columns 0-3 the parts, column `wall_column` the
  // walls' work, all of a wall contact to its sphere
  virtual void energy_sums(double *parts, double *work, double **peratom, int wall_column) const = 0;

 protected:
  // not deleted through this interface (a fix's destructor may throw in LAMMPS: no virtual one here)
  ~EnergySource() = default;
};

}  // namespace tdem_lammps
