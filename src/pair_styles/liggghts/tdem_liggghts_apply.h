// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: applies a normal law's force sidata.Fn to the two partners the way LIGGGHTS's own
// normal models do (same arithmetic, so trajectories stay bitwise equal to the stock models).
#pragma once

#include "contact_interface.h"
#include "contact/kinematics.h"

namespace tdem {
namespace liggghts {

// LIGGGHTS calls a model's surfacesClose only for pairs closer than contactDistanceFactor x
// radsum, i.e. never for separated spheres by default, so the history of a pair that separated
// lives on until the next neighbour rebuild. A law whose history must start afresh at every new
// contact (xi_max of the hysteretic laws, v0 and coefficients of the extended laws) keeps the
// step of its last evaluation + 1 in an extra history slot `stamp`; when the pair was apart
// since then, the law's n values from `hist` on are cleared before the law runs. Set-up passes
// (no update) neither clear nor stamp. (Tangential laws are left as in stock LIGGGHTS.)
inline void clear_history_of_new_contact(double& stamp, double* hist, int n, double step, bool update) {
  const double now = step + 1.0;
  if (stamp != 0.0 && now - stamp > 1.0)
    for (int s = 0; s < n; ++s) hist[s] = 0.0;
  if (update) stamp = now;
}

// Adds the normal force fn along the normal to the two partners (a wall: times the element's area
// ratio, to i only). Written out as the stock models do it (a loop with the wall test
// inside cost 0.9-1.3 % pair-loop instructions); with the partners' forces still zero, as when a
// normal model applies its force, it is their arithmetic exactly.
inline void add_normal_force(const LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, double fn,
                             LIGGGHTS::ContactModels::ForceData& i_forces,
                             LIGGGHTS::ContactModels::ForceData& j_forces) {
  if (sidata.is_wall) {
    const double fw = fn * sidata.area_ratio;
    i_forces.delta_F[0] += fw * sidata.en[0];
    i_forces.delta_F[1] += fw * sidata.en[1];
    i_forces.delta_F[2] += fw * sidata.en[2];
  } else {
    const double f0 = fn * sidata.en[0], f1 = fn * sidata.en[1], f2 = fn * sidata.en[2];
    i_forces.delta_F[0] += f0;
    i_forces.delta_F[1] += f1;
    i_forces.delta_F[2] += f2;
    j_forces.delta_F[0] -= f0;
    j_forces.delta_F[1] -= f1;
    j_forces.delta_F[2] -= f2;
  }
}

inline void apply_normal_force(const LIGGGHTS::ContactModels::SurfacesIntersectData& sidata,
                               LIGGGHTS::ContactModels::ForceData& i_forces,
                               LIGGGHTS::ContactModels::ForceData& j_forces) {
  add_normal_force(sidata, sidata.Fn, i_forces, j_forces);
}

// The two entry points of a tdem normal model's evaluate<Result>(sidata, out) (the law on the
// contact data, its result published to sidata for the tangential law and, if Result, written to
// *out; always inlined into its caller):
//  - intersect: LIGGGHTS's surfacesIntersect, the law and its force applied. The model declares
//    its surfacesIntersect [[gnu::flatten]], so that the law's kernel is inlined there whatever
//    else calls it (the grid correction's probes call it too, which made GCC keep tdem::hertz::force
//    out of line: +1.8 % pair-loop instructions);
//  - law_result: the result (the grid correction's probe, tdem_liggghts_grid.h).
template <class Model>
[[gnu::always_inline]] inline void intersect(Model& m, LIGGGHTS::ContactModels::SurfacesIntersectData& sidata,
                                             LIGGGHTS::ContactModels::ForceData& i_forces,
                                             LIGGGHTS::ContactModels::ForceData& j_forces) {
  m.template evaluate<false>(sidata, nullptr);
  apply_normal_force(sidata, i_forces, j_forces);
}
template <class Model>
tdem::NormalResult<double> law_result(Model& m, LIGGGHTS::ContactModels::SurfacesIntersectData& sidata) {
  tdem::NormalResult<double> r;
  m.template evaluate<true>(sidata, &r);
  return r;
}

// Publish a normal law's result to the contact data: force, stiffnesses and damping that the
// tangential law reads; no tangential damping.
inline void publish_normal_result(LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, double fn, double kn,
                                  double kt, double gamman) {
  sidata.Fn = fn;
  sidata.kn = kn;
  sidata.kt = kt;
  sidata.gamman = gamman;
  sidata.gammat = 0.0;
}

}  // namespace liggghts
}  // namespace tdem
