// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/timestep (see fix_tdem_timestep.h and docs/timestep.md).
#include "fix_tdem_timestep.h"
#include "fixes/liggghts/style_maps.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "integrators/liggghts/fix_tdem_integrate.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "group.h"
#include "lammps.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair.h"
#include "pair_gran.h"
#include "contact/laws.h"
#include "tdem_liggghts_advice.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace ta = tdem::advice;
namespace th = tdem::advice::host;

namespace {


// The tdem normal laws: lsd, hertz, the units of src/contact/laws.h, then the rest.
const std::vector<std::string>& tdem_laws() {
  static const std::vector<std::string> v = [] {
    std::vector<std::string> m = {"tdem/lsd", "tdem/hertz"};
    for (const tdem::law::Description* d : tdem::law::normal_laws) m.push_back(std::string("tdem/") + d->name);
    for (const char* s : {"tdem/continuous_potential", "tdem/extended_linear", "tdem/extended_hertz"}) m.push_back(s);
    return m;
  }();
  return v;
}

// normal laws pair gran / fix wall/gran may use (for the name in the table and the warnings)
const char* const kStockModels[] = {"hooke", "hooke/stiffness", "hooke/hysteresis", "hertz", "hertz/stiffness",
                                    "thorntonning", "edinburgh", "edinburgh/stiffness", "luding", "off"};

template <class Obj>
std::string model_of(Obj* o) {
  for (const std::string& m : tdem_laws())
    if (o->contact_match("normal", m.c_str())) return m;
  for (const char* m : kStockModels)
    if (o->contact_match("normal", m)) return m;
  return "";
}

using Candidate = std::pair<std::string, std::function<ta::Advice(const ta::Input&)>>;

// The advice of the candidate with the smallest dt_c (the settings the fix cannot see).
ta::Advice smallest(const std::vector<Candidate>& cs, const ta::Input& in) {
  ta::Advice best;
  bool have = false;
  std::string err;
  for (const Candidate& c : cs) {
    try {
      ta::Advice a = c.second(in);
      if (cs.size() > 1) a.law = c.first + " [smallest dt_c of " + std::to_string(cs.size()) + " settings]";
      else a.law = c.first;
      if (!have || a.dt_critical < best.dt_critical) best = a;
      have = true;
    } catch (const std::exception& e) {
      err = e.what();
    }
  }
  if (!have) throw std::domain_error(err.empty() ? "no parameters" : err);
  return best;
}

const tdem::ContactEnd kEnds[2] = {tdem::ContactEnd::zero_overlap, tdem::ContactEnd::zero_force};

std::string tdem_law_list() {
  std::string s;
  for (const std::string& m : tdem_laws()) s += (s.empty() ? "" : ", ") + m;
  return s;
}

// laws whose table rows carry the Rayleigh time of the smaller particle
bool hertz_type(const std::string& model) {
  if (model == "tdem/hertz" || model == "hertz" || model == "tdem/extended_hertz") return true;
  for (const tdem::law::Description* d : tdem::law::normal_laws)  // the units with materials
    if (d->materials && model == std::string("tdem/") + d->name) return true;
  return false;
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMTimestep::FixTDEMTimestep(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg),
      natoms_(0), watch_every_step_(false) {
  try {
    st_.opt = th::parse_options(narg, arg, 3);
  } catch (const std::exception& e) {
    error->all(FLERR, (std::string("fix ") + id + " tdem/timestep: " + e.what()).c_str());
  }
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, (std::string("fix ") + id + " tdem/timestep requires atom style sphere (radius and rmass)").c_str());
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;
  nevery = 1;  // the run-time check keeps its own cadence (every); the lost-atom watch may need each step
}

int FixTDEMTimestep::setmask() { return st_.opt.every > 0 || st_.opt.check != th::CheckMode::off ? END_OF_STEP : 0; }

void FixTDEMTimestep::say(const std::string& s) {
  if (comm->me != 0) return;
  if (screen) fputs(s.c_str(), screen);
  if (logfile) fputs(s.c_str(), logfile);
}

/* ---------------------------------------------------------------------- */

void FixTDEMTimestep::init() { st_.scheme = th::scheme_in_use<FixTDEMIntegrate>(st_.opt, modify); }

/* ---------------------------------------------------------------------- properties */

double FixTDEMTimestep::pair_prop(const char* name, int i, int j, bool& found) {
  const int n = atom->ntypes;
  Fix* f = modify->find_fix_property(name, "property/global", "peratomtypepair", n, n, id, false);
  found = f != nullptr;
  return f ? static_cast<FixPropertyGlobal*>(f)->compute_array(i - 1, j - 1) : 0.0;
}

double FixTDEMTimestep::type_prop(const char* name, int i, bool& found) {
  Fix* f = modify->find_fix_property(name, "property/global", "peratomtype", atom->ntypes, 0, id, false);
  found = f != nullptr;
  return f ? static_cast<FixPropertyGlobal*>(f)->compute_vector(i - 1) : 0.0;
}

double FixTDEMTimestep::scalar_prop(const char* name, bool& found) {
  Fix* f = modify->find_fix_property(name, "property/global", "scalar", 0, 0, id, false);
  found = f != nullptr;
  return f ? static_cast<FixPropertyGlobal*>(f)->compute_scalar() : 0.0;
}

// The row of a tdem normal model from what the model published (tdem_liggghts_advice.h): the law
// and setting in use and the coefficients of the pair exactly as the model forms them.
bool FixTDEMTimestep::published_row(const void* owner, int i, int j, bool wall, th::Row& r) {
  namespace ad = tdem::liggghts::advice;
  const ad::Entry* entry = ad::find(owner);
  if (!entry || !entry->coefficients) return false;
  const ad::Entry e = *entry;  // a copy: the rows outlive no model, but keep them independent
  ad::PairData pd;
  pd.itype = i, pd.jtype = j, pd.wall = wall, pd.meff = r.meff, pd.reff = r.reff, pd.distance = r.distance;
  const std::string name = e.settings.empty() ? e.name : e.name + " (" + e.settings + ")";
  r.law = name;
  r.supported = true;
  const tdem::ContactEnd end = e.end;
  auto coef = [e, pd](const ta::Input& in) {
    ad::PairData d = pd;
    d.meff = in.meff;
    d.reff = in.reff;
    return e.coefficients(d);
  };
  auto named = [name](ta::Advice a) {
    a.law = name + ": " + a.law;
    return a;
  };
  switch (e.law) {
    case ad::Law::lsd:
      r.advise = [coef, end, named](const ta::Input& in) { return named(ta::for_linear(coef(in).lsd, end, in)); };
      break;
    case ad::Law::hertz: {
      const tdem::hertz::Damping dmp = e.damping;
      r.advise = [coef, end, dmp, named](const ta::Input& in) {
        return named(ta::for_hertz(dmp, end, coef(in).hertz, in));
      };
      const tdem::hertz::Params<double> p = coef(ta::Input{r.meff, r.reff}).hertz;
      const double meff = r.meff, reff = r.reff;
      r.stiffness = [p, dmp, end, meff, reff](double xi, double& k, double& c) {
        const auto res = tdem::hertz::force(dmp, end, p, tdem::NormalKinematics<double>{xi, 0.0, meff, reff});
        k = res.stiffness, c = res.damping;
        return true;
      };
      break;
    }
    case ad::Law::continuous_potential: {
      r.advise = [coef, end, named](const ta::Input& in) {
        return named(ta::for_continuous_potential(end, coef(in).potential, in));
      };
      const tdem::continuous_potential::Params<double> p = coef(ta::Input{r.meff, r.reff}).potential;
      r.stiffness = [p](double xi, double& k, double& c) {  // dF/dX at X = d - xi
        const double x = p.d - xi;
        if (!(x > 0.0)) return false;
        k = (p.n + 1.0) * p.n * p.eps * std::pow(p.d / x, p.n) / (x * x), c = p.gamma;
        return true;
      };
      break;
    }
    case ad::Law::extended_linear:
      r.advise = [coef, end, named](const ta::Input& in) {
        return named(ta::for_extended_linear(end, coef(in).extended_linear, in));
      };
      break;
    case ad::Law::extended_hertz:
      r.advise = [coef, end, named](const ta::Input& in) {
        return named(ta::for_extended_hertz(end, coef(in).extended_hertz, in));
      };
      break;
    case ad::Law::unit:
      tdem::law::visit<tdem::law::normal_units>(e.unit, [&](auto tag) {
        using U = typename decltype(tag)::type;
        using P = typename U::Params;
        r.advise = [coef, named](const ta::Input& in) { return named(ta::for_law<U>(coef(in).unit.template get<P>(), in)); };
        const P p = coef(ta::Input{r.meff, r.reff}).unit.template get<P>();
        const double reff = r.reff;
        r.stiffness = [p, reff](double xi, double& k, double& c) {  // the largest tangent with xi_max = xi
          k = U::stiffness_at(p, reff, xi), c = 0.0;
          return true;
        };
      });
      break;
  }
  return true;
}

// The row of a normal law between a particle of type i and a partner of material type j
// (another particle, or the wall's atom type).
void FixTDEMTimestep::law_row(const std::string& model, int i, int j, th::Row& r) {
  const double meff = r.meff, reff = r.reff;
  r.law = model.empty() ? "unknown" : model;
  bool fE1, fE2, fn1, fn2;
  const double E1 = type_prop("youngsModulus", i, fE1), E2 = type_prop("youngsModulus", j, fE2);
  const double n1 = type_prop("poissonsRatio", i, fn1), n2 = type_prop("poissonsRatio", j, fn2);
  const bool have_mat = fE1 && fE2 && fn1 && fn2 && E1 > 0.0 && E2 > 0.0;
  const double ystar = have_mat ? 1.0 / ((1.0 - n1 * n1) / E1 + (1.0 - n2 * n2) / E2) : 0.0;
  bool fe, ftc, fkn, fgn, fga, fv, fdc, fdx;
  const double e = pair_prop("coefficientRestitution", i, j, fe);
  const double tc = pair_prop("contactTime", i, j, ftc);
  const double kn = pair_prop("kn", i, j, fkn) / force->nktv2p;
  const double gn = pair_prop("gamman", i, j, fgn);
  const double ga = pair_prop("gamman_abs", i, j, fga);
  const double vchar = scalar_prop("characteristicVelocity", fv);
  const double dc = pair_prop("dampingCoefficient", i, j, fdc);
  const double dx = pair_prop("dampingExponent", i, j, fdx);
  std::vector<Candidate> cs;

  auto linear = [&](const std::string& name, tdem::lsd::Coefficients<double> k, tdem::ContactEnd end) {
    cs.push_back({name, [k, end](const ta::Input& in) { return ta::for_linear(k, end, in); }});
  };
  auto stiffness_mode = [&](const std::string& base) {
    if (!fkn) return;
    if (fgn) linear(base + " (kn, m* gamman)", {kn, meff * gn}, tdem::ContactEnd::zero_overlap);
    if (fga) linear(base + " (kn, gamman_abs)", {kn, ga}, tdem::ContactEnd::zero_overlap);
  };
  auto material_mode = [&](const std::string& base, bool both_ends) {
    if (!(have_mat && fe && fv)) return;
    const double k = tdem::lsd::stiffness_matching_hertz(ystar, reff, meff, vchar);
    for (int m = 0; m < (both_ends ? 2 : 1); ++m) {
      try {
        linear(base + " (material, " + tdem::to_string(kEnds[m]) + ")",
               tdem::lsd::from_restitution_and_stiffness(e, k, meff, kEnds[m]), kEnds[m]);
      } catch (const std::exception&) {
      }
    }
  };
  // Hertz with damping c xi^Theta, c and Theta given per contact
  auto hertz = [&](const std::string& name, tdem::hertz::Damping d, tdem::ContactEnd end, double damp, double theta) {
    const tdem::hertz::Params<double> p{tdem::hertz::stiffness(ystar, reff), damp, theta};
    cs.push_back({name, [p, d, end](const ta::Input& in) { return ta::for_hertz(d, end, p, in); }});
    if (!r.stiffness || damp > 0.0)  // the largest damping of the candidates (smallest w_c)
      r.stiffness = [p, d, end, meff, reff](double xi, double& k, double& c) {
        const auto res = tdem::hertz::force(d, end, p, tdem::NormalKinematics<double>{xi, 0.0, meff, reff});
        k = res.stiffness, c = res.damping;
        return true;
      };
  };

  if (model == "tdem/lsd") {
    stiffness_mode("tdem/lsd");
    if (fe && ftc)
      for (int m = 0; m < 2; ++m) {
        try {
          const tdem::lsd::MassRates<double> rates = tdem::lsd::rates_from_restitution_and_time(e, tc, kEnds[m]);
          const tdem::ContactEnd end = kEnds[m];
          cs.push_back({std::string("tdem/lsd (restitution, ") + tdem::to_string(end) + ")",
                        [rates, end](const ta::Input& in) { return ta::for_linear(rates, end, in); }});
        } catch (const std::exception&) {
        }
      }
    material_mode("tdem/lsd", true);
  } else if (model == "hooke/stiffness") {
    stiffness_mode("hooke/stiffness");
  } else if (model == "hooke") {
    material_mode("hooke", false);
  } else if (model == "tdem/hertz" && have_mat) {
    if (fe)
      for (int m = 0; m < 2; ++m) {
        try {
          hertz(std::string("tdem/hertz tsuji (") + tdem::to_string(kEnds[m]) + ")", tdem::hertz::Damping::tsuji,
                kEnds[m], tdem::hertz::tsuji_alpha_from_restitution(e, kEnds[m]), 0.0);
        } catch (const std::exception&) {
        }
      }
    if (fdc && fdx) hertz("tdem/hertz general", tdem::hertz::Damping::general, tdem::ContactEnd::zero_overlap, dc, dx);
    if (fdc) {
      hertz("tdem/hertz linear", tdem::hertz::Damping::linear, tdem::ContactEnd::zero_overlap, dc, 0.0);
      hertz("tdem/hertz kuwabara_kono", tdem::hertz::Damping::kuwabara_kono, tdem::ContactEnd::zero_overlap, dc, 0.0);
    }
  } else if (model == "hertz" && have_mat && fe) {
    // LIGGGHTS hertz: F = 4/3 Y* sqrt(R* xi) xi + 2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(R* xi) m*) xi_dot,
    // beta = ln e / sqrt(ln^2 e + pi^2): damping c xi^(1/4), c = 2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(R*) m*)
    const double le = std::log(e);
    const double beta = std::fabs(le) / std::sqrt(le * le + M_PI * M_PI);
    const double c = 2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(2.0 * ystar * std::sqrt(reff) * meff);
    hertz("hertz (stock)", tdem::hertz::Damping::general, tdem::ContactEnd::zero_overlap, c, 0.25);
  }
  if (cs.empty()) {
    r.supported = false;
    if (model == "tdem/lsd" || model == "tdem/hertz" || model == "hooke" || model == "hooke/stiffness" ||
        model == "hertz")
      r.law += " (its properties were not found)";
    return;
  }
  if (cs.size() > 1) {
    r.law += " [settings not visible; candidates:";
    for (const Candidate& c : cs) r.law += " " + c.first + ";";
    r.law += " the smallest dt_c counts]";
  } else {
    r.law = cs[0].first;
  }
  r.advise = [cs](const ta::Input& in) { return smallest(cs, in); };
}

/* ---------------------------------------------------------------------- atoms */

/* ---------------------------------------------------------------------- rows */

void FixTDEMTimestep::build_rows(double v_setup) {
  st_.rows.clear();
  const int nt = atom->ntypes;
  const th::TypeMinima tm = th::type_minima(world, atom, groupbit);
  const std::vector<double> &rmin = tm.r, &rhomin = tm.rho;
  auto material = [&](int t, int mt, double r, double rho) {
    bool fE, fn;
    const double E = type_prop("youngsModulus", mt, fE), nu = type_prop("poissonsRatio", mt, fn);
    (void)t;
    return fE && fn ? ta::Material{r, rho, E, nu} : ta::Material{};
  };
  std::vector<std::string> warnings;

  PairGran* pg = dynamic_cast<PairGran*>(force->pair);
  if (force->pair && !pg)
    warnings.push_back(std::string("pair style ") + force->pair_style +
                       " is not supported (only pair gran); no advice for its contacts");
  if (pg) {
    const std::string model = model_of(pg);
    for (int i = 1; i <= nt; i++)
      for (int j = i; j <= nt; j++) {
        if (!tm.present(i) || !tm.present(j)) continue;
        th::Row r = tm.pair_row(i, j);
        if (!published_row(static_cast<LIGGGHTS::IContactHistorySetup*>(pg), i, j, false, r))
          law_row(model, i, j, r);
        if (hertz_type(model)) {
          const ta::Material a = material(i, i, rmin[i], rhomin[i]), b = material(j, j, rmin[j], rhomin[j]);
          r.material = a;
          if (a.given() && b.given()) {
            try {
              if (ta::rayleigh_time(b) < ta::rayleigh_time(a)) r.material = b;
            } catch (const std::exception&) {
            }
          }
        }
        st_.rows.push_back(r);
      }
  }
  for (int k = 0; k < modify->nfix; k++) {
    FixWallGran* w = dynamic_cast<FixWallGran*>(modify->fix[k]);
    if (!w) continue;
    const th::TypeMinima wtm = th::type_minima(world, atom, groupbit | w->groupbit);
    const std::vector<double> &wr = wtm.r, &wrho = wtm.rho;
    const std::string model = model_of(w);
    const int wt = w->atom_type_wall();
    for (int t = 1; t <= nt; t++) {
      if (!wtm.present(t)) continue;
      th::Row r = wtm.wall_row(w->id, t);
      const int partner = wt >= 1 && wt <= nt ? wt : t;
      if (!published_row(static_cast<LIGGGHTS::IContactHistorySetup*>(w), t, partner, true, r))
        law_row(model, t, partner, r);
      if (hertz_type(model)) r.material = material(t, t, wr[t], wrho[t]);
      st_.rows.push_back(r);
    }
  }
  th::advise_rows(st_.rows, v_setup, st_.scheme, update->dt);
  for (const th::Row& r : st_.rows)
    if (!r.supported)
      warnings.push_back("the law of " + r.what + " (" + r.law +
                         ") is not supported (supported: the tdem normal laws " + tdem_law_list() +
                         ", and hooke, hooke/stiffness, hertz); no advice");
  if (comm->me == 0)
    for (const std::string& w : warnings) error->warning(FLERR, (std::string("fix ") + id + " tdem/timestep: " + w).c_str());
}

/* ---------------------------------------------------------------------- set-up and run */

void FixTDEMTimestep::setup(int) {
  const th::SetupSpeed v = th::setup_speed(st_.opt, st_.opt.vmax_given ? 0.0 : th::largest_speed(world, atom, groupbit));
  build_rows(v.v);
  const th::SetupReport rep = st_.setup(update->dt, v, static_cast<long long>(update->ntimestep), where());
  say(rep.log);
  natoms_ = group->count(igroup);
  watch_every_step_ = st_.opt.check != th::CheckMode::off && !rep.unstable.empty();
  unstable_ = st_.opt.check != th::CheckMode::off ? rep.unstable : std::string();
  if (comm->me == 0)
    for (const std::string& w : rep.warnings) error->warning(FLERR, w.c_str());
  if (!rep.stop.empty()) error->all(FLERR, rep.stop.c_str());
}

void FixTDEMTimestep::lost_check() {
  const bigint n = group->count(igroup);
  if (n >= natoms_) {
    natoms_ = n;  // insertion
    return;
  }
  const std::string msg = std::string("fix ") + id + " tdem/timestep: " + std::to_string(static_cast<long long>(natoms_ - n)) +
                          " of " + std::to_string(static_cast<long long>(natoms_)) + " atoms of the group were lost by step " +
                          std::to_string(static_cast<long long>(update->ntimestep)) +
                          " (LIGGGHTS removes atoms that leave the box without an error)";
  if (watch_every_step_)
    error->all(FLERR, (msg + "; the time step is unstable: " + unstable_).c_str());
  if (comm->me == 0)
    error->warning(FLERR, (msg + "; the time step is within the advice (an open boundary or outflow?)").c_str());
  natoms_ = n;
}

void FixTDEMTimestep::run_check(const char* when) {
  const th::RuntimeReport rep =
      st_.recheck(th::largest_speed(world, atom, groupbit),
                  th::largest_overlaps(world, atom, force->pair ? force->pair->list : nullptr, groupbit, NEIGHMASK),
                  atom->ntypes, update->dt, when, static_cast<long long>(update->ntimestep), where());
  if (rep.action == th::Action::stop) error->all(FLERR, rep.message.c_str());
  if (rep.action == th::Action::warn && comm->me == 0)
    error->warning(FLERR, (rep.message + " (warned once per run)").c_str());
}

std::string FixTDEMTimestep::where() const { return std::string("fix ") + id + " tdem/timestep"; }

void FixTDEMTimestep::end_of_step() {
  const bool periodic = st_.opt.every > 0 && update->ntimestep % st_.opt.every == 0;
  if (st_.opt.check != th::CheckMode::off && (watch_every_step_ || periodic)) lost_check();
  if (periodic) run_check("run-time");
}

double FixTDEMTimestep::compute_vector(int n) {
  if (update->ntimestep != st_.last_step) run_check(nullptr);
  return st_.vec[n];
}

/* ---------------------------------------------------------------------- registration */

void tdem::liggghts::register_timestep_fix(LAMMPS_NS::LAMMPS* lmp) {
  add_fix_style(lmp, "tdem/timestep", &create_fix<FixTDEMTimestep>);
}
