// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the laws that can be fitted, each as (fitted parameters, single-collision solution,
// closed form where one exists, coefficients, input lines for LIGGGHTS and LAMMPS).
//
// The prediction of a law at an impact velocity is the single-collision solution of
// src/collision/head_on.h (RK4 with event location). Closed forms (where the kernels provide
// them) are only a speed-up for the minimisation; the driver checks them against the
// integration at the optimum and reports the largest difference.
//
// Fitted parameters are "internal" coordinates chosen so that the minimiser sees a well-scaled
// problem (e.g. the power law's a_ul through the restitution at the reference velocity); the
// law coefficients are derived from them in coefficients().
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "collision/head_on.h"
#include "impact_data.h"

namespace tdem {
namespace fitting {

// ------------------------------------------------------------------ context
struct Context {
  fitdata::Data data;
  collision::Bodies bodies;
  double meff = NAN, reff = NAN, estar = NAN, khertz = NAN;
  double v_ref = NAN;   // median impact velocity of the data
  double e_med = NAN;   // median restitution
  double tc_med = NAN;  // median contact time (NaN without t_c data)
  double v_lo = NAN, v_hi = NAN;  // range of the data
  bool has_tc = false, has_f = false;
  ContactEnd end = ContactEnd::zero_force;
  int steps = 2000;
  double kappa = NAN, mu = 0.5;  // tangential law (not fitted; for the input lines)
  fits::Range range;             // clamp of the extended laws (defaults)
};

inline std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

struct Param {
  std::string name, unit;
  double lo, hi;  // bounds of the internal value
  bool log;       // minimise over ln(value)
};

struct Coef {
  std::string name, unit;
  double value;
  bool fitted;  // false: fixed (from the material or a rule)
  std::string note;
};

struct Prediction {
  bool ok = false;
  double e = NAN, tc = NAN, fmax = NAN;
};

// ------------------------------------------------------------------ integration
template <class Law>
Prediction integrate_law(Law& law, const Context& c, double v0) {
  Prediction p;
  collision::Options o;
  o.steps_per_contact = c.steps;
  o.max_contact_times = 30.0;
  try {
    const auto r = collision::integrate(law, c.bodies, v0, o);
    if (!r.ended) return p;
    p.ok = true;
    p.e = r.restitution;
    p.tc = r.contact_time;
    p.fmax = r.max_force;
  } catch (const std::exception&) {
  }
  return p;
}

// ------------------------------------------------------------------ host input lines
struct HostLines {
  std::vector<std::string> liggghts, lammps;
};

// Which LIGGGHTS properties a law needs.
struct LiggghtsSpec {
  std::string model;     // e.g. "tdem/hertz"
  std::string settings;  // e.g. "damping tsuji limitForce on"
  bool material = false;  // youngsModulus / poissonsRatio (peratomtype)
  std::vector<std::pair<std::string, double>> pair_props;    // peratomtypepair
  std::vector<std::pair<std::string, double>> scalar_props;  // scalar
};

inline bool two_types(const Context& c) {
  return c.data.wall || c.data.E2 != c.data.E || c.data.nu2 != c.data.nu;
}

// E2 = inf (rigid partner) cannot be given to the hosts: 1e30 Pa gives the same E* in double precision.
inline double host_E2(const Context& c) { return std::isinf(c.data.E2) ? 1e30 : c.data.E2; }

inline void liggghts_lines(const Context& c, const LiggghtsSpec& s, HostLines& h) {
  auto& L = h.liggghts;
  const bool two = two_types(c);
  const int n = two ? 2 : 1;
  L.push_back(std::string("# LIGGGHTS, units si; ") +
              (c.data.wall ? "atom type 1 = the sphere, type 2 = the wall (fitted: the 1-2 entries)"
                           : two ? "atom types 1, 2 = the two spheres (fitted: the 1-2 entries)"
                                 : "atom type 1 = the spheres"));
  if (s.material) {
    if (c.data.E > 1e9 || (two && host_E2(c) > 1e9))
      L.push_back("hard_particles yes   # LIGGGHTS refuses youngsModulus > 1e9 Pa in units si without it");
    L.push_back("fix m_E all property/global youngsModulus peratomtype " + num(c.data.E) +
                (two ? " " + num(host_E2(c)) : "") + (std::isinf(c.data.E2) ? "   # wall: rigid (E2 = inf)" : ""));
    L.push_back("fix m_nu all property/global poissonsRatio peratomtype " + num(c.data.nu) +
                (two ? " " + num(c.data.nu2) : ""));
  }
  auto pairprop = [&](const std::string& id, const std::string& name, double v) {
    std::string line = "fix " + id + " all property/global " + name + " peratomtypepair " + std::to_string(n);
    for (int i = 0; i < n * n; ++i) line += " " + num(v);
    L.push_back(line);
  };
  int k = 0;
  for (const auto& p : s.pair_props) pairprop("m_p" + std::to_string(++k), p.first, p.second);
  pairprop("m_ka", "tangentialStiffnessRatio", c.kappa);
  pairprop("m_mu", "coefficientFriction", c.mu);
  for (const auto& p : s.scalar_props)
    L.push_back("fix m_s" + std::to_string(++k) + " all property/global " + p.first + " scalar " + num(p.second));
  const std::string model = "model " + s.model + " tangential tdem/cundall_strack";
  const std::string set = s.settings.empty() ? "" : " " + s.settings;
  L.push_back("pair_style gran " + model + set);
  L.push_back("pair_coeff * *");
  if (c.data.wall)
    L.push_back("fix wall all wall/gran " + model + " primitive type 2 zplane 0.0" + set);
}

// normal_fit: the law words of the fitted contact; normal_11: of the sphere-sphere contact of
// material 1 (wall data: not fitted, given so that the script runs).
inline void lammps_lines(const Context& c, const std::string& normal_fit, const std::string& normal_11,
                         bool uses_limit_force, HostLines& h) {
  auto& L = h.lammps;
  const std::string tang = " tangential cundall_strack " + num(c.kappa) + " " + num(c.mu) +
                           (uses_limit_force && c.end == ContactEnd::zero_force ? " limit_force yes" : "");
  L.push_back(std::string("# LAMMPS, units si; ") +
              (c.data.wall ? "the fitted contact is sphere (type 1) - wall"
                           : two_types(c) ? "types 1, 2 = the two spheres (fitted: 1 2)" : "type 1 = the spheres"));
  L.push_back("pair_style tdem/gran");
  if (c.data.wall) {
    L.push_back("pair_coeff * * " + normal_11 + tang + "   # sphere-sphere: not fitted");
    L.push_back("fix wall all tdem/wall/gran " + normal_fit + tang + " zplane 0 NULL");
  } else if (two_types(c)) {
    L.push_back("pair_coeff 1 2 " + normal_fit + tang + "   # give 1 1 and 2 2 as well");
  } else {
    L.push_back("pair_coeff * * " + normal_fit + tang);
  }
}

// "E NU" or "E1 NU1 E2 NU2" for the hertz-type LAMMPS laws.
inline std::string lammps_materials(const Context& c) {
  if (c.data.E2 == c.data.E && c.data.nu2 == c.data.nu) return num(c.data.E) + " " + num(c.data.nu);
  return num(c.data.E) + " " + num(c.data.nu) + " " + num(host_E2(c)) + " " + num(c.data.nu2);
}

inline std::string limit_force_setting(const Context& c) {
  return std::string("limitForce ") + (c.end == ContactEnd::zero_force ? "on" : "off");
}

// Similarity form (tabulate.h): the prediction at v0 is {E(q, key), t_scale T(q, key),
// f_scale F(q, key)} of a family of dimensionless solutions.
struct Similar {
  double q = NAN, key = 0.0, t_scale = 1.0, f_scale = 1.0;
};

// ------------------------------------------------------------------ the law interface
class FitLaw {
 public:
  explicit FitLaw(const Context& c) : c_(c) {}
  virtual ~FitLaw() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual std::vector<Param> params() const = 0;
  virtual std::vector<std::vector<double>> starts() const = 0;  // internal values
  virtual Prediction simulate(const std::vector<double>& x, double v0) const = 0;
  // Closed form; NaN for a quantity without one.
  virtual Prediction closed(const std::vector<double>& x, double v0) const { return Prediction(); }
  virtual std::vector<Coef> coefficients(const std::vector<double>& x) const = 0;
  virtual HostLines hosts(const std::vector<double>& x) const = 0;
  // The similarity variable of the collision at v0 with parameters x (false: none, or none at this
  // v0); node() integrates the member (q, key) and returns e, t_c / t_scale, F_max / f_scale.
  virtual bool similar(const std::vector<double>& x, double v0, Similar& s) const { return false; }
  virtual Prediction node(double q, double key) const { return Prediction(); }
  virtual bool key_continuous() const { return false; }  // interpolate across the key (grid kTableStep)
  virtual bool kink_at_one() const { return false; }     // q = 1 is a kink of the solution

 protected:
  const Context& c_;
};

// Hertz spring k~ xi^(3/2) + damping c xi^Theta xi': in xi* = (m* v0^2/k~)^(2/5), t* = xi*/v0,
// F* = m* v0^2/xi* the collision is s'' = -s^(3/2) - D s^Theta s', s(0) = 0, s'(0) = 1, with
// D = c xi*^(Theta+1)/(m* v0) (Tsuji's alpha sqrt(m* k~) xi^(1/4): D = alpha).
inline void hertz_similar(const Context& c, double c_gen, double theta, double v0, Similar& s) {
  const double xs = std::pow(c.meff * v0 * v0 / c.khertz, 0.4);
  s.q = c_gen * std::pow(xs, theta + 1.0) / (c.meff * v0);
  s.key = theta;
  s.t_scale = xs / v0;
  s.f_scale = c.meff * v0 * v0 / xs;
}
inline Prediction hertz_node(const Context& c, double q, double theta) {
  const double v = c.v_ref;
  Similar s;
  hertz_similar(c, 1.0, theta, v, s);  // s.q = the D of c_gen = 1
  collision::HertzLaw law;
  law.damping = hertz::Damping::general;
  law.end_mode = c.end;
  law.p = hertz::Params<double>{c.khertz, q / s.q, theta};
  Prediction p = integrate_law(law, c, v);
  if (p.ok) {
    p.tc /= s.t_scale;
    p.fmax /= s.f_scale;
  }
  return p;
}

// Starting values: scaled copies of a guess.
inline std::vector<std::vector<double>> around(const std::vector<double>& g, const std::vector<double>& factors,
                                               size_t which = 0) {
  std::vector<std::vector<double>> s;
  for (double f : factors) {
    auto x = g;
    x[which] *= f;
    s.push_back(x);
  }
  return s;
}

inline double clamp_e(double e) { return std::min(std::max(e, 0.02), 0.995); }

// Linear stiffness matching Hertz at the median impact velocity (LIGGGHTS `model hooke`).
inline double k_matching(const Context& c) {
  return lsd::stiffness_matching_hertz(c.estar, c.reff, c.meff, c.v_ref);
}

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
    HostLines h;
    const auto p = par(x);
    LiggghtsSpec s;
    s.model = "tdem/walton_braun";
    s.pair_props = {{"loadingStiffness", p.k_load}, {"unloadingStiffness", p.k_unload},
                    {"unloadingStiffnessSlope", p.slope}};
    liggghts_lines(c_, s, h);
    const std::string n = "normal walton_braun " + num(p.k_load) + " " + num(p.k_unload) + " " + num(p.slope);
    lammps_lines(c_, n, n, false, h);
    return h;
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
  HostLines hosts(const std::vector<double>& x) const override {
    HostLines h;
    LiggghtsSpec s;
    s.model = "tdem/thornton";
    s.material = true;
    s.pair_props = {{"yieldPressure", x[0]}};
    liggghts_lines(c_, s, h);
    lammps_lines(c_, "normal thornton " + lammps_materials(c_) + " " + num(x[0]),
                 "normal thornton " + num(c_.data.E) + " " + num(c_.data.nu) + " " + num(x[0]), false, h);
    return h;
  }
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
    HostLines h;
    const auto p = par(x);
    LiggghtsSpec s;
    s.model = "tdem/power_law";
    s.pair_props = {{"loadingCoefficient", p.a_load}, {"loadingExponent", p.p},
                    {"unloadingCoefficient", p.a_unload}, {"unloadingExponentIncrement", p.q}};
    liggghts_lines(c_, s, h);
    const std::string n = "normal power_law " + num(p.a_load) + " " + num(p.p) + " " + num(p.a_unload) + " " + num(p.q);
    lammps_lines(c_, n, n, false, h);
    return h;
  }
};

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

inline const std::vector<std::string>& law_names() {
  static const std::vector<std::string> n = {"lsd",
                                             "hertz_linear",
                                             "hertz_kuwabara_kono",
                                             "hertz_tsuji",
                                             "hertz_general",
                                             "walton_braun_constant",
                                             "walton_braun_force_dependent",
                                             "thornton",
                                             "power_law",
                                             "extended_linear",
                                             "extended_hertz"};
  return n;
}

inline std::unique_ptr<FitLaw> make_law(const std::string& name, const Context& c) {
  if (name == "lsd") return std::make_unique<LsdFit>(c);
  if (name == "hertz_linear") return std::make_unique<HertzFit>(c, hertz::Damping::linear);
  if (name == "hertz_kuwabara_kono") return std::make_unique<HertzFit>(c, hertz::Damping::kuwabara_kono);
  if (name == "hertz_tsuji") return std::make_unique<HertzFit>(c, hertz::Damping::tsuji);
  if (name == "hertz_general") return std::make_unique<HertzFit>(c, hertz::Damping::general);
  if (name == "walton_braun_constant") return std::make_unique<WaltonBraunFit>(c, false);
  if (name == "walton_braun_force_dependent") return std::make_unique<WaltonBraunFit>(c, true);
  if (name == "thornton") return std::make_unique<ThorntonFit>(c);
  if (name == "power_law") return std::make_unique<PowerLawFit>(c);
  if (name == "extended_linear") return std::make_unique<ExtendedLinearFit>(c);
  if (name == "extended_hertz") return std::make_unique<ExtendedHertzFit>(c);
  return nullptr;
}

}  // namespace fitting
}  // namespace tdem
