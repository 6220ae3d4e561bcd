// SPDX-License-Identifier: GPL-2.0-or-later
// tdem integrator study driver (validation/integrators/run.sh compiles it against src/, header-only):
// for every scheme of collision/integrate_impact.h (the 18 one-evaluation schemes of
// integrators/schemes.h and heun, rk4, vv2, abm4_pece; the one-evaluation ones once more with the
// time-grid correction of contact/grid_correction.h, named SCHEME+gc) and N = 5 ... 500 steps per
// contact, the phase-averaged |error| (P start phases, gap = (i + 1/2)/P v_n0 dt) of e, beta, e_t,
// spin, the contact time (relative; steps x dt, or the interpolated time of a corrected run) and the
// rebound angles against the closed form of collision/analytic.h, on two step grids:
//   integer  dt = t_c/N exactly (physics_reference 5.2 convention: the contact lasts a whole number
//            of steps, the end of contact falls at the same grid phase as the start);
//   generic  dt = t_c/(N + f), averaged over f = 1/8, 3/8, 5/8, 7/8 (a step that is not a whole
//            fraction of the contact time, as in any real simulation).
// Cases: headon_52   physics_reference 5.2 (m = 0.01 kg, k = 1e5 N/m, gamma = 4.48097 kg/s,
//                    variant A = zero_overlap end, frictionless, |v| = 1 m/s, R = 0.01 m);
//        headon_52_zf  the same with the zero-force end (e = 0.8081);
//        oblique_THETA  8.5(a): R = 2.5 mm, rho = 4000, LSD from e = 0.98, t_n = 1e-5 s (variant-A
//                    formulas), zero_force end, Cundall-Strack kappa = 2/7, mu = 0.092, |v| = 3.9 m/s.
//        headon_hertz_tsuji  Hertz + Tsuji damping (force continuous at touch), 8.2 steel sphere,
//                    alpha = 0.2, v0 = 1 m/s; reference e from head_on.h (RK4, located end).
// Output CSV on stdout, one line per case, scheme, grid, N.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "collision/analytic.h"
#include "collision/integrate_impact.h"
#include "collision/phase_average.h"

using namespace tdem;
using namespace tdem::collision;

namespace {

template <class Law>
struct Case {
  std::string name;
  Law law;
  CundallStrackTangential cs;  // mu = 0: frictionless
  ImpactSetup setup;
  ImpactReference ref;
  double tc = 0.0;
};

Case<LsdLaw> make_case(const std::string& name, double m, double R, double kn, double gn, ContactEnd end, double kt,
                       double mu, double speed, double theta_deg) {
  Case<LsdLaw> c;
  c.name = name;
  c.law.c = {kn, gn};
  c.law.end_mode = end;
  c.cs.p = {kt, 0.0, mu};
  c.setup.m = m, c.setup.R = R, c.setup.speed = speed, c.setup.angle = theta_deg * M_PI / 180.0;
  analytic::Input in;
  in.m = m, in.R = R, in.kn = kn, in.gn = gn, in.kt = kt, in.mu = mu, in.end = end;
  in.vn0 = speed * std::cos(c.setup.angle);
  in.vt0 = speed * std::sin(c.setup.angle);
  const analytic::Output x = analytic::impact(in);
  c.ref.e = x.e;
  c.ref.beta = x.beta;
  c.ref.e_t = x.e_t;
  c.ref.omega = x.omega;
  c.ref.rebound_angle_com = x.rebound_angle_com;
  c.ref.rebound_angle_contact = x.rebound_angle_contact;
  c.tc = x.contact_time;
  c.ref.contact_time = x.contact_time;
  const double I = 0.4 * m * R * R;
  c.ref.dissipated_energy = 0.5 * m * speed * speed - 0.5 * m * (x.vn * x.vn + x.vt * x.vt) - 0.5 * I * x.omega * x.omega;
  return c;
}

// Hertz with Tsuji damping (force continuous at touch: c ~ xi^(1/4)), physics_reference 8.2 sphere
// (m = 4.110250e-3 kg, k~ = 1.087857e10 N/m^1.5), alpha = 0.2, v0 = 1 m/s, zero-overlap end,
// frictionless; reference: head_on.h's RK4 with the end located by bisection at 160000 steps per
// contact (an independent integrator; the t^(1/4) start of the Tsuji force limits it to order ~1.3:
// 10000 / 40000 / 160000 steps differ by 4.8e-7 and 7.2e-8, so the reference is good to ~2e-8).
Case<HertzLaw> make_hertz_case() {
  Case<HertzLaw> c;
  c.name = "headon_hertz_tsuji";
  c.law.damping = hertz::Damping::tsuji;
  c.law.p.k = 1.087857e10;
  c.law.p.damp = 0.2;
  c.law.end_mode = ContactEnd::zero_overlap;
  c.cs.p = {1.0, 0.0, 0.0};
  c.setup.m = 4.110250e-3, c.setup.R = 5e-3, c.setup.speed = 1.0;
  Bodies b;
  b.m1 = c.setup.m;
  b.R1 = c.setup.R;
  Options o;
  o.steps_per_contact = 160000;
  const Result r = integrate(c.law, b, 1.0, o);
  c.ref.e = r.restitution;
  c.ref.omega = 0.0;
  c.ref.rebound_angle_com = c.ref.rebound_angle_contact = 0.0;
  c.tc = r.contact_time;
  c.ref.contact_time = r.contact_time;
  c.ref.dissipated_energy = 0.5 * c.setup.m * (1.0 - r.restitution * r.restitution);
  return c;
}

const int kNs[] = {5, 10, 20, 25, 40, 80, 160, 320, 500};
const double kFracs[] = {0.125, 0.375, 0.625, 0.875};

template <class Law>
void study(const Case<Law>& c0, int phases) {
  const double deg = 180.0 / M_PI;
  const double k0 = 0.5 * c0.setup.m * c0.setup.speed * c0.setup.speed;
  std::vector<std::pair<ImpactScheme, bool>> runs;  // (scheme, grid correction)
  for (const ImpactScheme& s : all_impact_schemes()) runs.push_back({s, false});
  for (const ImpactScheme& s : all_impact_schemes())
    if (!s.multi) runs.push_back({s, true});
  for (const auto& run : runs) {
    const ImpactScheme& s = run.first;
    const std::string name = std::string(s.name()) + (run.second ? "+gc" : "");
    for (int N : kNs) {
      for (int grid = 0; grid < 2; ++grid) {
        double acc[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        int n = 0;
        bool ok = true;
        for (double f : kFracs) {
          if (grid == 0 && n == 1) break;
          Case<Law> c = c0;
          ImpactOptions o;
          o.dt = c.tc / (grid == 0 ? static_cast<double>(N) : N + f);
          o.grid_correction = run.second;
          o.energy = !s.multi;
          const PhaseAverage pa = phase_averaged(c.law, c.cs, s, c.setup, o, phases, c.ref);
          if (pa.ended != phases) ok = false;
          const double v[9] = {pa.e, pa.beta, pa.e_t, pa.omega, pa.rebound_angle_com * deg,
                               pa.rebound_angle_contact * deg, pa.contact_time / c.tc, pa.dissipated_energy / k0,
                               pa.energy_residual / k0};
          for (int k = 0; k < 9; ++k) acc[k] += v[k];
          ++n;
        }
        std::printf("%s,%s,%s,%d,%d,%d", c0.name.c_str(), name.c_str(), grid == 0 ? "integer" : "generic", N,
                    s.evaluations(), s.history());
        for (int k = 0; k < 7; ++k) {
          const double v = acc[k] / n;
          if (ok && std::isfinite(v)) std::printf(",%.6e", v);
          else std::printf(",");
        }
        std::printf(",%.10g,%.10g,%.10g", c0.ref.e, c0.ref.beta, c0.ref.rebound_angle_contact * deg);
        for (int k = 7; k < 9; ++k) {  // the energy columns (issue 23) after the references
          const double v = acc[k] / n;
          if (ok && std::isfinite(v)) std::printf(",%.6e", v);
          else std::printf(",");
        }
        std::printf("\n");
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int phases = argc > 1 ? std::atoi(argv[1]) : 16;
  std::vector<Case<LsdLaw>> cases;
  cases.push_back(make_case("headon_52", 0.01, 0.01, 1e5, 4.48097, ContactEnd::zero_overlap, 2.0 / 7.0 * 1e5, 0.0,
                            1.0, 0.0));
  cases.push_back(make_case("headon_52_zf", 0.01, 0.01, 1e5, 4.48097, ContactEnd::zero_force, 2.0 / 7.0 * 1e5, 0.0,
                            1.0, 0.0));
  {
    const double R = 2.5e-3, m = 4.0 / 3.0 * M_PI * R * R * R * 4000.0, le = std::log(0.98), tn = 1e-5;
    const double kn = m * (M_PI * M_PI + le * le) / (tn * tn), gn = -2.0 * m * le / tn;
    for (double th : {5.0, 25.0, 60.0})
      cases.push_back(make_case("oblique_" + std::to_string(static_cast<int>(th)), m, R, kn, gn, ContactEnd::zero_force,
                                2.0 / 7.0 * kn, 0.092, 3.9, th));
  }
  std::printf("case,scheme,grid,N,evaluations_per_step,history_doubles,err_e,err_beta,err_et,err_spin,"
              "err_rebound_com_deg,err_rebound_contact_deg,err_tc_rel,ref_e,ref_beta,ref_rebound_contact_deg,"
              "err_energy_rel,energy_residual_rel\n");
  for (const auto& c : cases) study(c, phases);
  study(make_hertz_case(), phases);
  return 0;
}
