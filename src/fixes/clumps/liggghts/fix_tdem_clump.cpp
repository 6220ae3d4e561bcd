// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/clump (see fix_tdem_clump.h and docs/liggghts/fix_tdem_clump.md).
#include "fix_tdem_clump.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

#include "fixes/clumps/clump_host.h"
#include "tdem_liggghts_ids.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;

namespace {

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
      bodies_(std::string("fix ") + arg[0] + " tdem/clump"),
      restarted_(false),
      formed_(false),
      have_force_(false),
      need_set_(false),
      correction_(cl::Correction::none),
      link_(lmp, sides_) {
  sides_.bodies = &bodies_;
  where_ = std::string("fix ") + id + " tdem/clump";
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

  cl::declare_clump_fix(this);
  rigid_flag = 0;  // LIGGGHTS casts fixes with rigid_flag to FixRigid in places; the body mass is not passed
  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow
  atom->add_callback(1);  // restart
}

FixTDEMClump::~FixTDEMClump() {
  if (tdem::liggghts::clump_link::active == &link_) tdem::liggghts::clump_link::active = nullptr;
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
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
  if (vtk_) mask |= END_OF_STEP;
  if (correction_ != cl::Correction::none) mask |= PRE_FORCE;
  return mask;
}

/* ---------------------------------------------------------------------- input */

void FixTDEMClump::parse(int narg, char** arg) {
  // the arguments and the template: one parser for both engines (fixes/clumps/clump_args.h)
  try {
    args_ = cl::parse_clump_args(std::vector<std::string>(arg + 3, arg + narg), where_, atom->ntypes);
    bodies_.configure(cl::clump_template(args_, where_), args_.scheme);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  correction_ = args_.correction;
  if (args_.vtk_every > 0) vtk_.reset(new cl::BodyVtk(args_.vtk_every, args_.vtk_prefix));
  clock_ = {update->atime + (update->ntimestep - update->atimestep) * update->dt, update->dt, update->ntimestep};
  log(bodies_.template_message(correction_));
}

// Modify calls the constructor, post_create_pre_restart(), restart() (if the restart file holds a
// record of this fix) and then post_create(): insertion only without a restart record.
// Bodies from the molecules present are formed here already, so that the rows of the global array
// exist when a thermo_style or variable referring to them is defined (LIGGGHTS checks the range then).
void FixTDEMClump::post_create() {
  if (args_.ninsert > 0 && !restarted_) insert_clumps();
  else if (args_.ninsert > 0) log(where_ + ": bodies read from the restart file, 'insert' is skipped\n");
  if (args_.bodies_molecule && !restarted_ && form_bodies() > 0) {
    have_force_ = false;
    need_set_ = true;
  }
}

void FixTDEMClump::insert_clumps() {
  const std::string& rname = args_.insert_region;
  const int iregion = domain->find_region(rname.c_str());
  if (iregion < 0) fail(where_ + ": insert region '" + rname + "' does not exist (keyword 'insert')");
  Region* region = domain->regions[iregion];
  cl::Inserted ins;
  try {
    // the placement of the core (clump_host.h): the same seed gives the same clumps in both engines
    ins = cl::insert_clumps(bodies_, args_, world, atom, region,
                                [&](double* d) { domain->minimum_image(d[0], d[1], d[2]); }, cl::periods(domain));
  } catch (const std::exception& e) {
    fail(e.what());
  }
  const std::vector<cl::NewSphere>& spheres = ins.spheres;
  size_array_rows = static_cast<int>(bodies_.size());

  // create the spheres this rank owns (the upper end of a non-periodic box belongs to its rank)
  const int nprev = atom->nlocal;
  bool top[3];
  for (int d = 0; d < 3; d++) top[d] = comm->myloc[d] == comm->procgrid[d] - 1 && !domain->periodicity[d];
  const int created = static_cast<int>(cl::create_spheres(bodies_, atom, spheres, groupbit, world, [&](const cl::NewSphere& s) {
    double xw[3] = {s.x[0], s.x[1], s.x[2]};
    tagint img = (static_cast<tagint>(IMGMAX) << IMG2BITS) | (static_cast<tagint>(IMGMAX) << IMGBITS) | IMGMAX;
    domain->remap(xw, img);
    if (!cl::owns_point(xw, domain->sublo, domain->subhi, top)) return -1;
    atom->avec->create_atom(args_.insert_type, xw);
    atom->image[atom->nlocal - 1] = img;
    return atom->nlocal - 1;
  }));
  if (created != static_cast<int>(spheres.size()))
    fail(where_ + ": insert: " + std::to_string(created) + " spheres created instead of " +
         std::to_string(spheres.size()) + " (a sphere outside every subdomain: is region " + rname +
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
  log(cl::inserted_message(bodies_, ins, args_.ninsert, created, rname));
}

// Bodies from the group's molecules that are not bodies yet (atom ID order = template order).
int FixTDEMClump::form_bodies() {
  const auto unmap = [&](int i, double* xu) { domain->unmap(atom->x[i], atom->image[i], xu); };
  int nnew = 0;
  try {
    nnew = cl::form_and_adopt(bodies_, world,
                              cl::form_rows(bodies_, atom->nlocal, atom->mask, groupbit, atom->tag, atom->molecule,
                                            unmap, atom->v, atom->omega, atom->radius),
                              group->names[igroup], atom->nlocal, atom->tag);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  size_array_rows = static_cast<int>(bodies_.size());
  if (nnew > 0) log(cl::formed_message(bodies_, nnew, group->names[igroup]));
  return nnew;
}

// The local bodies after an exchange: per-atom body and sphere index of owned and ghost atoms;
// sphere radius and mass from the template (body_set.h).
void FixTDEMClump::map_atoms() {
  std::int64_t missing = -1;
  const std::int64_t all = bodies_.map_atoms(atom->nlocal, atom->nghost, atom->tag, atom->radius, atom->rmass, world,
                                             [&](cl::BodySet::Comm c) { forward(c); }, missing);
  // LIGGGHTS's granular borders take atoms within cutghost / 2 + skin / 2 (+ their radius)
  const double cut = std::min(comm->cutghost[0], std::min(comm->cutghost[1], comm->cutghost[2]));
  if (missing >= 0) fail(bodies_.reach_message(missing, 0.5 * cut + 0.5 * neighbor->skin));
  if (all != bodies_.size() * bodies_.nsph()) fail(bodies_.lost_message(all));
  size_array_rows = static_cast<int>(bodies_.size());
}

void FixTDEMClump::forward(cl::BodySet::Comm c) {
  bodies_.set_comm(c);
  comm->forward_comm_fix(this);
}

// a rank that owns a sphere of a body must see all its spheres: LIGGGHTS's granular borders take the
// atoms within cutghost / 2 + skin / 2 of a sub-domain, and Comm::setup makes cutghost at least this
// plus the skin (as fix multisphere asks for twice its bounding radius)
double FixTDEMClump::extend_cut_ghost() { return 2.0 * bodies_.reach(); }

/* ---------------------------------------------------------------------- run */

// Molecules that appeared since the fix was created become bodies here.
void FixTDEMClump::init() {
  if (correction_ != cl::Correction::none) {
    auto*& act = tdem::liggghts::clump_link::active;
    if (act && act != &link_)
      fail(where_ + ": keyword 'correction': another fix (tdem/clump or tdem/correction) already applies a "
                    "multiple-contact correction (at most one fix may have a correction other than none)");
    act = &link_;
  }
  if (args_.bodies_molecule && form_bodies() > 0) {
    formed_ = true;
    have_force_ = false;
    need_set_ = true;
  }
  // the spheres of one body must not interact with each other: every clump sphere must be in the
  // group of a `neigh_modify exclude molecule` entry
  if (bodies_.nsph() > 1) {
    std::vector<int> bits;
    for (int g : NeighborExclusionPeek::molecule_groups(neighbor)) bits.push_back(group->bitmask[g]);
    int uncovered = 0, any = 0;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!bodies_.is_sphere(i)) continue;
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
          (bodies_.is_sphere(j) || (args_.bodies_molecule && (atom->mask[j] & groupbit) && atom->molecule[j] > 0)))
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
    set_spheres(false);
    need_set_ = false;
  }
}

void FixTDEMClump::pre_neighbor() { map_atoms(); }

// The force of the last final_integrate if there is one (continuing run or restart), else the
// set-up force.
void FixTDEMClump::setup(int) {
  bodies_.refresh_kinematics([&](cl::BodySet::Comm c) { forward(c); });
  if (!have_force_) bodies_.sum_forces(atom->nlocal, atom->f, atom->torque, [&](cl::BodySet::Comm c) { forward(c); });
  have_force_ = true;
  write_vtk();
}

void FixTDEMClump::end_of_step() { write_vtk(); }

// the bodies as prefix_STEP.vtu (+ prefix.pvd) when vtk N prefix asks for this step
void FixTDEMClump::write_vtk() {
  clock_.follow(update->ntimestep, update->dt);  // LIGGGHTS's `timestep` calls no reset_dt
  if (!vtk_ || !vtk_->due(update->ntimestep)) return;
  const std::string msg = vtk_->write(update->ntimestep, clock_.at(update->ntimestep), bodies_, world);
  if (!msg.empty()) fail(where_ + ": " + msg);
}

void FixTDEMClump::reset_dt() { clock_.follow(update->ntimestep, update->dt); }

// owned spheres from their bodies: x (if positions, with the image flags), v, omega
void FixTDEMClump::set_spheres(bool positions) {
  cl::set_spheres(bodies_, atom, domain->prd, {IMGMASK, IMGBITS, IMG2BITS, IMGMAX}, positions);
}

void FixTDEMClump::initial_integrate(int) {
  bodies_.initial_integrate(update->dt, force->ftm2v, [&](cl::BodySet::Comm c) { forward(c); });
  set_spheres(true);
}

void FixTDEMClump::final_integrate() {
  bodies_.sum_forces(atom->nlocal, atom->f, atom->torque, [&](cl::BodySet::Comm c) { forward(c); });
  bodies_.final_integrate(update->dt, force->ftm2v);
  set_spheres(false);
}

void FixTDEMClump::setup_pre_force(int) {
  double d = 0.0;  // spheres of clumps not inserted yet
  for (const auto& s : bodies_.tmpl().body) d = std::max(d, 2.0 * s.r);
  link_.setup(correction_, where_, d);
  pre_force(0);
}

void FixTDEMClump::pre_force(int) {
  if (link_.tallies()) link_.tally();
}

/* ---------------------------------------------------------------------- output */

double FixTDEMClump::compute_scalar() { return reports_.kinetic_energy(bodies_, force->mvv2e, world); }

// [1] bodies, [2-4] total momentum, [5-7] sum of the bodies' angular momenta about their com,
// [8] translational, [9] rotational kinetic energy
double FixTDEMClump::compute_vector(int n) { return reports_.vector(bodies_, n, force->mvv2e, world); }

// row per body in molecule ID order: mol, x y z, vx vy vz, qw qx qy qz, Lx Ly Lz, wx wy wz
double FixTDEMClump::compute_array(int i, int j) { return reports_.array(bodies_, i, j, world); }

// "tdem_clump_body": int per atom (owned and ghost, valid after the first set-up), local body index or -1;
// "tdem_clump_key": int64 per atom, the body's molecule ID or -1;
// "tdem_clump_sphere": int per atom, sphere index in the template or -1;
// "tdem_clump_mass": double, the body mass (dim 0)
void* FixTDEMClump::extract(const char* name, int& dim) {
  dim = 1;
  if (std::strcmp(name, "tdem_clump_body") == 0) return static_cast<void*>(bodies_.body_index());
  if (std::strcmp(name, "tdem_clump_sphere") == 0) return static_cast<void*>(bodies_.sphere_index());
  if (std::strcmp(name, "tdem_clump_key") == 0) return static_cast<void*>(bodies_.body_key());
  dim = 0;
  if (std::strcmp(name, "tdem_clump_mass") == 0) return const_cast<double*>(&bodies_.body().mass);
  return nullptr;
}

/* ---------------------------------------------------------------------- restart */

namespace {
constexpr double kRestartMagic = 20261206.0;        // local bodies: counts here, bodies per atom
constexpr double kRestartMagicClock = 20261208.0;   // the same with the fix's clock (time, step)
constexpr double kRestartMagicGlobal = 20261130.0;  // global bodies: every body in the record
}  // namespace

// magic, nbody, nsph, formed, have_force (clump_host.h); the bodies (with their last force sums)
// are in the per-atom records
void FixTDEMClump::write_restart(FILE* fp) {
  if (comm->me == 0)
    cl::write_restart_record(fp, bodies_, kRestartMagicClock, {formed_ ? 1.0 : 0.0, have_force_ ? 1.0 : 0.0,
                                                              clock_.at(update->ntimestep), (double)update->ntimestep});
}

// this version's record, or one of the global-bodies version (every body, given to its spheres at
// the next set-up)
void FixTDEMClump::restart(char* raw) {
  double flags[4] = {0.0, 0.0, 0.0, 0.0};
  const bool with_clock = reinterpret_cast<const double*>(raw)[0] == kRestartMagicClock;
  try {
    cl::read_restart_record(raw, bodies_, with_clock ? kRestartMagicClock : kRestartMagic, kRestartMagicGlobal, flags,
                            with_clock ? 4 : 2, true,
                            where_ + ": the restart record is not a tdem/clump record of this version");
  } catch (const std::exception& e) {
    fail(e.what());
  }
  formed_ = flags[0] != 0.0;
  have_force_ = flags[1] != 0.0;
  if (with_clock) clock_ = {flags[2], update->dt, static_cast<long long>(flags[3])};
  size_array_rows = static_cast<int>(bodies_.size());
  restarted_ = true;
  log(where_ + ": " + std::to_string(bodies_.size()) + " bodies read from the restart file\n");
}

double FixTDEMClump::memory_usage() { return bodies_.memory_usage() + reports_.memory_usage(); }

/* ---------------------------------------------------------------------- per-atom data */

void FixTDEMClump::grow_arrays(int nmax) { bodies_.grow(nmax); }

void FixTDEMClump::copy_arrays(int i, int j, int) { bodies_.copy_atom(i, j); }

int FixTDEMClump::pack_exchange(int i, double* buf) { return bodies_.pack_exchange(i, buf); }

int FixTDEMClump::unpack_exchange(int n, double* buf) { return bodies_.unpack_exchange(n, buf); }

int FixTDEMClump::pack_restart(int i, double* buf) { return bodies_.pack_restart(i, buf); }

void FixTDEMClump::unpack_restart(int n, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[n][m]);
  bodies_.unpack_restart(n, &extra[n][m]);
}

int FixTDEMClump::size_restart(int i) { return 1 + (bodies_.is_sphere(i) ? cl::BodySet::kExchange : 1); }

int FixTDEMClump::maxsize_restart() { return cl::BodySet::kRestartMax; }

// LIGGGHTS's forward communication wants the number of values per atom
int FixTDEMClump::pack_comm(int n, int* list, double* buf, int, int*) {
  bodies_.pack_forward(n, list, buf);
  return cl::BodySet::comm_size(bodies_.comm());
}

void FixTDEMClump::unpack_comm(int n, int first, double* buf) { bodies_.unpack_forward(n, first, buf); }
