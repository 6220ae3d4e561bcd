// SPDX-License-Identifier: GPL-2.0-or-later
// tdem LAMMPS plugin: lammpsplugin_init registers the tdem styles with the LAMMPS PLUGIN
// package ABI (lammpsplugin.h). Load with `plugin load /path/to/tdem_lammps_plugin.so` in a
// PLUGIN-enabled LAMMPS of the same version (shared-library build) or in tdem-lammps.
#include "lammpsplugin.h"
#include "version.h"

#include "tdem_lammps_styles.h"

extern "C" __attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle,
                                                                          void *regfunc)
{
  auto reg = (lammpsplugin_regfunc) regfunc;
  for (const tdem_lammps::StyleEntry *e = tdem_lammps::style_table(); e->name; ++e) {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.author = "tdem contributors";
    plugin.handle = handle;
    plugin.name = e->name;
    plugin.info = e->info;
    if (e->kind == tdem_lammps::StyleKind::pair) {
      plugin.style = "pair";
      plugin.creator.v1 = (lammpsplugin_factory1 *) e->creator;
    } else if (e->kind == tdem_lammps::StyleKind::compute) {
      plugin.style = "compute";
      plugin.creator.v2 = (lammpsplugin_factory2 *) e->creator;
    } else {
      plugin.style = "fix";
      plugin.creator.v2 = (lammpsplugin_factory2 *) e->creator;
    }
    (*reg)(&plugin, lmp);
  }
}
