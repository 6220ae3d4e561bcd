// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: registration of the styles of the module 'mixing' (compute tdem/mixing/velocity,
// fix tdem/mixing/depth; docs/mixing_hosts.md).
#include <map>
#include <string>

#include "compute_tdem_mixing_velocity.h"
#include "fix_tdem_mixing_depth.h"
#include "lammps.h"
#include "modify.h"
#include "tdem_liggghts.h"

using namespace LAMMPS_NS;

namespace {

// LIGGGHTS 3.8 keeps Modify::fix_map / compute_map private and has no registration API: an explicit
// template instantiation may name a private member ([temp.explicit]) and hands the member pointer
// to a friend function (as register_fixes in src/integrators/liggghts/fix_tdem_integrate.cpp).
using FixCreatorFn = Fix *(*)(LAMMPS *, int, char **);
using ComputeCreatorFn = Compute *(*)(LAMMPS *, int, int, char **);
struct MixFixMap {
  using type = std::map<std::string, FixCreatorFn> *Modify::*;
};
struct MixComputeMap {
  using type = std::map<std::string, ComputeCreatorFn> *Modify::*;
};
template <class Tag, typename Tag::type M>
struct MixExpose {
  friend typename Tag::type mix_member(Tag) { return M; }
};
MixFixMap::type mix_member(MixFixMap);
MixComputeMap::type mix_member(MixComputeMap);
template struct MixExpose<MixFixMap, &Modify::fix_map>;
template struct MixExpose<MixComputeMap, &Modify::compute_map>;

Fix *create_mixing_depth(LAMMPS *lmp, int narg, char **arg) { return new FixTdemMixingDepth(lmp, narg, arg); }
Compute *create_mixing_velocity(LAMMPS *lmp, int iarg, int narg, char **arg)
{
  return new ComputeTdemMixingVelocity(lmp, iarg, narg, arg);
}

}  // namespace

namespace tdem {
namespace liggghts {

void register_mixing(LAMMPS_NS::LAMMPS *lmp)
{
  if (!lmp || !lmp->modify) return;
  auto *fmap = lmp->modify->*mix_member(MixFixMap());
  auto *cmap = lmp->modify->*mix_member(MixComputeMap());
  if (fmap) (*fmap)["tdem/mixing/depth"] = &create_mixing_depth;
  if (cmap) (*cmap)["tdem/mixing/velocity"] = &create_mixing_velocity;
}

}  // namespace liggghts
}  // namespace tdem
