// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: pair style tdem/gran, the parts of its contact loop that run out of line: the
// time-grid correction's contact and force (grid_host.h), the energy accounting's last step of a
// contact, its sums for compute tdem/energy (src/contact/energy.h), the history transfer and the
// error of coincident centres. The loop itself is in pair_tdem_gran.cpp.

#include "pair_tdem_gran.h"

#include "fix_tdem_energy_store.h"
#include "grid_host.h"

#include "atom.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "update.h"

#include "contact/energy.h"

#include <cmath>
#include <string>

using namespace LAMMPS_NS;
using tdem_lammps::LawCoeffs;

// The contact of pair (i, j) as the correction takes it (the geometry, the effective mass and the
// relative velocities of the loop of eval).
tdem_lammps::GcContact PairTDEMGran::gc_pair_contact(int i, int j, const LawCoeffs &lw)
{
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
  const double rsq = delx * delx + dely * dely + delz * delz;
  const double r = sqrt(rsq), rinv = 1.0 / r;
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double mi = rigid.of(i, atom->rmass[i]), mj = rigid.of(j, atom->rmass[j]);
  double meff = mi * mj / (mi + mj);
  if (atom->mask[i] & freeze_group_bit) meff = mj;
  if (atom->mask[j] & freeze_group_bit) meff = mi;
  return {&lw, meff, delx, dely, delz, r, rinv, 1.0 / rsq, radi + radj - r,
          {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]},
          {(radi * omega[i][0] + radj * omega[j][0]) * rinv, (radi * omega[i][1] + radj * omega[j][1]) * rinv,
           (radi * omega[i][2] + radj * omega[j][2]) * rinv},
          dt, radi, radj, omega[i], omega[j]};
}

// Force ccel del + fs and its torques (+ the rolling torque troll) on i and, with newton or an
// owned j, the opposite on j, as the loop of eval adds them.
void PairTDEMGran::gc_add_force(int i, int j, const tdem_lammps::GcContact &c, double ccel, const double *fs,
                                const double *troll)
{
  double **f = atom->f, **torque = atom->torque;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double fx = c.delx * ccel + fs[0], fy = c.dely * ccel + fs[1], fz = c.delz * ccel + fs[2];
  const double tor1 = c.rinv * (c.dely * fs[2] - c.delz * fs[1]);
  const double tor2 = c.rinv * (c.delz * fs[0] - c.delx * fs[2]);
  const double tor3 = c.rinv * (c.delx * fs[1] - c.dely * fs[0]);
  f[i][0] += fx;
  f[i][1] += fy;
  f[i][2] += fz;
  torque[i][0] += -c.radi * tor1 + troll[0];
  torque[i][1] += -c.radi * tor2 + troll[1];
  torque[i][2] += -c.radi * tor3 + troll[2];
  if (newton_pair || j < nlocal) {
    f[j][0] -= fx;
    f[j][1] -= fy;
    f[j][2] -= fz;
    torque[j][0] -= c.radj * tor1 + troll[0];
    torque[j][1] -= c.radj * tor2 + troll[1];
    torque[j][2] -= c.radj * tor3 + troll[2];
  }
  if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, c.delx, c.dely, c.delz);
}

// energy yes: the first step without contact of pair (i, j): the last half step of its loads, then
// its work (as energy taken out of the motion) half to each atom's store and the slots zeroed
void PairTDEMGran::energy_end(int i, int j, double *slots, bool update)
{
  namespace en = tdem::energy;
  if (update) {
    double **v = atom->v, **omega = atom->omega;
    en::step(slots, en::Compact<double>{}, en::pair_motion(v[i], v[j], omega[i], omega[j], dt));
  }
  double taken[en::kParts] = {};
  en::close(slots, taken);
  double *ri = estore->row(i), *rj = estore->row(j);
  const bool to_j = force->newton_pair || j < atom->nlocal;
  for (int p = 0; p < en::kParts; p++) {
    ri[p] += 0.5 * taken[p];
    if (to_j) rj[p] += 0.5 * taken[p];
  }
}

void PairTDEMGran::energy_sums(double *sums, double **peratom)
{
  namespace en = tdem::energy;
  for (int p = 0; p < en::kParts; p++) sums[p] = 0.0;
  if (!energy_on || !estore) return;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  for (int i = 0; i < nlocal; i++) {
    const double *r = estore->row(i);
    for (int p = 0; p < en::kParts; p++) {
      sums[p] += r[p];
      if (peratom) peratom[i][p] += r[p];
    }
  }
  if (!list || !fix_history) return;
  const int hsize = size_history;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *touch = fix_history->firstflag[i];
    const double *allslots = fix_history->firstvalue[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (!touch[jj]) continue;
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      const double *w = allslots + hsize * jj + hsize - en::kSlots + en::kCompactSize;
      const bool both = newton_pair || j < nlocal;
      for (int p = 0; p < en::kParts; p++) {
        sums[p] -= both ? w[p] : 0.5 * w[p];
        if (peratom) {
          peratom[i][p] -= 0.5 * w[p];
          if (both) peratom[j][p] -= 0.5 * w[p];
        }
      }
    }
  }
}

void PairTDEMGran::energy_local(std::vector<double> &rows)
{
  namespace en = tdem::energy;
  rows.clear();
  if (!energy_on || !list || !fix_history) return;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair, hsize = size_history;
  const tagint *tag = atom->tag;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *touch = fix_history->firstflag[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (!touch[jj]) continue;
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      // newton off: a pair with a ghost partner is in the lists of both ranks; one row of it
      if (!newton_pair && j >= nlocal && tag[i] > tag[j]) continue;
      const double *w = fix_history->firstvalue[i] + hsize * jj + hsize - en::kSlots + en::kCompactSize;
      rows.push_back((double) tag[i]);
      rows.push_back((double) tag[j]);
      double taken = 0.0;
      for (int p = 0; p < en::kParts; p++) rows.push_back(-w[p]), taken -= w[p];
      rows.push_back(taken);
    }
  }
}

// history of j-i from that of i-j: the tangential spring flips sign, the normal-law slots
// (xi_max of walton_braun) and the time-grid correction's flags do not. Used by FixNeighHistory
// when nondefault_history_transfer.
void PairTDEMGran::transfer_history(TDEM_LMP_TRANSFER_HISTORY_PARAMS(source, target))
{
  // the tangential block: vectors flip (kernel HistorySlot::flips_sign), scalars do not
  const int nt = tdem_lammps::tangential_history_size(utlaw);
  for (int m = 0; m < nt && m < size_history; m++)
    target[m] = tdem_lammps::tangential_slot_flips(utlaw, m) ? -source[m] : source[m];
  const int ne = energy_on ? size_history - tdem::energy::kSlots : size_history;
  for (int m = nt; m < ne; m++) target[m] = source[m];
  if (energy_on) tdem::energy::reverse(source + ne, target + ne);
}

void PairTDEMGran::coincident_centres(int i, int j) {
  error->one(FLERR, "pair tdem/gran: atoms " + std::to_string(static_cast<long long>(atom->tag[i])) + " and " +
                        std::to_string(static_cast<long long>(atom->tag[j])) +
                        " have coincident centres (distance 0) at step " +
                        std::to_string(static_cast<long long>(update->ntimestep)) +
                        ": the contact normal is undefined; place the particles apart (e.g. delete_atoms overlap)");
}
