// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: a single collision with one of the tdem normal laws, without a host engine:
// head-on (src/collision/head_on.h), or oblique with spin and a tangential law
// (src/collision/oblique.h, with --angle, --spin or --tangential). Prints JSON (e, contact time,
// largest overlap and force, residual overlap, ...; beta, e_t, spin and rebound angles for oblique
// impacts) to stdout and optionally writes the force-overlap curve as CSV. With --scheme the
// sphere-wall impact is integrated in whole steps with a chosen time-integration scheme from free
// flight, as a host engine does it (src/collision/integrate_impact.h), optionally averaged over
// the start phase of the contact (--phases). See docs/tools/tdem-collide.md.
// Exit status: 0 success, 1 the contact did not end / the curve could not be written,
// 2 bad input (the message names the option, the value and the allowed range).
#include "collide_unit.h"

namespace {

Run run(Args& a) {
  Run run;
  if (a.flag("--help")) return run;
  const std::vector<std::string> laws = law_names();
  std::string law_list;
  for (const std::string& l : laws) law_list += (law_list.empty() ? "" : ", ") + l;
  a.require("--law", "(" + law_list + ")");
  run.law = a.choice("--law", laws);
  run.analytic = a.flag("--analytic");
  if (run.analytic) analytic_check_start(a, run.law);
  a.require("--v0", "(impact velocity)");
  const double speed = a.positive("--v0");
  const double angle_deg = a.has("--angle") ? a.number("--angle", 0.0, 90.0, false, true, "[0, 90) degrees") : 0.0;
  // The laws are set up for the normal impact velocity (the normal problem of an oblique impact).
  const double v0 = angle_deg > 0.0 ? speed * std::cos(angle_deg * M_PI / 180.0) : speed;

  // ------------------------------------------------ bodies
  Bodies b;
  if (a.has("--R1")) b.R1 = a.positive("--R1");
  double rho = 0.0;
  if (a.has("--rho")) rho = a.positive("--rho");
  if (a.has("--m1")) {
    a.forbid("--rho", "together with --m1 (give the mass or the density of sphere 1)");
    b.m1 = a.positive("--m1");
  } else {
    if (!a.has("--rho")) throw BadInput("option --m1 (or --rho with --R1) is required for the mass of sphere 1");
    a.require("--R1", "with --rho");
    b.m1 = collision::sphere_mass(b.R1, rho);
  }
  if (a.flag("--wall")) {
    for (const char* o : {"--m2", "--R2", "--rho2"}) a.forbid(o, "with --wall");
  } else {
    if (a.has("--R2")) b.R2 = a.positive("--R2");
    else b.R2 = 0.0;  // unknown
    if (a.has("--m2")) {
      a.forbid("--rho2", "together with --m2");
      b.m2 = a.positive("--m2");
    } else {
      const double rho2 = a.has("--rho2") ? a.positive("--rho2") : rho;
      if (!(rho2 > 0.0)) throw BadInput("option --m2 (or --R2 with --rho/--rho2) is required for sphere 2, or give --wall");
      a.require("--R2", "with a density for sphere 2");
      b.m2 = collision::sphere_mass(b.R2, rho2);
    }
  }
  const double meff = b.meff();
  run.meff = meff;
  if (b.R1 > 0.0 && (std::isinf(b.R2) || b.R2 > 0.0)) run.reff = b.reff();
  auto& P = run.params;

  collision::Options opt;
  if (a.has("--dt")) {
    a.forbid("--steps", "together with --dt");
    opt.dt = a.positive("--dt");
  } else if (a.has("--steps")) {
    opt.steps_per_contact = static_cast<int>(a.number("--steps", 1.0, 1e6, false, false, "[1, 1e6]"));
    if (opt.steps_per_contact != a.number("--steps", 1.0, 1e6, false, false, "[1, 1e6]"))
      throw BadInput("option --steps = " + a.str("--steps") + " is not an integer in [1, 1e6]");
  }
  opt.record = a.has("--curve");
  if (opt.record) a.str("--curve");
  run.obl = read_oblique(a, b, speed, angle_deg);
  if (a.has("--scheme")) {
    SchemeRun& S = run.sch;
    const std::string name = a.str("--scheme");
    if (!collision::parse_impact_scheme(name, S.scheme))
      throw BadInput("option --scheme = '" + name + "' is not one of: " + collision::impact_scheme_names(", "));
    S.active = true;
    if (run.analytic) throw BadInput("option --scheme cannot be used with --analytic (no time stepping)");
    if (!a.has("--wall"))
      throw BadInput("option --scheme needs --wall (the whole-step integration is a sphere-wall impact)");
    a.require("--R1", "with --scheme (the sphere starts at z = R1 + gap)");
    S.setup.m = b.m1;
    S.setup.R = b.R1;
    S.setup.speed = speed;
    S.setup.angle = angle_deg * M_PI / 180.0;
    S.setup.omega0 = run.obl.active ? run.obl.impact.omega1 : 0.0;
    if (a.has("--gap")) S.setup.gap = a.non_negative("--gap");
    if (a.has("--phases")) {
      const double p = a.number("--phases", 1.0, 10000.0, false, false, "[1, 10000]");
      if (p != std::floor(p)) throw BadInput("option --phases = " + a.str("--phases") + " is not an integer in [1, 10000]");
      S.phases = static_cast<int>(p);
      if (a.has("--curve")) throw BadInput("option --curve cannot be used with --phases (one curve per run)");
    }
    if (a.has("--grid-correction")) {
      S.opt.grid_correction = a.choice("--grid-correction", {"off", "on"}) == "on";
      if (S.opt.grid_correction && S.scheme.multi)
        throw BadInput("option --grid-correction on needs a one-evaluation scheme (the host's step); '" + name +
                       "' evaluates the force " + std::to_string(S.scheme.evaluations()) + " times per step");
    }
    if (a.has("--energy")) {
      S.opt.energy = a.choice("--energy", {"off", "on"}) == "on";
      if (S.opt.energy && S.scheme.multi)
        throw BadInput("option --energy on needs a one-evaluation scheme (the work of the force applied "
                       "once per step); '" + name + "' evaluates the force " + std::to_string(S.scheme.evaluations()) +
                       " times per step");
    }
    S.opt.dt = opt.dt;
    S.opt.lever_factor = run.obl.opt.lever == collision::LeverArm::contact_point ? 0.5 : 0.0;
    S.opt.steps_per_contact = a.has("--steps") ? opt.steps_per_contact : 1000;
    S.opt.record = opt.record;
  } else {
    for (const char* o : {"--gap", "--phases", "--grid-correction", "--energy"})
      if (a.has(o)) throw BadInput(std::string("option ") + o + " needs --scheme");
  }
  if (run.analytic) analytic_check_oblique(a, run.obl);
  if (run.obl.active && a.has("--steps")) run.obl.opt.steps_per_contact = opt.steps_per_contact;

  // ------------------------------------------------ laws
  const int unit = tdem::law::index_of<tdem::law::normal_units>(run.law.c_str());
  if (a.has("--params")) {
    run_unit(run, a, unit, b, meff, v0, opt);
  } else if (run.law == "lsd") {
    collision::LsdLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--e")) {
      a.forbid("--gamma", "together with --e (the damping follows from e)");
      const double e = a.restitution("--e");
      if (a.has("--tc")) {
        a.forbid("--k", "together with --e and --tc");
        law.c = lsd::from_restitution_and_time(e, a.positive("--tc"), meff, law.end_mode);
      } else {
        a.require("--k", "with --e (or give --tc)");
        law.c = lsd::from_restitution_and_stiffness(e, a.positive("--k"), meff, law.end_mode);
      }
    } else {
      a.require("--k", "for --law lsd (or --e with --tc)");
      law.c = {a.positive("--k"), a.has("--gamma") ? a.non_negative("--gamma") : 0.0};
    }
    run.end = to_string(law.end_mode);
    P = {{"k", law.c.k}, {"gamma", law.c.gamma}};
    predict(run, "e", [&] { return lsd::restitution(law.c, meff, law.end_mode); });
    predict(run, "contact_time", [&] { return lsd::contact_time(law.c, meff, law.end_mode); });
    predict(run, "max_overlap", [&] { return lsd::max_overlap(law.c, meff, v0); });
    a.check_all_used(run.law);
    if (run.analytic) run_analytic(run, law, b, v0);
    else go(run, law, b, v0, opt);
  } else if (run.law == "hertz") {
    collision::HertzLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--k")) {
      law.p.k = a.positive("--k");
    } else if (a.has("--tc")) {
      law.p.k = hertz::stiffness_from_contact_time(a.positive("--tc"), meff, v0);
    } else {
      const double es = read_modulus(a);
      law.p.k = hertz::stiffness(es, need_reff(b, "for the Hertz stiffness from the modulus"));
      P.push_back({"Estar", es});
    }
    const std::string d = a.has("--damping")
                              ? a.choice("--damping", {"none", "linear", "kuwabara_kono", "tsuji", "general"})
                              : "none";
    law.p.damp = 0.0;
    law.p.theta = 0.0;
    // --e for the damping forms without a closed form: root search over the collision (conversions.h).
    auto damping_from_e = [&](collision::HertzLaw& l) {
      if (!a.has("--e")) return false;
      a.forbid("--gamma", "together with --e (the damping follows from e)");
      const double e = a.number("--e", 0.0, 1.0, true, true, "(0, 1)");
      l.p.damp = collision::hertz_damping_for_restitution(l.damping, l.end_mode, l.p, b, v0, e);
      return true;
    };
    if (d == "none") {
      law.damping = hertz::Damping::linear;
    } else if (d == "linear") {
      law.damping = hertz::Damping::linear;
      if (!damping_from_e(law)) {
        a.require("--gamma", "(or --e) for --damping linear");
        law.p.damp = a.non_negative("--gamma");
      }
    } else if (d == "kuwabara_kono") {
      law.damping = hertz::Damping::kuwabara_kono;
      if (damping_from_e(law)) {
        a.forbid("--A", "together with --e");
      } else if (a.has("--A")) {
        a.forbid("--gamma", "together with --A");
        law.p.damp = hertz::kuwabara_kono_damping(a.non_negative("--A"), law.p.k);
      } else {
        a.require("--gamma", "(or --A, or --e) for --damping kuwabara_kono");
        law.p.damp = a.non_negative("--gamma");
      }
    } else if (d == "tsuji") {
      law.damping = hertz::Damping::tsuji;
      if (a.has("--e")) {
        a.forbid("--alpha", "together with --e");
        law.p.damp = hertz::tsuji_alpha_from_restitution(a.restitution("--e"), law.end_mode);
      } else {
        a.require("--alpha", "(or --e) for --damping tsuji");
        law.p.damp = a.non_negative("--alpha");
      }
    } else {
      law.damping = hertz::Damping::general;
      a.require("--theta", "for --damping general");
      law.p.theta = a.non_negative("--theta");
      if (!damping_from_e(law)) {
        a.require("--gamma", "(or --e) for --damping general");
        law.p.damp = a.non_negative("--gamma");
      }
    }
    hertz::validate(law.damping, law.p);
    run.end = to_string(law.end_mode);
    P.push_back({"k", law.p.k});
    P.push_back({law.damping == hertz::Damping::tsuji ? "alpha" : "damping", law.p.damp});
    if (law.damping == hertz::Damping::general) P.push_back({"theta", law.p.theta});
    if (law.p.damp == 0.0) {
      predict(run, "e", [] { return 1.0; });
      predict(run, "contact_time", [&] { return hertz::contact_time_elastic(law.p.k, meff, v0); });
      predict(run, "max_overlap", [&] { return hertz::max_overlap_elastic(law.p.k, meff, v0); });
    } else if (law.damping == hertz::Damping::tsuji) {
      predict(run, "e", [&] { return hertz::tsuji_restitution(law.p.damp, law.end_mode); });
    }
    run.damping = d;
    a.check_all_used("hertz");
    go(run, law, b, v0, opt);
  } else if (run.law == "walton_braun") {
    collision::WaltonBraunLaw law;
    only_zero_force_end(a, "walton_braun");
    if (a.has("--e")) {
      a.forbid("--kul", "together with --e");
      a.forbid("--s", "together with --e");
      const double e = a.restitution("--e");
      if (a.has("--tc")) {
        a.forbid("--kl", "together with --e and --tc");
        law.p = walton_braun::from_restitution_and_time(e, a.positive("--tc"), meff);
      } else {
        a.require("--kl", "with --e (or give --tc)");
        law.p = walton_braun::from_restitution_and_stiffness(e, a.positive("--kl"));
      }
    } else {
      a.require("--kl", "for --law walton_braun (or --e with --tc)");
      const double kl = a.positive("--kl");
      const double ku = a.has("--kul") ? a.positive("--kul") : kl;
      if (ku < kl)
        throw BadInput("option --kul = " + num_str(ku) + " is outside the allowed range [k_l, inf) = [" +
                       num_str(kl) + ", inf)");
      law.p = {kl, ku, a.has("--s") ? a.non_negative("--s") : 0.0};
    }
    walton_braun::validate(law.p);
    run.end = "zero_force";
    P = {{"k_l", law.p.k_load}, {"k_u", law.p.k_unload}, {"s", law.p.slope}};
    predict(run, "e", [&] { return walton_braun::restitution(law.p, meff, v0); });
    predict(run, "contact_time", [&] { return walton_braun::contact_time(law.p, meff, v0); });
    predict(run, "max_overlap", [&] { return walton_braun::max_overlap(law.p, meff, v0); });
    predict(run, "residual_overlap", [&] {
      return walton_braun::residual_overlap_ratio(law.p, meff, v0) * walton_braun::max_overlap(law.p, meff, v0);
    });
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  } else if (run.law == "thornton") {
    collision::ThorntonLaw law;
    only_zero_force_end(a, "thornton");
    law.p.e_star = read_modulus(a);
    const double reff = need_reff(b, "for --law thornton");
    int n_yield = a.has("--py") + a.has("--vy") + a.has("--e");
    if (n_yield != 1) throw BadInput("exactly one of --py, --vy, --e is required for --law thornton");
    if (a.has("--py")) law.p.p_y = a.positive("--py");
    else if (a.has("--vy")) law.p.p_y = thornton::yield_pressure_from_yield_velocity(a.positive("--vy"), law.p.e_star, reff, meff);
    else {
      const double e = a.number("--e", 0.0, 1.0, true, true, "(0, 1)");
      law.p.p_y = thornton::yield_pressure_from_restitution(e, v0, law.p.e_star, reff, meff);
    }
    thornton::validate(law.p);
    run.end = "zero_force";
    P = {{"Estar", law.p.e_star}, {"p_y", law.p.p_y}, {"xi_y", thornton::yield_overlap(law.p, reff)},
         {"v_y", thornton::yield_velocity(law.p, reff, meff)}};
    predict(run, "e", [&] { return thornton::restitution(law.p, reff, meff, v0); });
    predict(run, "max_overlap", [&] { return thornton::max_overlap(law.p, reff, meff, v0); });
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  } else if (run.law == "power_law") {
    collision::PowerLawLaw law;
    only_zero_force_end(a, "power_law");
    a.require("--al", "for --law power_law");
    a.require("--p", "for --law power_law");
    law.p.a_load = a.positive("--al");
    law.p.p = a.positive("--p");
    if (a.has("--e")) {
      a.forbid("--aul", "together with --e");
      a.forbid("--q", "together with --e (q = 0)");
      law.p = power_law::from_restitution(law.p.a_load, law.p.p, a.restitution("--e"));
    } else {
      a.require("--aul", "(or --e) for --law power_law");
      law.p.a_unload = a.positive("--aul");
      law.p.q = a.has("--q") ? a.non_negative("--q") : 0.0;
    }
    power_law::validate(law.p);
    run.end = "zero_force";
    P = {{"a_l", law.p.a_load}, {"p", law.p.p}, {"a_ul", law.p.a_unload}, {"q", law.p.q}};
    predict(run, "e", [&] { return power_law::restitution(law.p, meff, v0); });
    predict(run, "contact_time", [&] { return power_law::contact_time(law.p, meff, v0); });
    predict(run, "max_overlap", [&] { return power_law::max_overlap(law.p, meff, v0); });
    predict(run, "residual_overlap", [&] { return power_law::residual_overlap(law.p, meff, v0); });
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  } else if (run.law == "extended_linear") {
    collision::ExtendedLinearLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    law.p.e_fit = read_fit(a, "--e-fit", "--e-coef", 'e');
    law.p.tc_fit = read_fit(a, "--tc-fit", "--tc-coef", 't');
    law.p.range = read_range(a);
    extended::validate(law.p);
    run.end = to_string(law.end_mode);
    fit_params(P, "e_fit", law.p.e_fit);
    fit_params(P, "tc_fit", law.p.tc_fit);
    const auto c = extended::linear_coefficients(law.end_mode, law.p, meff, v0);
    P.push_back({"k", c.k});
    P.push_back({"gamma", c.gamma});
    predict(run, "e", [&] { return extended::linear_restitution(law.p, v0); });
    predict(run, "contact_time", [&] { return extended::linear_contact_time(law.p, v0); });
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  } else if (run.law == "extended_hertz") {
    collision::ExtendedHertzLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--k")) {
      law.p.k = a.positive("--k");
    } else {
      const double es = read_modulus(a);
      law.p.k = hertz::stiffness(es, need_reff(b, "for the Hertz stiffness from the modulus"));
      P.push_back({"Estar", es});
    }
    law.p.e_fit = read_fit(a, "--e-fit", "--e-coef", 'e');
    law.p.range = read_range(a);
    extended::validate(law.p);
    run.end = to_string(law.end_mode);
    P.push_back({"k", law.p.k});
    fit_params(P, "e_fit", law.p.e_fit);
    P.push_back({"alpha", extended::hertz_alpha(law.end_mode, law.p.e_fit, law.p.range, v0)});
    predict(run, "e", [&] { return extended::hertz_restitution(law.p, v0); });
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  } else {  // continuous_potential
    collision::ContinuousPotentialLaw law;
    law.end_mode = read_end(a, ContactEnd::zero_overlap);
    if (a.has("--d")) {
      law.p.d = a.positive("--d");
    } else {
      if (!(b.R1 > 0.0)) throw BadInput("option --d (or --R1) is required for --law continuous_potential");
      if (!std::isinf(b.R2) && !(b.R2 > 0.0)) throw BadInput("option --d (or --R2) is required for --law continuous_potential");
      law.p.d = std::isinf(b.R2) ? b.R1 : b.R1 + b.R2;
    }
    law.p.n = a.has("--n") ? a.positive("--n") : 36.0;
    law.p.x_cut = a.has("--x-cut") ? a.positive("--x-cut", true) : INFINITY;
    law.p.gamma = a.has("--gamma") ? a.non_negative("--gamma") : 0.0;
    if (a.has("--x-min")) {
      a.forbid("--eps", "together with --x-min");
      const double x_min = a.positive("--x-min");
      const double x_start = std::isinf(law.p.x_cut) ? law.p.d : law.p.x_cut;
      if (!(x_min < x_start))
        throw BadInput("option --x-min = " + num_str(x_min) + " is outside the allowed range (0, X_start) = (0, " +
                       num_str(x_start) + ") (X_start: --x-cut, or --d without a cut-off)");
      law.p.eps = continuous_potential::energy_for_closest_approach(x_min, meff, v0, law.p.d, law.p.n,
                                                                    std::isinf(law.p.x_cut) ? law.p.d : law.p.x_cut);
    } else {
      a.require("--eps", "(or --x-min) for --law continuous_potential");
      law.p.eps = a.positive("--eps");
    }
    continuous_potential::validate(law.p);
    run.end = to_string(law.end_mode);
    P = {{"eps", law.p.eps}, {"d", law.p.d}, {"n", law.p.n}, {"x_cut", law.p.x_cut}, {"gamma", law.p.gamma}};
    if (law.p.gamma == 0.0) {
      predict(run, "e", [] { return 1.0; });
      predict(run, "max_overlap", [&] {
        auto from_start = law.p;  // energy counted from the start of the collision
        from_start.x_cut = law.p.d - law.start_overlap();
        return law.p.d - continuous_potential::closest_approach(from_start, meff, v0);
      });
    }
    a.check_all_used(run.law);
    go(run, law, b, v0, opt);
  }
  return run;
}

void write_oblique(Json& j, const Oblique& o) {
  const auto& x = o.r;
  const double deg = 180.0 / M_PI;
  const bool wall = o.bodies.wall();
  j.str("collision", wall ? "oblique_sphere_wall" : "oblique_sphere_sphere");
  j.str("tangential", o.tangential);
  j.open("tangential_parameters");
  for (const auto& p : o.tparams) j.num(p.first, p.second);
  for (const auto& p : o.tchoices) j.str(p.first, p.second);
  j.close();
  j.str("lever_arm", collision::to_string(o.opt.lever));
  j.num("speed", o.speed);
  j.num("angle", o.angle_deg);
  // NaN (null) where the impact did not end or the ratio is undefined (no tangential velocity)
  for (const ObliqueField& f : kObliqueFields)
    if (!(f.pair_only && wall)) j.num(f.name, x.*f.m * (f.angle ? deg : 1.0));
  j.boolean("sliding_at_start", x.sliding_at_start);
  std::string sw = "[";
  for (size_t i = 0; i < x.switches.size(); ++i) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s{\"t\": %.17g, \"to\": \"%s\"}", i ? ", " : "", x.switches[i].t,
                  x.switches[i].sliding ? "slip" : "stick");
    sw += buf;
  }
  sw += "]";
  j.raw("stick_slip_switches", sw);
  j.integer("n_switches", x.n_switches);
  j.open("rigid_body");
  j.num("beta0", o.beta0);
  j.boolean("beta0_assumed", !o.beta0_given);
  if (o.rb_valid) {
    j.num("e", o.rb.vn / x.vn0);
    j.num("mu", x.mu);
    j.boolean("gross_sliding", o.rb.gross_sliding);
    j.num("beta", o.rb.beta);
    j.num("e_t", o.rb.e_t);
    j.num("vt", o.rb.vt);
    j.num("vs", o.rb.vs);
    j.num("spin_after", o.rb.omega1);
    if (!wall) j.num("spin2_after", o.rb.omega2);
    j.num("rebound_angle_com", o.rb.rebound_angle_com * deg);
    j.num("rebound_angle_contact", o.rb.rebound_angle_contact * deg);
    j.num("slip_ratio_gross_sliding", o.rb.psi_slide);
  }
  j.close();
}

void write_scheme(Json& j, const Run& r) {
  const SchemeRun& S = r.sch;
  const double deg = 180.0 / M_PI;
  j.str("scheme", S.scheme.name());
  j.str("grid_correction", S.opt.grid_correction ? "on" : "off");
  j.num("gap", S.setup.gap);
  j.integer("evaluations_per_step", S.scheme.evaluations());
  j.integer("history_per_particle", S.scheme.history());
  j.integer("contact_steps", S.one.contact_steps);
  j.integer("total_steps", S.one.steps);
  if (S.opt.energy) {  // -W of each part (contact/energy.h) of the single run
    const collision::ImpactResult& x = S.one;
    j.open("energy");
    j.open("dissipated");
    for (int p = 0; p < energy::kParts; ++p) j.num(energy::part_names[p], -x.work.w[p]);
    j.close();
    j.num("total", -x.work.total());
    j.num("kinetic_lost", x.dissipated_energy);
    j.num("balance_residual_max", x.energy_residual_max);
    j.num("balance_residual_end", x.energy_residual_end);
    j.close();
  }
  if (S.phases > 0) {
    j.integer("phases", S.phases);
    std::string es = "[";
    for (size_t i = 0; i < S.pa.runs.size(); ++i) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%s%.17g", i ? ", " : "", S.pa.runs[i].e);
      es += S.pa.runs[i].ended ? buf : (i ? ", null" : "null");
    }
    j.raw("phase_e", es + "]");
  } else {
    j.null("phases");
  }
  if (!S.have_ref) {
    j.null("reference");
    j.null("abs_error");
    return;
  }
  const collision::ImpactResult& x = S.one;
  j.open("reference");
  j.str("method", "analytic");
  j.num("e", S.ref.e);
  j.num("beta", S.ref.beta);
  j.num("e_t", S.ref.e_t);
  j.num("spin_after", S.ref.omega);
  j.num("rebound_angle_com", S.ref.rebound_angle_com * deg);
  j.num("rebound_angle_contact", S.ref.rebound_angle_contact * deg);
  j.close();
  j.open("abs_error");  // mean over the phases with --phases
  if (S.phases > 0) {
    j.num("e", S.pa.e);
    j.num("beta", S.pa.beta);
    j.num("e_t", S.pa.e_t);
    j.num("spin_after", S.pa.omega);
    j.num("rebound_angle_com", S.pa.rebound_angle_com * deg);
    j.num("rebound_angle_contact", S.pa.rebound_angle_contact * deg);
  } else {
    j.num("e", std::fabs(x.e - S.ref.e));
    j.num("beta", std::fabs(x.beta - S.ref.beta));
    j.num("e_t", std::fabs(x.e_t - S.ref.e_t));
    j.num("spin_after", std::fabs(x.omega1 - S.ref.omega));
    j.num("rebound_angle_com", std::fabs(x.rebound_angle_com - S.ref.rebound_angle_com) * deg);
    j.num("rebound_angle_contact", std::fabs(x.rebound_angle_contact - S.ref.rebound_angle_contact) * deg);
  }
  j.close();
}

}  // namespace

int main(int argc, char** argv) {
  Run r;
  std::string curve;
  try {
    Args a(argc, argv);
    if (a.has("--help")) {
      std::fputs(kHelp, stdout);
      return 0;
    }
    r = run(a);
    if (a.has("--curve")) curve = a.str("--curve");
  } catch (const BadInput& e) {
    std::fprintf(stderr, "tdem-collide: error: %s\n", e.what());
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "tdem-collide: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tdem-collide: error: %s\n", e.what());
    return 1;
  }
  const auto& res = r.result;
  int status = 0;
  if (!curve.empty()) {
    std::FILE* f = std::fopen(curve.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "tdem-collide: error: cannot write the curve file '%s': %s\n", curve.c_str(),
                   std::strerror(errno));
      status = 1;
    } else {
      if (r.obl.active) {
        std::fputs("t,xi,xi_dot,F,Ft,vs,sliding\n", f);
        for (const auto& s : r.obl.r.samples)
          std::fprintf(f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", s.t, s.xi, s.xi_dot, s.fn, s.ft, s.vs,
                       s.sliding ? 1 : 0);
      } else {
        std::fputs("t,xi,xi_dot,F\n", f);
        for (const auto& s : res.samples) std::fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", s.t, s.xi, s.xi_dot, s.force);
      }
      if (std::fclose(f) != 0) status = 1;
    }
  }
  Json j;
  j.str("law", r.law);
  j.str("method", r.analytic ? "analytic" : "integrated");
  j.str("end", r.end);
  if (!r.damping.empty()) j.str("damping", r.damping);
  j.open("parameters");
  for (const auto& p : r.params) j.num(p.first, p.second);
  j.close();
  j.num("m_eff", r.meff);
  j.num("r_eff", r.reff);
  j.num("v0", res.v0);
  j.boolean("ended", res.ended);
  if (res.ended) {
    j.num("e", res.restitution);
    j.num("contact_time", res.contact_time);
    j.num("rebound_velocity", res.rebound_velocity);
    j.num("residual_overlap", res.residual_overlap);
    j.num("dissipated_energy", res.dissipated_energy);
  } else {
    for (const char* k : {"e", "contact_time", "rebound_velocity", "residual_overlap", "dissipated_energy"}) j.null(k);
  }
  j.num("max_overlap", res.max_overlap);
  j.num("max_force", res.max_force);
  j.integer("steps", res.steps);
  j.num("dt", res.dt);
  j.num("contact_time_estimate", res.contact_time_estimate);
  j.open("closed_form");
  for (const auto& p : r.closed) j.num(p.first, p.second);
  j.close();
  if (!curve.empty()) j.str("curve", curve);
  else j.null("curve");
  if (r.sch.active) write_scheme(j, r);
  if (r.obl.active) write_oblique(j, r.obl);
  std::fputs(j.done().c_str(), stdout);
  if (res.ended && res.steps < 20 && !r.analytic)
    std::fprintf(stderr, "tdem-collide: warning: only %ld steps in the contact; use a smaller --dt or more --steps\n",
                 res.steps);
  if (!res.ended) {
    std::fprintf(stderr, "tdem-collide: the contact did not end within %ld steps (t = %g s)%s\n", res.steps,
                 res.steps * res.dt, res.steps >= collision::Options().max_steps ? "; is --dt too small?" : "");
    return 1;
  }
  return status;
}
