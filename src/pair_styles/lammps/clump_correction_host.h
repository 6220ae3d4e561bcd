// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the multiple-contact correction of fix tdem/clump as seen by the tdem pair and
// wall styles (pair tdem/gran, fix tdem/wall/gran). Header-only, reached through Fix::extract, so
// the pair and wall styles build (and run, without correction) when the clump module is off.
//
//   find_clump_correction   the clump fix and its correction (none when there is no clump fix)
//   ClumpView               per-step pointers: body index and key per atom, body mass, com, inverse
//                           inertia (space frame); inverse local mass of one side
// The global contact counts and overlap sums come from clumps/contact_tally_mpi.h
// (merge_with_neighbours; exact fixed-point sums, independent of the rank split).
#pragma once

#include "contact/multi_contact/contact_tally.h"
#include "contact/multi_contact/contact_tally_mpi.h"
#include "contact/multi_contact/multi_contact.h"

#include "comm.h"
#include "domain.h"
#include "lammps_compat.h"
#include "lammps.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "neighbor.h"

#include <cstdint>
#include <cstring>
#include <mpi.h>
#include <string>
#include <vector>

namespace tdem_lammps {

// The fix tdem/clump of the run and its correction (Correction::none: no clump fix, or no
// correction). Errors when several clump fixes exist and one has a correction (their body
// indices would collide).
inline LAMMPS_NS::Fix *find_clump_correction(LAMMPS_NS::LAMMPS *lmp, const std::string &where, int &mode) {
  mode = (int) tdem::clumps::Correction::none;
  LAMMPS_NS::Fix *found = nullptr;
  int nclump = 0;
  for (int i = 0; i < lmp->modify->nfix; i++) {
    LAMMPS_NS::Fix *f = lmp->modify->fix[i];
    const bool corr_only = std::strcmp(f->style, "tdem/correction") == 0;  // bodies of another fix
    if (std::strcmp(f->style, "tdem/clump") != 0 && !corr_only) continue;
    if (!corr_only) nclump++;
    int dim = 0;
    const int *c = (const int *) f->extract("tdem_clump_correction", dim);
    const int m = c ? *c : 0;
    if (m != (int) tdem::clumps::Correction::none) {
      if (found)
        lmp->error->all(FLERR, where + ": several fix tdem/clump with a multiple-contact correction; allowed: "
                                       "one fix tdem/clump when 'correction' is not none");
      found = f;
      mode = m;
    }
  }
  if (found && nclump > 1)
    lmp->error->all(FLERR, where + ": fix " + std::string(found->id) + " has correction " +
                               tdem::clumps::to_string((tdem::clumps::Correction) mode) +
                               ", which needs it to be the only fix tdem/clump (found " + std::to_string(nclump) + ")");
  return found;
}

// The correction as a pair or wall style keeps it: the clump fix, its mode (Correction, none:
// the plain loop), the per-step contact tally and the scratch of its MPI merge.
struct ClumpCorrection {
  LAMMPS_NS::Fix *fix = nullptr;
  int mode = 0;
  tdem::clumps::ContactTally tally;
  tdem::clumps::TallyExchange buf;

  // at init; dmax bounds the overlaps (the largest sphere diameter: the unit of the fixed-point
  // overlap sums)
  void find(LAMMPS_NS::LAMMPS *lmp, const std::string &where, double dmax) {
    fix = find_clump_correction(lmp, where, mode);
    if (!fix) mode = 0;
    if (mode != 0) tally.set_length_scale(dmax > 0.0 ? dmax : 1.0);
  }
  tdem::clumps::Correction correction() const { return (tdem::clumps::Correction) mode; }
  // count and overlap tally the contacts of a step first
  bool shares() const {
    return correction() == tdem::clumps::Correction::count || correction() == tdem::clumps::Correction::overlap_share;
  }
  tdem::clumps::TallyNeighbours near;  // the ranks whose entries this rank's pairs may need
  // the tally of this step, global for every pair this rank has: from the ranks within reach
  // (contact_tally_mpi.h), found again at every re-neighbouring; a triclinic box gathers from all
  void merge(LAMMPS_NS::LAMMPS *lmp) {
    if (lmp->comm->nprocs == 1) return;
    LAMMPS_NS::Domain *d = lmp->domain;
    if (d->triclinic) return tdem::clumps::merge_over_ranks(tally, lmp->world, buf);
    const bool periodic[3] = {d->xperiodic != 0, d->yperiodic != 0, d->zperiodic != 0};
    near.refresh(lmp->world, lmp->neighbor->ago == 0, d->sublo, d->subhi, periodic, d->prd, lmp->comm->cutghost,
                 lmp->neighbor->skin);
    tdem::clumps::merge_with_neighbours(tally, lmp->world, near, buf);
  }
};

// Per-step view of the clump fix's body data.
struct ClumpView {
  const int *body = nullptr;       // per atom (owned and ghost): local body index or -1
  const std::int64_t *key = nullptr;  // per atom: the body's molecule ID (the same on every rank)
  const double *mass = nullptr;    // per local body
  const double *com = nullptr;     // 3 per local body (local_mass)
  const double *inv_i = nullptr;   // 9 per local body (local_mass)

  void fetch(LAMMPS_NS::Fix *f, bool local_mass) {
    int dim = 0;
    body = (const int *) f->extract("tdem_clump_body", dim);
    key = (const std::int64_t *) f->extract("tdem_clump_key", dim);
    mass = (const double *) f->extract("masstotal", dim);
    com = local_mass ? (const double *) f->extract("tdem_clump_com", dim) : nullptr;
    inv_i = local_mass ? (const double *) f->extract("tdem_clump_inv_inertia", dim) : nullptr;
  }

  // 1/M + (r x n).I^-1 (r x n) of body b, r = contact point - com (minimum image), n unit normal
  double inverse_local_mass(LAMMPS_NS::Domain *domain, int b, const double *xc, const double *n) const {
    double r[3] = {xc[0] - com[3 * b], xc[1] - com[3 * b + 1], xc[2] - com[3 * b + 2]};
    tdem_lammps::compat::minimum_image(domain, r[0], r[1], r[2]);
    const double c[3] = {r[1] * n[2] - r[2] * n[1], r[2] * n[0] - r[0] * n[2], r[0] * n[1] - r[1] * n[0]};
    const double *I = inv_i + 9 * b;
    double q = 0.0;
    for (int i = 0; i < 3; i++) q += c[i] * (I[3 * i] * c[0] + I[3 * i + 1] * c[1] + I[3 * i + 2] * c[2]);
    return 1.0 / mass[b] + q;
  }
};

}  // namespace tdem_lammps
