// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the host-independent part of fix tdem/timestep (LAMMPS: src/fixes/timestep/lammps, LIGGGHTS:
// src/fixes/timestep/liggghts): one row per type pair (or wall and type) with the law in use, the
// run-start table, the run-time re-check from the largest particle speed and the largest overlap,
// and the keyword parser of the fix. The hosts only find the laws, the particles and the step.
//
//   fix ID group tdem/timestep [vmax V] [check off|warn|stop] [every N] [fraction F] [scheme NAME]
//
// Each row holds two functions made by the host from the law's parameters:
//   advise(in)        the core's advice (advice::for_linear, for_hertz, ...) for the pair's m*, R*
//                     at the impact velocity in.v_max (src/fixes/timestep/timestep.h)
//   stiffness(xi, k, c) the tangent stiffness dF/dxi and damping dF/dxi' of the law at overlap xi
//                     (false: the law's stiffness does not depend on the overlap, or not known)
// See docs/timestep.md, "fix tdem/timestep".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixes/timestep/timestep.h"

#include <mpi.h>

namespace tdem {
namespace advice {
namespace host {

enum class CheckMode { off, warn, stop };

inline const char* to_string(CheckMode m) {
  return m == CheckMode::off ? "off" : m == CheckMode::warn ? "warn" : "stop";
}

// Keywords of the fix (after "fix ID group tdem/timestep").
struct Options {
  double vmax = 0.0;  // 0: not given (2 x the largest particle speed at set-up)
  bool vmax_given = false;
  CheckMode check = CheckMode::warn;
  long every = 1000;     // run-time check every N steps (0: off)
  double fraction = 0.5; // warn above this fraction of dt_c (Policy::warn_fraction)
  bool scheme_given = false;
  integrators::Scheme scheme = integrators::Scheme::velocity_verlet;
};

// Parse the keywords; a bad one throws std::invalid_argument with a message naming the
// keyword, the value and the allowed values.
inline Options parse_options(int narg, char** arg, int iarg) {
  Options o;
  auto value = [&](int i, const char* kw) -> std::string {
    if (i + 1 >= narg)
      throw std::invalid_argument(std::string("keyword '") + kw + "' needs a value");
    return arg[i + 1];
  };
  auto real = [&](const std::string& s, const char* kw, const char* allowed) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v))
      throw std::invalid_argument(std::string("keyword '") + kw + "' value '" + s +
                                  "' is not a number; allowed: " + allowed);
    return v;
  };
  for (int i = iarg; i < narg; i += 2) {
    const std::string kw = arg[i];
    if (kw == "vmax") {
      const std::string s = value(i, "vmax");
      o.vmax = real(s, "vmax", "a velocity > 0");
      if (!(o.vmax > 0.0))
        throw std::invalid_argument("keyword 'vmax' value " + s + " is outside the allowed range (0, inf)");
      o.vmax_given = true;
    } else if (kw == "check") {
      const std::string s = value(i, "check");
      if (s == "off") o.check = CheckMode::off;
      else if (s == "warn") o.check = CheckMode::warn;
      else if (s == "stop") o.check = CheckMode::stop;
      else throw std::invalid_argument("keyword 'check' value '" + s + "' is not one of off|warn|stop");
    } else if (kw == "every") {
      const std::string s = value(i, "every");
      char* end = nullptr;
      const long n = std::strtol(s.c_str(), &end, 10);
      if (s.empty() || *end != '\0' || n < 0)
        throw std::invalid_argument("keyword 'every' value '" + s +
                                    "' is not allowed; allowed: an integer >= 0 (0: no run-time check)");
      o.every = n;
    } else if (kw == "fraction") {
      const std::string s = value(i, "fraction");
      o.fraction = real(s, "fraction", "a number in (0, 1]");
      if (!(o.fraction > 0.0 && o.fraction <= 1.0))
        throw std::invalid_argument("keyword 'fraction' value " + s +
                                    " is outside the allowed range (0, 1] (warn above this fraction of dt_c)");
    } else if (kw == "scheme") {
      const std::string s = value(i, "scheme");
      if (!integrators::parse_scheme(s, o.scheme))
        throw std::invalid_argument("keyword 'scheme' value '" + s + "' is not one of " +
                                    integrators::scheme_names("|"));
      o.scheme_given = true;
    } else {
      throw std::invalid_argument("unknown keyword '" + kw +
                                  "'; allowed: vmax V, check off|warn|stop, every N, fraction F, scheme NAME");
    }
  }
  return o;
}

inline Policy policy_of(const Options& o) {
  Policy p;
  p.warn_fraction = o.fraction;
  return p;
}

struct Row {
  std::string what;  // "pair 1 2", "wall w1 type 1"
  std::string law;   // law name as the host calls it
  bool supported = true;
  int itype = 0, jtype = 0;  // types (jtype = 0: a wall)
  double meff = 0.0, reff = 0.0;
  double distance = 0.0;  // R_i + R_j of the row's spheres (a wall: R_i), continuous_potential's d
  Material material{};  // radius 0: not known
  std::function<Advice(const Input&)> advise;
  std::function<bool(double xi, double& k, double& c)> stiffness;
  Advice a;              // the set-up advice
  bool advised = false;  // a holds a result
  std::string error;     // why the advice failed
  bool warned = false;   // a warning was issued for this row in this run
  // run-time cache: the advice at the approach velocity cache_v (recomputed when v moves by > 1 %;
  // a damped Hertz-type law integrates its contact time, ~ms)
  double cache_v = -1.0;
  Advice cache_a;
  bool cache_ok = false;
};

inline std::string num(double v) {
  if (std::isnan(v)) return "-";
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

inline std::string squeeze(std::string s) {
  for (char& ch : s)
    if (ch == ' ') ch = '_';
  return s;
}

// The set-up advice of every row.
inline void advise_rows(std::vector<Row>& rows, double v_max, integrators::Scheme s, double dt) {
  for (Row& r : rows) {
    r.advised = false;
    r.warned = false;
    r.error.clear();
    if (!r.supported || !r.advise) continue;
    Input in;
    in.meff = r.meff;
    in.reff = r.reff;
    in.v_max = v_max;
    in.scheme = s;
    in.dt = dt;
    in.material = r.material;
    try {
      r.a = r.advise(in);
      r.advised = true;
    } catch (const std::exception& e) {
      r.error = e.what();
    }
  }
}

// The run-start table (one line per row, whitespace separated; '-' where not known).
inline std::string table(const std::vector<Row>& rows, const std::string& head, const Policy& pol = Policy()) {
  std::string s = head + "\n";
  char b[512];
  std::snprintf(b, sizeof b, "%-18s %-34s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s\n",
                "#what", "law", "m*", "R*", "k_max", "zeta", "dt_critical", "T_Rayleigh", "t_contact",
                "steps/contact", "dt/dt_c", "dt_advised", "verdict");
  s += b;
  for (const Row& r : rows) {
    if (!r.advised) {
      s += squeeze(r.what) + "  " + squeeze(r.law) + "  not advised: " + (r.supported ? r.error : "unsupported law") + "\n";
      continue;
    }
    const Advice& a = r.a;
    const std::string verdict = a.dt > 0.0 ? to_string(check(a, a.dt, pol).verdict) : "-";
    std::snprintf(b, sizeof b, "%-18s %-34s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s %-15s\n",
                  squeeze(r.what).c_str(), squeeze(a.law).c_str(), num(a.meff).c_str(), num(a.reff).c_str(),
                  num(a.stiffness).c_str(), num(a.damping_ratio).c_str(), num(a.dt_critical).c_str(),
                  num(a.rayleigh_time).c_str(), num(a.contact_time).c_str(), num(a.steps_per_contact).c_str(),
                  num(a.fraction_of_critical).c_str(), num(a.dt_advised).c_str(), verdict.c_str());
    s += b;
  }
  return s;
}

// The run-time state: the advice at the largest approach velocity and overlap seen now.
struct Now {
  double dt_critical = INFINITY;
  double steps_per_contact = INFINITY;
  double fraction = 0.0;
  int worst = -1;  // row of the smallest dt_c
  Verdict verdict = Verdict::ok;
  std::string message;
};

// Re-check every row: v_pair = the bound on the approach velocity of a particle pair (2 x the
// largest speed), v_wall = of a particle and a wall (the largest speed), xi(row) = the largest
// overlap of the row's contacts now (0: none). Per row, the advice at that velocity (the core's
// law function) and the linearisation at that overlap (from_stiffness) - the smaller dt_c counts.
inline Now recheck(std::vector<Row>& rows, double v_pair, double v_wall, const std::function<double(const Row&)>& xi,
                   integrators::Scheme s, double dt, const Policy& pol) {
  Now now;
  for (size_t i = 0; i < rows.size(); ++i) {
    Row& r = rows[i];
    if (!r.advised) continue;
    const double v = r.jtype ? v_pair : v_wall;
    Input in;
    in.meff = r.meff;
    in.reff = r.reff;
    in.scheme = s;
    in.dt = dt;
    in.material = r.material;
    Advice best;
    bool have = false;
    if (v > 0.0) {
      in.v_max = v;
      if (!(r.cache_v > 0.0 && std::fabs(v - r.cache_v) <= 0.01 * r.cache_v)) {
        r.cache_v = v;
        try {
          r.cache_a = r.advise(in);
          r.cache_ok = true;
        } catch (const std::exception&) {
          r.cache_ok = false;
        }
      }
      if (r.cache_ok) {
        best = r.cache_a;
        set_step(best, dt);
        have = true;
      }
    }
    const double x = xi(r);
    double k = 0.0, c = 0.0;
    if (x > 0.0 && r.stiffness && r.stiffness(x, k, c) && k > 0.0) {
      in.v_max = v > 0.0 ? v : r.a.v_max;
      try {
        Advice f = from_stiffness(k, c, in);
        f.law = r.a.law + " at overlap " + num(x) + " m";
        if (!have || f.dt_critical < best.dt_critical) {
          if (have && std::isfinite(best.contact_time)) {
            f.contact_time = best.contact_time;  // the law's own contact time at v
            f.contact_time_source = best.contact_time_source;
            set_step(f, dt);
          }
          best = f;
        }
        have = true;
      } catch (const std::exception&) {
      }
    }
    if (!have) continue;
    if (best.dt_critical < now.dt_critical) {
      now.dt_critical = best.dt_critical;
      now.worst = static_cast<int>(i);
    }
    now.steps_per_contact = std::min(now.steps_per_contact, best.steps_per_contact);
    const Check c2 = check(best, dt, pol);
    if (static_cast<int>(c2.verdict) > static_cast<int>(now.verdict) ||
        (now.message.empty() && c2.verdict != Verdict::ok)) {
      now.verdict = c2.verdict;
      now.message = r.what + ": " + c2.message;
    }
  }
  now.fraction = std::isfinite(now.dt_critical) && now.dt_critical > 0.0 ? dt / now.dt_critical : 0.0;
  if (now.dt_critical == 0.0) now.fraction = INFINITY;
  return now;
}

// ---------------------------------------------------------------- set-up and run-time reports
// What both engines' fixes print and decide; `fix` is "fix ID tdem/timestep" (messages start with
// it), the hosts only print the log on rank 0 and pass warnings and stops to their error calls.

// The impact velocity of the set-up advice: vmax, else 2 x the largest particle speed, else 1.
struct SetupSpeed {
  double v = 1.0;
  std::string source;
};
inline SetupSpeed setup_speed(const Options& opt, double largest_speed) {
  if (opt.vmax_given) return {opt.vmax, "vmax"};
  const double v = 2.0 * largest_speed;
  if (v > 0.0) return {v, "2 x the largest particle speed"};
  return {1.0, "no vmax given and every particle at rest: 1 (velocity units)"};
}

struct SetupReport {
  std::string log;                    // head line, table, one summary per advised row
  std::vector<std::string> warnings;  // full messages (check warn, or stop with check warn)
  std::string stop;                   // the error of check stop (empty: none)
  std::string unstable;               // the first row whose check says stop ("what: message")
  double vec[3] = {INFINITY, INFINITY, 0.0};  // dt_c, steps per contact, dt / dt_c at set-up
};
inline SetupReport setup_report(const std::vector<Row>& rows, const Options& opt, integrators::Scheme scheme,
                                double dt, const SetupSpeed& v, const std::string& fix) {
  SetupReport rep;
  const Policy pol = policy_of(opt);
  const std::string head = fix + ": scheme " + integrators::info(scheme).name + ", dt = " + num(dt) +
                           ", v_max = " + num(v.v) + " (" + v.source + "), check " + to_string(opt.check) +
                           ", every " + std::to_string(opt.every) + ", fraction " + num(opt.fraction);
  rep.log = table(rows, head, pol);
  for (const Row& r : rows)
    if (r.advised) {
      rep.log += "  " + r.what + ": " + summary(r.a) + "\n";
      if (r.law.find("candidates") != std::string::npos) rep.log += "    (" + r.law + ")\n";
      rep.vec[0] = std::min(rep.vec[0], r.a.dt_critical);
      rep.vec[1] = std::min(rep.vec[1], r.a.steps_per_contact);
    }
  if (rows.empty()) rep.log += "  (no type pair or wall with a supported law in the group)\n";
  rep.vec[2] = std::isfinite(rep.vec[0]) && rep.vec[0] > 0.0 ? dt / rep.vec[0] : 0.0;
  if (opt.check == CheckMode::off) return rep;
  for (const Row& r : rows) {
    if (!r.advised) continue;
    const Check c = check(r.a, dt, pol);
    if (c.verdict == Verdict::stop && rep.unstable.empty()) rep.unstable = r.what + ": " + c.message;
    if (c.verdict != Verdict::ok && !(c.verdict == Verdict::stop && opt.check == CheckMode::stop))
      rep.warnings.push_back(fix + ": " + r.what + ": " + c.message);
  }
  if (!rep.unstable.empty() && opt.check == CheckMode::stop) rep.stop = fix + " (check stop): " + rep.unstable;
  return rep;
}

// The run-time re-check (recheck) from the largest particle speed and the largest overlap per
// type pair xi[a * (ntypes + 1) + b]; when: "run-time" (act on the verdict) or nullptr (values only).
enum class Action { none, warn, stop };
struct RuntimeReport {
  double vec[3] = {INFINITY, INFINITY, 0.0};
  Action action = Action::none;
  std::string message;
};
inline RuntimeReport runtime_report(std::vector<Row>& rows, double speed, const std::vector<double>& xi, int ntypes,
                                    integrators::Scheme scheme, double dt, const Options& opt, const char* when,
                                    long long step, const std::string& fix) {
  auto row_xi = [&](const Row& r) { return r.jtype ? xi[r.itype * (ntypes + 1) + r.jtype] : 0.0; };
  const Now now = recheck(rows, 2.0 * speed, speed, row_xi, scheme, dt, policy_of(opt));
  RuntimeReport rep;
  rep.vec[0] = now.dt_critical;
  rep.vec[1] = now.steps_per_contact;
  rep.vec[2] = now.fraction;
  if (!when || opt.check == CheckMode::off || now.verdict == Verdict::ok) return rep;
  double xmax = 0.0;
  for (double v : xi) xmax = std::max(xmax, v);
  rep.message = fix + ": " + when + " check at step " + std::to_string(step) + " (largest particle speed " +
                num(speed) + ", approach velocity bound " + num(2.0 * speed) + ", largest pair overlap " + num(xmax) +
                "): " + now.message;
  rep.action = now.verdict == Verdict::stop && opt.check == CheckMode::stop ? Action::stop : Action::warn;
  return rep;
}

// The state of a fix tdem/timestep, the same in both engines: its options, the scheme advised on,
// the rows (built by the host from its laws), the global vector and the once-per-run warning.
struct FixState {
  Options opt;
  integrators::Scheme scheme = integrators::Scheme::velocity_verlet;
  std::vector<Row> rows;
  double vec[3] = {0.0, 0.0, 0.0};  // dt_c, steps per contact, dt / dt_c (intensive)
  bool runtime_warned = false;
  long long last_step = -1;  // step of the values in vec

  // after the rows are built at set-up
  SetupReport setup(double dt, const SetupSpeed& v, long long step, const std::string& fix) {
    SetupReport rep = setup_report(rows, opt, scheme, dt, v, fix);
    std::copy(rep.vec, rep.vec + 3, vec);
    last_step = step;
    runtime_warned = false;
    return rep;
  }
  // the run-time re-check; a warning only once per run (action none after the first)
  RuntimeReport recheck(double speed, const std::vector<double>& xi, int ntypes, double dt, const char* when,
                        long long step, const std::string& fix) {
    RuntimeReport rep = runtime_report(rows, speed, xi, ntypes, scheme, dt, opt, when, step, fix);
    std::copy(rep.vec, rep.vec + 3, vec);
    last_step = step;
    if (rep.action != Action::none) {
      if (rep.action == Action::warn && runtime_warned) rep.action = Action::none;
      runtime_warned = true;
    }
    return rep;
  }
};

// ---------------------------------------------------------------- run-time scans (both engines)
// The smallest mass, radius and density per atom type of the local atoms with all of `bits` set
// in their mask (3 (ntypes + 1) entries: masses, radii, densities, each indexed by type; a type
// without such atoms keeps the largest double), reduce with MPI_MIN.
inline std::vector<double> local_type_minima(const double* rmass, const double* radius, const int* type,
                                             const int* mask, int nlocal, int bits, int ntypes) {
  const std::size_t nt1 = static_cast<std::size_t>(ntypes + 1);
  std::vector<double> loc(3 * nt1, std::numeric_limits<double>::max());
  for (int i = 0; i < nlocal; i++) {
    if ((mask[i] & bits) != bits) continue;
    const std::size_t t = static_cast<std::size_t>(type[i]);
    const double m = rmass[i], r = radius[i];
    if (!(r > 0.0)) continue;
    loc[t] = std::min(loc[t], m);
    loc[nt1 + t] = std::min(loc[nt1 + t], r);
    loc[2 * nt1 + t] = std::min(loc[2 * nt1 + t], m / (4.0 / 3.0 * M_PI * r * r * r));
  }
  return loc;
}

// The smallest mass, radius and density per atom type over all ranks (type_minima below).
struct TypeMinima {
  std::vector<double> m, r, rho;
  // Does type t have atoms of the group?
  bool present(int t) const {
    return m[t] < std::numeric_limits<double>::max() && r[t] < std::numeric_limits<double>::max();
  }
  // The row of type pair i, j (m* and R* of their smallest spheres).
  Row pair_row(int i, int j) const {
    Row w;
    w.what = "pair " + std::to_string(i) + " " + std::to_string(j);
    w.itype = i, w.jtype = j;
    w.meff = hertz::effective_mass(m[i], m[j]);
    w.reff = hertz::effective_radius(r[i], r[j]);
    w.distance = r[i] + r[j];
    return w;
  }
  // The row of type t against wall `wall` (a flat wall: the sphere's mass and radius).
  Row wall_row(const std::string& wall, int t) const {
    Row w;
    w.what = "wall " + wall + " type " + std::to_string(t);
    w.itype = t, w.jtype = 0;
    w.meff = m[t];
    w.reff = r[t];
    w.distance = r[t];
    return w;
  }
};

// The largest squared speed of the local atoms of the group (reduce with MPI_MAX, then sqrt).
inline double local_largest_speed2(double* const* v, const int* mask, int nlocal, int groupbit) {
  double v2 = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) v2 = std::max(v2, v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
  return v2;
}

// The largest overlap per type pair (index a * (ntypes + 1) + b, a <= b) among the pairs of a
// half or full neighbour list (LAMMPS/LIGGGHTS NeighList) whose atoms are both in the group; loc has
// (ntypes + 1)^2 entries, reduce with MPI_MAX.
template <class List>
void local_largest_overlaps(const List* list, double* const* x, const double* rad, const int* type,
                            const int* mask, int groupbit, int ntypes, int neighmask, std::vector<double>& loc) {
  loc.assign(static_cast<std::size_t>((ntypes + 1) * (ntypes + 1)), 0.0);
  if (!list || list->inum <= 0 || !list->ilist) return;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int* jl = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jl[jj] & neighmask;
      if (!(mask[j] & groupbit)) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double ov = rad[i] + rad[j] - std::sqrt(dx * dx + dy * dy + dz * dz);
      if (ov <= 0.0) continue;
      const int a = std::min(type[i], type[j]), b = std::max(type[i], type[j]);
      double& m = loc[static_cast<std::size_t>(a * (ntypes + 1) + b)];
      m = std::max(m, ov);
    }
  }
}

// The same over all ranks of `world`, for an engine's Atom (rmass, radius, type, mask, v, x, nlocal,
// ntypes): the smallest mass, radius and density per type of the atoms with all of `bits` set, the
// largest speed of the group, the largest overlap per type pair of a neighbour list's pairs.
template <class AtomT>
TypeMinima type_minima(MPI_Comm world, const AtomT* atom, int bits) {
  const int nt = atom->ntypes;
  const std::vector<double> loc =
      local_type_minima(atom->rmass, atom->radius, atom->type, atom->mask, atom->nlocal, bits, nt);
  std::vector<double> all(loc.size());
  MPI_Allreduce(loc.data(), all.data(), static_cast<int>(loc.size()), MPI_DOUBLE, MPI_MIN, world);
  TypeMinima tm;
  tm.m.assign(all.begin(), all.begin() + nt + 1);
  tm.r.assign(all.begin() + nt + 1, all.begin() + 2 * (nt + 1));
  tm.rho.assign(all.begin() + 2 * (nt + 1), all.end());
  return tm;
}
template <class AtomT>
double largest_speed(MPI_Comm world, const AtomT* atom, int groupbit) {
  const double v2 = local_largest_speed2(atom->v, atom->mask, atom->nlocal, groupbit);
  double all = 0.0;
  MPI_Allreduce(&v2, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return std::sqrt(all);
}
template <class AtomT, class List>
std::vector<double> largest_overlaps(MPI_Comm world, const AtomT* atom, const List* list, int groupbit, int neighmask) {
  std::vector<double> loc;
  local_largest_overlaps(list, atom->x, atom->radius, atom->type, atom->mask, groupbit, atom->ntypes, neighmask, loc);
  std::vector<double> xi(loc.size(), 0.0);
  MPI_Allreduce(loc.data(), xi.data(), static_cast<int>(loc.size()), MPI_DOUBLE, MPI_MAX, world);
  return xi;
}

// The scheme the advice is for: `scheme`, else the one of the first fix tdem/integrate (class
// Integrate, with scheme_in_use()), else velocity_verlet (nve/sphere).
template <class Integrate, class ModifyT>
integrators::Scheme scheme_in_use(const Options& opt, const ModifyT* modify) {
  if (opt.scheme_given) return opt.scheme;
  for (int i = 0; i < modify->nfix; i++) {
    const auto* f = modify->fix[i];
    if (std::strcmp(f->style, "tdem/integrate") != 0) continue;
    if (const auto* fi = dynamic_cast<const Integrate*>(f)) return fi->scheme_in_use();
  }
  return integrators::Scheme::velocity_verlet;
}

}  // namespace host
}  // namespace advice
}  // namespace tdem
