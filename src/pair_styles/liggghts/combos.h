// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the one list of (normal, tangential, cohesion, rolling, surface) combinations that tdem
// compiles into LIGGGHTS's pair gran and wall gran, built from the lists of laws by the rules
// below. The build compiles each group of the list in a translation unit of its own
// (register_part.inc, generated register_part_<k>.cpp, TDEM_LIGGGHTS_PARTS of them), so that it
// compiles in parallel; a law added to a list below is compiled in with every partner its rule
// gives it, with no file to write.
//
// The rules (121 combinations with the lists as they are):
//  - every tdem normal law with the basic tangential models (tdem/cundall_strack, history, off)
//    and with every tdem tangential law; and with surface tdem/clump and the basic ones;
//  - tdem/lsd also with the stock no_history, with and without surface tdem/clump;
//  - tdem/continuous_potential with the basic tangential models only (it passes no tangent
//    stiffness to a tangential law), with and without surface tdem/clump;
//  - the stock hertz and hooke with tdem/cundall_strack and every tdem tangential law, and with
//    surface tdem/clump and the stock history and off; hertz/stiffness with tdem/cundall_strack;
//    hooke/stiffness with tdem/cundall_strack, and with surface tdem/clump and history, off;
//  - rolling: tdem/lsd + tdem/cundall_strack with the stock cdt and epsd2 and tdem/sds; tdem/hertz
//    with tdem/cundall_strack and tdem/mindlin_deresiewicz, each with epsd2 and tdem/sds.
#pragma once

#include "contact_models.h"
#include "tdem_liggghts_ids.h"

namespace tdem {
namespace liggghts {
namespace combos {

using namespace LIGGGHTS::ContactModels;

// ---------------------------------------------------------------- the lists of laws
// (the laws that are units, TDEM_LIGGGHTS_UNITS of tdem_liggghts_ids.h, between hertz and the
// extended laws)
#define TDEM_UNIT_ID(constant, id, ns) constant,
inline constexpr int tdem_normals[] = {TDEM_LSD, TDEM_HERTZ, TDEM_LIGGGHTS_UNITS(TDEM_UNIT_ID) TDEM_EXTENDED_LINEAR,
                                       TDEM_EXTENDED_HERTZ};
#undef TDEM_UNIT_ID
inline constexpr int tdem_tangentials[] = {TDEM_HAFF_WERNER,         TDEM_LINEAR_SPRING,   TDEM_WALTON_BRAUN_T,
                                           TDEM_MINDLIN_DERESIEWICZ, TDEM_MINDLIN_NO_SLIP, TDEM_DI_RENZO};
inline constexpr int basic_tangentials[] = {TDEM_CUNDALL_STRACK, TANGENTIAL_HISTORY, TANGENTIAL_OFF};
inline constexpr int stock_normals[] = {HERTZ, HOOKE};

// The combinations whose contact model is tdem's (tdem_liggghts_grid.h: LIGGGHTS's sequence of
// the five models, and the keyword grid_correction, each compiled twice: without and with the
// correction): a tdem normal law with the default surface.
constexpr bool tdem_contact_model(int normal, int surface) {
  if (surface != SURFACE_DEFAULT) return false;
  for (int n : tdem_normals)
    if (n == normal) return true;
  return false;
}

// ---------------------------------------------------------------- the list of combinations
struct Combo {
  int normal, tangential, cohesion, rolling, surface;
  int group;  // combinations of one group are compiled in one translation unit
};

struct List {
  static constexpr int capacity = 256;
  Combo at[capacity] = {};
  int count = 0;
  int groups = 0;  // the next group starts at index `groups`
  constexpr void add(int n, int t, int r = ROLLING_OFF, int s = SURFACE_DEFAULT) {
    at[count++] = Combo{n, t, COHESION_OFF, r, s, groups};
  }
  constexpr void add_clump(int n, int t) { add(n, t, ROLLING_OFF, TDEM_CLUMP_SURFACE); }
  constexpr void next_group() { ++groups; }
};

// The groups keep the translation units small and alike (a normal law with the basic tangential
// models; a tdem tangential law with every normal law; the clump combinations in two halves; the
// stock laws; rolling). Mixed units of about 12 combinations changed the instructions per contact
// of tdem/hertz by 1.6 % (most likely GCC's per-unit inlining limits); with these groups every law
// stays within 0.3 % of the hand-written units (bench/liggghts/bench_laws.sh, CALLGRIND=1).
constexpr List build() {
  List l;
  for (int n : tdem_normals) {
    for (int t : basic_tangentials) l.add(n, t);
    if (n == TDEM_LSD) l.add(TDEM_LSD, TANGENTIAL_NO_HISTORY);
    l.next_group();
  }
  for (int t : tdem_tangentials) {
    for (int n : tdem_normals) l.add(n, t);
    for (int n : stock_normals) l.add(n, t);
    l.next_group();
  }
  constexpr int nn = sizeof(tdem_normals) / sizeof(tdem_normals[0]);
  for (int k = 0; k < nn; ++k) {  // clumps: the first four normal laws, then the rest
    const int n = tdem_normals[k];
    if (k == 4) l.next_group();
    for (int t : basic_tangentials) l.add_clump(n, t);
    if (n == TDEM_LSD) l.add_clump(TDEM_LSD, TANGENTIAL_NO_HISTORY);
  }
  for (int t : basic_tangentials) l.add_clump(TDEM_CONTINUOUS_POTENTIAL, t);
  for (int n : stock_normals) l.add_clump(n, TANGENTIAL_HISTORY), l.add_clump(n, TANGENTIAL_OFF);
  l.add_clump(HOOKE_STIFFNESS, TANGENTIAL_HISTORY), l.add_clump(HOOKE_STIFFNESS, TANGENTIAL_OFF);
  l.next_group();
  for (int t : basic_tangentials) l.add(TDEM_CONTINUOUS_POTENTIAL, t);
  l.next_group();
  l.add(HOOKE, TDEM_CUNDALL_STRACK), l.add(HOOKE_STIFFNESS, TDEM_CUNDALL_STRACK);
  l.next_group();
  l.add(HERTZ, TDEM_CUNDALL_STRACK), l.add(HERTZ_STIFFNESS, TDEM_CUNDALL_STRACK);
  l.next_group();
  for (int r : {ROLLING_CDT, ROLLING_EPSD2, TDEM_SDS}) l.add(TDEM_LSD, TDEM_CUNDALL_STRACK, r);
  l.next_group();
  for (int t : {TDEM_CUNDALL_STRACK, TDEM_MINDLIN_DERESIEWICZ})
    for (int r : {ROLLING_EPSD2, TDEM_SDS}) l.add(TDEM_HERTZ, t, r);
  l.next_group();
  return l;
}

inline constexpr List list = build();
static_assert(list.count <= List::capacity, "raise List::capacity");

// The translation unit of group g: TDEM_LIGGGHTS_PARTS units, one group each while there are
// fewer groups than units (a group more shares a unit).
constexpr int part_of(int group, int parts) { return group % parts; }

// Number of combinations of translation unit `part` of `parts`, and the index of the k-th of them.
constexpr int part_count(int part, int parts) {
  int n = 0;
  for (int i = 0; i < list.count; ++i) n += part_of(list.at[i].group, parts) == part ? 1 : 0;
  return n;
}
constexpr int part_index(int part, int parts, int k) {
  for (int i = 0; i < list.count; ++i)
    if (part_of(list.at[i].group, parts) == part && k-- == 0) return i;
  return -1;
}

}  // namespace combos
}  // namespace liggghts
}  // namespace tdem
