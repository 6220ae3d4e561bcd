// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: fits the coefficients of the tdem normal laws to measured e(v0) (and t_c(v0), peak
// force where given) by weighted least squares over the single-collision solution, and prints
// the coefficients, chi^2 and ready-to-paste input lines for LIGGGHTS and LAMMPS. See docs/fit.md.
// Exit status: 0 success, 1 a fit failed / the JSON file could not be written, 2 bad input (the
// message names the option or the file line, the value and the allowed range).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fit_laws.h"
#include "tabulate.h"
#include "impact_data.h"
#include "nelder_mead.h"

namespace {

using namespace tdem;
using namespace tdem::fitting;

const char* kHelp = R"(tdem-fit: fit the tdem normal laws to measured impact data.

Usage: tdem-fit DATA.csv [--law NAME[,NAME...]|all] [--json FILE] [options]

DATA.csv (docs/fit.md): comment lines '# key: value' with material, source, notes,
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

// ------------------------------------------------------------------ weights and chi^2
struct Weights {
  std::vector<double> e, tc, f;  // per point, 0 where the quantity is missing
  bool from_errors = true;       // every used weight comes from a given error
  int n = 0;                     // number of data values
  std::string note;
};

// w_i = (phi_i / sigma_i)^2 where sigma_i is given; points of a quantity without an error get the
// median relative error of the points that have one (1 if none has).
std::vector<double> quantity_weights(const Context& c, char q, bool relative, double wq, Weights& W,
                                     std::string& note) {
  std::vector<double> w(c.data.points.size(), 0.0), rel;
  auto val = [&](const fitdata::Point& p) { return q == 'e' ? p.e : q == 't' ? p.tc : p.fmax; };
  auto err = [&](const fitdata::Point& p) { return q == 'e' ? p.e_err : q == 't' ? p.tc_err : p.fmax_err; };
  int present = 0;
  for (const auto& p : c.data.points)
    if (std::isfinite(val(p))) {
      ++present;
      if (!relative && std::isfinite(err(p))) rel.push_back(err(p) / val(p));
    }
  if (present == 0) return w;
  const char* qn = q == 'e' ? "e" : q == 't' ? "t_c" : "F_max";
  double fill = 1.0;
  if (rel.empty()) {
    W.from_errors = false;
    note += std::string(qn) + ": relative residuals, weight 1; ";
  } else if (static_cast<int>(rel.size()) < present) {
    fill = 1.0 / std::pow(median(rel), 2);
    note += std::string(qn) + ": 1/sigma^2 (points without an error use the median relative error " +
            num(median(rel)) + "); ";
  } else {
    note += std::string(qn) + ": 1/sigma^2 from the given errors; ";
  }
  for (size_t i = 0; i < c.data.points.size(); ++i) {
    const auto& p = c.data.points[i];
    if (!std::isfinite(val(p))) continue;
    ++W.n;
    w[i] = wq * (std::isfinite(err(p)) && !relative ? std::pow(val(p) / err(p), 2) : fill);
  }
  return w;
}

Weights make_weights(const Context& c, const Options& o) {
  Weights W;
  std::string note;
  W.e = quantity_weights(c, 'e', o.relative, o.w_e, W, note);
  W.tc = quantity_weights(c, 't', o.relative, o.w_tc, W, note);
  W.f = quantity_weights(c, 'f', o.relative, o.w_f, W, note);
  if (!note.empty()) note.erase(note.size() - 2);
  W.note = note;
  return W;
}

struct Residual {
  double chi2 = 0, max_rel = 0;
  std::string max_q;
  int max_line = 0;
};

Residual residuals(const Context& c, const Weights& W, const std::vector<Prediction>& pred) {
  Residual r;
  for (size_t i = 0; i < c.data.points.size(); ++i) {
    const auto& p = c.data.points[i];
    const auto& m = pred[i];
    auto add = [&](double meas, double model, double w, const char* q) {
      if (!std::isfinite(meas)) return;
      const double rel = m.ok && std::isfinite(model) ? (meas - model) / meas : 1e6;
      r.chi2 += w * rel * rel;
      if (std::fabs(rel) > r.max_rel) {
        r.max_rel = std::fabs(rel);
        r.max_q = q;
        r.max_line = p.line;
      }
    };
    add(p.e, m.e, W.e[i], "e");
    add(p.tc, m.tc, W.tc[i], "t_c");
    add(p.fmax, m.fmax, W.f[i], "F_max");
  }
  return r;
}

// ------------------------------------------------------------------ one fit
struct FitResult {
  std::string law, description;
  std::vector<Param> params;
  std::vector<double> x;
  std::vector<Prediction> pred;  // integrated, at the data points
  Residual res;
  int k = 0, n = 0;
  double reduced = NAN, aic = NAN, aicc = NAN;
  bool closed_used = false;
  double closed_check = NAN;  // largest relative difference closed form vs integration at the optimum
  bool tabulated = false;     // integrated predictions from the tables (tabulate.h)
  double table_check = NAN;   // largest relative difference table vs integration at the optimum
  long integrations = 0;      // single collisions integrated (direct and table nodes)
  int evals = 0;
  std::vector<Coef> coefs;
  HostLines hosts;
  std::vector<double> cv, ce, ctc, cf;  // curve
  bool ok = true;
  std::string warning;
};

std::vector<double> to_x(const std::vector<Param>& P, const std::vector<double>& z) {
  std::vector<double> x(z.size());
  for (size_t i = 0; i < z.size(); ++i) x[i] = P[i].log ? std::exp(z[i]) : z[i];
  return x;
}

FitResult fit_one(const FitLaw& law, const Context& c, const Weights& W, const std::string& table) {
  FitResult R;
  R.law = law.name();
  R.description = law.description();
  R.params = law.params();
  const auto& P = R.params;
  const size_t np = P.size();
  std::vector<double> lo(np), hi(np);
  for (size_t i = 0; i < np; ++i) {
    lo[i] = P[i].log ? std::log(P[i].lo) : P[i].lo;
    hi[i] = P[i].log ? std::log(P[i].hi) : P[i].hi;
  }
  const auto& pts = c.data.points;
  auto needs_ok = [&](const Prediction& p, const fitdata::Point& d) {
    return p.ok && (!std::isfinite(d.e) || std::isfinite(p.e)) && (!std::isfinite(d.tc) || std::isfinite(p.tc)) &&
           (!std::isfinite(d.fmax) || std::isfinite(p.fmax));
  };
  auto starts = law.starts();
  // Closed forms cover every measured quantity?
  bool closed = true;
  for (const auto& d : pts) {
    Prediction p;
    try {
      p = law.closed(starts[0], d.v0);
    } catch (const std::exception&) {
      p.ok = false;
    }
    if (!needs_ok(p, d)) closed = false;
  }
  R.tabulated = table == "on" || (table == "auto" && pts.size() > kDirectRows);
  Tabulator tab(law);
  std::vector<double> v0s;
  for (const auto& d : pts) v0s.push_back(d.v0);
  long direct = 0;
  auto one = [&](const std::vector<double>& x, size_t i, bool use_closed) {
    Prediction p;
    try {
      if (!use_closed) ++direct;
      p = use_closed ? law.closed(x, pts[i].v0) : law.simulate(x, pts[i].v0);
    } catch (const std::exception&) {
      p.ok = false;
    }
    return p;
  };
  auto predict = [&](const std::vector<double>& x, bool use_closed) {
    if (!use_closed && R.tabulated) return tab.predict(x, v0s);
    std::vector<Prediction> out(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) out[i] = one(x, i, use_closed);
    return out;
  };
  // rows for the checks against direct integration: all, or kTableCheckRows spread over v0
  std::vector<size_t> check_rows(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) check_rows[i] = i;
  if (R.tabulated && pts.size() > kTableCheckRows) {
    std::sort(check_rows.begin(), check_rows.end(), [&](size_t a, size_t b) { return pts[a].v0 < pts[b].v0; });
    std::vector<size_t> pick;
    for (size_t k = 0; k < kTableCheckRows; ++k) pick.push_back(check_rows[k * (pts.size() - 1) / (kTableCheckRows - 1)]);
    check_rows = pick;
  }
  // largest relative difference of two predictions over the measured quantities of the check rows
  auto difference = [&](const std::vector<Prediction>& a, const std::vector<Prediction>& b) -> double {
    double d = 0;
    for (size_t k = 0; k < check_rows.size(); ++k) {
      const size_t i = check_rows[k];
      if (!b[k].ok) return INFINITY;
      if (!a[k].ok) return INFINITY;
      auto cmp = [&](double x, double y, double meas) {
        if (std::isfinite(meas)) d = std::max(d, std::fabs(x - y) / std::fabs(y));
      };
      cmp(a[k].e, b[k].e, pts[i].e);
      cmp(a[k].tc, b[k].tc, pts[i].tc);
      cmp(a[k].fmax, b[k].fmax, pts[i].fmax);
    }
    return d;
  };
  auto at_check_rows = [&](const std::vector<double>& x, int how) {  // 0 closed, 1 direct, 2 as predict()
    std::vector<Prediction> out;
    std::vector<Prediction> all;
    if (how == 2) all = predict(x, false);
    for (size_t i : check_rows) out.push_back(how == 2 ? all[i] : one(x, i, how == 0));
    return out;
  };
  auto objective = [&](bool use_closed) {
    return [&, use_closed](const std::vector<double>& z) { return residuals(c, W, predict(to_x(P, z), use_closed)).chi2; };
  };
  auto transform = [&](const std::vector<double>& x) {
    std::vector<double> z(np);
    for (size_t i = 0; i < np; ++i) z[i] = P[i].log ? std::log(x[i]) : x[i];
    return z;
  };
  NMOptions nmo;
  NMResult best;
  {
    NelderMead nm(objective(closed), lo, hi, nmo);
    for (const auto& s : starts) {
      auto r = nm.minimise(transform(s));
      if (r.f < best.f) best = r;
    }
    R.evals = nm.evals();
  }
  std::vector<double> x = to_x(P, best.z);
  R.closed_used = closed;
  // Largest relative difference closed form vs integration over the measured quantities.
  auto closed_vs_integrated = [&](const std::vector<double>& xx) -> double {
    return difference(at_check_rows(xx, 0), at_check_rows(xx, 1));
  };
  if (closed) {
    const double d = closed_vs_integrated(x);
    R.closed_check = d;
    if (!(d <= 1e-6)) {  // the closed form is not the integrated law here: refine on the integration
      NelderMead nm(objective(false), lo, hi, nmo);
      auto r = nm.minimise(best.z);
      R.evals += nm.evals();
      best = r;
      x = to_x(P, best.z);
      R.closed_check = closed_vs_integrated(x);
      R.warning = "closed form vs integration " + num(d) + " at the closed-form optimum: refined on the "
                  "integration (" + num(R.closed_check) + " at the final optimum)";
    }
  }
  R.x = x;
  // A parameter on an artificial edge of its search box (not a natural limit such as q = 0 or
  // e = 1): the fit is constrained there.
  for (size_t i = 0; i < np; ++i) {
    const double tol = 1e-6 * (hi[i] - lo[i]);
    const bool at_lo = best.z[i] <= lo[i] + tol && !(!P[i].log && P[i].lo == 0.0);
    const bool at_hi = best.z[i] >= hi[i] - tol && !(!P[i].log && P[i].hi == 1.0);
    if (at_lo || at_hi)
      R.warning += (R.warning.empty() ? "" : "; ") + P[i].name + " = " + num(x[i]) + " is at the " +
                   (at_lo ? "lower" : "upper") + " bound of its search range [" + num(P[i].lo) +
                   ", " + num(P[i].hi) + "]";
  }
  R.pred = predict(x, false);
  if (R.tabulated) {
    R.table_check = difference(at_check_rows(x, 2), at_check_rows(x, 1));
    if (!(R.table_check <= 1e-6))
      R.warning += (R.warning.empty() ? "" : "; ") + std::string("tabulated vs integrated solution ") +
                   num(R.table_check) + " at the optimum (rerun with --table off)";
  }
  R.integrations = direct + tab.integrations();
  R.res = residuals(c, W, R.pred);
  for (size_t i = 0; i < pts.size(); ++i)
    if (!needs_ok(R.pred[i], pts[i])) {
      R.ok = false;
      R.warning += (R.warning.empty() ? "" : "; ") + std::string("the contact did not end at v0 = ") + num(pts[i].v0);
    }
  R.k = static_cast<int>(np);
  R.n = W.n;
  if (R.n > R.k) R.reduced = R.res.chi2 / (R.n - R.k);
  // Akaike: with 1/sigma^2 weights chi^2 is -2 ln L + const; otherwise the Gaussian likelihood with
  // an unknown common scale: N ln(chi^2/N).
  R.aic = (W.from_errors ? R.res.chi2 : R.n * std::log(std::max(R.res.chi2 / R.n, 1e-300))) + 2.0 * R.k;
  if (R.n - R.k - 1 > 0) R.aicc = R.aic + 2.0 * R.k * (R.k + 1.0) / (R.n - R.k - 1.0);
  R.coefs = law.coefficients(x);
  R.hosts = law.hosts(x);
  return R;
}

void add_curve(FitResult& R, const FitLaw& law, const Context& c, int n) {
  if (n <= 0) return;
  const double lo = c.v_lo / 1.5, hi = c.v_hi * 1.5;
  for (int i = 0; i < n; ++i) {
    const double v = n == 1 ? c.v_ref : lo * std::pow(hi / lo, double(i) / (n - 1));
    const auto p = law.simulate(R.x, v);
    R.cv.push_back(v);
    R.ce.push_back(p.ok ? p.e : NAN);
    R.ctc.push_back(p.ok ? p.tc : NAN);
    R.cf.push_back(p.ok ? p.fmax : NAN);
  }
}

// ------------------------------------------------------------------ output
std::string g(double v, int prec = 6) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}

std::string json_str(const std::string& s) {
  std::string o = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') {
      o += '\\';
      o += ch;
    } else if (ch == '\n') {
      o += "\\n";
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", ch);
      o += buf;
    } else {
      o += ch;
    }
  }
  return o + "\"";
}

std::string json_num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string json_array(const std::vector<double>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + json_num(v[i]);
  return s + "]";
}

std::string json_lines(const std::vector<std::string>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ",\n        " : "\n        ") + json_str(v[i]);
  return s + "]";
}

struct Best {
  std::string by_chi2, by_aic;
  std::string criterion;
  std::vector<std::string> near_chi2, near_aic;  // within 1 % of the lowest chi^2 / within 2 of the lowest AIC(c)
};

Best choose(const std::vector<FitResult>& rs) {
  Best b;
  double bc = INFINITY, ba = INFINITY;
  bool all_aicc = true;
  for (const auto& r : rs)
    if (r.ok && !std::isfinite(r.aicc)) all_aicc = false;
  b.criterion = all_aicc ? "AICc" : "AIC";
  for (const auto& r : rs) {
    if (!r.ok) continue;
    if (r.res.chi2 < bc) {
      bc = r.res.chi2;
      b.by_chi2 = r.law;
    }
    const double a = all_aicc ? r.aicc : r.aic;
    if (a < ba) {
      ba = a;
      b.by_aic = r.law;
    }
  }
  for (const auto& r : rs) {
    if (!r.ok) continue;
    if (r.law != b.by_chi2 && r.res.chi2 <= 1.01 * bc) b.near_chi2.push_back(r.law);
    if (r.law != b.by_aic && (all_aicc ? r.aicc : r.aic) < ba + 2.0) b.near_aic.push_back(r.law);
  }
  return b;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

void print_report(const Context& c, const Weights& W, const std::vector<FitResult>& rs, const Best& best,
                  bool quiet) {
  const auto& d = c.data;
  std::printf("tdem-fit: %s\n", d.file == "-" ? "standard input" : d.file.c_str());
  std::printf("material: %s\n", d.material.c_str());
  std::printf("configuration: %s; R1 = %s m, rho = %s kg/m^3, E = %s Pa, nu = %s; partner E2 = %s Pa, nu2 = %s",
              d.wall ? "sphere on a wall" : "two spheres", g(d.R1).c_str(), g(d.rho).c_str(), g(d.E).c_str(),
              g(d.nu).c_str(), std::isinf(d.E2) ? "inf" : g(d.E2).c_str(), g(d.nu2).c_str());
  if (!d.wall) std::printf(", R2 = %s m, rho2 = %s kg/m^3", g(d.R2).c_str(), g(d.rho2).c_str());
  std::printf("\nm* = %s kg, R* = %s m, E* = %s Pa, k~ = %s N/m^1.5\n", g(c.meff).c_str(), g(c.reff).c_str(),
              g(c.estar).c_str(), g(c.khertz).c_str());
  std::printf("data: %d e, %d t_c, %d F_max values at v0 = %s ... %s m/s (median %s); weights: %s\n",
              d.count('e'), d.count('t'), d.count('f'), g(c.v_lo).c_str(), g(c.v_hi).c_str(), g(c.v_ref).c_str(),
              W.note.c_str());
  std::printf("end of contact (lsd, hertz_*, extended_*): %s\n\n", to_string(c.end));
  if (!quiet) {
    for (const auto& r : rs) {
      std::printf("== %s: %s\n", r.law.c_str(), r.description.c_str());
      for (const auto& k : r.coefs)
        std::printf("   %-6s %-8s = %-16s %-14s %s\n", k.fitted ? "fitted" : "fixed", k.name.c_str(),
                    g(k.value, 9).c_str(), ("[" + k.unit + "]").c_str(), k.note.c_str());
      std::printf("   chi2 = %s, reduced chi2 = %s (N = %d, k = %d), max |rel. residual| = %s (%s, line %d), %s = %s\n",
                  g(r.res.chi2).c_str(), g(r.reduced).c_str(), r.n, r.k, g(r.res.max_rel, 3).c_str(),
                  r.res.max_q.c_str(), r.res.max_line, best.criterion.c_str(),
                  g(best.criterion == "AICc" ? r.aicc : r.aic, 5).c_str());
      std::printf("   minimised on the %s (%d evaluations)", r.closed_used ? "closed form" : "integration", r.evals);
      if (r.closed_used) std::printf("; closed form vs integration at the optimum: %s", g(r.closed_check, 2).c_str());
      std::printf("\n");
      std::printf("   %ld single collisions integrated", r.integrations);
      if (r.tabulated)
        std::printf(" (tabulated solutions; table vs integration at %zu rows at the optimum: %s)",
                    std::min(d.points.size(), kTableCheckRows), g(r.table_check, 2).c_str());
      std::printf("\n");
      if (!r.warning.empty()) std::printf("   warning: %s\n", r.warning.c_str());
      std::printf("   v0 [m/s]   e data   e model");
      if (c.has_tc) std::printf("   t_c data    t_c model");
      if (c.has_f) std::printf("  F data      F model");
      std::printf("\n");
      for (size_t i = 0; i < d.points.size(); ++i) {
        const auto& p = d.points[i];
        const auto& m = r.pred[i];
        std::printf("   %-9s  %-7s  %-8s", g(p.v0, 4).c_str(), std::isfinite(p.e) ? g(p.e, 4).c_str() : "-",
                    m.ok ? g(m.e, 4).c_str() : "-");
        if (c.has_tc)
          std::printf("  %-10s  %-10s", std::isfinite(p.tc) ? g(p.tc, 4).c_str() : "-", m.ok ? g(m.tc, 4).c_str() : "-");
        if (c.has_f)
          std::printf("  %-10s  %-10s", std::isfinite(p.fmax) ? g(p.fmax, 4).c_str() : "-",
                      m.ok ? g(m.fmax, 4).c_str() : "-");
        std::printf("\n");
      }
      std::printf("   LIGGGHTS:\n");
      for (const auto& l : r.hosts.liggghts) std::printf("     %s\n", l.c_str());
      std::printf("   LAMMPS:\n");
      for (const auto& l : r.hosts.lammps) std::printf("     %s\n", l.c_str());
      std::printf("\n");
    }
  }
  std::printf("summary (%s):\n", d.material.c_str());
  std::printf("  %-30s %12s %12s %4s %12s %12s\n", "law", "chi2", "red. chi2", "k", "max |res|",
              best.criterion.c_str());
  for (const auto& r : rs)
    std::printf("  %-30s %12s %12s %4d %12s %12s%s\n", r.law.c_str(), g(r.res.chi2, 4).c_str(),
                g(r.reduced, 4).c_str(), r.k, g(r.res.max_rel, 3).c_str(),
                g(best.criterion == "AICc" ? r.aicc : r.aic, 5).c_str(), r.ok ? "" : "  (failed)");
  std::printf("best law (lowest chi2): %s\n", best.by_chi2.c_str());
  if (!best.near_chi2.empty())
    std::printf("  (within 1 %% of its chi2: %s)\n", join(best.near_chi2).c_str());
  std::printf("best law (lowest %s, penalises the number of parameters): %s\n", best.criterion.c_str(),
              best.by_aic.c_str());
  if (!best.near_aic.empty())
    std::printf("  (within 2 of its %s, about as well supported: %s)\n", best.criterion.c_str(),
                join(best.near_aic).c_str());
}

bool write_json(const std::string& path, const Context& c, const Weights& W, const std::vector<FitResult>& rs,
                const Best& best, const Options& o) {
  const auto& d = c.data;
  std::string s = "{\n";
  s += "  \"file\": " + json_str(d.file) + ",\n";
  s += "  \"material\": " + json_str(d.material) + ",\n";
  s += "  \"source\": " + json_str(d.source) + ",\n";
  s += "  \"notes\": " + json_str(d.notes) + ",\n";
  s += "  \"configuration\": " + json_str(d.wall ? "wall" : "pair") + ",\n";
  s += "  \"R1\": " + json_num(d.R1) + ", \"rho\": " + json_num(d.rho) + ", \"E\": " + json_num(d.E) +
       ", \"nu\": " + json_num(d.nu) + ",\n";
  s += "  \"E2\": " + (std::isinf(d.E2) ? std::string("\"inf\"") : json_num(d.E2)) + ", \"nu2\": " + json_num(d.nu2) +
       ", \"R2\": " + (std::isinf(d.R2) ? std::string("\"inf\"") : json_num(d.R2)) +
       ", \"rho2\": " + (std::isinf(d.rho2) ? std::string("\"inf\"") : json_num(d.rho2)) + ",\n";
  s += "  \"m_eff\": " + json_num(c.meff) + ", \"r_eff\": " + json_num(c.reff) + ", \"E_star\": " +
       json_num(c.estar) + ", \"k_hertz\": " + json_num(c.khertz) + ",\n";
  s += "  \"v_ref\": " + json_num(c.v_ref) + ",\n";
  s += "  \"end\": " + json_str(to_string(c.end)) + ",\n";
  s += "  \"weights\": " + json_str(W.note) + ",\n";
  s += "  \"weights_from_errors\": " + std::string(W.from_errors ? "true" : "false") + ",\n";
  s += "  \"steps\": " + std::to_string(o.steps) + ",\n";
  auto col = [&](auto f) {
    std::vector<double> v;
    for (const auto& p : d.points) v.push_back(f(p));
    return json_array(v);
  };
  s += "  \"data\": {\"v0\": " + col([](const auto& p) { return p.v0; }) +
       ", \"e\": " + col([](const auto& p) { return p.e; }) +
       ", \"e_err\": " + col([](const auto& p) { return p.e_err; }) +
       ", \"tc\": " + col([](const auto& p) { return p.tc; }) +
       ", \"tc_err\": " + col([](const auto& p) { return p.tc_err; }) +
       ", \"fmax\": " + col([](const auto& p) { return p.fmax; }) +
       ", \"fmax_err\": " + col([](const auto& p) { return p.fmax_err; }) + "},\n";
  s += "  \"criterion\": " + json_str(best.criterion) + ",\n";
  s += "  \"best_chi2\": " + json_str(best.by_chi2) + ",\n";
  s += "  \"best_aic\": " + json_str(best.by_aic) + ",\n";
  auto str_list = [](const std::vector<std::string>& v) {
    std::string l = "[";
    for (size_t i = 0; i < v.size(); ++i) l += (i ? ", " : "") + json_str(v[i]);
    return l + "]";
  };
  s += "  \"near_best_chi2\": " + str_list(best.near_chi2) + ",\n";
  s += "  \"near_best_aic\": " + str_list(best.near_aic) + ",\n";
  s += "  \"laws\": [";
  for (size_t li = 0; li < rs.size(); ++li) {
    const auto& r = rs[li];
    s += li ? ",\n    {\n" : "\n    {\n";
    s += "      \"law\": " + json_str(r.law) + ",\n";
    s += "      \"description\": " + json_str(r.description) + ",\n";
    s += "      \"ok\": " + std::string(r.ok ? "true" : "false") + ",\n";
    s += "      \"coefficients\": [";
    for (size_t i = 0; i < r.coefs.size(); ++i) {
      const auto& k = r.coefs[i];
      s += (i ? ",\n        " : "\n        ") + std::string("{\"name\": ") + json_str(k.name) +
           ", \"unit\": " + json_str(k.unit) + ", \"value\": " + json_num(k.value) +
           ", \"fitted\": " + (k.fitted ? "true" : "false") + ", \"note\": " + json_str(k.note) + "}";
    }
    s += "],\n";
    s += "      \"chi2\": " + json_num(r.res.chi2) + ", \"reduced_chi2\": " + json_num(r.reduced) +
         ", \"n\": " + std::to_string(r.n) + ", \"k\": " + std::to_string(r.k) + ",\n";
    s += "      \"max_rel_residual\": " + json_num(r.res.max_rel) + ", \"max_rel_residual_quantity\": " +
         json_str(r.res.max_q) + ", \"max_rel_residual_line\": " + std::to_string(r.res.max_line) + ",\n";
    s += "      \"aic\": " + json_num(r.aic) + ", \"aicc\": " + json_num(r.aicc) + ",\n";
    s += "      \"closed_form_used\": " + std::string(r.closed_used ? "true" : "false") +
         ", \"closed_form_check\": " + json_num(r.closed_check) + ", \"evaluations\": " + std::to_string(r.evals) +
         ", \"tabulated\": " + (r.tabulated ? "true" : "false") + ", \"table_check\": " + json_num(r.table_check) +
         ", \"integrations\": " + std::to_string(r.integrations) +
         ",\n";
    s += "      \"warning\": " + json_str(r.warning) + ",\n";
    std::vector<double> pe, pt, pf;
    for (const auto& p : r.pred) {
      pe.push_back(p.ok ? p.e : NAN);
      pt.push_back(p.ok ? p.tc : NAN);
      pf.push_back(p.ok ? p.fmax : NAN);
    }
    s += "      \"model\": {\"e\": " + json_array(pe) + ", \"tc\": " + json_array(pt) + ", \"fmax\": " +
         json_array(pf) + "},\n";
    s += "      \"curve\": {\"v0\": " + json_array(r.cv) + ", \"e\": " + json_array(r.ce) + ", \"tc\": " +
         json_array(r.ctc) + ", \"fmax\": " + json_array(r.cf) + "},\n";
    s += "      \"liggghts\": " + json_lines(r.hosts.liggghts) + ",\n";
    s += "      \"lammps\": " + json_lines(r.hosts.lammps) + "\n";
    s += "    }";
  }
  s += "\n  ]\n}\n";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "tdem-fit: error: cannot write the JSON file '%s': %s\n", path.c_str(), std::strerror(errno));
    return false;
  }
  std::fputs(s.c_str(), f);
  return std::fclose(f) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  Context c;
  try {
    o = parse_args(argc, argv);
    if (o.help) {
      std::fputs(kHelp, stdout);
      return 0;
    }
    const auto data = fitdata::read(o.file);
    for (const std::string& w : data.warnings) std::fprintf(stderr, "tdem-fit: warning: %s\n", w.c_str());
    c = make_context(data, o);
  } catch (const BadInput& e) {
    std::fprintf(stderr, "tdem-fit: error: %s\n", e.what());
    return 2;
  } catch (const fitdata::BadData& e) {
    std::fprintf(stderr, "tdem-fit: error: %s\n", e.what());
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "tdem-fit: error: %s: %s\n", o.file.c_str(), e.what());
    return 2;
  }
  const Weights W = make_weights(c, o);
  std::vector<FitResult> rs;
  int status = 0;
  for (const auto& name : o.laws) {
    const auto law = make_law(name, c);
    try {
      rs.push_back(fit_one(*law, c, W, o.table));
      add_curve(rs.back(), *law, c, o.curve);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tdem-fit: error: law %s: %s\n", name.c_str(), e.what());
      status = 1;
      continue;
    }
    if (!rs.back().ok) status = 1;
  }
  const Best best = choose(rs);
  print_report(c, W, rs, best, o.quiet);
  if (!o.json.empty() && !write_json(o.json, c, W, rs, best, o)) status = 1;
  return status;
}
