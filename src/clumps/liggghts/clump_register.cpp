// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'clump' (fix tdem/clump).
#include <map>
#include <string>

#include "fix_tdem_clump.h"
#include "lammps.h"
#include "modify.h"
#include "tdem_liggghts.h"

namespace {

// LIGGGHTS 3.8 keeps Modify::fix_map private and has no registration API: an explicit template
// instantiation may name a private member ([temp.explicit]) and hands its pointer to a friend
// function (same technique as register_fixes in src/integrators/liggghts/fix_tdem_integrate.cpp).
using FixCreatorFn = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using FixMap = std::map<std::string, FixCreatorFn>;
struct ClumpFixMapMember {
  using type = FixMap* LAMMPS_NS::Modify::*;
};
template <class Tag, typename Tag::type M> struct ClumpExposeMember {
  friend typename Tag::type clump_member_pointer(Tag) { return M; }
};
ClumpFixMapMember::type clump_member_pointer(ClumpFixMapMember);
template struct ClumpExposeMember<ClumpFixMapMember, &LAMMPS_NS::Modify::fix_map>;

LAMMPS_NS::Fix* create_tdem_clump(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new LAMMPS_NS::FixTdemClump(lmp, narg, arg);
}

}  // namespace

namespace tdem {
namespace liggghts {

void register_clump(LAMMPS_NS::LAMMPS* lmp) {
  if (!lmp || !lmp->modify) return;
  FixMap* map = lmp->modify->*clump_member_pointer(ClumpFixMapMember());
  if (map) (*map)["tdem/clump"] = &create_tdem_clump;
}

}  // namespace liggghts
}  // namespace tdem
