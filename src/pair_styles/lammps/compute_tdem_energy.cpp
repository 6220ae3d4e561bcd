// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: compute tdem/energy (see the header and docs/lammps/compute_tdem_energy.md).
#include "compute_tdem_energy.h"

#include "lammps_compat.h"
#include "pair_tdem_gran.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
namespace en = tdem::energy;

ComputeTDEMEnergy::ComputeTDEMEnergy(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  form = en::Form::kick_drift_kick;
  form_given = false;
  for (int a = 3; a < narg; a += 2) {
    if (std::strcmp(arg[a], "form") != 0)
      error->all(FLERR, std::string("compute tdem/energy: unknown keyword '") + arg[a] + "' (it takes form)");
    if (a + 1 >= narg) error->all(FLERR, "compute tdem/energy: form needs a value, kick_drift_kick or kick_then_drift");
    form_given = true;
    if (std::strcmp(arg[a + 1], "kick_drift_kick") == 0)
      form = en::Form::kick_drift_kick;
    else if (std::strcmp(arg[a + 1], "kick_then_drift") == 0)
      form = en::Form::kick_then_drift;
    else
      error->all(FLERR, std::string("compute tdem/energy: form takes kick_drift_kick (fix nve/sphere, velocity "
                                    "Verlet) or kick_then_drift (symplectic Euler, leapfrog), got '") +
                            arg[a + 1] + "'");
  }
  scalar_flag = vector_flag = peratom_flag = local_flag = 1;
  size_vector = kVector;
  size_peratom_cols = kColumns;
  size_local_cols = PairTDEMGran::kLocalColumns;
  size_local_rows = 0;
  extscalar = extvector = 1;
  comm_reverse = en::kParts;
  pair = nullptr;
  gvec = nullptr;
  gravity_groupbit = 0;
  have_reference = false;
  reference = 0.0;
  peratom = nullptr;
  nmax = 0;
  local = nullptr;
  nlocal_max = 0;
  vector = new double[kVector]();
}

ComputeTDEMEnergy::~ComputeTDEMEnergy()
{
  delete[] vector;
  memory->destroy(peratom);
  memory->sfree(local);
}

void ComputeTDEMEnergy::init()
{
  pair = dynamic_cast<PairTDEMGran *>(force->pair_match("tdem/gran", 1));
  if (!pair || !pair->energy_enabled())
    error->all(FLERR, "compute tdem/energy needs pair_style tdem/gran energy yes (the contacts account their "
                      "work only then)");
  // the fixes whose contacts account their energy (fix tdem/wall/gran energy yes); a tdem wall
  // without it would leave its contacts out of the balance
  sources.clear();
  for (int k = 0; k < modify->nfix; k++) {
    const auto *src = dynamic_cast<const tdem_lammps::EnergySource *>(modify->fix[k]);
    if (!src) continue;
    if (!src->energy_enabled())
      error->all(FLERR, std::string("compute tdem/energy: fix ") + modify->fix[k]->id + " (" + modify->fix[k]->style +
                            ") does not account its contacts' energy; add 'energy yes' to it");
    sources.push_back(src);
  }
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "compute tdem/energy requires atom_style sphere");
  // fixes whose forces the balance does not know yet: it does not close with them
  if (comm->me == 0)
    for (const char *style : {"^wall/gran", "^tdem/clump", "^rigid", "^viscous", "^addforce"})
      for (const Fix *fx : tdem_lammps::compat::fixes_by_style(modify, style))
        error->warning(FLERR, std::string("compute tdem/energy: the work of fix ") + fx->id + " (" + fx->style +
                                  ") is not in the balance; c_" + id + "[10] will not stay at round-off");
  // the integrator's form (fix tdem/integrate; fix nve/sphere kicks, drifts and kicks again)
  if (!form_given) {
    form = en::Form::kick_drift_kick;
    int seen = -2;
    std::string which;
    for (const Fix *fx : tdem_lammps::compat::fixes_by_style(modify, "^tdem/integrate")) {
      int dim = 0;
      const int *ef = static_cast<const int *>(const_cast<Fix *>(fx)->extract("tdem_energy_form", dim));
      if (!ef) continue;
      if (seen != -2 && ef[0] != seen)
        error->all(FLERR, std::string("compute tdem/energy: the fixes tdem/integrate ") + which + " and " + fx->id +
                              " move the bodies in different ways; give the form keyword");
      seen = ef[0], which = fx->id;
      if (ef[0] == 1) form = en::Form::kick_then_drift;
      if (comm->me == 0 && (ef[0] < 0 || ef[1]))
        error->warning(FLERR, std::string("compute tdem/energy: the scheme of fix ") + fx->id +
                                  (ef[0] < 0 ? " has no exact discrete kinetic energy"
                                             : "'s force sees a predicted velocity, not the step's drift") +
                                  ": c_" + id + "[10] will not stay at round-off (the scheme's energy error, and "
                                  "the contacts' work over the velocity the force sees rather than the step's drift)");
    }
  }
  // fix gravity: its potential energy -m g . x (x unwrapped)
  gvec = nullptr;
  gravity_groupbit = 0;
  const auto grav = tdem_lammps::compat::fixes_by_style(modify, "^gravity");
  if (grav.size() > 1) error->all(FLERR, "compute tdem/energy: more than one fix gravity");
  if (!grav.empty()) {
    int dim = 0;
    gvec = static_cast<const double *>(grav[0]->extract("gvec", dim));
    if (!gvec) error->all(FLERR, "compute tdem/energy: fix gravity gives no gravity vector");
    gravity_groupbit = grav[0]->groupbit;
  }
}

void ComputeTDEMEnergy::body_energy(int i, double &kinetic, double &potential) const
{
  const double m = atom->rmass[i], r = atom->radius[i], inertia = 0.4 * m * r * r;
  double a[3], alpha[3];
  for (int k = 0; k < 3; k++) a[k] = atom->f[i][k] / m, alpha[k] = atom->torque[i][k] / inertia;
  kinetic = en::kinetic(form, m, inertia, atom->v[i], atom->omega[i], a, alpha, update->dt);
  potential = 0.0;
  if (gvec && (atom->mask[i] & gravity_groupbit)) {
    double xu[3];
    domain->unmap(atom->x[i], atom->image[i], xu);
    potential = -m * (gvec[0] * xu[0] + gvec[1] * xu[1] + gvec[2] * xu[2]);
  }
}

void ComputeTDEMEnergy::compute_vector()
{
  invoked_vector = update->ntimestep;
  double local[en::kParts + 3];
  pair->energy_sums(local, nullptr);
  double walls = 0.0;
  for (const auto *src : sources) src->energy_sums(local, &walls, nullptr, 7);
  double kin = 0.0, pot = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    double k, p;
    body_energy(i, k, p);
    kin += k, pot += p;
  }
  local[en::kParts] = kin, local[en::kParts + 1] = pot, local[en::kParts + 2] = walls;
  double all[en::kParts + 3];
  MPI_Allreduce(local, all, en::kParts + 3, MPI_DOUBLE, MPI_SUM, world);
  double taken = 0.0;
  for (int p = 0; p < en::kParts; p++) vector[p] = all[p], taken += all[p];
  vector[4] = taken;
  vector[5] = all[en::kParts];
  vector[6] = all[en::kParts + 1];
  vector[7] = all[en::kParts + 2];
  vector[8] = vector[5] + vector[6] + taken - vector[7];
  if (!have_reference) reference = vector[8], have_reference = true;
  vector[9] = vector[8] - reference;
}

double ComputeTDEMEnergy::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (invoked_vector != update->ntimestep) compute_vector();
  return scalar = vector[4];
}

void ComputeTDEMEnergy::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(peratom);
    nmax = atom->nmax;
    memory->create(peratom, nmax, kColumns, "tdem/energy:peratom");
    array_atom = peratom;
  }
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int c = 0; c < kColumns; c++) peratom[i][c] = 0.0;
  double sums[en::kParts];
  pair->energy_sums(sums, peratom);
  if (force->newton_pair) tdem_lammps::compat::reverse_comm(comm, this);
  double walls = 0.0;
  for (const auto *src : sources) src->energy_sums(sums, &walls, peratom, 7);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) {
      for (int c = 0; c < kColumns; c++) peratom[i][c] = 0.0;
      continue;
    }
    double taken = 0.0;
    for (int p = 0; p < en::kParts; p++) taken += peratom[i][p];
    peratom[i][4] = taken;
    body_energy(i, peratom[i][5], peratom[i][6]);
  }
}

void ComputeTDEMEnergy::compute_local()
{
  invoked_local = update->ntimestep;
  pair->energy_local(local_rows);
  const int ncol = PairTDEMGran::kLocalColumns;
  size_local_rows = static_cast<int>(local_rows.size() / ncol);
  if (size_local_rows > nlocal_max) {
    nlocal_max = size_local_rows;
    local = static_cast<double **>(memory->srealloc(local, sizeof(double *) * nlocal_max, "tdem/energy:local"));
  }
  for (int r = 0; r < size_local_rows; r++) local[r] = local_rows.data() + (std::size_t) r * ncol;
  array_local = local;
}

int ComputeTDEMEnergy::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int p = 0; p < en::kParts; p++) buf[m++] = peratom[i][p];
  return m;
}

void ComputeTDEMEnergy::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int p = 0; p < en::kParts; p++) peratom[list[i]][p] += buf[m++];
}

double ComputeTDEMEnergy::memory_usage()
{
  return (double) nmax * kColumns * sizeof(double) + (double) local_rows.capacity() * sizeof(double);
}
