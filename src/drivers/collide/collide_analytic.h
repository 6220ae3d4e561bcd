// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: the analytical solution of the linear viscoelastic + Coulomb contact (--analytic). A part of main.cpp (collide_common.h).
#pragma once

#include "collide_common.h"
#include "collide_oblique.h"

namespace {

// ------------------------------------------------ --analytic
constexpr const char* kAnalyticSupports =
    "--analytic supports a sphere-wall (--wall) or two-sphere impact with --law lsd (--k/--gamma, --e with --k "
    "or --tc, either --end) and --tangential none or cundall_strack (--mu, --kt or --kappa, --gammat, "
    "--friction-limit), lever arm radius, no --curve/--steps/--dt";

// Refuses what the closed form cannot do (before the laws read their options).
void analytic_check_start(Args& a, const std::string& law) {
  if (law != "lsd")
    throw BadInput("option --analytic does not support --law " + law + " (" + kAnalyticSupports + ")");
  for (const char* opt : {"--curve", "--steps", "--dt"})
    if (a.has(opt))
      throw BadInput(std::string("option ") + opt + " cannot be used with --analytic (no time stepping; " +
                     kAnalyticSupports + ")");
}

void analytic_check_oblique(Args& a, const Oblique& o) {
  if (o.tangential != "none" && o.tangential != "cundall_strack")
    throw BadInput("option --analytic does not support --tangential " + o.tangential + " (" + kAnalyticSupports +
                   ")");
  if (o.opt.lever != collision::LeverArm::radius)
    throw BadInput(std::string("option --lever-arm contact_point cannot be used with --analytic (") +
                   kAnalyticSupports + ")");
}

// The closed-form impact on a wall or of two spheres (lsd normal law, Cundall-Strack spring with
// or without a dashpot, or frictionless).
void run_analytic(Run& run, const collision::LsdLaw& law, const Bodies& b, double v0) {
  Oblique& o = run.obl;
  namespace an = collision::analytic;
  const bool wall = std::isinf(b.m2);
  an::Input in;
  in.m = b.m1;
  in.R = b.R1 > 0.0 ? b.R1 : 1.0;  // head-on without a radius: the lever arm plays no role
  in.I = 0.0;                      // solid sphere, as the integrator
  if (!wall) {
    in.m2 = b.m2;
    in.R2 = std::isfinite(b.R2) && b.R2 > 0.0 ? b.R2 : 1.0;  // idem
    in.I2 = 0.0;
    in.omega2 = o.active ? o.impact.omega2 : 0.0;
  }
  in.kn = law.c.k;
  in.gn = law.c.gamma;
  in.end = law.end_mode;
  const bool friction = o.tangential == "cundall_strack";
  double kt = NAN;
  double kappa = o.psi_kappa;
  if (friction) {
    kt = std::isnan(o.kt) ? o.kappa * law.c.k : o.kt;
    in.kt = kt;
    in.gt = o.gammat;
    in.rule = cundall_strack::SlipRule::spring_cap;  // as CundallStrackTangential in run_oblique
    in.mu = o.mu;
    in.limit = o.limit;
    o.tparams = {{"kt", kt}, {"gammat", o.gammat}, {"mu", o.mu}};
    o.tchoices = {{"friction_limit", tangential::to_string(o.limit)}, {"slip_rule", "spring"}};
    if (std::isnan(kappa)) kappa = std::isnan(o.kappa) ? kt / law.c.k : o.kappa;
  } else {
    in.kt = law.c.k;  // unused without friction (mu = 0)
    in.mu = 0.0;
  }
  in.vn0 = v0;
  in.vt0 = o.active ? o.impact.speed * std::sin(o.impact.angle) : 0.0;
  in.omega0 = o.active ? o.impact.omega1 : 0.0;
  const an::Output x = an::impact(in);
  const an::Normal nrm = an::make_normal(in);
  const double I = an::inertia1(in), I2 = an::inertia2(in);

  // normal closed forms: largest overlap (xi' = 0) and force (F' = 0, or F(0) = gamma v0)
  const double t_xmax = std::atan2(nrm.w, nrm.delta) / nrm.w;
  const double A = (nrm.k - nrm.g * nrm.delta) / nrm.w;
  double t_fmax = std::atan2(nrm.w * A - nrm.delta * nrm.g, nrm.delta * A + nrm.w * nrm.g) / nrm.w;
  t_fmax = std::min(std::max(t_fmax, 0.0), nrm.t_end);
  // sphere 2 at rest before (v2n0 = v2t0 = 0), as in integrate_oblique
  double ke0 = 0.5 * in.m * (in.vn0 * in.vn0 + in.vt0 * in.vt0) + 0.5 * I * in.omega0 * in.omega0;
  double ke1 = 0.5 * in.m * (x.v1n * x.v1n + x.v1t * x.v1t) + 0.5 * I * x.omega * x.omega;
  if (!wall) {
    ke0 += 0.5 * I2 * in.omega2 * in.omega2;
    ke1 += 0.5 * in.m2 * (x.v2n * x.v2n + x.v2t * x.v2t) + 0.5 * I2 * x.omega2 * x.omega2;
  }

  auto& res = run.result;
  res.ended = true;
  res.v0 = v0;
  res.restitution = x.e;
  res.rebound_velocity = x.vn;
  res.contact_time = x.contact_time;
  res.residual_overlap = in.end == ContactEnd::zero_overlap ? 0.0 : nrm.xi(nrm.t_end);
  res.dissipated_energy = ke0 - ke1;
  res.max_overlap = nrm.xi(t_xmax);
  res.max_force = std::max(nrm.fn(0.0), nrm.fn(t_fmax));
  res.steps = 0;
  res.dt = NAN;
  res.contact_time_estimate = x.contact_time;
  if (!o.active) return;

  collision::ObliqueResult& r = o.r;
  r.ended = true;
  r.vn0 = in.vn0;
  r.vt0 = in.vt0;
  r.vs0 = x.vs0;
  r.omega1_0 = in.omega0;
  r.omega2_0 = in.omega2;
  r.impact_angle = std::atan2(r.vt0, r.vn0);
  r.impact_angle_contact = std::atan2(r.vs0, r.vn0);
  r.e = x.e;
  r.vn = x.vn;
  r.vt = x.vt;
  r.vs = x.vs;
  r.omega1 = x.omega;
  r.omega2 = x.omega2;
  r.normal_turn = 0.0;  // the closed form keeps the contact frame fixed
  r.beta = x.beta;
  r.e_t = x.e_t;
  r.rebound_angle_com = x.rebound_angle_com;
  r.rebound_angle_contact = x.rebound_angle_contact;
  r.mu = in.mu;
  r.kappa = kappa;
  if (r.mu > 0.0) {
    r.slip_ratio_in = x.slip_ratio_in;
    r.slip_ratio_out = x.slip_ratio_out;
    r.psi1 = r.kappa * r.slip_ratio_in;
    r.psi2 = r.kappa * r.slip_ratio_out;
  }
  r.contact_time = x.contact_time;
  r.max_overlap = res.max_overlap;
  r.max_normal_force = res.max_force;
  r.max_tangential_force = NAN;  // not evaluated by the closed form
  r.residual_overlap = res.residual_overlap;
  r.dissipated_energy = res.dissipated_energy;
  r.m_n = x.m_n;
  r.m_t = x.m_t;
  r.sliding_at_start = x.sliding_at_start;
  for (const auto& s : x.switches) r.switches.push_back({s.t, s.sliding});
  r.n_switches = static_cast<long>(x.switches.size());
  r.dt = NAN;
  r.steps = 0;
  r.contact_time_estimate = x.contact_time;
  o.rb = collision::rigid_body_prediction(o.bodies, o.impact, std::min(std::max(x.e, 0.0), 1.0), o.mu, o.beta0);
  o.rb_valid = true;
}

}  // namespace
