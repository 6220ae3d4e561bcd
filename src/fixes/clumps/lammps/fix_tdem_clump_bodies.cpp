// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/clump, making the bodies: insert (templates placed without overlap),
// form_bodies (the bodies molecule form and restart) and add_body. The time stepping, the
// correction and restart are in fix_tdem_clump.cpp.

#include "fix_tdem_clump.h"

#include "fixes/clumps/clump_args.h"
#include "fixes/clumps/host_bodies.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "lammps_compat.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "region.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <mpi.h>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;
using cl::Mat3;
using cl::Vec3;
/* ---------------------------------------------------------------------- */

void FixTDEMClump::add_body(tagint mol, const cl::State &s, const tagint *tags)
{
  const int b = (int) st.size();
  st.push_back(s);
  molid.push_back(mol);
  masstotal.push_back(bprop.mass);
  fsum.resize(6 * st.size(), 0.0);
  rot.push_back(cl::rotation_matrix(s.q));
  omg.push_back(cl::angular_velocity(s, bprop));
  for (int k = 0; k < nsph; k++) {
    btags.push_back(tags[k]);
    slot[tags[k]] = b * nsph + k;
  }
  size_array_rows = (int) st.size();
}

void FixTDEMClump::insert_clumps()
{
  Region *region = tdem_lammps::compat::region_by_id(domain, insert_region);
  if (!region) error->all(FLERR, where + ": insert region '" + insert_region + "' does not exist");
  if (!region->bboxflag)
    error->all(FLERR, where + ": insert region '" + insert_region + "' has no bounding box (use a bounded region)");
  region->prematch();
  // existing atoms (all ranks see all): positions and radii
  const int nlocal = atom->nlocal;
  std::vector<double> mine(4 * nlocal);
  for (int i = 0; i < nlocal; i++) {
    for (int k = 0; k < 3; k++) mine[4 * i + k] = atom->x[i][k];
    mine[4 * i + 3] = atom->radius[i];
  }
  int nme = 4 * nlocal;
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&nme, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int ntot = 0;
  for (int p = 0; p < comm->nprocs; p++) {
    displs[p] = ntot;
    ntot += counts[p];
  }
  std::vector<double> old(ntot);
  MPI_Allgatherv(mine.data(), nme, MPI_DOUBLE, old.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  const int nold = ntot / 4;

  tagint maxtag = 0, maxmol = 0, all;
  for (int i = 0; i < nlocal; i++) {
    maxtag = std::max(maxtag, atom->tag[i]);
    maxmol = std::max(maxmol, atom->molecule[i]);
  }
  MPI_Allreduce(&maxtag, &all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  maxtag = all;
  MPI_Allreduce(&maxmol, &all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  maxmol = all;
  for (const tagint m : molid) maxmol = std::max(maxmol, m);

  // the placement of the core (src/fixes/clumps/host_bodies.h), as in LIGGGHTS: the same seed gives the
  // same clumps in both engines
  cl::PlacementInput in;
  in.n = ninsert;
  in.seed = (std::uint64_t) insert_seed;
  in.lo = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
  in.hi = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
  in.inside = [&](const Vec3 &p, double r) {
    if (!region->match(p[0], p[1], p[2])) return false;
    for (int k = 0; k < 3; k++)
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        Vec3 q = p;
        q[k] += sgn * r;
        if (!region->match(q[0], q[1], q[2])) return false;
      }
    return true;
  };
  in.delta = [&](const Vec3 &a, const Vec3 &b) {
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    tdem_lammps::compat::minimum_image(domain, dx, dy, dz);
    return Vec3{dx, dy, dz};
  };
  for (int i = 0; i < nold; i++) in.existing.push_back({Vec3{old[4 * i], old[4 * i + 1], old[4 * i + 2]}, old[4 * i + 3]});
  in.period = {domain->xperiodic ? domain->xprd : 0.0, domain->yperiodic ? domain->yprd : 0.0,
               domain->zperiodic ? domain->zprd : 0.0};
  const cl::PlacementResult res = cl::place_clumps(tmpl, in);
  if (!res.complete)
    error->all(FLERR, fmt::format("{}: insert: placed only {} of {} clumps in region {}: {} random attempts "
                                  "in a row found no free place (region too small or too full); use a larger "
                                  "region or a smaller N",
                                  where, res.bodies.size(), ninsert, insert_region, in.max_failures));
  std::vector<cl::State> newbodies = res.bodies;
  for (auto &s : newbodies) {
    s.v = {insert_vel[0], insert_vel[1], insert_vel[2]};
    s.L = {0, 0, 0};
  }
  const std::vector<Vec3> &placed = res.spheres;  // sphere centres of the new clumps (unwrapped)

  // create the spheres this rank owns
  const int nprev = atom->nlocal;
  bigint mycreated = 0;
  double *sublo = domain->sublo, *subhi = domain->subhi;
  for (int b = 0; b < ninsert; b++) {
    std::vector<tagint> tags(nsph);
    const tagint mol = maxmol + 1 + b;
    for (int k = 0; k < nsph; k++) tags[k] = maxtag + 1 + (tagint) b * nsph + k;
    add_body(mol, newbodies[b], tags.data());
    const cl::State &s = newbodies[b];
    const Vec3 w = cl::angular_velocity(s, bprop);
    for (int k = 0; k < nsph; k++) {
      const Vec3 xu = placed[(std::size_t) b * nsph + k];
      double xw[3] = {xu[0], xu[1], xu[2]};
      imageint img = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
      domain->remap(xw, img);
      bool own = true;
      for (int dd = 0; dd < 3; dd++) {
        const bool top = subhi[dd] == domain->boxhi[dd];  // the upper end of a non-periodic box belongs here
        if (!(xw[dd] >= sublo[dd] && (xw[dd] < subhi[dd] || (top && !domain->periodicity[dd] && xw[dd] <= subhi[dd]))))
          own = false;
      }
      if (!own) continue;
      atom->avec->create_atom(insert_type, xw);
      const int n = atom->nlocal - 1;
      atom->tag[n] = tags[k];
      atom->molecule[n] = mol;
      atom->image[n] = img;
      atom->mask[n] |= groupbit;
      atom->radius[n] = tmpl.body[k].r;
      atom->rmass[n] = sphere_mass[k];
      const Vec3 vi = cl::add(s.v, cl::cross(w, cl::sub(xu, s.x)));
      for (int dd = 0; dd < 3; dd++) {
        atom->v[n][dd] = vi[dd];
        atom->omega[n][dd] = w[dd];
      }
      mycreated++;
    }
  }
  bigint created = 0;
  MPI_Allreduce(&mycreated, &created, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (created != (bigint) ninsert * nsph)
    error->all(FLERR, fmt::format("{}: insert: {} spheres created instead of {} (a sphere outside every "
                                  "subdomain: is the region inside the box?)",
                                  where, created, (bigint) ninsert * nsph));
  atom->natoms += created;
  atom->data_fix_compute_variable(nprev, atom->nlocal);
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
  if (comm->me == 0)
    utils::logmesg(lmp, fmt::format("{}: inserted {} clumps ({} spheres) in region {} after {} attempts; "
                                    "molecule IDs {}-{}, atom IDs {}-{}\n",
                                    where, ninsert, created, insert_region, res.attempts, maxmol + 1, maxmol + ninsert,
                                    maxtag + 1, maxtag + created));
}

// Bodies from the group's molecules that are not bodies yet (tag order = template order).
void FixTDEMClump::form_bodies()
{
  const int nlocal = atom->nlocal;
  constexpr int W = 12;  // tag, mol, xu3, v3, omega3, radius
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || atom->molecule[i] <= 0) continue;
    if (slot.count(atom->tag[i])) continue;
    double xu[3];
    unwrapped(i, xu);
    const double row[W] = {(double) atom->tag[i], (double) atom->molecule[i], xu[0], xu[1], xu[2], atom->v[i][0],
                           atom->v[i][1], atom->v[i][2], atom->omega[i][0], atom->omega[i][1], atom->omega[i][2],
                           atom->radius[i]};
    mine.insert(mine.end(), row, row + W);
  }
  int nme = (int) mine.size();
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&nme, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int ntot = 0;
  for (int p = 0; p < comm->nprocs; p++) {
    displs[p] = ntot;
    ntot += counts[p];
  }
  std::vector<double> rows(ntot);
  MPI_Allgatherv(mine.data(), nme, MPI_DOUBLE, rows.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  std::map<tagint, std::vector<const double *>> mols;
  for (int k = 0; k < ntot / W; k++) mols[(tagint) rows[W * k + 1]].push_back(&rows[W * k]);
  for (const tagint m : molid)
    if (mols.count(m))
      error->all(FLERR, fmt::format("{}: molecule {} is already a body; its spheres must not change", where, m));
  int nnew = 0;
  for (auto &kv : mols) {
    auto &v = kv.second;
    std::sort(v.begin(), v.end(), [](const double *a, const double *b) { return a[0] < b[0]; });
    if ((int) v.size() != nsph)
      error->all(FLERR, fmt::format("{}: molecule {} has {} spheres in group {}, template {} has {}", where, kv.first,
                                    v.size(), group->names[igroup], tmpl.name, nsph));
    std::vector<tagint> tags(nsph);
    for (int k = 0; k < nsph; k++) {
      tags[k] = (tagint) v[k][0];
      const double r = tmpl.body[k].r;
      if (std::fabs(v[k][11] - r) > 1e-6 * r)
        error->all(FLERR, fmt::format("{}: atom {} (molecule {}) has radius {} but sphere {} of template {} has "
                                      "radius {}",
                                      where, tags[k], kv.first, v[k][11], k + 1, tmpl.name, r));
    }
    // orientation (Horn's quaternion) and velocities (least squares) of the core, as in LIGGGHTS
    std::vector<Vec3> p(nsph), vel(nsph), om(nsph);
    for (int k = 0; k < nsph; k++) {
      p[k] = {v[k][2], v[k][3], v[k][4]};
      vel[k] = {v[k][5], v[k][6], v[k][7]};
      om[k] = {v[k][8], v[k][9], v[k][10]};
    }
    cl::BodyFit fit;
    try {
      fit = cl::fit_body(tmpl, bprop, p, vel, om);
    } catch (const std::exception &ex) {
      error->all(FLERR, where + ": internal error: " + ex.what());
    }
    if (fit.residual > 1e-6 * tmpl.bounding_radius)
      error->all(FLERR, fmt::format("{}: the spheres of molecule {} (atom IDs {}..., in ID order) are not a rigid "
                                    "copy of template {}: largest distance {} from the best fit (allowed {})",
                                    where, kv.first, tags[0], tmpl.name, fit.residual, 1e-6 * tmpl.bounding_radius));
    const cl::State &s = fit.state;
    add_body(kv.first, s, tags.data());
    nnew++;
  }
  if (comm->me == 0)
    utils::logmesg(lmp, fmt::format("{}: {} bodies formed from the molecules of group {} ({} bodies in all)\n", where,
                                    nnew, group->names[igroup], st.size()));
}
