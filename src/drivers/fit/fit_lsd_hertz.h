// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the linear (lsd) and Hertz (with its damping members) laws (fit_laws.h).
#pragma once

#include "fit_law.h"

namespace tdem {
namespace fitting {

// ------------------------------------------------------------------ lsd
class LsdFit : public FitLaw {
 public:
  using FitLaw::FitLaw;
  std::string name() const override { return "lsd"; }
  std::string description() const override {
    return c_.has_tc ? "linear spring-dashpot, constant e and t_c (fitted)"
                     : "linear spring-dashpot, k matching Hertz at the median v0 (LIGGGHTS rule), e fitted";
  }
  std::vector<Param> params() const override {
    std::vector<Param> p = {{"e", "-", 1e-3, 1.0, false}};
    if (c_.has_tc) p.push_back({"t_c", "s", c_.tc_med * 1e-3, c_.tc_med * 1e3, true});
    return p;
  }
  std::vector<std::vector<double>> starts() const override {
    std::vector<double> g = {clamp_e(c_.e_med)};
    if (c_.has_tc) g.push_back(c_.tc_med);
    return {g};
  }
  // the coefficients of the last x (the zero-force conversion is a root search; closed() asks
  // for the same x at every data row)
  lsd::Coefficients<double> coef(const std::vector<double>& x) const {
    if (x == last_x_) return last_;
    last_ = c_.has_tc ? lsd::from_restitution_and_time(x[0], x[1], c_.meff, c_.end)
                      : lsd::from_restitution_and_stiffness(x[0], k_matching(c_), c_.meff, c_.end);
    last_x_ = x;
    return last_;
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::LsdLaw law;
    law.end_mode = c_.end;
    law.c = coef(x);
    return integrate_law(law, c_, v0);
  }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    const auto k = coef(x);
    Prediction p;
    p.ok = true;
    p.e = lsd::restitution(k, c_.meff, c_.end);
    p.tc = lsd::contact_time(k, c_.meff, c_.end);
    return p;
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const auto k = coef(x);
    std::vector<Coef> r = {{"e", "-", x[0], true, ""}};
    if (c_.has_tc) {
      r.push_back({"t_c", "s", x[1], true, ""});
      r.push_back({"k", "N/m", k.k, false, "from e, t_c at m*"});
    } else {
      r.push_back({"t_c", "s", lsd::contact_time(k, c_.meff, c_.end), false, "from k, e at m*"});
      r.push_back({"k", "N/m", k.k, false, "Hertz matching at v = " + num(c_.v_ref) + " m/s"});
    }
    r.push_back({"gamma", "kg/s", k.gamma, false, "from e at m*"});
    return r;
  }
  HostLines hosts(const std::vector<double>& x) const override {
    HostLines h;
    const auto k = coef(x);
    LiggghtsSpec s;
    s.model = "tdem/lsd";
    if (c_.has_tc) {
      s.settings = "parameters restitution " + limit_force_setting(c_);
      s.pair_props = {{"coefficientRestitution", x[0]}, {"contactTime", x[1]}};
    } else if (c_.v_ref < 1e-2) {
      // LIGGGHTS refuses characteristicVelocity < 1e-2 m/s in units si: give t_c of this m* instead
      s.settings = "parameters restitution " + limit_force_setting(c_);
      s.pair_props = {{"coefficientRestitution", x[0]}, {"contactTime", lsd::contact_time(k, c_.meff, c_.end)}};
    } else {
      s.settings = "parameters material " + limit_force_setting(c_);
      s.material = true;
      s.pair_props = {{"coefficientRestitution", x[0]}};
      s.scalar_props = {{"characteristicVelocity", c_.v_ref}};
    }
    liggghts_lines(c_, s, h);
    if (!c_.has_tc && c_.v_ref < 1e-2)
      h.liggghts.push_back("# (contactTime: t_c of the Hertz-matching k at m* = " + num(c_.meff) +
                           " kg; LIGGGHTS needs characteristicVelocity >= 1e-2 m/s for parameters material)");
    const std::string n = "normal lsd restitution " + num(x[0]) + " " + num(lsd::contact_time(k, c_.meff, c_.end));
    lammps_lines(c_, n, n, true, h);
    if (!c_.has_tc)
      h.lammps.push_back("# (t_c from the Hertz-matching k at m* = " + num(c_.meff) + " kg; other masses: other k)");
    return h;
  }
 private:
  mutable std::vector<double> last_x_;
  mutable lsd::Coefficients<double> last_{};
};

// ------------------------------------------------------------------ Hertz + damping
class HertzFit : public FitLaw {
 public:
  HertzFit(const Context& c, hertz::Damping d) : FitLaw(c), d_(d) {}
  std::string name() const override { return std::string("hertz_") + hertz::to_string(d_); }
  std::string description() const override {
    switch (d_) {
      case hertz::Damping::linear: return "Hertz spring + linear damping gamma xi' (Theta = 0)";
      case hertz::Damping::kuwabara_kono: return "Hertz spring + Kuwabara-Kono damping gamma~ xi^1/2 xi' (Theta = 1/2)";
      case hertz::Damping::tsuji: return "Hertz spring + Tsuji damping alpha sqrt(m* k~) xi^1/4 xi' (constant e)";
      default: return "Hertz spring + general damping c xi^Theta xi' (c, Theta fitted)";
    }
  }
  // general: internal c_ref = c xi_ref^Theta, the damping [kg/s] at the elastic xi_max of v_ref.
  double xi_ref() const { return hertz::max_overlap_elastic(c_.khertz, c_.meff, c_.v_ref); }
  std::vector<Param> params() const override {
    const double g = guess();
    switch (d_) {
      case hertz::Damping::linear: return {{"gamma", "kg/s", g * 1e-5, g * 1e5, true}};
      case hertz::Damping::kuwabara_kono: return {{"gamma~", "kg/(s m^0.5)", g * 1e-5, g * 1e5, true}};
      case hertz::Damping::tsuji: return {{"alpha", "-", 1e-8, 50.0, true}};
      default: return {{"c_ref", "kg/s", g * 1e-5, g * 1e5, true}, {"Theta", "-", 0.0, 2.0, false}};
    }
  }
  // The damping that gives the median restitution at the median v0, in each form.
  double guess() const {
    const double beta = lsd::damping_ratio_from_restitution(clamp_e(c_.e_med), c_.end);
    const double klin = k_matching(c_);
    const double glin = 2.0 * beta * std::sqrt(klin * c_.meff);
    switch (d_) {
      case hertz::Damping::linear: return glin;
      case hertz::Damping::kuwabara_kono: return glin / std::sqrt(0.5 * xi_ref());
      case hertz::Damping::tsuji: return std::sqrt(5.0) * beta;
      default: return std::sqrt(5.0) * beta * std::sqrt(c_.meff * c_.khertz) * std::pow(xi_ref(), 0.25);
    }
  }
  std::vector<std::vector<double>> starts() const override {
    const double g = guess();
    if (d_ == hertz::Damping::general) return {{g, 0.25}, {g, 0.0}, {g, 0.5}, {g, 1.0}};
    return {{g}, {g * 0.2}, {g * 5.0}};
  }
  hertz::Params<double> par(const std::vector<double>& x) const {
    hertz::Params<double> p{c_.khertz, x[0], 0.0};
    if (d_ == hertz::Damping::general) {
      p.theta = x[1];
      p.damp = x[0] / std::pow(xi_ref(), x[1]);
    }
    return p;
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::HertzLaw law;
    law.damping = d_;
    law.end_mode = c_.end;
    law.p = par(x);
    return integrate_law(law, c_, v0);
  }
  bool similar(const std::vector<double>& x, double v0, Similar& s) const override {
    const auto p = par(x);
    switch (d_) {
      case hertz::Damping::linear: hertz_similar(c_, p.damp, 0.0, v0, s); break;
      case hertz::Damping::kuwabara_kono: hertz_similar(c_, p.damp, 0.5, v0, s); break;
      case hertz::Damping::tsuji: hertz_similar(c_, p.damp * std::sqrt(c_.meff * p.k), 0.25, v0, s); break;
      default: hertz_similar(c_, p.damp, p.theta, v0, s); break;
    }
    return true;
  }
  Prediction node(double q, double key) const override { return hertz_node(c_, q, key); }
  bool key_continuous() const override { return d_ == hertz::Damping::general; }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    Prediction p;
    if (d_ == hertz::Damping::tsuji) {
      p.ok = true;
      p.e = hertz::tsuji_restitution(x[0], c_.end);
    }
    return p;
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const auto p = par(x);
    std::vector<Coef> r;
    switch (d_) {
      case hertz::Damping::linear: r.push_back({"gamma", "kg/s", p.damp, true, ""}); break;
      case hertz::Damping::kuwabara_kono:
        r.push_back({"gamma~", "kg/(s m^0.5)", p.damp, true, ""});
        r.push_back({"A", "s", hertz::dissipative_time(p.damp, p.k), false, "dissipative time, gamma~ = 3/2 A k~"});
        break;
      case hertz::Damping::tsuji:
        r.push_back({"alpha", "-", p.damp, true, ""});
        r.push_back({"e", "-", hertz::tsuji_restitution(p.damp, c_.end), false, "restitution of this alpha"});
        break;
      default:
        r.push_back({"c", "kg/(s m^Theta)", p.damp, true, ""});
        r.push_back({"Theta", "-", p.theta, true, ""});
        break;
    }
    r.push_back({"k~", "N/m^1.5", p.k, false, "4/3 E* sqrt(R*)"});
    return r;
  }
  HostLines hosts(const std::vector<double>& x) const override {
    HostLines h;
    const auto p = par(x);
    LiggghtsSpec s;
    s.model = "tdem/hertz";
    s.material = true;
    s.settings = std::string("damping ") + hertz::to_string(d_) + " " + limit_force_setting(c_);
    std::string dl;  // LAMMPS damping words
    switch (d_) {
      case hertz::Damping::linear:
        s.pair_props = {{"dampingCoefficient", p.damp}};
        dl = "damping linear " + num(p.damp);
        break;
      case hertz::Damping::kuwabara_kono:
        s.pair_props = {{"dampingCoefficient", p.damp}};
        dl = "damping kuwabara_kono " + num(p.damp);
        break;
      case hertz::Damping::tsuji: {
        const double e = hertz::tsuji_restitution(p.damp, c_.end);
        s.pair_props = {{"coefficientRestitution", e}};
        dl = "damping tsuji " + num(e);
        break;
      }
      default:
        s.pair_props = {{"dampingCoefficient", p.damp}, {"dampingExponent", p.theta}};
        dl = "damping general " + num(p.theta) + " " + num(p.damp);
        break;
    }
    liggghts_lines(c_, s, h);
    lammps_lines(c_, "normal hertz " + lammps_materials(c_) + " " + dl,
                 "normal hertz " + num(c_.data.E) + " " + num(c_.data.nu) + " " + dl, true, h);
    return h;
  }

 private:
  hertz::Damping d_;
};

}  // namespace fitting
}  // namespace tdem
