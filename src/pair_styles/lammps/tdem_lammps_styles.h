// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the one registration table of the LAMMPS styles. Used by tdem-lammps
// (direct insertion into the style maps) and by the plugin (lammpsplugin_init).
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tdem_lammps {

enum class StyleKind { pair, fix };

struct StyleEntry {
  StyleKind kind;
  const char *name;
  const char *info;
  void *creator;  // Pair *(*)(LAMMPS *) or Fix *(*)(LAMMPS *, int, char **)
};

// The table, terminated by an entry with name == nullptr.
const StyleEntry *style_table();

// Insert every style of the table into lmp->force->pair_map / lmp->modify->fix_map.
void register_styles(LAMMPS_NS::LAMMPS *lmp);

// The LAMMPS version (LAMMPS_VERSION) these styles were compiled against.
const char *compiled_lammps_version();

}  // namespace tdem_lammps
