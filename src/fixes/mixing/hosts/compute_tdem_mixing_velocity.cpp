// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS and LIGGGHTS (one source, src/fixes/<host>/tdem_fix_host.h): compute tdem/mixing/velocity (see the header and docs/mixing_hosts.md).
#include "compute_tdem_mixing_velocity.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "tdem_fix_host.h"

#include <cstdio>
#include "group.h"
#include "memory.h"
#include "update.h"

#include <string>
#include <vector>

using namespace LAMMPS_NS;
namespace mh = tdem::grate::mixing::host;

ComputeTDEMMixingVelocity::ComputeTDEMMixingVelocity(LAMMPS *lmp, TDEM_COMPUTE_CTOR_ARGS) :
    TDEM_COMPUTE_BASE_INIT(lmp), excludebit(0), table(nullptr)
{
  const std::string ctx = std::string("compute ") + id + " tdem/mixing/velocity";
  std::vector<std::string> a(arg + TDEM_COMPUTE_FIRST_ARG, arg + narg);
  TDEM_COMPUTE_ARGS_DONE();
  try {
    cfg = mh::parse_velocity(a, ctx);
  } catch (std::exception &e) {
    tdem_host::all(error, FLERR, e.what());
  }
  for (int k = 0; k < 3; k++)
    if (cfg.periodic[k] && !domain->periodicity[k])
      tdem_host::all(error, FLERR, ctx + ": keyword 'periodic' value '" + std::string(1, "xyz"[k]) +
                            "' is invalid; allowed: the periodic axes of the simulation box");
  if (!cfg.exclude.empty() && group->find(cfg.exclude.c_str()) < 0)
    tdem_host::all(error, FLERR, ctx + ": keyword 'exclude' value '" + cfg.exclude + "' is invalid; allowed: an existing group ID");
  scalar_flag = 1;
  extscalar = 0;
  array_flag = 1;
  size_array_rows = cfg.bins.count + 1;
  size_array_cols = mh::kVelocityCols;
  extarray = 0;
  memory->create(table, size_array_rows, size_array_cols, "tdem/mixing/velocity:table");
  array = table;
}

ComputeTDEMMixingVelocity::~ComputeTDEMMixingVelocity()
{
  memory->destroy(table);
}

void ComputeTDEMMixingVelocity::init()
{
  excludebit = 0;
  if (!cfg.exclude.empty()) {
    const int g = group->find(cfg.exclude.c_str());
    if (g < 0)
      tdem_host::all(error, FLERR, std::string("compute ") + id + " tdem/mixing/velocity: keyword 'exclude' value '" +
                            cfg.exclude + "' is invalid; allowed: an existing group ID");
    excludebit = group->bitmask[g];
  }
  for (int k = 0; k < 3; k++) {
    const double len = domain->boxhi[k] - domain->boxlo[k];
    if (cfg.periodic[k] && !(2.0 * cfg.radius <= len))
      tdem_host::all(error, FLERR,
                     std::string("compute ") + id + " tdem/mixing/velocity: keyword 'radius' value '" +
                         mh::number_text(cfg.radius) + "' is invalid with 'periodic " + "xyz"[k] + "' (box length " +
                         mh::number_text(len) + "); allowed: R_V <= half the periodic box length");
  }
}

void ComputeTDEMMixingVelocity::evaluate()
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
  tdem::grate::mixing::Periodic per;
  for (int k = 0; k < 3; k++) {
    per.on[k] = cfg.periodic[k];
    per.lo[k] = domain->boxlo[k];
    per.hi[k] = domain->boxhi[k];
  }
  std::vector<double> t;
  try {
    t = mh::velocity_table(world, rows, cfg, per, held);
    mh::report(world, "velocity", held);
  } catch (std::exception &e) {
    tdem_host::all(error, FLERR, std::string("compute ") + id + " tdem/mixing/velocity: " + e.what());
  }
  for (int r = 0; r < size_array_rows; r++)
    for (int c = 0; c < size_array_cols; c++) table[r][c] = t[r * size_array_cols + c];
}

double ComputeTDEMMixingVelocity::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  evaluate();
  scalar = table[size_array_rows - 1][4];
  return scalar;
}

void ComputeTDEMMixingVelocity::compute_array()
{
  invoked_array = update->ntimestep;
  evaluate();
}
