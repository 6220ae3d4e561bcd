// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: what compute tdem/energy asks of a fix whose contacts account their energy
// (fix tdem/wall/gran energy yes; src/contact/energy.h). The compute finds such fixes by this
// interface, so a fix module (a layer above) can take part without the compute knowing it.
#pragma once

#include "contact/energy.h"

namespace tdem_lammps {

// The loads of a contact as the LAMMPS contact loops have them (del = x_i - contact partner,
// normal force fn along del / r of which `elastic` is the law's elastic part, tangential force fs
// on i, lever arms ci, cj, rolling torque on i troll or nullptr) in the compact form of
// src/contact/energy.h.
inline tdem::energy::Compact<double> contact_loads(double delx, double dely, double delz, double rinv, double fn,
                                                   double elastic, const double *fs, double ci, double cj,
                                                   const double *troll)
{
  tdem::energy::Compact<double> c;
  c.n[0] = delx * rinv, c.n[1] = dely * rinv, c.n[2] = delz * rinv;
  c.fe = elastic;
  c.fd = fn - elastic;
  c.ci = ci, c.cj = cj;
  for (int k = 0; k < 3; k++) c.ft[k] = fs[k], c.tr[k] = troll ? troll[k] : 0.0;
  return c;
}

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
