// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: compute tdem/mixing/velocity (see the header and docs/mixing_hosts.md).
#include "compute_tdem_mixing_velocity.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include <cstdio>
#include "group.h"
#include "memory.h"
#include "update.h"

#include <string>
#include <vector>

using namespace LAMMPS_NS;
namespace mh = tdem::grate::mixing::host;

ComputeTdemMixingVelocity::ComputeTdemMixingVelocity(LAMMPS *lmp, int &iarg, int narg, char **arg) :
    Compute(lmp, iarg, narg, arg), excludebit(0), table(nullptr)
{
  const std::string ctx = std::string("compute ") + id + " tdem/mixing/velocity";
  std::vector<std::string> a(arg + iarg, arg + narg);
  iarg = narg;
  try {
    cfg = mh::parse_velocity(a, ctx);
  } catch (std::exception &e) {
    error->all(FLERR, e.what());
  }
  for (int k = 0; k < 3; k++)
    if (cfg.periodic[k] && !domain->periodicity[k])
      error->all(FLERR, (ctx + ": keyword 'periodic' value '" + std::string(1, "xyz"[k]) +
                            "' is invalid; allowed: the periodic axes of the simulation box").c_str());
  if (!cfg.exclude.empty() && group->find(cfg.exclude.c_str()) < 0)
    error->all(FLERR, (ctx + ": keyword 'exclude' value '" + cfg.exclude + "' is invalid; allowed: an existing group ID").c_str());
  scalar_flag = 1;
  extscalar = 0;
  array_flag = 1;
  size_array_rows = cfg.bins.count + 1;
  size_array_cols = mh::kVelocityCols;
  extarray = 0;
  memory->create(table, size_array_rows, size_array_cols, "tdem/mixing/velocity:table");
  array = table;
}

ComputeTdemMixingVelocity::~ComputeTdemMixingVelocity()
{
  memory->destroy(table);
}

void ComputeTdemMixingVelocity::init()
{
  excludebit = 0;
  if (!cfg.exclude.empty()) {
    const int g = group->find(cfg.exclude.c_str());
    if (g < 0)
      error->all(FLERR, (std::string("compute ") + id + " tdem/mixing/velocity: keyword 'exclude' value '" +
                            cfg.exclude + "' is invalid; allowed: an existing group ID").c_str());
    excludebit = group->bitmask[g];
  }
  for (int k = 0; k < 3; k++) {
    const double len = domain->boxhi[k] - domain->boxlo[k];
    if (cfg.periodic[k] && !(2.0 * cfg.radius <= len))
    {
      char buf[512];
      snprintf(buf, sizeof buf,
               "compute %s tdem/mixing/velocity: keyword 'radius' value '%g' is invalid with 'periodic %c' (box "
               "length %g); allowed: R_V <= half the periodic box length", id, cfg.radius, "xyz"[k], len);
      error->all(FLERR, buf);
    }
  }
}

void ComputeTdemMixingVelocity::evaluate()
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  std::vector<double> rows;
  rows.reserve(static_cast<size_t>(nlocal) * mh::kVelocityWidth);
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    rows.push_back(static_cast<double>(atom->tag[i]));
    for (int k = 0; k < 3; k++) rows.push_back(atom->x[i][k]);
    for (int k = 0; k < 3; k++) rows.push_back(atom->v[i][k]);
    rows.push_back((mask[i] & excludebit) ? 0.0 : 1.0);
  }
  const std::vector<double> all = mh::allgather_sorted(world, rows, mh::kVelocityWidth);
  tdem::grate::mixing::Periodic per;
  for (int k = 0; k < 3; k++) {
    per.on[k] = cfg.periodic[k];
    per.lo[k] = domain->boxlo[k];
    per.hi[k] = domain->boxhi[k];
  }
  std::vector<double> t;
  try {
    t = mh::velocity_table(all, cfg, per);
  } catch (std::exception &e) {
    error->all(FLERR, (std::string("compute ") + id + " tdem/mixing/velocity: " + e.what()).c_str());
  }
  for (int r = 0; r < size_array_rows; r++)
    for (int c = 0; c < size_array_cols; c++) table[r][c] = t[r * size_array_cols + c];
}

double ComputeTdemMixingVelocity::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  evaluate();
  scalar = table[size_array_rows - 1][4];
  return scalar;
}

void ComputeTdemMixingVelocity::compute_array()
{
  invoked_array = update->ntimestep;
  evaluate();
}
