// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: the run of a law (go), the list of law names, and the laws that are units
// (src/contact/law_unit.h) from --params, the values of their input line. A part of main.cpp.
#pragma once

#include "collide_analytic.h"

namespace {

template <class Law>
void go(Run& run, Law& law, const Bodies& b, double v0, const collision::Options& o) {
  if (run.obl.active) {
    run_oblique(run, law, o);
  } else if (run.sch.active) {
    collision::Frictionless none;
    scheme_with(run, law, none);
  } else {
    run.result = collision::integrate(law, b, v0, o);
  }
}

// The values of --law: lsd, hertz, the units of src/contact/laws.h, the other laws.
std::vector<std::string> law_names() {
  std::vector<std::string> laws = {"lsd", "hertz"};
  for (const tdem::law::Description* d : tdem::law::normal_laws) laws.push_back(d->name);
  for (const char* l : {"continuous_potential", "extended_linear", "extended_hertz"}) laws.push_back(l);
  return laws;
}

// The parameters of a unit law (src/contact/law_unit.h) from --params, the values of its input
// line as pair_coeff ... normal NAME <values> takes them, with the checks and words of its
// description.
template <class U>
typename U::Params read_unit_params(Args& a) {
  const tdem::law::Description& d = U::description;
  const std::vector<double> w = a.numbers("--params");
  const int n = static_cast<int>(w.size());
  if (!tdem::law::count_ok(d, n)) throw BadInput("option --params: " + tdem::law::count_message(d, n));
  double x[tdem::law::MAX_UNIT_VALUES], v[tdem::law::MAX_UNIT_VALUES];
  tdem::law::expand(d, w.data(), n, x);
  const std::string bad = tdem::law::check(d, x);
  if (!bad.empty()) throw BadInput("option --params: " + bad);
  try {
    tdem::law::unit_values(d, x, v);
    return U::params(v);
  } catch (const std::exception& e) {
    throw BadInput(std::string("option --params: ") + d.kind + " " + d.name + ": " + e.what());
  }
}

// --law NAME --params V1 V2 ...: a unit's input line as pair_coeff ... normal NAME <values> takes
// it, checked by its description; unit = its index in the list (-1: not a unit, an error).
void run_unit(Run& run, Args& a, int unit, const Bodies& b, double meff, double v0, const collision::Options& opt) {
  if (unit < 0)
    throw BadInput("option --params takes the values of a law of the list of src/contact/laws.h (" +
                   std::string(tdem::law::normal_laws[0]->name) + ", ...); --law " + run.law +
                   " has options of its own (see --help)");
  auto& P = run.params;
  tdem::law::visit<tdem::law::normal_units>(unit, [&](auto tag) {
    using U = typename decltype(tag)::type;
    collision::UnitLaw<U> law;
    if (a.has("--end") && read_end(a, U::end) != U::end)
      throw BadInput("option --end = " + a.str("--end") + " is not allowed for --law " + run.law + " (allowed: " +
                     to_string(U::end) + ")");
    law.p = read_unit_params<U>(a);
    const double reff = U::needs_reff ? need_reff(b, ("for --law " + run.law).c_str()) : 0.0;
    run.end = to_string(U::end);
    double x[tdem::law::MAX_UNIT_VALUES];
    const std::vector<double> words = a.numbers("--params");
    tdem::law::expand(U::description, words.data(), static_cast<int>(words.size()), x);
    for (int k = 0; k < tdem::law::value_count(U::description); ++k)
      P.push_back({tdem::law::parameter(U::description, k).name, x[k]});
    predict(run, "max_overlap", [&] { return U::max_overlap(law.p, meff, reff, v0); });
    if (!std::isnan(U::contact_time(law.p, meff, reff, v0)))
      predict(run, "contact_time", [&] { return U::contact_time(law.p, meff, reff, v0); });
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  });
}

}  // namespace
