// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: compile-time instantiation of one (normal, tangential, cohesion, rolling, surface)
// combination as a LIGGGHTS pair gran and wall gran style, registered under the same hash
// LIGGGHTS computes from the `model ... tangential ...` keywords.
#pragma once

#include <cstdint>

#include "contact_models.h"
// fix_insert_stream_predefined.h (included by pair_gran_base.h) is a stub in LIGGGHTS-PUBLIC
// that derives from FixInsertStream without including its header.
#include "fix_insert_stream.h"
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"

#include "normal_model_tdem_lsd.h"
#include "normal_model_tdem_hertz.h"
#include "normal_model_tdem_walton_braun.h"
#include "normal_model_tdem_thornton.h"
#include "normal_model_tdem_continuous_potential.h"
#include "normal_model_tdem_power_law.h"
#include "normal_model_tdem_extended_linear.h"
#include "normal_model_tdem_extended_hertz.h"
#include "tangential_model_tdem_cundall_strack.h"
#include "tangential_model_tdem_laws.h"
#include "rolling_model_tdem_sds.h"

namespace tdem {
namespace liggghts {
namespace detail {

void note_compiled(int64_t hash);  // registry.cpp: remembers what is compiled in

template <class CModel>
LIGGGHTS::PairStyles::IGranularPairStyle* create_pair(LAMMPS_NS::LAMMPS* lmp, LAMMPS_NS::PairGran* parent,
                                                       int64_t hash) {
  return new LIGGGHTS::PairStyles::Granular<CModel>(lmp, parent, hash);
}

template <class CModel>
LIGGGHTS::Walls::IGranularWall* create_wall(LAMMPS_NS::LAMMPS* lmp, LAMMPS_NS::FixWallGran* parent,
                                            int64_t hash) {
  return new LIGGGHTS::Walls::Granular<CModel>(lmp, parent, hash);
}

template <int N, int T, int C = LIGGGHTS::ContactModels::COHESION_OFF,
          int R = LIGGGHTS::ContactModels::ROLLING_OFF, int S = LIGGGHTS::ContactModels::SURFACE_DEFAULT>
void register_combo() {
  using Style = LIGGGHTS::ContactModels::GranStyle<N, T, C, R, S>;
  using CModel = LIGGGHTS::ContactModels::ContactModel<Style>;
  const int64_t hash = Style::HASHCODE;
  LIGGGHTS::PairStyles::Factory::instance().addStyle("gran", static_cast<int>(hash), &create_pair<CModel>);
  LIGGGHTS::Walls::Factory::instance().addStyle("gran", static_cast<int>(hash), &create_wall<CModel>);
  note_compiled(hash);
}

// The same combination with the surface model tdem/clump (the multiple-contact correction of fix
// tdem/clump); the translation unit includes surface_model_tdem_clump.h.
template <int N, int T>
void register_clump_combo() {
  register_combo<N, T, LIGGGHTS::ContactModels::COHESION_OFF, LIGGGHTS::ContactModels::ROLLING_OFF,
                 LIGGGHTS::ContactModels::TDEM_CLUMP_SURFACE>();
}

// One function per translation unit (they compile in parallel).
void register_lsd_a();
void register_lsd_b();
void register_stock_hooke();
void register_stock_hertz();
void register_lsd_rolling();
void register_hertz_rolling();
void register_hertz();
void register_walton_braun();
void register_thornton();
void register_continuous_potential();
void register_power_law();
void register_extended_linear();
void register_extended_hertz();
void register_tangential_haff_werner();
void register_tangential_linear_spring();
void register_tangential_walton_braun();
void register_tangential_mindlin_deresiewicz();
void register_tangential_mindlin_no_slip();
void register_tangential_di_renzo();
void register_clump_a();  // surface tdem/clump (register_clump_{a,b}.cpp)
void register_clump_b();

}  // namespace detail
}  // namespace liggghts
}  // namespace tdem
