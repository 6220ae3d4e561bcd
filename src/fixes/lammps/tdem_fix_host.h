// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: what a fix or compute shared by both engines (src/fixes/<module>/hosts/) needs to know of
// LAMMPS. Its twin src/fixes/liggghts/tdem_fix_host.h gives the same names for LIGGGHTS; each
// host's build puts its own on the include path.
//   tdem_host::all / one / warning   Error::all / one / warning with a std::string message
//   tdem_host::CB_GROW, CB_RESTART   the Atom::add_callback flags
//   tdem_host::set_maxexchange       Fix::maxexchange (LIGGGHTS has none)
//   TDEM_COMPUTE_CTOR_ARGS, TDEM_COMPUTE_BASE_INIT, TDEM_COMPUTE_FIRST_ARG, TDEM_COMPUTE_ARGS_DONE
//                                    the compute constructor: (lmp, narg, arg) here,
//                                    (lmp, iarg, narg, arg) in LIGGGHTS
#pragma once

#include "atom.h"
#include "error.h"
#include "fix.h"

#include <string>

namespace tdem_host {

inline constexpr const char *engine = "LAMMPS";
inline constexpr int CB_GROW = LAMMPS_NS::Atom::GROW;
inline constexpr int CB_RESTART = LAMMPS_NS::Atom::RESTART;

inline void all(LAMMPS_NS::Error *e, const char *file, int line, const std::string &m) { e->all(file, line, m); }
inline void one(LAMMPS_NS::Error *e, const char *file, int line, const std::string &m) { e->one(file, line, m); }
inline void warning(LAMMPS_NS::Error *e, const char *file, int line, const std::string &m) { e->warning(file, line, m); }

inline void set_maxexchange(LAMMPS_NS::Fix *f, int n) { f->maxexchange = n; }

}  // namespace tdem_host

#define TDEM_COMPUTE_CTOR_ARGS int narg, char **arg
#define TDEM_COMPUTE_CTOR_DECL int, char **
#define TDEM_COMPUTE_BASE_INIT(lmp) Compute(lmp, narg, arg)
#define TDEM_COMPUTE_FIRST_ARG 3
#define TDEM_COMPUTE_ARGS_DONE()
