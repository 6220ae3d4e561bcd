// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'grate' (fix tdem/grate).
#include <map>
#include <string>

#include "fix_tdem_grate.h"
#include "lammps.h"
#include "modify.h"
#include "tdem_liggghts.h"

namespace {

// LIGGGHTS 3.8 keeps Modify::fix_map private and has no registration API: an explicit template
// instantiation may name a private member ([temp.explicit]) and hands its pointer to a friend
// function (same technique as register_fixes in src/integrators/liggghts/fix_tdem_integrate.cpp).
using FixCreatorFn = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using FixMap = std::map<std::string, FixCreatorFn>;
struct GrateFixMapMember {
  using type = FixMap* LAMMPS_NS::Modify::*;
};
template <class Tag, typename Tag::type M> struct GrateExposeMember {
  friend typename Tag::type grate_member_pointer(Tag) { return M; }
};
GrateFixMapMember::type grate_member_pointer(GrateFixMapMember);
template struct GrateExposeMember<GrateFixMapMember, &LAMMPS_NS::Modify::fix_map>;

LAMMPS_NS::Fix* create_tdem_grate(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new LAMMPS_NS::FixTdemGrate(lmp, narg, arg);
}

}  // namespace

namespace tdem {
namespace liggghts {

void register_grate(LAMMPS_NS::LAMMPS* lmp) {
  if (!lmp || !lmp->modify) return;
  FixMap* map = lmp->modify->*grate_member_pointer(GrateFixMapMember());
  if (map) (*map)["tdem/grate"] = &create_tdem_grate;
}

}  // namespace liggghts
}  // namespace tdem
