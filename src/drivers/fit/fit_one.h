// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: weights, residuals and chi^2, and one fit of one law (Nelder-Mead over its parameters). A part of main.cpp (fit_common.h).
#pragma once

#include "fit_options.h"

namespace {

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

}  // namespace
