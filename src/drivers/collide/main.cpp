// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: a single collision with one of the tdem normal laws, without a host engine:
// head-on (src/collision/head_on.h), or oblique with spin and a tangential law
// (src/collision/oblique.h, with --angle, --spin or --tangential). Prints JSON (e, contact time,
// largest overlap and force, residual overlap, ...; beta, e_t, spin and rebound angles for oblique
// impacts) to stdout and optionally writes the force-overlap curve as CSV. With --scheme the
// sphere-wall impact is integrated in whole steps with a chosen time-integration scheme from free
// flight, as a host engine does it (src/collision/integrate_impact.h), optionally averaged over
// the start phase of the contact (--phases). See docs/collide.md.
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
#include <type_traits>
#include <utility>
#include <vector>

#include "collision/conversions.h"
#include "collision/head_on.h"
#include "collision/analytic.h"
#include "collision/integrate_impact.h"
#include "collision/phase_average.h"
#include "collision/oblique.h"
#include "collision/rigid_body.h"
#include "contact/tangential/di_renzo.h"
#include "contact/tangential/haff_werner.h"
#include "contact/tangential/linear_spring.h"
#include "contact/tangential/mindlin_deresiewicz.h"
#include "contact/tangential/mindlin_no_slip.h"
#include "contact/tangential/parameters.h"
#include "contact/tangential/walton_braun_tangential.h"

namespace {

using namespace tdem;
using tdem::collision::Bodies;

const char* kHelp = R"(tdem-collide: one collision with a tdem normal law (no host engine): head-on, or
oblique with spin and a tangential law.

Usage: tdem-collide --law LAW [law parameters] [bodies] --v0 V [options]
       tdem-collide --law LAW [...] --R1 R [bodies] --v0 V --angle DEG [--spin W]
                    [--tangential TLAW [tangential parameters]] [oblique options]

Bodies (sphere 1 hits sphere 2 or a wall; m* and R* are formed from them):
  --m1 M | --rho RHO      mass of sphere 1 [kg], or its density [kg/m^3] (needs --R1)
  --R1 R                  radius of sphere 1 [m] (needed by hertz --E/--Estar, thornton,
                          continuous_potential without --d, and with --rho)
  --wall                  sphere 1 hits a plane wall (m2 = R2 = infinity)
  --m2 M | --rho2 RHO     mass or density of sphere 2 (default density: --rho)
  --R2 R                  radius of sphere 2 [m]
  --v0 V                  impact velocity (relative normal velocity) [m/s], > 0; with --angle
                          the impact speed |v| (the normal component is V cos(angle))

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

Oblique impacts (any of --angle > 0, --spin != 0, --spin2 != 0, --tangential other than none;
solid spheres, velocity Verlet as the hosts integrate, end of contact located in the step):
  --angle DEG             impact angle from the normal, [0, 90) degrees (default 0)
  --spin W                initial spin of sphere 1 [1/s] about the axis normal to the impact plane,
                          sign: slip velocity v_s = v_t + R1 W (+ R2 W2), v_s = 0 for rolling
  --spin2 W               initial spin of sphere 2 (not with --wall)
  --tangential TLAW       tangential law (default none: frictionless):
      cundall_strack      spring + Coulomb slider (kernel cundall_strack.h, spring truncated on slip)
          --mu MU  --kt KT | --kappa K (k_t = K k_n; needs lsd, extended_linear or walton_braun)
          [--gammat G] [--friction-limit positive_normal|absolute]  (default absolute: mu |F_n|)
      linear_spring       spring(-dashpot) with Coulomb limit (linear_spring.h)
          --mu MU  --kt KT and/or --kappa K (k_t = KT + K k_n, k_n the normal tangent stiffness)
          [--gammat G] [--slip-reset spring_only|spring_and_dashpot] [--friction-limit ...]
      haff_werner         viscous friction, no memory: --mu MU --gammat G [--friction-limit ...]
      walton_braun        Walton-Braun stiffness k_t0 (1 - x)^(1/3) from the last reversal
                          (walton_braun_tangential.h): --mu MU --kt KT and/or --kappa K [--friction-limit]
      mindlin_no_slip     Tsuji no-slip Mindlin spring 8 G* a with dashpot eta_t = R gamma_n:
          --mu MU  --gstar G | --E E --nu NU [--E2 E --nu2 NU]  [--eta-ratio R] (default 1)
          [--slip-reset ...] [--friction-limit ...]
      di_renzo            2/3 of the no-slip stiffness, no dashpot: --mu MU, G* as mindlin_no_slip
      mindlin_deresiewicz loading/unloading/reloading branches (mindlin_deresiewicz.h): --mu MU, G* as
                          mindlin_no_slip [--friction-limit ...]
  --beta0 B               sticking tangential restitution of the rigid-body (Walton) prediction,
                          [-1, 1] (default 1, marked as assumed)
  --psi-kappa K           kappa of psi_1 = kappa v_s0/(mu v_n0), psi_2 = kappa v_s'/(mu v_n0)
                          (default: k_t/k_n of the linear springs and Walton-Braun (k_t0), 4 G*/E* of
                          the Mindlin laws; none for haff_werner)
  --lever-arm radius|contact_point   lever of the tangential force: R, or R - xi/2 as LIGGGHTS
                          (default radius)

Integration and output:
  --steps N               RK4 steps per estimated contact time, 1 ... 1e6 (default 4000;
                          oblique impacts: velocity Verlet steps, default 100000)
  --dt DT                 fixed time step [s] (overrides --steps)
  --curve FILE            write the samples t,xi,xi_dot,F (CSV, one per step) to FILE
                          (oblique: t,xi,xi_dot,F,Ft,vs,sliding)
  --scheme NAME           integrate a sphere-wall impact (--wall, --R1) in whole steps with the
                          scheme NAME as a host engine does (collision/integrate_impact.h): from
                          free flight at z = R1 + GAP, predict - force - correct per step, the
                          contact ends at the first step with overlap <= 0, results read 10
                          free-flight steps later. NAME: one-evaluation schemes
                          euler|symplectic_euler|taylor2|taylor3|leapfrog|position_verlet|
                          velocity_verlet|velocity_verlet_sync|beeman|ab2|ab3|ab4|ab5|abm4|gear4|
                          gear5|gear6, or the harness-only heun|rk4|vv2|abm4_pece. Step: --dt, or
                          --steps N per estimated contact time (default 1000). Any normal law;
                          --tangential as above; lever arm radius only
  --gap GAP               with --scheme: the start gap [m], >= 0 (default 0: touch at t = 0)
  --phases P              with --scheme: P runs with gap GAP + (i + 1/2)/P v_n0 dt, i = 0..P-1
                          (the contact start phase on the time grid); prints the means and, where
                          the closed form exists (lsd, tangential none or cundall_strack without
                          --gammat), the mean |error| against it
  --analytic              closed-form solution instead of the integrator (collision/analytic.h):
                          a sphere on a wall or two spheres (contact frame fixed: the turning of the
                          line of centres is neglected), --law lsd (any parameter form, either
                          --end) and --tangential none or cundall_strack (with or without --gammat),
                          lever arm radius; not with --curve, --steps or --dt. "method": "analytic";
                          steps = 0, dt and max_tangential_force null
  --help                  this text

Output: JSON on stdout with law, method (integrated|analytic), end, parameters, m_eff, r_eff, v0, e, contact_time,
max_overlap, max_force, residual_overlap, rebound_velocity, dissipated_energy, steps, dt,
contact_time_estimate, ended, curve; oblique impacts add speed, angle, vn0, vt0, vs0, spin, beta,
e_t, spin_after, rebound angles, psi1, psi2, stick/slip switches and rigid_body (docs/collide.md).
Exit status 0 ok, 1 the contact did not end (e is null) or FILE could not be written, 2 bad input.
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
    static const std::set<std::string> flags = {"--wall", "--help", "--analytic"};
    static const std::set<std::string> known = {
        "--law", "--m1", "--m2", "--R1", "--R2", "--rho", "--rho2", "--wall", "--v0", "--k",
        "--gamma", "--e", "--tc", "--end", "--Estar", "--E", "--nu", "--E2", "--nu2",
        "--damping", "--A", "--alpha", "--theta", "--kl", "--kul", "--s", "--py", "--vy",
        "--eps", "--x-min", "--n", "--d", "--x-cut", "--steps", "--dt", "--curve", "--help",
        "--e-fit", "--e-coef", "--tc-fit", "--tc-coef", "--v-min", "--v-max", "--e-min", "--al", "--p",
        "--aul", "--q", "--angle", "--spin", "--spin2", "--tangential", "--mu", "--kt", "--kappa", "--gammat",
        "--friction-limit", "--slip-reset", "--gstar", "--eta-ratio", "--beta0", "--psi-kappa", "--lever-arm",
        "--analytic", "--scheme", "--gap", "--phases"};
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
  void raw(const std::string& k, const std::string& json) {
    key(k);
    out_ += json;
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
  try {  // the kernel's range checks, with the option named
    if (what == 'e') fits::validate_restitution(f);
    else fits::validate_contact_time(f);
  } catch (const std::exception& e) {
    throw BadInput("option " + coef_opt + " (form " + fits::to_string(f.form) + "): " + e.what());
  }
  return f;
}

fits::Range read_range(Args& a) {
  fits::Range r;
  if (a.has("--v-min")) r.v_min = a.positive("--v-min");
  if (a.has("--v-max")) r.v_max = a.positive("--v-max");
  if (a.has("--e-min")) r.e_min = a.number("--e-min", 0.0, 1.0, true, true, "(0, 1)");
  try {
    fits::validate_range(r);
  } catch (const std::exception& e) {
    throw BadInput(std::string("options --v-min, --v-max, --e-min: ") + e.what());
  }
  return r;
}

void fit_params(std::vector<std::pair<std::string, double>>& P, const char* name, const fits::Fit& f) {
  const int n = fits::coefficient_count(f.form, name[0] == 'e' ? 'e' : 't');
  for (int i = 0; i < n; ++i) P.push_back({std::string(name) + "_c" + std::to_string(i), f.c[i]});
}

// The oblique set-up, read before the laws (so that every option is marked as used).
struct Oblique {
  bool active = false;
  double speed = 0.0, angle_deg = 0.0;
  collision::ObliqueBodies bodies;
  collision::ObliqueImpact impact;
  collision::ObliqueOptions opt;
  std::string tangential = "none";
  double mu = 0.0, kt = NAN, kappa = NAN, gammat = 0.0, gstar = NAN, estar = NAN, eta_ratio = 1.0;
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  tangential::SlipReset reset = tangential::SlipReset::spring_only;
  bool beta0_given = false;
  double beta0 = 1.0;
  double psi_kappa = NAN;
  // results
  std::vector<std::pair<std::string, double>> tparams;  // the tangential coefficients used
  std::vector<std::pair<std::string, std::string>> tchoices;
  collision::ObliqueResult r;
  rigid_body::Output rb;
  bool rb_valid = false;
};

// --scheme: the whole-step integration of integrate_impact.h (optionally phase-averaged).
struct SchemeRun {
  bool active = false;
  collision::ImpactScheme scheme;
  collision::ImpactSetup setup;
  collision::ImpactOptions opt;
  int phases = 0;  // 0: one run at the given gap
  bool have_ref = false;
  collision::ImpactReference ref;
  collision::PhaseAverage pa;
  collision::ImpactResult one;
};

struct Run {
  std::string law, end, damping;  // damping: hertz only
  std::vector<std::pair<std::string, double>> params;  // the coefficients used
  double meff = NAN, reff = NAN;                      // reff: NaN if no radius was given
  std::vector<std::pair<std::string, double>> closed;  // closed-form predictions, where known
  collision::Result result;
  Oblique obl;
  SchemeRun sch;
  bool analytic = false;  // --analytic: closed form (collision/analytic.h) instead of the integrator
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

// ------------------------------------------------ oblique impacts
Oblique read_oblique(Args& a, const Bodies& b, double speed, double angle_deg) {
  Oblique o;
  o.speed = speed;
  o.angle_deg = angle_deg;
  const double spin = a.has("--spin") ? a.number("--spin", -INFINITY, INFINITY, true, true, "(-inf, inf)") : 0.0;
  double spin2 = 0.0;
  if (a.has("--spin2")) {
    if (std::isinf(b.m2) && std::isinf(b.R2)) throw BadInput("option --spin2 cannot be used with --wall");
    spin2 = a.number("--spin2", -INFINITY, INFINITY, true, true, "(-inf, inf)");
  }
  if (a.has("--tangential"))
    o.tangential = a.choice("--tangential", {"none", "cundall_strack", "linear_spring", "haff_werner", "walton_braun",
                                              "mindlin_no_slip", "di_renzo", "mindlin_deresiewicz"});
  o.active = angle_deg > 0.0 || spin != 0.0 || spin2 != 0.0 || o.tangential != "none";
  const char* oblique_only[] = {"--mu", "--kt", "--kappa", "--gammat", "--friction-limit", "--slip-reset", "--gstar",
                                "--eta-ratio", "--beta0", "--psi-kappa", "--lever-arm"};
  if (!o.active) {
    for (const char* opt : oblique_only)
      if (a.has(opt))
        throw BadInput(std::string("option ") + opt + " needs an oblique impact (--angle > 0, --spin or --tangential)");
    return o;
  }
  // bodies: solid spheres, radii needed
  if (!(b.R1 > 0.0)) throw BadInput("option --R1 is required for an oblique impact (lever arm of the friction)");
  if (!std::isinf(b.R2) && !(b.R2 > 0.0)) throw BadInput("option --R2 is required for an oblique impact of two spheres");
  o.bodies.m1 = b.m1;
  o.bodies.R1 = b.R1;
  o.bodies.m2 = b.m2;
  o.bodies.R2 = b.R2;
  o.impact.speed = speed;
  o.impact.angle = angle_deg * M_PI / 180.0;
  o.impact.omega1 = spin;
  o.impact.omega2 = spin2;
  if (a.has("--lever-arm"))
    o.opt.lever = a.choice("--lever-arm", {"radius", "contact_point"}) == "radius" ? collision::LeverArm::radius
                                                                                   : collision::LeverArm::contact_point;
  if (a.has("--beta0")) {
    o.beta0_given = true;
    o.beta0 = a.number("--beta0", -1.0, 1.0, false, false, "[-1, 1]");
  }
  if (a.has("--psi-kappa")) o.psi_kappa = a.positive("--psi-kappa");

  // tangential law parameters
  const std::string& t = o.tangential;
  auto need = [&](const char* opt) { a.require(opt, "for --tangential " + t); };
  auto refuse = [&](const char* opt) {
    if (a.has(opt)) throw BadInput(std::string("option ") + opt + " does not apply to --tangential " + t);
  };
  if (t == "none") {
    for (const char* opt : {"--mu", "--kt", "--kappa", "--gammat", "--friction-limit", "--slip-reset", "--gstar",
                            "--eta-ratio"})
      refuse(opt);
    return o;
  }
  need("--mu");
  o.mu = a.non_negative("--mu");
  if (a.has("--friction-limit"))
    o.limit = a.choice("--friction-limit", {"positive_normal", "absolute"}) == "absolute"
                  ? tangential::FrictionLimit::absolute
                  : tangential::FrictionLimit::positive_normal;
  if (a.has("--slip-reset")) {
    if (t != "linear_spring" && t != "mindlin_no_slip") refuse("--slip-reset");
    o.reset = a.choice("--slip-reset", {"spring_only", "spring_and_dashpot"}) == "spring_only"
                  ? tangential::SlipReset::spring_only
                  : tangential::SlipReset::spring_and_dashpot;
  }
  if (t == "cundall_strack" || t == "linear_spring" || t == "walton_braun") {
    for (const char* opt : {"--gstar", "--eta-ratio"}) refuse(opt);
    if (t == "walton_braun") refuse("--gammat");
    if (t == "cundall_strack" && a.has("--kt") && a.has("--kappa"))
      throw BadInput("options --kt and --kappa cannot be used together for --tangential cundall_strack");
    if (!a.has("--kt") && !a.has("--kappa"))
      throw BadInput("option --kt or --kappa is required for --tangential " + t);
    if (a.has("--kt")) o.kt = a.positive("--kt");
    if (a.has("--kappa")) o.kappa = a.positive("--kappa");
    if (a.has("--gammat")) o.gammat = a.non_negative("--gammat");
  } else if (t == "haff_werner") {
    for (const char* opt : {"--kt", "--kappa", "--gstar", "--eta-ratio"}) refuse(opt);
    need("--gammat");
    o.gammat = a.non_negative("--gammat");
  } else {  // mindlin_no_slip, di_renzo, mindlin_deresiewicz
    for (const char* opt : {"--kt", "--kappa", "--gammat"}) refuse(opt);
    if (t != "mindlin_no_slip") refuse("--eta-ratio");
    // G* from --gstar or from --E --nu [--E2 --nu2] (the materials of the Hertz normal law); E*
    // (for kappa = 4 G*/E* of psi) from --Estar or the same materials.
    if (!a.has("--gstar") && !a.has("--E"))
      throw BadInput("option --gstar (or --E with --nu) is required for --tangential " + t);
    if (a.has("--E")) {
      need("--nu");
      const double E1 = a.positive("--E");
      const double nu1 = a.poisson("--nu");
      const double E2 = a.has("--E2") ? a.positive("--E2", true) : E1;
      const double nu2 = a.has("--nu2") ? a.poisson("--nu2") : nu1;
      o.gstar = tangential::effective_shear_modulus_from_E(E1, nu1, E2, nu2);
      o.estar = tangential::effective_youngs_modulus(E1, nu1, E2, nu2);
    }
    if (a.has("--gstar")) o.gstar = a.positive("--gstar");
    if (a.has("--Estar")) o.estar = a.positive("--Estar");
    if (a.has("--eta-ratio")) o.eta_ratio = a.non_negative("--eta-ratio");
  }
  return o;
}

// A normal stiffness that stays constant through the contact (for kappa), NaN otherwise.
double constant_normal_stiffness(const Run& run) {
  const char* key = run.law == "lsd" || run.law == "extended_linear" ? "k"
                    : run.law == "walton_braun"                      ? "k_l"
                                                                     : nullptr;
  if (!key) return NAN;
  for (const auto& p : run.params)
    if (p.first == key) return p.second;
  return NAN;
}

// The closed-form reference of integrate_impact (lsd with the Cundall-Strack spring, with or without dashpot,
// or frictionless): sets run.sch.ref.
template <class Law, class TLaw>
void scheme_reference(Run& run, const Law& law, const TLaw& tlaw) {
  SchemeRun& S = run.sch;
  if constexpr (std::is_same_v<Law, collision::LsdLaw> &&
                (std::is_same_v<TLaw, collision::Frictionless> ||
                 std::is_same_v<TLaw, collision::CundallStrackTangential>)) {
    namespace an = collision::analytic;
    an::Input in;
    in.m = S.setup.m;
    in.R = S.setup.R;
    in.kn = law.c.k;
    in.gn = law.c.gamma;
    in.end = law.end_mode;
    in.vn0 = S.setup.speed * std::cos(S.setup.angle);
    in.vt0 = S.setup.speed * std::sin(S.setup.angle);
    in.omega0 = S.setup.omega0;
    if constexpr (std::is_same_v<TLaw, collision::CundallStrackTangential>) {
      in.kt = tlaw.p.kt;
      in.gt = tlaw.p.gammat;
      in.rule = tlaw.rule;
      in.mu = tlaw.p.mu;
      in.limit = tlaw.limit;
    } else {
      in.kt = law.c.k;
      in.mu = 0.0;
    }
    try {
      const an::Output x = an::impact(in);
      S.ref.e = x.e;
      S.ref.beta = x.beta;
      S.ref.e_t = x.e_t;
      S.ref.omega = x.omega;
      S.ref.rebound_angle_com = x.rebound_angle_com;
      S.ref.rebound_angle_contact = x.rebound_angle_contact;
      S.have_ref = true;
    } catch (const std::exception&) {  // e.g. overdamped: no closed form
    }
  } else {
    (void)run, (void)law, (void)tlaw;
  }
}

// --scheme: integrate_impact (one run, or the phase average) into run.result / run.obl.r.
template <class Law, class TLaw>
void scheme_with(Run& run, Law& law, TLaw& tlaw) {
  SchemeRun& S = run.sch;
  Oblique& o = run.obl;
  scheme_reference(run, law, tlaw);
  collision::ImpactResult x;
  if (S.phases > 0) {
    S.pa = collision::phase_averaged(law, tlaw, S.scheme, S.setup, S.opt, S.phases, S.ref, true);
    x = S.pa.runs.front();
    x.ended = S.pa.ended == S.phases;
    if (x.ended) {  // the means over the phases
      auto mean = [&](auto get) {
        double s = 0.0;
        for (const auto& q : S.pa.runs) s += get(q);
        return s / S.phases;
      };
      using R = collision::ImpactResult;
      x.e = mean([](const R& q) { return q.e; });
      x.vn = mean([](const R& q) { return q.vn; });
      x.vt = mean([](const R& q) { return q.vt; });
      x.vs = mean([](const R& q) { return q.vs; });
      x.omega1 = mean([](const R& q) { return q.omega1; });
      x.beta = mean([](const R& q) { return q.beta; });
      x.e_t = mean([](const R& q) { return q.e_t; });
      x.rebound_angle_com = mean([](const R& q) { return q.rebound_angle_com; });
      x.rebound_angle_contact = mean([](const R& q) { return q.rebound_angle_contact; });
      x.contact_time = mean([](const R& q) { return q.contact_time; });
      x.dissipated_energy = mean([](const R& q) { return q.dissipated_energy; });
      x.slip_ratio_out = mean([](const R& q) { return q.slip_ratio_out; });
    }
  } else {
    x = collision::integrate_impact(law, tlaw, S.scheme, S.setup, S.opt);
  }
  S.one = x;
  x.kappa = o.opt.kappa;
  if (x.mu > 0.0) {
    x.psi1 = x.kappa * x.slip_ratio_in;
    x.psi2 = x.kappa * x.slip_ratio_out;
  }
  auto& res = run.result;
  res.ended = x.ended;
  res.v0 = x.vn0;
  res.restitution = x.e;
  res.rebound_velocity = x.vn;
  res.contact_time = x.contact_time;
  res.residual_overlap = NAN;
  res.dissipated_energy = x.dissipated_energy;
  res.max_overlap = x.max_overlap;
  res.max_force = x.max_normal_force;
  res.steps = x.contact_steps;
  res.dt = x.dt;
  res.contact_time_estimate = x.contact_time_estimate;
  if (S.phases == 0 && !x.samples.empty()) {
    for (const auto& q : x.samples) res.samples.push_back({q.t, q.xi, q.xi_dot, q.fn});
  }
  if (o.active) {
    o.r = x;
    o.r.residual_overlap = NAN;
    if (x.ended) {
      o.rb = collision::rigid_body_prediction(o.bodies, o.impact, std::min(std::max(x.e, 0.0), 1.0), o.mu, o.beta0);
      o.rb_valid = true;
    }
  }
}

template <class Law, class TLaw>
void oblique_with(Run& run, Law& law, TLaw& tlaw) {
  if (run.sch.active) {
    scheme_with(run, law, tlaw);
    return;
  }
  Oblique& o = run.obl;
  o.r = collision::integrate_oblique(law, tlaw, o.bodies, o.impact, o.opt);
  auto& res = run.result;
  res.ended = o.r.ended;
  res.v0 = o.r.vn0;
  res.restitution = o.r.e;
  res.rebound_velocity = o.r.vn;
  res.contact_time = o.r.contact_time;
  res.residual_overlap = o.r.residual_overlap;
  res.dissipated_energy = o.r.dissipated_energy;
  res.max_overlap = o.r.max_overlap;
  res.max_force = o.r.max_normal_force;
  res.steps = o.r.steps;
  res.dt = o.r.dt;
  res.contact_time_estimate = o.r.contact_time_estimate;
  if (o.r.ended) {
    o.rb = collision::rigid_body_prediction(o.bodies, o.impact, std::min(std::max(o.r.e, 0.0), 1.0), o.mu, o.beta0);
    o.rb_valid = true;
  }
}

template <class Law>
void run_oblique(Run& run, Law& law, const collision::Options& ho) {
  Oblique& o = run.obl;
  o.opt.dt = ho.dt;
  o.opt.record = ho.record;
  const std::string& t = o.tangential;
  const double kn = constant_normal_stiffness(run);
  auto& T = o.tparams;
  double kappa = o.psi_kappa;
  if (t == "none") {
    collision::Frictionless tl;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "cundall_strack") {
    collision::CundallStrackTangential tl;
    double kt = o.kt;
    if (std::isnan(kt)) {
      if (std::isnan(kn))
        throw BadInput("option --kappa needs a normal law with a constant stiffness (lsd, extended_linear, "
                       "walton_braun) for --tangential cundall_strack; give --kt, or use --tangential linear_spring");
      kt = o.kappa * kn;
    }
    tl.p = {kt, o.gammat, o.mu};
    tl.limit = o.limit;
    T = {{"kt", kt}, {"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_rule", "spring"}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kappa) ? kt / kn : o.kappa;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "linear_spring") {
    collision::TangentialKernelLaw<linear_spring::Params<double>, linear_spring::history_size,
                                   &linear_spring::force<double>>
        tl;
    tl.p = {std::isnan(o.kt) ? 0.0 : o.kt, std::isnan(o.kappa) ? 0.0 : o.kappa, o.gammat, o.mu, o.limit, o.reset};
    linear_spring::validate(tl.p);
    T = {{"kt", tl.p.kt}, {"kappa", tl.p.kappa}, {"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_reset", tangential::to_string(o.reset)}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kt) ? o.kappa : tl.p.kappa + tl.p.kt / kn;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "haff_werner") {
    collision::TangentialKernelLaw<haff_werner::Params<double>, haff_werner::history_size, &haff_werner::force<double>>
        tl;
    tl.p = {o.gammat, o.mu, o.limit};
    haff_werner::validate(tl.p);
    T = {{"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "mindlin_no_slip") {
    collision::TangentialKernelLaw<mindlin_no_slip::Params<double>, mindlin_no_slip::history_size,
                                   &mindlin_no_slip::force<double>>
        tl;
    tl.p = {o.gstar, o.eta_ratio, o.mu, o.limit, o.reset};
    mindlin_no_slip::validate(tl.p);
    T = {{"gstar", o.gstar}, {"eta_ratio", o.eta_ratio}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_reset", tangential::to_string(o.reset)}};
    if (std::isnan(kappa) && !std::isnan(o.estar)) kappa = tangential::kappa_hertz_mindlin(o.gstar, o.estar);
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "walton_braun") {
    collision::TangentialKernelLaw<walton_braun_tangential::Params<double>, walton_braun_tangential::history_size,
                                   &walton_braun_tangential::force<double>>
        tl;
    tl.p = {std::isnan(o.kt) ? 0.0 : o.kt, std::isnan(o.kappa) ? 0.0 : o.kappa, o.mu, o.limit};
    walton_braun_tangential::validate(tl.p);
    T = {{"kt0", tl.p.kt}, {"kappa", tl.p.kappa}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kt) ? o.kappa : tl.p.kappa + tl.p.kt / kn;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "mindlin_deresiewicz") {
    collision::TangentialKernelLaw<mindlin_deresiewicz::Params<double>, mindlin_deresiewicz::history_size,
                                   &mindlin_deresiewicz::force<double>>
        tl;
    tl.p = {o.gstar, o.mu, o.limit};
    mindlin_deresiewicz::validate(tl.p);
    T = {{"gstar", o.gstar}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    if (std::isnan(kappa) && !std::isnan(o.estar)) kappa = tangential::kappa_hertz_mindlin(o.gstar, o.estar);
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else {  // di_renzo
    collision::TangentialKernelLaw<di_renzo::Params<double>, di_renzo::history_size, &di_renzo::force<double>> tl;
    tl.p = {o.gstar, o.mu, o.limit};
    di_renzo::validate(tl.p);
    T = {{"gstar", o.gstar}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    if (std::isnan(kappa) && !std::isnan(o.estar)) kappa = tangential::kappa_hertz_mindlin(o.gstar, o.estar);
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  }
}

// ------------------------------------------------ --analytic
constexpr const char* kAnalyticSupports =
    "--analytic supports a sphere-wall (--wall) or two-sphere impact with --law lsd (--k/--gamma, --e with --k "
    "or --tc, either --end) and --tangential none or cundall_strack (--mu, --kt or --kappa, --gammat, "
    "--friction-limit), lever arm radius, no --curve/--steps/--dt";

// Refuses what the closed form cannot do (before the laws read their options).
void analytic_check_start(Args& a, const std::string& law) {
  if (law != "lsd")
    throw BadInput("option --analytic does not support --law " + law + " (" + kAnalyticSupports + ")");
  for (const char* opt : {"--curve", "--steps", "--dt"})
    if (a.has(opt))
      throw BadInput(std::string("option ") + opt + " cannot be used with --analytic (no time stepping; " +
                     kAnalyticSupports + ")");
}

void analytic_check_oblique(Args& a, const Oblique& o) {
  if (o.tangential != "none" && o.tangential != "cundall_strack")
    throw BadInput("option --analytic does not support --tangential " + o.tangential + " (" + kAnalyticSupports +
                   ")");
  if (o.opt.lever != collision::LeverArm::radius)
    throw BadInput(std::string("option --lever-arm contact_point cannot be used with --analytic (") +
                   kAnalyticSupports + ")");
}

// The closed-form impact on a wall or of two spheres (lsd normal law, Cundall-Strack spring with
// or without a dashpot, or frictionless).
void run_analytic(Run& run, const collision::LsdLaw& law, const Bodies& b, double v0) {
  Oblique& o = run.obl;
  namespace an = collision::analytic;
  const bool wall = std::isinf(b.m2);
  an::Input in;
  in.m = b.m1;
  in.R = b.R1 > 0.0 ? b.R1 : 1.0;  // head-on without a radius: the lever arm plays no role
  in.I = 0.0;                      // solid sphere, as the integrator
  if (!wall) {
    in.m2 = b.m2;
    in.R2 = std::isfinite(b.R2) && b.R2 > 0.0 ? b.R2 : 1.0;  // idem
    in.I2 = 0.0;
    in.omega2 = o.active ? o.impact.omega2 : 0.0;
  }
  in.kn = law.c.k;
  in.gn = law.c.gamma;
  in.end = law.end_mode;
  const bool friction = o.tangential == "cundall_strack";
  double kt = NAN;
  double kappa = o.psi_kappa;
  if (friction) {
    kt = std::isnan(o.kt) ? o.kappa * law.c.k : o.kt;
    in.kt = kt;
    in.gt = o.gammat;
    in.rule = cundall_strack::SlipRule::spring_cap;  // as CundallStrackTangential in run_oblique
    in.mu = o.mu;
    in.limit = o.limit;
    o.tparams = {{"kt", kt}, {"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_rule", "spring"}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kappa) ? kt / law.c.k : o.kappa;
  } else {
    in.kt = law.c.k;  // unused without friction (mu = 0)
    in.mu = 0.0;
  }
  in.vn0 = v0;
  in.vt0 = o.active ? o.impact.speed * std::sin(o.impact.angle) : 0.0;
  in.omega0 = o.active ? o.impact.omega1 : 0.0;
  const an::Output x = an::impact(in);
  const an::Normal nrm = an::make_normal(in);
  const double I = an::inertia1(in), I2 = an::inertia2(in);

  // normal closed forms: largest overlap (xi' = 0) and force (F' = 0, or F(0) = gamma v0)
  const double t_xmax = std::atan2(nrm.w, nrm.delta) / nrm.w;
  const double A = (nrm.k - nrm.g * nrm.delta) / nrm.w;
  double t_fmax = std::atan2(nrm.w * A - nrm.delta * nrm.g, nrm.delta * A + nrm.w * nrm.g) / nrm.w;
  t_fmax = std::min(std::max(t_fmax, 0.0), nrm.t_end);
  // sphere 2 at rest before (v2n0 = v2t0 = 0), as in integrate_oblique
  double ke0 = 0.5 * in.m * (in.vn0 * in.vn0 + in.vt0 * in.vt0) + 0.5 * I * in.omega0 * in.omega0;
  double ke1 = 0.5 * in.m * (x.v1n * x.v1n + x.v1t * x.v1t) + 0.5 * I * x.omega * x.omega;
  if (!wall) {
    ke0 += 0.5 * I2 * in.omega2 * in.omega2;
    ke1 += 0.5 * in.m2 * (x.v2n * x.v2n + x.v2t * x.v2t) + 0.5 * I2 * x.omega2 * x.omega2;
  }

  auto& res = run.result;
  res.ended = true;
  res.v0 = v0;
  res.restitution = x.e;
  res.rebound_velocity = x.vn;
  res.contact_time = x.contact_time;
  res.residual_overlap = in.end == ContactEnd::zero_overlap ? 0.0 : nrm.xi(nrm.t_end);
  res.dissipated_energy = ke0 - ke1;
  res.max_overlap = nrm.xi(t_xmax);
  res.max_force = std::max(nrm.fn(0.0), nrm.fn(t_fmax));
  res.steps = 0;
  res.dt = NAN;
  res.contact_time_estimate = x.contact_time;
  if (!o.active) return;

  collision::ObliqueResult& r = o.r;
  r.ended = true;
  r.vn0 = in.vn0;
  r.vt0 = in.vt0;
  r.vs0 = x.vs0;
  r.omega1_0 = in.omega0;
  r.omega2_0 = in.omega2;
  r.impact_angle = std::atan2(r.vt0, r.vn0);
  r.impact_angle_contact = std::atan2(r.vs0, r.vn0);
  r.e = x.e;
  r.vn = x.vn;
  r.vt = x.vt;
  r.vs = x.vs;
  r.omega1 = x.omega;
  r.omega2 = x.omega2;
  r.normal_turn = 0.0;  // the closed form keeps the contact frame fixed
  r.beta = x.beta;
  r.e_t = x.e_t;
  r.rebound_angle_com = x.rebound_angle_com;
  r.rebound_angle_contact = x.rebound_angle_contact;
  r.mu = in.mu;
  r.kappa = kappa;
  if (r.mu > 0.0) {
    r.slip_ratio_in = x.slip_ratio_in;
    r.slip_ratio_out = x.slip_ratio_out;
    r.psi1 = r.kappa * r.slip_ratio_in;
    r.psi2 = r.kappa * r.slip_ratio_out;
  }
  r.contact_time = x.contact_time;
  r.max_overlap = res.max_overlap;
  r.max_normal_force = res.max_force;
  r.max_tangential_force = NAN;  // not evaluated by the closed form
  r.residual_overlap = res.residual_overlap;
  r.dissipated_energy = res.dissipated_energy;
  r.m_n = x.m_n;
  r.m_t = x.m_t;
  r.sliding_at_start = x.sliding_at_start;
  for (const auto& s : x.switches) r.switches.push_back({s.t, s.sliding});
  r.n_switches = static_cast<long>(x.switches.size());
  r.dt = NAN;
  r.steps = 0;
  r.contact_time_estimate = x.contact_time;
  o.rb = collision::rigid_body_prediction(o.bodies, o.impact, std::min(std::max(x.e, 0.0), 1.0), o.mu, o.beta0);
  o.rb_valid = true;
}

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

Run run(Args& a) {
  Run run;
  if (a.flag("--help")) return run;
  a.require("--law", "(lsd, hertz, walton_braun, thornton, continuous_potential, power_law, extended_linear, "
                     "extended_hertz)");
  run.law = a.choice("--law", {"lsd", "hertz", "walton_braun", "thornton", "continuous_potential", "power_law",
                               "extended_linear", "extended_hertz"});
  run.analytic = a.flag("--analytic");
  if (run.analytic) analytic_check_start(a, run.law);
  a.require("--v0", "(impact velocity)");
  const double speed = a.positive("--v0");
  const double angle_deg = a.has("--angle") ? a.number("--angle", 0.0, 90.0, false, true, "[0, 90) degrees") : 0.0;
  // The laws are set up for the normal impact velocity (the normal problem of an oblique impact).
  const double v0 = angle_deg > 0.0 ? speed * std::cos(angle_deg * M_PI / 180.0) : speed;

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
  run.obl = read_oblique(a, b, speed, angle_deg);
  if (a.has("--scheme")) {
    SchemeRun& S = run.sch;
    const std::string name = a.str("--scheme");
    if (!collision::parse_impact_scheme(name, S.scheme))
      throw BadInput("option --scheme = '" + name + "' is not one of: " + collision::impact_scheme_names(", "));
    S.active = true;
    if (run.analytic) throw BadInput("option --scheme cannot be used with --analytic (no time stepping)");
    if (!a.has("--wall"))
      throw BadInput("option --scheme needs --wall (the whole-step integration is a sphere-wall impact)");
    a.require("--R1", "with --scheme (the sphere starts at z = R1 + gap)");
    if (run.obl.opt.lever != collision::LeverArm::radius)
      throw BadInput("option --lever-arm contact_point cannot be used with --scheme (allowed: radius)");
    S.setup.m = b.m1;
    S.setup.R = b.R1;
    S.setup.speed = speed;
    S.setup.angle = angle_deg * M_PI / 180.0;
    S.setup.omega0 = run.obl.active ? run.obl.impact.omega1 : 0.0;
    if (a.has("--gap")) S.setup.gap = a.non_negative("--gap");
    if (a.has("--phases")) {
      const double p = a.number("--phases", 1.0, 10000.0, false, false, "[1, 10000]");
      if (p != std::floor(p)) throw BadInput("option --phases = " + a.str("--phases") + " is not an integer in [1, 10000]");
      S.phases = static_cast<int>(p);
      if (a.has("--curve")) throw BadInput("option --curve cannot be used with --phases (one curve per run)");
    }
    S.opt.dt = opt.dt;
    S.opt.steps_per_contact = a.has("--steps") ? opt.steps_per_contact : 1000;
    S.opt.record = opt.record;
  } else {
    for (const char* o : {"--gap", "--phases"})
      if (a.has(o)) throw BadInput(std::string("option ") + o + " needs --scheme");
  }
  if (run.analytic) analytic_check_oblique(a, run.obl);
  if (run.obl.active && a.has("--steps")) run.obl.opt.steps_per_contact = opt.steps_per_contact;

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
    if (run.analytic) run_analytic(run, law, b, v0);
    else go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
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
    go(run, law, b, v0, opt);
  }
  return run;
}

void write_oblique(Json& j, const Oblique& o) {
  const auto& x = o.r;
  const double deg = 180.0 / M_PI;
  const bool wall = o.bodies.wall();
  j.str("collision", wall ? "oblique_sphere_wall" : "oblique_sphere_sphere");
  j.str("tangential", o.tangential);
  j.open("tangential_parameters");
  for (const auto& p : o.tparams) j.num(p.first, p.second);
  for (const auto& p : o.tchoices) j.str(p.first, p.second);
  j.close();
  j.str("lever_arm", collision::to_string(o.opt.lever));
  j.num("speed", o.speed);
  j.num("angle", o.angle_deg);
  j.num("vn0", x.vn0);
  j.num("vt0", x.vt0);
  j.num("vs0", x.vs0);
  j.num("spin", x.omega1_0);
  if (!wall) j.num("spin2", x.omega2_0);
  j.num("impact_angle_contact", x.impact_angle_contact * deg);
  j.num("m_t", x.m_t);
  // NaN (null) where the impact did not end or the ratio is undefined (no tangential velocity)
  j.num("beta", x.beta);
  j.num("e_t", x.e_t);
  j.num("vn", x.vn);
  j.num("vt", x.vt);
  j.num("vs", x.vs);
  j.num("spin_after", x.omega1);
  if (!wall) j.num("spin2_after", x.omega2);
  j.num("rebound_angle_com", x.rebound_angle_com * deg);
  j.num("rebound_angle_contact", x.rebound_angle_contact * deg);
  j.num("mu", x.mu);
  j.num("kappa", x.kappa);
  j.num("slip_ratio_in", x.slip_ratio_in);
  j.num("slip_ratio_out", x.slip_ratio_out);
  j.num("psi1", x.psi1);
  j.num("psi2", x.psi2);
  j.num("max_tangential_force", x.max_tangential_force);
  if (!wall) j.num("normal_turn", x.normal_turn * deg);
  j.boolean("sliding_at_start", x.sliding_at_start);
  std::string sw = "[";
  for (size_t i = 0; i < x.switches.size(); ++i) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s{\"t\": %.17g, \"to\": \"%s\"}", i ? ", " : "", x.switches[i].t,
                  x.switches[i].sliding ? "slip" : "stick");
    sw += buf;
  }
  sw += "]";
  j.raw("stick_slip_switches", sw);
  j.integer("n_switches", x.n_switches);
  j.open("rigid_body");
  j.num("beta0", o.beta0);
  j.boolean("beta0_assumed", !o.beta0_given);
  if (o.rb_valid) {
    j.num("e", o.rb.vn / x.vn0);
    j.num("mu", x.mu);
    j.boolean("gross_sliding", o.rb.gross_sliding);
    j.num("beta", o.rb.beta);
    j.num("e_t", o.rb.e_t);
    j.num("vt", o.rb.vt);
    j.num("vs", o.rb.vs);
    j.num("spin_after", o.rb.omega1);
    if (!wall) j.num("spin2_after", o.rb.omega2);
    j.num("rebound_angle_com", o.rb.rebound_angle_com * deg);
    j.num("rebound_angle_contact", o.rb.rebound_angle_contact * deg);
    j.num("slip_ratio_gross_sliding", o.rb.psi_slide);
  }
  j.close();
}

void write_scheme(Json& j, const Run& r) {
  const SchemeRun& S = r.sch;
  const double deg = 180.0 / M_PI;
  j.str("scheme", S.scheme.name());
  j.num("gap", S.setup.gap);
  j.integer("evaluations_per_step", S.scheme.evaluations());
  j.integer("history_per_particle", S.scheme.history());
  j.integer("contact_steps", S.one.contact_steps);
  j.integer("total_steps", S.one.steps);
  if (S.phases > 0) {
    j.integer("phases", S.phases);
    std::string es = "[";
    for (size_t i = 0; i < S.pa.runs.size(); ++i) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%s%.17g", i ? ", " : "", S.pa.runs[i].e);
      es += S.pa.runs[i].ended ? buf : (i ? ", null" : "null");
    }
    j.raw("phase_e", es + "]");
  } else {
    j.null("phases");
  }
  if (!S.have_ref) {
    j.null("reference");
    j.null("abs_error");
    return;
  }
  const collision::ImpactResult& x = S.one;
  j.open("reference");
  j.str("method", "analytic");
  j.num("e", S.ref.e);
  j.num("beta", S.ref.beta);
  j.num("e_t", S.ref.e_t);
  j.num("spin_after", S.ref.omega);
  j.num("rebound_angle_com", S.ref.rebound_angle_com * deg);
  j.num("rebound_angle_contact", S.ref.rebound_angle_contact * deg);
  j.close();
  j.open("abs_error");  // mean over the phases with --phases
  if (S.phases > 0) {
    j.num("e", S.pa.e);
    j.num("beta", S.pa.beta);
    j.num("e_t", S.pa.e_t);
    j.num("spin_after", S.pa.omega);
    j.num("rebound_angle_com", S.pa.rebound_angle_com * deg);
    j.num("rebound_angle_contact", S.pa.rebound_angle_contact * deg);
  } else {
    j.num("e", std::fabs(x.e - S.ref.e));
    j.num("beta", std::fabs(x.beta - S.ref.beta));
    j.num("e_t", std::fabs(x.e_t - S.ref.e_t));
    j.num("spin_after", std::fabs(x.omega1 - S.ref.omega));
    j.num("rebound_angle_com", std::fabs(x.rebound_angle_com - S.ref.rebound_angle_com) * deg);
    j.num("rebound_angle_contact", std::fabs(x.rebound_angle_contact - S.ref.rebound_angle_contact) * deg);
  }
  j.close();
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
      if (r.obl.active) {
        std::fputs("t,xi,xi_dot,F,Ft,vs,sliding\n", f);
        for (const auto& s : r.obl.r.samples)
          std::fprintf(f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", s.t, s.xi, s.xi_dot, s.fn, s.ft, s.vs,
                       s.sliding ? 1 : 0);
      } else {
        std::fputs("t,xi,xi_dot,F\n", f);
        for (const auto& s : res.samples) std::fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", s.t, s.xi, s.xi_dot, s.force);
      }
      if (std::fclose(f) != 0) status = 1;
    }
  }
  Json j;
  j.str("law", r.law);
  j.str("method", r.analytic ? "analytic" : "integrated");
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
  if (r.sch.active) write_scheme(j, r);
  if (r.obl.active) write_oblique(j, r.obl);
  std::fputs(j.done().c_str(), stdout);
  if (res.ended && res.steps < 20 && !r.analytic)
    std::fprintf(stderr, "tdem-collide: warning: only %ld steps in the contact; use a smaller --dt or more --steps\n",
                 res.steps);
  if (!res.ended) {
    std::fprintf(stderr, "tdem-collide: the contact did not end within %ld steps (t = %g s)%s\n", res.steps,
                 res.steps * res.dt, res.steps >= collision::Options().max_steps ? "; is --dt too small?" : "");
    return 1;
  }
  return status;
}
