// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the per-atom store of pair tdem/gran's energy accounting (see the header).
#include "fix_tdem_energy_store.h"

#include "lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"

using namespace LAMMPS_NS;

FixTDEMEnergyStore::FixTDEMEnergyStore(LAMMPS *lmp, int narg, char **arg) : PerAtomRows(lmp, narg, arg)
{
  if (narg != 3) error->all(FLERR, "fix TDEM/ENERGY/STORE is internal to pair tdem/gran (energy yes)");
  restart_peratom = 1;
  comm_reverse = kValues;
  rows_init(kValues, "tdem/energy/store:rows");
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixTDEMEnergyStore::~FixTDEMEnergyStore()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

int FixTDEMEnergyStore::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < kValues; k++) buf[m++] = rows_[i][k];
  return m;
}

void FixTDEMEnergyStore::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < kValues; k++) rows_[list[i]][k] += buf[m++];
}

void FixTDEMEnergyStore::clear_ghosts()
{
  grow_arrays(atom->nmax);
  const int nall = atom->nlocal + atom->nghost;
  for (int i = atom->nlocal; i < nall; i++)
    for (int k = 0; k < kValues; k++) rows_[i][k] = 0.0;
}

void FixTDEMEnergyStore::fold()
{
  if (!force->newton_pair) return;  // newton off: every rank adds only to its own atoms
  tdem_lammps::compat::reverse_comm(comm, this);
  clear_ghosts();
}
