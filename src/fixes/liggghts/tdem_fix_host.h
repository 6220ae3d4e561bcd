// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: what a fix or compute shared by both engines (src/fixes/<module>/hosts/) needs to know of
// LIGGGHTS 3.8; the twin of src/fixes/lammps/tdem_fix_host.h (the names are explained there).
#pragma once

#include "atom.h"
#include "error.h"
#include "fix.h"

#include <string>

namespace tdem_host {

inline constexpr const char *engine = "LIGGGHTS";
inline constexpr int CB_GROW = 0;     // Atom::add_callback(0): grow_arrays and copy_arrays
inline constexpr int CB_RESTART = 1;  // Atom::add_callback(1): unpack_restart

inline void all(LAMMPS_NS::Error *e, const char *file, int line, const std::string &m) { e->all(file, line, m.c_str()); }
inline void one(LAMMPS_NS::Error *e, const char *file, int line, const std::string &m) { e->one(file, line, m.c_str()); }
inline void warning(LAMMPS_NS::Error *e, const char *file, int line, const std::string &m)
{
  e->warning(file, line, m.c_str());
}

inline void set_maxexchange(LAMMPS_NS::Fix *, int) {}  // LIGGGHTS sizes its exchange buffer itself

}  // namespace tdem_host

#define TDEM_COMPUTE_CTOR_ARGS int &iarg, int narg, char **arg
#define TDEM_COMPUTE_CTOR_DECL int &, int, char **
#define TDEM_COMPUTE_BASE_INIT(lmp) Compute(lmp, iarg, narg, arg)
#define TDEM_COMPUTE_FIRST_ARG iarg
#define TDEM_COMPUTE_ARGS_DONE() (iarg = narg)
