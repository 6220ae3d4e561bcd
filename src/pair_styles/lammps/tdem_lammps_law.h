// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the normal laws lsd (tdem::lsd), hertz (tdem::hertz), walton_braun,
// thornton, power_law (tdem::power_law), extended_linear and extended_hertz (tdem::extended)
// with the Cundall-Strack tangential law (tdem::cundall_strack), as used by pair tdem/gran and
// fix tdem/wall/gran. The lsd modes run on compile-time specialised paths (M = LawMode 0..2,
// end and slip fixed too), the other laws on paths specialised for the law (M = 3..8, end and
// slip read at run time); type pairs with different laws use the run-time path (M = -1).
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

#include "contact/normal/extended.h"
#include "contact/normal/hertz_damped.h"
#include "contact/normal/linear_viscoelastic.h"
#include "contact/normal/power_law_hysteresis.h"
#include "contact/normal/thornton.h"
#include "contact/normal/walton_braun.h"
#include "contact/tangential/cundall_strack.h"

#include <cmath>
#include <cstddef>
#include <string>

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
  MODE_WALTON_BRAUN = 4,    // normal walton_braun KL KUL [S]; kt = KAPPA KL; history xi_max
  MODE_THORNTON = 5,        // normal thornton E NU [E2 NU2] PY; kt = KAPPA 2 E* a;
                            // history xi_max, f_max
  MODE_POWER_LAW = 6,       // normal power_law AL P AUL [Q]; kt = KAPPA dF/dxi; history: the
                            // kernel's slots (tdem::power_law::history_size)
  MODE_EXT_LINEAR = 7,      // normal extended_linear e_fit .. tc_fit .. [v_min V] [v_max V];
                            // kt = KAPPA k(v0); history v0, k, gamma
  MODE_EXT_HERTZ = 8        // normal extended_hertz E NU [E2 NU2] e_fit .. [v_min] [v_max];
                            // kt = KAPPA dF/dxi (Hertz tangent); history v0, alpha
};

// History values per contact: 3 (tangential spring) + the normal law's own slots.
inline constexpr int TANGENTIAL_HISTORY = 3;
constexpr int history_size(int mode) {
  return TANGENTIAL_HISTORY + (mode == MODE_WALTON_BRAUN ? tdem::walton_braun::history_size
                               : mode == MODE_THORNTON   ? tdem::thornton::history_size
                               : mode == MODE_POWER_LAW  ? tdem::power_law::history_size
                               : mode == MODE_EXT_LINEAR ? tdem::extended::linear_history_size
                               : mode == MODE_EXT_HERTZ  ? tdem::extended::hertz_history_size
                                                         : 0);
}

// The largest history_size of any mode (tangential spring + extended_linear's v0, k, gamma).
inline constexpr int MAX_HISTORY = TANGENTIAL_HISTORY + tdem::extended::linear_history_size;
static_assert(history_size(MODE_THORNTON) <= MAX_HISTORY && history_size(MODE_EXT_HERTZ) <= MAX_HISTORY &&
                  history_size(MODE_POWER_LAW) <= MAX_HISTORY && history_size(MODE_WALTON_BRAUN) <= MAX_HISTORY,
              "MAX_HISTORY must cover every law");

// Zero the normal-law slots of a contact's history (hsize values in all). Explicit stores:
// a loop of run-time length here became a memset call per non-touching neighbour (~20 % of
// the pair time of the history laws).
inline void clear_law_history(double *shear, int hsize) {
  static_assert(MAX_HISTORY - TANGENTIAL_HISTORY == 3, "adapt clear_law_history");
  if (hsize > TANGENTIAL_HISTORY) shear[TANGENTIAL_HISTORY] = 0.0;
  if (hsize > TANGENTIAL_HISTORY + 1) shear[TANGENTIAL_HISTORY + 1] = 0.0;
  if (hsize > TANGENTIAL_HISTORY + 2) shear[TANGENTIAL_HISTORY + 2] = 0.0;
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
  // normal walton_braun (MODE_WALTON_BRAUN): k_l, k_u, s (k_ul = k_u + s F_max)
  double wb_kl = 0, wb_ku = 0, wb_s = 0;
  // normal thornton (MODE_THORNTON): limiting contact pressure p_y (materials in E1 .. estar)
  double th_py = 0;
  // ---- restart format version 3 appends the members below (version 2 files end here)
  // normal power_law (MODE_POWER_LAW): a_l, p, a_ul, q
  tdem::power_law::Params<double> pl{0.0, 0.0, 0.0, 0.0};
  // normal extended_linear / extended_hertz (MODE_EXT_LINEAR, MODE_EXT_HERTZ): the fits e(v0),
  // t_c(v0) (linear only) and the impact-velocity clamp; extended_hertz keeps its materials in
  // E1 .. estar (k~ = 4/3 E* sqrt(R*) per contact)
  tdem::extended::LinearParams ext;
};
// Bytes of LawCoeffs in restart files of version 2 (before the members of version 3).
inline constexpr size_t LAW_COEFFS_V2_SIZE = offsetof(LawCoeffs, pl);

inline tdem::ContactEnd contact_end(int end) {
  return end ? tdem::ContactEnd::zero_force : tdem::ContactEnd::zero_overlap;
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

// Derive the per-unit-mass rates of restitution mode; errors through error->all.
void derive_law(LAMMPS_NS::LAMMPS *lmp, const std::string &where, LawCoeffs &c);

// Human-readable summary (log output).
std::string describe_law(const LawCoeffs &c);

// ------------------------------------------------------------------- per-contact evaluation
// One contact. del = x_i - x_j (or sphere centre minus wall point), overlap = radsum - r,
// vr = relative translational velocity v_i - v_j, wr = relative rotational term
// (rad_i w_i + rad_j w_j)/r. Writes ccel (normal force over r, along del) and the tangential
// force fs on i. M, E, S are LawMode, end, slip; -1 reads them from c at run time.
template <int M, int E, int S>
inline void evaluate_contact(const LawCoeffs &c, double meff, double delx, double dely,
                             double delz, double r, double rinv, double rsqinv, double overlap,
                             double vr1, double vr2, double vr3, double wr1, double wr2,
                             double wr3, double dt, bool update, double *shear, double &ccel,
                             double *fs, double radi = 0.0, double radj = 0.0) {
  const int mode = M >= 0 ? M : c.mode;
  const int end = E >= 0 ? E : c.end;
  const int slip = S >= 0 ? S : c.slip;

  // normal component of the relative velocity, tangential rest
  const double vnnr = vr1 * delx + vr2 * dely + vr3 * delz;
  const double vn1 = delx * vnnr * rsqinv;
  const double vn2 = dely * vnnr * rsqinv;
  const double vn3 = delz * vnnr * rsqinv;
  const double vt1 = vr1 - vn1;
  const double vt2 = vr2 - vn2;
  const double vt3 = vr3 - vn3;

  // coefficients of this contact
  tdem::lsd::Coefficients<double> nc;
  tdem::cundall_strack::Params<double> tp;
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
  if (mode == MODE_HERTZ) {
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
    const auto res = tdem::hertz::force(hertz_damping(c.hdamp), contact_end(end), hp, kin);
    ccel = res.force * rinv;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * 2 E* a, tangent stiffness dF/dxi
    tp.gammat = 0.0;
  } else if (mode == MODE_WALTON_BRAUN) {
    // hysteretic: xi_max in history slot TANGENTIAL_HISTORY (after the tangential spring)
    tdem::walton_braun::Params<double> wp;
    wp.k_load = c.wb_kl;
    wp.k_unload = c.wb_ku;
    wp.slope = c.wb_s;
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = 0.0;
    const auto res = tdem::walton_braun::force(wp, kin, shear + TANGENTIAL_HISTORY, update);
    ccel = res.force * rinv;
    tp.kt = c.kappa * c.wb_kl;
    tp.gammat = 0.0;
  } else if (mode == MODE_THORNTON) {
    // elastic-perfectly plastic; xi_max, f_max in history slots 3, 4
    const double reff = radj > 0.0 ? radi * radj / (radi + radj) : radi;
    tdem::thornton::Params<double> thp;
    thp.e_star = c.estar;
    thp.p_y = c.th_py;
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = reff;
    const auto res = tdem::thornton::force(thp, kin, shear + TANGENTIAL_HISTORY, update);
    ccel = res.force * rinv;
    tp.kt = c.kappa * 2.0 * c.estar * sqrt(reff * overlap);  // KAPPA * 2 E* a (Hertz tangent)
    tp.gammat = 0.0;
  } else if (mode == MODE_POWER_LAW) {
    // power-law hysteresis; its history slots (xi_max ...) from slot 3 on; ends at zero force
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = 0.0;
    const auto res = tdem::power_law::force(c.pl, kin, shear + TANGENTIAL_HISTORY, update);
    ccel = res.force * rinv;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * dF/dxi of the branch in use
    tp.gammat = 0.0;
  } else if (mode == MODE_EXT_LINEAR) {
    // k(v0), gamma(v0) fixed at first touch; v0, k, gamma in history slots 3..5
    tdem::NormalKinematics<double> kin;
    kin.overlap = overlap;
    kin.overlap_rate = -vnnr * rinv;
    kin.meff = meff;
    kin.reff = 0.0;
    double *h = shear + TANGENTIAL_HISTORY;
    const auto res =
        end ? tdem::extended::linear_force<tdem::ContactEnd::zero_force>(c.ext, kin, h, update)
            : tdem::extended::linear_force<tdem::ContactEnd::zero_overlap>(c.ext, kin, h, update);
    ccel = res.force * rinv;
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
    double *h = shear + TANGENTIAL_HISTORY;
    const auto res =
        end ? tdem::extended::hertz_force<tdem::ContactEnd::zero_force>(hp, kin, h, update)
            : tdem::extended::hertz_force<tdem::ContactEnd::zero_overlap>(hp, kin, h, update);
    ccel = res.force * rinv;
    tp.kt = c.kappa * res.stiffness;  // KAPPA * dF/dxi (Hertz tangent 3/2 k~ sqrt(xi))
    tp.gammat = 0.0;
  } else if (end)
    ccel = tdem::lsd::force_over_distance<tdem::ContactEnd::zero_force>(nc, overlap, vnnr, rinv, rsqinv);
  else
    ccel = tdem::lsd::force_over_distance<tdem::ContactEnd::zero_overlap>(nc, overlap, vnnr, rinv, rsqinv);

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

  // tangential law (normal force magnitude ccel*r)
  if (slip)
    tdem::cundall_strack::force<tdem::cundall_strack::SlipRule::spring_dashpot_cap>(
        tp, tk, ccel * r, update, shear, fs);
  else
    tdem::cundall_strack::force<tdem::cundall_strack::SlipRule::spring_cap>(tp, tk, ccel * r,
                                                                          update, shear, fs);
}

// Dispatch helper: calls F.template run<M,E,S>() for the combination (all compile-time; the
// laws other than lsd with the law fixed at compile time and end, slip read at run time) or
// the run-time fallback run<-1,-1,-1>() when `uniform` is false.
template <class F>
inline void dispatch(bool uniform, int mode, int end, int slip, F &&f) {
  if (!uniform) return f.template run<-1, -1, -1>();
#define TDEM_LMP_CASE(m, e, s) \
  if (mode == m && end == e && slip == s) return f.template run<m, e, s>();
  TDEM_LMP_CASE(0, 0, 0) TDEM_LMP_CASE(0, 0, 1) TDEM_LMP_CASE(0, 1, 0) TDEM_LMP_CASE(0, 1, 1)
  TDEM_LMP_CASE(1, 0, 0) TDEM_LMP_CASE(1, 0, 1) TDEM_LMP_CASE(1, 1, 0) TDEM_LMP_CASE(1, 1, 1)
  TDEM_LMP_CASE(2, 0, 0) TDEM_LMP_CASE(2, 0, 1) TDEM_LMP_CASE(2, 1, 0) TDEM_LMP_CASE(2, 1, 1)
#undef TDEM_LMP_CASE
#define TDEM_LMP_CASE(m) \
  if (mode == m) return f.template run<m, -1, -1>();
  TDEM_LMP_CASE(MODE_HERTZ) TDEM_LMP_CASE(MODE_WALTON_BRAUN) TDEM_LMP_CASE(MODE_THORNTON)
  TDEM_LMP_CASE(MODE_POWER_LAW) TDEM_LMP_CASE(MODE_EXT_LINEAR) TDEM_LMP_CASE(MODE_EXT_HERTZ)
#undef TDEM_LMP_CASE
  f.template run<-1, -1, -1>();
}

}  // namespace tdem_lammps
