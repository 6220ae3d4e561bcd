// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: one impact of integrate_impact.h, averaged over the phase of the first contact within a
// time step (the gap shifted by (i + 1/2)/phases of one step's approach), against reference values:
// the errors a host run meets on average, not those of one lucky or unlucky phase.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include "collision/integrate_impact.h"
#include "contact/input_checks.h"

namespace tdem {
namespace collision {

// Reference values (NaN: not compared).
struct ImpactReference {
  double e = NAN, beta = NAN, e_t = NAN, omega = NAN;               // omega: spin after [1/s]
  double rebound_angle_com = NAN, rebound_angle_contact = NAN;      // [rad]
  double contact_time = NAN;                                         // [s]
  double dissipated_energy = NAN;  // kinetic energy lost by the impact [J] (issue 23)
};

struct PhaseAverage {
  int phases = 0;
  int ended = 0;  // runs whose contact ended
  // mean |result - reference| over the phases (NaN where the reference is NaN or a run did not end)
  double e = NAN, beta = NAN, e_t = NAN, omega = NAN, rebound_angle_com = NAN, rebound_angle_contact = NAN;
  // |contact time - reference|: the interpolated one of a corrected run, else contact_steps * dt
  double contact_time = NAN;
  // with ImpactOptions::energy: mean |kinetic energy lost - reference| [J] and mean largest balance
  // residual (energy.h) [J]
  double dissipated_energy = NAN, energy_residual = NAN;
  double mean_e = NAN;  // mean e itself
  double contact_steps = 0.0;  // mean
  double dt = 0.0;
  std::vector<ImpactResult> runs;
};

template <class NormalLaw, class TangentialLaw>
PhaseAverage phase_averaged(NormalLaw& normal, TangentialLaw& tang, const ImpactScheme& scheme,
                            const ImpactSetup& setup, const ImpactOptions& opt, int phases,
                            const ImpactReference& ref, bool keep_runs = false) {
  if (phases < 1) checks::fail("phases", phases, "[1, inf)");
  validate(setup);
  const double vn0 = setup.speed * std::cos(setup.angle);
  double dt = opt.dt;
  if (!(dt > 0.0)) dt = normal.contact_time_estimate(setup.m, setup.R, vn0) / static_cast<double>(opt.steps_per_contact);
  ImpactOptions o = opt;
  o.dt = dt;
  PhaseAverage pa;
  pa.phases = phases;
  pa.dt = dt;
  double s[6] = {0, 0, 0, 0, 0, 0}, se = 0.0, sc = 0.0, stc = 0.0, sde = 0.0, sres = 0.0;
  const double* refs[6] = {&ref.e, &ref.beta, &ref.e_t, &ref.omega, &ref.rebound_angle_com, &ref.rebound_angle_contact};
  for (int i = 0; i < phases; ++i) {
    ImpactSetup su = setup;
    su.gap = setup.gap + (i + 0.5) / phases * vn0 * dt;
    ImpactResult res = integrate_impact(normal, tang, scheme, su, o);
    if (res.ended) {
      ++pa.ended;
      const double got[6] = {res.e, res.beta, res.e_t, res.omega1, res.rebound_angle_com, res.rebound_angle_contact};
      for (int k = 0; k < 6; ++k) s[k] += std::fabs(got[k] - *refs[k]);
      const double tc = std::isfinite(res.contact_time_interpolated) ? res.contact_time_interpolated : res.contact_time;
      stc += std::fabs(tc - ref.contact_time);
      se += res.e;
      sc += static_cast<double>(res.contact_steps);
      sde += std::fabs(res.dissipated_energy - ref.dissipated_energy);
      sres += res.energy_residual_max;  // (NaN without opt.energy)
    }
    if (keep_runs) pa.runs.push_back(std::move(res));
  }
  if (pa.ended == phases) {
    double* outs[6] = {&pa.e, &pa.beta, &pa.e_t, &pa.omega, &pa.rebound_angle_com, &pa.rebound_angle_contact};
    for (int k = 0; k < 6; ++k) *outs[k] = s[k] / phases;  // NaN reference -> NaN
    pa.mean_e = se / phases;
    pa.contact_time = stc / phases;
    pa.contact_steps = sc / phases;
    pa.dissipated_energy = sde / phases;
    pa.energy_residual = sres / phases;
  }
  return pa;
}

}  // namespace collision
}  // namespace tdem
