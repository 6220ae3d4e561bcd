// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: reporting an error found on one rank only (inside the force loop) through LIGGGHTS's
// error->one, so that the message is not lost.
//
// LIGGGHTS 3.8.0's Error::one writes to `screen` without flushing and calls MPI_Abort, so when
// the output goes to a pipe or file the message is lost; it also never writes to the log file.
// error_one() writes the message to the log file and makes `screen` unbuffered first.
#pragma once

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tdem {
namespace liggghts {

[[noreturn]] void error_one(LAMMPS_NS::LAMMPS* lmp, const char* file, int line, const std::string& msg);

// A contact with distance 0 between the centres (pair, j >= 0) or between a centre and a wall
// surface (wall): its normal is undefined. Stops with the atom IDs instead of NaN forces. The
// models call it behind an unlikely branch, so it costs one compare per contact.
[[noreturn, gnu::cold, gnu::noinline]] void zero_distance(LAMMPS_NS::LAMMPS* lmp, const char* model, int i, int j, bool wall);
// The same for `model tdem/<law>` of a law name (a compile-time constant: the caller's hot path
// builds no string).
[[noreturn, gnu::cold, gnu::noinline]] void zero_distance_of_law(LAMMPS_NS::LAMMPS* lmp, const char* law, int i, int j,
                                                                 bool wall);

}  // namespace liggghts
}  // namespace tdem
