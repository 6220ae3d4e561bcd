// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the normal laws lsd (tdem::lsd), hertz (tdem::hertz), extended_linear and
// extended_hertz (tdem::extended), continuous_potential, and every normal law that is a unit (src/contact/law_unit.h,
// listed in src/contact/laws.h: walton_braun, thornton, power_law)
// with the Cundall-Strack tangential law (tdem::cundall_strack) or one of the tangential laws of
// src/contact/tangential/ (haff_werner, linear_spring, walton_braun_tangential,
// mindlin_deresiewicz, mindlin_no_slip, di_renzo), as used by pair tdem/gran and fix
// tdem/wall/gran. With cundall_strack the lsd modes run on compile-time specialised paths
// (M = LawMode 0..2, end and slip fixed too), the other laws on paths specialised for the law
// (M = 3, 7, 8, 9 and MODE_UNIT + k, end and slip read at run time); type pairs with different laws use the run-time
// path (M = -1). The other tangential laws run on one path per law (TL fixed at compile time,
// the normal law read at run time).
//
// This header is host-specific glue: it holds the per-type-pair coefficients, the argument
// parser shared by pair_coeff and the wall fix (tdem_lammps_law.cpp), and the per-contact
// evaluation that feeds the host-independent kernels in src/contact/.
//
// Rounding order. LAMMPS gran/hooke/history forms the normal "force over distance"
//   ccel = kn*(radsum - r)*rinv - (meff*gamman*vnnr)*rsqinv
// while tdem::lsd::force forms F = gamma*xi_dot + k*xi. To reproduce the stock style bit for
// bit, the adapter uses the kernel's force-over-distance form (tdem::lsd::force_over_distance),
// which evaluates the same law in LAMMPS's order; the zero_force clip is applied to ccel exactly
// where LAMMPS applies limit_damping.
#pragma once

#include "contact/grid_correction.h"
#include "contact/laws.h"
#include "contact/normal/extended.h"
#include "contact/normal/hertz_damped.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/tangential/cundall_strack.h"
#include "contact/rolling/sds.h"
#include "contact/tangential/di_renzo.h"
#include "contact/tangential/haff_werner.h"
#include "contact/tangential/linear_spring.h"
#include "contact/tangential/mindlin_deresiewicz.h"
#include "contact/tangential/mindlin_no_slip.h"
#include "contact/tangential/walton_braun_tangential.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tdem_lammps {

// How the normal coefficients are given.
enum LawMode : int {
  MODE_STIFFNESS_MASS = 0,  // k = KN, gamma = m* GAMMAN   (gran/hooke/history, GAMMAN in 1/time)
  MODE_STIFFNESS_ABS = 1,   // k = KN, gamma = GAMMAN      (GAMMAN in mass/time)
  MODE_RESTITUTION = 2,     // k = m* omega0^2, gamma = m* 2 delta from (e, t_c); kt = KAPPA k
  MODE_HERTZ = 3,           // normal hertz: k~ = 4/3 E* sqrt(R*), damping member hdamp;
                            // kt = KAPPA * 2 E* a
  // 4, 5, 6: walton_braun, thornton, power_law in restart files of versions 2-6 (LEGACY_MODE_*)
  MODE_EXT_LINEAR = 7,      // normal extended_linear e_fit .. tc_fit .. [v_min V] [v_max V];
                            // kt = KAPPA k(v0); history v0, k, gamma
  MODE_EXT_HERTZ = 8,       // normal extended_hertz E NU [E2 NU2] e_fit .. [v_min] [v_max];
                            // kt = KAPPA dF/dxi (Hertz tangent); history v0, alpha
  MODE_CONT_POT = 9,        // normal continuous_potential EPS N GAMMA (in LawCoeffs::uv), d =
                            // X_cut = R_i + R_j (a wall: R_i); kt = KAPPA dF/dxi
  MODE_UNIT = 16            // MODE_UNIT + k: the k-th law of tdem::law::normal_units, with its
                            // input line, kt = KAPPA * its tangential basis and its history slots
};
enum LegacyMode : int { LEGACY_MODE_WALTON_BRAUN = 4, LEGACY_MODE_THORNTON = 5, LEGACY_MODE_POWER_LAW = 6 };

using NormalUnits = tdem::law::normal_units;
inline constexpr bool is_unit(int mode) { return mode >= MODE_UNIT && mode < MODE_UNIT + NormalUnits::size; }
// The unit of law mode M (M >= MODE_UNIT).
template <int M>
using UnitOf = tdem::law::UnitAt<M - MODE_UNIT, NormalUnits>;
// Does pair tdem/gran mix the materials of types I and J for this law? (hertz, extended_hertz
// and the units with materials); "hertz/thornton/extended_hertz" names them.
inline bool mixes_materials(int mode) {
  return mode == MODE_HERTZ || mode == MODE_EXT_HERTZ ||
         (is_unit(mode) && NormalUnits::descriptions[mode - MODE_UNIT]->materials);
}
std::string material_law_names();

// Tangential laws (LawCoeffs::tlaw). cundall_strack is the original path (bitwise equal to
// gran/hooke/history with normal lsd stiffness); the others run the kernels of
// src/contact/tangential/ on the common TangentialKinematics interface.
enum TangentialLaw : int {
  TLAW_CUNDALL_STRACK = 0,
  TLAW_HAFF_WERNER = 1,        // tangential haff_werner GAMMAT MU
  TLAW_LINEAR_SPRING = 2,      // tangential linear_spring KT KAPPA GAMMAT MU
  TLAW_WALTON_BRAUN = 3,       // tangential walton_braun KT KAPPA MU
  TLAW_MINDLIN_DERESIEWICZ = 4,  // tangential mindlin_deresiewicz E NU [E2 NU2] MU
  TLAW_MINDLIN_NO_SLIP = 5,    // tangential mindlin_no_slip E NU [E2 NU2] RATIO MU
  TLAW_DI_RENZO = 6            // tangential di_renzo E NU [E2 NU2] MU
};
inline constexpr int TLAW_COUNT = 7;
const char *tangential_name(int tlaw);

// History values per contact: the tangential block (3 for the spring laws and Haff-Werner, whose
// slots stay unused, 8 walton_braun, 13 mindlin_deresiewicz) first, then the normal law's slots.
inline constexpr int TANGENTIAL_HISTORY = 3;  // the block of cundall_strack
constexpr int tangential_history_size(int tlaw) {
  return tlaw == TLAW_WALTON_BRAUN          ? tdem::walton_braun_tangential::history_size
         : tlaw == TLAW_MINDLIN_DERESIEWICZ ? tdem::mindlin_deresiewicz::history_size
                                            : TANGENTIAL_HISTORY;
}
constexpr int normal_history_size(int mode) {
  return is_unit(mode)             ? NormalUnits::descriptions[mode - MODE_UNIT]->history_size
         : mode == MODE_EXT_LINEAR ? tdem::extended::linear_history_size
         : mode == MODE_EXT_HERTZ  ? tdem::extended::hertz_history_size
                                   : 0;
}
constexpr int history_size(int mode, int tlaw = TLAW_CUNDALL_STRACK) {
  return tangential_history_size(tlaw) + normal_history_size(mode);
}
// Does history slot m (< tangential_history_size(tlaw)) change sign when the pair is seen from
// the other particle? (the kernels' HistorySlot::flips_sign; all three for the spring laws)
inline bool tangential_slot_flips(int tlaw, int m) {
  if (tlaw == TLAW_WALTON_BRAUN) return tdem::walton_braun_tangential::history[m].flips_sign;
  if (tlaw == TLAW_MINDLIN_DERESIEWICZ) return tdem::mindlin_deresiewicz::history[m].flips_sign;
  return m < TANGENTIAL_HISTORY;
}

// The largest number of normal-law slots (extended_linear's v0, k, gamma) and of history values.
inline constexpr int MAX_NORMAL_HISTORY = tdem::extended::linear_history_size;
inline constexpr int MAX_HISTORY = tdem::mindlin_deresiewicz::history_size + MAX_NORMAL_HISTORY;
constexpr bool covers_every_law() {
  for (int k = 0; k < NormalUnits::size; ++k)
    if (normal_history_size(MODE_UNIT + k) > MAX_NORMAL_HISTORY) return false;
  return normal_history_size(MODE_EXT_HERTZ) <= MAX_NORMAL_HISTORY;
}
static_assert(covers_every_law(), "MAX_NORMAL_HISTORY must cover every law");

// Zero the slots after the tangential block of nt values: the normal law's (at most 3) and the
// rolling displacement's (3; they follow the normal law's). Explicit stores: a loop of run-time
// length here became a memset call per non-touching neighbour (~20 % of the pair time of the
// history laws); with hsize known at compile time the unused stores vanish.
inline void clear_after_tangential(double *shear, int nt, int hsize) {
  static_assert(MAX_NORMAL_HISTORY + tdem::rolling_sds::history_size == 6, "adapt clear_after_tangential");
  if (hsize > nt) shear[nt] = 0.0;
  if (hsize > nt + 1) shear[nt + 1] = 0.0;
  if (hsize > nt + 2) shear[nt + 2] = 0.0;
  if (hsize > nt + 3) shear[nt + 3] = 0.0;
  if (hsize > nt + 4) shear[nt + 4] = 0.0;
  if (hsize > nt + 5) shear[nt + 5] = 0.0;
}

// Zero the slots after the cundall_strack spring of a contact's history (hsize values in all).
inline void clear_law_history(double *shear, int hsize) {
  clear_after_tangential(shear, TANGENTIAL_HISTORY, hsize);
}

// Zero the whole history of a contact of tangential law TL (> 0) with hsize values in all: the
// tangential block has a compile-time length, the normal slots are explicit stores (a loop of
// run-time length becomes a memset call per non-touching neighbour).
template <int TL>
inline void clear_history(double *shear, int hsize) {
  constexpr int nt = tangential_history_size(TL);
  for (int m = 0; m < nt; m++) shear[m] = 0.0;
  clear_after_tangential(shear, nt, hsize);
}

// Damping member of normal hertz (values of LawCoeffs::hdamp).
enum HertzDamping : int { HDAMP_LINEAR = 0, HDAMP_KK = 1, HDAMP_TSUJI = 2, HDAMP_GENERAL = 3 };

inline tdem::hertz::Damping hertz_damping(int d) {
  return d == HDAMP_LINEAR ? tdem::hertz::Damping::linear
         : d == HDAMP_KK   ? tdem::hertz::Damping::kuwabara_kono
         : d == HDAMP_TSUJI ? tdem::hertz::Damping::tsuji
                            : tdem::hertz::Damping::general;
}

// Coefficients of one type pair (or of one wall). Plain data, written to restart files.
struct LawCoeffs {
  int mode = MODE_STIFFNESS_MASS;
  int end = 0;   // 0 = zero_overlap (limit_force no), 1 = zero_force (limit_force yes)
  int slip = 1;  // 0 = spring (cap the spring force), 1 = spring_dashpot (cap spring + dashpot)
  int pad = 0;
  // user input
  double kn = 0, gamman = 0, kt = 0, gammat = 0, mu = 0;  // stiffness modes
  double e = 0, tc = 0, kappa = 0;                          // restitution mode (mu shared)
  // derived (restitution mode): per unit effective mass
  double k_per_mass = 0, gamma_per_mass = 0;
  // normal hertz (MODE_HERTZ): materials of the two partners (pair: type I, type J; wall fix:
  // sphere, wall), damping member and its values, derived E* and (tsuji) alpha
  int hdamp = HDAMP_LINEAR, pad2 = 0;
  double E1 = 0, nu1 = 0, E2 = 0, nu2 = 0;
  double hgamma = 0;  // linear [mass/time], kuwabara_kono [mass/(time length^1/2)],
                      // general [mass/(time length^THETA)]; tsuji: derived alpha
  double htheta = 0;  // general: exponent THETA
  double he = 0;      // tsuji: requested restitution E
  double estar = 0;   // derived: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2
  // restart files of versions 2-6 only (read_legacy_units): walton_braun k_l, k_u, s; thornton
  // p_y (its materials in E1 .. nu2)
  double legacy_wb_kl = 0, legacy_wb_ku = 0, legacy_wb_s = 0, legacy_th_py = 0;
  // ---- restart format version 3 appends the members below (version 2 files end here)
  // restart files of versions 3-6 only: power_law a_l, p, a_ul, q
  double legacy_pl[4] = {0.0, 0.0, 0.0, 0.0};
  // normal extended_linear / extended_hertz (MODE_EXT_LINEAR, MODE_EXT_HERTZ): the fits e(v0),
  // t_c(v0) (linear only) and the impact-velocity clamp; extended_hertz keeps its materials in
  // E1 .. estar (k~ = 4/3 E* sqrt(R*) per contact)
  tdem::extended::LinearParams ext;
  // ---- restart format version 4 appends the members below (version 3 files end here)
  // tangential law other than cundall_strack (tlaw != 0; the cundall_strack members are kt,
  // gammat, kappa, mu above)
  int tlaw = TLAW_CUNDALL_STRACK;
  int tlimit = 0;  // FrictionLimit: 0 absolute (mu |F_n|), 1 positive_normal (mu max(F_n, 0))
  double t_kt = 0, t_kappa = 0, t_gammat = 0, t_mu = 0, t_ratio = 0;
  // materials of the two partners of the Mindlin-type laws, and the derived G*
  double tE1 = 0, tnu1 = 0, tE2 = 0, tnu2 = 0, t_gstar = 0;
  // ---- restart format version 6 appends the members below (versions 4 and 5 end here)
  // rolling resistance `rolling sds KR GAMMAR MUR` (src/contact/rolling/sds.h); roll = 0: none
  int roll = 0, pad3 = 0;
  tdem::rolling_sds::Params<double> rp{0.0, 0.0, 0.0};
  // ---- restart format version 7 appends the members below, and stores the law's name
  // a normal law that is a unit (mode >= MODE_UNIT): its expanded input values (materials
  // E1 NU1 E2 NU2 first) and the kernel parameters derived from them (derive_law);
  // continuous_potential (MODE_CONT_POT): EPS N GAMMA in uv
  double uv[tdem::law::MAX_UNIT_VALUES] = {};
  tdem::law::ParamStore up{};
  // ---- restart format version 8 appends the members below (version 7 files end here)
  // grid_correction on|off (src/contact/grid_correction.h, grid_host.h): the start and end steps
  int gc = 0, pad4 = 0;
};
// Bytes of LawCoeffs in restart files of version 2 (before the members of version 3), 3, and 4/5.
inline constexpr size_t LAW_COEFFS_V2_SIZE = offsetof(LawCoeffs, legacy_pl);
inline constexpr size_t LAW_COEFFS_V3_SIZE = offsetof(LawCoeffs, tlaw);
inline constexpr size_t LAW_COEFFS_V5_SIZE = offsetof(LawCoeffs, roll);
inline constexpr size_t LAW_COEFFS_V6_SIZE = offsetof(LawCoeffs, uv);
inline constexpr size_t LAW_COEFFS_V7_SIZE = offsetof(LawCoeffs, gc);

// The coefficients of a file of versions 2-6 in this build's form: walton_braun, thornton and
// power_law (modes 4, 5, 6 there) become their units with the values of their legacy members.
void read_legacy_units(LawCoeffs &c);

// The name of the normal law of c ("lsd", "hertz", "thornton", ...), as restart files store it.
const char *normal_name(const LawCoeffs &c);
// The law mode of a normal law name stored in a restart file (lsd: the mode stored with it), or
// -1 if this build has no such law.
int mode_of_name(const char *name, int stored_mode);

// History values of a type pair's law: the tangential block, the normal law's slots, then the
// rolling displacement (3) when rolling resistance is on, then the time-grid correction's values
// (tdem::grid::history_size; a host keeps them last: at hsize - that, hsize the host's largest).
inline int law_history_size(const LawCoeffs &c, int tlaw) {
  return history_size(c.mode, tlaw) + (c.roll ? tdem::rolling_sds::history_size : 0) +
         (c.gc ? tdem::grid::history_size : 0);
}

// Does the contact end where the force reaches zero? A unit by its own convention (U::end), the
// other laws by limit_force (LawCoeffs::end).
template <class... U>
constexpr bool unit_ends_at_zero_force(int k, tdem::law::Units<U...> *) {
  constexpr bool r[sizeof...(U) > 0 ? sizeof...(U) : 1] = {(U::end == tdem::ContactEnd::zero_force)...};
  return r[k];
}
inline bool ends_at_zero_force(const LawCoeffs &c) {
  return is_unit(c.mode) ? unit_ends_at_zero_force(c.mode - MODE_UNIT, static_cast<NormalUnits *>(nullptr))
                         : c.end != 0;
}

inline tdem::ContactEnd contact_end(int end) {
  return end ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;
}
inline tdem::tangential::FrictionLimit friction_limit(int l) {
  return l ? tdem::tangential::FrictionLimit::positive_normal : tdem::tangential::FrictionLimit::absolute;
}
inline tdem::tangential::SlipReset slip_reset(int slip) {
  return slip ? tdem::tangential::SlipReset::spring_and_dashpot : tdem::tangential::SlipReset::spring_only;
}
inline tdem::cundall_strack::SlipRule slip_rule(int slip) {
  return slip ? tdem::cundall_strack::SlipRule::spring_dashpot_cap
              : tdem::cundall_strack::SlipRule::spring_cap;
}

// Parse "normal lsd ... tangential cundall_strack ... [options]" starting at arg[iarg].
// `where` names the command in error messages ("pair_coeff 1 1", "fix wall tdem/wall/gran").
// With stop_at_unknown = true, parsing ends at the first word that is not a law keyword
// (the wall fix continues with its wall arguments); otherwise an unknown word is an error.
// Returns the index of the first unparsed argument. Errors go through error->all.
int parse_law(LAMMPS_NS::LAMMPS *lmp, const std::string &where, int narg, char **arg, int iarg,
              bool stop_at_unknown, LawCoeffs &out);

// The error of a law's input: error->all(where + ": " + what); does not return.
[[noreturn]] void law_error(LAMMPS_NS::LAMMPS *lmp, const std::string &where, const std::string &what);

// Derive the per-unit-mass rates of restitution mode; errors through error->all.
void derive_law(LAMMPS_NS::LAMMPS *lmp, const std::string &where, LawCoeffs &c);

// Human-readable summary (log output).
std::string describe_law(const LawCoeffs &c);

// ------------------------------------------------------------------- per-contact evaluation
// One contact. del = x_i - x_j (or sphere centre minus wall point), overlap = radsum - r,
// vr = relative translational velocity v_i - v_j, wr = relative rotational term
// (rad_i w_i + rad_j w_j)/r. Writes ccel (normal force over r, along del) and the tangential
// force fs on i. M, E, S are LawMode, end, slip; -1 reads them from c at run time.
//
// TL is the tangential law (TangentialLaw; -1 reads c.tlaw). The laws other than cundall_strack
// also need the angular velocities omega_i, omega_j (omega_j = nullptr: a plane wall) for the
// twist spin_n = (omega_i + omega_j)/2 . n, and take the turning rate of the normal
// omega_t = n x (v_i - v_j)/r for a pair (radj > 0), 0 for a wall.
//
// D is the damping member of normal hertz (HertzDamping; used with E >= 0, -1 reads c.hdamp).
// nres (optional): the normal law's result (force, elastic part, tangent stiffness, damping
// coefficient), for the time-grid correction (grid_host.h).
// Rolling-resistance torque on i (troll; the torque on j is -troll) of a contact with rolling
// on: the rolling displacement follows the law's other history values. n = del / r points from j
// to i; omega_j = nullptr is a wall (at rest); fn the normal force. troll stays 0 without rolling.
inline void rolling_torque(const LawCoeffs &c, int tlaw, double delx, double dely, double delz, double rinv,
                           double fn, double radi, double radj, const double *omega_i, const double *omega_j,
                           double dt, bool update, double *shear, double *troll) {
  if (!c.roll || !troll) return;
  static const double rest[3] = {0.0, 0.0, 0.0};
  const double n[3] = {delx * rinv, dely * rinv, delz * rinv};
  const double reff = radj > 0.0 ? radi * radj / (radi + radj) : radi;
  tdem::rolling_sds::torque(c.rp, n, reff, omega_i ? omega_i : rest, omega_j ? omega_j : rest, fn, dt, update,
                            shear + history_size(c.mode, tlaw), troll);
}

// The normal force of a contact of unit U (src/contact/law_unit.h): its kernel on its history
// slots h, the force over distance ccel, the tangent stiffness and damping for the tangential
// law, and k_t = KAPPA * the unit's tangential basis for cundall_strack.
template <class U>
TDEM_KERNEL void unit_normal(const LawCoeffs &c, double meff, double overlap, double overlap_rate, double rinv,
                             double radi, double radj, double *h, bool update, double &ccel, double &kn_used,
                             double &gn_used, double &kt, tdem::NormalResult<double> *nres = nullptr) {
  tdem::NormalKinematics<double> kin;
  kin.overlap = overlap;
  kin.overlap_rate = overlap_rate;
  kin.meff = meff;
  kin.reff = U::needs_reff ? (radj > 0.0 ? radi * radj / (radi + radj) : radi) : 0.0;
  const auto &p = c.up.as<typename U::Params>();
  const auto res = U::force(p, kin, h, update);
  kt = c.kappa * U::tangential_basis(p, res, kin);
  kn_used = res.stiffness, gn_used = res.damping;
  ccel = res.force * rinv;
  if (nres) *nres = res;
}

// The normal law of one contact (the first part of evaluate_contact, also the time-grid
// correction's probes): the force over distance ccel, the normal tangent stiffness and damping
// coefficient for the tangential law, the cundall_strack parameters tp of the contact, and
// optionally the law's result nres. hn: the normal law's history slots. M, E, D as for
// evaluate_contact.
template <int M, int E, int D = -1>
TDEM_KERNEL void normal_contact(const LawCoeffs &c, double meff, double r, double rinv, double rsqinv,
                                double overlap, double vnnr, double radi, double radj, double *hn, bool update,
                                double &ccel, double &kn_used, double &gn_used,
                                tdem::cundall_strack::Params<double> &tp, tdem::NormalResult<double> *nres) {
  const int mode = M >= 0 ? M : c.mode;
  const int end = E >= 0 ? E : c.end;
  // coefficients of this contact
  tdem::lsd::Coefficients<double> nc;
  tp.mu = c.mu;
  if (mode == MODE_STIFFNESS_MASS) {
    nc.k = c.kn;
    nc.gamma = meff * c.gamman;
    tp.kt = c.kt;
    tp.gammat = meff * c.gammat;
  } else if (mode == MODE_STIFFNESS_ABS) {
    nc.k = c.kn;
    nc.gamma = c.gamman;
    tp.kt = c.kt;
    tp.gammat = c.gammat;
  } else {  // MODE_RESTITUTION (MODE_HERTZ sets tp below and does not use nc)
    nc.k = meff * c.k_per_mass;
    nc.gamma = meff * c.gamma_per_mass;
    tp.kt = c.kappa * nc.k;
    tp.gammat = 0.0;
  }

  // normal law, as force over distance (LAMMPS applies it along del)
  if (mode == MODE_CONT_POT) {
    // Langston's potential from geometric touch on: d = X_cut = R_i + R_j (a wall: R_i)
    const auto p = tdem::continuous_potential::at_contact(c.uv, radj > 0.0 ? radi + radj : radi);
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = 0.0;
    const auto res = end ? tdem::continuous_potential::force<tdem::ContactEnd::zero_force>(p, kin)
                         : tdem::continuous_potential::force<tdem::ContactEnd::zero_overlap>(p, kin);
    ccel = res.force * rinv;
    kn_used = res.stiffness, gn_used = res.damping;
    if (nres) *nres = res;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * dF/dxi
    tp.gammat = 0.0;
  } else if (mode == MODE_HERTZ) {
    // R* from the two radii (radj = 0: wall, R* = R_i); k~ = 4/3 E* sqrt(R*)
    const double reff = radj > 0.0 ? radi * radj / (radi + radj) : radi;
    tdem::hertz::Params<double> hp;
    hp.k = tdem::hertz::stiffness(c.estar, reff);
    hp.damp = c.hgamma;
    hp.theta = c.htheta;
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = reff;
    tdem::NormalResult<double> res;
    if constexpr (D >= 0 && E >= 0) {
      constexpr auto ce = E ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;
      res = tdem::hertz::force<D == HDAMP_LINEAR ? tdem::hertz::Damping::linear
                               : D == HDAMP_KK   ? tdem::hertz::Damping::kuwabara_kono
                               : D == HDAMP_TSUJI ? tdem::hertz::Damping::tsuji
                                                  : tdem::hertz::Damping::general,
                               ce>(hp, kin);
    } else {
      res = tdem::hertz::force(hertz_damping(c.hdamp), contact_end(end), hp, kin);
    }
    ccel = res.force * rinv;
    kn_used = res.stiffness, gn_used = res.damping;
    if (nres) *nres = res;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * 2 E* a, tangent stiffness dF/dxi
    tp.gammat = 0.0;
  } else if (is_unit(mode)) {
    // a unit (src/contact/law_unit.h): its kernel on its history slots after the tangential block
    if constexpr (M >= MODE_UNIT) {
      unit_normal<UnitOf<M>>(c, meff, overlap, -vnnr * rinv, rinv, radi, radj, hn, update, ccel, kn_used,
                             gn_used, tp.kt, nres);
    } else {
      tdem::law::visit<NormalUnits>(mode - MODE_UNIT, [&](auto tag) {
        unit_normal<typename decltype(tag)::type>(c, meff, overlap, -vnnr * rinv, rinv, radi, radj, hn,
                                                  update, ccel, kn_used, gn_used, tp.kt, nres);
      });
    }
    tp.gammat = 0.0;
  } else if (mode == MODE_EXT_LINEAR) {
    // k(v0), gamma(v0) fixed at first touch; v0, k, gamma in history slots 3..5
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = 0.0;
    double *h = hn;
    const auto res =
        end ? tdem::extended::linear_force<tdem::ContactEnd::zero_force>(c.ext, kin, h, update)
            : tdem::extended::linear_force<tdem::ContactEnd::zero_overlap>(c.ext, kin, h, update);
    ccel = res.force * rinv;
    kn_used = res.stiffness, gn_used = res.damping;
    if (nres) *nres = res;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * k(v0)
    tp.gammat = 0.0;
  } else if (mode == MODE_EXT_HERTZ) {
    // Hertz spring with Tsuji damping alpha(v0) fixed at first touch; v0, alpha in slots 3, 4
    const double reff = radj > 0.0 ? radi * radj / (radi + radj) : radi;
    const tdem::extended::HertzParams hp{tdem::hertz::stiffness(c.estar, reff), c.ext.e_fit,
                                         c.ext.range};
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = reff;
    double *h = hn;
    const auto res =
        end ? tdem::extended::hertz_force<tdem::ContactEnd::zero_force>(hp, kin, h, update)
            : tdem::extended::hertz_force<tdem::ContactEnd::zero_overlap>(hp, kin, h, update);
    ccel = res.force * rinv;
    kn_used = res.stiffness, gn_used = res.damping;
    if (nres) *nres = res;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * dF/dxi (Hertz tangent 3/2 k~ sqrt(xi))
    tp.gammat = 0.0;
  } else {
    kn_used = nc.k, gn_used = nc.gamma;
    if (end)
      ccel = tdem::lsd::force_over_distance<tdem::ContactEnd::zero_force>(nc, overlap, vnnr, rinv, rsqinv);
    else
      ccel = tdem::lsd::force_over_distance<tdem::ContactEnd::zero_overlap>(nc, overlap, vnnr, rinv, rsqinv);
    if (nres) *nres = {ccel * r, nc.k * overlap, nc.k, nc.gamma};  // the kernel's parts (grid correction)
  }

}

template <int M, int E, int S, int TL = TLAW_CUNDALL_STRACK, int D = -1>
inline void evaluate_contact(const LawCoeffs &c, double meff, double delx, double dely,
                             double delz, double r, double rinv, double rsqinv, double overlap,
                             double vr1, double vr2, double vr3, double wr1, double wr2,
                             double wr3, double dt, bool update, double *shear, double &ccel,
                             double *fs, double radi = 0.0, double radj = 0.0,
                             const double *omega_i = nullptr, const double *omega_j = nullptr,
                             double *troll = nullptr, tdem::NormalResult<double> *nres = nullptr) {
  const int slip = S >= 0 ? S : c.slip;
  const int tlaw = TL >= 0 ? TL : c.tlaw;
  // the normal law's slots follow the tangential block
  const int toff = tlaw == TLAW_CUNDALL_STRACK ? TANGENTIAL_HISTORY : tangential_history_size(tlaw);
  // normal tangent stiffness and damping coefficient of this step (for the tangential law)
  double kn_used = 0.0, gn_used = 0.0;

  // normal component of the relative velocity, tangential rest
  const double vnnr = vr1 * delx + vr2 * dely + vr3 * delz;
  const double vn1 = delx * vnnr * rsqinv;
  const double vn2 = dely * vnnr * rsqinv;
  const double vn3 = delz * vnnr * rsqinv;
  const double vt1 = vr1 - vn1;
  const double vt2 = vr2 - vn2;
  const double vt3 = vr3 - vn3;

  tdem::cundall_strack::Params<double> tp;
  normal_contact<M, E, D>(c, meff, r, rinv, rsqinv, overlap, vnnr, radi, radj, shear + toff, update, ccel, kn_used,
                          gn_used, tp, nres);

  // relative velocity of the contact point
  tdem::cundall_strack::Kinematics<double> tk;
  tk.d[0] = delx;
  tk.d[1] = dely;
  tk.d[2] = delz;
  tk.d_scale = rsqinv;
  tk.vt[0] = vt1 - (delz * wr2 - dely * wr3);
  tk.vt[1] = vt2 - (delx * wr3 - delz * wr1);
  tk.vt[2] = vt3 - (dely * wr1 - delx * wr2);
  tk.dt = dt;

  if (tlaw != TLAW_CUNDALL_STRACK) {
    // the laws of src/contact/tangential/ on the common interface
    tdem::tangential::TangentialKinematics<double> k;
    k.n[0] = delx * rinv;
    k.n[1] = dely * rinv;
    k.n[2] = delz * rinv;
    k.vt[0] = tk.vt[0];
    k.vt[1] = tk.vt[1];
    k.vt[2] = tk.vt[2];
    double ws0 = omega_i ? omega_i[0] : 0.0, ws1 = omega_i ? omega_i[1] : 0.0,
           ws2 = omega_i ? omega_i[2] : 0.0;
    if (omega_j) ws0 += omega_j[0], ws1 += omega_j[1], ws2 += omega_j[2];
    k.spin_n = 0.5 * (ws0 * k.n[0] + ws1 * k.n[1] + ws2 * k.n[2]);
    k.dt = dt;
    k.overlap = overlap > 0.0 ? overlap : 0.0;
    k.meff = meff;
    k.reff = radj > 0.0 ? radi * radj / (radi + radj) : radi;
    k.fn = ccel * r;
    k.kn = kn_used;
    k.gamman = gn_used;
    if (radj > 0.0) {  // n x (v_i - v_j) / r = (del x vr) / r^2
      k.omega_t[0] = (dely * vr3 - delz * vr2) * rsqinv;
      k.omega_t[1] = (delz * vr1 - delx * vr3) * rsqinv;
      k.omega_t[2] = (delx * vr2 - dely * vr1) * rsqinv;
    }
    const auto lim = friction_limit(c.tlimit);
    if (tlaw == TLAW_HAFF_WERNER) {
      const tdem::haff_werner::Params<double> p{c.t_gammat, c.t_mu, lim};
      tdem::haff_werner::force(p, k, shear, update, fs);
    } else if (tlaw == TLAW_LINEAR_SPRING) {
      const tdem::linear_spring::Params<double> p{c.t_kt, c.t_kappa, c.t_gammat, c.t_mu, lim, slip_reset(slip)};
      tdem::linear_spring::force(p, k, shear, update, fs);
    } else if (tlaw == TLAW_WALTON_BRAUN) {
      const tdem::walton_braun_tangential::Params<double> p{c.t_kt, c.t_kappa, c.t_mu, lim};
      tdem::walton_braun_tangential::force(p, k, shear, update, fs);
    } else if (tlaw == TLAW_MINDLIN_DERESIEWICZ) {
      const tdem::mindlin_deresiewicz::Params<double> p{c.t_gstar, c.t_mu, lim};
      tdem::mindlin_deresiewicz::force(p, k, shear, update, fs);
    } else if (tlaw == TLAW_MINDLIN_NO_SLIP) {
      const tdem::mindlin_no_slip::Params<double> p{c.t_gstar, c.t_ratio, c.t_mu, lim, slip_reset(slip)};
      tdem::mindlin_no_slip::force(p, k, shear, update, fs);
    } else {
      const tdem::di_renzo::Params<double> p{c.t_gstar, c.t_mu, lim};
      tdem::di_renzo::force(p, k, shear, update, fs);
    }
    if constexpr (M < 0) rolling_torque(c, tlaw, delx, dely, delz, rinv, ccel * r, radi, radj, omega_i, omega_j, dt,
                                        update, shear, troll);
    return;
  }

  // tangential law (normal force magnitude ccel*r)
  if (slip)
    tdem::cundall_strack::force<tdem::cundall_strack::SlipRule::spring_dashpot_cap>(
        tp, tk, ccel * r, update, shear, fs);
  else
    tdem::cundall_strack::force<tdem::cundall_strack::SlipRule::spring_cap>(tp, tk, ccel * r,
                                                                          update, shear, fs);
  // rolling resistance only on the run-time path: a law with it has more history values than
  // its compile-time path, so the hosts never take those paths for it (no cost there)
  if constexpr (M < 0) rolling_torque(c, tlaw, delx, dely, delz, rinv, ccel * r, radi, radj, omega_i, omega_j, dt,
                                      update, shear, troll);
}

}  // namespace tdem_lammps

// the compile-time path dispatcher of the contact loops (dispatch, dispatch_unit)
#include "tdem_lammps_dispatch.h"
