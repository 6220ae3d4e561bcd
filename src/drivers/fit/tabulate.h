// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: tabulated single-collision solutions, so that a fit to 10^4 impacts does not integrate
// one collision per data row and minimiser step.
//
// Two tables, both on uniform grids in a logarithmic variable u with cubic Lagrange interpolation
// (nodes are integrated on first use and kept):
//   * Similarity table. Where a law's collision is one member of a family of dimensionless
//     solutions (FitLaw::similar: Hertz with damping c xi^Theta xi' in xi* = (m* v0^2/k~)^(2/5),
//     t* = xi*/v0 depends only on D = c xi*^(Theta+1)/(m* v0) and Theta; Thornton's only on v0/v_y),
//     the table is over u = ln q (and the key Theta, interpolated across its own grid for the
//     general damping) and serves every parameter vector of the fit.
//   * Velocity table. Otherwise, for one parameter vector, over u = ln v0 (used for the integrated
//     predictions of the laws that are minimised on closed forms).
// Grid step h = 1/64 in u (and in Theta): the cubic's error is ~ h^4/24 f'''' ~ 1e-8 f''''. The
// driver checks the table against direct integration at a sample of the data and reports it.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>
#include <vector>

#include "fit_laws.h"

namespace tdem {
namespace fitting {

inline constexpr double kTableStep = 1.0 / 64.0;

// Cubic Lagrange weights at t in [0, 1) of the cell between nodes 1 and 2 of the stencil 0..3.
inline void cubic_weights(double t, double w[4]) {
  w[0] = -t * (t - 1.0) * (t - 2.0) / 6.0;
  w[1] = (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0;
  w[2] = -(t + 1.0) * t * (t - 2.0) / 2.0;
  w[3] = (t + 1.0) * t * (t - 1.0) / 6.0;
}

// First node of the 4-point stencil for u in cell i (between nodes i and i+1). A kink at node 0
// (kink = true) is never inside a stencil: cells next to it take one-sided stencils.
inline long stencil_start(long i, bool kink) {
  if (kink && i == 0) return 0;
  if (kink && i == -1) return -3;
  return i - 1;
}

// Nodes f(i, j) = the scaled prediction at u = i h and key = j h (key_grid) or the exact key,
// each integrated once.
class LazyGrid {
 public:
  using Eval = std::function<Prediction(double u, double key)>;
  LazyGrid(Eval f, bool key_grid) : f_(std::move(f)), key_grid_(key_grid) {}

  const Prediction& node(long i, long j, double exact_key) {
    const long long id = (static_cast<long long>(j) << 32) ^ static_cast<long long>(i & 0xffffffffL);
    auto it = cache_.find(id);
    if (it != cache_.end() && (key_grid_ || it->second.key == exact_key)) return it->second.p;
    ++evaluations_;
    Entry& e = cache_[id];
    e.key = exact_key;
    e.p = f_(i * kTableStep, key_grid_ ? j * kTableStep : exact_key);
    return e.p;
  }
  // The node values at u = i h, i = lo .. hi, at the key (cubic across the key grid).
  std::vector<Prediction> column(long lo, long hi, double key) {
    std::vector<Prediction> col(static_cast<size_t>(hi - lo + 1));
    double wk[4] = {1.0, 0.0, 0.0, 0.0};
    long j0 = 0;
    int nk = 1;
    if (key_grid_) {
      const double sk = key / kTableStep;
      j0 = std::max(0L, static_cast<long>(std::floor(sk)) - 1);  // the key (Theta) starts at 0
      cubic_weights(sk - (j0 + 1), wk);
      nk = 4;
    }
    for (long i = lo; i <= hi; ++i) {
      Prediction out;
      out.ok = true;
      out.e = out.tc = out.fmax = 0.0;
      for (int b = 0; b < nk && out.ok; ++b) {
        const Prediction& p = node(i, j0 + b, key);
        if (!p.ok) out = Prediction();
        else {
          out.e += wk[b] * p.e;
          out.tc += wk[b] * p.tc;
          out.fmax += wk[b] * p.fmax;
        }
      }
      col[static_cast<size_t>(i - lo)] = out;
    }
    return col;
  }
  long evaluations() const { return evaluations_; }

 private:
  struct Entry {
    Prediction p;
    double key = NAN;
  };
  Eval f_;
  bool key_grid_;
  std::unordered_map<long long, Entry> cache_;
  long evaluations_ = 0;
};

// Cubic interpolation at the points u[k] (mask[k]) from the values at u = i h of a grid, the
// nodes integrated through `grid`; a kink at u = 0 stays out of every stencil.
inline void interpolate(LazyGrid& grid, double key, bool kink, const std::vector<double>& u,
                        const std::vector<char>& mask, std::vector<Prediction>& out) {
  long lo = 0, hi = -1;
  for (size_t k = 0; k < u.size(); ++k) {
    if (!mask[k]) continue;
    const long i0 = stencil_start(static_cast<long>(std::floor(u[k] / kTableStep)), kink);
    if (hi < lo) lo = i0, hi = i0 + 3;
    lo = std::min(lo, i0);
    hi = std::max(hi, i0 + 3);
  }
  if (hi < lo) return;
  const std::vector<Prediction> col = grid.column(lo, hi, key);
  for (size_t k = 0; k < u.size(); ++k) {
    if (!mask[k]) continue;
    const double s = u[k] / kTableStep;
    const long i0 = stencil_start(static_cast<long>(std::floor(s)), kink);
    double w[4];
    cubic_weights(s - (i0 + 1), w);
    Prediction p;
    p.ok = true;
    p.e = p.tc = p.fmax = 0.0;
    for (int a = 0; a < 4 && p.ok; ++a) {
      const Prediction& n = col[static_cast<size_t>(i0 + a - lo)];
      if (!n.ok) p = Prediction();
      else {
        p.e += w[a] * n.e;
        p.tc += w[a] * n.tc;
        p.fmax += w[a] * n.fmax;
      }
    }
    out[k] = p;
  }
}

// The integrated predictions of a law at the data velocities, from the tables.
class Tabulator {
 public:
  explicit Tabulator(const FitLaw& law)
      : law_(law), similar_([this](double u, double key) { return law_.node(std::exp(u), key); },
                            law.key_continuous()) {}

  std::vector<Prediction> predict(const std::vector<double>& x, const std::vector<double>& v0) {
    const size_t n = v0.size();
    std::vector<Prediction> out(n);
    std::vector<double> u(n, 0.0), ts(n, 1.0), fs(n, 1.0), uv(n, 0.0);
    std::vector<char> sim(n, 0), rest(n, 0);
    double key = NAN;
    for (size_t k = 0; k < n; ++k) {
      Similar s;
      if (law_.similar(x, v0[k], s) && s.q > 0.0 && std::isfinite(s.q) && (std::isnan(key) || s.key == key)) {
        key = s.key;
        sim[k] = 1;
        u[k] = std::log(s.q);
        ts[k] = s.t_scale;
        fs[k] = s.f_scale;
      } else {
        rest[k] = 1;
        uv[k] = std::log(v0[k]);
      }
    }
    interpolate(similar_, key, law_.kink_at_one(), u, sim, out);
    for (size_t k = 0; k < n; ++k)
      if (sim[k] && out[k].ok) {
        out[k].tc *= ts[k];
        out[k].fmax *= fs[k];
      }
    if (std::find(rest.begin(), rest.end(), 1) != rest.end()) {
      LazyGrid velocity([&](double uu, double) { return law_.simulate(x, std::exp(uu)); }, false);
      interpolate(velocity, 0.0, false, uv, rest, out);
      velocity_evaluations_ += velocity.evaluations();
    }
    return out;
  }

  long integrations() const { return similar_.evaluations() + velocity_evaluations_; }

 private:
  const FitLaw& law_;
  LazyGrid similar_;
  long velocity_evaluations_ = 0;
};

}  // namespace fitting
}  // namespace tdem
