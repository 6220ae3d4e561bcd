// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS and LIGGGHTS (one source, src/fixes/<host>/tdem_fix_host.h): fix tdem/mixing/depth (see the header and docs/mixing_hosts.md).
#include "fix_tdem_mixing_depth.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "tdem_fix_host.h"

#include <cstdio>
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cstring>
#include <string>
#include <vector>

#include "fixes/grate/geometry.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace mh = tdem::grate::mixing::host;
namespace mx = tdem::grate::mixing;

// simulation time; time_offset carries the time of a restart file over (read_restart of this LAMMPS
// version does not restore update->atime; the offset is set at the setup of the first run)
double FixTDEMMixingDepth::sim_time() const
{
  return update->atime + (update->ntimestep - update->atimestep) * update->dt + time_offset;
}

std::string FixTDEMMixingDepth::ctx() const
{
  return std::string("fix ") + id + " tdem/mixing/depth";
}

FixTDEMMixingDepth::FixTDEMMixingDepth(LAMMPS *lmp, int narg, char **arg) :
    PerAtomRows(lmp, narg, arg), snapshot(0), last_step(-1), grate_fix(nullptr), fp(nullptr), time_offset(0.0),
    offset_pending(0), saved_time(0.0), saved_step(0)
{
  if (!atom->radius_flag) tdem_host::all(error, FLERR, ctx() + " requires per-atom radii (atom_style sphere)");
  std::vector<std::string> a(arg + 3, arg + narg);
  try {
    cfg = mh::parse_depth(a, ctx(), domain->dimension);
  } catch (std::exception &e) {
    tdem_host::all(error, FLERR, e.what());
  }
  nevery = static_cast<int>(cfg.every);
  scalar_flag = 1;
  extscalar = 0;
  array_flag = 1;
  size_array_rows = cfg.bins.count + 1;
  size_array_cols = mh::kDepthCols;
  extarray = 0;
  global_freq = 1;  // the values of the last snapshot are kept (and migrate), valid at any step
  peratom_flag = 1;
  size_peratom_cols = mh::kPeratomCols;
  peratom_freq = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  rows_init(stride, "tdem/mixing/depth:rows");
  tdem_host::set_maxexchange(this, stride);
  rs.region.resize(cfg.bins.count);
  rs.count_now.assign(cfg.bins.count, 0);
  rs.sigma_now.assign(cfg.bins.count, 0.0);
  table = mh::depth_table(rs, cfg.bins.count);

  grow_arrays(atom->nmax);
  atom->add_callback(tdem_host::CB_GROW);
  atom->add_callback(tdem_host::CB_RESTART);

  if (!cfg.file.empty() && comm->me == 0) {
    fp = fopen(cfg.file.c_str(), "w");
    if (!fp)
      tdem_host::one(error, FLERR, ctx() + ": keyword 'file' value '" + cfg.file +
                            "' is invalid; allowed: a file name that can be opened for writing");
    fprintf(fp, "# fix %s tdem/mixing/depth: every %ld steps, column %.9g, %s\n", id, cfg.every, cfg.column,
            cfg.normalise ? "D normalised (surface 0, grate 1)" : "depth D [length units]");
    fprintf(fp, "# per snapshot: '# step time' then one row per bin (last row: all bins):\n"
                "# bin count meanD mean_sigmaD Qprime sigmaD_samples samples\n");
  }
}

FixTDEMMixingDepth::~FixTDEMMixingDepth()
{
  atom->delete_callback(id, tdem_host::CB_GROW);
  atom->delete_callback(id, tdem_host::CB_RESTART);
  if (fp) fclose(fp);
}

int FixTDEMMixingDepth::setmask()
{
  return END_OF_STEP;
}

void FixTDEMMixingDepth::init()
{
  grate_fix = nullptr;
  if (cfg.use_grate) {
    const int ifix = modify->find_fix(cfg.grate_fix.c_str());
    int dim = 0;
    if (ifix < 0 || !modify->fix[ifix]->extract("tdem_grate", dim) ||
        !modify->fix[ifix]->extract("tdem_grate_time", dim))
      tdem_host::all(error, FLERR, ctx() + ": keyword 'grate' value '" + cfg.grate_fix +
                            "' is invalid; allowed: the ID of a grate fix (one that provides extract(\"tdem_grate\"))");
    grate_fix = modify->fix[ifix];
  }
  for (int k = 0; k < 3; k++) {
    const double len = domain->boxhi[k] - domain->boxlo[k];
    if (domain->periodicity[k] && k != cfg.up && (k == cfg.bins.axis || k == cfg.lateral) && !(cfg.column <= len))
      tdem_host::all(error, FLERR,
                     ctx() + ": keyword 'column' value '" + mh::number_text(cfg.column) + "' is invalid with the periodic axis " +
                         "xyz"[k] + " (box length " + mh::number_text(len) + "); allowed: C <= the periodic box length");
  }
}

void FixTDEMMixingDepth::setup(int /*vflag*/)
{
  if (offset_pending) {
    time_offset = 0.0;
    time_offset = saved_time + (update->ntimestep - saved_step) * update->dt - sim_time();
    offset_pending = 0;
  }
  if (update->ntimestep % nevery == 0) take_snapshot();
}

void FixTDEMMixingDepth::end_of_step()
{
  take_snapshot();
}

void FixTDEMMixingDepth::take_snapshot()
{
  if (update->ntimestep == last_step) return;
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  std::vector<double> id, x, rad, state;
  std::vector<int> index;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    index.push_back(i);
    id.push_back(static_cast<double>(atom->tag[i]));
    for (int k = 0; k < 3; k++) x.push_back(atom->x[i][k]);
    rad.push_back(atom->radius[i]);
    for (int k = 0; k < mh::kStateWidth; k++) state.push_back(rows_[i][mh::kPeratomCols + k]);
  }

  mx::DepthOptions o;
  o.transport_axis = cfg.bins.axis;
  o.up_axis = cfg.up;
  o.lateral_axis = cfg.lateral;
  o.column_width = cfg.column;
  o.normalise = cfg.normalise;
  for (int k = 0; k < 3; k++) {
    o.periodic.on[k] = domain->periodicity[k] && k != cfg.up;
    o.periodic.lo[k] = domain->boxlo[k];
    o.periodic.hi[k] = domain->boxhi[k];
  }
  const double t = sim_time();
  if (grate_fix) {
    int dim = 0;
    const auto *g = static_cast<const tdem::grate::Grate *>(grate_fix->extract("tdem_grate", dim));
    const double *gt = static_cast<const double *>(grate_fix->extract("tdem_grate_time", dim));
    if (!g || !gt) tdem_host::all(error, FLERR, ctx() + ": the grate fix '" + cfg.grate_fix + "' provides no grate");
    const double tg = *gt;
    o.grate_height = [g, tg](double xt, double xl) { return g->surface_height(xt, xl, tg); };
  } else {
    const double h = cfg.floor;
    o.grate_height = [h](double, double) { return h; };
  }
  std::vector<double> depth;
  try {
    mh::depth_snapshot(world, index.size(), id.data(), x.data(), rad.data(), state.data(), o, cfg.bins, t,
                       snapshot + 1, rs, depth, held);
  } catch (std::exception &e) {
    tdem_host::all(error, FLERR, ctx() + ": " + e.what());
  }
  mh::report(world, "depth", held);
  ++snapshot;
  last_step = update->ntimestep;

  for (std::size_t q = 0; q < index.size(); q++) {
    const int i = index[q];
    const double *s = &state[q * mh::kStateWidth];
    for (int k = 0; k < mh::kStateWidth; k++) rows_[i][mh::kPeratomCols + k] = s[k];
    rows_[i][0] = depth[q];
    rows_[i][1] = mh::state_mean(s);
    rows_[i][2] = mh::state_sigma(s);
    rows_[i][3] = mh::state_q(s);
  }
  table = mh::depth_table(rs, cfg.bins.count);
  if (fp) {
    fprintf(fp, "# %lld %.17g\n", static_cast<long long>(update->ntimestep), t);
    for (int b = 0; b <= cfg.bins.count; b++) {
      const double *row = &table[b * mh::kDepthCols];
      fprintf(fp, "%d %.0f %.17g %.17g %.17g %.17g %.0f\n", b < cfg.bins.count ? b + 1 : 0, row[0], row[1], row[2],
              row[3], row[4], row[5]);
    }
    fflush(fp);
  }
}

double FixTDEMMixingDepth::compute_scalar()
{
  return table[cfg.bins.count * mh::kDepthCols + 3];
}

double FixTDEMMixingDepth::compute_array(int i, int j)
{
  return table[i * mh::kDepthCols + j];
}

/* ---------------------------------------------------------------------- per-atom arrays */

double FixTDEMMixingDepth::memory_usage()
{
  return rows_memory();
}

// global record: nbins, snapshot, last step, step now, time now, then per bin total_abs, total_dt, samples, sum_d, sum_d2,
// count now, sum of sigma now
void FixTDEMMixingDepth::write_restart(FILE *f)
{
  if (comm->me != 0) return;
  std::vector<double> list = {static_cast<double>(cfg.bins.count), static_cast<double>(snapshot),
                              static_cast<double>(last_step), static_cast<double>(update->ntimestep),
                              sim_time()};
  for (int b = 0; b < cfg.bins.count; b++) {
    const auto &g = rs.region[b];
    for (double v : {g.total_abs, g.total_dt, static_cast<double>(g.samples), g.sum_d, g.sum_d2,
                     static_cast<double>(rs.count_now[b]), rs.sigma_now[b]})
      list.push_back(v);
  }
  const int size = static_cast<int>(list.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, f);
  fwrite(list.data(), sizeof(double), list.size(), f);
}

void FixTDEMMixingDepth::restart(char *buf)
{
  const double *list = reinterpret_cast<const double *>(buf);
  if (static_cast<int>(list[0]) != cfg.bins.count) {
    if (comm->me == 0)
      tdem_host::warning(error, FLERR, ctx() + ": the restart file has another number of bins; the bin sums start from zero");
    return;
  }
  snapshot = static_cast<long>(list[1]);
  last_step = static_cast<bigint>(list[2]);
  saved_step = static_cast<bigint>(list[3]);
  saved_time = list[4];
  offset_pending = 1;
  for (int b = 0; b < cfg.bins.count; b++) {
    const double *v = list + 5 + 7 * b;
    auto &g = rs.region[b];
    g.total_abs = v[0];
    g.total_dt = v[1];
    g.samples = static_cast<long>(v[2]);
    g.sum_d = v[3];
    g.sum_d2 = v[4];
    rs.count_now[b] = static_cast<long>(v[5]);
    rs.sigma_now[b] = v[6];
  }
  table = mh::depth_table(rs, cfg.bins.count);
}
