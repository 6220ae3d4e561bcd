// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the one registration table of the LAMMPS styles. Used by tdem-lammps
// (direct insertion into the style maps) and by the plugin (lammpsplugin_init).
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tdem_lammps {

enum class StyleKind { pair, fix, compute };

struct StyleEntry {
  StyleKind kind;
  const char *name;
  const char *info;
  void *creator;  // Pair *(*)(LAMMPS *), Fix *(*)(LAMMPS *, int, char **) or Compute *(*)(...)
};

// Styles of the optional modules (CMake options TDEM_LAMMPS_<MODULE>, default ON), each a table
// terminated by an entry with name == nullptr; defined in src/<module>/lammps/*_styles.cpp.
const StyleEntry *grate_styles();     // TDEM_LMP_MODULE_GRATE    (src/grate/lammps)
const StyleEntry *mixing_styles();    // TDEM_LMP_MODULE_MIXING   (src/grate/lammps)
const StyleEntry *timestep_styles();  // TDEM_LMP_MODULE_TIMESTEP (src/advice/lammps)
const StyleEntry *clump_styles();     // TDEM_LMP_MODULE_CLUMP    (src/clumps/lammps)

// The table of all styles (core + enabled modules), terminated by an entry with name == nullptr.
const StyleEntry *style_table();

// Insert every style of the table into lmp->force->pair_map / modify->fix_map / compute_map.
void register_styles(LAMMPS_NS::LAMMPS *lmp);

// The LAMMPS version (LAMMPS_VERSION) these styles were compiled against.
const char *compiled_lammps_version();

}  // namespace tdem_lammps
