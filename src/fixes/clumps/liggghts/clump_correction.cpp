// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: the multiple-contact correction for any bodies (see clump_correction.h).
#include "clump_correction.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "primitive_wall.h"

#include "tdem_liggghts_ids.h"

using namespace LAMMPS_NS;
namespace cl = tdem::clumps;

namespace {
// side ids of the contact tally: body key >= 1, free sphere -(tag + 1), wall kWallSide + fix index
constexpr std::int64_t kWallSide = std::int64_t(1) << 40;
}  // namespace

// The granular pair and the wall/gran fixes whose contacts are tallied. The correction acts through
// the surface model tdem/clump (surface_model_tdem_clump.h): a pair style or wall/gran fix without
// it is an error (its body contacts would silently stay uncorrected).
void ClumpCorrection::setup(cl::Correction mode, const std::string& where, double diameter) {
  mode_ = mode;
  Force* force = lmp_->force;
  auto fail = [&](const std::string& msg) { lmp_->error->all(FLERR, msg.c_str()); };
  const std::string what = where + ": keyword 'correction " + std::string(cl::to_string(mode_)) + "': ";
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
  Modify* modify = lmp_->modify;
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
      if (tallies())
        fail(what + "fix " + std::string(f->id) + " is a mesh wall; count and overlap support primitive walls only "
                                                    "(allowed with meshes: none, local_mass)");
      continue;
    }
    walls_.push_back(w);
    wall_sides_.push_back({owner, kWallSide + m});
  }
  // overlaps are at most a sphere diameter (the tally's fixed point resolves 2^-80 of it)
  double dmax = diameter;
  for (int i = 0; i < lmp_->atom->nlocal; i++) dmax = std::max(dmax, 2.0 * lmp_->atom->radius[i]);
  double all = dmax;
  MPI_Allreduce(&dmax, &all, 1, MPI_DOUBLE, MPI_MAX, lmp_->world);
  tally_.set_length_scale(all > 0.0 ? all : 1.0);
}

// a side of the tally: the body key (>= 1), or -(tag + 1) for a free sphere; kept per atom (owned and
// ghost) by tally() for this step's contacts
std::int64_t ClumpCorrection::side(int a) const { return side_[a]; }

// Every touching contact with a body on at least one side, per pair of sides, global over the
// ranks (contact_tally.h). Same touching tests as the pair loop (rsq < radsum^2) and the primitive
// wall loop (resolveContact <= 0).
void ClumpCorrection::tally() {
  tally_.clear();
  Atom* atom = lmp_->atom;
  const int nlocal = atom->nlocal;
  double** x = atom->x;
  const double* radius = atom->radius;
  const int* tag = atom->tag;
  const int nall = nlocal + atom->nghost;
  if (static_cast<int>(side_.size()) < nall) side_.resize(atom->nmax > nall ? atom->nmax : nall);
  for (int a = 0; a < nall; a++) side_[a] = sides_.in_body(a) ? sides_.key(a) : -(std::int64_t(tag[a]) + 1);
  if (pair_gran_ && pair_gran_->list) {
    NeighList* list = pair_gran_->list;
    const bool newton = lmp_->force->newton_pair != 0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int* jlist = list->firstneigh[i];
      const int jnum = list->numneigh[i];
      const std::int64_t a = side_[i];
      for (int jj = 0; jj < jnum; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        const std::int64_t b = side_[j];
        if (a < 0 && b < 0) continue;  // two free spheres
        const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
        const double rsq = dx * dx + dy * dy + dz * dz;
        const double radsum = radius[i] + radius[j];
        if (!(rsq < radsum * radsum)) continue;
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
      if (side_[i] < 0 || !(mask[i] & bit)) continue;
      double delta[3];
      const double d = pw->resolveContact(x[i], radius[i], delta);
      if (d <= 0.0) tally_.add(side_[i], wall_sides_[w].second, -d);
    }
  }
  // global per pair this rank has, from the ranks within reach (contact_tally_mpi.h), found again at
  // every re-neighbouring; a triclinic box gathers from all
  if (lmp_->comm->nprocs == 1) return;
  Domain* d = lmp_->domain;
  if (d->triclinic) return cl::merge_over_ranks(tally_, lmp_->world, exchange_);
  const bool periodic[3] = {d->xperiodic != 0, d->yperiodic != 0, d->zperiodic != 0};
  near_.refresh(lmp_->world, lmp_->neighbor->ago == 0, d->sublo, d->subhi, periodic, d->prd, lmp_->comm->cutghost,
                lmp_->neighbor->skin);
  cl::merge_with_neighbours(tally_, lmp_->world, near_, exchange_);
}

// 1/M + (r x n).I^-1 (r x n) of the body of atom a, 1/m of a free sphere
double ClumpCorrection::inverse_mass(int a, const double* n) const {
  return sides_.in_body(a) ? sides_.inverse_side_mass(a, n) : 1.0 / lmp_->atom->rmass[a];
}

double ClumpCorrection::prepare(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const void* owner) const {
  const int i = sidata.i;
  const bool bi = sides_.in_body(i);
  std::int64_t a, b;
  if (sidata.is_wall) {
    if (!bi) return 1.0;
    if (mode_ == cl::Correction::local_mass) {
      sidata.meff = 1.0 / inverse_mass(i, sidata.en);
      return 1.0;
    }
    a = sides_.key(i);
    b = -1;
    for (const auto& ws : wall_sides_)
      if (ws.first == owner) b = ws.second;
    if (b < 0) return 1.0;
  } else {
    const int j = sidata.j;
    if (!bi && !sides_.in_body(j)) return 1.0;
    if (mode_ == cl::Correction::local_mass) {
      sidata.meff = 1.0 / (inverse_mass(i, sidata.en) + inverse_mass(j, sidata.en));
      return 1.0;
    }
    a = side(i);
    b = side(j);
  }
  return tally_.pair_factor(mode_, tally_.find(a, b), sidata.deltan);
}
