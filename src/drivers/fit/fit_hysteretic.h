// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the hysteretic laws: Walton-Braun, Thornton, power law (fit_laws.h).
#pragma once

#include "fit_law.h"

namespace tdem {
namespace fitting {

// ------------------------------------------------------------------ Walton-Braun
class WaltonBraunFit : public FitLaw {
 public:
  WaltonBraunFit(const Context& c, bool force_dependent) : FitLaw(c), fd_(force_dependent) {}
  std::string name() const override { return fd_ ? "walton_braun_force_dependent" : "walton_braun_constant"; }
  std::string description() const override {
    const std::string kl = c_.has_tc ? "k_l fitted" : "k_l matching Hertz at the median v0";
    return fd_ ? "Walton-Braun, k_ul = k_l + s F_max (" + kl + ", s fitted)"
               : "Walton-Braun, constant k_ul = k_l/e^2 (" + kl + ", e fitted)";
  }
  double kl_guess() const {
    if (c_.has_tc) return walton_braun::from_restitution_and_time(clamp_e(c_.e_med), c_.tc_med, c_.meff).k_load;
    return k_matching(c_);
  }
  double s_guess(double kl) const {
    return walton_braun::force_dependent_from_restitution(clamp_e(c_.e_med), c_.v_ref, kl, c_.meff).slope;
  }
  std::vector<Param> params() const override {
    std::vector<Param> p;
    const double kl = kl_guess();
    if (c_.has_tc) p.push_back({"k_l", "N/m", kl * 1e-4, kl * 1e4, true});
    if (fd_) {
      const double s = s_guess(kl);
      p.push_back({"s", "1/m", s * 1e-6, s * 1e6, true});
    } else {
      p.push_back({"e", "-", 1e-3, 1.0, false});
    }
    return p;
  }
  std::vector<std::vector<double>> starts() const override {
    const double kl = kl_guess();
    std::vector<double> g;
    if (c_.has_tc) g.push_back(kl);
    g.push_back(fd_ ? s_guess(kl) : clamp_e(c_.e_med));
    const size_t last = g.size() - 1;
    if (fd_) return around(g, {1.0, 0.1, 10.0}, last);
    return {g};
  }
  walton_braun::Params<double> par(const std::vector<double>& x) const {
    const double kl = c_.has_tc ? x[0] : k_matching(c_);
    const double y = x[c_.has_tc ? 1 : 0];
    return fd_ ? walton_braun::force_dependent(kl, y) : walton_braun::constant(kl, kl / (y * y));
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::WaltonBraunLaw law;
    law.p = par(x);
    return integrate_law(law, c_, v0);
  }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    const auto p = par(x);
    Prediction r;
    r.ok = true;
    r.e = walton_braun::restitution(p, c_.meff, v0);
    r.tc = walton_braun::contact_time(p, c_.meff, v0);
    r.fmax = p.k_load * walton_braun::max_overlap(p, c_.meff, v0);
    return r;
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const auto p = par(x);
    const std::string kl_note = c_.has_tc ? "" : "Hertz matching at v = " + num(c_.v_ref) + " m/s";
    std::vector<Coef> r = {{"k_l", "N/m", p.k_load, c_.has_tc, kl_note}};
    if (fd_) {
      r.push_back({"s", "1/m", p.slope, true, ""});
      r.push_back({"k_u", "N/m", p.k_unload, false, "= k_l"});
    } else {
      r.push_back({"k_ul", "N/m", p.k_unload, true, "e = sqrt(k_l/k_ul) = " + num(std::sqrt(p.k_load / p.k_unload))});
    }
    return r;
  }
  HostLines hosts(const std::vector<double>& x) const override {
    const auto p = par(x);
    return unit_hosts<walton_braun::Law>(c_, {p.k_load, p.k_unload, p.slope});
  }


 private:
  bool fd_;
};

// ------------------------------------------------------------------ Thornton
class ThorntonFit : public FitLaw {
 public:
  using FitLaw::FitLaw;
  std::string name() const override { return "thornton"; }
  std::string description() const override { return "Thornton elastic-perfectly-plastic (p_y fitted, E* from the data)"; }
  double guess() const {
    if (c_.e_med < 1.0)
      return thornton::yield_pressure_from_restitution(c_.e_med, c_.v_ref, c_.estar, c_.reff, c_.meff);
    return thornton::yield_pressure_from_yield_velocity(c_.v_hi, c_.estar, c_.reff, c_.meff);
  }
  std::vector<Param> params() const override {
    const double g = guess();
    return {{"p_y", "Pa", g * 1e-4, g * 1e4, true}};
  }
  std::vector<std::vector<double>> starts() const override { return around({guess()}, {1.0, 0.3, 3.0}); }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::ThorntonLaw law;
    law.p = {c_.estar, x[0]};
    return integrate_law(law, c_, v0);
  }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    Prediction r;
    r.ok = true;
    r.e = thornton::restitution({c_.estar, x[0]}, c_.reff, c_.meff, v0);
    return r;
  }
  // In the yield overlap xi_y, force F_y and velocity v_y the collision depends on v0/v_y only
  // (the plastic slope pi p_y R* is 3/2 F_y/xi_y); v0 = v_y is a kink (e = 1 below).
  bool similar(const std::vector<double>& x, double v0, Similar& s) const override {
    const thornton::Params<double> p{c_.estar, x[0]};
    const double vy = thornton::yield_velocity(p, c_.reff, c_.meff);
    s.q = v0 / vy;
    s.t_scale = thornton::yield_overlap(p, c_.reff) / vy;
    s.f_scale = thornton::yield_force(p, c_.reff);
    return true;
  }
  Prediction node(double q, double) const override {
    const thornton::Params<double> p{c_.estar, guess()};
    Similar s;
    similar({p.p_y}, 1.0, s);
    const double vy = 1.0 / s.q;
    collision::ThorntonLaw law;
    law.p = p;
    Prediction r = integrate_law(law, c_, q * vy);
    if (r.ok) {
      r.tc /= s.t_scale;
      r.fmax /= s.f_scale;
    }
    return r;
  }
  bool kink_at_one() const override { return true; }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const thornton::Params<double> p{c_.estar, x[0]};
    return {{"p_y", "Pa", x[0], true, ""},
            {"v_y", "m/s", thornton::yield_velocity(p, c_.reff, c_.meff), false, "yield velocity at m*, R*"},
            {"E*", "Pa", c_.estar, false, "from E, nu, E2, nu2"}};
  }
  HostLines hosts(const std::vector<double>& x) const override { return unit_hosts<thornton::Law>(c_, {x[0]}); }

};

// ------------------------------------------------------------------ power law
// p = 1.5, a_l = Hertz k~; internal (e_ref, q): the restitution at v_ref and q.
class PowerLawFit : public FitLaw {
 public:
  using FitLaw::FitLaw;
  std::string name() const override { return "power_law"; }
  std::string description() const override {
    return "power-law hysteresis, p = 1.5, a_l = Hertz k~ (a_ul, q fitted)";
  }
  std::vector<Param> params() const override { return {{"e_ref", "-", 1e-3, 1.0, false}, {"q", "-", 0.0, 3.0, false}}; }
  std::vector<std::vector<double>> starts() const override {
    const double e = clamp_e(c_.e_med);
    return {{e, 0.0}, {e, 0.3}, {e, 1.0}};
  }
  power_law::Params<double> par(const std::vector<double>& x) const {
    power_law::Params<double> p{c_.khertz, 1.5, 0.0, x[1]};
    const double xm = power_law::max_overlap({p.a_load, p.p, 1.0, 0.0}, c_.meff, c_.v_ref);
    const double n = p.p + p.q;
    const double d = x[0] * x[0] * xm * (n + 1.0) / (p.p + 1.0);
    p.a_unload = p.a_load * std::pow(xm, p.p) / std::pow(d, n);
    return p;
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::PowerLawLaw law;
    law.p = par(x);
    return integrate_law(law, c_, v0);
  }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    const auto p = par(x);
    Prediction r;
    r.ok = true;
    r.e = power_law::restitution(p, c_.meff, v0);
    r.tc = power_law::contact_time(p, c_.meff, v0);
    return r;
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const auto p = par(x);
    return {{"a_ul", "N/m^(p+q)", p.a_unload, true, "e(" + num(c_.v_ref) + " m/s) = " + num(x[0])},
            {"q", "-", p.q, true, ""},
            {"a_l", "N/m^1.5", p.a_load, false, "Hertz k~"},
            {"p", "-", p.p, false, ""}};
  }
  HostLines hosts(const std::vector<double>& x) const override {
    const auto p = par(x);
    return unit_hosts<power_law::Law>(c_, {p.a_load, p.p, p.a_unload, p.q});
  }

};

}  // namespace fitting
}  // namespace tdem
