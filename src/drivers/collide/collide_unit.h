// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: the run of a law (go), the list of law names, and the laws that are units
// (src/contact/law_unit.h) from --params, the values of their input line. A part of main.cpp.
#pragma once

#include "collide_analytic.h"

#include <sstream>

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

// The values of --law: every normal law of src/contact/laws.h.
std::vector<std::string> law_names() {
  std::vector<std::string> laws;
  for (const tdem::law::Description* d : tdem::law::all_normal_laws) laws.push_back(d->name);
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

// The words of --params (blanks or commas between them).
std::vector<std::string> param_words(Args& a) {
  std::string t = a.str("--params");
  for (char& ch : t)
    if (ch == ',') ch = ' ';
  std::istringstream in(t);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

// --law lsd|hertz|extended_linear|extended_hertz|continuous_potential --params "WORDS": the law's input line as
// pair_coeff ... normal NAME <words> takes it (normal lsd stiffness KN GAMMAN: GAMMAN per unit
// effective mass, as pair tdem/gran's default `damping mass`), read by its description
// (src/contact/law_input.h); --end as the hosts' limit_force.
void run_described(Run& run, Args& a, const tdem::law::Description& d, const Bodies& b, double meff, double v0,
                   const collision::Options& opt) {
  namespace law = tdem::law;
  const std::vector<std::string> w = param_words(a);
  std::vector<const char*> p;
  for (const auto& x : w) p.push_back(x.c_str());
  const law::Reading r = law::read(d, static_cast<int>(p.size()), p.data(), nullptr);
  if (!r.ok()) throw BadInput("option --params: " + r.error);
  if (r.next != static_cast<int>(p.size()))
    throw BadInput("option --params: '" + w[r.next] + "' follows the input of normal " + d.name);
  const ContactEnd end = read_end(a, ContactEnd::zero_overlap);
  run.end = to_string(end);
  auto& P = run.params;
  const double* g = d.group_count ? law::group_values(d, 0, r.v) : nullptr;
  const auto estar = [&] { return tdem::material::effective_modulus(r.v[0], r.v[1], r.v[2], r.v[3]); };
  const auto reff = [&] { return need_reff(b, ("for --law " + run.law + " (the Hertz stiffness)").c_str()); };
  try {
    if (&d == &tdem::lsd::description) {
      collision::LsdLaw law;
      law.end_mode = end;
      law.c = law::choice_of(d, 0, r.v) == tdem::lsd::form_stiffness
                  ? lsd::Coefficients<double>{g[0], meff * g[1]}
                  : lsd::from_restitution_and_time(g[0], g[1], meff, end);
      P = {{"k", law.c.k}, {"gamma", law.c.gamma}};
      predict(run, "e", [&] { return lsd::restitution(law.c, meff, end); });
      predict(run, "contact_time", [&] { return lsd::contact_time(law.c, meff, end); });
      a.check_all_used(run.law);
      go(run, law, b, v0, opt);
    } else if (&d == &tdem::hertz::description) {
      collision::HertzLaw law;
      law.end_mode = end;
      law.damping = static_cast<hertz::Damping>(law::choice_of(d, 0, r.v));
      law.p.k = hertz::stiffness(estar(), reff());
      law.p.damp = law.damping == hertz::Damping::tsuji     ? hertz::tsuji_alpha_from_restitution(g[0], end)
                   : law.damping == hertz::Damping::general ? g[1]
                                                            : g[0];
      law.p.theta = law.damping == hertz::Damping::general ? g[0] : 0.0;
      P = {{"Estar", estar()}, {"k", law.p.k}, {"damping", law.p.damp}};
      a.check_all_used(run.law);
      go(run, law, b, v0, opt);
    } else if (&d == &tdem::extended::linear_description) {
      collision::ExtendedLinearLaw law;
      law.end_mode = end;
      law.p = extended::linear_params(r.v);
      extended::validate(law.p);
      predict(run, "e", [&] { return extended::linear_restitution(law.p, v0); });
      predict(run, "contact_time", [&] { return extended::linear_contact_time(law.p, v0); });
      a.check_all_used(run.law);
      go(run, law, b, v0, opt);
    } else if (&d == &tdem::continuous_potential::description) {
      // d = X_cut = R1 + R2 (R1 with --wall), as the hosts take them per contact
      if (!(b.R1 > 0.0) || (!std::isinf(b.R2) && !(b.R2 > 0.0)))
        throw BadInput("option --params of --law continuous_potential needs --R1 (and --R2 or --wall): d = R1 + R2");
      collision::ContinuousPotentialLaw law;
      law.end_mode = end;
      law.p = tdem::continuous_potential::at_contact(r.v, std::isinf(b.R2) ? b.R1 : b.R1 + b.R2);
      continuous_potential::validate(law.p);
      P = {{"eps", law.p.eps}, {"n", law.p.n}, {"gamma", law.p.gamma}, {"d", law.p.d}};
      a.check_all_used(run.law);
      go(run, law, b, v0, opt);
    } else {  // extended_hertz
      collision::ExtendedHertzLaw law;
      law.end_mode = end;
      const extended::LinearParams f = extended::hertz_fits(r.v + law::MATERIAL_VALUES);
      law.p = extended::HertzParams{hertz::stiffness(estar(), reff()), f.e_fit, f.range};
      extended::validate(law.p);
      P = {{"Estar", estar()}, {"k", law.p.k}};
      predict(run, "e", [&] { return extended::hertz_restitution(law.p, v0); });
      a.check_all_used(run.law);
      go(run, law, b, v0, opt);
    }
  } catch (const BadInput&) {
    throw;
  } catch (const std::exception& e) {
    throw BadInput(std::string("option --params: normal ") + d.name + ": " + e.what());
  }
}

// --law NAME --params V1 V2 ...: a unit's input line as pair_coeff ... normal NAME <values> takes
// it, checked by its description; unit = its index in the list (-1: not a unit, an error).
void run_unit(Run& run, Args& a, int unit, const Bodies& b, double meff, double v0, const collision::Options& opt) {
  if (unit < 0) {
    if (const tdem::law::Description* d = tdem::law::find(tdem::law::all_normal_laws, run.law.c_str()))
      return run_described(run, a, *d, b, meff, v0, opt);
  }
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
