// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: what every fitted law shares: the context (data, bodies, options), the law interface
// (FitLaw), the integration of a prediction, and the LIGGGHTS/LAMMPS input lines (fit_laws.h).
#pragma once

#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision/head_on.h"
#include "contact/laws.h"
#include "contact/input_checks.h"
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

inline std::string num(double v) { return checks::number(v); }

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

// The law words "normal NAME ..." of a printed LAMMPS line, read back by the description of the
// law (src/contact/law_input.h, the reader of pair tdem/gran): a line the host would refuse is a
// defect of this program, not of the data.
inline void check_lammps_law(const std::string& words) {
  std::istringstream in(words);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  const law::Description* d = w.size() >= 2 && w[0] == "normal" ? law::find(law::all_normal_laws, w[1].c_str()) : nullptr;
  std::vector<const char*> p;
  for (std::size_t k = 2; k < w.size(); ++k) p.push_back(w[k].c_str());
  const law::Reading r = d ? law::read(*d, static_cast<int>(p.size()), p.data(), nullptr) : law::Reading();
  if (!d || !r.ok() || r.next != static_cast<int>(p.size()))
    throw std::logic_error("tdem-fit printed a LAMMPS law that pair tdem/gran would refuse: '" + words + "'" +
                           (d && !r.ok() ? " (" + r.error + ")" : std::string()));
}

// normal_fit: the law words of the fitted contact; normal_11: of the sphere-sphere contact of
// material 1 (wall data: not fitted, given so that the script runs).
inline void lammps_lines(const Context& c, const std::string& normal_fit, const std::string& normal_11,
                         bool uses_limit_force, HostLines& h) {
  check_lammps_law(normal_fit);
  check_lammps_law(normal_11);
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

// The input lines of a normal law that is a unit (src/contact/law_unit.h) with its own values
// (after the materials, which come from the data): LIGGGHTS `model tdem/NAME` with one
// peratomtypepair property per value (the unit's property names), LAMMPS `normal NAME [E NU [E2
// NU2]] values`.
template <class U>
HostLines unit_hosts(const Context& c, const std::vector<double>& own) {
  HostLines h;
  const law::Description& d = U::description;
  LiggghtsSpec s;
  s.model = std::string("tdem/") + d.name;
  s.material = d.materials;
  for (int k = 0; k < d.count && k < static_cast<int>(own.size()); ++k) s.pair_props.push_back({U::properties[k], own[k]});
  liggghts_lines(c, s, h);
  std::string values;
  for (double v : own) values += " " + num(v);
  const std::string n = std::string("normal ") + d.name;
  if (d.materials)
    lammps_lines(c, n + " " + lammps_materials(c) + values, n + " " + num(c.data.E) + " " + num(c.data.nu) + values,
                 false, h);
  else
    lammps_lines(c, n + values, n + values, false, h);
  return h;
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

}  // namespace fitting
}  // namespace tdem
