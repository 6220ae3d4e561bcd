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
#include "normal_model_tdem_history.h"
#include "normal_model_tdem_continuous_potential.h"
#include "normal_model_tdem_extended_linear.h"
#include "normal_model_tdem_extended_hertz.h"
#include "tangential_model_tdem_cundall_strack.h"
#include "tangential_model_tdem_laws.h"
#include "rolling_model_tdem_sds.h"
#include "combos.h"
#include "tdem_liggghts_grid.h"

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

// The pair and wall creators of contact model CModel under its hash.
template <class CModel>
void add() {
  const int64_t hash = CModel::STYLE_HASHCODE;
  LIGGGHTS::PairStyles::Factory::instance().addStyle("gran", static_cast<int>(hash), &create_pair<CModel>);
  LIGGGHTS::Walls::Factory::instance().addStyle("gran", static_cast<int>(hash), &create_wall<CModel>);
  note_compiled(hash);
}

template <int N, int T, int C = LIGGGHTS::ContactModels::COHESION_OFF,
          int R = LIGGGHTS::ContactModels::ROLLING_OFF, int S = LIGGGHTS::ContactModels::SURFACE_DEFAULT>
void register_combo() {
  using Style = LIGGGHTS::ContactModels::GranStyle<N, T, C, R, S>;
  if constexpr (combos::tdem_contact_model(N, S)) {
    add<LIGGGHTS::ContactModels::TdemContactModel<Style, false>>();
    add<LIGGGHTS::ContactModels::TdemContactModel<Style, true>>();  // grid_correction on
  } else {
    add<LIGGGHTS::ContactModels::ContactModel<Style>>();
  }
}

// Part k of the list of combinations (combos.h), k < TDEM_LIGGGHTS_PARTS: one generated
// translation unit each (register_part.inc), so that they compile in parallel.
template <int Part>
void register_part();

}  // namespace detail
}  // namespace liggghts
}  // namespace tdem
