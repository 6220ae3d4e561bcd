// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/timestep (see fix_tdem_timestep.h and docs/timestep.md).
#include "fix_tdem_timestep.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include "fix_tdem_wall_gran.h"
#include "fix_tdem_integrate.h"
#include "pair_tdem_gran.h"
#include "tdem_lammps_law.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <algorithm>
#include <limits>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace ta = tdem::advice;
namespace th = tdem::advice::host;

namespace {


// The law of a tdem type pair (or wall: reff = sphere radius) as the two functions of a row.
void law_row(const tdem_lammps::LawCoeffs &c, th::Row &r)
{
  using namespace tdem_lammps;
  const double meff = r.meff, reff = r.reff;
  const tdem::ContactEnd end = contact_end(c.end);
  r.law = describe_law(c);
  switch (c.mode) {
    case MODE_STIFFNESS_MASS:
    case MODE_STIFFNESS_ABS: {
      const tdem::lsd::Coefficients<double> k{c.kn, c.mode == MODE_STIFFNESS_MASS ? meff * c.gamman : c.gamman};
      r.advise = [k, end](const ta::Input &in) { return ta::for_linear(k, end, in); };
      break;
    }
    case MODE_RESTITUTION: {
      const tdem::lsd::MassRates<double> m{c.k_per_mass, c.gamma_per_mass};
      r.advise = [m, end](const ta::Input &in) { return ta::for_linear(m, end, in); };
      break;
    }
    case MODE_HERTZ: {
      const tdem::hertz::Params<double> p{tdem::hertz::stiffness(c.estar, reff), c.hgamma, c.htheta};
      const tdem::hertz::Damping d = hertz_damping(c.hdamp);
      r.advise = [p, d, end](const ta::Input &in) { return ta::for_hertz(d, end, p, in); };
      r.stiffness = [p, d, end, meff, reff](double xi, double &k, double &g) {
        const auto res = tdem::hertz::force(d, end, p, tdem::NormalKinematics<double>{xi, 0.0, meff, reff});
        k = res.stiffness, g = res.damping;
        return true;
      };
      break;
    }
    case MODE_CONT_POT: {
      const auto p = tdem::continuous_potential::at_contact(c.uv, r.distance);
      r.advise = [p, end](const ta::Input &in) { return ta::for_continuous_potential(end, p, in); };
      break;
    }
    case MODE_EXT_LINEAR: {
      const tdem::extended::LinearParams p = c.ext;
      r.advise = [p, end](const ta::Input &in) { return ta::for_extended_linear(end, p, in); };
      break;
    }
    case MODE_EXT_HERTZ: {
      const tdem::extended::HertzParams p{tdem::hertz::stiffness(c.estar, reff), c.ext.e_fit, c.ext.range};
      r.advise = [p, end](const ta::Input &in) { return ta::for_extended_hertz(end, p, in); };
      break;
    }
    default:
      if (!is_unit(c.mode)) {
        r.supported = false;
        break;
      }
      tdem::law::visit<NormalUnits>(c.mode - MODE_UNIT, [&](auto tag) {  // a unit (src/contact/laws.h)
        using U = typename decltype(tag)::type;
        const auto p = c.up.get<typename U::Params>();
        r.advise = [p](const ta::Input &in) { return ta::for_law<U>(p, in); };
        r.stiffness = [p, reff](double xi, double &k, double &g) {  // the largest tangent with xi_max = xi
          k = U::stiffness_at(p, reff, xi), g = 0.0;
          return true;
        };
      });
  }
}

// Material of the particle with the smaller Rayleigh time of the two (E, nu known: Hertz-type laws)
ta::Material smaller_rayleigh(const ta::Material &a, const ta::Material &b)
{
  if (!a.given()) return b;
  if (!b.given()) return a;
  try {
    return ta::rayleigh_time(a) <= ta::rayleigh_time(b) ? a : b;
  } catch (const std::exception &) {
    return a;
  }
}

bool has_material(int mode)
{
  using namespace tdem_lammps;
  return mixes_materials(mode);
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMTimestep::FixTDEMTimestep(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg)
{
  try {
    st.opt = th::parse_options(narg, arg, 3);
  } catch (const std::exception &e) {
    error->all(FLERR, fmt::format("fix {} tdem/timestep: {}", id, e.what()));
  }
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, fmt::format("fix {} tdem/timestep requires atom style sphere (radius and rmass)", id));
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;
  nevery = st.opt.every > 0 ? static_cast<int>(st.opt.every) : 1;
}

int FixTDEMTimestep::setmask()
{
  return st.opt.every > 0 ? END_OF_STEP : 0;
}

/* ---------------------------------------------------------------------- */

void FixTDEMTimestep::init()
{
  // the scheme: `scheme`, else the one of a fix tdem/integrate on the group, else nve/sphere
  st.scheme = th::scheme_in_use<FixTDEMIntegrate>(st.opt, modify);
}

/* ---------------------------------------------------------------------- */

/* ---------------------------------------------------------------------- */

void FixTDEMTimestep::build_rows(double v_setup)
{
  st.rows.clear();
  const int nt = atom->ntypes;
  const th::TypeMinima tm = th::type_minima(world, atom, groupbit);
  const std::vector<double> &rmin = tm.r, &rhomin = tm.rho;

  // the pair style
  Pair *pair = force->pair;
  auto *tp = dynamic_cast<PairTDEMGran *>(pair);
  const char *pstyle = force->pair_style ? force->pair_style : "none";
  const bool stock_hooke = pair && (!strcmp(pstyle, "gran/hooke/history") || !strcmp(pstyle, "gran/hooke"));
  const bool stock_hertz = pair && !strcmp(pstyle, "gran/hertz/history");
  double stock[5] = {0, 0, 0, 0, 0};  // kn kt gamman gammat xmu (the pair's restart settings)
  if (stock_hooke || stock_hertz) {
    if (comm->me == 0) {
      char buf[256] = {0};
      FILE *fp = fmemopen(buf, sizeof buf, "w+b");
      if (fp) {
        pair->write_restart_settings(fp);
        fflush(fp);
        memcpy(stock, buf, sizeof stock);
        fclose(fp);
      }
    }
    MPI_Bcast(stock, 5, MPI_DOUBLE, 0, world);
  }
  if (pair && !tp && !stock_hooke && !stock_hertz && comm->me == 0)
    error->warning(FLERR, fmt::format("fix {} tdem/timestep: pair style {} is not supported (supported: tdem/gran, "
                                      "gran/hooke, gran/hooke/history, gran/hertz/history); no advice for its contacts",
                                      id, pstyle));
  if (tp || stock_hooke || stock_hertz) {
    for (int i = 1; i <= nt; i++)
      for (int j = i; j <= nt; j++) {
        if (!tm.present(i) || !tm.present(j)) continue;
        th::Row r = tm.pair_row(i, j);
        if (tp) {
          const tdem_lammps::LawCoeffs &c = tp->law_of(i, j);
          law_row(c, r);
          if (has_material(c.mode))
            r.material = smaller_rayleigh(ta::Material{rmin[i], rhomin[i], c.E1, c.nu1},
                                          ta::Material{rmin[j], rhomin[j], c.E2, c.nu2});
        } else if (stock_hooke) {
          // F = kn xi + m* gamman xi_dot
          const tdem::lsd::Coefficients<double> k{stock[0], r.meff * stock[2]};
          r.law = fmt::format("{} kn {} gamman {}", pstyle, stock[0], stock[2]);
          r.advise = [k](const ta::Input &in) { return ta::for_linear(k, tdem::ContactEnd::zero_overlap, in); };
        } else {
          // F = sqrt(R* xi) (kn xi + m* gamman xi_dot): Hertz k~ = kn sqrt(R*), Kuwabara-Kono
          // damping c = m* gamman sqrt(R*) sqrt(xi)
          const tdem::hertz::Params<double> p{stock[0] * std::sqrt(r.reff), r.meff * stock[2] * std::sqrt(r.reff),
                                              0.0};
          const double meff = r.meff, reff = r.reff;
          r.law = fmt::format("{} kn {} gamman {}", pstyle, stock[0], stock[2]);
          r.advise = [p](const ta::Input &in) {
            ta::Advice a = ta::for_hertz(tdem::hertz::Damping::kuwabara_kono, tdem::ContactEnd::zero_overlap, p, in);
            return a;
          };
          r.stiffness = [p, meff, reff](double xi, double &k, double &g) {
            const auto res = tdem::hertz::force(tdem::hertz::Damping::kuwabara_kono, tdem::ContactEnd::zero_overlap,
                                                p, tdem::NormalKinematics<double>{xi, 0.0, meff, reff});
            k = res.stiffness, g = res.damping;
            return true;
          };
        }
        st.rows.push_back(r);
      }
  }

  // tdem walls (the sphere against an infinitely heavy and large wall: m* = m, R* = R)
  for (int k = 0; k < modify->nfix; k++) {
    auto *w = dynamic_cast<FixTDEMWallGran *>(modify->fix[k]);
    if (!w) {
      if (strstr(modify->fix[k]->style, "wall/gran") && comm->me == 0)
        error->warning(FLERR, fmt::format("fix {} tdem/timestep: fix {} {} is not supported (only tdem/wall/gran); "
                                          "no advice for its contacts",
                                          id, modify->fix[k]->id, modify->fix[k]->style));
      continue;
    }
    const th::TypeMinima wtm = th::type_minima(world, atom, groupbit | w->groupbit);
    const std::vector<double> &wr = wtm.r, &wrho = wtm.rho;
    const tdem_lammps::LawCoeffs &c = w->wall_law();
    for (int t = 1; t <= nt; t++) {
      if (!wtm.present(t)) continue;
      th::Row r = wtm.wall_row(w->id, t);
      law_row(c, r);
      if (has_material(c.mode)) r.material = ta::Material{wr[t], wrho[t], c.E1, c.nu1};
      st.rows.push_back(r);
    }
  }

  th::advise_rows(st.rows, v_setup, st.scheme, update->dt);
  for (const th::Row &r : st.rows)
    if (!r.supported && comm->me == 0)
      error->warning(FLERR, fmt::format("fix {} tdem/timestep: the law of {} ({}) is not supported; no advice",
                                        id, r.what, r.law));
}

/* ---------------------------------------------------------------------- */

void FixTDEMTimestep::setup(int)
{
  const th::SetupSpeed v = th::setup_speed(st.opt, st.opt.vmax_given ? 0.0 : th::largest_speed(world, atom, groupbit));
  build_rows(v.v);
  const th::SetupReport rep = st.setup(update->dt, v, update->ntimestep, where());
  if (comm->me == 0) {
    utils::logmesg(lmp, rep.log);
    for (const std::string &w : rep.warnings) error->warning(FLERR, w);
  }
  if (!rep.stop.empty()) error->all(FLERR, rep.stop);
}

/* ---------------------------------------------------------------------- */

void FixTDEMTimestep::run_check(const char *when)
{
  const th::RuntimeReport rep = st.recheck(
      th::largest_speed(world, atom, groupbit),
      th::largest_overlaps(world, atom, force->pair ? force->pair->list : nullptr, groupbit, NEIGHMASK), atom->ntypes,
      update->dt, when, update->ntimestep, where());
  if (rep.action == th::Action::stop) error->all(FLERR, rep.message);
  if (rep.action == th::Action::warn && comm->me == 0) error->warning(FLERR, rep.message + " (warned once per run)");
}

std::string FixTDEMTimestep::where() const
{
  return std::string("fix ") + id + " tdem/timestep";
}

void FixTDEMTimestep::end_of_step()
{
  run_check("run-time");
}

double FixTDEMTimestep::compute_vector(int n)
{
  if (update->ntimestep != st.last_step) run_check(nullptr);
  return st.vec[n];
}
