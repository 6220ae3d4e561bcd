// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: what the clump fixes of both engines do with their atoms and ranks besides the bodies
// (body_set.h): rows gathered from every rank, the rows that form bodies, the spheres of an
// insertion, which rank owns a new sphere, the fix's output flags. Templated on the engine's Atom
// and Fix, so that no engine header is needed here.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "fixes/clumps/body_making.h"
#include "fixes/clumps/body_output.h"
#include "fixes/clumps/body_set.h"
#include "fixes/clumps/clump_args.h"

namespace tdem {
namespace clumps {

// The largest value of v[0..n) over all ranks (0 if there is none), as int64.
template <class T>
std::int64_t max_over_ranks(MPI_Comm comm, int n, const T* v) {
  std::int64_t m = 0, all = 0;
  for (int i = 0; i < n; i++) m = std::max(m, static_cast<std::int64_t>(v[i]));
  MPI_Allreduce(&m, &all, 1, MPI_INT64_T, MPI_MAX, comm);
  return all;
}

// The output, integration and communication flags of a fix tdem/clump (an engine's Fix): scalar =
// kinetic energy, vector of 9 (BodyOutput::vector), one array row per body (BodyOutput::array), a
// global restart record (counts, flags) and per-atom records (the body state each sphere carries),
// forward communication of the BodySet, exchange records.
template <class FixT>
void declare_clump_fix(FixT* f) {
  f->time_integrate = 1;
  f->restart_global = 1;
  f->restart_peratom = 1;
  f->comm_forward = BodySet::kCommMax;
  f->scalar_flag = 1;
  f->extscalar = 1;
  f->vector_flag = 1;
  f->size_vector = 9;
  f->extvector = 1;
  f->array_flag = 1;
  f->size_array_cols = BodyOutput::kArrayColumns;
  f->size_array_rows = 0;
  f->extarray = 0;
  f->global_freq = 1;
}

// The rows of form(): the atoms of group bit `groupbit` with a molecule ID > 0 that are not clump
// spheres yet; unmap(i, xu) gives the unwrapped position of atom i.
template <class TagT, class MolT, class Unmap>
std::vector<double> form_rows(const BodySet& set, int nlocal, const int* mask, int groupbit, const TagT* tag,
                              const MolT* molecule, Unmap unmap, double* const* v, double* const* omega,
                              const double* radius) {
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || molecule[i] <= 0 || set.is_sphere(i)) continue;
    double xu[3];
    unmap(i, xu);
    const double row[BodySet::kFormRow] = {static_cast<double>(tag[i]), static_cast<double>(molecule[i]), xu[0], xu[1],
                                           xu[2], v[i][0], v[i][1], v[i][2], omega[i][0], omega[i][1], omega[i][2],
                                           radius[i]};
    mine.insert(mine.end(), row, row + BodySet::kFormRow);
  }
  return mine;
}

// The spheres of all ranks (centre, radius) for the overlap test of an insertion.
inline std::vector<Sphere> all_spheres(MPI_Comm comm, int nlocal, double* const* x, const double* radius) {
  std::vector<double> mine(4 * static_cast<std::size_t>(nlocal));
  for (int i = 0; i < nlocal; i++) {
    for (int k = 0; k < 3; k++) mine[4 * i + k] = x[i][k];
    mine[4 * i + 3] = radius[i];
  }
  const std::vector<double> all = allgather_rows(comm, mine);
  std::vector<Sphere> out;
  for (std::size_t i = 0; i < all.size() / 4; i++) out.push_back({Vec3{all[4 * i], all[4 * i + 1], all[4 * i + 2]}, all[4 * i + 3]});
  return out;
}

// Does a sphere lie in a region (match(x, y, z)) with its six extreme points? (insertion)
template <class Match>
bool sphere_inside(Match match, const Vec3& p, double r) {
  if (!match(p[0], p[1], p[2])) return false;
  for (int k = 0; k < 3; k++)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      Vec3 q = p;
      q[k] += sgn * r;
      if (!match(q[0], q[1], q[2])) return false;
    }
  return true;
}

// The spheres of `a.ninsert` clumps placed in an engine's Region (its bounding box and match())
// without overlap with each other and with the spheres of every rank (minimum_image(d) the
// minimum image in place, period: the box length of each periodic direction, else 0), as new
// bodies of `set` numbered after the largest tag and molecule ID of any rank. Throws if the
// region has no bounding box.
template <class AtomT, class RegionT, class MinImage>
Inserted insert_clumps(BodySet& set, const ClumpArgs& a, MPI_Comm world, const AtomT* atom,
                                     RegionT* region, MinImage minimum_image, const Vec3& period) {
  if (!region->bboxflag)
    throw std::runtime_error(set.where() + ": insert region '" + a.insert_region +
                             "' has no bounding box (use a bounded region)");
  region->prematch();
  const double lo[3] = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
  const double hi[3] = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
  auto match = [&](double x, double y, double z) { return region->match(x, y, z) != 0; };
  PlacementInput in;
  in.n = a.ninsert;
  in.seed = static_cast<std::uint64_t>(a.insert_seed);
  in.lo = {lo[0], lo[1], lo[2]};
  in.hi = {hi[0], hi[1], hi[2]};
  in.inside = [&](const Vec3& p, double r) { return sphere_inside(match, p, r); };
  in.delta = [&](const Vec3& p, const Vec3& q) {
    double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    minimum_image(d);
    return Vec3{d[0], d[1], d[2]};
  };
  in.existing = all_spheres(world, atom->nlocal, atom->x, atom->radius);
  in.period = period;
  return insert_bodies(set, in, Vec3{a.insert_vel[0], a.insert_vel[1], a.insert_vel[2]},
                       max_over_ranks(world, atom->nlocal, atom->tag), max_over_ranks(world, atom->nlocal, atom->molecule),
                       a.insert_region);
}

// The box length of each periodic direction of an engine's Domain, else 0.
template <class DomainT>
Vec3 periods(const DomainT* d) {
  return Vec3{d->xperiodic ? d->xprd : 0.0, d->yperiodic ? d->yprd : 0.0, d->zperiodic ? d->zprd : 0.0};
}

// A clump fix's global restart record: magic, body count, spheres per body, the fix's own flags
// (the bodies travel in the per-atom records, BodySet::pack_restart), written as the engines read
// it back (its size in bytes, then the doubles). Rank 0 writes.
inline void write_restart_record(std::FILE* fp, const BodySet& set, double magic, std::initializer_list<double> flags) {
  std::vector<double> buf = {magic, static_cast<double>(set.size()), static_cast<double>(set.nsph())};
  buf.insert(buf.end(), flags);
  const int size = static_cast<int>(buf.size() * sizeof(double));
  std::fwrite(&size, sizeof(int), 1, fp);
  std::fwrite(buf.data(), sizeof(double), buf.size(), fp);
}

// Reads a record of write_restart_record() with nflags flags into set and flags, or a record of the
// global-bodies version (magic `legacy`: every body follows the flags, kRow or kRowForce doubles
// with_force, and its tags; the bodies go to their spheres at the next set-up); throws `not_ours`
// if the magic is neither.
inline void read_restart_record(const char* raw, BodySet& set, double magic, double legacy, double* flags, int nflags,
                                bool with_force, const std::string& not_ours) {
  const double* buf = reinterpret_cast<const double*>(raw);
  if (buf[0] != magic && buf[0] != legacy) throw std::runtime_error(not_ours);
  std::copy(buf + 3, buf + 3 + nflags, flags);
  if (buf[0] == legacy) {
    set.unpack_global_bodies(buf + 3 + nflags, static_cast<int>(buf[1]), static_cast<int>(buf[2]), with_force);
    return;
  }
  if (static_cast<int>(buf[2]) != set.nsph())
    throw std::runtime_error(set.where() + ": the restart file has clumps of " + std::to_string(static_cast<int>(buf[2])) +
                             " spheres, template " + set.tmpl().name + " has " + std::to_string(set.nsph()));
  set.set_size(static_cast<std::int64_t>(buf[1]));
}

// Bodies from the molecules of the group atoms that are not clump spheres yet (rows of form_rows()
// of this rank): the rows and the keys of the existing bodies are gathered from every rank, every
// rank fits the same bodies and gives them to the spheres it owns. Returns the number of new bodies.
template <class TagT>
int form_and_adopt(BodySet& set, MPI_Comm world, const std::vector<double>& mine, const std::string& group,
                   int nlocal, const TagT* tag) {
  std::vector<double> keys;  // the molecule IDs of the bodies whose spheres this rank owns
  for (int i = 0; i < nlocal; i++)
    if (set.is_sphere(i)) keys.push_back(static_cast<double>(set.body_key()[i]));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<std::int64_t> existing;
  for (const double k : allgather_rows(world, keys)) existing.push_back(static_cast<std::int64_t>(k));
  const std::vector<NewBody> made = form_bodies(set, allgather_rows(world, mine), group, existing);
  set.adopt(made, nlocal, tag);
  return static_cast<int>(made.size());
}

// Is the remapped point xw in the sub-domain [lo, hi)? top[d]: this rank holds the upper end of a
// non-periodic box in direction d, which belongs to it.
inline bool owns_point(const double* xw, const double* lo, const double* hi, const bool* top_closed) {
  for (int d = 0; d < 3; d++)
    if (!(xw[d] >= lo[d] && (xw[d] < hi[d] || (top_closed[d] && xw[d] <= hi[d])))) return false;
  return true;
}

// The engine's packing of the three periodic image counts into one integer (IMGMASK, IMGBITS,
// IMG2BITS, IMGMAX of its lmptype.h).
struct ImageBits {
  long long mask;
  int bits, bits2, max;
};

// Owned spheres of an engine's Atom from their bodies: x (if positions, with the image flags), v,
// omega (BodySet::set_spheres); prd the box lengths.
template <class AtomT>
void set_spheres(const BodySet& set, AtomT* atom, const double* prd, const ImageBits& ib, bool positions) {
  const auto* image = atom->image;
  set.set_spheres(
      atom->nlocal, atom->x, atom->v, atom->omega, prd,
      [&](int i, int* box) {
        const long long img = static_cast<long long>(image[i]);
        box[0] = static_cast<int>(img & ib.mask) - ib.max;
        box[1] = static_cast<int>(img >> ib.bits & ib.mask) - ib.max;
        box[2] = static_cast<int>(img >> ib.bits2) - ib.max;
      },
      positions);
}

// Creates the spheres of an insertion that this rank owns: create(s) makes the atom of sphere s
// if this rank owns its place (remapped into the box, with its image flags) and returns its index,
// else -1; the tag, molecule, group, radius, mass share, velocity and spin are set here. Returns
// the number of spheres created on all ranks.
template <class AtomT, class Create>
std::int64_t create_spheres(BodySet& set, AtomT* atom, const std::vector<NewSphere>& spheres, int groupbit,
                            MPI_Comm world, Create create) {
  using Tag = std::remove_reference_t<decltype(atom->tag[0])>;
  using Mol = std::remove_reference_t<decltype(atom->molecule[0])>;
  std::int64_t mine = 0, all = 0;
  for (const NewSphere& s : spheres) {
    const int n = create(s);
    if (n < 0) continue;
    atom->tag[n] = static_cast<Tag>(s.tag);
    atom->molecule[n] = static_cast<Mol>(s.mol);
    atom->mask[n] |= groupbit;
    atom->radius[n] = set.tmpl().body[s.sphere].r;
    atom->rmass[n] = set.sphere_mass()[s.sphere];
    for (int d = 0; d < 3; d++) {
      atom->v[n][d] = s.v[d];
      atom->omega[n][d] = 0.0;
    }
    set.set_atom(n, s.mol, s.sphere, s.body);
    mine++;
  }
  MPI_Allreduce(&mine, &all, 1, MPI_INT64_T, MPI_SUM, world);
  return all;
}

}  // namespace clumps
}  // namespace tdem
