// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: bounded Nelder-Mead simplex minimiser.
//
// Minimises f(z) over the box lo <= z <= hi (the caller works in transformed coordinates, e.g.
// z = ln p for a positive parameter). Standard reflection / expansion / contraction / shrink
// (coefficients 1, 2, 1/2, 1/2); every trial point is projected onto the box. Stops when the
// spread of f over the simplex is below ftol (absolute or relative) and the simplex is smaller
// than xtol in every coordinate, or after max_evals evaluations. minimise() restarts from the
// best point with a fresh simplex until a restart no longer improves f (the usual cure for a
// simplex that collapsed early).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace tdem {
namespace fitting {

struct NMOptions {
  double ftol = 1e-15;         // on the spread of f over the simplex (absolute or relative)
  double xtol = 1e-10;         // on the simplex size in every coordinate
  int max_evals = 4000;        // per simplex run
  int max_restarts = 6;        // fresh simplices from the best point
  double initial_step = 0.1;   // initial simplex edge, as a fraction of (hi - lo) (capped at 1)
};

struct NMResult {
  std::vector<double> z;
  double f = std::numeric_limits<double>::infinity();
  int evals = 0;
  int restarts = 0;
};

class NelderMead {
 public:
  using Fn = std::function<double(const std::vector<double>&)>;
  NelderMead(Fn f, std::vector<double> lo, std::vector<double> hi, NMOptions o = NMOptions())
      : f_(std::move(f)), lo_(std::move(lo)), hi_(std::move(hi)), o_(o) {}

  NMResult minimise(std::vector<double> z0) {
    project(z0);
    NMResult best;
    best.z = z0;
    best.f = eval(z0);
    double step = o_.initial_step;
    for (int r = 0; r <= o_.max_restarts; ++r) {
      NMResult run = one_run(best.z, step);
      const bool improved = run.f < best.f - std::max(1e-14 * std::fabs(best.f), 1e-300);
      if (run.f <= best.f) {
        best.z = run.z;
        best.f = run.f;
      }
      best.restarts = r;
      if (!improved && r > 0) break;
      step = std::max(step * 0.5, 1e-4);
    }
    best.evals = evals_;
    return best;
  }

  int evals() const { return evals_; }

 private:
  Fn f_;
  std::vector<double> lo_, hi_;
  NMOptions o_;
  int evals_ = 0;

  void project(std::vector<double>& z) const {
    for (size_t i = 0; i < z.size(); ++i) z[i] = std::min(std::max(z[i], lo_[i]), hi_[i]);
  }
  double eval(std::vector<double>& z) {
    project(z);
    ++evals_;
    const double v = f_(z);
    return std::isfinite(v) ? v : std::numeric_limits<double>::max();
  }

  NMResult one_run(const std::vector<double>& start, double frac) {
    const size_t n = start.size();
    std::vector<std::vector<double>> s(n + 1, start);
    std::vector<double> fs(n + 1);
    for (size_t i = 0; i < n; ++i) {
      const double width = hi_[i] - lo_[i];
      double h = std::min(frac * width, 1.0);
      if (!(h > 0)) h = 0.1;
      // step away from the nearer bound so that the simplex does not start flat
      if (start[i] + h > hi_[i]) h = -h;
      s[i + 1][i] += h;
    }
    for (size_t i = 0; i <= n; ++i) fs[i] = eval(s[i]);
    const int limit = evals_ + o_.max_evals;
    std::vector<size_t> idx(n + 1);
    while (evals_ < limit) {
      for (size_t i = 0; i <= n; ++i) idx[i] = i;
      std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return fs[a] < fs[b]; });
      const size_t ib = idx[0], iw = idx[n], isw = idx[n > 0 ? n - 1 : 0];
      // convergence
      const double spread = fs[iw] - fs[ib];
      double size = 0.0;
      for (size_t i = 0; i <= n; ++i)
        for (size_t j = 0; j < n; ++j) size = std::max(size, std::fabs(s[i][j] - s[ib][j]));
      if ((spread <= o_.ftol * std::fabs(fs[ib]) || spread <= 1e-300 || fs[ib] <= 1e-300) && size <= o_.xtol) break;
      if (size <= 1e-14) break;
      // centroid of all but the worst
      std::vector<double> c(n, 0.0);
      for (size_t i = 0; i <= n; ++i)
        if (i != iw)
          for (size_t j = 0; j < n; ++j) c[j] += s[i][j] / n;
      auto along = [&](double t) {
        std::vector<double> z(n);
        for (size_t j = 0; j < n; ++j) z[j] = c[j] + t * (s[iw][j] - c[j]);
        return z;
      };
      std::vector<double> zr = along(-1.0);
      const double fr = eval(zr);
      if (fr < fs[ib]) {
        std::vector<double> ze = along(-2.0);
        const double fe = eval(ze);
        if (fe < fr) { s[iw] = ze; fs[iw] = fe; } else { s[iw] = zr; fs[iw] = fr; }
        continue;
      }
      if (fr < fs[isw]) {
        s[iw] = zr;
        fs[iw] = fr;
        continue;
      }
      const bool outside = fr < fs[iw];
      std::vector<double> zc = along(outside ? -0.5 : 0.5);
      const double fc = eval(zc);
      if (fc < (outside ? fr : fs[iw])) {
        s[iw] = zc;
        fs[iw] = fc;
        continue;
      }
      for (size_t i = 0; i <= n; ++i) {  // shrink towards the best
        if (i == ib) continue;
        for (size_t j = 0; j < n; ++j) s[i][j] = s[ib][j] + 0.5 * (s[i][j] - s[ib][j]);
        fs[i] = eval(s[i]);
      }
    }
    size_t ib = 0;
    for (size_t i = 1; i <= n; ++i)
      if (fs[i] < fs[ib]) ib = i;
    NMResult r;
    r.z = s[ib];
    r.f = fs[ib];
    return r;
  }
};

}  // namespace fitting
}  // namespace tdem
