// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: oblique impacts with a tangential law, and whole-step integration with a scheme (--scheme). A part of main.cpp (collide_common.h).
#pragma once

#include "collide_common.h"
#include "collide_args.h"

namespace {

struct Oblique {
  bool active = false;
  double speed = 0.0, angle_deg = 0.0;
  collision::ObliqueBodies bodies;
  collision::ObliqueImpact impact;
  collision::ObliqueOptions opt;
  std::string tangential = "none";
  double mu = 0.0, kt = NAN, kappa = NAN, gammat = 0.0, gstar = NAN, estar = NAN, eta_ratio = 1.0;
  tangential::FrictionLimit limit = tangential::FrictionLimit::absolute;
  tangential::SlipReset reset = tangential::SlipReset::spring_only;
  bool beta0_given = false;
  double beta0 = 1.0;
  double psi_kappa = NAN;
  // results
  std::vector<std::pair<std::string, double>> tparams;  // the tangential coefficients used
  std::vector<std::pair<std::string, std::string>> tchoices;
  collision::ObliqueResult r;
  rigid_body::Output rb;
  bool rb_valid = false;
};

// --scheme: the whole-step integration of integrate_impact.h (optionally phase-averaged).
struct SchemeRun {
  bool active = false;
  collision::ImpactScheme scheme;
  collision::ImpactSetup setup;
  collision::ImpactOptions opt;
  int phases = 0;  // 0: one run at the given gap
  bool have_ref = false;
  collision::ImpactReference ref;
  collision::PhaseAverage pa;
  collision::ImpactResult one;
};

struct Run {
  std::string law, end, damping;  // damping: hertz only
  std::vector<std::pair<std::string, double>> params;  // the coefficients used
  double meff = NAN, reff = NAN;                      // reff: NaN if no radius was given
  std::vector<std::pair<std::string, double>> closed;  // closed-form predictions, where known
  collision::Result result;
  Oblique obl;
  SchemeRun sch;
  bool analytic = false;  // --analytic: closed form (collision/analytic.h) instead of the integrator
};

// Adds a closed-form prediction; skipped where the closed form does not apply (it throws).
template <class F>
void predict(Run& run, const char* key, F f) {
  try {
    const double v = f();
    if (std::isfinite(v)) run.closed.push_back({key, v});
  } catch (const std::exception&) {
  }
}

// ------------------------------------------------ oblique impacts
Oblique read_oblique(Args& a, const Bodies& b, double speed, double angle_deg) {
  Oblique o;
  o.speed = speed;
  o.angle_deg = angle_deg;
  const double spin = a.has("--spin") ? a.number("--spin", -INFINITY, INFINITY, true, true, "(-inf, inf)") : 0.0;
  double spin2 = 0.0;
  if (a.has("--spin2")) {
    if (std::isinf(b.m2) && std::isinf(b.R2)) throw BadInput("option --spin2 cannot be used with --wall");
    spin2 = a.number("--spin2", -INFINITY, INFINITY, true, true, "(-inf, inf)");
  }
  if (a.has("--tangential"))
    o.tangential = a.choice("--tangential", {"none", "cundall_strack", "linear_spring", "haff_werner", "walton_braun",
                                              "mindlin_no_slip", "di_renzo", "mindlin_deresiewicz"});
  o.active = angle_deg > 0.0 || spin != 0.0 || spin2 != 0.0 || o.tangential != "none";
  const char* oblique_only[] = {"--mu", "--kt", "--kappa", "--gammat", "--friction-limit", "--slip-reset", "--gstar",
                                "--eta-ratio", "--beta0", "--psi-kappa", "--lever-arm"};
  if (!o.active) {
    for (const char* opt : oblique_only)
      if (a.has(opt))
        throw BadInput(std::string("option ") + opt + " needs an oblique impact (--angle > 0, --spin or --tangential)");
    return o;
  }
  // bodies: solid spheres, radii needed
  if (!(b.R1 > 0.0)) throw BadInput("option --R1 is required for an oblique impact (lever arm of the friction)");
  if (!std::isinf(b.R2) && !(b.R2 > 0.0)) throw BadInput("option --R2 is required for an oblique impact of two spheres");
  o.bodies.m1 = b.m1;
  o.bodies.R1 = b.R1;
  o.bodies.m2 = b.m2;
  o.bodies.R2 = b.R2;
  o.impact.speed = speed;
  o.impact.angle = angle_deg * M_PI / 180.0;
  o.impact.omega1 = spin;
  o.impact.omega2 = spin2;
  if (a.has("--lever-arm"))
    o.opt.lever = a.choice("--lever-arm", {"radius", "contact_point"}) == "radius" ? collision::LeverArm::radius
                                                                                   : collision::LeverArm::contact_point;
  if (a.has("--beta0")) {
    o.beta0_given = true;
    o.beta0 = a.number("--beta0", -1.0, 1.0, false, false, "[-1, 1]");
  }
  if (a.has("--psi-kappa")) o.psi_kappa = a.positive("--psi-kappa");

  // tangential law parameters
  const std::string& t = o.tangential;
  auto need = [&](const char* opt) { a.require(opt, "for --tangential " + t); };
  auto refuse = [&](const char* opt) {
    if (a.has(opt)) throw BadInput(std::string("option ") + opt + " does not apply to --tangential " + t);
  };
  if (t == "none") {
    for (const char* opt : {"--mu", "--kt", "--kappa", "--gammat", "--friction-limit", "--slip-reset", "--gstar",
                            "--eta-ratio"})
      refuse(opt);
    return o;
  }
  need("--mu");
  o.mu = a.non_negative("--mu");
  if (a.has("--friction-limit"))
    o.limit = a.choice("--friction-limit", {"positive_normal", "absolute"}) == "absolute"
                  ? tangential::FrictionLimit::absolute
                  : tangential::FrictionLimit::positive_normal;
  if (a.has("--slip-reset")) {
    if (t != "linear_spring" && t != "mindlin_no_slip") refuse("--slip-reset");
    o.reset = a.choice("--slip-reset", {"spring_only", "spring_and_dashpot"}) == "spring_only"
                  ? tangential::SlipReset::spring_only
                  : tangential::SlipReset::spring_and_dashpot;
  }
  if (t == "cundall_strack" || t == "linear_spring" || t == "walton_braun") {
    for (const char* opt : {"--gstar", "--eta-ratio"}) refuse(opt);
    if (t == "walton_braun") refuse("--gammat");
    if (t == "cundall_strack" && a.has("--kt") && a.has("--kappa"))
      throw BadInput("options --kt and --kappa cannot be used together for --tangential cundall_strack");
    if (!a.has("--kt") && !a.has("--kappa"))
      throw BadInput("option --kt or --kappa is required for --tangential " + t);
    if (a.has("--kt")) o.kt = a.positive("--kt");
    if (a.has("--kappa")) o.kappa = a.positive("--kappa");
    if (a.has("--gammat")) o.gammat = a.non_negative("--gammat");
  } else if (t == "haff_werner") {
    for (const char* opt : {"--kt", "--kappa", "--gstar", "--eta-ratio"}) refuse(opt);
    need("--gammat");
    o.gammat = a.non_negative("--gammat");
  } else {  // mindlin_no_slip, di_renzo, mindlin_deresiewicz
    for (const char* opt : {"--kt", "--kappa", "--gammat"}) refuse(opt);
    if (t != "mindlin_no_slip") refuse("--eta-ratio");
    // G* from --gstar or from --E --nu [--E2 --nu2] (the materials of the Hertz normal law); E*
    // (for kappa = 4 G*/E* of psi) from --Estar or the same materials.
    if (!a.has("--gstar") && !a.has("--E"))
      throw BadInput("option --gstar (or --E with --nu) is required for --tangential " + t);
    if (a.has("--E")) {
      need("--nu");
      const double E1 = a.positive("--E");
      const double nu1 = a.poisson("--nu");
      const double E2 = a.has("--E2") ? a.positive("--E2", true) : E1;
      const double nu2 = a.has("--nu2") ? a.poisson("--nu2") : nu1;
      o.gstar = tangential::effective_shear_modulus_from_E(E1, nu1, E2, nu2);
      o.estar = tangential::effective_youngs_modulus(E1, nu1, E2, nu2);
    }
    if (a.has("--gstar")) o.gstar = a.positive("--gstar");
    if (a.has("--Estar")) o.estar = a.positive("--Estar");
    if (a.has("--eta-ratio")) o.eta_ratio = a.non_negative("--eta-ratio");
  }
  return o;
}

// A normal stiffness that stays constant through the contact (for kappa), NaN otherwise.
double constant_normal_stiffness(const Run& run) {
  const char* key = run.law == "lsd" || run.law == "extended_linear" ? "k"
                    : run.law == "walton_braun"                      ? "k_l"
                                                                     : nullptr;
  if (!key) return NAN;
  for (const auto& p : run.params)
    if (p.first == key) return p.second;
  return NAN;
}

// The closed-form reference of integrate_impact (lsd with the Cundall-Strack spring, with or without dashpot,
// or frictionless): sets run.sch.ref.
template <class Law, class TLaw>
void scheme_reference(Run& run, const Law& law, const TLaw& tlaw) {
  SchemeRun& S = run.sch;
  if (S.opt.lever_factor != 0.0) return;  // the closed form has the lever arm R
  if constexpr (std::is_same_v<Law, collision::LsdLaw> &&
                (std::is_same_v<TLaw, collision::Frictionless> ||
                 std::is_same_v<TLaw, collision::CundallStrackTangential>)) {
    namespace an = collision::analytic;
    an::Input in;
    in.m = S.setup.m;
    in.R = S.setup.R;
    in.kn = law.c.k;
    in.gn = law.c.gamma;
    in.end = law.end_mode;
    in.vn0 = S.setup.speed * std::cos(S.setup.angle);
    in.vt0 = S.setup.speed * std::sin(S.setup.angle);
    in.omega0 = S.setup.omega0;
    if constexpr (std::is_same_v<TLaw, collision::CundallStrackTangential>) {
      in.kt = tlaw.p.kt;
      in.gt = tlaw.p.gammat;
      in.rule = tlaw.rule;
      in.mu = tlaw.p.mu;
      in.limit = tlaw.limit;
    } else {
      in.kt = law.c.k;
      in.mu = 0.0;
    }
    try {
      const an::Output x = an::impact(in);
      S.ref.e = x.e;
      S.ref.beta = x.beta;
      S.ref.e_t = x.e_t;
      S.ref.omega = x.omega;
      S.ref.rebound_angle_com = x.rebound_angle_com;
      S.ref.rebound_angle_contact = x.rebound_angle_contact;
      S.have_ref = true;
    } catch (const std::exception&) {  // e.g. overdamped: no closed form
    }
  } else {
    (void)run, (void)law, (void)tlaw;
  }
}

// --scheme: integrate_impact (one run, or the phase average) into run.result / run.obl.r.
template <class Law, class TLaw>
void scheme_with(Run& run, Law& law, TLaw& tlaw) {
  SchemeRun& S = run.sch;
  Oblique& o = run.obl;
  scheme_reference(run, law, tlaw);
  collision::ImpactResult x;
  if (S.phases > 0) {
    S.pa = collision::phase_averaged(law, tlaw, S.scheme, S.setup, S.opt, S.phases, S.ref, true);
    x = S.pa.runs.front();
    x.ended = S.pa.ended == S.phases;
    if (x.ended) {  // the means over the phases
      auto mean = [&](auto get) {
        double s = 0.0;
        for (const auto& q : S.pa.runs) s += get(q);
        return s / S.phases;
      };
      using R = collision::ImpactResult;
      x.e = mean([](const R& q) { return q.e; });
      x.vn = mean([](const R& q) { return q.vn; });
      x.vt = mean([](const R& q) { return q.vt; });
      x.vs = mean([](const R& q) { return q.vs; });
      x.omega1 = mean([](const R& q) { return q.omega1; });
      x.beta = mean([](const R& q) { return q.beta; });
      x.e_t = mean([](const R& q) { return q.e_t; });
      x.rebound_angle_com = mean([](const R& q) { return q.rebound_angle_com; });
      x.rebound_angle_contact = mean([](const R& q) { return q.rebound_angle_contact; });
      x.contact_time = mean([](const R& q) { return q.contact_time; });
      x.dissipated_energy = mean([](const R& q) { return q.dissipated_energy; });
      x.slip_ratio_out = mean([](const R& q) { return q.slip_ratio_out; });
    }
  } else {
    x = collision::integrate_impact(law, tlaw, S.scheme, S.setup, S.opt);
  }
  S.one = x;
  x.kappa = o.opt.kappa;
  if (x.mu > 0.0) {
    x.psi1 = x.kappa * x.slip_ratio_in;
    x.psi2 = x.kappa * x.slip_ratio_out;
  }
  auto& res = run.result;
  res.ended = x.ended;
  res.v0 = x.vn0;
  res.restitution = x.e;
  res.rebound_velocity = x.vn;
  res.contact_time = x.contact_time;
  res.residual_overlap = NAN;
  res.dissipated_energy = x.dissipated_energy;
  res.max_overlap = x.max_overlap;
  res.max_force = x.max_normal_force;
  res.steps = x.contact_steps;
  res.dt = x.dt;
  res.contact_time_estimate = x.contact_time_estimate;
  if (S.phases == 0 && !x.samples.empty()) {
    for (const auto& q : x.samples) res.samples.push_back({q.t, q.xi, q.xi_dot, q.fn});
  }
  if (o.active) {
    o.r = x;
    o.r.residual_overlap = NAN;
    if (x.ended) {
      o.rb = collision::rigid_body_prediction(o.bodies, o.impact, std::min(std::max(x.e, 0.0), 1.0), o.mu, o.beta0);
      o.rb_valid = true;
    }
  }
}

template <class Law, class TLaw>
void oblique_with(Run& run, Law& law, TLaw& tlaw) {
  if (run.sch.active) {
    scheme_with(run, law, tlaw);
    return;
  }
  Oblique& o = run.obl;
  o.r = collision::integrate_oblique(law, tlaw, o.bodies, o.impact, o.opt);
  auto& res = run.result;
  res.ended = o.r.ended;
  res.v0 = o.r.vn0;
  res.restitution = o.r.e;
  res.rebound_velocity = o.r.vn;
  res.contact_time = o.r.contact_time;
  res.residual_overlap = o.r.residual_overlap;
  res.dissipated_energy = o.r.dissipated_energy;
  res.max_overlap = o.r.max_overlap;
  res.max_force = o.r.max_normal_force;
  res.steps = o.r.steps;
  res.dt = o.r.dt;
  res.contact_time_estimate = o.r.contact_time_estimate;
  if (o.r.ended) {
    o.rb = collision::rigid_body_prediction(o.bodies, o.impact, std::min(std::max(o.r.e, 0.0), 1.0), o.mu, o.beta0);
    o.rb_valid = true;
  }
}

template <class Law>
void run_oblique(Run& run, Law& law, const collision::Options& ho) {
  Oblique& o = run.obl;
  o.opt.dt = ho.dt;
  o.opt.record = ho.record;
  const std::string& t = o.tangential;
  const double kn = constant_normal_stiffness(run);
  auto& T = o.tparams;
  double kappa = o.psi_kappa;
  if (t == "none") {
    collision::Frictionless tl;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "cundall_strack") {
    collision::CundallStrackTangential tl;
    double kt = o.kt;
    if (std::isnan(kt)) {
      if (std::isnan(kn))
        throw BadInput("option --kappa needs a normal law with a constant stiffness (lsd, extended_linear, "
                       "walton_braun) for --tangential cundall_strack; give --kt, or use --tangential linear_spring");
      kt = o.kappa * kn;
    }
    tl.p = {kt, o.gammat, o.mu};
    tl.limit = o.limit;
    T = {{"kt", kt}, {"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_rule", "spring"}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kappa) ? kt / kn : o.kappa;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "linear_spring") {
    collision::TangentialKernelLaw<linear_spring::Params<double>, linear_spring::history_size,
                                   &linear_spring::force<double>>
        tl;
    tl.p = {std::isnan(o.kt) ? 0.0 : o.kt, std::isnan(o.kappa) ? 0.0 : o.kappa, o.gammat, o.mu, o.limit, o.reset};
    linear_spring::validate(tl.p);
    T = {{"kt", tl.p.kt}, {"kappa", tl.p.kappa}, {"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_reset", tangential::to_string(o.reset)}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kt) ? o.kappa : tl.p.kappa + tl.p.kt / kn;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "haff_werner") {
    collision::TangentialKernelLaw<haff_werner::Params<double>, haff_werner::history_size, &haff_werner::force<double>>
        tl;
    tl.p = {o.gammat, o.mu, o.limit};
    haff_werner::validate(tl.p);
    T = {{"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "mindlin_no_slip") {
    collision::TangentialKernelLaw<mindlin_no_slip::Params<double>, mindlin_no_slip::history_size,
                                   &mindlin_no_slip::force<double>>
        tl;
    tl.p = {o.gstar, o.eta_ratio, o.mu, o.limit, o.reset};
    mindlin_no_slip::validate(tl.p);
    T = {{"gstar", o.gstar}, {"eta_ratio", o.eta_ratio}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_reset", tangential::to_string(o.reset)}};
    if (std::isnan(kappa) && !std::isnan(o.estar)) kappa = tangential::kappa_hertz_mindlin(o.gstar, o.estar);
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "walton_braun") {
    collision::TangentialKernelLaw<walton_braun_tangential::Params<double>, walton_braun_tangential::history_size,
                                   &walton_braun_tangential::force<double>>
        tl;
    tl.p = {std::isnan(o.kt) ? 0.0 : o.kt, std::isnan(o.kappa) ? 0.0 : o.kappa, o.mu, o.limit};
    walton_braun_tangential::validate(tl.p);
    T = {{"kt0", tl.p.kt}, {"kappa", tl.p.kappa}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kt) ? o.kappa : tl.p.kappa + tl.p.kt / kn;
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else if (t == "mindlin_deresiewicz") {
    collision::TangentialKernelLaw<mindlin_deresiewicz::Params<double>, mindlin_deresiewicz::history_size,
                                   &mindlin_deresiewicz::force<double>>
        tl;
    tl.p = {o.gstar, o.mu, o.limit};
    mindlin_deresiewicz::validate(tl.p);
    T = {{"gstar", o.gstar}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    if (std::isnan(kappa) && !std::isnan(o.estar)) kappa = tangential::kappa_hertz_mindlin(o.gstar, o.estar);
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  } else {  // di_renzo
    collision::TangentialKernelLaw<di_renzo::Params<double>, di_renzo::history_size, &di_renzo::force<double>> tl;
    tl.p = {o.gstar, o.mu, o.limit};
    di_renzo::validate(tl.p);
    T = {{"gstar", o.gstar}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}};
    if (std::isnan(kappa) && !std::isnan(o.estar)) kappa = tangential::kappa_hertz_mindlin(o.gstar, o.estar);
    o.opt.kappa = kappa;
    oblique_with(run, law, tl);
  }
}

// The values of an oblique impact in the JSON output, in order: name, member, in degrees, only
// for two spheres.
struct ObliqueField {
  const char* name;
  double collision::ObliqueResult::*m;
  bool angle = false, pair_only = false;
};
using OR = collision::ObliqueResult;
const ObliqueField kObliqueFields[] = {
    {"vn0", &OR::vn0},
    {"vt0", &OR::vt0},
    {"vs0", &OR::vs0},
    {"spin", &OR::omega1_0},
    {"spin2", &OR::omega2_0, false, true},
    {"impact_angle_contact", &OR::impact_angle_contact, true},
    {"m_t", &OR::m_t},
    {"beta", &OR::beta},
    {"e_t", &OR::e_t},
    {"vn", &OR::vn},
    {"vt", &OR::vt},
    {"vs", &OR::vs},
    {"spin_after", &OR::omega1},
    {"spin2_after", &OR::omega2, false, true},
    {"rebound_angle_com", &OR::rebound_angle_com, true},
    {"rebound_angle_contact", &OR::rebound_angle_contact, true},
    {"mu", &OR::mu},
    {"kappa", &OR::kappa},
    {"slip_ratio_in", &OR::slip_ratio_in},
    {"slip_ratio_out", &OR::slip_ratio_out},
    {"psi1", &OR::psi1},
    {"psi2", &OR::psi2},
    {"max_tangential_force", &OR::max_tangential_force},
    {"normal_turn", &OR::normal_turn, true, true},
};

}  // namespace
