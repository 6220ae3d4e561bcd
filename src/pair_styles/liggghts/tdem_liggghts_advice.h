// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: a read-only registry through which every tdem normal model publishes its
// settings and its per-type-pair coefficients, so that fix tdem/timestep (src/fixes/timestep/liggghts)
// advises the law exactly as the model evaluates it (issue 8).
//
// Key: the owner of the contact model, i.e. the LIGGGHTS::IContactHistorySetup* the model is
// constructed with (the PairGran of pair gran, or the FixWallGran of a fix wall/gran; the fix
// finds it with static_cast<LIGGGHTS::IContactHistorySetup*>(pair or wall)). A model publishes in
// connectToProperties (after its settings and properties are known; called from the owner's
// init) and withdraws in its destructor. Nothing here is touched by surfacesIntersect: the
// contact loop is unchanged.
//
// The published callback returns the law's coefficients for one pair of type i, j (a wall: j the
// wall's type), with the effective mass, effective radius and contact distance of that pair, in
// the very form the model hands them to its tdem kernel (k and gamma formed from m*, R* as in
// surfacesIntersect; SI force units, i.e. already divided by force->nktv2p).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>

#include "contact/normal/continuous_potential.h"
#include "contact/normal/extended.h"
#include "contact/normal/hertz_damped.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/law_unit.h"

namespace tdem {
namespace liggghts {
namespace advice {

// `unit`: a normal law of src/contact/laws.h (normal_units), Entry::unit its index there.
enum class Law { lsd, hertz, continuous_potential, extended_linear, extended_hertz, unit };

// One contact for which the coefficients are asked.
struct PairData {
  int itype = 0, jtype = 0;  // jtype: the partner's type (a wall: the wall's atom type)
  bool wall = false;
  double meff = 0.0;      // m* (a wall: the particle's mass)
  double reff = 0.0;      // R* (a wall: the particle's radius)
  double distance = 0.0;  // R_i + R_j (a wall: R_i), the contact distance of tdem/continuous_potential
};

// The coefficients of the law of the entry (only the member of Entry::law is filled).
struct Coefficients {
  lsd::Coefficients<double> lsd{0.0, 0.0};
  hertz::Params<double> hertz{0.0, 0.0, 0.0};
  law::ParamStore unit{};  // the unit's Params
  continuous_potential::Params<double> potential{0.0, 0.0, 0.0, 0.0, 0.0};
  extended::LinearParams extended_linear{};
  extended::HertzParams extended_hertz{};
};

struct Entry {
  const void* model = nullptr;  // the publishing model (withdraw only removes its own entry)
  Law law = Law::lsd;
  int unit = -1;  // Law::unit: index in tdem::law::normal_units
  std::string name;      // "tdem/lsd", ...
  std::string settings;  // the model settings in force, e.g. "parameters stiffness, limitForce on"
  ContactEnd end = ContactEnd::zero_overlap;      // limitForce off | on
  hertz::Damping damping = hertz::Damping::tsuji;  // tdem/hertz only
  std::function<Coefficients(const PairData&)> coefficients;
};

inline std::map<const void*, Entry>& entries() {
  static std::map<const void*, Entry> m;
  return m;
}

inline void publish(const void* owner, Entry e) { entries()[owner] = std::move(e); }

inline void withdraw(const void* owner, const void* model) {
  auto& m = entries();
  auto it = m.find(owner);
  if (it != m.end() && it->second.model == model) m.erase(it);
}

// nullptr: the owner has no tdem normal model (a stock model, or none yet initialised).
inline const Entry* find(const void* owner) {
  const auto& m = entries();
  const auto it = m.find(owner);
  return it == m.end() ? nullptr : &it->second;
}

inline const char* on_off(bool b) { return b ? "on" : "off"; }

// Publishes the entry of `model` under `owner` with the coefficients of its per-type-pair table
// (a copy is kept): fill(row of types i j, pair data, coefficients) writes the law's member.
// Returns the published entry.
template <class Table, class Fill>
Entry& publish_table(const void* owner, const void* model, Law law, std::string name, ContactEnd end,
                     std::string settings, const Table& table, Fill fill,
                     hertz::Damping damping = hertz::Damping::tsuji) {
  Entry e;
  e.model = model;
  e.law = law;
  e.name = std::move(name);
  e.settings = std::move(settings);
  e.end = end;
  e.damping = damping;
  e.coefficients = [table, fill](const PairData& d) {
    Coefficients c;
    fill(table(d.itype, d.jtype), d, c);
    return c;
  };
  publish(owner, std::move(e));
  return entries()[owner];
}

}  // namespace advice
}  // namespace liggghts
}  // namespace tdem
