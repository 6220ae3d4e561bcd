// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/correction (see fix_tdem_correction.h and docs/liggghts/fix_tdem_clump.md).
#include "fix_tdem_correction.h"

#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_multisphere.h"
#include "modify.h"
#include "multisphere.h"

#include "fixes/clumps/rigid_body.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;

bool FixTDEMCorrection::Sides::in_body(int i) const { return ms->belongs_to(i) >= 0; }
std::int64_t FixTDEMCorrection::Sides::key(int i) const { return std::int64_t(ms->belongs_to(i)) + 1; }

namespace {
constexpr int kValues = 14;  // per atom: set flag, mass, com (3), inverse inertia (9)
}

// 1/M + (r x n).I^-1 (r x n), r = sphere centre - com (the contact point lies on the normal through
// the centre)
double FixTDEMCorrection::Sides::inverse_side_mass(int i, const double* n) const {
  const double* d = &data[kValues * static_cast<std::size_t>(i)];
  double r[3] = {atom->x[i][0] - d[2], atom->x[i][1] - d[3], atom->x[i][2] - d[4]};
  domain->minimum_image(r);
  const double c[3] = {r[1] * n[2] - r[2] * n[1], r[2] * n[0] - r[0] * n[2], r[0] * n[1] - r[1] * n[0]};
  const double* I = d + 5;
  double q = 0.0;
  for (int a = 0; a < 3; a++) q += c[a] * (I[3 * a] * c[0] + I[3 * a + 1] * c[1] + I[3 * a + 2] * c[2]);
  return 1.0 / d[1] + q;
}

FixTDEMCorrection::FixTDEMCorrection(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg), mode_(cl::Correction::none), link_(lmp, sides_) {
  where_ = std::string("fix ") + id + " tdem/correction";
  const std::string syntax = "; syntax: fix ID group tdem/correction count|overlap|local_mass bodies FIXID";
  if (narg != 6 || std::strcmp(arg[4], "bodies") != 0)
    fail(where_ + ": expected 3 arguments (a correction, 'bodies' and a fix ID), got " + std::to_string(narg - 3) +
         syntax);
  const std::string mode = arg[3];
  if (mode == "count") mode_ = cl::Correction::count;
  else if (mode == "overlap") mode_ = cl::Correction::overlap_share;
  else if (mode == "local_mass") mode_ = cl::Correction::local_mass;
  else
    fail(where_ + ": correction '" + mode + "' is unknown; allowed: count, overlap, local_mass" + syntax);
  bodies_id_ = arg[5];
  sides_.domain = domain;
  sides_.atom = atom;
  if (mode_ == cl::Correction::local_mass) comm_forward = comm_reverse = kValues;
}

FixTDEMCorrection::~FixTDEMCorrection() {
  if (tdem::liggghts::clump_link::active == &link_) tdem::liggghts::clump_link::active = nullptr;
}

void FixTDEMCorrection::fail(const std::string& msg) {
  error->all(FLERR, msg.c_str());
  std::abort();  // not reached
}

int FixTDEMCorrection::setmask() { return PRE_FORCE; }

void FixTDEMCorrection::init() {
  const int ifix = modify->find_fix(bodies_id_.c_str());
  if (ifix < 0) fail(where_ + ": keyword 'bodies': fix " + bodies_id_ + " does not exist");
  Fix* f = modify->fix[ifix];
  sides_.ms = std::strncmp(f->style, "multisphere", 11) == 0 ? static_cast<FixMultisphere*>(f) : nullptr;
  if (!sides_.ms)
    fail(where_ + ": keyword 'bodies': fix " + bodies_id_ + " (" + std::string(f->style) +
         ") is not a fix multisphere; allowed: the ID of a fix multisphere (for fix tdem/clump bodies use its own "
         "keyword 'correction')");
  auto*& act = tdem::liggghts::clump_link::active;
  if (act && act != &link_)
    fail(where_ + ": another fix (tdem/clump or tdem/correction) already applies a multiple-contact correction; "
                  "allowed: one");
  act = &link_;
}

void FixTDEMCorrection::setup_pre_force(int) {
  link_.setup(mode_, where_, 0.0);
  pre_force(0);
}

void FixTDEMCorrection::pre_force(int) {
  if (link_.tallies()) link_.tally();
  else body_data();
}

// local_mass: every atom (owned and ghost) of a body gets the body's mass, com and inverse inertia
void FixTDEMCorrection::body_data() {
  const int nall = atom->nlocal + atom->nghost;
  const std::size_t need = kValues * static_cast<std::size_t>(atom->nmax > nall ? atom->nmax : nall);
  if (sides_.data.size() < need) sides_.data.resize(need);
  Multisphere& ms = sides_.ms->data();
  double** xcm = ms.extract_double_vector("xcm");
  double** inertia = ms.extract_double_vector("inertia");
  double** ex = ms.extract_double_vector("ex_space");
  double** ey = ms.extract_double_vector("ey_space");
  double** ez = ms.extract_double_vector("ez_space");
  double* mass = ms.extract_double_scalar("masstotal");
  if (!xcm || !inertia || !ex || !ey || !ez || !mass)
    fail(where_ + ": fix " + bodies_id_ + " does not expose its bodies' xcm, inertia, axes and mass");
  for (int i = 0; i < nall; i++) {
    double* d = &sides_.data[kValues * static_cast<std::size_t>(i)];
    d[0] = 0.0;
    const int tag = sides_.ms->belongs_to(i);
    const int b = tag >= 0 ? ms.map(tag) : -1;
    if (b < 0) continue;  // a free sphere, or a body owned by another rank
    d[0] = 1.0;
    d[1] = mass[b];
    for (int k = 0; k < 3; k++) d[2 + k] = xcm[b][k];
    cl::Mat3 R;
    for (int k = 0; k < 3; k++) R[k] = cl::Vec3{ex[b][k], ey[b][k], ez[b][k]};
    const cl::Mat3 inv = cl::inverse_inertia_space(R, cl::Vec3{inertia[b][0], inertia[b][1], inertia[b][2]});
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 3; c++) d[5 + 3 * a + c] = inv[a][c];
  }
  comm->reverse_comm_fix(this);  // to the ranks owning the atoms
  for (int i = 0; i < atom->nlocal; i++)
    if (sides_.ms->belongs_to(i) >= 0 && sides_.data[kValues * static_cast<std::size_t>(i)] != 1.0)
      error->one(FLERR, (where_ + ": the body of atom " + std::to_string(atom->tag[i]) +
                         " is on no rank that holds the atom").c_str());
  comm->forward_comm_fix(this);  // to their ghosts
}

// LIGGGHTS 3.8's Comm takes the values per atom from the pack functions (the LAMMPS of 2013)
int FixTDEMCorrection::pack_reverse_comm(int n, int first, double* buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < kValues; k++) buf[m++] = sides_.data[kValues * static_cast<std::size_t>(i) + k];
  return kValues;
}

// only the rank owning the body has set the values of a ghost
void FixTDEMCorrection::unpack_reverse_comm(int n, int* list, double* buf) {
  for (int k = 0; k < n; k++, buf += kValues)
    if (buf[0] == 1.0)
      for (int c = 0; c < kValues; c++) sides_.data[kValues * static_cast<std::size_t>(list[k]) + c] = buf[c];
}

int FixTDEMCorrection::pack_comm(int n, int* list, double* buf, int, int*) {
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < kValues; c++) buf[m++] = sides_.data[kValues * static_cast<std::size_t>(list[k]) + c];
  return kValues;
}

void FixTDEMCorrection::unpack_comm(int n, int first, double* buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int c = 0; c < kValues; c++) sides_.data[kValues * static_cast<std::size_t>(i) + c] = buf[m++];
}

double FixTDEMCorrection::memory_usage() { return static_cast<double>(sides_.data.capacity()) * sizeof(double); }
