// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/clump (see fix_tdem_clump.h and docs/clumps_liggghts.md).
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
constexpr double kRestartMagic = 20261130.0;
constexpr int kBodyDoubles = 20;  // mol, x3, v3, q4, L3, force3, torque3

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// Neighbor's molecule exclusion list is protected in LIGGGHTS 3.8: read through pointers to members
// taken in a derived class (the legal way to reach a protected member of another object).
struct NeighborExclusionPeek : public Neighbor {
  // groups of the `neigh_modify exclude molecule` entries (ex_mol_bit is set only in Neighbor::init,
  // after the fixes' init)
  static std::vector<int> molecule_groups(Neighbor* n) {
    int Neighbor::*count = &NeighborExclusionPeek::nex_mol;
    int* Neighbor::*groups = &NeighborExclusionPeek::ex_mol_group;
    std::vector<int> out;
    for (int k = 0; k < n->*count; k++) out.push_back((n->*groups)[k]);
    return out;
  }
};

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMClump::FixTDEMClump(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg),
      scheme_(cl::Rotation::splitting),
      nsph_(0),
      bodies_molecule_(false),
      restarted_(false),
      formed_(false),
      have_force_(false),
      need_set_(false),
      ninsert_(0),
      insert_type_(1),
      insert_seed_(0),
      nmax_idx_(0),
      bodyidx_(nullptr),
      sphidx_(nullptr),
      correction_(cl::Correction::none),
      pair_gran_(nullptr) {
  where_ = std::string("fix ") + id + " tdem/clump";
  insert_vel_[0] = insert_vel_[1] = insert_vel_[2] = 0.0;
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    fail(where_ + " requires atom_style sphere/granular attributes (radius, rmass, omega, torque); atom_style '" +
         std::string(atom->atom_style ? atom->atom_style : "?") + "' lacks them");
  if (!atom->molecule_flag)
    fail(where_ + " requires per-atom molecule IDs (the spheres of one body share a molecule ID): use "
                  "'atom_style hybrid sphere molecular' (atom_style '" +
         std::string(atom->atom_style ? atom->atom_style : "?") + "' has none)");
  if (domain->triclinic) fail(where_ + " supports orthogonal boxes only (the box is triclinic)");
  if (domain->dimension != 3) fail(where_ + " needs a 3d simulation (dimension is 2)");
  parse(narg, arg);

  rigid_flag = 0;  // LIGGGHTS casts fixes with rigid_flag to FixRigid in places; the body mass is not passed
  time_integrate = 1;
  restart_global = 1;
  scalar_flag = 1;
  extscalar = 1;
  vector_flag = 1;
  size_vector = 9;
  extvector = 1;
  array_flag = 1;
  size_array_cols = 17;
  size_array_rows = 0;
  extarray = 0;
  global_freq = 1;
}

FixTDEMClump::~FixTDEMClump() {
  if (tdem::liggghts::clump_link::active == this) tdem::liggghts::clump_link::active = nullptr;
  memory->destroy(bodyidx_);
  memory->destroy(sphidx_);
}

void FixTDEMClump::fail(const std::string& msg) {
  error->all(FLERR, msg.c_str());
  std::abort();  // not reached
}

void FixTDEMClump::log(const std::string& msg) {
  if (comm->me != 0) return;
  if (screen) std::fputs(msg.c_str(), screen);
  if (logfile) std::fputs(msg.c_str(), logfile);
}

int FixTDEMClump::setmask() {
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= FINAL_INTEGRATE;
  mask |= PRE_NEIGHBOR;
  if (correction_ != cl::Correction::none) mask |= PRE_FORCE;
  return mask;
}

/* ---------------------------------------------------------------------- input */

void FixTDEMClump::parse(int narg, char** arg) {
  // the arguments and the template: one parser for both engines (fixes/clumps/clump_args.h)
  cl::ClumpArgs a;
  try {
    a = cl::parse_clump_args(std::vector<std::string>(arg + 3, arg + narg), where_, atom->ntypes);
    tmpl_ = cl::clump_template(a, where_);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  scheme_ = a.scheme;
  ninsert_ = a.ninsert;
  insert_type_ = a.insert_type;
  insert_region_ = a.insert_region;
  insert_seed_ = a.insert_seed;
  for (int k = 0; k < 3; k++) insert_vel_[k] = a.insert_vel[k];
  bodies_molecule_ = a.bodies_molecule;
  correction_ = a.correction;
  const std::string name = tmpl_.name;
  bprop_ = cl::Body::from(tmpl_);
  nsph_ = static_cast<int>(tmpl_.body.size());
  sphere_mass_ = cl::sphere_masses(tmpl_);
  log(where_ + ": template " + name + " (" + std::to_string(nsph_) + " spheres): mass " + num(tmpl_.mp.mass) +
      ", principal inertia " + num(tmpl_.mp.principal[0]) + " " + num(tmpl_.mp.principal[1]) + " " +
      num(tmpl_.mp.principal[2]) + ", bounding radius " + num(tmpl_.bounding_radius) + ", rotation " +
      cl::to_string(scheme_) + ", multiple-contact correction " + cl::to_string(correction_) + "\n");
}

// Modify calls the constructor, post_create_pre_restart(), restart() (if the restart file holds a
// record of this fix) and then post_create(): insertion only without a restart record.
// Bodies from the molecules present are formed here already, so that the rows of the global array
// exist when a thermo_style or variable referring to them is defined (LIGGGHTS checks the range then).
void FixTDEMClump::post_create() {
  if (ninsert_ > 0 && !restarted_) insert_clumps();
  else if (ninsert_ > 0) log(where_ + ": bodies read from the restart file, 'insert' is skipped\n");
  if (bodies_molecule_ && !restarted_ && form_bodies() > 0) {
    have_force_ = false;
    need_set_ = true;
  }
}

// Per-atom body and sphere index of owned and ghost atoms; sphere radius and mass from the template.
void FixTDEMClump::map_atoms() {
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax_idx_) {
    nmax_idx_ = atom->nmax;
    memory->destroy(bodyidx_);
    memory->destroy(sphidx_);
    memory->create(bodyidx_, nmax_idx_, "tdem/clump:bodyidx");
    memory->create(sphidx_, nmax_idx_, "tdem/clump:sphidx");
  }
  int nmine = tdem::clumps::map_clump_atoms(nall, atom->nlocal, atom->tag, slot_, nsph_, tmpl_, sphere_mass_,
                                            bodyidx_, sphidx_, atom->radius, atom->rmass);
  int all = 0;
  MPI_Allreduce(&nmine, &all, 1, MPI_INT, MPI_SUM, world);
  if (all != static_cast<int>(st_.size()) * nsph_)
    fail(where_ + ": " + std::to_string(all) + " clump spheres found, " + std::to_string(st_.size()) + " bodies need " +
         std::to_string(st_.size() * nsph_) + " (clump spheres lost or deleted)");
  // Layout of the per-step reduction (ownership changes only here, after the exchange): a body
  // whose spheres one rank owns entirely is summed on that rank (6 doubles), a body split over
  // ranks contributes its per-sphere slots (6 nsph doubles), summed after the reduction in
  // template order - so the result is bitwise the same for any number of ranks.
  const std::size_t nb = st_.size();
  std::vector<int> cnt(nb, 0), mx(nb, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (bodyidx_[i] >= 0) cnt[bodyidx_[i]]++;
  if (comm->nprocs > 1 && nb > 0)
    MPI_Allreduce(cnt.data(), mx.data(), static_cast<int>(nb), MPI_INT, MPI_MAX, world);
  else
    mx = cnt;
  red_off_.assign(nb + 1, 0);
  split_.assign(nb, 0);
  for (std::size_t b = 0; b < nb; b++) {
    split_[b] = mx[b] < nsph_ ? 1 : 0;
    red_off_[b + 1] = red_off_[b] + (split_[b] ? 6 * nsph_ : 6);
  }
}

void FixTDEMClump::refresh_kinematics() {
  for (std::size_t b = 0; b < st_.size(); b++) {
    rot_[b] = cl::rotation_matrix(st_[b].q);
    const Vec3 pi = cl::mul_t(rot_[b], st_[b].L);
    omg_[b] = cl::mul(rot_[b], Vec3{pi[0] / bprop_.inertia[0], pi[1] / bprop_.inertia[1], pi[2] / bprop_.inertia[2]});
  }
}

/* ---------------------------------------------------------------------- run */

// Molecules that appeared since the fix was created become bodies here.
void FixTDEMClump::init() {
  if (correction_ != cl::Correction::none) {
    auto*& act = tdem::liggghts::clump_link::active;
    if (act && act != this)
      fail(where_ + ": keyword 'correction': another fix tdem/clump already applies a multiple-contact correction "
                    "(at most one fix may have a correction other than none)");
    act = this;
  }
  if (bodies_molecule_ && form_bodies() > 0) {
    formed_ = true;
    have_force_ = false;
    need_set_ = true;
  }
  // the spheres of one body must not interact with each other
  // the spheres of one body must not interact with each other: every clump sphere must be in the
  // group of a `neigh_modify exclude molecule` entry
  if (nsph_ > 1) {
    std::vector<int> bits;
    for (int g : NeighborExclusionPeek::molecule_groups(neighbor)) bits.push_back(group->bitmask[g]);
    int uncovered = 0, any = 0;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!slot_.count(atom->tag[i])) continue;
      bool covered = false;
      for (int bit : bits)
        if (atom->mask[i] & bit) covered = true;
      if (!covered) uncovered = 1;
    }
    MPI_Allreduce(&uncovered, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      fail(where_ + ": the spheres of one clump would interact with each other: add 'neigh_modify exclude molecule " +
           std::string(group->names[igroup]) + "' (or a group holding all clump spheres) before the run");
  }
  // another time integrator on the same atoms would move them twice
  for (int i = 0; i < modify->nfix; i++) {
    Fix* f = modify->fix[i];
    if (f == this || !f->time_integrate) continue;
    if (std::strcmp(f->style, "tdem/clump") == 0) continue;  // moves only its own bodies, not its group
    int mine = 0, any = 0;
    for (int j = 0; j < atom->nlocal; j++)
      if ((atom->mask[j] & f->groupbit) &&
          (slot_.count(atom->tag[j]) || (bodies_molecule_ && (atom->mask[j] & groupbit) && atom->molecule[j] > 0)))
        mine = 1;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      fail(where_ + ": fix " + std::string(f->id) + " (" + std::string(f->style) +
           ") also integrates clump spheres; exclude them from its group");
  }
}

void FixTDEMClump::setup_pre_neighbor() {
  map_atoms();
  if (need_set_) {  // bodies just formed: sphere velocities of the rigid motion
    refresh_kinematics();
    set_spheres(false);
    need_set_ = false;
  }
}

void FixTDEMClump::pre_neighbor() { map_atoms(); }

// The force of the last final_integrate if there is one (continuing run or restart), else the
// set-up force.
void FixTDEMClump::setup(int) {
  refresh_kinematics();
  if (!have_force_) sum_forces();
  have_force_ = true;
}

void FixTDEMClump::reset_dt() {}

// fsum <- force and torque about the com of every body: per-sphere slots (local), summed per body
// in template order, reduced over the ranks with the layout of map_atoms.
void FixTDEMClump::sum_forces() {
  const std::size_t nb = st_.size(), nslot = nb * nsph_;
  if (slotf_.size() != 6 * nslot) slotf_.assign(6 * nslot, 0.0);
  else std::fill(slotf_.begin(), slotf_.end(), 0.0);
  const int nlocal = atom->nlocal;
  double** f = atom->f;
  double** t = atom->torque;
  for (int i = 0; i < nlocal; i++) {
    const int b = bodyidx_[i];
    if (b < 0) continue;
    const Vec3 r = cl::mul(rot_[b], tmpl_.body[sphidx_[i]].x);
    double* fs = &slotf_[6 * (static_cast<std::size_t>(b) * nsph_ + sphidx_[i])];
    fs[0] = f[i][0];
    fs[1] = f[i][1];
    fs[2] = f[i][2];
    fs[3] = r[1] * f[i][2] - r[2] * f[i][1] + t[i][0];
    fs[4] = r[2] * f[i][0] - r[0] * f[i][2] + t[i][1];
    fs[5] = r[0] * f[i][1] - r[1] * f[i][0] + t[i][2];
  }
  auto body_sum = [&](const double* fs, double* fb) {
    for (int c = 0; c < 6; c++) fb[c] = fs[c];
    for (int k = 1; k < nsph_; k++)
      for (int c = 0; c < 6; c++) fb[c] += fs[6 * k + c];
  };
  if (comm->nprocs == 1) {
    for (std::size_t b = 0; b < nb; b++) body_sum(&slotf_[6 * b * nsph_], &fsum_[6 * b]);
    return;
  }
  red_.assign(red_off_[nb], 0.0);
  for (std::size_t b = 0; b < nb; b++) {
    const double* fs = &slotf_[6 * b * nsph_];
    double* out = &red_[red_off_[b]];
    if (split_[b]) std::copy(fs, fs + 6 * nsph_, out);
    else body_sum(fs, out);  // zero on the ranks that do not own the body
  }
  MPI_Allreduce(MPI_IN_PLACE, red_.data(), static_cast<int>(red_.size()), MPI_DOUBLE, MPI_SUM, world);
  for (std::size_t b = 0; b < nb; b++) {
    const double* in = &red_[red_off_[b]];
    if (split_[b]) body_sum(in, &fsum_[6 * b]);
    else std::copy(in, in + 6, &fsum_[6 * b]);
  }
}

// owned spheres from their bodies: x (if positions, with the image flags), v, omega
void FixTDEMClump::set_spheres(bool positions) {
  const int nlocal = atom->nlocal;
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};
  for (int i = 0; i < nlocal; i++) {
    const int b = bodyidx_[i];
    if (b < 0) continue;
    const Vec3 r = cl::mul(rot_[b], tmpl_.body[sphidx_[i]].x);
    if (positions) {
      const tagint img = atom->image[i];
      const int box[3] = {static_cast<int>(img & IMGMASK) - IMGMAX, static_cast<int>(img >> IMGBITS & IMGMASK) - IMGMAX,
                          static_cast<int>(img >> IMG2BITS) - IMGMAX};
      for (int k = 0; k < 3; k++) atom->x[i][k] = st_[b].x[k] + r[k] - box[k] * prd[k];
    }
    const Vec3& w = omg_[b];
    atom->v[i][0] = st_[b].v[0] + w[1] * r[2] - w[2] * r[1];
    atom->v[i][1] = st_[b].v[1] + w[2] * r[0] - w[0] * r[2];
    atom->v[i][2] = st_[b].v[2] + w[0] * r[1] - w[1] * r[0];
    atom->omega[i][0] = w[0];
    atom->omega[i][1] = w[1];
    atom->omega[i][2] = w[2];
  }
}

void FixTDEMClump::initial_integrate(int) {
  const double h = update->dt, c = force->ftm2v;
  for (std::size_t b = 0; b < st_.size(); b++) {
    const double* fb = &fsum_[6 * b];
    cl::initial_integrate(st_[b], bprop_, Vec3{c * fb[0], c * fb[1], c * fb[2]}, Vec3{c * fb[3], c * fb[4], c * fb[5]},
                          h, scheme_);
  }
  refresh_kinematics();
  set_spheres(true);
}

void FixTDEMClump::final_integrate() {
  sum_forces();
  const double h = update->dt, c = force->ftm2v;
  for (std::size_t b = 0; b < st_.size(); b++) {
    const double* fb = &fsum_[6 * b];
    cl::final_integrate(st_[b], bprop_, Vec3{c * fb[0], c * fb[1], c * fb[2]}, Vec3{c * fb[3], c * fb[4], c * fb[5]}, h);
  }
  refresh_kinematics();
  set_spheres(false);
}

void FixTDEMClump::setup_pre_force(int) {
  setup_correction();
  pre_force(0);
}

void FixTDEMClump::pre_force(int) {
  if (correction_ == cl::Correction::count || correction_ == cl::Correction::overlap_share) build_tally();
}

/* ---------------------------------------------------------------------- output */

double FixTDEMClump::compute_scalar() {
  double e = 0.0;
  for (const auto& s : st_) e += cl::kinetic_energy(s, bprop_);
  return e * force->mvv2e;
}

// [1] bodies, [2-4] total momentum, [5-7] sum of the bodies' angular momenta about their com,
// [8] translational, [9] rotational kinetic energy
double FixTDEMClump::compute_vector(int n) {
  if (n == 0) return static_cast<double>(st_.size());
  double out = 0.0;
  for (const auto& s : st_) {
    if (n >= 1 && n <= 3) out += bprop_.mass * s.v[n - 1];
    else if (n >= 4 && n <= 6) out += s.L[n - 4];
    else if (n == 7) out += 0.5 * bprop_.mass * cl::dot(s.v, s.v) * force->mvv2e;
    else if (n == 8) out += cl::rotational_energy(s, bprop_) * force->mvv2e;
  }
  return out;
}

// row per body: mol, x y z, vx vy vz, qw qx qy qz, Lx Ly Lz, wx wy wz
double FixTDEMClump::compute_array(int i, int j) {
  if (i < 0 || i >= static_cast<int>(st_.size())) return 0.0;
  const cl::State& s = st_[i];
  if (j == 0) return static_cast<double>(molid_[i]);
  if (j <= 3) return s.x[j - 1];
  if (j <= 6) return s.v[j - 4];
  if (j == 7) return s.q.w;
  if (j == 8) return s.q.x;
  if (j == 9) return s.q.y;
  if (j == 10) return s.q.z;
  if (j <= 13) return s.L[j - 11];
  if (j <= 16) return cl::angular_velocity(s, bprop_)[j - 14];
  return 0.0;
}

// "tdem_clump_body": int per atom (owned and ghost, valid after the first set-up), body index or -1;
// "tdem_clump_sphere": int per atom, sphere index in the template or -1;
// "tdem_clump_mass": double, the body mass (dim 0)
void* FixTDEMClump::extract(const char* name, int& dim) {
  dim = 1;
  if (std::strcmp(name, "tdem_clump_body") == 0) return static_cast<void*>(bodyidx_);
  if (std::strcmp(name, "tdem_clump_sphere") == 0) return static_cast<void*>(sphidx_);
  dim = 0;
  if (std::strcmp(name, "tdem_clump_mass") == 0) return static_cast<void*>(&bprop_.mass);
  return nullptr;
}

/* ---------------------------------------------------------------------- restart */

// magic, nbody, nsph, formed, have_force, then per body: mol, x, v, q, L, F, T, nsph tags
void FixTDEMClump::write_restart(FILE* fp) {
  if (comm->me != 0) return;
  std::vector<double> buf = {kRestartMagic, static_cast<double>(st_.size()), static_cast<double>(nsph_),
                             formed_ ? 1.0 : 0.0, have_force_ ? 1.0 : 0.0};
  for (std::size_t b = 0; b < st_.size(); b++) {
    const cl::State& s = st_[b];
    const double* F = &fsum_[6 * b];
    const double row[kBodyDoubles] = {static_cast<double>(molid_[b]), s.x[0], s.x[1], s.x[2], s.v[0], s.v[1], s.v[2],
                                      s.q.w, s.q.x, s.q.y, s.q.z, s.L[0], s.L[1], s.L[2],
                                      F[0], F[1], F[2], F[3], F[4], F[5]};
    buf.insert(buf.end(), row, row + kBodyDoubles);
    for (int k = 0; k < nsph_; k++) buf.push_back(static_cast<double>(btags_[b * nsph_ + k]));
  }
  const int size = static_cast<int>(buf.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(buf.data(), sizeof(double), buf.size(), fp);
}

void FixTDEMClump::restart(char* raw) {
  const double* buf = reinterpret_cast<const double*>(raw);
  if (buf[0] != kRestartMagic) fail(where_ + ": the restart record is not a tdem/clump record of this version");
  const int nb = static_cast<int>(buf[1]), ns = static_cast<int>(buf[2]);
  if (ns != nsph_)
    fail(where_ + ": the restart file has clumps of " + std::to_string(ns) + " spheres, template " + tmpl_.name +
         " has " + std::to_string(nsph_));
  formed_ = buf[3] != 0.0;
  have_force_ = buf[4] != 0.0;
  st_.clear();
  molid_.clear();
  btags_.clear();
  fsum_.clear();
  rot_.clear();
  omg_.clear();
  slot_.clear();
  const double* p = buf + 5;
  for (int b = 0; b < nb; b++) {
    cl::State s;
    s.x = {p[1], p[2], p[3]};
    s.v = {p[4], p[5], p[6]};
    s.q = {p[7], p[8], p[9], p[10]};
    s.L = {p[11], p[12], p[13]};
    std::vector<int> tags(nsph_);
    for (int k = 0; k < nsph_; k++) tags[k] = static_cast<int>(p[kBodyDoubles + k]);
    add_body(static_cast<int>(p[0]), s, tags.data());
    for (int c = 0; c < 6; c++) fsum_[6 * b + c] = p[14 + c];
    p += kBodyDoubles + nsph_;
  }
  restarted_ = true;
  log(where_ + ": " + std::to_string(nb) + " bodies read from the restart file\n");
}

double FixTDEMClump::memory_usage() {
  return static_cast<double>(nmax_idx_) * 2 * sizeof(int) +
         static_cast<double>(st_.size()) * (sizeof(cl::State) + sizeof(Mat3) + sizeof(Vec3) + 6 * sizeof(double)) +
         static_cast<double>(btags_.size()) * (sizeof(int) + 6 * sizeof(double) + 32);
}
