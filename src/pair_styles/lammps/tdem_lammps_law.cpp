// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: argument parsing of the normal and tangential laws (pair_coeff, wall fix).
#include "tdem_lammps_law.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include "contact/laws.h"
#include "contact/tangential/parameters.h"
#include "contact/usual_ranges.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;

namespace tdem_lammps {

void law_error(LAMMPS *lmp, const std::string &where, const std::string &what) {
  lmp->error->all(FLERR, where + ": " + what);
  std::abort();  // not reached: error->all does not return
}

namespace {

std::string num(double v) { return tdem::law::number_text(v); }

[[noreturn]] void fail(LAMMPS *lmp, const std::string &where, const std::string &what) { law_error(lmp, where, what); }

// The words that end a law's values in pair_coeff and the wall fix (the laws' own group keywords
// are known to their descriptions).
bool host_keyword(const char *w) {
  static const char *const keywords[] = {"normal", "tangential", "damping", "limit_force", "slip", "grid_correction", "xplane",
                                         "yplane", "zplane", "zcylinder", "wiggle", "shear", "friction_limit",
                                         "rolling", nullptr};
  for (int k = 0; keywords[k]; ++k)
    if (strcmp(w, keywords[k]) == 0) return true;
  return false;
}

// number of value words before the next keyword or the end of the line
int available(int narg, char **arg, int iarg) {
  int n = 0;
  while (iarg + n < narg && !host_keyword(arg[iarg + n])) ++n;
  return n;
}

// a warning (rank 0) for a value outside its usual range (tdem::usual)
void unusual(LAMMPS *lmp, const std::string &where, const std::string &prefix, const std::string &text) {
  if (!text.empty() && lmp->comm->me == 0) lmp->error->warning(FLERR, where + ": " + prefix + text);
}

// The input of law d at arg[iarg] (the word after its name), read by its description
// (src/contact/law_input.h); errors through error->all, a warning for an unusual Poisson ratio.
// r.next is the index of the first argument after the law's words.
tdem::law::Reading read_law(LAMMPS *lmp, const std::string &where, const tdem::law::Description &d, int narg,
                            char **arg, int iarg, const std::string &qualifier = "") {
  namespace law = tdem::law;
  law::Reading r = law::read(d, narg - iarg, arg + iarg, host_keyword, qualifier);
  if (!r.ok()) fail(lmp, where, r.error);
  r.next += iarg;
  for (int k = 0; k < law::value_count(d); ++k) {  // usual ranges (a copied second material once)
    if (law::parameter(d, k).bound != law::Bound::poisson) continue;
    if (d.materials && k == 3 && r.v[3] == r.v[1] && r.v[2] == r.v[0]) continue;
    unusual(lmp, where, law::value_name(d, k) + ": ", tdem::usual::poisson(r.v[k]));
  }
  return r;
}

// Store the values of a unit (src/contact/laws.h) in the type pair's coefficients; derive_law
// derives its kernel parameters.
void store_described(const tdem::law::Description &d, const double *v, LawCoeffs &c) {
  c.mode = MODE_UNIT + tdem::law::index_of<NormalUnits>(&d);
  for (int k = 0; k < tdem::law::value_count(d); ++k) c.uv[k] = v[k];
}

// The coefficients of normal law d from its expanded values (law_input.h).
void store_normal(const tdem::law::Description &d, const double *v, LawCoeffs &c) {
  namespace law = tdem::law;
  if (&d == &tdem::lsd::description) {
    const double *g = law::group_values(d, 0, v);
    if (law::choice_of(d, 0, v) == tdem::lsd::form_stiffness) c.mode = MODE_STIFFNESS_MASS, c.kn = g[0], c.gamman = g[1];
    else c.mode = MODE_RESTITUTION, c.e = g[0], c.tc = g[1];
  } else if (&d == &tdem::hertz::description || &d == &tdem::extended::hertz_description) {
    c.E1 = v[0], c.nu1 = v[1], c.E2 = v[2], c.nu2 = v[3];
    if (&d == &tdem::extended::hertz_description) {
      c.mode = MODE_EXT_HERTZ;
      c.ext = tdem::extended::hertz_fits(v + law::MATERIAL_VALUES);
      return;
    }
    c.mode = MODE_HERTZ;
    c.hdamp = law::choice_of(d, 0, v);
    const double *g = law::group_values(d, 0, v);
    if (c.hdamp == HDAMP_TSUJI) c.he = g[0];
    else if (c.hdamp == HDAMP_GENERAL) c.htheta = g[0], c.hgamma = g[1];
    else c.hgamma = g[0];
  } else if (&d == &tdem::extended::linear_description) {
    c.mode = MODE_EXT_LINEAR;
    c.ext = tdem::extended::linear_params(v);
  } else if (&d == &tdem::continuous_potential::description) {
    c.mode = MODE_CONT_POT;  // EPS N GAMMA, kept with the values of the units
    for (int k = 0; k < law::value_count(d); ++k) c.uv[k] = v[k];
  } else {
    store_described(d, v, c);
  }
}

// "lsd, hertz, walton_braun, ..." (sep ", "): every normal law of the list (src/contact/laws.h).
std::string normal_law_names(const char *sep = ", ") {
  std::string s;
  for (const tdem::law::Description *d : tdem::law::all_normal_laws) s += (s.empty() ? "" : sep) + std::string(d->name);
  return s;
}


// "cundall_strack, haff_werner, ...": every tangential law of the list (src/contact/laws.h).
const std::string TANGENTIAL_LAWS = [] {
  std::string s;
  for (const tdem::law::Description *d : tdem::law::all_tangential_laws) s += (s.empty() ? "" : ", ") + std::string(d->name);
  return s;
}();

// tangential haff_werner | linear_spring | walton_braun | mindlin_deresiewicz | mindlin_no_slip |
// di_renzo with their values, at arg[iarg] (the first value): the laws of the list of
// src/contact/laws.h, read and checked from their Description; returns the next index.
int parse_tangential(LAMMPS *lmp, const std::string &where, const std::string &name, int narg,
                     char **arg, int iarg, LawCoeffs &c) {
  namespace law = tdem::law;
  const law::Description *d = law::find(law::tangential_laws, name.c_str());
  if (!d) fail(lmp, where, "tangential law '" + name + "' is unknown; allowed: " + TANGENTIAL_LAWS);
  const law::Reading r = read_law(lmp, where, *d, narg, arg, iarg);
  const double *v = r.v;
  iarg = r.next;
  const std::string t = "tangential " + name + " ";
  if (d == &tdem::haff_werner::description) {
    c.tlaw = TLAW_HAFF_WERNER;
    c.t_gammat = v[0], c.t_mu = v[1];
  } else if (d == &tdem::linear_spring::description || d == &tdem::walton_braun_tangential::description) {
    const bool lin = d == &tdem::linear_spring::description;
    c.tlaw = lin ? TLAW_LINEAR_SPRING : TLAW_WALTON_BRAUN;
    c.t_kt = v[0], c.t_kappa = v[1];
    if (lin) c.t_gammat = v[2];
    c.t_mu = v[lin ? 3 : 2];
    if (!(c.t_kt > 0.0 || c.t_kappa > 0.0))
      fail(lmp, where, t + "KT = " + num(c.t_kt) + ", KAPPA = " + num(c.t_kappa) +
                           ": the stiffness KT + KAPPA k_n must be > 0 (give KT > 0 or KAPPA > 0)");
  } else {  // the Mindlin-type laws: E1 NU1 E2 NU2 [RATIO] MU
    c.tlaw = d == &tdem::mindlin_no_slip::description ? TLAW_MINDLIN_NO_SLIP
             : d == &tdem::di_renzo::description      ? TLAW_DI_RENZO
                                                      : TLAW_MINDLIN_DERESIEWICZ;
    c.tE1 = v[0], c.tnu1 = v[1], c.tE2 = v[2], c.tnu2 = v[3];
    if (c.tlaw == TLAW_MINDLIN_NO_SLIP) c.t_ratio = v[4];
    c.t_mu = v[law::value_count(*d) - 1];
  }
  unusual(lmp, where, t, tdem::usual::friction(c.t_mu));
  if (c.tlaw == TLAW_LINEAR_SPRING || c.tlaw == TLAW_WALTON_BRAUN)
    unusual(lmp, where, t, tdem::usual::stiffness_ratio(c.t_kappa));
  return iarg;
}
}  // namespace

int parse_law(LAMMPS *lmp, const std::string &where, int narg, char **arg, int iarg,
              bool stop_at_unknown, LawCoeffs &c) {
  namespace law = tdem::law;
  c = LawCoeffs();

  // ---- normal NAME ...: every law of the list, read by its description
  if (iarg >= narg || strcmp(arg[iarg], "normal") != 0)
    fail(lmp, where,
         "expected 'normal " + normal_law_names("|") + " ...' first, got '" +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  if (iarg + 1 >= narg) fail(lmp, where, "keyword 'normal' needs a law name; allowed: " + normal_law_names());
  const law::Description *nd = law::find(law::all_normal_laws, arg[iarg + 1]);
  if (!nd) fail(lmp, where, std::string("normal law '") + arg[iarg + 1] + "' is unknown; allowed: " + normal_law_names());
  const law::Reading nr = read_law(lmp, where, *nd, narg, arg, iarg + 2);
  store_normal(*nd, nr.v, c);
  iarg = nr.next;

  // ---- tangential cundall_strack KT GAMMAT MU (normal lsd stiffness) | KAPPA MU (the others),
  // or another tangential law
  if (iarg >= narg || strcmp(arg[iarg], "tangential") != 0)
    fail(lmp, where,
         std::string("expected 'tangential LAW ...' after the normal law (LAW: ") + TANGENTIAL_LAWS + "), got '" +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  if (iarg + 1 >= narg)
    fail(lmp, where, "keyword 'tangential' needs a law name; allowed: " + TANGENTIAL_LAWS);
  if (strcmp(arg[iarg + 1], "cundall_strack") != 0) {
    iarg = parse_tangential(lmp, where, arg[iarg + 1], narg, arg, iarg + 2, c);
  } else if ((iarg += 2), c.mode != MODE_STIFFNESS_MASS) {
    // a third number: the KT GAMMAT MU form of normal lsd stiffness, given with another law
    if (iarg + 2 < narg && available(narg, arg, iarg) >= 3) {
      char *end = nullptr;
      strtod(arg[iarg + 2], &end);
      if (end != arg[iarg + 2] && *end == '\0')
        fail(lmp, where,
             std::string("tangential cundall_strack takes 2 values (KAPPA MU) with this normal law, but a third "
                         "number '") + arg[iarg + 2] + "' follows '" + arg[iarg] + " " + arg[iarg + 1] +
                 "'; 'KT GAMMAT MU' is the form for 'normal lsd stiffness' only");
    }
    const law::Reading t =
        read_law(lmp, where, tdem::cundall_strack::ratio_description, narg, arg, iarg,
                 std::string(" (with normal ") + (c.mode == MODE_RESTITUTION ? "lsd restitution" : normal_name(c)) + ")");
    c.kappa = t.v[0], c.mu = t.v[1];
    iarg = t.next;
    unusual(lmp, where, "tangential cundall_strack ", tdem::usual::stiffness_ratio(c.kappa));
    unusual(lmp, where, "tangential cundall_strack ", tdem::usual::friction(c.mu));
  } else {
    const law::Reading t = read_law(lmp, where, tdem::cundall_strack::stiffness_description, narg, arg, iarg,
                                    " (with normal lsd stiffness)");
    c.kt = t.v[0], c.gammat = t.v[1], c.mu = t.v[2];
    iarg = t.next;
    unusual(lmp, where, "tangential cundall_strack ", tdem::usual::friction(c.mu));
    if (c.kn > 0.0) unusual(lmp, where, "tangential cundall_strack ", tdem::usual::stiffness_ratio(c.kt / c.kn));
  }

  // ---- options
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "damping") {
      if (iarg + 1 >= narg)
        fail(lmp, where, "keyword 'damping' needs a value; allowed: mass, absolute");
      const std::string v = arg[iarg + 1];
      if (is_unit(c.mode))
        fail(lmp, where, "keyword 'damping " + v + "' applies to 'normal lsd stiffness' only (normal " +
                             normal_name(c) + " has no damping)");
      if (c.mode == MODE_EXT_LINEAR || c.mode == MODE_EXT_HERTZ)
        fail(lmp, where, "keyword 'damping " + v + "' applies to 'normal lsd stiffness' only "
                         "(the extended laws derive their damping from e_fit)");
      if (c.mode == MODE_HERTZ)
        fail(lmp, where,
             "keyword 'damping " + v +
                 "' after the tangential law applies to 'normal lsd stiffness' only; for normal "
                 "hertz write 'damping linear|kuwabara_kono|tsuji|general ...' right after E NU");
      if (c.mode == MODE_RESTITUTION)
        fail(lmp, where,
             "keyword 'damping " + v +
                 "' applies to 'normal lsd stiffness' only (restitution derives the damping)");
      if (v == "mass") c.mode = MODE_STIFFNESS_MASS;
      else if (v == "absolute") c.mode = MODE_STIFFNESS_ABS;
      else fail(lmp, where, "damping '" + v + "' is unknown; allowed: mass, absolute");
      iarg += 2;
    } else if (key == "limit_force") {
      if (iarg + 1 >= narg) fail(lmp, where, "keyword 'limit_force' needs a value; allowed: yes, no");
      const std::string v = arg[iarg + 1];
      if (v == "yes") c.end = 1;
      else if (v == "no") c.end = 0;
      else fail(lmp, where, "limit_force '" + v + "' is unknown; allowed: yes, no");
      iarg += 2;
    } else if (key == "friction_limit") {
      if (iarg + 1 >= narg)
        fail(lmp, where, "keyword 'friction_limit' needs a value; allowed: absolute, positive_normal");
      const std::string v = arg[iarg + 1];
      if (c.tlaw == TLAW_CUNDALL_STRACK)
        fail(lmp, where, "keyword 'friction_limit " + v + "' applies to the tangential laws other than "
                         "cundall_strack (cundall_strack always uses mu |F_n|)");
      if (v == "absolute") c.tlimit = 0;
      else if (v == "positive_normal") c.tlimit = 1;
      else fail(lmp, where, "friction_limit '" + v + "' is unknown; allowed: absolute, positive_normal");
      iarg += 2;
    } else if (key == "rolling") {
      // rolling resistance: rolling sds KR GAMMAR MUR (src/contact/rolling/sds.h)
      if (iarg + 1 >= narg) fail(lmp, where, "keyword 'rolling' needs a model; allowed: sds KR GAMMAR MUR");
      const std::string m = arg[iarg + 1];
      if (m != "sds") fail(lmp, where, "rolling '" + m + "' is unknown; allowed: sds KR GAMMAR MUR");
      const law::Reading r = read_law(lmp, where, tdem::rolling_sds::description, narg, arg, iarg + 2);
      c.rp.kr = r.v[0], c.rp.gammar = r.v[1], c.rp.mur = r.v[2];
      c.roll = 1;
      iarg = r.next;
    } else if (key == "grid_correction") {
      if (iarg + 1 >= narg) fail(lmp, where, "keyword 'grid_correction' needs a value; allowed: on, off");
      const std::string v = arg[iarg + 1];
      if (v == "on") c.gc = 1;
      else if (v == "off") c.gc = 0;
      else fail(lmp, where, "grid_correction '" + v + "' is unknown; allowed: on, off");
      iarg += 2;
    } else if (key == "slip") {
      if (iarg + 1 >= narg)
        fail(lmp, where, "keyword 'slip' needs a value; allowed: spring_dashpot, spring");
      const std::string v = arg[iarg + 1];
      if (v == "spring_dashpot") c.slip = 1;
      else if (v == "spring") c.slip = 0;
      else fail(lmp, where, "slip '" + v + "' is unknown; allowed: spring_dashpot, spring");
      iarg += 2;
    } else if (stop_at_unknown) {
      break;
    } else {
      fail(lmp, where,
           "unexpected argument '" + key +
               "'; allowed options: damping mass|absolute, limit_force yes|no, "
               "slip spring_dashpot|spring, friction_limit absolute|positive_normal, "
               "rolling sds KR GAMMAR MUR, grid_correction on|off");
    }
  }
  derive_law(lmp, where, c);
  return iarg;
}

}  // namespace tdem_lammps
