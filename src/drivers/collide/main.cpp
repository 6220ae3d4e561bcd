// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: a single head-on collision with one of the tdem normal laws, without a host
// engine. Prints JSON (e, contact time, largest overlap and force, residual overlap, ...) to
// stdout and optionally writes the force-overlap curve as CSV. See docs/collide.md.
// Exit status: 0 success, 1 the contact did not end / the curve could not be written,
// 2 bad input (the message names the option, the value and the allowed range).
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "collision/conversions.h"
#include "collision/head_on.h"

namespace {

using namespace tdem;
using tdem::collision::Bodies;

const char* kHelp = R"(tdem-collide: one head-on collision with a tdem normal law (no host engine).

Usage: tdem-collide --law LAW [law parameters] [bodies] --v0 V [options]

Bodies (sphere 1 hits sphere 2 or a wall; m* and R* are formed from them):
  --m1 M | --rho RHO      mass of sphere 1 [kg], or its density [kg/m^3] (needs --R1)
  --R1 R                  radius of sphere 1 [m] (needed by hertz --E/--Estar, thornton,
                          continuous_potential without --d, and with --rho)
  --wall                  sphere 1 hits a plane wall (m2 = R2 = infinity)
  --m2 M | --rho2 RHO     mass or density of sphere 2 (default density: --rho)
  --R2 R                  radius of sphere 2 [m]
  --v0 V                  impact velocity (relative normal velocity) [m/s], > 0

Laws and their parameters (coefficients, or measurable quantities):
  --law lsd               linear spring-dashpot F = k xi + gamma xi'
      --k K [--gamma G]           stiffness [N/m], damping [kg/s] (default 0)
      --e E --tc T                restitution (0,1] and contact time [s] at this m*
      --e E --k K                 restitution and stiffness
      --end zero_overlap|zero_force   (default zero_overlap)
  --law hertz             F = k~ xi^1.5 + c xi^Theta xi'
      stiffness: --k K~ [N/m^1.5] | --Estar E* [Pa] | --E E --nu NU [--E2 E --nu2 NU]
                 (sphere 2 / wall material, default the same; --E2 inf: rigid) | --tc T
                 (undamped contact time at v0)
      --damping none|linear|kuwabara_kono|tsuji|general   (default none)
        linear: --gamma G [kg/s];  kuwabara_kono: --gamma G~ [kg/(s m^0.5)] | --A T [s];
        tsuji: --alpha A | --e E;  general: --gamma C --theta TH
        linear, kuwabara_kono, general: --e E (< 1) instead of --gamma: the damping that gives
        restitution E at this v0 (root search over the collision)
      --end zero_overlap|zero_force   (default zero_overlap)
  --law walton_braun      hysteretic linear law (contact ends at zero force)
      --kl K [--kul K] [--s S]    loading, unloading stiffness [N/m] (default k_l), slope [1/m]
      --e E --tc T | --e E --kl K constant k_ul from restitution
  --law thornton          elastic-perfectly-plastic (contact ends at zero force)
      modulus as hertz: --Estar | --E --nu [--E2 --nu2]; radius --R1 (and --R2)
      --py P [Pa] | --vy V (yield velocity) [m/s] | --e E (restitution at v0, < 1)
  --law continuous_potential   F = n eps d^n / X^(n+1), X = d - xi
      --eps EPS [J] | --x-min X (closest approach at v0 [m]);  --n N (default 36)
      --d D (default R1 + R2, or R1 with --wall);  --x-cut X (default inf; the collision
      starts at X_cut, or at X = d without cut-off);  --gamma G [kg/s] (default 0);  --end
  --law power_law         power-law hysteresis F = a_l xi^p, unloading a_ul (xi - xi_f)^(p+q)
      --al A --p P  and  --aul A [--q Q]  (default q = 0) | --e E  (q = 0, a_ul from e)
  --law extended_linear   k, gamma from measured e(v0), t_c(v0) at first touch
      --e-fit constant|rational|power --e-coef C0[,C1[,C2]]
            constant e = C0;  rational e = C0 / (C1 + v0^C2);  power e = min(1, (v0/C0)^(-C1))
      --tc-fit constant|power --tc-coef C0[,C1]
            constant t_c = C0;  power t_c = C0 v0^(-C1)
      --v-min V --v-max V     clamp of v0 before the fits (default 1e-3, 1e3 m/s)
      --e-min E               smallest e a fit may give (default 1e-3)
      --end zero_overlap|zero_force   (default zero_overlap)
  --law extended_hertz    Hertz spring (stiffness as hertz: --k | --Estar | --E --nu ...) with
                          Tsuji damping alpha(v0) from e(v0): --e-fit, --e-coef, --v-min, --v-max,
                          --e-min, --end as extended_linear

Integration and output:
  --steps N               RK4 steps per estimated contact time, 1 ... 1e6 (default 4000)
  --dt DT                 fixed time step [s] (overrides --steps)
  --curve FILE            write the samples t,xi,xi_dot,F (CSV, one per step) to FILE
  --help                  this text

Output: JSON on stdout with law, end, parameters, m_eff, r_eff, v0, e, contact_time,
max_overlap, max_force, residual_overlap, rebound_velocity, dissipated_energy, steps, dt,
contact_time_estimate, ended, curve. Exit status 0 ok, 1 the contact did not end (e is null)
or FILE could not be written, 2 bad input.
)";

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string num_str(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

class Args {
 public:
  Args(int argc, char** argv) {
    static const std::set<std::string> flags = {"--wall", "--help"};
    static const std::set<std::string> known = {
        "--law", "--m1", "--m2", "--R1", "--R2", "--rho", "--rho2", "--wall", "--v0", "--k",
        "--gamma", "--e", "--tc", "--end", "--Estar", "--E", "--nu", "--E2", "--nu2",
        "--damping", "--A", "--alpha", "--theta", "--kl", "--kul", "--s", "--py", "--vy",
        "--eps", "--x-min", "--n", "--d", "--x-cut", "--steps", "--dt", "--curve", "--help",
        "--e-fit", "--e-coef", "--tc-fit", "--tc-coef", "--v-min", "--v-max", "--e-min", "--al", "--p",
        "--aul", "--q"};
    for (int i = 1; i < argc; ++i) {
      std::string a = argv[i];
      if (a == "-h") a = "--help";
      if (!known.count(a)) throw BadInput("unknown option '" + a + "' (see --help)");
      if (given_.count(a)) throw BadInput("option " + a + " is given twice");
      if (flags.count(a)) {
        given_[a] = "";
        continue;
      }
      if (i + 1 >= argc) throw BadInput("option " + a + " needs a value");
      given_[a] = argv[++i];
    }
  }
  bool has(const std::string& o) const { return given_.count(o) != 0; }
  bool flag(const std::string& o) {
    used_.insert(o);
    return has(o);
  }
  std::string str(const std::string& o) {
    used_.insert(o);
    return given_.at(o);
  }
  // A number in the range; 'what' is the range as text; allow_inf for "inf".
  double number(const std::string& o, double lo, double hi, bool lo_open, bool hi_open, const char* what,
                bool allow_inf = false) {
    used_.insert(o);
    const std::string& s = given_.at(o);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end == s.c_str() || *end != '\0' || std::isnan(v))
      throw BadInput("option " + o + ": '" + s + "' is not a number (allowed: " + what + ")");
    const bool inf_ok = allow_inf && v == INFINITY;
    if (!inf_ok && (!std::isfinite(v) || (lo_open ? v <= lo : v < lo) || (hi_open ? v >= hi : v > hi)))
      throw BadInput("option " + o + " = " + s + " is outside the allowed range " + what);
    return v;
  }
  double positive(const std::string& o, bool allow_inf = false) {
    return number(o, 0.0, INFINITY, true, true, allow_inf ? "(0, inf]" : "(0, inf)", allow_inf);
  }
  double non_negative(const std::string& o) { return number(o, 0.0, INFINITY, false, true, "[0, inf)"); }
  double restitution(const std::string& o) { return number(o, 0.0, 1.0, true, false, "(0, 1]"); }
  double poisson(const std::string& o) { return number(o, -1.0, 0.5, true, false, "(-1, 0.5]"); }
  std::string choice(const std::string& o, const std::vector<std::string>& allowed) {
    const std::string v = str(o);
    std::string list;
    for (const auto& a : allowed) {
      if (a == v) return v;
      list += (list.empty() ? "" : ", ") + a;
    }
    throw BadInput("option " + o + " = '" + v + "' is not one of: " + list);
  }
  void require(const std::string& o, const std::string& why) const {
    if (!has(o)) throw BadInput("option " + o + " is required " + why);
  }
  void forbid(const std::string& o, const std::string& why) const {
    if (has(o)) throw BadInput("option " + o + " cannot be used " + why);
  }
  // Every option given must have been read.
  void check_all_used(const std::string& law) const {
    for (const auto& kv : given_)
      if (!used_.count(kv.first))
        throw BadInput("option " + kv.first + " does not apply to --law " + law +
                       " with the other options given (see --help)");
  }

 private:
  std::map<std::string, std::string> given_;
  std::set<std::string> used_;
};

// JSON object writer (flat values and one level of nesting).
class Json {
 public:
  void key(const std::string& k) {
    out_ += first_ ? "\n" : ",\n";
    out_ += std::string(2 * depth_, ' ') + "\"" + k + "\": ";
    first_ = false;
  }
  void num(const std::string& k, double v) {
    key(k);
    if (!std::isfinite(v)) {
      out_ += "null";
      return;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    out_ += buf;
  }
  void integer(const std::string& k, long v) {
    key(k);
    out_ += std::to_string(v);
  }
  void boolean(const std::string& k, bool v) {
    key(k);
    out_ += v ? "true" : "false";
  }
  void null(const std::string& k) {
    key(k);
    out_ += "null";
  }
  void str(const std::string& k, const std::string& v) {
    key(k);
    out_ += "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else {
        out_ += c;
      }
    }
    out_ += "\"";
  }
  void open(const std::string& k) {
    key(k);
    out_ += "{";
    ++depth_;
    first_ = true;
  }
  void close() {
    --depth_;
    out_ += "\n" + std::string(2 * depth_, ' ') + "}";
    first_ = false;
  }
  std::string done() { return "{" + out_ + "\n}\n"; }

 private:
  std::string out_;
  bool first_ = true;
  int depth_ = 1;
};

ContactEnd read_end(Args& a, ContactEnd dflt) {
  if (!a.has("--end")) return dflt;
  return a.choice("--end", {"zero_overlap", "zero_force"}) == "zero_force" ? ContactEnd::zero_force
                                                                           : ContactEnd::zero_overlap;
}

// E* from --Estar or --E/--nu [--E2/--nu2]; for hertz also --k or --tc (returns k~ directly).
double read_modulus(Args& a) {
  if (a.has("--Estar")) {
    a.forbid("--E", "together with --Estar");
    return a.positive("--Estar");
  }
  a.require("--E", "(or --Estar) for the elastic modulus");
  a.require("--nu", "with --E");
  const double E1 = a.positive("--E"), nu1 = a.poisson("--nu");
  const double E2 = a.has("--E2") ? a.positive("--E2", true) : E1;
  const double nu2 = a.has("--nu2") ? a.poisson("--nu2") : nu1;
  return hertz::effective_modulus(E1, nu1, E2, nu2);
}

double need_reff(const Bodies& b, const char* why) {
  if (!(b.R1 > 0.0)) throw BadInput(std::string("option --R1 is required ") + why);
  if (!std::isinf(b.R2) && !(b.R2 > 0.0)) throw BadInput(std::string("option --R2 is required ") + why);
  return b.reff();
}

// "C0,C1,..." -> the coefficients of a fit form.
fits::Fit read_fit(Args& a, const std::string& form_opt, const std::string& coef_opt, char what) {
  a.require(form_opt, "for this law");
  a.require(coef_opt, "with " + form_opt);
  fits::Fit f;
  const std::vector<std::string> forms = what == 'e' ? std::vector<std::string>{"constant", "rational", "power"}
                                                     : std::vector<std::string>{"constant", "power"};
  fits::parse(a.choice(form_opt, forms), f.form);
  const std::string list = a.str(coef_opt);
  std::vector<double> c;
  size_t pos = 0;
  while (pos <= list.size()) {
    const size_t comma = std::min(list.find(',', pos), list.size());
    const std::string item = list.substr(pos, comma - pos);
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v))
      throw BadInput("option " + coef_opt + ": '" + item + "' is not a finite number");
    c.push_back(v);
    pos = comma + 1;
  }
  const int n = fits::coefficient_count(f.form, what);
  if (static_cast<int>(c.size()) != n)
    throw BadInput("option " + coef_opt + " needs " + std::to_string(n) + " comma-separated coefficients for form '" +
                   fits::to_string(f.form) + "', got " + std::to_string(c.size()));
  for (int i = 0; i < n; ++i) f.c[i] = c[i];
  return f;
}

fits::Range read_range(Args& a) {
  fits::Range r;
  if (a.has("--v-min")) r.v_min = a.positive("--v-min");
  if (a.has("--v-max")) r.v_max = a.positive("--v-max");
  if (a.has("--e-min")) r.e_min = a.number("--e-min", 0.0, 1.0, true, true, "(0, 1)");
  fits::validate_range(r);
  return r;
}

void fit_params(std::vector<std::pair<std::string, double>>& P, const char* name, const fits::Fit& f) {
  const int n = fits::coefficient_count(f.form, name[0] == 'e' ? 'e' : 't');
  for (int i = 0; i < n; ++i) P.push_back({std::string(name) + "_c" + std::to_string(i), f.c[i]});
}

struct Run {
  std::string law, end, damping;  // damping: hertz only
  std::vector<std::pair<std::string, double>> params;  // the coefficients used
  double meff = NAN, reff = NAN;                      // reff: NaN if no radius was given
  std::vector<std::pair<std::string, double>> closed;  // closed-form predictions, where known
  collision::Result result;
};

// Adds a closed-form prediction; skipped where the closed form does not apply (it throws).
template <class F>
void predict(Run& run, const char* key, F f) {
  try {
    const double v = f();
    if (std::isfinite(v)) run.closed.push_back({key, v});
  } catch (const std::exception&) {
  }
}

template <class Law>
collision::Result go(Law& law, const Bodies& b, double v0, const collision::Options& o) {
  return collision::integrate(law, b, v0, o);
}

Run run(Args& a) {
  Run run;
  if (a.flag("--help")) return run;
  a.require("--law", "(lsd, hertz, walton_braun, thornton, continuous_potential, power_law, extended_linear, "
                     "extended_hertz)");
  run.law = a.choice("--law", {"lsd", "hertz", "walton_braun", "thornton", "continuous_potential", "power_law",
                               "extended_linear", "extended_hertz"});
  a.require("--v0", "(impact velocity)");
  const double v0 = a.positive("--v0");

  // ------------------------------------------------ bodies
  Bodies b;
  if (a.has("--R1")) b.R1 = a.positive("--R1");
  double rho = 0.0;
  if (a.has("--rho")) rho = a.positive("--rho");
  if (a.has("--m1")) {
    a.forbid("--rho", "together with --m1 (give the mass or the density of sphere 1)");
    b.m1 = a.positive("--m1");
  } else {
    if (!a.has("--rho")) throw BadInput("option --m1 (or --rho with --R1) is required for the mass of sphere 1");
    a.require("--R1", "with --rho");
    b.m1 = collision::sphere_mass(b.R1, rho);
  }
  if (a.flag("--wall")) {
    for (const char* o : {"--m2", "--R2", "--rho2"}) a.forbid(o, "with --wall");
  } else {
    if (a.has("--R2")) b.R2 = a.positive("--R2");
    else b.R2 = 0.0;  // unknown
    if (a.has("--m2")) {
      a.forbid("--rho2", "together with --m2");
      b.m2 = a.positive("--m2");
    } else {
      const double rho2 = a.has("--rho2") ? a.positive("--rho2") : rho;
      if (!(rho2 > 0.0)) throw BadInput("option --m2 (or --R2 with --rho/--rho2) is required for sphere 2, or give --wall");
      a.require("--R2", "with a density for sphere 2");
      b.m2 = collision::sphere_mass(b.R2, rho2);
    }
  }
  const double meff = b.meff();
  run.meff = meff;
  if (b.R1 > 0.0 && (std::isinf(b.R2) || b.R2 > 0.0)) run.reff = b.reff();
  auto& P = run.params;

  collision::Options opt;
  if (a.has("--dt")) {
    a.forbid("--steps", "together with --dt");
    opt.dt = a.positive("--dt");
  } else if (a.has("--steps")) {
    opt.steps_per_contact = static_cast<int>(a.number("--steps", 1.0, 1e6, false, false, "[1, 1e6]"));
    if (opt.steps_per_contact != a.number("--steps", 1.0, 1e6, false, false, "[1, 1e6]"))
      throw BadInput("option --steps = " + a.str("--steps") + " is not an integer in [1, 1e6]");
  }
  opt.record = a.has("--curve");
  if (opt.record) a.str("--curve");

  // ------------------------------------------------ laws
  if (run.law == "lsd") {
    collision::LsdLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--e")) {
      a.forbid("--gamma", "together with --e (the damping follows from e)");
      const double e = a.restitution("--e");
      if (a.has("--tc")) {
        a.forbid("--k", "together with --e and --tc");
        law.c = lsd::from_restitution_and_time(e, a.positive("--tc"), meff, law.end_mode);
      } else {
        a.require("--k", "with --e (or give --tc)");
        law.c = lsd::from_restitution_and_stiffness(e, a.positive("--k"), meff, law.end_mode);
      }
    } else {
      a.require("--k", "for --law lsd (or --e with --tc)");
      law.c = {a.positive("--k"), a.has("--gamma") ? a.non_negative("--gamma") : 0.0};
    }
    run.end = to_string(law.end_mode);
    P = {{"k", law.c.k}, {"gamma", law.c.gamma}};
    predict(run, "e", [&] { return lsd::restitution(law.c, meff, law.end_mode); });
    predict(run, "contact_time", [&] { return lsd::contact_time(law.c, meff, law.end_mode); });
    predict(run, "max_overlap", [&] { return lsd::max_overlap(law.c, meff, v0); });
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  } else if (run.law == "hertz") {
    collision::HertzLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--k")) {
      law.p.k = a.positive("--k");
    } else if (a.has("--tc")) {
      law.p.k = hertz::stiffness_from_contact_time(a.positive("--tc"), meff, v0);
    } else {
      const double es = read_modulus(a);
      law.p.k = hertz::stiffness(es, need_reff(b, "for the Hertz stiffness from the modulus"));
      P.push_back({"Estar", es});
    }
    const std::string d = a.has("--damping")
                              ? a.choice("--damping", {"none", "linear", "kuwabara_kono", "tsuji", "general"})
                              : "none";
    law.p.damp = 0.0;
    law.p.theta = 0.0;
    // --e for the damping forms without a closed form: root search over the collision (conversions.h).
    auto damping_from_e = [&](collision::HertzLaw& l) {
      if (!a.has("--e")) return false;
      a.forbid("--gamma", "together with --e (the damping follows from e)");
      const double e = a.number("--e", 0.0, 1.0, true, true, "(0, 1)");
      l.p.damp = collision::hertz_damping_for_restitution(l.damping, l.end_mode, l.p, b, v0, e);
      return true;
    };
    if (d == "none") {
      law.damping = hertz::Damping::linear;
    } else if (d == "linear") {
      law.damping = hertz::Damping::linear;
      if (!damping_from_e(law)) {
        a.require("--gamma", "(or --e) for --damping linear");
        law.p.damp = a.non_negative("--gamma");
      }
    } else if (d == "kuwabara_kono") {
      law.damping = hertz::Damping::kuwabara_kono;
      if (damping_from_e(law)) {
        a.forbid("--A", "together with --e");
      } else if (a.has("--A")) {
        a.forbid("--gamma", "together with --A");
        law.p.damp = hertz::kuwabara_kono_damping(a.non_negative("--A"), law.p.k);
      } else {
        a.require("--gamma", "(or --A, or --e) for --damping kuwabara_kono");
        law.p.damp = a.non_negative("--gamma");
      }
    } else if (d == "tsuji") {
      law.damping = hertz::Damping::tsuji;
      if (a.has("--e")) {
        a.forbid("--alpha", "together with --e");
        law.p.damp = hertz::tsuji_alpha_from_restitution(a.restitution("--e"), law.end_mode);
      } else {
        a.require("--alpha", "(or --e) for --damping tsuji");
        law.p.damp = a.non_negative("--alpha");
      }
    } else {
      law.damping = hertz::Damping::general;
      a.require("--theta", "for --damping general");
      law.p.theta = a.non_negative("--theta");
      if (!damping_from_e(law)) {
        a.require("--gamma", "(or --e) for --damping general");
        law.p.damp = a.non_negative("--gamma");
      }
    }
    hertz::validate(law.damping, law.p);
    run.end = to_string(law.end_mode);
    P.push_back({"k", law.p.k});
    P.push_back({law.damping == hertz::Damping::tsuji ? "alpha" : "damping", law.p.damp});
    if (law.damping == hertz::Damping::general) P.push_back({"theta", law.p.theta});
    if (law.p.damp == 0.0) {
      predict(run, "e", [] { return 1.0; });
      predict(run, "contact_time", [&] { return hertz::contact_time_elastic(law.p.k, meff, v0); });
      predict(run, "max_overlap", [&] { return hertz::max_overlap_elastic(law.p.k, meff, v0); });
    } else if (law.damping == hertz::Damping::tsuji) {
      predict(run, "e", [&] { return hertz::tsuji_restitution(law.p.damp, law.end_mode); });
    }
    run.damping = d;
    a.check_all_used("hertz");
    run.result = go(law, b, v0, opt);
  } else if (run.law == "walton_braun") {
    collision::WaltonBraunLaw law;
    if (a.has("--end") && read_end(a, ContactEnd::zero_force) != ContactEnd::zero_force)
      throw BadInput("option --end = zero_overlap is not allowed for --law walton_braun (allowed: zero_force)");
    if (a.has("--e")) {
      a.forbid("--kul", "together with --e");
      a.forbid("--s", "together with --e");
      const double e = a.restitution("--e");
      if (a.has("--tc")) {
        a.forbid("--kl", "together with --e and --tc");
        law.p = walton_braun::from_restitution_and_time(e, a.positive("--tc"), meff);
      } else {
        a.require("--kl", "with --e (or give --tc)");
        law.p = walton_braun::from_restitution_and_stiffness(e, a.positive("--kl"));
      }
    } else {
      a.require("--kl", "for --law walton_braun (or --e with --tc)");
      const double kl = a.positive("--kl");
      const double ku = a.has("--kul") ? a.positive("--kul") : kl;
      if (ku < kl)
        throw BadInput("option --kul = " + num_str(ku) + " is outside the allowed range [k_l, inf) = [" +
                       num_str(kl) + ", inf)");
      law.p = {kl, ku, a.has("--s") ? a.non_negative("--s") : 0.0};
    }
    walton_braun::validate(law.p);
    run.end = "zero_force";
    P = {{"k_l", law.p.k_load}, {"k_u", law.p.k_unload}, {"s", law.p.slope}};
    predict(run, "e", [&] { return walton_braun::restitution(law.p, meff, v0); });
    predict(run, "contact_time", [&] { return walton_braun::contact_time(law.p, meff, v0); });
    predict(run, "max_overlap", [&] { return walton_braun::max_overlap(law.p, meff, v0); });
    predict(run, "residual_overlap", [&] {
      return walton_braun::residual_overlap_ratio(law.p, meff, v0) * walton_braun::max_overlap(law.p, meff, v0);
    });
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  } else if (run.law == "thornton") {
    collision::ThorntonLaw law;
    if (a.has("--end") && read_end(a, ContactEnd::zero_force) != ContactEnd::zero_force)
      throw BadInput("option --end = zero_overlap is not allowed for --law thornton (allowed: zero_force)");
    law.p.e_star = read_modulus(a);
    const double reff = need_reff(b, "for --law thornton");
    int n_yield = a.has("--py") + a.has("--vy") + a.has("--e");
    if (n_yield != 1) throw BadInput("exactly one of --py, --vy, --e is required for --law thornton");
    if (a.has("--py")) law.p.p_y = a.positive("--py");
    else if (a.has("--vy")) law.p.p_y = thornton::yield_pressure_from_yield_velocity(a.positive("--vy"), law.p.e_star, reff, meff);
    else {
      const double e = a.number("--e", 0.0, 1.0, true, true, "(0, 1)");
      law.p.p_y = thornton::yield_pressure_from_restitution(e, v0, law.p.e_star, reff, meff);
    }
    thornton::validate(law.p);
    run.end = "zero_force";
    P = {{"Estar", law.p.e_star}, {"p_y", law.p.p_y}, {"xi_y", thornton::yield_overlap(law.p, reff)},
         {"v_y", thornton::yield_velocity(law.p, reff, meff)}};
    predict(run, "e", [&] { return thornton::restitution(law.p, reff, meff, v0); });
    predict(run, "max_overlap", [&] { return thornton::max_overlap(law.p, reff, meff, v0); });
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  } else if (run.law == "power_law") {
    collision::PowerLawLaw law;
    if (a.has("--end") && read_end(a, ContactEnd::zero_force) != ContactEnd::zero_force)
      throw BadInput("option --end = zero_overlap is not allowed for --law power_law (allowed: zero_force)");
    a.require("--al", "for --law power_law");
    a.require("--p", "for --law power_law");
    law.p.a_load = a.positive("--al");
    law.p.p = a.positive("--p");
    if (a.has("--e")) {
      a.forbid("--aul", "together with --e");
      a.forbid("--q", "together with --e (q = 0)");
      law.p = power_law::from_restitution(law.p.a_load, law.p.p, a.restitution("--e"));
    } else {
      a.require("--aul", "(or --e) for --law power_law");
      law.p.a_unload = a.positive("--aul");
      law.p.q = a.has("--q") ? a.non_negative("--q") : 0.0;
    }
    power_law::validate(law.p);
    run.end = "zero_force";
    P = {{"a_l", law.p.a_load}, {"p", law.p.p}, {"a_ul", law.p.a_unload}, {"q", law.p.q}};
    predict(run, "e", [&] { return power_law::restitution(law.p, meff, v0); });
    predict(run, "contact_time", [&] { return power_law::contact_time(law.p, meff, v0); });
    predict(run, "max_overlap", [&] { return power_law::max_overlap(law.p, meff, v0); });
    predict(run, "residual_overlap", [&] { return power_law::residual_overlap(law.p, meff, v0); });
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  } else if (run.law == "extended_linear") {
    collision::ExtendedLinearLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    law.p.e_fit = read_fit(a, "--e-fit", "--e-coef", 'e');
    law.p.tc_fit = read_fit(a, "--tc-fit", "--tc-coef", 't');
    law.p.range = read_range(a);
    extended::validate(law.p);
    run.end = to_string(law.end_mode);
    fit_params(P, "e_fit", law.p.e_fit);
    fit_params(P, "tc_fit", law.p.tc_fit);
    const auto c = extended::linear_coefficients(law.end_mode, law.p, meff, v0);
    P.push_back({"k", c.k});
    P.push_back({"gamma", c.gamma});
    predict(run, "e", [&] { return extended::linear_restitution(law.p, v0); });
    predict(run, "contact_time", [&] { return extended::linear_contact_time(law.p, v0); });
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  } else if (run.law == "extended_hertz") {
    collision::ExtendedHertzLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--k")) {
      law.p.k = a.positive("--k");
    } else {
      const double es = read_modulus(a);
      law.p.k = hertz::stiffness(es, need_reff(b, "for the Hertz stiffness from the modulus"));
      P.push_back({"Estar", es});
    }
    law.p.e_fit = read_fit(a, "--e-fit", "--e-coef", 'e');
    law.p.range = read_range(a);
    extended::validate(law.p);
    run.end = to_string(law.end_mode);
    P.push_back({"k", law.p.k});
    fit_params(P, "e_fit", law.p.e_fit);
    P.push_back({"alpha", extended::hertz_alpha(law.end_mode, law.p.e_fit, law.p.range, v0)});
    predict(run, "e", [&] { return extended::hertz_restitution(law.p, v0); });
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  } else {  // continuous_potential
    collision::ContinuousPotentialLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--d")) {
      law.p.d = a.positive("--d");
    } else {
      if (!(b.R1 > 0.0)) throw BadInput("option --d (or --R1) is required for --law continuous_potential");
      if (!std::isinf(b.R2) && !(b.R2 > 0.0)) throw BadInput("option --d (or --R2) is required for --law continuous_potential");
      law.p.d = std::isinf(b.R2) ? b.R1 : b.R1 + b.R2;
    }
    law.p.n = a.has("--n") ? a.positive("--n") : 36.0;
    law.p.x_cut = a.has("--x-cut") ? a.positive("--x-cut", true) : INFINITY;
    law.p.gamma = a.has("--gamma") ? a.non_negative("--gamma") : 0.0;
    if (a.has("--x-min")) {
      a.forbid("--eps", "together with --x-min");
      const double x_min = a.positive("--x-min");
      const double x_start = std::isinf(law.p.x_cut) ? law.p.d : law.p.x_cut;
      if (!(x_min < x_start))
        throw BadInput("option --x-min = " + num_str(x_min) + " is outside the allowed range (0, X_start) = (0, " +
                       num_str(x_start) + ") (X_start: --x-cut, or --d without a cut-off)");
      law.p.eps = continuous_potential::energy_for_closest_approach(x_min, meff, v0, law.p.d, law.p.n,
                                                                    std::isinf(law.p.x_cut) ? law.p.d : law.p.x_cut);
    } else {
      a.require("--eps", "(or --x-min) for --law continuous_potential");
      law.p.eps = a.positive("--eps");
    }
    continuous_potential::validate(law.p);
    run.end = to_string(law.end_mode);
    P = {{"eps", law.p.eps}, {"d", law.p.d}, {"n", law.p.n}, {"x_cut", law.p.x_cut}, {"gamma", law.p.gamma}};
    if (law.p.gamma == 0.0) {
      predict(run, "e", [] { return 1.0; });
      predict(run, "max_overlap", [&] {
        auto from_start = law.p;  // energy counted from the start of the collision
        from_start.x_cut = law.p.d - law.start_overlap();
        return law.p.d - continuous_potential::closest_approach(from_start, meff, v0);
      });
    }
    a.check_all_used(run.law);
    run.result = go(law, b, v0, opt);
  }
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  Run r;
  std::string curve;
  try {
    Args a(argc, argv);
    if (a.has("--help")) {
      std::fputs(kHelp, stdout);
      return 0;
    }
    r = run(a);
    if (a.has("--curve")) curve = a.str("--curve");
  } catch (const BadInput& e) {
    std::fprintf(stderr, "tdem-collide: error: %s\n", e.what());
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "tdem-collide: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tdem-collide: error: %s\n", e.what());
    return 1;
  }
  const auto& res = r.result;
  int status = 0;
  if (!curve.empty()) {
    std::FILE* f = std::fopen(curve.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "tdem-collide: error: cannot write the curve file '%s': %s\n", curve.c_str(),
                   std::strerror(errno));
      status = 1;
    } else {
      std::fputs("t,xi,xi_dot,F\n", f);
      for (const auto& s : res.samples) std::fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", s.t, s.xi, s.xi_dot, s.force);
      if (std::fclose(f) != 0) status = 1;
    }
  }
  Json j;
  j.str("law", r.law);
  j.str("end", r.end);
  if (!r.damping.empty()) j.str("damping", r.damping);
  j.open("parameters");
  for (const auto& p : r.params) j.num(p.first, p.second);
  j.close();
  j.num("m_eff", r.meff);
  j.num("r_eff", r.reff);
  j.num("v0", res.v0);
  j.boolean("ended", res.ended);
  if (res.ended) {
    j.num("e", res.restitution);
    j.num("contact_time", res.contact_time);
    j.num("rebound_velocity", res.rebound_velocity);
    j.num("residual_overlap", res.residual_overlap);
    j.num("dissipated_energy", res.dissipated_energy);
  } else {
    for (const char* k : {"e", "contact_time", "rebound_velocity", "residual_overlap", "dissipated_energy"}) j.null(k);
  }
  j.num("max_overlap", res.max_overlap);
  j.num("max_force", res.max_force);
  j.integer("steps", res.steps);
  j.num("dt", res.dt);
  j.num("contact_time_estimate", res.contact_time_estimate);
  j.open("closed_form");
  for (const auto& p : r.closed) j.num(p.first, p.second);
  j.close();
  if (!curve.empty()) j.str("curve", curve);
  else j.null("curve");
  std::fputs(j.done().c_str(), stdout);
  if (res.ended && res.steps < 20)
    std::fprintf(stderr, "tdem-collide: warning: only %ld steps in the contact; use a smaller --dt or more --steps\n",
                 res.steps);
  if (!res.ended) {
    std::fprintf(stderr, "tdem-collide: the contact did not end within %ld steps (t = %g s)%s\n", res.steps,
                 res.steps * res.dt, res.steps >= collision::Options().max_steps ? "; is --dt too small?" : "");
    return 1;
  }
  return status;
}
