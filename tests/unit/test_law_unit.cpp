// SPDX-License-Identifier: GPL-2.0-or-later
// The normal laws as units (src/contact/law_unit.h, the list in src/contact/laws.h): the list and
// its look-ups, the type-erased parameter store, the values -> Params conversion with E* of a law
// with materials, and each unit's advice numbers against closed forms and central differences
// of its own force.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "collision/head_on.h"
#include "contact/laws.h"

namespace law = tdem::law;

TEST(LawUnit, ListAndLookUps) {
  EXPECT_EQ(law::normal_units::size, 4);
  std::set<std::string> names;
  for (int k = 0; k < law::normal_units::size; ++k) {
    const law::Description* d = law::normal_units::descriptions[k];
    EXPECT_STREQ(d->kind, "normal");
    EXPECT_TRUE(names.insert(d->name).second) << d->name;
    EXPECT_EQ(law::index_of<law::normal_units>(d), k);
    EXPECT_EQ(law::index_of<law::normal_units>(d->name), k);
    EXPECT_EQ(law::normal_laws[k], d);
    int seen = -1;
    EXPECT_TRUE(law::visit<law::normal_units>(k, [&](auto tag) {
      using U = typename decltype(tag)::type;
      seen = law::index_of<law::normal_units>(&U::description);
      // one property name per parameter, every name distinct
      std::set<std::string> props(std::begin(U::properties), std::end(U::properties));
      EXPECT_EQ(static_cast<int>(props.size()), U::description.count);
      EXPECT_EQ(static_cast<int>(sizeof(U::properties) / sizeof(U::properties[0])), U::description.count);
    }));
    EXPECT_EQ(seen, k);
  }
  EXPECT_FALSE(law::visit<law::normal_units>(law::normal_units::size, [](auto) {}));
  EXPECT_EQ(law::index_of<law::normal_units>("lsd"), -1);
  static_assert(std::is_same<law::UnitAt<1, law::normal_units>, tdem::thornton::Law>::value, "UnitAt");
}

TEST(LawUnit, ParamStoreRoundTrip) {
  const tdem::power_law::Params<double> p{1.5e6, 1.25, 3.0e7, 0.5};
  law::ParamStore s;
  s.set(p);
  const auto q = s.get<tdem::power_law::Params<double>>();
  EXPECT_EQ(q.a_load, p.a_load);
  EXPECT_EQ(q.p, p.p);
  EXPECT_EQ(q.a_unload, p.a_unload);
  EXPECT_EQ(q.q, p.q);
}

TEST(LawUnit, ValuesWithMaterialsGiveEffectiveModulus) {
  // thornton E1 NU1 E2 NU2 PY: params receive E* = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2), then PY
  const double x[5] = {7e10, 0.3, 2e11, 0.25, 4e8};
  double v[law::MAX_UNIT_VALUES];
  law::unit_values(tdem::thornton::description, x, v);
  EXPECT_EQ(law::unit_value_count(tdem::thornton::description), 2);
  const double estar = 1.0 / ((1 - 0.09) / 7e10 + (1 - 0.0625) / 2e11);
  EXPECT_NEAR(v[0], estar, 1e-6 * estar);
  EXPECT_EQ(v[1], 4e8);
  const auto p = tdem::thornton::Law::params(v);
  EXPECT_EQ(p.e_star, v[0]);
  EXPECT_EQ(p.p_y, 4e8);
  // a law without materials takes its values as they are; a bad combination throws
  const double w[3] = {1e5, 2e5, 0.0};
  law::unit_values(tdem::walton_braun::description, w, v);
  EXPECT_EQ(tdem::walton_braun::Law::params(v).k_unload, 2e5);
  const double bad[3] = {1e5, 5e4, 0.0};
  EXPECT_THROW(tdem::walton_braun::Law::params(bad), std::exception);
  // force units: the hosts scale these (LIGGGHTS nktv2p)
  EXPECT_TRUE(law::force_units(tdem::walton_braun::parameters[0]));       // N/m
  EXPECT_TRUE(law::force_units(tdem::thornton::parameters[0]));           // Pa
  EXPECT_FALSE(law::force_units(tdem::power_law::parameters[1]));         // exponent
}

// Each unit: its largest tangent stiffness at xi_max equals the slope of its own unloading
// force there (central differences on a copy of the history), its largest overlap makes the
// loading work equal to 1/2 m* v^2, and a closed-form contact time agrees with the integrated
// head-on impact.
template <class U>
void check_unit(const typename U::Params& p, double meff, double reff, double v) {
  SCOPED_TRACE(U::description.name);
  const double xm = U::max_overlap(p, meff, reff, v);
  // loading work by the trapezoidal rule on the loading branch (fresh history each point)
  double work = 0.0;
  const int n = 20000;
  double f_prev = 0.0;
  for (int i = 1; i <= n; ++i) {
    double h[8] = {};
    const double xi = xm * i / n;
    const double f = U::force(p, tdem::NormalKinematics<double>{xi, 1.0, meff, reff}, h, true).force;
    work += 0.5 * (f + f_prev) * xm / n;
    f_prev = f;
  }
  EXPECT_NEAR(work, 0.5 * meff * v * v, 1e-4 * 0.5 * meff * v * v);
  // unloading slope at xi_max from the history of a loading to xi_max
  double h[8] = {};
  U::force(p, tdem::NormalKinematics<double>{xm, 1.0, meff, reff}, h, true);
  const double d = 1e-6 * xm;
  double h1[8], h2[8];
  std::copy(h, h + 8, h1);
  std::copy(h, h + 8, h2);
  const double f1 = U::force(p, tdem::NormalKinematics<double>{xm - d, -1.0, meff, reff}, h1, false).force;
  const double f2 = U::force(p, tdem::NormalKinematics<double>{xm - 2 * d, -1.0, meff, reff}, h2, false).force;
  const double slope = (f1 - f2) / d;  // backward difference, inside the unloading branch
  const double k = U::stiffness_at(p, reff, xm);
  EXPECT_NEAR(slope, k, 1e-4 * k);
  const double tc = U::contact_time(p, meff, reff, v);
  if (!std::isnan(tc)) {
    tdem::collision::UnitLaw<U> l;
    l.p = p;
    tdem::collision::Bodies b;
    b.m1 = meff;
    b.R1 = reff;
    const auto r = tdem::collision::integrate(l, b, v);
    EXPECT_NEAR(r.contact_time, tc, 1e-3 * tc);
  }
}

TEST(LawUnit, AdviceNumbersOfEveryUnit) {
  const double meff = 1e-3, reff = 1e-3, v = 1.0;
  check_unit<tdem::walton_braun::Law>({1e5, 2e5, 0.0}, meff, reff, v);
  check_unit<tdem::walton_braun::Law>({1e5, 1e5, 3.0}, meff, reff, v);
  check_unit<tdem::thornton::Law>({1e10, 3e7}, meff, reff, v);
  check_unit<tdem::power_law::Law>({1e7, 1.5, 5e9, 0.5}, meff, reff, v);
  check_unit<tdem::luding::Law>({1e5, 5e5, 0.2}, meff, reff, v);   // xi_max below xi_lim
  check_unit<tdem::luding::Law>({1e5, 5e5, 0.02}, meff, reff, v);  // beyond
}

// Luding's law (docs/adding_a_law.md): the closed forms re-derived here against the integrated
// impact of its kernel, below and beyond the plastic limit, and the zero-force rule.
TEST(LawUnit, LudingClosedForms) {
  const double m = 0.01, r = 0.005, k1 = 1e5, k2m = 5e5;
  for (double phi : {0.05, 0.01}) {
    SCOPED_TRACE(phi);
    const tdem::luding::Params<double> p{k1, k2m, phi};
    const double xl = k2m / (k2m - k1) * phi * 2 * r, a = std::sqrt(m / k1);
    double e, tc;
    if (a < xl) {
      const double k2 = k1 + (k2m - k1) * a / xl;
      e = std::sqrt(k1 / k2);
      tc = 0.5 * M_PI * (std::sqrt(m / k1) + std::sqrt(m / k2));
    } else {  // rebound energy 1/2 k2m (xi_max - xi_0)^2 from the energy balance of loading
      const double x0 = xl * (1 - k1 / k2m);
      const double excess = 0.5 * m - 0.5 * k1 * xl * xl;  // kinetic energy left at xi_lim
      const double d = (-k1 * xl + std::sqrt(k1 * k1 * xl * xl + 2 * k2m * excess)) / k2m;  // xi_max - xi_lim
      e = std::sqrt(k2m * (xl + d - x0) * (xl + d - x0) / m);
      tc = NAN;
    }
    EXPECT_NEAR(tdem::luding::restitution(p, m, r, 1.0), e, 1e-12);
    tdem::collision::UnitLaw<tdem::luding::Law> l;
    l.p = p;
    tdem::collision::Bodies b;
    b.m1 = m;
    b.R1 = r;
    const auto res = tdem::collision::integrate(l, b, 1.0);
    EXPECT_NEAR(res.restitution, e, 1e-7);
    EXPECT_NEAR(res.contact_time, tdem::luding::contact_time(p, m, r, 1.0), 1e-6 * res.contact_time);
    if (!std::isnan(tc)) {
      EXPECT_NEAR(res.contact_time, tc, 1e-12);
    }
  }
  // unloading past zero force: no attraction, and xi_max moves so that the line passes through xi
  const tdem::luding::Params<double> p{k1, k2m, 0.05};
  double h[1] = {0.0};
  tdem::luding::force(p, tdem::NormalKinematics<double>{2e-4, 1.0, m, r}, h, true);
  EXPECT_EQ(h[0], 2e-4);
  const auto z = tdem::luding::force(p, tdem::NormalKinematics<double>{1e-5, -1.0, m, r}, h, true);
  EXPECT_EQ(z.force, 0.0);
  const double xl = tdem::luding::limit_overlap(p, r);
  const double k2 = k1 + (k2m - k1) * h[0] / xl;
  EXPECT_NEAR(k2 * (1e-5 - h[0]) + k1 * h[0], 0.0, 1e-9 * k1 * 2e-4);  // the new line through xi
}
