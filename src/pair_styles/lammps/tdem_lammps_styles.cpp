// SPDX-License-Identifier: GPL-2.0-or-later
#include "tdem_lammps_styles.h"

#include "compute_tdem_energy.h"
#include "fix_tdem_energy_store.h"
#include "fix_tdem_wall_gran.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "pair_tdem_gran.h"
#include "version.h"

#include <cstdio>
#include <vector>

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {
const StyleEntry core_table[] = {
    {StyleKind::pair, "tdem/gran", "tdem pair style tdem/gran (lsd + cundall_strack)",
     (void *) &create_pair<PairTDEMGran>},
    {StyleKind::fix, "tdem/wall/gran", "tdem fix style tdem/wall/gran (lsd + cundall_strack)",
     (void *) &create_fix<FixTDEMWallGran>},
    {StyleKind::compute, "tdem/energy", "tdem compute style tdem/energy (energy balance of pair tdem/gran)",
     (void *) &create_compute<ComputeTDEMEnergy>},
    // internal (upper case, as LAMMPS's own NEIGH_HISTORY): created by pair tdem/gran energy yes
    {StyleKind::fix, "TDEM/ENERGY/STORE", "tdem internal per-atom store of pair tdem/gran energy yes",
     (void *) &create_fix<FixTDEMEnergyStore>},
    {}};
}  // namespace

const StyleEntry *style_table()
{
  static const std::vector<StyleEntry> all = [] {
    std::vector<StyleEntry> v;
    auto add = [&v](const StyleEntry *t) {
      for (; t->name; ++t) v.push_back(*t);
    };
    add(core_table);
    add(integrate_styles());
#ifdef TDEM_LMP_MODULE_GRATE
    add(grate_styles());
#endif
#ifdef TDEM_LMP_MODULE_MIXING
    add(mixing_styles());
#endif
#ifdef TDEM_LMP_MODULE_TIMESTEP
    add(timestep_styles());
#endif
#ifdef TDEM_LMP_MODULE_CLUMP
    add(clump_styles());
#endif
    v.push_back(StyleEntry{StyleKind::pair, nullptr, nullptr, nullptr});
    return v;
  }();
  return all.data();
}

std::string style_listing()
{
  std::string out = "\n* tdem styles (tdem-lammps adds them to the lists above; one page per style in docs/lammps/):\n";
  const struct {
    StyleKind kind;
    const char *title;
  } kinds[] = {{StyleKind::pair, "Pair"}, {StyleKind::fix, "Fix"}, {StyleKind::compute, "Compute"}};
  for (const auto &k : kinds) {
    std::string body, line;
    for (const StyleEntry *e = style_table(); e->name; ++e)
      if (e->kind == k.kind && !(e->name[0] >= 'A' && e->name[0] <= 'Z')) {  // internal styles unlisted
        char cell[32];
        std::snprintf(cell, sizeof cell, "%-20s", e->name);
        if (line.size() + 20 > 80) {
          body += line + "\n";
          line.clear();
        }
        line += cell;
      }
    out += std::string("\n* ") + k.title + " styles (tdem):\n" + body + line + "\n";
  }
  return out;
}

void register_styles(LAMMPS *lmp)
{
  for (const StyleEntry *e = style_table(); e->name; ++e) {
    if (e->kind == StyleKind::pair)
      (*lmp->force->pair_map)[e->name] = (Force::PairCreator) e->creator;
    else if (e->kind == StyleKind::fix)
      (*lmp->modify->fix_map)[e->name] = (Modify::FixCreator) e->creator;
    else
      (*lmp->modify->compute_map)[e->name] = (Modify::ComputeCreator) e->creator;
  }
}

const char *compiled_lammps_version()
{
  return LAMMPS_VERSION;
}

}  // namespace tdem_lammps
