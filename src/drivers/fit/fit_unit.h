// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: any normal law that is a unit (src/contact/law_unit.h) and declares fit_guess: its own
// values (after the materials, which come from the data) are the fitted parameters, over their
// logarithm within 1e-4 ... 1e4 of the unit's guess; the prediction is the single collision of its
// kernel (collision::UnitLaw); the input lines are the unit's (unit_hosts). A unit with a fit of
// its own (walton_braun, thornton, power_law: fit_hysteretic.h) keeps that one (fit_laws.h).
#pragma once

#include <string>
#include <vector>

#include "contact/laws.h"
#include "fit_law.h"

namespace tdem {
namespace fitting {

template <class U>
class UnitFit : public FitLaw {
 public:
  using FitLaw::FitLaw;
  static constexpr const law::Description& d = U::description;
  std::string name() const override { return d.name; }
  std::string description() const override {
    return std::string(d.name) + " (" + law::syntax(d) + " fitted" + (d.materials ? ", E* from the data)" : ")");
  }
  std::vector<double> guess() const {
    std::vector<double> g(d.count);
    U::fit_guess(law::FitHint{c_.estar, c_.meff, c_.reff, c_.v_ref, c_.e_med, c_.has_tc ? c_.tc_med : NAN},
                 g.data());
    return g;
  }
  std::vector<Param> params() const override {
    std::vector<Param> p;
    const std::vector<double> g = guess();
    for (int k = 0; k < d.count; ++k) p.push_back({d.params[k].name, d.params[k].unit, g[k] * 1e-4, g[k] * 1e4, true});
    return p;
  }
  // the guess, and each value halved and doubled
  std::vector<std::vector<double>> starts() const override {
    const std::vector<double> g = guess();
    std::vector<std::vector<double>> s = {g};
    for (int k = 0; k < d.count; ++k)
      for (double f : {0.5, 2.0}) {
        s.push_back(g);
        s.back()[k] *= f;
      }
    return s;
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::UnitLaw<U> law;
    law.p = U::params(values(x).data());  // throws outside the ranges: no prediction
    return integrate_law(law, c_, v0);
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    std::vector<Coef> out;
    for (int k = 0; k < d.count; ++k) out.push_back({d.params[k].name, d.params[k].unit, x[k], true, d.params[k].meaning});
    if (d.materials) out.push_back({"E*", "Pa", c_.estar, false, "from E, nu, E2, nu2"});
    return out;
  }
  HostLines hosts(const std::vector<double>& x) const override { return unit_hosts<U>(c_, x); }

 private:
  // the values of U::params (law::unit_values): E* first for a law with materials
  std::vector<double> values(const std::vector<double>& x) const {
    std::vector<double> v;
    if (d.materials) v.push_back(c_.estar);
    v.insert(v.end(), x.begin(), x.end());
    return v;
  }
};

// The units that tdem-fit fits as units: those with fit_guess.
template <class U>
inline constexpr bool fitted_as_unit = law::HasFitGuess<U>::value;

}  // namespace fitting
}  // namespace tdem
