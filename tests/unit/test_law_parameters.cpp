// SPDX-License-Identifier: GPL-2.0-or-later
// The law descriptions (src/contact/law_parameters.h, src/contact/laws.h): value counts, syntax,
// range checks and their messages, the expansion of the material pair, and the values -> Params
// conversion against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "contact/laws.h"

namespace law = tdem::law;

TEST(LawParameters, SyntaxAndCounts) {
  const auto& wb = tdem::walton_braun::description;
  EXPECT_EQ(law::syntax(wb), "KL KUL [S]");
  EXPECT_FALSE(law::count_ok(wb, 1));
  EXPECT_TRUE(law::count_ok(wb, 2));
  EXPECT_TRUE(law::count_ok(wb, 3));
  EXPECT_FALSE(law::count_ok(wb, 4));
  EXPECT_EQ(law::count_message(wb, 1), "normal walton_braun needs 2 or 3 values (KL KUL [S]), got 1");

  const auto& th = tdem::thornton::description;
  EXPECT_EQ(law::syntax(th), "E NU PY");
  EXPECT_EQ(law::syntax(th, true), "E1 NU1 E2 NU2 PY");
  EXPECT_TRUE(law::count_ok(th, 3));
  EXPECT_FALSE(law::count_ok(th, 4));
  EXPECT_TRUE(law::count_ok(th, 5));
  EXPECT_EQ(law::count_message(th, 2),
            "normal thornton needs 3 values (E NU PY: both partners of one material) or 5 values "
            "(E1 NU1 E2 NU2 PY), got 2");

  const auto& pl = tdem::power_law::description;
  EXPECT_EQ(law::count_message(pl, 5), "normal power_law needs 3 or 4 values (AL P AUL [Q]), got 5");
}

TEST(LawParameters, RangeMessages) {
  const auto& wb = tdem::walton_braun::description;
  double v[3] = {-1e5, 1.5e5, 0.0};
  EXPECT_EQ(law::check(wb, v), "normal walton_braun KL (loading stiffness) = -100000 must be > 0");
  v[0] = 1e5, v[1] = 5e4;
  EXPECT_EQ(law::check(wb, v),
            "normal walton_braun KUL (unloading stiffness) = 50000 is outside the allowed range [KL, inf) = "
            "[100000, inf)");
  v[1] = 1e5, v[2] = -2;
  EXPECT_EQ(law::check(wb, v), "normal walton_braun S (slope of KUL with F_max) = -2 must be >= 0");
  v[2] = 0.0;
  EXPECT_EQ(law::check(wb, v), "");  // KUL = KL is allowed (elastic)

  const auto& th = tdem::thornton::description;
  double t[5] = {2e8, -1.5, 2e8, -1.5, 1e6};
  EXPECT_EQ(law::check(th, t), "normal thornton NU (Poisson ratio) = -1.5 is outside the allowed range (-1, 0.5]");
  t[1] = t[3] = 0.5;  // incompressible: the closed upper end
  EXPECT_EQ(law::check(th, t), "");
  t[4] = 0.0;
  EXPECT_EQ(law::check(th, t), "normal thornton PY (limiting contact pressure) = 0 must be > 0");
}

TEST(LawParameters, ExpansionAndConversion) {
  // one material: E NU PY -> E NU E NU PY; E* = E / (2 (1 - nu^2))
  const auto& th = tdem::thornton::description;
  const double words[3] = {7e10, 0.3, 1e8};
  double v[5];
  law::expand(th, words, 3, v);
  EXPECT_EQ(v[2], 7e10);
  EXPECT_EQ(v[3], 0.3);
  EXPECT_EQ(v[4], 1e8);
  const auto p = tdem::thornton::from_values(v);
  EXPECT_NEAR(p.e_star, 7e10 / (2.0 * (1.0 - 0.09)), 1e-6 * p.e_star);
  EXPECT_EQ(p.p_y, 1e8);
  // two materials: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
  const double w5[5] = {7e10, 0.3, 2e11, 0.25, 1e8};
  law::expand(th, w5, 5, v);
  EXPECT_NEAR(tdem::thornton::from_values(v).e_star, 1.0 / ((1 - 0.09) / 7e10 + (1 - 0.0625) / 2e11), 1.0);

  // an optional tail value left out takes its fallback (S = 0, Q = 0)
  const double wb[2] = {1e5, 2e5};
  double x[3] = {9, 9, 9};
  law::expand(tdem::walton_braun::description, wb, 2, x);
  EXPECT_EQ(x[2], 0.0);
  const auto wp = tdem::walton_braun::from_values(x);
  EXPECT_EQ(wp.k_load, 1e5);
  EXPECT_EQ(wp.k_unload, 2e5);
  EXPECT_EQ(wp.slope, 0.0);
  // e = sqrt(k_l / k_ul) for a constant unloading stiffness (closed form of the law)
  EXPECT_NEAR(tdem::walton_braun::restitution(wp, 1e-3, 1.0), std::sqrt(0.5), 1e-14);
}

TEST(LawParameters, EveryListedLawIsConsistent) {
  std::set<std::string> names;
  for (const law::Description* d : law::normal_laws) {
    SCOPED_TRACE(d->name);
    EXPECT_TRUE(names.insert(d->name).second) << "a name twice in the list";
    EXPECT_STREQ(d->kind, "normal");
    EXPECT_EQ(law::find(law::normal_laws, d->name), d);
    std::set<std::string> words;
    bool optional_seen = false;
    for (int k = 0; k < law::value_count(*d); ++k) {
      const law::Parameter& p = law::parameter(*d, k);
      EXPECT_TRUE(words.insert(p.name).second) << p.name << " twice";
      EXPECT_TRUE(p.unit && *p.unit && p.meaning && *p.meaning);
      if (p.bound == law::Bound::at_least) {
        EXPECT_TRUE(p.ref >= 0 && p.ref < k - (d->materials ? 4 : 0));
      }
      if (k >= (d->materials ? 4 : 0)) {  // optional values only at the end of the line
        if (optional_seen) {
          EXPECT_TRUE(p.optional) << p.name << " follows an optional value";
        }
        optional_seen = optional_seen || p.optional;
      }
    }
    EXPECT_GE(d->history_size, 0);
  }
  EXPECT_EQ(law::find(law::normal_laws, "no_such_law"), nullptr);
  EXPECT_EQ(tdem::walton_braun::description.history_size, tdem::walton_braun::history_size);
  EXPECT_EQ(tdem::thornton::description.history, tdem::thornton::history);
  EXPECT_EQ(tdem::power_law::description.history_size, tdem::power_law::history_size);
}

TEST(LawParameters, TangentialLaws) {
  const auto& md = tdem::mindlin_deresiewicz::description;
  EXPECT_EQ(law::count_message(md, 2), "tangential mindlin_deresiewicz needs 3 or 5 values (E NU [E2 NU2] MU), got 2");
  EXPECT_EQ(law::count_message(tdem::mindlin_no_slip::description, 3),
            "tangential mindlin_no_slip needs 4 or 6 values (E NU [E2 NU2] RATIO MU), got 3");
  EXPECT_EQ(law::count_message(tdem::haff_werner::description, 1), "tangential haff_werner needs 2 values (GAMMAT MU), got 1");
  const double hw[2] = {-20.0, 0.5};
  EXPECT_EQ(law::check(tdem::haff_werner::description, hw),
            "tangential haff_werner GAMMAT (damping coefficient, mass/time) = -20 must be >= 0");
  // E NU RATIO MU with one material: RATIO and MU are values 4 and 5
  const double w[4] = {7e10, 0.3, 0.5, 0.4};
  double v[6];
  law::expand(tdem::mindlin_no_slip::description, w, 4, v);
  EXPECT_EQ(v[2], 7e10);
  EXPECT_EQ(v[3], 0.3);
  EXPECT_EQ(v[4], 0.5);
  EXPECT_EQ(v[5], 0.4);
  std::set<std::string> names;
  for (const law::Description* d : law::tangential_laws) {
    SCOPED_TRACE(d->name);
    EXPECT_TRUE(names.insert(d->name).second);
    EXPECT_STREQ(d->kind, "tangential");
    EXPECT_STREQ(law::parameter(*d, law::value_count(*d) - 1).name, "MU");  // the friction coefficient last
  }
  EXPECT_EQ(names.size(), 6u);
}
