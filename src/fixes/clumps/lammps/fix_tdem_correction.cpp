// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/correction (see fix_tdem_correction.h and docs/lammps/fix_tdem_clump.md).
#include "fix_tdem_correction.h"

#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/rigid_body.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "error.h"
#include "lammps_compat.h"
#include "modify.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;

namespace {
// columns of the internal compute rigid/local
enum { C_ID, C_MOL, C_MASS, C_X, C_Q = C_X + 3, C_I = C_Q + 4, C_N = C_I + 3 };
const char *const kColumns = "id mol mass x y z quatw quati quatj quatk inertiax inertiay inertiaz";
bool is_rigid_small(const char *style)
{
  return std::strncmp(style, "rigid/", 6) == 0 && std::strstr(style, "small") != nullptr;
}
}  // namespace

FixTDEMCorrection::FixTDEMCorrection(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), correction((int) cl::Correction::none), bodies(nullptr), rigid_local(nullptr),
    comm_values(1)
{
  where = std::string("fix ") + id + " tdem/correction";
  const std::string syntax = "; syntax: fix ID group tdem/correction count|overlap|local_mass bodies FIXID";
  if (narg != 6 || std::strcmp(arg[4], "bodies") != 0)
    error->all(FLERR, where + ": expected 3 arguments (a correction, 'bodies' and a fix ID), got " +
                          std::to_string(narg - 3) + syntax);
  const std::string mode = arg[3];
  if (mode == "count") correction = (int) cl::Correction::count;
  else if (mode == "overlap") correction = (int) cl::Correction::overlap_share;
  else if (mode == "local_mass") correction = (int) cl::Correction::local_mass;
  else
    error->all(FLERR, where + ": correction '" + mode + "' is unknown; allowed: count, overlap, local_mass" + syntax);
  bodies_id = arg[5];
  if (!atom->molecule_flag)
    error->all(FLERR, where + " requires molecule IDs (the sides of the contact count): add 'fix ID all "
                              "property/atom mol ghost yes' before the atoms are created");
  comm_forward = correction == (int) cl::Correction::local_mass ? 12 : 1;
  if (correction == (int) cl::Correction::local_mass) compute_id = std::string(id) + "_rigid_local";
}

FixTDEMCorrection::~FixTDEMCorrection()
{
  if (!compute_id.empty() && modify && modify->find_compute(compute_id) >= 0) modify->delete_compute(compute_id);
}

int FixTDEMCorrection::setmask()
{
  return PRE_FORCE;
}

void FixTDEMCorrection::init()
{
  bodies = nullptr;
  for (int i = 0; i < modify->nfix; i++)
    if (bodies_id == modify->fix[i]->id) bodies = modify->fix[i];
  if (!bodies) error->all(FLERR, where + ": keyword 'bodies': fix " + bodies_id + " does not exist");
  if (!bodies->rigid_flag) no_bodies();
  if (correction == (int) cl::Correction::local_mass && !is_rigid_small(bodies->style))
    error->all(FLERR, where + ": correction 'local_mass' needs the bodies' centres of mass and inertia, which "
                          "only the rigid/small styles export (compute rigid/local); fix " + bodies_id + " is " +
                          std::string(bodies->style) + "; allowed with it: count, overlap");
  if (correction == (int) cl::Correction::local_mass) {
    // made here, once the body fix is known to be a rigid/small style; initialised here, since the
    // computes may be initialised before the fixes
    const int ic = modify->find_compute(compute_id);
    rigid_local = ic >= 0 ? modify->compute[ic]
                          : modify->add_compute(compute_id + " all rigid/local " + bodies_id + " " + kColumns);
    rigid_local->init();
  }
  for (int i = 0; i < modify->nfix; i++) {
    Fix *f = modify->fix[i];
    if (f != this && (std::strcmp(f->style, "tdem/correction") == 0 || std::strcmp(f->style, "tdem/clump") == 0)) {
      int d = 0;
      const int *c = (const int *) f->extract("tdem_clump_correction", d);
      if (std::strcmp(f->style, "tdem/correction") == 0 || (c && *c != (int) cl::Correction::none))
        error->all(FLERR, where + ": fix " + std::string(f->id) + " also applies a multiple-contact correction; "
                              "allowed: one");
    }
  }
}

void FixTDEMCorrection::no_bodies()
{
  error->all(FLERR, where + ": keyword 'bodies': fix " + bodies_id + " (" + std::string(bodies->style) +
                        ") exports no rigid bodies; allowed: a fix such as rigid/small or rigid (extract 'body' "
                        "and 'masstotal')");
}

void FixTDEMCorrection::grow()
{
  const std::size_t n = (std::size_t) atom->nmax;
  if (state.size() >= n) return;
  state.resize(n);
  body.resize(n);
  key.resize(n);
  if (correction != (int) cl::Correction::local_mass) return;
  mass.resize(n);
  com.resize(3 * n);
  pose.resize(7 * n);
  inv_inertia.resize(9 * n);
}

// The body atoms (owned and ghost) and, for local_mass, their bodies' data; before the pair and
// wall forces of every step
void FixTDEMCorrection::refresh()
{
  int dim = 0;
  const int *a2b = (const int *) bodies->extract("body", dim);  // set up before the forces
  if (!a2b || !bodies->extract("masstotal", dim)) no_bodies();
  grow();
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (correction == (int) cl::Correction::local_mass) body_data();
  else {
    for (int i = 0; i < nlocal; i++) state[i] = a2b[i] >= 0 ? 1.0 : 0.0;
    comm_values = 1;
    tdem_lammps::compat::forward_comm(comm, this, 1);
  }
  const tagint *mol = atom->molecule;
  for (int i = 0; i < nall; i++) {
    const bool in = state[i] > 0.0;
    body[i] = in ? i : -1;
    key[i] = in ? (std::int64_t) mol[i] : -1;
  }
}

void FixTDEMCorrection::body_data()
{
  int dim = 0;
  const int *a2b = (const int *) bodies->extract("body", dim);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) state[i] = 0.0;
  // the owning atom of every body of this rank carries the body's data
  rigid_local->compute_local();
  double **rows = rigid_local->array_local;
  for (int r = 0; r < rigid_local->size_local_rows; r++) {
    const int i = atom->map((tagint) rows[r][C_ID]);
    if (i < 0 || i >= nlocal) error->one(FLERR, where + ": the atom owning a body of fix " + bodies_id + " is missing");
    state[i] = 2.0;
    mass[i] = rows[r][C_MASS];
    for (int k = 0; k < 3; k++) com[3 * i + k] = rows[r][C_X + k];
    for (int k = 0; k < 7; k++) pose[7 * i + k] = rows[r][C_Q + k];
  }
  comm_values = 12;
  tdem_lammps::compat::forward_comm(comm, this, 12);
  // every owned atom of a body copies its body's data from the owning atom (owned or ghost here)
  const tagint *mol = atom->molecule;
  owner.clear();
  for (int i = 0; i < nall; i++)
    if (state[i] == 2.0) owner.emplace((std::int64_t) mol[i], i);
  for (int i = 0; i < nlocal; i++) {
    if (a2b[i] < 0 || state[i] == 2.0) continue;
    const auto it = owner.find((std::int64_t) mol[i]);
    if (it == owner.end())
      error->one(FLERR, where + ": no atom owning the body of molecule " + std::to_string((long long) mol[i]) +
                            " is in reach (one molecule ID per body is required)");
    const int o = it->second;
    state[i] = 1.0;
    mass[i] = mass[o];
    for (int k = 0; k < 3; k++) com[3 * i + k] = com[3 * o + k];
    for (int k = 0; k < 7; k++) pose[7 * i + k] = pose[7 * o + k];
  }
  tdem_lammps::compat::forward_comm(comm, this, 12);
  for (int i = 0; i < nall; i++) {
    if (state[i] <= 0.0) continue;
    const double *p = &pose[7 * i];
    const cl::Mat3 R = cl::rotation_matrix(cl::Quat{p[0], p[1], p[2], p[3]});
    const cl::Mat3 inv = cl::inverse_inertia_space(R, cl::Vec3{p[4], p[5], p[6]});
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) inv_inertia[9 * i + 3 * a + b] = inv[a][b];
  }
}

int FixTDEMCorrection::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    buf[m++] = state[j];
    if (comm_values == 1) continue;
    buf[m++] = mass[j];
    for (int c = 0; c < 3; c++) buf[m++] = com[3 * j + c];
    for (int c = 0; c < 7; c++) buf[m++] = pose[7 * j + c];
  }
  return m;
}

void FixTDEMCorrection::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    state[i] = buf[m++];
    if (comm_values == 1) continue;
    mass[i] = buf[m++];
    for (int c = 0; c < 3; c++) com[3 * i + c] = buf[m++];
    for (int c = 0; c < 7; c++) pose[7 * i + c] = buf[m++];
  }
}

void FixTDEMCorrection::setup_pre_force(int)
{
  refresh();
}

void FixTDEMCorrection::pre_force(int)
{
  refresh();
}

// as fix tdem/clump (clump_correction_host.h): "tdem_clump_correction" (dim 0), per atom (owned and
// ghost) "tdem_clump_body" / "body" (the atom's own index for a body atom, else -1), "tdem_clump_key"
// (int64 molecule ID), per such index "masstotal", "tdem_clump_com" (3), "tdem_clump_inv_inertia" (9)
// (local_mass only)
void *FixTDEMCorrection::extract(const char *name, int &dim)
{
  dim = 0;
  if (std::strcmp(name, "tdem_clump_correction") == 0) return (void *) &correction;
  dim = 1;
  if (std::strcmp(name, "tdem_clump_key") == 0) return (void *) key.data();
  if (std::strcmp(name, "tdem_clump_body") == 0 || std::strcmp(name, "body") == 0) return (void *) body.data();
  if (correction != (int) cl::Correction::local_mass) return nullptr;
  if (std::strcmp(name, "masstotal") == 0) return (void *) mass.data();
  dim = 2;
  if (std::strcmp(name, "tdem_clump_com") == 0) return (void *) com.data();
  if (std::strcmp(name, "tdem_clump_inv_inertia") == 0) return (void *) inv_inertia.data();
  return nullptr;
}

double FixTDEMCorrection::memory_usage()
{
  return (double) state.capacity() * sizeof(double) + (double) body.capacity() * sizeof(int) +
         (double) key.capacity() * sizeof(std::int64_t) +
         (double) (mass.capacity() + com.capacity() + pose.capacity() + inv_inertia.capacity()) * sizeof(double);
}
