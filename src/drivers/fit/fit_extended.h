// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the extended laws with velocity-dependent e and t_c (fit_laws.h).
#pragma once

#include "fit_law.h"

namespace tdem {
namespace fitting {

// ------------------------------------------------------------------ extended laws
// Rational e(v0) = chi1/(v00 + v0^chi2), internally 1/e = a + B (v0/v_ref)^chi2.
struct RationalE {
  static std::vector<Param> params() {
    return {{"a", "-", 0.0, 1e3, false}, {"B", "-", 1e-6, 1e6, true}, {"chi2", "-", 0.0, 10.0, false}};
  }
  static fits::Fit fit(const std::vector<double>& x, double v_ref) {
    fits::Fit f;
    f.form = fits::Form::rational;
    const double chi1 = std::pow(v_ref, x[2]) / x[1];
    f.c[0] = chi1;
    f.c[1] = x[0] * chi1;
    f.c[2] = x[2];
    return f;
  }
  // Linear least squares of 1/e = a + B u, u = (v/v_ref)^chi2, on a grid of chi2.
  static std::vector<std::vector<double>> starts(const Context& c) {
    std::vector<std::pair<double, std::vector<double>>> cand;
    for (int i = 0; i <= 30; ++i) {
      const double chi2 = 0.1 * i;
      double s1 = 0, su = 0, suu = 0, sy = 0, suy = 0;
      for (const auto& p : c.data.points) {
        if (!std::isfinite(p.e)) continue;
        const double u = std::pow(p.v0 / c.v_ref, chi2), y = 1.0 / p.e;
        s1 += 1;
        su += u;
        suu += u * u;
        sy += y;
        suy += u * y;
      }
      const double det = s1 * suu - su * su;
      double a, B;
      if (std::fabs(det) < 1e-12 * s1 * suu) {
        a = 0.0;
        B = sy / su;
      } else {
        a = (suu * sy - su * suy) / det;
        B = (s1 * suy - su * sy) / det;
      }
      if (!(B > 1e-6)) B = 1e-6;
      if (a < 0) a = 0;
      double chi = 0;
      for (const auto& p : c.data.points)
        if (std::isfinite(p.e)) {
          const double r = (p.e - std::min(1.0, 1.0 / (a + B * std::pow(p.v0 / c.v_ref, chi2)))) / p.e;
          chi += r * r;
        }
      cand.push_back({chi, {a, B, chi2}});
    }
    std::sort(cand.begin(), cand.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    return {cand[0].second, cand[1].second, cand[2].second};
  }
};

class ExtendedLinearFit : public FitLaw {
 public:
  using FitLaw::FitLaw;
  std::string name() const override { return "extended_linear"; }
  std::string description() const override {
    return c_.has_tc ? "extended linear: rational e(v0) and power t_c(v0) fitted"
                     : "extended linear: rational e(v0) fitted, t_c(v0) of Hertz (chi4 = 0.2)";
  }
  std::vector<Param> params() const override {
    auto p = RationalE::params();
    if (c_.has_tc) {
      p.push_back({"t_c,ref", "s", c_.tc_med * 1e-3, c_.tc_med * 1e3, true});
      p.push_back({"chi4", "-", -3.0, 3.0, false});
    }
    return p;
  }
  std::vector<std::vector<double>> starts() const override {
    auto s = RationalE::starts(c_);
    if (c_.has_tc) {
      // log-linear least squares: ln t_c = ln t_ref - chi4 ln(v/v_ref)
      double n = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
      for (const auto& p : c_.data.points)
        if (std::isfinite(p.tc)) {
          const double x = std::log(p.v0 / c_.v_ref), y = std::log(p.tc);
          n += 1; sx += x; sxx += x * x; sy += y; sxy += x * y;
        }
      const double det = n * sxx - sx * sx;
      double chi4 = 0.2, lt = sy / n;
      if (det > 1e-12 * n * std::max(sxx, 1e-300)) {
        chi4 = -(n * sxy - sx * sy) / det;
        lt = (sy - (-chi4) * sx) / n;
      }
      chi4 = std::min(std::max(chi4, -3.0), 3.0);
      for (auto& x : s) {
        x.push_back(std::exp(lt));
        x.push_back(chi4);
      }
    }
    return s;
  }
  extended::LinearParams par(const std::vector<double>& x) const {
    extended::LinearParams p;
    p.e_fit = RationalE::fit(x, c_.v_ref);
    p.tc_fit.form = fits::Form::power;
    if (c_.has_tc) {
      p.tc_fit.c[0] = x[3] * std::pow(c_.v_ref, x[4]);
      p.tc_fit.c[1] = x[4];
    } else {
      p.tc_fit.c[0] = hertz::contact_time_elastic(c_.khertz, c_.meff, 1.0);
      p.tc_fit.c[1] = 0.2;
    }
    p.range = c_.range;
    return p;
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::ExtendedLinearLaw law;
    law.end_mode = c_.end;
    law.p = par(x);
    return integrate_law(law, c_, v0);
  }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    const auto p = par(x);
    Prediction r;
    r.ok = true;
    r.e = extended::linear_restitution(p, v0);
    r.tc = extended::linear_contact_time(p, v0);
    return r;
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const auto p = par(x);
    return {{"chi1", "(m/s)^chi2", p.e_fit.c[0], true, "e = chi1/(v00 + v0^chi2)"},
            {"v00", "(m/s)^chi2", p.e_fit.c[1], true, ""},
            {"chi2", "-", p.e_fit.c[2], true, ""},
            {"chi3", "s (m/s)^chi4", p.tc_fit.c[0], c_.has_tc, c_.has_tc ? "t_c = chi3 v0^-chi4" : "Hertz t_c at m*"},
            {"chi4", "-", p.tc_fit.c[1], c_.has_tc, c_.has_tc ? "" : "Hertz"}};
  }
  HostLines hosts(const std::vector<double>& x) const override {
    HostLines h;
    const auto p = par(x);
    LiggghtsSpec s;
    s.model = "tdem/extended_linear";
    s.settings = "restitutionFit rational contactTimeFit power " + limit_force_setting(c_);
    s.pair_props = {{"restitutionFitC0", p.e_fit.c[0]}, {"restitutionFitC1", p.e_fit.c[1]},
                    {"restitutionFitC2", p.e_fit.c[2]}, {"contactTimeFitC0", p.tc_fit.c[0]},
                    {"contactTimeFitC1", p.tc_fit.c[1]}};
    s.scalar_props = {{"impactVelocityMin", p.range.v_min}, {"impactVelocityMax", p.range.v_max}};
    liggghts_lines(c_, s, h);
    const std::string n = "normal extended_linear e_fit rational " + num(p.e_fit.c[0]) + " " + num(p.e_fit.c[1]) +
                          " " + num(p.e_fit.c[2]) + " tc_fit power " + num(p.tc_fit.c[0]) + " " +
                          num(p.tc_fit.c[1]) + " v_min " + num(p.range.v_min) + " v_max " + num(p.range.v_max);
    lammps_lines(c_, n, n, true, h);
    return h;
  }
};

class ExtendedHertzFit : public FitLaw {
 public:
  using FitLaw::FitLaw;
  std::string name() const override { return "extended_hertz"; }
  std::string description() const override {
    return "extended Hertz: Hertz spring, Tsuji damping alpha(v0) from a rational e(v0) (fitted)";
  }
  std::vector<Param> params() const override { return RationalE::params(); }
  std::vector<std::vector<double>> starts() const override { return RationalE::starts(c_); }
  extended::HertzParams par(const std::vector<double>& x) const {
    extended::HertzParams p;
    p.k = c_.khertz;
    p.e_fit = RationalE::fit(x, c_.v_ref);
    p.range = c_.range;
    return p;
  }
  Prediction simulate(const std::vector<double>& x, double v0) const override {
    collision::ExtendedHertzLaw law;
    law.end_mode = c_.end;
    law.p = par(x);
    return integrate_law(law, c_, v0);
  }
  Prediction closed(const std::vector<double>& x, double v0) const override {
    Prediction r;
    r.ok = true;
    r.e = extended::hertz_restitution(par(x), v0);
    return r;
  }
  // Hertz + Tsuji with alpha(e_fit(v0)) taken at the touch: D = alpha (hertz_similar). The table
  // is over q = -ln e_fit(v0), proportional to alpha for e -> 1 (alpha(e) is a root search, made
  // once per node instead of per row; t_c varies like alpha^(4/5) there, smooth in ln q, not in e).
  bool similar(const std::vector<double>& x, double v0, Similar& s) const override {
    const auto p = par(x);
    double e = NAN;
    try {
      e = extended::hertz_restitution(p, p.range.clamp(v0));
    } catch (const std::exception&) {
      return false;
    }
    if (!(e > 0.0 && e < 1.0)) return false;
    hertz_similar(c_, 1.0, 0.25, v0, s);
    s.q = -std::log(e);
    return true;
  }
  Prediction node(double q, double key) const override {
    double alpha = NAN;
    try {
      alpha = hertz::tsuji_alpha_from_restitution(std::exp(-q), c_.end);
    } catch (const std::exception&) {
      return Prediction();
    }
    return hertz_node(c_, alpha, key);
  }
  std::vector<Coef> coefficients(const std::vector<double>& x) const override {
    const auto p = par(x);
    return {{"chi1", "(m/s)^chi2", p.e_fit.c[0], true, "e = chi1/(v00 + v0^chi2)"},
            {"v00", "(m/s)^chi2", p.e_fit.c[1], true, ""},
            {"chi2", "-", p.e_fit.c[2], true, ""},
            {"k~", "N/m^1.5", p.k, false, "4/3 E* sqrt(R*)"}};
  }
  HostLines hosts(const std::vector<double>& x) const override {
    HostLines h;
    const auto p = par(x);
    LiggghtsSpec s;
    s.model = "tdem/extended_hertz";
    s.material = true;
    s.settings = "restitutionFit rational " + limit_force_setting(c_);
    s.pair_props = {{"restitutionFitC0", p.e_fit.c[0]}, {"restitutionFitC1", p.e_fit.c[1]},
                    {"restitutionFitC2", p.e_fit.c[2]}};
    s.scalar_props = {{"impactVelocityMin", p.range.v_min}, {"impactVelocityMax", p.range.v_max}};
    liggghts_lines(c_, s, h);
    const std::string fit = " e_fit rational " + num(p.e_fit.c[0]) + " " + num(p.e_fit.c[1]) + " " +
                            num(p.e_fit.c[2]) + " v_min " + num(p.range.v_min) + " v_max " + num(p.range.v_max);
    lammps_lines(c_, "normal extended_hertz " + lammps_materials(c_) + fit,
                 "normal extended_hertz " + num(c_.data.E) + " " + num(c_.data.nu) + fit, true, h);
    return h;
  }
};

}  // namespace fitting
}  // namespace tdem
