// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the list of contact laws that describe their input line (src/contact/law_parameters.h).
// A host parses, checks and reports the values of every law in this list in one place; a law
// added here with its Description is known to that parser without further edits.
//
// The normal laws that are units (src/contact/law_unit.h) are listed once, in normal_units: a law
// added there is parsed, checked, evaluated, restarted and advised on by both hosts, tdem-collide
// and the advice with no other edit (LIGGGHTS also needs its model id: one line in
// src/pair_styles/liggghts/tdem_liggghts_units.h).
//
// The laws with keyword forms (lsd stiffness|restitution, hertz with its damping members, the
// extended laws with their fits) describe their input too, with keyword groups; every normal law
// is named once in all_normal_laws, and the hosts read every input line through law_input.h.
// Their kernels run on paths of their own in the hosts (lsd's is bitwise gran/hooke/history).
#pragma once

#include "law_input.h"
#include "law_parameters.h"
#include "law_unit.h"
#include "normal/continuous_potential.h"
#include "normal/extended.h"
#include "normal/hertz_damped.h"
#include "normal/linear_viscoelastic.h"
#include "tangential/cundall_strack.h"
#include "normal/luding.h"
#include "normal/power_law_hysteresis.h"
#include "normal/thornton.h"
#include "normal/walton_braun.h"
#include "tangential/di_renzo.h"
#include "tangential/haff_werner.h"
#include "tangential/linear_spring.h"
#include "tangential/mindlin_deresiewicz.h"
#include "tangential/mindlin_no_slip.h"
#include "tangential/walton_braun_tangential.h"

#include <cstring>

namespace tdem {
namespace law {

// The normal laws as units, in the order of their LAMMPS law numbers (stable only within one
// build: restart files store the law's name).
using normal_units = Units<walton_braun::Law, thornton::Law, power_law::Law, luding::Law>;

// Their descriptions.
inline constexpr const auto& normal_laws = normal_units::descriptions;

// Every normal law of the hosts' input lines, in the order of their "allowed:" lists: lsd, hertz,
// the units, the extended laws, continuous_potential.
template <class L>
struct AllNormal;
template <class... U>
struct AllNormal<Units<U...>> {
  static constexpr const Description* list[] = {&lsd::description, &hertz::description, &U::description...,
                                                &extended::linear_description, &extended::hertz_description,
                                                &continuous_potential::description};
};
inline constexpr const auto& all_normal_laws = AllNormal<normal_units>::list;

// The tangential laws other than cundall_strack (whose two forms, cundall_strack::
// stiffness_description and ratio_description, depend on the normal law).
inline constexpr const Description* tangential_laws[] = {
    &haff_werner::description,         &linear_spring::description,   &walton_braun_tangential::description,
    &mindlin_deresiewicz::description, &mindlin_no_slip::description, &di_renzo::description,
};

// Every tangential law of the hosts' input lines: cundall_strack (its first form), then the others.
inline constexpr const Description* all_tangential_laws[] = {
    &cundall_strack::stiffness_description, &haff_werner::description,         &linear_spring::description,
    &walton_braun_tangential::description,  &mindlin_deresiewicz::description, &mindlin_no_slip::description,
    &di_renzo::description,
};

// The law of `name` in the list, or nullptr.
template <int N>
inline const Description* find(const Description* const (&list)[N], const char* name) {
  for (const Description* d : list)
    if (std::strcmp(d->name, name) == 0) return d;
  return nullptr;
}

}  // namespace law
}  // namespace tdem
