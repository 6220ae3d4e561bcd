// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/clump (see fix_tdem_clump.h and docs/lammps/fix_tdem_clump.md).

#include "fix_tdem_clump.h"

#include "fixes/clumps/clump_host.h"

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
#include <mpi.h>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;

namespace {
constexpr double kRestartMagic = 20261205.0;        // local bodies: counts here, bodies per atom
constexpr double kRestartMagicClock = 20261207.0;   // the same with the fix's clock (time, step)
constexpr double kRestartMagicGlobal = 20261129.0;  // global bodies: every body in the record

// Modify calls post_constructor() before restart(): whether the restart file read holds a global
// record of this fix is looked up in Modify's list (protected members reached through pointers
// to members of a derived class, the legal way).
struct ModifyRestartPeek : public Modify {
  static bool has_global(Modify *m, const std::string &id, const std::string &style)
  {
    char **Modify::*ids = &ModifyRestartPeek::id_restart_global;
    char **Modify::*styles = &ModifyRestartPeek::style_restart_global;
    for (int i = 0; i < m->nfix_restart_global; i++)
      if (id == (m->*ids)[i] && style == (m->*styles)[i]) return true;
    return false;
  }
};

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMClump::FixTDEMClump(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), bodies(std::string("fix ") + arg[0] + " tdem/clump"),
    correction((int) cl::Correction::none), restarted(0), formed(0), dtv(0.0), dtf(0.0)
{
  where = std::string("fix ") + id + " tdem/clump";
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, where + " requires atom_style sphere (per-atom radius, rmass, omega, torque); the current "
                              "atom style '" + std::string(atom->atom_style) + "' lacks them");
  if (!atom->molecule_flag)
    error->all(FLERR, where + " requires molecule IDs (the spheres of one body share a molecule ID): add "
                              "'fix ID all property/atom mol ghost yes' before the box is filled");
  if (domain->triclinic) error->all(FLERR, where + " supports orthogonal boxes only (the box is triclinic)");
  if (domain->dimension != 3) error->all(FLERR, where + " needs a 3d simulation (dimension is 2)");
  parse(narg, arg);

  cl::declare_clump_fix(this);
  rigid_flag = 1;
  dynamic_group_allow = 0;
  size_array_rows_variable = 1;
  thermo_energy = 0;
  maxexchange = cl::BodySet::kExchange;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixTDEMClump::~FixTDEMClump()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

/* ---------------------------------------------------------------------- */

void FixTDEMClump::parse(int narg, char **arg)
{
  // the arguments and the template: one parser for both engines (fixes/clumps/clump_args.h)
  try {
    args = cl::parse_clump_args(std::vector<std::string>(arg + 3, arg + narg), where, atom->ntypes);
    bodies.configure(cl::clump_template(args, where), args.scheme);
  } catch (const std::exception &e) {
    error->all(FLERR, e.what());
  }
  correction = (int) args.correction;
  if (args.vtk_every > 0) vtk = std::make_unique<cl::BodyVtk>(args.vtk_every, args.vtk_prefix);
  clock = {update->atime + (update->ntimestep - update->atimestep) * update->dt, update->dt, update->ntimestep};
  bodies.keep_local_mass(args.correction == cl::Correction::local_mass);
  if (comm->me == 0) utils::logmesg(lmp, bodies.template_message(args.correction));
}

int FixTDEMClump::setmask()
{
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= FINAL_INTEGRATE;
  mask |= PRE_NEIGHBOR;
  if (vtk) mask |= END_OF_STEP;
  return mask;
}

// N clumps at random positions and orientations in the region, without overlap with each other
// and with existing atoms. Every rank draws the same sequence; each creates the spheres it owns.
void FixTDEMClump::post_constructor()
{
  if (ModifyRestartPeek::has_global(modify, id, "tdem/clump")) restarted = 1;
  if (args.ninsert > 0 && !restarted) insert_clumps();
  else if (args.ninsert > 0 && comm->me == 0)
    utils::logmesg(lmp, where + ": bodies read from the restart file, 'insert' is skipped\n");
}

void FixTDEMClump::insert_clumps()
{
  const std::string &rname = args.insert_region;
  Region *region = tdem_lammps::compat::region_by_id(domain, rname);
  if (!region) error->all(FLERR, where + ": insert region '" + rname + "' does not exist (keyword 'insert')");
  cl::Inserted ins;
  try {
    // the placement of the core (clump_host.h): the same seed gives the same clumps in both engines
    ins = cl::insert_clumps(
        bodies, args, world, atom, region,
        [&](double *d) { tdem_lammps::compat::minimum_image(domain, d[0], d[1], d[2]); }, cl::periods(domain));
  } catch (const std::exception &e) {
    error->all(FLERR, e.what());
  }
  const std::vector<cl::NewSphere> &spheres = ins.spheres;
  size_array_rows = (int) bodies.size();

  // create the spheres this rank owns (the upper end of a non-periodic box belongs to its rank)
  const int nprev = atom->nlocal;
  bool top[3];
  for (int d = 0; d < 3; d++) top[d] = domain->subhi[d] == domain->boxhi[d] && !domain->periodicity[d];
  const bigint created = cl::create_spheres(bodies, atom, spheres, groupbit, world, [&](const cl::NewSphere &s) {
    double xw[3] = {s.x[0], s.x[1], s.x[2]};
    imageint img = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(xw, img);
    if (!cl::owns_point(xw, domain->sublo, domain->subhi, top)) return -1;
    atom->avec->create_atom(args.insert_type, xw);
    atom->image[atom->nlocal - 1] = img;
    return atom->nlocal - 1;
  });
  if (created != (bigint) spheres.size())
    error->all(FLERR, fmt::format("{}: insert: {} spheres created instead of {} (a sphere outside every "
                                  "subdomain: is region {} inside the box?)",
                                  where, created, spheres.size(), rname));
  atom->natoms += created;
  atom->data_fix_compute_variable(nprev, atom->nlocal);
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
  if (comm->me == 0) utils::logmesg(lmp, cl::inserted_message(bodies, ins, args.ninsert, created, rname));
}

// Bodies from the group's molecules that are not bodies yet (tag order = template order).
void FixTDEMClump::form_bodies()
{
  const auto unmap = [&](int i, double *xu) { domain->unmap(atom->x[i], atom->image[i], xu); };
  try {
    const int nnew = cl::form_and_adopt(bodies, world,
                                        cl::form_rows(bodies, atom->nlocal, atom->mask, groupbit, atom->tag,
                                                      atom->molecule, unmap, atom->v, atom->omega, atom->radius),
                                        group->names[igroup], atom->nlocal, atom->tag);
    if (comm->me == 0) utils::logmesg(lmp, cl::formed_message(bodies, nnew, group->names[igroup]));
  } catch (const std::exception &e) {
    error->all(FLERR, e.what());
  }
  size_array_rows = (int) bodies.size();
}

/* ---------------------------------------------------------------------- */

void FixTDEMClump::init()
{
  dtv = update->dt;
  dtf = 0.5 * update->dt * force->ftm2v;
  // the spheres of one body must not interact with each other
  bool excluded = false;
  for (int k = 0; k < neighbor->nex_mol; k++)
    if (neighbor->ex_mol_intra[k] && (neighbor->ex_mol_group[k] == igroup || neighbor->ex_mol_group[k] == 0))
      excluded = true;
  if (!excluded && bodies.nsph() > 1 && comm->me == 0)
    error->warning(FLERR, where + ": spheres of one clump interact with each other; add 'neigh_modify exclude "
                              "molecule/intra " + std::string(group->names[igroup]) + "'");
  // a rank that owns a sphere of a body must see all its spheres: ghost cutoff >= reach
  const double cutneigh = (force->pair ? force->pair->cutforce : 0.0) + neighbor->skin;
  if (bodies.reach() > std::max(cutneigh, comm->cutghostuser)) {
    comm->cutghostuser = bodies.reach();
    if (comm->me == 0)
      utils::logmesg(lmp, fmt::format("{}: ghost cutoff set to {} (the largest distance between two spheres of "
                                      "template {}; the pair cutoff is {})\n",
                                      where, bodies.reach(), bodies.tmpl().name, cutneigh));
  }
  // another time integrator on the same atoms would move them twice
  for (int i = 0; i < modify->nfix; i++) {
    Fix *f = modify->fix[i];
    if (f == this || !f->time_integrate) continue;
    int mine = 0, any = 0;
    for (int j = 0; j < atom->nlocal; j++)
      if ((atom->mask[j] & f->groupbit) &&
          (bodies.is_sphere(j) ||
           (args.bodies_molecule && !formed && (atom->mask[j] & groupbit) && atom->molecule[j] > 0)))
        mine = 1;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      error->all(FLERR, where + ": fix " + std::string(f->id) + " (" + std::string(f->style) +
                            ") also integrates clump spheres; exclude them from its group");
  }
}

// The local bodies after an exchange: per-atom body and sphere index of owned and ghost atoms;
// sphere radius and mass from the template (body_set.h).
void FixTDEMClump::map_atoms()
{
  std::int64_t missing = -1;
  const std::int64_t all = bodies.map_atoms(atom->nlocal, atom->nghost, atom->tag, atom->radius, atom->rmass, world,
                                            [&](cl::BodySet::Comm c) { forward(c); }, missing);
  if (missing >= 0)
    error->all(FLERR, bodies.reach_message(missing, std::max(comm->cutghost[0],
                                                             std::max(comm->cutghost[1], comm->cutghost[2]))));
  if (all != bodies.size() * bodies.nsph()) error->all(FLERR, bodies.lost_message(all));
  size_array_rows = (int) bodies.size();
}

void FixTDEMClump::forward(cl::BodySet::Comm c)
{
  bodies.set_comm(c);
  tdem_lammps::compat::forward_comm(comm, this, cl::BodySet::comm_size(c));
}

void FixTDEMClump::setup_pre_neighbor()
{
  if (args.bodies_molecule && !formed) {
    form_bodies();
    formed = 1;
    map_atoms();
    set_spheres(false);
  } else {
    map_atoms();  // also com and inertia for the pair and wall styles' setup forces (local_mass)
  }
}

void FixTDEMClump::pre_neighbor()
{
  map_atoms();
}

void FixTDEMClump::setup(int /*vflag*/)
{
  dtv = update->dt;
  dtf = 0.5 * update->dt * force->ftm2v;
  bodies.refresh_kinematics([&](cl::BodySet::Comm c) { forward(c); });
  bodies.sum_forces(atom->nlocal, atom->f, atom->torque, [&](cl::BodySet::Comm c) { forward(c); });
  write_vtk();
}

void FixTDEMClump::end_of_step()
{
  write_vtk();
}

// the bodies as prefix_STEP.vtu (+ prefix.pvd) when vtk N prefix asks for this step
void FixTDEMClump::write_vtk()
{
  clock.follow(update->ntimestep, update->dt);
  if (!vtk || !vtk->due(update->ntimestep)) return;
  const std::string msg = vtk->write(update->ntimestep, clock.at(update->ntimestep), bodies, world);
  if (!msg.empty()) error->all(FLERR, where + ": " + msg);
}

void FixTDEMClump::reset_dt()
{
  clock.follow(update->ntimestep, update->dt);
  dtv = update->dt;
  dtf = 0.5 * update->dt * force->ftm2v;
}

// owned spheres from their bodies: x (if positions, with the image flags), v, omega
void FixTDEMClump::set_spheres(bool positions)
{
  cl::set_spheres(bodies, atom, domain->prd, {IMGMASK, IMGBITS, IMG2BITS, IMGMAX}, positions);
}

void FixTDEMClump::initial_integrate(int /*vflag*/)
{
  bodies.initial_integrate(dtv, 2.0 * dtf / dtv, [&](cl::BodySet::Comm c) { forward(c); });  // 2 dtf / dtv = ftm2v
  set_spheres(true);
}

void FixTDEMClump::final_integrate()
{
  bodies.sum_forces(atom->nlocal, atom->f, atom->torque, [&](cl::BodySet::Comm c) { forward(c); });
  bodies.final_integrate(dtv, 2.0 * dtf / dtv);
  set_spheres(false);
}

/* ---------------------------------------------------------------------- */

double FixTDEMClump::compute_scalar()
{
  return reports.kinetic_energy(bodies, force->mvv2e, world);
}

// 1: bodies, 2-4: total momentum, 5-7: sum of the bodies' angular momenta about their com,
// 8: translational, 9: rotational kinetic energy
double FixTDEMClump::compute_vector(int n)
{
  return reports.vector(bodies, n, force->mvv2e, world);
}

// row per body in molecule ID order: mol, x y z, vx vy vz, qw qx qy qz, Lx Ly Lz, wx wy wz
double FixTDEMClump::compute_array(int i, int j)
{
  return reports.array(bodies, i, j, world);
}

// "body" / "tdem_clump_body": int per atom (owned and ghost), local body index or -1;
// "masstotal": double per local body (as fix rigid, for the granular pair and wall styles);
// "tdem_clump_key": int64 per atom (owned and ghost), the body's molecule ID or -1;
// "tdem_clump_correction": int (dim 0), the multiple-contact correction (tdem::clumps::Correction);
// "tdem_clump_com", "tdem_clump_inv_inertia": double, 3 / 9 per body (local_mass only)
void *FixTDEMClump::extract(const char *name, int &dim)
{
  dim = 1;
  if (std::strcmp(name, "body") == 0 || std::strcmp(name, "tdem_clump_body") == 0) return (void *) bodies.body_index();
  if (std::strcmp(name, "masstotal") == 0) return (void *) bodies.masses();
  if (std::strcmp(name, "tdem_clump_sphere") == 0) return (void *) bodies.sphere_index();
  if (std::strcmp(name, "tdem_clump_key") == 0) return (void *) bodies.body_key();
  if (std::strcmp(name, "tdem_clump_com") == 0) return (void *) bodies.com();
  if (std::strcmp(name, "tdem_clump_inv_inertia") == 0) return (void *) bodies.inverse_inertia();
  dim = 0;
  if (std::strcmp(name, "tdem_clump_correction") == 0) return (void *) &correction;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

// magic, nbody, nsph, formed (clump_host.h); the bodies are in the per-atom records
void FixTDEMClump::write_restart(FILE *fp)
{
  if (comm->me == 0)
    cl::write_restart_record(fp, bodies, kRestartMagicClock,
                             {(double) formed, clock.at(update->ntimestep), (double) update->ntimestep});
}

// this version's record, or one of the global-bodies version (every body, given to its spheres at
// the next set-up)
void FixTDEMClump::restart(char *raw)
{
  double flag[3] = {0.0, 0.0, 0.0};
  const bool with_clock = reinterpret_cast<const double *>(raw)[0] == kRestartMagicClock;
  try {
    cl::read_restart_record(raw, bodies, with_clock ? kRestartMagicClock : kRestartMagic, kRestartMagicGlobal, flag,
                            with_clock ? 3 : 1, false, where + ": the restart record is not a tdem/clump record");
  } catch (const std::exception &e) {
    error->all(FLERR, e.what());
  }
  formed = (int) flag[0];
  if (with_clock) clock = {flag[1], update->dt, (bigint) flag[2]};
  size_array_rows = (int) bodies.size();
  restarted = 1;
}

/* ---------------------------------------------------------------------- per-atom data */

void FixTDEMClump::grow_arrays(int nmax)
{
  bodies.grow(nmax);
}

void FixTDEMClump::copy_arrays(int i, int j, int /*delflag*/)
{
  bodies.copy_atom(i, j);
}

int FixTDEMClump::pack_exchange(int i, double *buf)
{
  return bodies.pack_exchange(i, buf);
}

int FixTDEMClump::unpack_exchange(int n, double *buf)
{
  return bodies.unpack_exchange(n, buf);
}

int FixTDEMClump::pack_restart(int i, double *buf)
{
  return bodies.pack_restart(i, buf);
}

void FixTDEMClump::unpack_restart(int n, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[n][m]);
  bodies.unpack_restart(n, &extra[n][m]);
}

int FixTDEMClump::size_restart(int i)
{
  return 1 + (bodies.is_sphere(i) ? cl::BodySet::kExchange : 1);
}

int FixTDEMClump::maxsize_restart()
{
  return cl::BodySet::kRestartMax;
}

int FixTDEMClump::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  return bodies.pack_forward(n, list, buf);
}

void FixTDEMClump::unpack_forward_comm(int n, int first, double *buf)
{
  bodies.unpack_forward(n, first, buf);
}

double FixTDEMClump::memory_usage()
{
  return bodies.memory_usage() + reports.memory_usage();
}
