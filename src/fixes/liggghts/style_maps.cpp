// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: the style maps of Modify (see style_maps.h). An explicit template
// instantiation may name a private member ([temp.explicit]); it hands the member pointer to a
// friend function, which add_fix_style / add_compute_style call.
#include "style_maps.h"

#include "tdem_liggghts.h"

#include "lammps.h"
#include "modify.h"

#include <map>
#include <string>
#include <vector>

namespace {

struct FixMapTag {
  using type = std::map<std::string, tdem::liggghts::FixCreator>* LAMMPS_NS::Modify::*;
};
struct ComputeMapTag {
  using type = std::map<std::string, tdem::liggghts::ComputeCreator>* LAMMPS_NS::Modify::*;
};
template <class Tag, typename Tag::type M>
struct ExposeMember {
  friend typename Tag::type member_of(Tag) { return M; }
};
FixMapTag::type member_of(FixMapTag);
ComputeMapTag::type member_of(ComputeMapTag);
template struct ExposeMember<FixMapTag, &LAMMPS_NS::Modify::fix_map>;
template struct ExposeMember<ComputeMapTag, &LAMMPS_NS::Modify::compute_map>;

}  // namespace

namespace tdem {
namespace liggghts {

std::vector<std::string>& listed_styles() {
  static std::vector<std::string> names;
  return names;
}

void add_fix_style(LAMMPS_NS::LAMMPS* lmp, const char* name, FixCreator create) {
  if (!lmp) listed_styles().push_back(std::string("fix ") + name);
  if (!lmp || !lmp->modify) return;
  auto* map = lmp->modify->*member_of(FixMapTag());
  if (map) (*map)[name] = create;
}

void add_compute_style(LAMMPS_NS::LAMMPS* lmp, const char* name, ComputeCreator create) {
  if (!lmp) listed_styles().push_back(std::string("compute ") + name);
  if (!lmp || !lmp->modify) return;
  auto* map = lmp->modify->*member_of(ComputeMapTag());
  if (map) (*map)[name] = create;
}

}  // namespace liggghts
}  // namespace tdem
