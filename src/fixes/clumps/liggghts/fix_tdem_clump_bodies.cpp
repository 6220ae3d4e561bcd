// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/clump, making the bodies: insert (templates placed without
// overlap), form_bodies (the bodies molecule form and restart) and add_body; and the
// multiple-contact correction (setup_correction, the per-step contact tally, prepare). The time
// stepping and restart are in fix_tdem_clump.cpp.
#include "fix_tdem_clump.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "primitive_wall.h"
#include "region.h"
#include "update.h"

#include "fixes/clumps/clump_args.h"
#include "fixes/clumps/host_bodies.h"
#include "tdem_liggghts_ids.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;
using cl::Mat3;
using cl::Vec3;

namespace {
// side ids of the contact tally: body index >= 0, free sphere -(tag + 1), wall kWallSide + fix index
constexpr std::int64_t kWallSide = std::int64_t(1) << 40;

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}
}  // namespace

/* ---------------------------------------------------------------------- bodies */

void FixTDEMClump::add_body(int mol, const cl::State& s, const int* tags) {
  const int b = static_cast<int>(st_.size());
  st_.push_back(s);
  molid_.push_back(mol);
  fsum_.resize(6 * st_.size(), 0.0);
  rot_.push_back(cl::rotation_matrix(s.q));
  omg_.push_back(cl::angular_velocity(s, bprop_));
  for (int k = 0; k < nsph_; k++) {
    btags_.push_back(tags[k]);
    slot_[tags[k]] = b * nsph_ + k;
  }
  size_array_rows = static_cast<int>(st_.size());
}

void FixTDEMClump::insert_clumps() {
  const int iregion = domain->find_region(insert_region_.c_str());
  if (iregion < 0) fail(where_ + ": keyword 'insert': region '" + insert_region_ + "' does not exist");
  Region* region = domain->regions[iregion];
  if (!region->bboxflag)
    fail(where_ + ": keyword 'insert': region '" + insert_region_ + "' has no bounding box (use a bounded region)");
  region->prematch();
  // existing spheres: every rank sees all
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

  int maxtag = 0, maxmol = 0, all = 0;
  for (int i = 0; i < nlocal; i++) {
    maxtag = std::max(maxtag, atom->tag[i]);
    maxmol = std::max(maxmol, atom->molecule[i]);
  }
  MPI_Allreduce(&maxtag, &all, 1, MPI_INT, MPI_MAX, world);
  maxtag = all;
  MPI_Allreduce(&maxmol, &all, 1, MPI_INT, MPI_MAX, world);
  maxmol = all;
  for (const int m : molid_) maxmol = std::max(maxmol, m);

  cl::PlacementInput in;
  in.n = ninsert_;
  in.seed = static_cast<std::uint64_t>(insert_seed_);
  in.lo = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
  in.hi = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
  in.inside = [&](const Vec3& p, double r) {
    if (!region->match(p[0], p[1], p[2])) return false;
    for (int k = 0; k < 3; k++)
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        Vec3 q = p;
        q[k] += sgn * r;
        if (!region->match(q[0], q[1], q[2])) return false;
      }
    return true;
  };
  in.delta = [&](const Vec3& a, const Vec3& b) {
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    domain->minimum_image(dx, dy, dz);
    return Vec3{dx, dy, dz};
  };
  for (int i = 0; i < ntot / 4; i++) in.existing.push_back({Vec3{old[4 * i], old[4 * i + 1], old[4 * i + 2]}, old[4 * i + 3]});
  in.period = {domain->xperiodic ? domain->xprd : 0.0, domain->yperiodic ? domain->yprd : 0.0,
               domain->zperiodic ? domain->zprd : 0.0};
  const cl::PlacementResult res = cl::place_clumps(tmpl_, in);
  if (!res.complete)
    fail(where_ + ": keyword 'insert': placed only " + std::to_string(res.bodies.size()) + " of " +
         std::to_string(ninsert_) + " clumps in region " + insert_region_ + ": " + std::to_string(in.max_failures) +
         " random attempts in a row found no free place (region too small or too full); use a larger region or a "
         "smaller N");

  const int nprev = atom->nlocal;
  int mycreated = 0;
  const double *sublo = domain->sublo, *subhi = domain->subhi;
  for (int b = 0; b < ninsert_; b++) {
    std::vector<int> tags(nsph_);
    const int mol = maxmol + 1 + b;
    for (int k = 0; k < nsph_; k++) tags[k] = maxtag + 1 + b * nsph_ + k;
    cl::State s = res.bodies[b];
    s.v = {insert_vel_[0], insert_vel_[1], insert_vel_[2]};
    s.L = {0, 0, 0};
    add_body(mol, s, tags.data());
    for (int k = 0; k < nsph_; k++) {
      const Vec3& xu = res.spheres[static_cast<std::size_t>(b) * nsph_ + k];
      double xw[3] = {xu[0], xu[1], xu[2]};
      tagint img = (static_cast<tagint>(IMGMAX) << IMG2BITS) | (static_cast<tagint>(IMGMAX) << IMGBITS) | IMGMAX;
      domain->remap(xw, img);
      bool own = true;
      for (int dd = 0; dd < 3; dd++) {
        const bool top = comm->myloc[dd] == comm->procgrid[dd] - 1;
        if (!(xw[dd] >= sublo[dd] && (xw[dd] < subhi[dd] || (top && !domain->periodicity[dd] && xw[dd] <= subhi[dd]))))
          own = false;
      }
      if (!own) continue;
      atom->avec->create_atom(insert_type_, xw);
      const int i = atom->nlocal - 1;
      atom->tag[i] = tags[k];
      atom->molecule[i] = mol;
      atom->image[i] = img;
      atom->mask[i] |= groupbit;
      atom->radius[i] = tmpl_.body[k].r;
      atom->rmass[i] = sphere_mass_[k];
      for (int dd = 0; dd < 3; dd++) {
        atom->v[i][dd] = s.v[dd];
        atom->omega[i][dd] = 0.0;
      }
      mycreated++;
    }
  }
  int created = 0;
  MPI_Allreduce(&mycreated, &created, 1, MPI_INT, MPI_SUM, world);
  if (created != ninsert_ * nsph_)
    fail(where_ + ": keyword 'insert': " + std::to_string(created) + " spheres created instead of " +
         std::to_string(ninsert_ * nsph_) + " (a sphere outside every subdomain: is region " + insert_region_ +
         " inside the box?)");
  atom->natoms += created;
  for (int m = 0; m < modify->nfix; m++) {
    Fix* f = modify->fix[m];
    if (!f->create_attribute) continue;
    f->pre_set_arrays();
    for (int i = nprev; i < atom->nlocal; i++) f->set_arrays(i);
  }
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
  log(where_ + ": inserted " + std::to_string(ninsert_) + " clumps (" + std::to_string(created) +
      " spheres) in region " + insert_region_ + " after " + std::to_string(res.attempts) + " attempts; molecule IDs " +
      std::to_string(maxmol + 1) + "-" + std::to_string(maxmol + ninsert_) + ", atom IDs " +
      std::to_string(maxtag + 1) + "-" + std::to_string(maxtag + created) + "\n");
}

// Bodies from the group's molecules that are not bodies yet (atom ID order = template order).
int FixTDEMClump::form_bodies() {
  const int nlocal = atom->nlocal;
  constexpr int W = 12;  // tag, mol, xu3, v3, omega3, radius
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || atom->molecule[i] <= 0) continue;
    if (slot_.count(atom->tag[i])) continue;
    double xu[3];
    domain->unmap(atom->x[i], atom->image[i], xu);
    const double row[W] = {static_cast<double>(atom->tag[i]), static_cast<double>(atom->molecule[i]), xu[0], xu[1],
                           xu[2], atom->v[i][0], atom->v[i][1], atom->v[i][2], atom->omega[i][0], atom->omega[i][1],
                           atom->omega[i][2], atom->radius[i]};
    mine.insert(mine.end(), row, row + W);
  }
  int nme = static_cast<int>(mine.size());
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&nme, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int ntot = 0;
  for (int p = 0; p < comm->nprocs; p++) {
    displs[p] = ntot;
    ntot += counts[p];
  }
  std::vector<double> rows(ntot);
  MPI_Allgatherv(mine.data(), nme, MPI_DOUBLE, rows.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  std::map<int, std::vector<const double*>> mols;
  for (int k = 0; k < ntot / W; k++) mols[static_cast<int>(rows[W * k + 1])].push_back(&rows[W * k]);
  for (const int m : molid_)
    if (mols.count(m)) fail(where_ + ": molecule " + std::to_string(m) + " is already a body; its spheres must not change");
  int nnew = 0;
  for (auto& kv : mols) {
    auto& v = kv.second;
    std::sort(v.begin(), v.end(), [](const double* a, const double* b) { return a[0] < b[0]; });
    if (static_cast<int>(v.size()) != nsph_)
      fail(where_ + ": molecule " + std::to_string(kv.first) + " has " + std::to_string(v.size()) +
           " spheres in group " + group->names[igroup] + ", template " + tmpl_.name + " has " + std::to_string(nsph_));
    std::vector<int> tags(nsph_);
    std::vector<Vec3> p(nsph_), vel(nsph_), om(nsph_);
    for (int k = 0; k < nsph_; k++) {
      tags[k] = static_cast<int>(v[k][0]);
      const double r = tmpl_.body[k].r;
      if (std::fabs(v[k][11] - r) > 1e-6 * r)
        fail(where_ + ": atom " + std::to_string(tags[k]) + " (molecule " + std::to_string(kv.first) + ") has radius " +
             num(v[k][11]) + " but sphere " + std::to_string(k + 1) + " of template " + tmpl_.name + " has radius " +
             num(r));
      p[k] = {v[k][2], v[k][3], v[k][4]};
      vel[k] = {v[k][5], v[k][6], v[k][7]};
      om[k] = {v[k][8], v[k][9], v[k][10]};
    }
    cl::BodyFit fit;
    try {
      fit = cl::fit_body(tmpl_, bprop_, p, vel, om);
    } catch (const std::exception& e) {
      fail(where_ + ": molecule " + std::to_string(kv.first) + ": " + e.what());
    }
    const double allowed = 1e-6 * tmpl_.bounding_radius;
    if (fit.residual > allowed)
      fail(where_ + ": the spheres of molecule " + std::to_string(kv.first) + " (atom IDs " + std::to_string(tags[0]) +
           "..., in ID order) are not a rigid copy of template " + tmpl_.name + ": largest distance " +
           num(fit.residual) + " from the best fit (allowed " + num(allowed) + ")");
    add_body(kv.first, fit.state, tags.data());
    nnew++;
  }
  if (nnew > 0)
    log(where_ + ": " + std::to_string(nnew) + " bodies formed from the molecules of group " + group->names[igroup] +
        " (" + std::to_string(st_.size()) + " bodies in all)\n");
  return nnew;
}

/* ---------------------------------------------------------------------- multiple-contact correction */

// The granular pair and the wall/gran fixes whose contacts are tallied. The correction acts through
// the surface model tdem/clump (surface_model_tdem_clump.h): a pair style or wall/gran fix without
// it is an error (its clump contacts would silently stay uncorrected).
void FixTDEMClump::setup_correction() {
  const std::string what = where_ + ": keyword 'correction " + std::string(cl::to_string(correction_)) + "': ";
  pair_gran_ = force->pair ? dynamic_cast<PairGran*>(force->pair) : nullptr;
  if (force->pair && !pair_gran_)
    fail(what + "pair style '" + std::string(force->pair_style) +
         "' is not a granular pair style (pair_style gran model ... surface tdem/clump)");
  if (pair_gran_ && !pair_gran_->contact_match("surface", tdem::liggghts::kSurfaceClumpName))
    fail(what + "pair style '" + std::string(force->pair_style) +
         "' has no 'surface tdem/clump'; add 'surface tdem/clump' to its contact model (pair_style gran model M "
         "tangential T surface tdem/clump), through which the correction acts");
  walls_.clear();
  wall_sides_.clear();
  for (int m = 0; m < modify->nfix; m++) {
    Fix* f = modify->fix[m];
    if (std::strncmp(f->style, "wall/gran", 9) != 0) continue;
    FixWallGran* w = static_cast<FixWallGran*>(f);
    const void* owner = static_cast<LIGGGHTS::IContactHistorySetup*>(w);
    if (!w->contact_match("surface", tdem::liggghts::kSurfaceClumpName))
      fail(what + "fix " + std::string(f->id) + " (" + std::string(f->style) +
           ") has no 'surface tdem/clump'; add 'surface tdem/clump' to its contact model (fix ID group wall/gran "
           "model M tangential T surface tdem/clump ...), through which the correction acts");
    if (w->is_mesh_wall()) {
      if (correction_ == cl::Correction::count || correction_ == cl::Correction::overlap_share)
        fail(what + "fix " + std::string(f->id) + " is a mesh wall; count and overlap support primitive walls only "
                                                    "(allowed with meshes: none, local_mass)");
      continue;
    }
    walls_.push_back(w);
    wall_sides_.push_back({owner, kWallSide + m});
  }
  // overlaps are at most a sphere diameter (the tally's fixed point resolves 2^-80 of it)
  double dmax = 0.0;
  for (const auto& s : tmpl_.body) dmax = std::max(dmax, 2.0 * s.r);
  for (int i = 0; i < atom->nlocal; i++) dmax = std::max(dmax, 2.0 * atom->radius[i]);
  double all = dmax;
  MPI_Allreduce(&dmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  tally_.set_length_scale(all > 0.0 ? all : 1.0);
}

// Every touching contact with a body of this fix on at least one side, per pair of sides, global
// over the ranks (contact_tally.h). Same touching tests as the pair loop (rsq < radsum^2) and the
// primitive wall loop (resolveContact <= 0).
void FixTDEMClump::build_tally() {
  tally_.clear();
  const int nlocal = atom->nlocal;
  double** x = atom->x;
  const double* radius = atom->radius;
  const int* tag = atom->tag;
  auto side = [&](int a) -> std::int64_t {
    return bodyidx_[a] >= 0 ? std::int64_t(bodyidx_[a]) : -(std::int64_t(tag[a]) + 1);
  };
  if (pair_gran_ && pair_gran_->list) {
    NeighList* list = pair_gran_->list;
    const bool newton = force->newton_pair != 0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int* jlist = list->firstneigh[i];
      const int jnum = list->numneigh[i];
      for (int jj = 0; jj < jnum; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        if (bodyidx_[i] < 0 && bodyidx_[j] < 0) continue;
        const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
        const double rsq = dx * dx + dy * dy + dz * dz;
        const double radsum = radius[i] + radius[j];
        if (!(rsq < radsum * radsum)) continue;
        const std::int64_t a = side(i), b = side(j);
        if (a == b) continue;
        // newton off: a pair with a ghost partner is in the lists of both owners' ranks (or twice
        // on one rank across a periodic boundary): counted where tag[i] <= tag[j] (equal: two
        // images of one sphere, two contacts); the other copy only makes the pair known here
        tally_.add(a, b, radsum - std::sqrt(rsq), newton || j < nlocal || tag[i] <= tag[j]);
      }
    }
  }
  const int* mask = atom->mask;
  for (std::size_t w = 0; w < walls_.size(); w++) {
    PrimitiveWall* pw = walls_[w]->primitiveWall();
    if (!pw) continue;
    const int bit = walls_[w]->groupbit;
    for (int i = 0; i < nlocal; i++) {
      if (bodyidx_[i] < 0 || !(mask[i] & bit)) continue;
      double delta[3];
      const double d = pw->resolveContact(x[i], radius[i], delta);
      if (d <= 0.0) tally_.add(bodyidx_[i], wall_sides_[w].second, -d);
    }
  }
  cl::merge_over_ranks(tally_, world, exchange_);
}

// 1/M + (r x n).I^-1 (r x n) of the body of atom a (r: sphere centre - com; the contact point lies
// on the normal through the centre, so r x n is that of the contact point), 1/m of a free sphere.
double FixTDEMClump::inverse_side_mass(int a, const double* n) const {
  const int b = bodyidx_[a];
  if (b < 0) return 1.0 / atom->rmass[a];
  const Vec3 r = cl::mul(rot_[b], tmpl_.body[sphidx_[a]].x);
  const Vec3 rn = {r[1] * n[2] - r[2] * n[1], r[2] * n[0] - r[0] * n[2], r[0] * n[1] - r[1] * n[0]};
  const Vec3 w = cl::mul_t(rot_[b], rn);  // body frame: the principal inertia is diagonal
  return 1.0 / bprop_.mass + w[0] * w[0] / bprop_.inertia[0] + w[1] * w[1] / bprop_.inertia[1] +
         w[2] * w[2] / bprop_.inertia[2];
}

double FixTDEMClump::prepare(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const void* owner) const {
  const int i = sidata.i;
  const int bi = bodyidx_[i];
  std::int64_t a, b;
  if (sidata.is_wall) {
    if (bi < 0) return 1.0;
    if (correction_ == cl::Correction::local_mass) {
      sidata.meff = 1.0 / inverse_side_mass(i, sidata.en);
      return 1.0;
    }
    a = bi;
    b = -1;
    for (const auto& ws : wall_sides_)
      if (ws.first == owner) b = ws.second;
    if (b < 0) return 1.0;
  } else {
    const int j = sidata.j;
    const int bj = bodyidx_[j];
    if (bi < 0 && bj < 0) return 1.0;
    if (correction_ == cl::Correction::local_mass) {
      sidata.meff = 1.0 / (inverse_side_mass(i, sidata.en) + inverse_side_mass(j, sidata.en));
      return 1.0;
    }
    a = bi >= 0 ? std::int64_t(bi) : -(std::int64_t(atom->tag[i]) + 1);
    b = bj >= 0 ? std::int64_t(bj) : -(std::int64_t(atom->tag[j]) + 1);
  }
  return tally_.pair_factor(correction_, tally_.find(a, b), sidata.deltan);
}
