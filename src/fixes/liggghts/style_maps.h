// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: put a fix or compute style into an instance's style maps. LIGGGHTS 3.8 keeps
// Modify::fix_map and Modify::compute_map private and has no registration API; style_maps.cpp
// reaches them once for every tdem module. A `clear` command rebuilds the maps without them.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
class Compute;
}  // namespace LAMMPS_NS

namespace tdem {
namespace liggghts {

using FixCreator = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using ComputeCreator = LAMMPS_NS::Compute* (*)(LAMMPS_NS::LAMMPS*, int, int, char**);

// Both do nothing for an instance without Modify; lmp == nullptr only records "fix NAME" /
// "compute NAME" in listed_styles() (tdem_liggghts.h; the -h listing collects the names so).
void add_fix_style(LAMMPS_NS::LAMMPS* lmp, const char* name, FixCreator create);
void add_compute_style(LAMMPS_NS::LAMMPS* lmp, const char* name, ComputeCreator create);

// new T(lmp, narg, arg) / new T(lmp, iarg, narg, arg) as a creator
template <class T>
LAMMPS_NS::Fix* create_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new T(lmp, narg, arg);
}
template <class T>
LAMMPS_NS::Compute* create_compute(LAMMPS_NS::LAMMPS* lmp, int iarg, int narg, char** arg) {
  return new T(lmp, iarg, narg, arg);
}

}  // namespace liggghts
}  // namespace tdem
