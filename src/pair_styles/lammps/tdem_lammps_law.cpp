// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: argument parsing of the lsd + cundall_strack law (pair_coeff, wall fix).
#include "tdem_lammps_law.h"

#include "error.h"
#include "lammps.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {

std::string num(double v) {
  char buf[64];
  snprintf(buf, sizeof(buf), "%.10g", v);
  return buf;
}

[[noreturn]] void fail(LAMMPS *lmp, const std::string &where, const std::string &what) {
  lmp->error->all(FLERR, where + ": " + what);
  std::abort();  // not reached: error->all does not return
}

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
                                         "wiggle", "shear", nullptr};
  int n = 0;
  for (; iarg + n < narg; ++n) {
    for (int k = 0; keywords[k]; ++k)
      if (strcmp(arg[iarg + n], keywords[k]) == 0) return n;
  }
  return n;
}

void positive(LAMMPS *lmp, const std::string &where, const std::string &name, double v) {
  if (!(v > 0.0)) fail(lmp, where, name + " = " + num(v) + " must be > 0");
}
void non_negative(LAMMPS *lmp, const std::string &where, const std::string &name, double v) {
  if (!(v >= 0.0)) fail(lmp, where, name + " = " + num(v) + " must be >= 0");
}

}  // namespace

int parse_law(LAMMPS *lmp, const std::string &where, int narg, char **arg, int iarg,
              bool stop_at_unknown, LawCoeffs &c) {
  c = LawCoeffs();
  bool damping_given = false;

  // ---- normal lsd stiffness KN GAMMAN | normal lsd restitution E TC
  if (iarg >= narg || strcmp(arg[iarg], "normal") != 0)
    fail(lmp, where,
         std::string("expected 'normal lsd ...' first, got '") +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  if (iarg + 1 >= narg) fail(lmp, where, "keyword 'normal' needs a law name; allowed: lsd");
  if (strcmp(arg[iarg + 1], "lsd") != 0)
    fail(lmp, where, std::string("normal law '") + arg[iarg + 1] + "' is unknown; allowed: lsd");
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
    if (!(c.e > 0.0 && c.e <= 1.0))
      fail(lmp, where,
           "normal lsd restitution E = " + num(c.e) + " is outside the allowed range (0, 1]");
    positive(lmp, where, "normal lsd restitution TC (contact time)", c.tc);
    iarg += 2;
  } else {
    fail(lmp, where,
         "normal lsd parametrisation '" + par +
             "' is unknown; allowed: 'stiffness KN GAMMAN' or 'restitution E TC'");
  }

  // ---- tangential cundall_strack KT GAMMAT MU | tangential cundall_strack KAPPA MU
  if (iarg >= narg || strcmp(arg[iarg], "tangential") != 0)
    fail(lmp, where,
         std::string("expected 'tangential cundall_strack ...' after the normal law, got '") +
             (iarg < narg ? arg[iarg] : "end of line") + "'");
  if (iarg + 1 >= narg)
    fail(lmp, where, "keyword 'tangential' needs a law name; allowed: cundall_strack");
  if (strcmp(arg[iarg + 1], "cundall_strack") != 0)
    fail(lmp, where,
         std::string("tangential law '") + arg[iarg + 1] + "' is unknown; allowed: cundall_strack");
  iarg += 2;
  if (c.mode == MODE_RESTITUTION) {
    need(lmp, where, "tangential cundall_strack (with normal lsd restitution)", "KAPPA MU",
         available(narg, arg, iarg), 2);
    c.kappa = number(lmp, where, "tangential cundall_strack KAPPA", arg[iarg]);
    c.mu = number(lmp, where, "tangential cundall_strack MU", arg[iarg + 1]);
    positive(lmp, where, "tangential cundall_strack KAPPA (kt/kn)", c.kappa);
    non_negative(lmp, where, "tangential cundall_strack MU", c.mu);
    iarg += 2;
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
  }

  // ---- options
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "damping") {
      if (iarg + 1 >= narg)
        fail(lmp, where, "keyword 'damping' needs a value; allowed: mass, absolute");
      const std::string v = arg[iarg + 1];
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
               "slip spring_dashpot|spring");
    }
  }
  (void) damping_given;
  derive_law(lmp, where, c);
  return iarg;
}

void derive_law(LAMMPS *lmp, const std::string &where, LawCoeffs &c) {
  if (c.mode != MODE_RESTITUTION) return;
  try {
    const auto rates = tdem::lsd::rates_from_restitution_and_time(c.e, c.tc, contact_end(c.end));
    c.k_per_mass = rates.k_per_mass;
    c.gamma_per_mass = rates.gamma_per_mass;
  } catch (const std::exception &ex) {
    fail(lmp, where, std::string("normal lsd restitution: ") + ex.what());
  }
  if (!(c.k_per_mass > 0.0) || !std::isfinite(c.k_per_mass) || !(c.gamma_per_mass >= 0.0) ||
      !std::isfinite(c.gamma_per_mass))
    fail(lmp, where,
         "normal lsd restitution E = " + num(c.e) + ", TC = " + num(c.tc) +
             " gives no finite stiffness and damping");
}

std::string describe_law(const LawCoeffs &c) {
  std::string s = "normal lsd ";
  if (c.mode == MODE_RESTITUTION) {
    s += "restitution e=" + num(c.e) + " tc=" + num(c.tc) + " (k/m*=" + num(c.k_per_mass) +
         " gamma/m*=" + num(c.gamma_per_mass) + ") tangential cundall_strack kappa=" +
         num(c.kappa) + " mu=" + num(c.mu);
  } else {
    s += "stiffness kn=" + num(c.kn) + " gamman=" + num(c.gamman) +
         (c.mode == MODE_STIFFNESS_MASS ? " (x m*)" : " (absolute)") +
         " tangential cundall_strack kt=" + num(c.kt) + " gammat=" + num(c.gammat) +
         (c.mode == MODE_STIFFNESS_MASS ? " (x m*)" : "") + " mu=" + num(c.mu);
  }
  s += std::string(" limit_force ") + (c.end ? "yes" : "no") + " slip " +
       (c.slip ? "spring_dashpot" : "spring");
  return s;
}

}  // namespace tdem_lammps
