// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the --help text, the options and their checks, and the fitting context from the data. A part of main.cpp (fit_common.h).
#pragma once

#include "fit_common.h"

namespace {

const char* kHelp = R"(tdem-fit: fit the tdem normal laws to measured impact data.

Usage: tdem-fit DATA.csv [--law NAME[,NAME...]|all] [--json FILE] [options]

DATA.csv (docs/tools/tdem-fit.md): comment lines '# key: value' with material, source, notes,
configuration (wall|pair), R1 [m], rho [kg/m^3], E [Pa], nu, E2, nu2 (partner or wall
material; E2 may be inf), R2, rho2 (pair only); then a header line and rows with the columns
v0,e and optionally e_err,tc,tc_err,fmax,fmax_err (SI units; empty cells allowed).
DATA.csv = - reads standard input. UTF-8 (with or without a byte-order mark), LF or CRLF line ends.

Laws (--law, default all):
  lsd                           e, t_c constant (k from Hertz matching at the median v0 if no t_c data)
  hertz_linear                  Hertz + gamma xi'                       (gamma)
  hertz_kuwabara_kono           Hertz + gamma~ xi^1/2 xi'               (gamma~)
  hertz_tsuji                   Hertz + alpha sqrt(m* k~) xi^1/4 xi'    (alpha)
  hertz_general                 Hertz + c xi^Theta xi'                  (c, Theta)
  walton_braun_constant         constant k_ul                           (k_ul; k_l if t_c data)
  walton_braun_force_dependent  k_ul = k_l + s F_max                    (s; k_l if t_c data)
  thornton                      elastic-perfectly plastic               (p_y)
  power_law                     p = 1.5, a_l = Hertz k~                 (a_ul, q)
  extended_linear               rational e(v0); power t_c(v0) if t_c data, else Hertz t_c
  extended_hertz                Hertz spring, rational e(v0)
)";
// then the units (fit_laws.h: unit_help), then
const char* kHelpOptions = R"(
Options:
  --json FILE         write all results (and the curves of --curve) as JSON to FILE
  --steps N           RK4 steps per estimated contact time, 100 ... 1e6 (default 2000)
  --end zero_force|zero_overlap   end of contact of lsd, hertz_*, extended_* (default zero_force:
                      no attraction; printed as limitForce on / limit_force yes)
  --weights auto|relative   auto (default): 1/sigma^2 weights where the data give errors;
                      relative: every point weight 1 on its relative residual
  --w-e W, --w-tc W, --w-fmax W   extra weight of each quantity (default 1)
  --curve N           also evaluate every fitted law at N impact velocities (JSON only)
  --kappa K           tangentialStiffnessRatio / KAPPA printed in the input lines
                      (default 2(1-nu)/(2-nu); not fitted)
  --mu MU             friction coefficient printed in the input lines (default 0.5; not fitted)
  --table auto|on|off tabulated single-collision solutions (default auto: on above 64 rows): the
                      integrated predictions come from tables of the dimensionless solution (or
                      of v0 at fixed parameters), checked against direct integration at 24 rows
  --quiet             print only the summary table
  --help              this text

chi^2 = sum_q w_q sum_i w_i ((phi_i - model_i)/phi_i)^2 with w_i = (phi_i/sigma_i)^2 where the
error sigma_i is given (then chi^2 is the usual sum of ((phi - model)/sigma)^2), else 1.
Exit status 0 ok, 1 a fit failed or FILE could not be written, 2 bad input.
)";

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  std::string file, json;
  std::vector<std::string> laws;
  int steps = 2000;
  ContactEnd end = ContactEnd::zero_force;
  bool relative = false;
  double w_e = 1, w_tc = 1, w_f = 1;
  int curve = 0;
  double kappa = NAN, mu = 0.5;
  bool quiet = false;
  bool help = false;
  std::string table = "auto";  // auto | on | off: tabulated single-collision solutions (tabulate.h)
};

// Up to this many data rows the fit integrates one collision per row (as the tables would cost
// about as much); above it the integrated predictions come from the tables (--table auto).
constexpr size_t kDirectRows = 64;
// The tables are checked against direct integration at this many data rows (spread over v0).
constexpr size_t kTableCheckRows = 24;

double parse_num(const std::string& opt, const std::string& s, double lo, double hi, const char* range) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || std::isnan(v))
    throw BadInput("option " + opt + ": '" + s + "' is not a number (allowed: " + range + ")");
  if (!(v >= lo && v <= hi) || !std::isfinite(v))
    throw BadInput("option " + opt + " = " + s + " is outside the allowed range " + range);
  return v;
}

// an integer option: a number in [lo, hi] without a fractional part
int parse_int(const std::string& opt, const std::string& s, double lo, double hi, const char* range) {
  const double v = parse_num(opt, s, lo, hi, range);
  if (v != std::floor(v)) throw BadInput("option " + opt + " = " + s + " is not an integer (allowed: " + range + ")");
  return static_cast<int>(v);
}

Options parse_args(int argc, char** argv) {
  Options o;
  std::set<std::string> given;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
      return o;
    }
    if (a == "--quiet") {
      o.quiet = true;
      continue;
    }
    if (a.rfind("--", 0) != 0) {
      if (!o.file.empty()) throw BadInput("more than one data file given ('" + o.file + "', '" + a + "')");
      o.file = a;
      continue;
    }
    static const std::set<std::string> known = {"--law", "--json", "--steps", "--end", "--weights", "--w-e",
                                                "--w-tc", "--w-fmax", "--curve", "--kappa", "--mu", "--table"};
    if (!known.count(a)) throw BadInput("unknown option '" + a + "' (see --help)");
    if (given.count(a)) throw BadInput("option " + a + " is given twice");
    given.insert(a);
    if (i + 1 >= argc) throw BadInput("option " + a + " needs a value");
    const std::string v = argv[++i];
    if (a == "--law") {
      std::stringstream ss(v);
      std::string item;
      while (std::getline(ss, item, ',')) {
        if (item == "all") {
          for (const auto& n : law_names()) o.laws.push_back(n);
          continue;
        }
        if (std::find(law_names().begin(), law_names().end(), item) == law_names().end()) {
          std::string list;
          for (const auto& n : law_names()) list += ", " + n;
          throw BadInput("option --law = '" + item + "' is not one of: all" + list);
        }
        o.laws.push_back(item);
      }
      if (o.laws.empty()) throw BadInput("option --law: no law given");
    } else if (a == "--json") {
      o.json = v;
    } else if (a == "--steps") {
      o.steps = parse_int(a, v, 100, 1e6, "an integer in [100, 1e6]");
    } else if (a == "--end") {
      if (v == "zero_force") o.end = ContactEnd::zero_force;
      else if (v == "zero_overlap") o.end = ContactEnd::zero_overlap;
      else throw BadInput("option --end = '" + v + "' is not one of: zero_force, zero_overlap");
    } else if (a == "--weights") {
      if (v == "auto") o.relative = false;
      else if (v == "relative") o.relative = true;
      else throw BadInput("option --weights = '" + v + "' is not one of: auto, relative");
    } else if (a == "--w-e") {
      o.w_e = parse_num(a, v, 0, 1e12, "[0, 1e12]");
    } else if (a == "--w-tc") {
      o.w_tc = parse_num(a, v, 0, 1e12, "[0, 1e12]");
    } else if (a == "--w-fmax") {
      o.w_f = parse_num(a, v, 0, 1e12, "[0, 1e12]");
    } else if (a == "--curve") {
      o.curve = parse_int(a, v, 0, 10000, "an integer in [0, 10000]");
    } else if (a == "--kappa") {
      // KAPPA of the printed input lines: LAMMPS cundall_strack needs it > 0
      o.kappa = parse_num(a, v, 0, 1e6, "(0, 1e6]");
      if (!(o.kappa > 0.0)) throw BadInput("option --kappa = " + v + " is outside the allowed range (0, 1e6]");
    } else if (a == "--mu") {
      o.mu = parse_num(a, v, 0, 1e6, "[0, 1e6]");
    } else if (a == "--table") {
      if (v != "auto" && v != "on" && v != "off")
        throw BadInput("option --table = '" + v + "' is not one of: auto, on, off");
      o.table = v;
    }
  }
  if (o.file.empty()) throw BadInput("no data file given (usage: tdem-fit DATA.csv [options]; see --help)");
  if (o.laws.empty()) o.laws = law_names();
  // remove duplicates, keep order
  std::vector<std::string> u;
  for (const auto& n : o.laws)
    if (std::find(u.begin(), u.end(), n) == u.end()) u.push_back(n);
  o.laws = u;
  return o;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Context make_context(const fitdata::Data& d, const Options& o) {
  Context c;
  c.data = d;
  c.bodies.R1 = d.R1;
  c.bodies.m1 = collision::sphere_mass(d.R1, d.rho);
  if (!d.wall) {
    c.bodies.R2 = d.R2;
    c.bodies.m2 = collision::sphere_mass(d.R2, d.rho2);
  }
  c.meff = c.bodies.meff();
  c.reff = c.bodies.reff();
  c.estar = hertz::effective_modulus(d.E, d.nu, d.E2, d.nu2);
  c.khertz = hertz::stiffness(c.estar, c.reff);
  std::vector<double> v, e, tc;
  for (const auto& p : d.points) {
    v.push_back(p.v0);
    if (std::isfinite(p.e)) e.push_back(p.e);
    if (std::isfinite(p.tc)) tc.push_back(p.tc);
    if (std::isfinite(p.fmax)) c.has_f = true;
  }
  c.v_ref = median(v);
  c.v_lo = *std::min_element(v.begin(), v.end());
  c.v_hi = *std::max_element(v.begin(), v.end());
  c.e_med = median(e);
  c.has_tc = !tc.empty();
  if (c.has_tc) c.tc_med = median(tc);
  c.end = o.end;
  c.steps = o.steps;
  c.kappa = std::isfinite(o.kappa) ? o.kappa : 2.0 * (1.0 - d.nu) / (2.0 - d.nu);
  c.mu = o.mu;
  // The clamp of the extended laws (defaults 1e-3, 1e3 m/s) is widened to the measured range.
  c.range.v_min = std::min(c.range.v_min, c.v_lo);
  c.range.v_max = std::max(c.range.v_max, c.v_hi);
  return c;
}

}  // namespace
