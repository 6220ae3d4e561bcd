// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the per-atom store of pair tdem/gran's energy accounting (see the header).
#include "fix_tdem_energy_store.h"

#include "lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;

FixTDEMEnergyStore::FixTDEMEnergyStore(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg != 3) error->all(FLERR, "fix TDEM/ENERGY/STORE is internal to pair tdem/gran (energy yes)");
  restart_peratom = 1;
  comm_reverse = kValues;
  value = nullptr;
  nmax_rows = 0;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < nmax_rows; i++)
    for (int k = 0; k < kValues; k++) value[i][k] = 0.0;
}

FixTDEMEnergyStore::~FixTDEMEnergyStore()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(value);
}

void FixTDEMEnergyStore::grow_arrays(int nmax)
{
  memory->grow(value, nmax, kValues, "tdem/energy/store:value");
  for (int i = nmax_rows; i < nmax; i++)
    for (int k = 0; k < kValues; k++) value[i][k] = 0.0;
  nmax_rows = nmax;
}

void FixTDEMEnergyStore::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < kValues; k++) value[j][k] = value[i][k];
}

int FixTDEMEnergyStore::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < kValues; k++) buf[k] = value[i][k];
  return kValues;
}

int FixTDEMEnergyStore::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < kValues; k++) value[nlocal][k] = buf[k];
  return kValues;
}

int FixTDEMEnergyStore::pack_restart(int i, double *buf)
{
  buf[0] = kValues + 1;  // LAMMPS's per-atom restart layout: the count first
  for (int k = 0; k < kValues; k++) buf[k + 1] = value[i][k];
  return kValues + 1;
}

void FixTDEMEnergyStore::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < kValues; k++) value[nlocal][k] = extra[nlocal][m++];
}

int FixTDEMEnergyStore::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < kValues; k++) buf[m++] = value[i][k];
  return m;
}

void FixTDEMEnergyStore::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < kValues; k++) value[list[i]][k] += buf[m++];
}

void FixTDEMEnergyStore::clear_ghosts()
{
  if (atom->nmax > nmax_rows) grow_arrays(atom->nmax);
  const int nall = atom->nlocal + atom->nghost;
  for (int i = atom->nlocal; i < nall; i++)
    for (int k = 0; k < kValues; k++) value[i][k] = 0.0;
}

void FixTDEMEnergyStore::fold()
{
  if (!force->newton_pair) return;  // newton off: every rank adds only to its own atoms
  tdem_lammps::compat::reverse_comm(comm, this);
  clear_ghosts();
}

double FixTDEMEnergyStore::memory_usage()
{
  return (double) nmax_rows * kValues * sizeof(double);
}
