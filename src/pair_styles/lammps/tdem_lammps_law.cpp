// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: argument parsing of the normal and tangential laws (pair_coeff, wall fix).
#include "tdem_lammps_law.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include "contact/laws.h"
#include "contact/tangential/parameters.h"
#include "contact/usual_ranges.h"

#include <cerrno>
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

double number(LAMMPS *lmp, const std::string &where, const std::string &keyword, const char *text) {
  char *end = nullptr;
  errno = 0;
  const double v = strtod(text, &end);
  if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    fail(lmp, where, keyword + " expects a finite number, got '" + text + "'");
  return v;
}

void need(LAMMPS *lmp, const std::string &where, const std::string &what, const std::string &names,
          int have, int want) {
  if (have < want)
    fail(lmp, where,
         what + " needs " + std::to_string(want) + " value" + (want == 1 ? "" : "s") + " (" +
             names + "), got " + std::to_string(have < 0 ? 0 : have));
}

// number of value words before the next keyword or the end of the line
int available(int narg, char **arg, int iarg) {
  static const char *const keywords[] = {"normal", "tangential", "damping", "limit_force",
                                         "slip", "xplane", "yplane", "zplane", "zcylinder",
                                         "wiggle", "shear", "e_fit", "tc_fit", "v_min",
                                         "v_max", "friction_limit", "rolling", nullptr};
  int n = 0;
  for (; iarg + n < narg; ++n) {
    for (int k = 0; keywords[k]; ++k)
      if (strcmp(arg[iarg + n], keywords[k]) == 0) return n;
  }
  return n;
}

// a warning (rank 0) for a value outside its usual range (tdem::usual)
void unusual(LAMMPS *lmp, const std::string &where, const std::string &prefix, const std::string &text) {
  if (!text.empty() && lmp->comm->me == 0) lmp->error->warning(FLERR, where + ": " + prefix + text);
}

void positive(LAMMPS *lmp, const std::string &where, const std::string &name, double v) {
  if (!(v > 0.0)) fail(lmp, where, name + " = " + num(v) + " must be > 0");
}
void non_negative(LAMMPS *lmp, const std::string &where, const std::string &name, double v) {
  if (!(v >= 0.0)) fail(lmp, where, name + " = " + num(v) + " must be >= 0");
}

double poisson(LAMMPS *lmp, const std::string &where, const std::string &name, const char *text) {
  const double nu = number(lmp, where, name, text);
  if (!tdem::checks::poisson_ok(nu))
    fail(lmp, where, name + " = " + num(nu) + " is outside the allowed range (-1, 0.5]");
  unusual(lmp, where, name + ": ", tdem::usual::poisson(nu));
  return nu;
}

// The material pair `E NU [E2 NU2]` of normal LAW at arg[iarg] (n = 2 or 4 values) into c.E1 ..
// c.nu2; `before` names what follows in the count message ("" or " before e_fit").
int parse_materials(LAMMPS *lmp, const std::string &where, const std::string &law, int narg, char **arg, int iarg,
                    const char *before, LawCoeffs &c) {
  const int n = available(narg, arg, iarg);
  if (n != 2 && n != 4)
    fail(lmp, where,
         "normal " + law + " needs 2 values (E NU: both partners of one material) or 4 values (E1 NU1 E2 NU2)" +
             before + ", got " + std::to_string(n));
  const std::string w = "normal " + law + " ";
  c.E1 = number(lmp, where, w + "E", arg[iarg]);
  positive(lmp, where, w + "E (Young's modulus)", c.E1);
  c.nu1 = poisson(lmp, where, w + "NU (Poisson ratio)", arg[iarg + 1]);
  if (n == 4) {
    c.E2 = number(lmp, where, w + "E2", arg[iarg + 2]);
    positive(lmp, where, w + "E2 (Young's modulus)", c.E2);
    c.nu2 = poisson(lmp, where, w + "NU2 (Poisson ratio)", arg[iarg + 3]);
  } else {
    c.E2 = c.E1;
    c.nu2 = c.nu1;
  }
  return iarg + n;
}

// normal hertz E NU [E2 NU2] [damping linear GAMMA | kuwabara_kono GAMMA | tsuji E |
//                             general THETA C]
int parse_hertz(LAMMPS *lmp, const std::string &where, int narg, char **arg, int iarg,
                LawCoeffs &c) {
  c.mode = MODE_HERTZ;
  iarg = parse_materials(lmp, where, "hertz", narg, arg, iarg, "", c);
  c.hdamp = HDAMP_LINEAR;
  c.hgamma = 0.0;
  if (iarg < narg && strcmp(arg[iarg], "damping") == 0) {
    if (iarg + 1 >= narg)
      fail(lmp, where,
           "normal hertz damping needs a member; allowed: linear GAMMA, kuwabara_kono GAMMA, "
           "tsuji E, general THETA C");
    const std::string d = arg[iarg + 1];
    iarg += 2;
    const int have = available(narg, arg, iarg);
    if (d == "linear" || d == "kuwabara_kono") {
      need(lmp, where, "normal hertz damping " + d, "GAMMA", have, 1);
      if (have > 1)
        fail(lmp, where, "normal hertz damping " + d + " takes 1 value (GAMMA), got " +
                             std::to_string(have));
      c.hdamp = d == "linear" ? HDAMP_LINEAR : HDAMP_KK;
      c.hgamma = number(lmp, where, "normal hertz damping " + d + " GAMMA", arg[iarg]);
      non_negative(lmp, where, "normal hertz damping " + d + " GAMMA", c.hgamma);
      iarg += 1;
    } else if (d == "tsuji") {
      need(lmp, where, "normal hertz damping tsuji", "E (restitution)", have, 1);
      if (have > 1)
        fail(lmp, where, "normal hertz damping tsuji takes 1 value (E), got " +
                             std::to_string(have));
      c.hdamp = HDAMP_TSUJI;
      c.he = number(lmp, where, "normal hertz damping tsuji E", arg[iarg]);
      if (!tdem::checks::restitution_ok(c.he))
        fail(lmp, where,
             "normal hertz damping tsuji E = " + num(c.he) + " is outside the allowed range (0, 1]");
      iarg += 1;
    } else if (d == "general") {
      need(lmp, where, "normal hertz damping general", "THETA C", have, 2);
      if (have > 2)
        fail(lmp, where, "normal hertz damping general takes 2 values (THETA C), got " +
                             std::to_string(have));
      c.hdamp = HDAMP_GENERAL;
      c.htheta = number(lmp, where, "normal hertz damping general THETA", arg[iarg]);
      c.hgamma = number(lmp, where, "normal hertz damping general C", arg[iarg + 1]);
      non_negative(lmp, where, "normal hertz damping general THETA", c.htheta);
      non_negative(lmp, where, "normal hertz damping general C", c.hgamma);
      iarg += 2;
    } else {
      fail(lmp, where,
           "normal hertz damping '" + d +
               "' is unknown; allowed: linear GAMMA, kuwabara_kono GAMMA, tsuji E, general THETA C");
    }
  }
  return iarg;
}


std::string coefficient_names(int n) {
  return n == 1 ? "C0" : n == 2 ? "C0 C1" : "C0 C1 C2";
}

// e_fit FORM C0 [C1 [C2]] or tc_fit FORM C0 [C1] at arg[iarg] (the keyword); what = 'e' | 't'
int parse_fit(LAMMPS *lmp, const std::string &where, const std::string &law, int narg, char **arg,
              int iarg, char what, tdem::fits::Fit &fit) {
  const std::string key = arg[iarg];
  const char *allowed = what == 'e' ? "constant C0, rational C0 C1 C2, power C0 C1"
                                    : "constant C0, power C0 C1";
  if (iarg + 1 >= narg)
    fail(lmp, where, "normal " + law + " " + key + " needs a form; allowed: " + allowed);
  const std::string form = arg[iarg + 1];
  if (!tdem::fits::parse(form, fit.form) || (what == 't' && fit.form == tdem::fits::Form::rational))
    fail(lmp, where, "normal " + law + " " + key + " form '" + form + "' is unknown; allowed: " +
                         allowed);
  iarg += 2;
  const int want = tdem::fits::coefficient_count(fit.form, what);
  const int have = available(narg, arg, iarg);
  if (have != want)
    fail(lmp, where,
         "normal " + law + " " + key + " " + form + " needs " + std::to_string(want) + " value" +
             (want == 1 ? "" : "s") + " (" + coefficient_names(want) + "), got " +
             std::to_string(have));
  for (int k = 0; k < want; ++k)
    fit.c[k] = number(lmp, where, "normal " + law + " " + key + " " + form + " C" + std::to_string(k),
                      arg[iarg + k]);
  try {
    if (what == 'e') tdem::fits::validate_restitution(fit);
    else tdem::fits::validate_contact_time(fit);
  } catch (const std::exception &ex) {
    std::string vals;
    for (int k = 0; k < want; ++k)
      vals += std::string(k ? ", " : "") + "C" + std::to_string(k) + " = " + num(fit.c[k]);
    fail(lmp, where, "normal " + law + " " + key + " " + form + " (" + vals + "): " + ex.what());
  }
  return iarg + want;
}

// [v_min V] [v_max V] (any order); validates the range
int parse_range(LAMMPS *lmp, const std::string &where, const std::string &law, int narg, char **arg,
                int iarg, tdem::fits::Range &range) {
  range = tdem::fits::Range();
  while (iarg < narg && (strcmp(arg[iarg], "v_min") == 0 || strcmp(arg[iarg], "v_max") == 0)) {
    const std::string key = arg[iarg];
    const int have = available(narg, arg, iarg + 1);
    if (have != 1)
      fail(lmp, where, "normal " + law + " " + key + " needs 1 value (impact velocity), got " +
                           std::to_string(have));
    const double v = number(lmp, where, "normal " + law + " " + key, arg[iarg + 1]);
    if (key == "v_min") range.v_min = v;
    else range.v_max = v;
    iarg += 2;
  }
  try {
    tdem::fits::validate_range(range);
  } catch (const std::exception &ex) {
    fail(lmp, where, "normal " + law + " v_min = " + num(range.v_min) + ", v_max = " +
                         num(range.v_max) + ": " + ex.what() +
                         " (allowed: 0 < v_min <= v_max)");
  }
  return iarg;
}

// A law of the list of src/contact/laws.h: `normal NAME v1 v2 ...` at arg[iarg] (the first
// value). The count, the numbers and their ranges are checked from the law's Description, in
// the same words for every law; the values (materials expanded) go to `values`.
int parse_described(LAMMPS *lmp, const std::string &where, const tdem::law::Description &d, int narg,
                    char **arg, int iarg, double *values) {
  namespace law = tdem::law;
  const int n = available(narg, arg, iarg);
  if (!law::count_ok(d, n)) fail(lmp, where, law::count_message(d, n));
  double words[law::MATERIAL_VALUES + 8];
  for (int k = 0; k < n; ++k)
    words[k] = number(lmp, where,
                      std::string(d.kind) + " " + d.name + " " + law::parameter(d, law::value_index(d, n, k)).name,
                      arg[iarg + k]);
  law::expand(d, words, n, values);
  const std::string bad = law::check(d, values);
  if (!bad.empty()) fail(lmp, where, bad);
  for (int k = 0; k < n; ++k) {  // usual ranges of the given words
    const int v = law::value_index(d, n, k);
    if (law::parameter(d, v).bound == law::Bound::poisson)
      unusual(lmp, where, law::value_name(d, v) + ": ", tdem::usual::poisson(values[v]));
  }
  return iarg + n;
}

// Store the values of a unit (src/contact/laws.h) in the type pair's coefficients; derive_law
// derives its kernel parameters.
void store_described(const tdem::law::Description &d, const double *v, LawCoeffs &c) {
  c.mode = MODE_UNIT + tdem::law::index_of<NormalUnits>(&d);
  for (int k = 0; k < tdem::law::value_count(d); ++k) c.uv[k] = v[k];
}

// "walton_braun, thornton, power_law" (sep ", "), or with last = " and " before the last name.
std::string unit_names(const char *sep, const char *last = nullptr) {
  std::string s;
  for (int k = 0; k < NormalUnits::size; ++k)
    s += (k == 0 ? "" : last && k + 1 == NormalUnits::size ? last : sep) + std::string(NormalUnits::descriptions[k]->name);
  return s;
}
const std::string &normal_law_names() {
  static const std::string s = "lsd, hertz, " + unit_names(", ") + ", extended_linear, extended_hertz";
  return s;
}

// normal extended_linear e_fit FORM C.. tc_fit FORM C.. [v_min V] [v_max V]
// normal extended_hertz E NU [E2 NU2] e_fit FORM C.. [v_min V] [v_max V]
int parse_extended(LAMMPS *lmp, const std::string &where, bool hertz, int narg, char **arg,
                   int iarg, LawCoeffs &c) {
  const std::string law = hertz ? "extended_hertz" : "extended_linear";
  c.mode = hertz ? MODE_EXT_HERTZ : MODE_EXT_LINEAR;
  c.ext = tdem::extended::LinearParams();
  if (hertz) {
    iarg = parse_materials(lmp, where, law, narg, arg, iarg, " before e_fit", c);
  } else if (available(narg, arg, iarg) != 0) {
    fail(lmp, where, std::string("normal extended_linear expects 'e_fit FORM C..' next, got '") +
                         arg[iarg] + "'");
  }
  if (iarg >= narg || strcmp(arg[iarg], "e_fit") != 0)
    fail(lmp, where,
         "normal " + law + " needs 'e_fit constant|rational|power C0 ..', got '" +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  iarg = parse_fit(lmp, where, law, narg, arg, iarg, 'e', c.ext.e_fit);
  if (!hertz) {
    if (iarg >= narg || strcmp(arg[iarg], "tc_fit") != 0)
      fail(lmp, where,
           std::string("normal extended_linear needs 'tc_fit constant|power C0 ..' after e_fit, "
                       "got '") + (iarg < narg ? arg[iarg] : "end of line") + "'");
    iarg = parse_fit(lmp, where, law, narg, arg, iarg, 't', c.ext.tc_fit);
  } else {
    // extended_hertz has no contact-time fit (t_c follows from Hertz); keep a valid placeholder
    c.ext.tc_fit.form = tdem::fits::Form::constant;
    c.ext.tc_fit.c[0] = 1.0;
    if (iarg < narg && strcmp(arg[iarg], "tc_fit") == 0)
      fail(lmp, where, "normal extended_hertz takes no tc_fit (its contact time follows from "
                       "Hertz); allowed after e_fit: v_min V, v_max V");
  }
  iarg = parse_range(lmp, where, law, narg, arg, iarg, c.ext.range);
  try {
    tdem::extended::validate(c.ext);
  } catch (const std::exception &ex) {
    fail(lmp, where, "normal " + law + ": " + ex.what());
  }
  return iarg;
}



const char *const TANGENTIAL_LAWS =
    "cundall_strack, haff_werner, linear_spring, walton_braun, mindlin_deresiewicz, "
    "mindlin_no_slip, di_renzo";

// tangential haff_werner | linear_spring | walton_braun | mindlin_deresiewicz | mindlin_no_slip |
// di_renzo with their values, at arg[iarg] (the first value): the laws of the list of
// src/contact/laws.h, read and checked from their Description; returns the next index.
int parse_tangential(LAMMPS *lmp, const std::string &where, const std::string &name, int narg,
                     char **arg, int iarg, LawCoeffs &c) {
  namespace law = tdem::law;
  const law::Description *d = law::find(law::tangential_laws, name.c_str());
  if (!d) fail(lmp, where, "tangential law '" + name + "' is unknown; allowed: " + TANGENTIAL_LAWS);
  double v[law::MATERIAL_VALUES + 8];
  iarg = parse_described(lmp, where, *d, narg, arg, iarg, v);
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
  c = LawCoeffs();
  bool damping_given = false;

  // ---- normal lsd stiffness KN GAMMAN | normal lsd restitution E TC | normal hertz ...
  if (iarg >= narg || strcmp(arg[iarg], "normal") != 0)
    fail(lmp, where,
         "expected 'normal lsd|hertz|" + unit_names("|") + "|extended_linear|extended_hertz ...' first, got '" +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  if (iarg + 1 >= narg) fail(lmp, where, "keyword 'normal' needs a law name; allowed: " + normal_law_names());
  if (strcmp(arg[iarg + 1], "hertz") == 0) {
    iarg = parse_hertz(lmp, where, narg, arg, iarg + 2, c);
  } else if (const tdem::law::Description *d = tdem::law::find(tdem::law::normal_laws, arg[iarg + 1])) {
    double v[tdem::law::MAX_UNIT_VALUES];
    iarg = parse_described(lmp, where, *d, narg, arg, iarg + 2, v);
    store_described(*d, v, c);
  } else if (strcmp(arg[iarg + 1], "extended_linear") == 0) {
    iarg = parse_extended(lmp, where, false, narg, arg, iarg + 2, c);
  } else if (strcmp(arg[iarg + 1], "extended_hertz") == 0) {
    iarg = parse_extended(lmp, where, true, narg, arg, iarg + 2, c);
  } else if (strcmp(arg[iarg + 1], "lsd") != 0) {
    fail(lmp, where,
         std::string("normal law '") + arg[iarg + 1] +
             "' is unknown; allowed: " + normal_law_names());
  } else {
  if (iarg + 2 >= narg)
    fail(lmp, where,
         "normal lsd needs a parametrisation; allowed: 'stiffness KN GAMMAN' or "
         "'restitution E TC'");
  const std::string par = arg[iarg + 2];
  iarg += 3;
  if (par == "stiffness") {
    need(lmp, where, "normal lsd stiffness", "KN GAMMAN", available(narg, arg, iarg), 2);
    c.mode = MODE_STIFFNESS_MASS;
    c.kn = number(lmp, where, "normal lsd stiffness KN", arg[iarg]);
    c.gamman = number(lmp, where, "normal lsd stiffness GAMMAN", arg[iarg + 1]);
    positive(lmp, where, "normal lsd stiffness KN", c.kn);
    non_negative(lmp, where, "normal lsd stiffness GAMMAN", c.gamman);
    iarg += 2;
  } else if (par == "restitution") {
    need(lmp, where, "normal lsd restitution", "E TC", available(narg, arg, iarg), 2);
    c.mode = MODE_RESTITUTION;
    c.e = number(lmp, where, "normal lsd restitution E", arg[iarg]);
    c.tc = number(lmp, where, "normal lsd restitution TC", arg[iarg + 1]);
    if (!tdem::checks::restitution_ok(c.e))
      fail(lmp, where,
           "normal lsd restitution E = " + num(c.e) + " is outside the allowed range (0, 1]");
    positive(lmp, where, "normal lsd restitution TC (contact time)", c.tc);
    iarg += 2;
  } else {
    fail(lmp, where,
         "normal lsd parametrisation '" + par +
             "' is unknown; allowed: 'stiffness KN GAMMAN' or 'restitution E TC'");
  }
  }

  // ---- tangential cundall_strack KT GAMMAT MU | tangential cundall_strack KAPPA MU
  if (iarg >= narg || strcmp(arg[iarg], "tangential") != 0)
    fail(lmp, where,
         std::string("expected 'tangential LAW ...' after the normal law (LAW: ") + TANGENTIAL_LAWS + "), got '" +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  if (iarg + 1 >= narg)
    fail(lmp, where, std::string("keyword 'tangential' needs a law name; allowed: ") + TANGENTIAL_LAWS);
  if (strcmp(arg[iarg + 1], "cundall_strack") != 0) {
    iarg = parse_tangential(lmp, where, arg[iarg + 1], narg, arg, iarg + 2, c);
  } else if ((iarg += 2), c.mode != MODE_STIFFNESS_MASS && c.mode != MODE_STIFFNESS_ABS) {
    need(lmp, where,
         std::string("tangential cundall_strack (with normal ") +
             (c.mode == MODE_RESTITUTION ? "lsd restitution" : normal_name(c)) +
             ")",
         "KAPPA MU",
         available(narg, arg, iarg), 2);
    c.kappa = number(lmp, where, "tangential cundall_strack KAPPA", arg[iarg]);
    c.mu = number(lmp, where, "tangential cundall_strack MU", arg[iarg + 1]);
    positive(lmp, where, "tangential cundall_strack KAPPA (kt/kn)", c.kappa);
    non_negative(lmp, where, "tangential cundall_strack MU", c.mu);
    iarg += 2;
    // a third number: the KT GAMMAT MU form of normal lsd stiffness, read here as KAPPA MU
    if (available(narg, arg, iarg) > 0) {
      char *end = nullptr;
      strtod(arg[iarg], &end);
      if (end != arg[iarg] && *end == '\0')
        fail(lmp, where,
             std::string("tangential cundall_strack takes 2 values (KAPPA MU) with this normal law, but a third "
                         "number '") + arg[iarg] + "' follows '" + arg[iarg - 2] + " " + arg[iarg - 1] +
                 "'; 'KT GAMMAT MU' is the form for 'normal lsd stiffness' only");
    }
    unusual(lmp, where, "tangential cundall_strack ", tdem::usual::stiffness_ratio(c.kappa));
    unusual(lmp, where, "tangential cundall_strack ", tdem::usual::friction(c.mu));
  } else {
    need(lmp, where, "tangential cundall_strack (with normal lsd stiffness)", "KT GAMMAT MU",
         available(narg, arg, iarg), 3);
    c.kt = number(lmp, where, "tangential cundall_strack KT", arg[iarg]);
    c.gammat = number(lmp, where, "tangential cundall_strack GAMMAT", arg[iarg + 1]);
    c.mu = number(lmp, where, "tangential cundall_strack MU", arg[iarg + 2]);
    positive(lmp, where, "tangential cundall_strack KT", c.kt);
    non_negative(lmp, where, "tangential cundall_strack GAMMAT", c.gammat);
    non_negative(lmp, where, "tangential cundall_strack MU", c.mu);
    iarg += 3;
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
      damping_given = true;
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
      need(lmp, where, "rolling sds", "KR GAMMAR MUR", available(narg, arg, iarg + 2), 3);
      c.rp.kr = number(lmp, where, "rolling sds KR", arg[iarg + 2]);
      c.rp.gammar = number(lmp, where, "rolling sds GAMMAR", arg[iarg + 3]);
      c.rp.mur = number(lmp, where, "rolling sds MUR", arg[iarg + 4]);
      positive(lmp, where, "rolling sds KR", c.rp.kr);
      non_negative(lmp, where, "rolling sds GAMMAR", c.rp.gammar);
      non_negative(lmp, where, "rolling sds MUR", c.rp.mur);
      c.roll = 1;
      iarg += 5;
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
               "rolling sds KR GAMMAR MUR");
    }
  }
  (void) damping_given;
  derive_law(lmp, where, c);
  return iarg;
}

}  // namespace tdem_lammps
