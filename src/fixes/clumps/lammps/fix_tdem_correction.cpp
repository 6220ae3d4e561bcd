// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/correction (see fix_tdem_correction.h and docs/clumps_lammps.md).
#include "fix_tdem_correction.h"

#include "contact/multi_contact/multi_contact.h"

#include "atom.h"
#include "error.h"
#include "modify.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;

FixTDEMCorrection::FixTDEMCorrection(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), correction((int) cl::Correction::none), bodies(nullptr)
{
  where = std::string("fix ") + id + " tdem/correction";
  const std::string syntax = "; syntax: fix ID group tdem/correction count|overlap bodies FIXID";
  if (narg != 6 || std::strcmp(arg[4], "bodies") != 0)
    error->all(FLERR, where + ": expected 3 arguments (a correction, 'bodies' and a fix ID), got " +
                          std::to_string(narg - 3) + syntax);
  const std::string mode = arg[3];
  if (mode == "count") correction = (int) cl::Correction::count;
  else if (mode == "overlap") correction = (int) cl::Correction::overlap_share;
  else if (mode == "local_mass")
    error->all(FLERR, where + ": correction 'local_mass' needs the bodies' centres of mass and inertia, which "
                          "fix rigid and rigid/small do not export; allowed here: count, overlap (local_mass: fix "
                          "tdem/clump ... correction local_mass)");
  else
    error->all(FLERR, where + ": correction '" + mode + "' is unknown; allowed: count, overlap" + syntax);
  bodies_id = arg[5];
  if (!atom->molecule_flag)
    error->all(FLERR, where + " requires molecule IDs (the sides of the contact count): add 'fix ID all "
                              "property/atom mol ghost yes' before the atoms are created");
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

// the molecule ID of every body atom (owned and ghost), read before the pair and wall forces
void FixTDEMCorrection::update_keys()
{
  int dim = 0;
  const int *body = (const int *) bodies->extract("body", dim);  // set up before the forces
  if (!body || !bodies->extract("masstotal", dim)) no_bodies();
  const int n = atom->nlocal + atom->nghost;
  if ((int) key.size() < atom->nmax) key.resize(atom->nmax);
  for (int i = 0; i < n; i++) key[i] = (body && body[i] >= 0) ? (std::int64_t) atom->molecule[i] : -1;
}

void FixTDEMCorrection::setup_pre_force(int)
{
  update_keys();
}

void FixTDEMCorrection::pre_force(int)
{
  update_keys();
}

// as fix tdem/clump (clump_correction_host.h): "tdem_clump_correction" (dim 0), per atom
// "tdem_clump_body" / "body" (the body fix's index), "tdem_clump_key" (int64 molecule ID), per body
// "masstotal"
void *FixTDEMCorrection::extract(const char *name, int &dim)
{
  dim = 0;
  if (std::strcmp(name, "tdem_clump_correction") == 0) return (void *) &correction;
  dim = 1;
  if (std::strcmp(name, "tdem_clump_key") == 0) return (void *) key.data();
  if (!bodies) return nullptr;
  if (std::strcmp(name, "tdem_clump_body") == 0 || std::strcmp(name, "body") == 0)
    return bodies->extract("body", dim);
  if (std::strcmp(name, "masstotal") == 0) return bodies->extract("masstotal", dim);
  return nullptr;
}

double FixTDEMCorrection::memory_usage()
{
  return (double) key.capacity() * sizeof(std::int64_t);
}
