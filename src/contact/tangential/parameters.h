// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: parameters of the tangential laws (physics_reference.md sections 3.1 and 3.4).
//
// Elastic constants:  G = E/(2(1+nu)),  1/G* = (2-nu1)/G1 + (2-nu2)/G2,
//                     1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2,  Mindlin no-slip stiffness 8 G* a,
//                     a = sqrt(R* xi); Hertz normal tangent stiffness 2 E* a, so
//                     kappa_HM = k_t/k_n = 4 G*/E*  (= 2(1-nu)/(2-nu) for like materials).
// Contact-point mass: the slip velocity of the contact point of sphere i (radius R_i, mass m_i,
//   moment of inertia I_i about its centre) answers a tangential force F there with
//   dv_s/dt = F (1/m_i + R_i^2/I_i) (+ the same for j), so
//   1/m_t = 1/m_1 + R_1^2/I_1 + 1/m_2 + R_2^2/I_2  (a wall: the second pair of terms is 0).
//   Solid spheres: m_t = (2/7) m for a sphere on a wall, m/7 for two equal spheres; in both
//   cases m_t/m* = 2/7.
// Sticking tangential restitution beta_0 (contact point, stick for the whole contact time t_n):
//   undamped spring   v_s(t) = v_s0 cos(w t), beta_0 = -cos(w t_n)  =>  k_t = m_t (arccos(-beta_0)/t_n)^2
//   spring + dashpot with half period t_n (same as the normal LSD contact):
//     m_t s'' + gamma_t s' + k_t s = 0, s(0) = 0, s'(0) = v_s0  =>  v_s(pi/w_d) = -v_s0 exp(-zeta pi/w_d),
//     zeta = gamma_t/(2 m_t), w_d^2 = k_t/m_t - zeta^2 = (pi/t_n)^2, so
//     gamma_t = -2 m_t ln(beta_0)/t_n,   k_t = m_t (pi^2 + ln^2 beta_0)/t_n^2.
// Friction from the gross-sliding branch: sliding for the whole contact transmits the tangential
//   impulse mu J_n with J_n = m* (1+e) v_n0, so v_s0 - v_s' = mu (1+e) v_n0 m*/m_t and
//   mu = (v_s0 - v_s') m_t / ((1+e) v_n0 m*)  (= (v_s0 - v_s')/(3.5 (1+e) v_n0) for a solid sphere on
//   a wall); with beta = -v_s'/v_s0: mu = (1+beta) v_s0 m_t/((1+e) v_n0 m*).
#pragma once

#include <cmath>
#include <limits>

#include "../input_checks.h"
#include "../material.h"

namespace tdem {
namespace tangential {

// The elastic pair properties live in ../material.h (one definition for every law and tool).
using material::effective_shear_modulus;
using material::effective_shear_modulus_from_E;
using material::shear_modulus;
inline double effective_youngs_modulus(double E1, double nu1, double E2, double nu2) {
  return material::effective_modulus(E1, nu1, E2, nu2);
}

// Mindlin no-slip tangential stiffness 8 G* a with a = sqrt(R* xi).
inline double mindlin_stiffness(double gstar, double reff, double xi) {
  return 8.0 * gstar * std::sqrt(reff * (xi > 0.0 ? xi : 0.0));
}

using material::kappa_hertz_mindlin;  // 4 G*/E*; like materials 2 (1 - nu)/(2 - nu)

inline double stiffness_from_kappa(double kappa, double kn) {
  checks::positive("stiffness ratio kappa = k_t/k_n", kappa);
  checks::positive("normal stiffness k_n", kn);
  return kappa * kn;
}

// Moment of inertia of a solid sphere.
inline double solid_sphere_inertia(double m, double R) { return 0.4 * m * R * R; }

// Contact-point (tangential) effective mass of a pair; a wall: m2 = infinity (R2, I2 ignored).
inline double contact_point_mass(double m1, double R1, double I1, double m2 = std::numeric_limits<double>::infinity(),
                                 double R2 = 0.0, double I2 = 1.0) {
  checks::positive("mass m1", m1);
  checks::positive("radius R1", R1);
  checks::positive("moment of inertia I1", I1);
  double inv = 1.0 / m1 + R1 * R1 / I1;
  if (!std::isinf(m2)) {
    checks::positive("mass m2", m2);
    checks::positive("radius R2", R2);
    checks::positive("moment of inertia I2", I2);
    inv += 1.0 / m2 + R2 * R2 / I2;
  }
  return 1.0 / inv;
}

// Normal effective mass m* (a wall: m2 = infinity).
inline double normal_mass(double m1, double m2 = std::numeric_limits<double>::infinity()) {
  checks::positive("mass m1", m1);
  if (!(m2 > 0.0)) checks::fail("mass m2", m2, "(0, inf]");
  return std::isinf(m2) ? m1 : 1.0 / (1.0 / m1 + 1.0 / m2);
}

struct SpringDashpot {
  double kt;      // [N/m]
  double gammat;  // [kg/s]
};

// Undamped spring that gives beta_0 for a contact sticking for the contact time t_n.
inline double stiffness_from_beta0(double beta0, double tn, double mt) {
  if (!(beta0 > -1.0 && beta0 <= 1.0)) checks::fail("sticking tangential restitution beta_0", beta0, "(-1, 1]");
  checks::positive("contact time t_n", tn);
  checks::positive("contact-point mass m_t", mt);
  const double w = std::acos(-beta0) / tn;
  return mt * w * w;
}

// Spring and dashpot with the half period t_n that give beta_0 (> 0) for a sticking contact.
inline SpringDashpot spring_dashpot_from_beta0(double beta0, double tn, double mt) {
  if (!(beta0 > 0.0 && beta0 <= 1.0)) checks::fail("sticking tangential restitution beta_0", beta0, "(0, 1]");
  checks::positive("contact time t_n", tn);
  checks::positive("contact-point mass m_t", mt);
  const double l = std::log(beta0);
  return {mt * (M_PI * M_PI + l * l) / (tn * tn), -2.0 * mt * l / tn};
}

// mu from one impact in the gross-sliding range (see the header).
inline double friction_from_gross_sliding(double vs0, double vs1, double vn0, double e, double mstar, double mt) {
  checks::positive("incident normal velocity v_n0", vn0);
  checks::positive("coefficient of normal restitution e", e);
  checks::positive("effective mass m*", mstar);
  checks::positive("contact-point mass m_t", mt);
  const double mu = (vs0 - vs1) * mt / ((1.0 + e) * vn0 * mstar);
  if (!(mu >= 0.0)) checks::fail("friction coefficient mu from (v_s0 - v_s')", mu, "[0, inf) (v_s' must not exceed v_s0)");
  return mu;
}

}  // namespace tangential
}  // namespace tdem
