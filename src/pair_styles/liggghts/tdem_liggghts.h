// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: entry points of the tdem LIGGGHTS styles.
#pragma once

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tdem {
namespace liggghts {

// Adds the tdem contact laws to LIGGGHTS's contact-model factories: the model names
// (`model tdem/lsd`, `tangential tdem/cundall_strack`) and the compiled pair gran / wall gran
// combinations. Call once, before the first `new LAMMPS(...)`. Idempotent.
void register_styles();

// Installs the checking "gran" model selector (better error messages for unknown model names
// and for tdem combinations that are not compiled) and lets it report through this instance's
// error path. Call right after `new LAMMPS(...)` (whose constructor installs LIGGGHTS's own
// selector), and with nullptr before deleting the instance. Optional: without it, the tdem
// models work and LIGGGHTS's generic messages are given.
void attach(LAMMPS_NS::LAMMPS* lmp);

// The -h listing of what tdem adds: the contact models by kind (pair_style gran / fix wall/gran
// `model`, `tangential`, `surface`, `rolling_friction`) and the fix and compute styles.
std::string style_listing();
// "fix NAME" / "compute NAME" of every add_fix_style / add_compute_style with lmp == nullptr
// (fixes/liggghts/style_maps.cpp)
std::vector<std::string>& listed_styles();

// Fix/compute styles of the optional modules (CMake options TDEM_LIGGGHTS_<MODULE>, default ON),
// inserted into the instance's style maps by attach(); defined in src/fixes/<module>/liggghts/
// (register_fixes: fix tdem/integrate, src/integrators/liggghts/, always on).
void register_fixes(LAMMPS_NS::LAMMPS* lmp);
void register_grate(LAMMPS_NS::LAMMPS* lmp);     // TDEM_LIG_MODULE_GRATE    (src/fixes/grate/liggghts)
void register_mixing(LAMMPS_NS::LAMMPS* lmp);    // TDEM_LIG_MODULE_MIXING   (src/fixes/mixing/liggghts)
void register_timestep(LAMMPS_NS::LAMMPS* lmp);  // TDEM_LIG_MODULE_TIMESTEP (src/fixes/timestep/liggghts)
void register_clump(LAMMPS_NS::LAMMPS* lmp);     // TDEM_LIG_MODULE_CLUMP    (src/fixes/clumps/liggghts)

}  // namespace liggghts
}  // namespace tdem
