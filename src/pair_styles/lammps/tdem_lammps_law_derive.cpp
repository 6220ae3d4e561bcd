// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: what follows from the parsed coefficients of a type pair or wall (derive_law:
// per-unit-mass rates, E*, G*, the kernels' own checks) and their text for the log (describe_law).
// The parsing itself is in tdem_lammps_law.cpp.
#include "tdem_lammps_law.h"

#include "contact/law_parameters.h"
#include "contact/tangential/parameters.h"

#include <cmath>
#include <stdexcept>
#include <string>

using namespace LAMMPS_NS;

namespace tdem_lammps {

namespace {
std::string num(double v) { return tdem::law::number_text(v); }
[[noreturn]] void fail(LAMMPS *lmp, const std::string &where, const std::string &what) { law_error(lmp, where, what); }
}  // namespace

void derive_normal(LAMMPS *lmp, const std::string &where, LawCoeffs &c);
std::string describe_normal(const LawCoeffs &c);

void derive_law(LAMMPS *lmp, const std::string &where, LawCoeffs &c) {
  derive_normal(lmp, where, c);
  // the tangential laws other than cundall_strack: G* and the kernel's own checks
  if (c.tlaw == TLAW_CUNDALL_STRACK) return;
  const std::string t = std::string("tangential ") + tangential_name(c.tlaw);
  try {
    const auto lim = friction_limit(c.tlimit);
    if (c.tlaw == TLAW_MINDLIN_DERESIEWICZ || c.tlaw == TLAW_MINDLIN_NO_SLIP || c.tlaw == TLAW_DI_RENZO)
      c.t_gstar = tdem::tangential::effective_shear_modulus_from_E(c.tE1, c.tnu1, c.tE2, c.tnu2);
    if (c.tlaw == TLAW_HAFF_WERNER) tdem::haff_werner::validate({c.t_gammat, c.t_mu, lim});
    else if (c.tlaw == TLAW_LINEAR_SPRING)
      tdem::linear_spring::validate({c.t_kt, c.t_kappa, c.t_gammat, c.t_mu, lim, slip_reset(c.slip)});
    else if (c.tlaw == TLAW_WALTON_BRAUN)
      tdem::walton_braun_tangential::validate({c.t_kt, c.t_kappa, c.t_mu, lim});
    else if (c.tlaw == TLAW_MINDLIN_DERESIEWICZ) tdem::mindlin_deresiewicz::validate({c.t_gstar, c.t_mu, lim});
    else if (c.tlaw == TLAW_MINDLIN_NO_SLIP)
      tdem::mindlin_no_slip::validate({c.t_gstar, c.t_ratio, c.t_mu, lim, slip_reset(c.slip)});
    else tdem::di_renzo::validate({c.t_gstar, c.t_mu, lim});
  } catch (const std::exception &ex) {
    fail(lmp, where, t + ": " + ex.what());
  }
}

void derive_normal(LAMMPS *lmp, const std::string &where, LawCoeffs &c) {
  if (c.mode == MODE_EXT_HERTZ || c.mode == MODE_EXT_LINEAR) {
    const std::string law = c.mode == MODE_EXT_HERTZ ? "extended_hertz" : "extended_linear";
    try {
      if (c.mode == MODE_EXT_HERTZ) {
        c.estar = tdem::hertz::effective_modulus(c.E1, c.nu1, c.E2, c.nu2);
        tdem::extended::validate(tdem::extended::HertzParams{tdem::hertz::stiffness(c.estar, 1.0),
                                                              c.ext.e_fit, c.ext.range});
      } else {
        tdem::extended::validate(c.ext);
      }
      // the first-touch conversion must succeed over the whole clamp range (the kernel's
      // first-touch path is noexcept and would give a force-free contact otherwise)
      for (int k = 0; k <= 8; ++k) {
        const double v = c.ext.range.v_min *
                         std::pow(c.ext.range.v_max / c.ext.range.v_min, k / 8.0);
        if (c.mode == MODE_EXT_HERTZ) {
          const double a = tdem::extended::hertz_alpha(contact_end(c.end), c.ext.e_fit, c.ext.range, v);
          if (!(a >= 0.0) || !std::isfinite(a)) throw std::domain_error("no finite damping alpha at v0 = " + num(v));
        } else {
          const auto lc = tdem::extended::linear_coefficients(contact_end(c.end), c.ext, 1.0, v);
          if (!(lc.k > 0.0) || !std::isfinite(lc.k) || !(lc.gamma >= 0.0) || !std::isfinite(lc.gamma))
            throw std::domain_error("no finite stiffness and damping at v0 = " + num(v));
        }
      }
    } catch (const std::exception &ex) {
      fail(lmp, where, "normal " + law + ": " + ex.what());
    }
    return;
  }
  if (is_unit(c.mode)) {  // the unit's parameters from its values (E* for a law with materials)
    tdem::law::visit<NormalUnits>(c.mode - MODE_UNIT, [&](auto tag) {
      using U = typename decltype(tag)::type;
      try {
        double v[tdem::law::MAX_UNIT_VALUES];
        tdem::law::unit_values(U::description, c.uv, v);
        c.up = tdem::law::store<U>(v);
      } catch (const std::exception &ex) {
        fail(lmp, where, std::string("normal ") + U::description.name + ": " + ex.what());
      }
    });
    return;
  }
  if (c.mode == MODE_HERTZ) {
    try {
      c.estar = tdem::hertz::effective_modulus(c.E1, c.nu1, c.E2, c.nu2);
      if (c.hdamp == HDAMP_TSUJI) c.hgamma = tdem::hertz::tsuji_alpha_from_restitution(c.he, contact_end(c.end));
    } catch (const std::exception &ex) {
      fail(lmp, where, std::string("normal hertz: ") + ex.what());
    }
    if (!(c.estar > 0.0) || !std::isfinite(c.estar) || !(c.hgamma >= 0.0) || !std::isfinite(c.hgamma))
      fail(lmp, where, "normal hertz: the parameters give no finite E* and damping");
    return;
  }
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

const char *normal_name(const LawCoeffs &c) {
  if (is_unit(c.mode)) return NormalUnits::descriptions[c.mode - MODE_UNIT]->name;
  return c.mode == MODE_HERTZ        ? "hertz"
         : c.mode == MODE_EXT_LINEAR ? "extended_linear"
         : c.mode == MODE_EXT_HERTZ  ? "extended_hertz"
         : c.mode == MODE_CONT_POT   ? "continuous_potential"
                                     : "lsd";
}

std::string material_law_names() {
  std::string s = "hertz";
  for (const tdem::law::Description *d : tdem::law::normal_laws)
    if (d->materials) s += std::string("/") + d->name;
  return s + "/extended_hertz";
}

int mode_of_name(const char *name, int stored_mode) {
  const int k = tdem::law::index_of<NormalUnits>(name);
  if (k >= 0) return MODE_UNIT + k;
  const std::string n = name;
  if (n == "hertz") return MODE_HERTZ;
  if (n == "extended_linear") return MODE_EXT_LINEAR;
  if (n == "extended_hertz") return MODE_EXT_HERTZ;
  if (n == "continuous_potential") return MODE_CONT_POT;
  if (n == "lsd" && stored_mode >= MODE_STIFFNESS_MASS && stored_mode <= MODE_RESTITUTION) return stored_mode;
  return -1;
}

void read_legacy_units(LawCoeffs &c) {
  const char *name = c.mode == LEGACY_MODE_WALTON_BRAUN ? "walton_braun"
                     : c.mode == LEGACY_MODE_THORNTON   ? "thornton"
                     : c.mode == LEGACY_MODE_POWER_LAW  ? "power_law"
                                                        : nullptr;
  if (!name) return;
  const double wb[3] = {c.legacy_wb_kl, c.legacy_wb_ku, c.legacy_wb_s};
  const double th[5] = {c.E1, c.nu1, c.E2, c.nu2, c.legacy_th_py};
  const double *v = c.mode == LEGACY_MODE_WALTON_BRAUN ? wb : c.mode == LEGACY_MODE_THORNTON ? th : c.legacy_pl;
  const int n = c.mode == LEGACY_MODE_WALTON_BRAUN ? 3 : c.mode == LEGACY_MODE_THORNTON ? 5 : 4;
  c.mode = MODE_UNIT + tdem::law::index_of<NormalUnits>(name);
  for (int k = 0; k < tdem::law::MAX_UNIT_VALUES; ++k) c.uv[k] = k < n ? v[k] : 0.0;
}

const char *tangential_name(int tlaw) {
  static const char *const names[] = {"cundall_strack", "haff_werner", "linear_spring", "walton_braun",
                                      "mindlin_deresiewicz", "mindlin_no_slip", "di_renzo"};
  return tlaw >= 0 && tlaw < TLAW_COUNT ? names[tlaw] : "unknown";
}

std::string describe_rolling(const LawCoeffs &c) {
  const std::string g = c.gc ? " grid_correction on" : "";
  if (!c.roll) return g;
  return " rolling sds kr=" + num(c.rp.kr) + " gammar=" + num(c.rp.gammar) + " mur=" + num(c.rp.mur) + g;
}

std::string describe_law(const LawCoeffs &c) {
  std::string s = describe_normal(c) + describe_rolling(c);
  if (c.tlaw == TLAW_CUNDALL_STRACK) return s;
  // replace the cundall_strack part by the tangential law in use
  const size_t at = s.find(" tangential cundall_strack");
  const size_t opt = s.find(" limit_force ");
  std::string t = std::string(" tangential ") + tangential_name(c.tlaw);
  if (c.tlaw == TLAW_HAFF_WERNER) t += " gammat=" + num(c.t_gammat);
  else if (c.tlaw == TLAW_LINEAR_SPRING || c.tlaw == TLAW_WALTON_BRAUN) {
    t += " kt=" + num(c.t_kt) + " kappa=" + num(c.t_kappa) + " (k_t = kt + kappa k_n)";
    if (c.tlaw == TLAW_LINEAR_SPRING) t += " gammat=" + num(c.t_gammat);
  } else {
    t += " E1=" + num(c.tE1) + " nu1=" + num(c.tnu1) + " E2=" + num(c.tE2) + " nu2=" + num(c.tnu2) +
         " (G*=" + num(c.t_gstar) + ")";
    if (c.tlaw == TLAW_MINDLIN_NO_SLIP) t += " ratio=" + num(c.t_ratio) + " (eta_t = ratio gamma_n)";
  }
  t += " mu=" + num(c.t_mu) + " friction_limit " + (c.tlimit ? "positive_normal" : "absolute");
  if (at != std::string::npos && opt != std::string::npos && opt > at) s = s.substr(0, at) + t + s.substr(opt);
  return s;
}

std::string describe_normal(const LawCoeffs &c) {
  std::string s = "normal lsd ";
  auto fit = [](const tdem::fits::Fit &f, char what) {
    std::string t = tdem::fits::to_string(f.form);
    for (int k = 0; k < tdem::fits::coefficient_count(f.form, what); ++k) t += " " + num(f.c[k]);
    return t;
  };
  if (is_unit(c.mode)) {  // its values by name, E* of a law with materials, kt = kappa * its basis
    tdem::law::visit<NormalUnits>(c.mode - MODE_UNIT, [&](auto tag) {
      using U = typename decltype(tag)::type;
      constexpr const tdem::law::Description &d = U::description;
      double u[tdem::law::MAX_UNIT_VALUES];
      tdem::law::unit_values(d, c.uv, u);
      s = std::string("normal ") + d.name;
      for (int k = 0; k < tdem::law::value_count(d); ++k) {
        s += std::string(" ") + tdem::law::parameter(d, k).name + "=" + num(c.uv[k]);
        if (d.materials && k + 1 == tdem::law::MATERIAL_VALUES) s += " (E*=" + num(u[0]) + ")";
      }
      s += std::string(" tangential cundall_strack kappa=") + num(c.kappa) + " (kt = kappa " +
           U::tangential_basis_text + ") mu=" + num(c.mu);
    });
  } else if (c.mode == MODE_CONT_POT) {
    s = "normal continuous_potential eps=" + num(c.uv[0]) + " n=" + num(c.uv[1]) + " gamma=" + num(c.uv[2]) +
        " (d = X_cut = R_i + R_j) tangential cundall_strack kappa=" + num(c.kappa) + " (kt = kappa dF/dxi) mu=" +
        num(c.mu);
  } else if (c.mode == MODE_EXT_LINEAR) {
    s = "normal extended_linear e_fit " + fit(c.ext.e_fit, 'e') + " tc_fit " + fit(c.ext.tc_fit, 't') +
        " v_min=" + num(c.ext.range.v_min) + " v_max=" + num(c.ext.range.v_max) +
        " tangential cundall_strack kappa=" + num(c.kappa) + " (kt = kappa k(v0)) mu=" + num(c.mu);
  } else if (c.mode == MODE_EXT_HERTZ) {
    s = "normal extended_hertz E1=" + num(c.E1) + " nu1=" + num(c.nu1) + " E2=" + num(c.E2) +
        " nu2=" + num(c.nu2) + " (E*=" + num(c.estar) + ") e_fit " + fit(c.ext.e_fit, 'e') +
        " v_min=" + num(c.ext.range.v_min) + " v_max=" + num(c.ext.range.v_max) +
        " tangential cundall_strack kappa=" + num(c.kappa) + " (kt = kappa dF/dxi) mu=" + num(c.mu);
  } else if (c.mode == MODE_HERTZ) {
    static const char *const dn[] = {"linear", "kuwabara_kono", "tsuji", "general"};
    s = "normal hertz E1=" + num(c.E1) + " nu1=" + num(c.nu1) + " E2=" + num(c.E2) +
        " nu2=" + num(c.nu2) + " (E*=" + num(c.estar) + ") damping " + dn[c.hdamp & 3];
    if (c.hdamp == HDAMP_TSUJI) s += " e=" + num(c.he) + " (alpha=" + num(c.hgamma) + ")";
    else if (c.hdamp == HDAMP_GENERAL) s += " theta=" + num(c.htheta) + " c=" + num(c.hgamma);
    else s += " gamma=" + num(c.hgamma);
    s += " tangential cundall_strack kappa=" + num(c.kappa) + " (kt = kappa 2 E* a) mu=" + num(c.mu);
  } else if (c.mode == MODE_RESTITUTION) {
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
