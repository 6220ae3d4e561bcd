// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: a normal law as one unit of code. A law whose state is a set of history slots and that
// has no damping (walton_braun, thornton, power_law) declares, in its own file under
// src/contact/normal/, a `struct Law` with everything a host, the advice and the tools need:
//
//   static constexpr const law::Description& description;  // input line, ranges, history
//   using Params;                                            // the kernel's parameters (doubles)
//   static constexpr bool needs_reff;                        // the kernel reads R*
//   static constexpr double stress_strain_exponent;          // F ~ xi^x (1 linear, 1.5 Hertz)
//   static constexpr ContactEnd end;                         // how a contact ends
//   static constexpr const char* properties[];               // each parameter's name as a per-
//                                                            // type-pair property (LIGGGHTS
//                                                            // fix property/global NAME ...)
//   static constexpr const char* tangential_basis_text;      // "kl", "2 E* a", "dF/dxi"
//   static Params params(const double* v);                   // from the values of unit_values()
//                                                            // (below); throws on values the
//                                                            // ranges cannot express
//   static NormalResult<double> force(const Params&, const NormalKinematics<double>&,
//                                     double* hist, bool update);
//   static double tangential_basis(const Params&, const NormalResult<double>&,
//                                  const NormalKinematics<double>&);  // k_t = KAPPA * this
//   // the time-step advice (src/fixes/timestep/timestep.h) of a head-on impact at v:
//   static const char* family(const Params&);                 // its name there
//   static double max_overlap(const Params&, double meff, double reff, double v);  // checks p
//   static double stiffness_at(const Params&, double reff, double xi_max);  // largest tangent
//                                                            // stiffness with the largest overlap
//                                                            // xi_max (no damping: these laws
//                                                            // have none)
//   static double contact_time(const Params&, double meff, double reff, double v);  // NaN: no
//                                                            // closed form (the advice integrates)
//   static double contact_time_estimate(const Params&, double meff, double reff, double v0);
//                                                            // the step of an integrated impact
//
// Optional: a unit that declares
//   static void fit_guess(const law::FitHint&, double* own);  // starting values of its own values
// is fitted to impact data by tdem-fit (src/drivers/fit/fit_unit.h) with no further edit: every
// own value is a fitted parameter, the materials come from the data.
//
// The list of units is src/contact/laws.h (normal_units). The hosts take a unit through the
// templates below (visit by name or by description), and store its Params type-erased in a
// ParamStore, so that a law added to that list is parsed, checked, evaluated, restarted and
// advised on in both hosts without further edits.
#pragma once

#include <cmath>
#include <cstring>
#include <new>
#include <type_traits>

#include "kinematics.h"
#include "law_parameters.h"
#include "material.h"

namespace tdem {
namespace law {

// The kernel parameters of any unit, type-erased: plain doubles, trivially copyable, so that a
// host's per-type-pair table stays plain data.
struct ParamStore {
  static constexpr int capacity = 8;
  double v[capacity] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

  template <class P>
  void set(const P& p) {
    static_assert(std::is_trivially_copyable<P>::value && sizeof(P) <= sizeof(v), "Params must fit ParamStore");
    std::memcpy(v, &p, sizeof(P));
  }
  // The stored parameters in place (no copy: a host's per-pair table is read as the kernel's
  // Params on the contact path, as a struct member would be). P must be the type set() stored.
  template <class P>
  const P& as() const {
    static_assert(std::is_standard_layout<P>::value && sizeof(P) <= sizeof(v) && alignof(P) <= alignof(double),
                  "Params must fit ParamStore");
    return *std::launder(reinterpret_cast<const P*>(v));
  }
  template <class P>
  P get() const {
    static_assert(std::is_trivially_copyable<P>::value && sizeof(P) <= sizeof(v), "Params must fit ParamStore");
    P p;
    std::memcpy(&p, v, sizeof(P));
    return p;
  }
};

// What tdem-fit knows of the data when it asks a unit for starting values (fit_guess): the pair
// (E* from the data's materials), the median impact velocity and its restitution (< 1), the median
// contact time (NaN without contact-time data).
struct FitHint {
  double estar, meff, reff, v_ref, e_ref, tc_ref;
};
template <class U, class = void>
struct HasFitGuess : std::false_type {};
template <class U>
struct HasFitGuess<U, std::void_t<decltype(&U::fit_guess)>> : std::true_type {};

// The largest number of expanded values of a unit (materials E1 NU1 E2 NU2 + the law's own).
inline constexpr int MAX_UNIT_VALUES = 12;

template <class U>
struct Tag {
  using type = U;
};

// A list of units.
template <class... U>
struct Units {
  static constexpr int size = sizeof...(U);
  static constexpr const Description* descriptions[sizeof...(U) > 0 ? sizeof...(U) : 1] = {&U::description...};
};

// The I-th unit of a list: UnitAt<I, L>.
template <int I, class L>
struct UnitAtT;
template <class First, class... Rest>
struct UnitAtT<0, Units<First, Rest...>> {
  using type = First;
};
template <int I, class First, class... Rest>
struct UnitAtT<I, Units<First, Rest...>> : UnitAtT<I - 1, Units<Rest...>> {};
template <int I, class L>
using UnitAt = typename UnitAtT<I, L>::type;

namespace detail {
template <int I, class F, class First, class... Rest>
bool visit_at(int k, F&& f, Units<First, Rest...>*) {
  if (k == I) {
    f(Tag<First>{});
    return true;
  }
  if constexpr (sizeof...(Rest) > 0)
    return visit_at<I + 1>(k, static_cast<F&&>(f), static_cast<Units<Rest...>*>(nullptr));
  else
    return false;
}
}  // namespace detail

// Index of the unit of description d (or of name) in the list L; -1 if none.
template <class L>
int index_of(const Description* d) {
  for (int k = 0; k < L::size; ++k)
    if (L::descriptions[k] == d) return k;
  return -1;
}
template <class L>
int index_of(const char* name) {
  for (int k = 0; k < L::size; ++k)
    if (std::strcmp(L::descriptions[k]->name, name) == 0) return k;
  return -1;
}

// f(Tag<U>{}) for the k-th unit of L; false if there is none.
template <class L, class F>
bool visit(int k, F&& f) {
  if constexpr (L::size == 0)
    return false;
  else
    return detail::visit_at<0>(k, static_cast<F&&>(f), static_cast<L*>(nullptr));
}

// f(Tag<U>{}) for every unit of L, in order.
template <class L, class F>
void for_each(F&& f) {
  for (int k = 0; k < L::size; ++k) visit<L>(k, f);
}

// The kernel parameters of unit U from the expanded values v, stored.
template <class U>
ParamStore store(const double* v) {
  ParamStore s;
  s.set(U::params(v));
  return s;
}

// The values a unit's params() receives, from the expanded value list x of its description: x
// itself, or, for a law with materials, E* = 1/((1-NU1^2)/E1 + (1-NU2^2)/E2) in place of the four
// material values, then the law's own (a host that has E* already, as LIGGGHTS's Yeff, passes it).
inline int unit_value_count(const Description& d) { return (d.materials ? 1 : 0) + d.count; }
inline void unit_values(const Description& d, const double* x, double* out) {
  const int m = d.materials ? MATERIAL_VALUES : 0, o = d.materials ? 1 : 0;
  if (d.materials) out[0] = material::effective_modulus(x[0], x[1], x[2], x[3]);
  for (int k = 0; k < d.count; ++k) out[o + k] = x[m + k];
}

// Does a parameter carry force units (N, N/m, Pa, ...)? Hosts with their own unit systems scale
// such values (LIGGGHTS: force->nktv2p).
inline bool force_units(const Parameter& p) { return p.unit[0] == 'N' || (p.unit[0] == 'P' && p.unit[1] == 'a'); }

}  // namespace law
}  // namespace tdem
