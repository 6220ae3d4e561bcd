// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/correction (see fix_tdem_correction.h and docs/clumps_liggghts.md).
#include "fix_tdem_correction.h"

#include <cstdlib>
#include <cstring>
#include <string>

#include "error.h"
#include "fix_multisphere.h"
#include "modify.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace cl = tdem::clumps;

bool FixTDEMCorrection::Sides::in_body(int i) const { return ms->belongs_to(i) >= 0; }
std::int64_t FixTDEMCorrection::Sides::key(int i) const { return std::int64_t(ms->belongs_to(i)) + 1; }

FixTDEMCorrection::FixTDEMCorrection(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg), mode_(cl::Correction::none), link_(lmp, sides_) {
  where_ = std::string("fix ") + id + " tdem/correction";
  const std::string syntax = "; syntax: fix ID group tdem/correction count|overlap bodies FIXID";
  if (narg != 6 || std::strcmp(arg[4], "bodies") != 0)
    fail(where_ + ": expected 3 arguments (a correction, 'bodies' and a fix ID), got " + std::to_string(narg - 3) +
         syntax);
  const std::string mode = arg[3];
  if (mode == "count") mode_ = cl::Correction::count;
  else if (mode == "overlap") mode_ = cl::Correction::overlap_share;
  else if (mode == "local_mass")
    fail(where_ + ": correction 'local_mass' needs the centre of mass and inertia of the body of every ghost "
                  "sphere, which fix multisphere keeps only on the rank owning the body; allowed here: count, "
                  "overlap (local_mass: fix tdem/clump ... correction local_mass)");
  else
    fail(where_ + ": correction '" + mode + "' is unknown; allowed: count, overlap" + syntax);
  bodies_id_ = arg[5];
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

void FixTDEMCorrection::pre_force(int) { link_.tally(); }
