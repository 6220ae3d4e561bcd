// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the one registration table of the LAMMPS styles. Used by tdem-lammps
// (direct insertion into the style maps) and by the plugin (lammpsplugin_init).
#pragma once

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
class Pair;
class Fix;
class Compute;
}  // namespace LAMMPS_NS

namespace tdem_lammps {

enum class StyleKind { pair, fix, compute };

struct StyleEntry {
  StyleKind kind;
  const char *name;
  const char *info;
  void *creator;  // Pair *(*)(LAMMPS *), Fix *(*)(LAMMPS *, int, char **) or Compute *(*)(...)
};

// Creators of the table entries: (void *) &create_fix<FixTDEMClump>. A table ends with {}.
template <class T>
LAMMPS_NS::Pair *create_pair(LAMMPS_NS::LAMMPS *lmp)
{
  return new T(lmp);
}
template <class T>
LAMMPS_NS::Fix *create_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
template <class T>
LAMMPS_NS::Compute *create_compute(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

// Entries of a fix or compute style T.
template <class T>
StyleEntry fix_entry(const char *name, const char *info)
{
  return {StyleKind::fix, name, info, (void *) &create_fix<T>};
}
template <class T>
StyleEntry compute_entry(const char *name, const char *info)
{
  return {StyleKind::compute, name, info, (void *) &create_compute<T>};
}

// Defines a module's table function from its entries, as LAMMPS's FixStyle(name, class) lines
// do: TDEM_LAMMPS_MODULE(clump_styles, fix_entry<FixTDEMClump>("tdem/clump", "..."))
#define TDEM_LAMMPS_MODULE(function, ...)                  \
  const StyleEntry *function()                             \
  {                                                        \
    static const StyleEntry table[] = {__VA_ARGS__, {}};   \
    return table;                                          \
  }

// Styles of the optional modules (CMake options TDEM_LAMMPS_<MODULE>, default ON), each a table
// terminated by an entry with name == nullptr; defined in src/fixes/<module>/lammps/*_styles.cpp
// (integrate_styles: src/integrators/lammps/integrate_styles.cpp).
const StyleEntry *integrate_styles();  // fix tdem/integrate, always on (src/integrators/lammps)
const StyleEntry *grate_styles();      // TDEM_LMP_MODULE_GRATE    (src/fixes/grate/lammps)
const StyleEntry *mixing_styles();     // TDEM_LMP_MODULE_MIXING   (src/fixes/mixing/lammps)
const StyleEntry *timestep_styles();   // TDEM_LMP_MODULE_TIMESTEP (src/fixes/timestep/lammps)
const StyleEntry *clump_styles();      // TDEM_LMP_MODULE_CLUMP    (src/fixes/clumps/lammps)

// The table of all styles (core + enabled modules), terminated by an entry with name == nullptr.
const StyleEntry *style_table();

// The -h listing of the table: "* Pair styles (tdem):", "* Fix styles (tdem):", "* Compute styles
// (tdem):" with the names, in LAMMPS's layout (LAMMPS's own help prints its compiled lists only).
std::string style_listing();

// Insert every style of the table into lmp->force->pair_map / modify->fix_map / compute_map.
void register_styles(LAMMPS_NS::LAMMPS *lmp);

// The LAMMPS version (LAMMPS_VERSION) these styles were compiled against.
const char *compiled_lammps_version();

}  // namespace tdem_lammps
