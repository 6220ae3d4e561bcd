// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/clump (see fix_tdem_clump.h and docs/clumps_lammps.md).

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

namespace {
constexpr double kRestartMagic = 20261129.0;
constexpr int kBodyDoubles = 14;  // mol, x3, v3, q4, L3

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
    Fix(lmp, narg, arg), scheme(cl::Rotation::splitting), nsph(0), bodies_molecule(0),
    correction((int) cl::Correction::none), restarted(0),
    formed(0), ninsert(0), insert_type(1), insert_seed(0), nmax_idx(0), bodyidx(nullptr), sphidx(nullptr),
    dtv(0.0), dtf(0.0)
{
  where = std::string("fix ") + id + " tdem/clump";
  insert_vel[0] = insert_vel[1] = insert_vel[2] = 0.0;
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, where + " requires atom_style sphere (per-atom radius, rmass, omega, torque); the current "
                              "atom style '" + std::string(atom->atom_style) + "' lacks them");
  if (!atom->molecule_flag)
    error->all(FLERR, where + " requires molecule IDs (the spheres of one body share a molecule ID): add "
                              "'fix ID all property/atom mol ghost yes' before the box is filled");
  if (domain->triclinic) error->all(FLERR, where + " supports orthogonal boxes only (the box is triclinic)");
  if (domain->dimension != 3) error->all(FLERR, where + " needs a 3d simulation (dimension is 2)");
  parse(narg, arg);

  rigid_flag = 1;
  time_integrate = 1;
  restart_global = 1;
  dynamic_group_allow = 0;
  scalar_flag = 1;
  extscalar = 1;
  vector_flag = 1;
  size_vector = 9;
  extvector = 1;
  array_flag = 1;
  size_array_cols = 17;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  global_freq = 1;
  thermo_energy = 0;
}

FixTDEMClump::~FixTDEMClump()
{
  memory->destroy(bodyidx);
  memory->destroy(sphidx);
}

/* ---------------------------------------------------------------------- */

void FixTDEMClump::parse(int narg, char **arg)
{
  // the arguments and the template: one parser for both engines (fixes/clumps/clump_args.h)
  cl::ClumpArgs a;
  try {
    a = cl::parse_clump_args(std::vector<std::string>(arg + 3, arg + narg), where, atom->ntypes);
    tmpl = cl::clump_template(a, where);
  } catch (const std::exception &e) {
    error->all(FLERR, e.what());
  }
  scheme = a.scheme;
  ninsert = a.ninsert;
  insert_type = a.insert_type;
  insert_region = a.insert_region;
  insert_seed = a.insert_seed;
  for (int k = 0; k < 3; k++) insert_vel[k] = a.insert_vel[k];
  bodies_molecule = a.bodies_molecule ? 1 : 0;
  correction = (int) a.correction;
  bprop = cl::Body::from(tmpl);
  nsph = (int) tmpl.body.size();
  sphere_mass = cl::sphere_masses(tmpl);  // the body mass shared by r^3; exactly M for one sphere
  if (comm->me == 0)
    utils::logmesg(lmp, fmt::format("{}: template {} ({} spheres): mass {:.10g}, principal inertia {:.10g} {:.10g} "
                                    "{:.10g}, bounding radius {:.6g}, rotation {}\n",
                                    where, tmpl.name, nsph, tmpl.mp.mass, tmpl.mp.principal[0], tmpl.mp.principal[1],
                                    tmpl.mp.principal[2], tmpl.bounding_radius, cl::to_string(scheme)));
}

int FixTDEMClump::setmask()
{
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= FINAL_INTEGRATE;
  mask |= PRE_NEIGHBOR;
  return mask;
}

void FixTDEMClump::unwrapped(int i, double *xu) const
{
  domain->unmap(atom->x[i], atom->image[i], xu);
}

// N clumps at random positions and orientations in the region, without overlap with each other
// and with existing atoms. Every rank draws the same sequence; each creates the spheres it owns.
void FixTDEMClump::post_constructor()
{
  if (ModifyRestartPeek::has_global(modify, id, "tdem/clump")) restarted = 1;
  if (ninsert > 0 && !restarted) insert_clumps();
  else if (ninsert > 0 && comm->me == 0)
    utils::logmesg(lmp, where + ": bodies read from the restart file, 'insert' is skipped\n");
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
  if (!excluded && nsph > 1 && comm->me == 0)
    error->warning(FLERR, where + ": spheres of one clump interact with each other; add 'neigh_modify exclude "
                              "molecule/intra " + std::string(group->names[igroup]) + "'");
  // another time integrator on the same atoms would move them twice
  for (int i = 0; i < modify->nfix; i++) {
    Fix *f = modify->fix[i];
    if (f == this || !f->time_integrate) continue;
    int mine = 0, any = 0;
    for (int j = 0; j < atom->nlocal; j++)
      if ((atom->mask[j] & f->groupbit) &&
          (slot.count(atom->tag[j]) ||
           (bodies_molecule && !formed && (atom->mask[j] & groupbit) && atom->molecule[j] > 0)))
        mine = 1;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      error->all(FLERR, where + ": fix " + std::string(f->id) + " (" + std::string(f->style) +
                            ") also integrates clump spheres; exclude them from its group");
  }
}

// Per-atom body and sphere index of owned and ghost atoms; sphere radius and mass from the template.
void FixTDEMClump::map_atoms()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax_idx) {
    nmax_idx = atom->nmax;
    memory->destroy(bodyidx);
    memory->destroy(sphidx);
    memory->create(bodyidx, nmax_idx, "tdem/clump:bodyidx");
    memory->create(sphidx, nmax_idx, "tdem/clump:sphidx");
  }
  const int nmine = tdem::clumps::map_clump_atoms(nall, atom->nlocal, atom->tag, slot, nsph, tmpl, sphere_mass,
                                                  bodyidx, sphidx, atom->radius, atom->rmass);
  bigint mine = nmine, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all != (bigint) st.size() * nsph)
    error->all(FLERR, fmt::format("{}: {} clump spheres found, {} bodies need {} (clump spheres lost or deleted)",
                                  where, all, st.size(), (bigint) st.size() * nsph));
}

// omega = Lambda I^-1 Lambda^T L with the cached rotation matrix
static inline Vec3 omega_of(const Mat3 &R, const Vec3 &L, const cl::Body &b)
{
  const Vec3 pi = cl::mul_t(R, L);
  return cl::mul(R, Vec3{pi[0] / b.inertia[0], pi[1] / b.inertia[1], pi[2] / b.inertia[2]});
}

void FixTDEMClump::refresh_kinematics()
{
  for (std::size_t b = 0; b < st.size(); b++) {
    rot[b] = cl::rotation_matrix(st[b].q);
    omg[b] = omega_of(rot[b], st[b].L, bprop);
  }
  if (correction != (int) cl::Correction::local_mass) return;
  // com and inverse inertia (space frame, R diag(1/I) R^T) for the local_mass correction
  bcom.resize(3 * st.size());
  binv.resize(9 * st.size());
  for (std::size_t b = 0; b < st.size(); b++) {
    const Mat3 &R = rot[b];
    for (int i = 0; i < 3; i++) {
      bcom[3 * b + i] = st[b].x[i];
      for (int j = 0; j < 3; j++) {
        double s = 0.0;
        for (int k = 0; k < 3; k++) s += R[i][k] * R[j][k] / bprop.inertia[k];
        binv[9 * b + 3 * i + j] = s;
      }
    }
  }
}

void FixTDEMClump::setup_pre_neighbor()
{
  if (bodies_molecule && !formed) {
    form_bodies();
    formed = 1;
    map_atoms();
    refresh_kinematics();
    set_spheres(false);
  } else {
    map_atoms();
    // the pair and wall styles of the setup force evaluation need com and inertia (local_mass)
    if (correction == (int) cl::Correction::local_mass) refresh_kinematics();
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
  refresh_kinematics();
  sum_forces();
}

void FixTDEMClump::reset_dt()
{
  dtv = update->dt;
  dtf = 0.5 * update->dt * force->ftm2v;
}

// fsum <- force and torque about the com of every body. Each owned sphere writes its force and
// torque (about the com) into its own slot; the slots are combined over the ranks (one non-zero
// contribution per slot, so the reduction is exact) and summed per body in template order: the
// result does not depend on the order of the atoms or on the number of ranks.
void FixTDEMClump::sum_forces()
{
  const std::size_t nslot = st.size() * nsph;
  if (sphere_f.size() != 6 * nslot) sphere_f.assign(6 * nslot, 0.0);
  else std::fill(sphere_f.begin(), sphere_f.end(), 0.0);
  const int nlocal = atom->nlocal;
  double **f = atom->f, **t = atom->torque;
  for (int i = 0; i < nlocal; i++) {
    const int b = bodyidx[i];
    if (b < 0) continue;
    const Vec3 r = cl::mul(rot[b], tmpl.body[sphidx[i]].x);
    double *fs = &sphere_f[6 * ((std::size_t) b * nsph + sphidx[i])];
    fs[0] = f[i][0];
    fs[1] = f[i][1];
    fs[2] = f[i][2];
    fs[3] = r[1] * f[i][2] - r[2] * f[i][1] + t[i][0];
    fs[4] = r[2] * f[i][0] - r[0] * f[i][2] + t[i][1];
    fs[5] = r[0] * f[i][1] - r[1] * f[i][0] + t[i][2];
  }
  if (comm->nprocs > 1)
    MPI_Allreduce(MPI_IN_PLACE, sphere_f.data(), (int) sphere_f.size(), MPI_DOUBLE, MPI_SUM, world);
  for (std::size_t b = 0; b < st.size(); b++) {
    double *fb = &fsum[6 * b];
    const double *fs = &sphere_f[6 * b * nsph];
    for (int c = 0; c < 6; c++) fb[c] = fs[c];
    for (int k = 1; k < nsph; k++)
      for (int c = 0; c < 6; c++) fb[c] += fs[6 * k + c];
  }
}

// owned spheres from their bodies: x (if positions), v, omega
void FixTDEMClump::set_spheres(bool positions)
{
  const int nlocal = atom->nlocal;
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};
  for (int i = 0; i < nlocal; i++) {
    const int b = bodyidx[i];
    if (b < 0) continue;
    const Vec3 r = cl::mul(rot[b], tmpl.body[sphidx[i]].x);
    if (positions) {
      const imageint img = atom->image[i];
      const int box[3] = {(int) (img & IMGMASK) - IMGMAX, (int) (img >> IMGBITS & IMGMASK) - IMGMAX,
                          (int) (img >> IMG2BITS) - IMGMAX};
      for (int k = 0; k < 3; k++) atom->x[i][k] = st[b].x[k] + r[k] - box[k] * prd[k];
    }
    const Vec3 &w = omg[b];
    atom->v[i][0] = st[b].v[0] + w[1] * r[2] - w[2] * r[1];
    atom->v[i][1] = st[b].v[1] + w[2] * r[0] - w[0] * r[2];
    atom->v[i][2] = st[b].v[2] + w[0] * r[1] - w[1] * r[0];
    atom->omega[i][0] = w[0];
    atom->omega[i][1] = w[1];
    atom->omega[i][2] = w[2];
  }
}

void FixTDEMClump::initial_integrate(int /*vflag*/)
{
  const double h = dtv, c = 2.0 * dtf / dtv;  // c = ftm2v
  for (std::size_t b = 0; b < st.size(); b++) {
    const double *fb = &fsum[6 * b];
    cl::initial_integrate(st[b], bprop, Vec3{c * fb[0], c * fb[1], c * fb[2]}, Vec3{c * fb[3], c * fb[4], c * fb[5]},
                          h, scheme);
  }
  refresh_kinematics();
  set_spheres(true);
}

void FixTDEMClump::final_integrate()
{
  sum_forces();
  const double h = dtv, c = 2.0 * dtf / dtv;
  for (std::size_t b = 0; b < st.size(); b++) {
    const double *fb = &fsum[6 * b];
    cl::final_integrate(st[b], bprop, Vec3{c * fb[0], c * fb[1], c * fb[2]}, Vec3{c * fb[3], c * fb[4], c * fb[5]}, h);
    omg[b] = omega_of(rot[b], st[b].L, bprop);
  }
  set_spheres(false);
}

/* ---------------------------------------------------------------------- */

double FixTDEMClump::compute_scalar()
{
  double e = 0.0;
  for (const auto &s : st) e += cl::kinetic_energy(s, bprop);
  return e * force->mvv2e;
}

// 1: bodies, 2-4: total momentum, 5-7: sum of the bodies' angular momenta about their com,
// 8: translational, 9: rotational kinetic energy
double FixTDEMClump::compute_vector(int n)
{
  if (n == 0) return (double) st.size();
  double out = 0.0;
  for (const auto &s : st) {
    if (n >= 1 && n <= 3) out += bprop.mass * s.v[n - 1];
    else if (n >= 4 && n <= 6) out += s.L[n - 4];
    else if (n == 7) out += 0.5 * bprop.mass * cl::dot(s.v, s.v) * force->mvv2e;
    else if (n == 8) out += cl::rotational_energy(s, bprop) * force->mvv2e;
  }
  return out;
}

// row per body: mol, x y z, vx vy vz, qw qx qy qz, Lx Ly Lz, wx wy wz
double FixTDEMClump::compute_array(int i, int j)
{
  if (i < 0 || i >= (int) st.size()) return 0.0;
  const cl::State &s = st[i];
  if (j == 0) return (double) molid[i];
  if (j <= 3) return s.x[j - 1];
  if (j <= 6) return s.v[j - 4];
  if (j == 7) return s.q.w;
  if (j == 8) return s.q.x;
  if (j == 9) return s.q.y;
  if (j == 10) return s.q.z;
  if (j <= 13) return s.L[j - 11];
  if (j <= 16) return cl::angular_velocity(s, bprop)[j - 14];
  return 0.0;
}

// "body" / "tdem_clump_body": int per atom (owned and ghost), body index or -1;
// "masstotal": double per body (as fix rigid, for the granular pair and wall styles);
// "tdem_clump_correction": int (dim 0), the multiple-contact correction (tdem::clumps::Correction);
// "tdem_clump_com", "tdem_clump_inv_inertia": double, 3 / 9 per body (local_mass only)
void *FixTDEMClump::extract(const char *name, int &dim)
{
  dim = 1;
  if (std::strcmp(name, "body") == 0 || std::strcmp(name, "tdem_clump_body") == 0) return (void *) bodyidx;
  if (std::strcmp(name, "masstotal") == 0) return (void *) masstotal.data();
  if (std::strcmp(name, "tdem_clump_sphere") == 0) return (void *) sphidx;
  if (std::strcmp(name, "tdem_clump_com") == 0) return (void *) bcom.data();
  if (std::strcmp(name, "tdem_clump_inv_inertia") == 0) return (void *) binv.data();
  dim = 0;
  if (std::strcmp(name, "tdem_clump_correction") == 0) return (void *) &correction;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

void FixTDEMClump::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> buf = {kRestartMagic, (double) st.size(), (double) nsph, (double) formed};
  for (std::size_t b = 0; b < st.size(); b++) {
    const cl::State &s = st[b];
    const double row[kBodyDoubles] = {(double) molid[b], s.x[0], s.x[1], s.x[2], s.v[0], s.v[1], s.v[2],
                                      s.q.w, s.q.x, s.q.y, s.q.z, s.L[0], s.L[1], s.L[2]};
    buf.insert(buf.end(), row, row + kBodyDoubles);
    for (int k = 0; k < nsph; k++) buf.push_back((double) btags[b * nsph + k]);
  }
  const int size = (int) (buf.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(buf.data(), sizeof(double), buf.size(), fp);
}

void FixTDEMClump::restart(char *raw)
{
  const double *buf = (const double *) raw;
  if (buf[0] != kRestartMagic) error->all(FLERR, where + ": the restart record is not a tdem/clump record");
  const int nb = (int) buf[1], ns = (int) buf[2];
  if (ns != nsph)
    error->all(FLERR, fmt::format("{}: the restart file has clumps of {} spheres, template {} has {}", where, ns,
                                  tmpl.name, nsph));
  formed = (int) buf[3];
  st.clear();
  molid.clear();
  btags.clear();
  masstotal.clear();
  fsum.clear();
  rot.clear();
  omg.clear();
  slot.clear();
  const double *p = buf + 4;
  for (int b = 0; b < nb; b++) {
    cl::State s;
    s.x = {p[1], p[2], p[3]};
    s.v = {p[4], p[5], p[6]};
    s.q = {p[7], p[8], p[9], p[10]};
    s.L = {p[11], p[12], p[13]};
    std::vector<tagint> tags(nsph);
    for (int k = 0; k < nsph; k++) tags[k] = (tagint) p[kBodyDoubles + k];
    add_body((tagint) p[0], s, tags.data());
    p += kBodyDoubles + nsph;
  }
  restarted = 1;
}

double FixTDEMClump::memory_usage()
{
  return (double) nmax_idx * 2 * sizeof(int) +
         (double) st.size() * (sizeof(cl::State) + sizeof(Mat3) + sizeof(Vec3) + 8 * sizeof(double)) +
         (double) btags.size() * (sizeof(tagint) + 32);
}
