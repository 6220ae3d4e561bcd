// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the arguments of `fix ID group tdem/integrate scheme NAME [rotation yes|no]` and the
// set-up check of its atoms, the same in LAMMPS and LIGGGHTS. The parser says what is wrong
// (ArgProblem); each engine words the message in its own convention (src/integrators/<host>/).
#pragma once

#include <mpi.h>

#include <string>

#include "integrators/schemes.h"

namespace tdem {
namespace integrators {

struct FixArgs {
  Scheme scheme = Scheme::velocity_verlet;
  bool rotation = true;
};

struct ArgProblem {
  enum Kind { none, scheme_needs_value, scheme_unknown, rotation_needs_value, rotation_unknown, unknown_keyword,
              scheme_missing };
  Kind kind = none;
  std::string word;  // the value or keyword at fault
};

// arg[iarg ..] up to narg; out holds what was read up to a problem.
inline ArgProblem parse_fix_args(int narg, char** arg, int iarg, FixArgs& out) {
  bool have_scheme = false;
  for (; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    const bool has_value = iarg + 1 < narg;
    const std::string val = has_value ? arg[iarg + 1] : "";
    if (key == "scheme") {
      if (!has_value) return {ArgProblem::scheme_needs_value, key};
      if (!parse_scheme(val, out.scheme)) return {ArgProblem::scheme_unknown, val};
      have_scheme = true;
    } else if (key == "rotation") {
      if (!has_value) return {ArgProblem::rotation_needs_value, key};
      if (val != "yes" && val != "no") return {ArgProblem::rotation_unknown, val};
      out.rotation = val == "yes";
    } else {
      return {ArgProblem::unknown_keyword, key};
    }
  }
  if (!have_scheme) return {ArgProblem::scheme_missing, ""};
  return {};
}

// Does any atom of the group (on any rank) lack a positive radius? (the angular acceleration
// divides by r^2: extended particles only, as fix nve/sphere)
template <class AtomT>
bool any_point_particle(MPI_Comm world, const AtomT* atom, int groupbit) {
  int bad = 0, any = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && !(atom->radius[i] > 0.0)) bad = 1;
  MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

}  // namespace integrators
}  // namespace tdem
