// SPDX-License-Identifier: GPL-2.0-or-later
// Reading a law's input words by its description (src/contact/law_input.h): the keyword groups of
// lsd, hertz and the extended laws, the two forms of cundall_strack, the expanded values, where
// the law's words end, and the messages of bad input (the words the LAMMPS adapter has always
// printed for them).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "contact/laws.h"

namespace law = tdem::law;

namespace {
bool host_keyword(const char* w) {
  const std::string s = w;
  return s == "tangential" || s == "limit_force" || s == "damping" || s == "slip";
}
struct Words {
  std::vector<std::string> s;
  std::vector<const char*> p;
  explicit Words(const std::string& line) {
    std::istringstream in(line);
    for (std::string w; in >> w;) s.push_back(w);
    for (const auto& w : s) p.push_back(w.c_str());
  }
};
law::Reading read(const law::Description& d, const std::string& line, const std::string& q = "") {
  Words w(line);
  return law::read(d, static_cast<int>(w.p.size()), w.p.data(), host_keyword, q);
}
void expect_error(const law::Description& d, const std::string& line, const std::string& part) {
  const law::Reading r = read(d, line);
  EXPECT_NE(r.error.find(part), std::string::npos) << "input '" << line << "' gave '" << r.error << "'";
}
}  // namespace

TEST(LawInput, LsdForms) {
  const auto& d = tdem::lsd::description;
  ASSERT_EQ(law::all_values(d), 3);
  law::Reading r = read(d, "stiffness 2000 50 tangential cundall_strack 600 25 0.5");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 3);
  EXPECT_EQ(law::choice_of(d, 0, r.v), tdem::lsd::form_stiffness);
  EXPECT_EQ(law::group_values(d, 0, r.v)[0], 2000.0);
  EXPECT_EQ(law::group_values(d, 0, r.v)[1], 50.0);
  r = read(d, "restitution 0.6 1e-4");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(law::choice_of(d, 0, r.v), tdem::lsd::form_restitution);
  EXPECT_EQ(law::group_values(d, 0, r.v)[1], 1e-4);
  // a third number ends lsd's words (the host reports it where it expects 'tangential')
  r = read(d, "stiffness 2000 50 7 tangential");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 3);
  expect_error(d, "damped 2000 50", "normal lsd parametrisation 'damped' is unknown; allowed: stiffness KN GAMMAN, "
                                    "restitution E TC");
  expect_error(d, "", "normal lsd needs a parametrisation");
  expect_error(d, "stiffness 2000 tangential", "normal lsd stiffness needs 2 values (KN GAMMAN), got 1");
  expect_error(d, "stiffness -2000 50", "normal lsd stiffness KN = -2000 must be > 0");
  expect_error(d, "stiffness 2000 -50", "normal lsd stiffness GAMMAN = -50 must be >= 0");
  expect_error(d, "restitution 1.5 1e-4", "normal lsd restitution E = 1.5 is outside the allowed range (0, 1]");
  expect_error(d, "restitution 0.5 0", "normal lsd restitution TC (contact time) = 0 must be > 0");
  expect_error(d, "restitution 0.5 x", "normal lsd restitution TC expects a finite number, got 'x'");
}

TEST(LawInput, HertzDampingMembers) {
  const auto& d = tdem::hertz::description;
  ASSERT_EQ(law::all_values(d), 4 + 1 + 2);
  law::Reading r = read(d, "2e8 0.3 tangential");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 2);
  EXPECT_EQ(r.v[2], 2e8);  // the second material copies the first
  EXPECT_EQ(r.v[3], 0.3);
  EXPECT_EQ(law::choice_of(d, 0, r.v), static_cast<int>(tdem::hertz::Damping::linear));
  EXPECT_EQ(law::group_values(d, 0, r.v)[0], 0.0);  // default: no damping
  r = read(d, "2e8 0.3 1e8 0.25 damping general 0.5 7 tangential");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 8);
  EXPECT_EQ(r.v[2], 1e8);
  EXPECT_EQ(law::choice_of(d, 0, r.v), static_cast<int>(tdem::hertz::Damping::general));
  EXPECT_EQ(law::group_values(d, 0, r.v)[0], 0.5);
  EXPECT_EQ(law::group_values(d, 0, r.v)[1], 7.0);
  r = read(d, "2e8 0.3 damping tsuji 0.7");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(law::choice_of(d, 0, r.v), static_cast<int>(tdem::hertz::Damping::tsuji));
  EXPECT_EQ(law::group_values(d, 0, r.v)[0], 0.7);
  expect_error(d, "2e8 0.3 0.1 tangential", "normal hertz needs 2 values (E NU: both partners of one material) or 4 "
                                            "values (E1 NU1 E2 NU2), got 3");
  expect_error(d, "-2e8 0.3", "normal hertz E (Young's modulus) = -200000000 must be > 0");
  expect_error(d, "2e8 0.3 2e8 -1", "normal hertz NU2 (Poisson ratio) = -1 is outside the allowed range (-1, 0.5]");
  expect_error(d, "2e8 0.3 damping tsuji 1.2", "normal hertz damping tsuji E = 1.2 is outside the allowed range (0, 1]");
  expect_error(d, "2e8 0.3 damping linear -3", "normal hertz damping linear GAMMA = -3 must be >= 0");
  expect_error(d, "2e8 0.3 damping general 0.5 tangential", "normal hertz damping general needs 2 values (THETA C), "
                                                            "got 1");
  expect_error(d, "2e8 0.3 damping linear 1 2", "normal hertz damping linear needs 1 value (GAMMA), got 2");
  expect_error(d, "2e8 0.3 damping viscous 1", "normal hertz damping 'viscous' is unknown; allowed: linear GAMMA, "
                                               "kuwabara_kono GAMMA, tsuji E, general THETA C");
  expect_error(d, "2e8 0.3 damping", "normal hertz damping needs a member; allowed: linear GAMMA");
}

TEST(LawInput, ExtendedFits) {
  const auto& d = tdem::extended::linear_description;
  law::Reading r = read(d, "e_fit rational 1 2 0.5 tc_fit power 1e-3 -0.2 v_max 5 v_min 0.01 tangential");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 13);
  const tdem::extended::LinearParams p = tdem::extended::linear_params(r.v);
  EXPECT_EQ(p.e_fit.form, tdem::fits::Form::rational);
  EXPECT_EQ(p.e_fit.c[0], 1.0);
  EXPECT_EQ(p.e_fit.c[2], 0.5);
  EXPECT_EQ(p.tc_fit.form, tdem::fits::Form::power);
  EXPECT_EQ(p.tc_fit.c[1], -0.2);
  EXPECT_EQ(p.range.v_min, 0.01);
  EXPECT_EQ(p.range.v_max, 5.0);
  // the range falls back to the fits' defaults
  r = read(d, "e_fit constant 0.5 tc_fit constant 1e-3");
  ASSERT_TRUE(r.ok()) << r.error;
  const tdem::extended::LinearParams q = tdem::extended::linear_params(r.v);
  EXPECT_EQ(q.range.v_min, tdem::fits::Range().v_min);
  EXPECT_EQ(q.range.v_max, tdem::fits::Range().v_max);
  EXPECT_EQ(q.tc_fit.form, tdem::fits::Form::constant);
  EXPECT_EQ(q.tc_fit.c[0], 1e-3);

  expect_error(d, "tc_fit constant 1e-3 tangential", "normal extended_linear needs 'e_fit constant|rational|power "
                                                     "C0 ..', got 'tc_fit'");
  expect_error(d, "e_fit linear 0.5", "normal extended_linear e_fit form 'linear' is unknown; allowed: constant C0, "
                                      "rational C0 C1 C2, power C0 C1");
  expect_error(d, "e_fit rational 1 1 tc_fit constant 1e-3", "normal extended_linear e_fit rational needs 3 values "
                                                             "(C0 C1 C2), got 2");
  expect_error(d, "e_fit constant 1.5 tc_fit constant 1e-3", "normal extended_linear e_fit constant (C0 = 1.5): "
                                                             "coefficient of restitution e = 1.5 is outside the "
                                                             "allowed range (0, 1]");
  expect_error(d, "e_fit rational -1 1 0.2 tc_fit constant 1e-3", "e_fit rational (C0 = -1, C1 = 1, C2 = 0.2)");
  expect_error(d, "e_fit constant 0.5 tangential", "normal extended_linear needs 'tc_fit constant|power C0 ..' after "
                                                   "e_fit, got 'tangential'");
  expect_error(d, "e_fit constant 0.5 tc_fit rational 1 1 1", "normal extended_linear tc_fit form 'rational' is "
                                                              "unknown; allowed: constant C0, power C0 C1");
  expect_error(d, "e_fit constant 0.5 tc_fit constant 0", "tc_fit constant (C0 = 0)");
  expect_error(d, "e_fit constant 0.5 tc_fit power 1e-3 tangential", "normal extended_linear tc_fit power needs 2 "
                                                                     "values (C0 C1), got 1");
  expect_error(d, "e_fit constant 0.5 tc_fit constant 1e-3 v_max tangential", "normal extended_linear v_max needs 1 "
                                                                              "value (impact velocity), got 0");
  expect_error(d, "0.5 e_fit constant 0.5", "normal extended_linear needs 'e_fit constant|rational|power C0 ..', "
                                            "got '0.5'");

  const auto& h = tdem::extended::hertz_description;
  r = read(h, "1e9 0.3 e_fit power 0.1 0.2 v_min 0.5");
  ASSERT_TRUE(r.ok()) << r.error;
  const tdem::extended::LinearParams hp = tdem::extended::hertz_fits(r.v + 4);
  EXPECT_EQ(hp.e_fit.form, tdem::fits::Form::power);
  EXPECT_EQ(hp.e_fit.c[1], 0.2);
  EXPECT_EQ(hp.range.v_min, 0.5);
  EXPECT_EQ(hp.range.v_max, tdem::fits::Range().v_max);
  expect_error(h, "1e9 0.3 1e9 e_fit constant 0.5", "normal extended_hertz needs 2 values (E NU: both partners of "
                                                    "one material) or 4 values (E1 NU1 E2 NU2) before e_fit, got 3");
  expect_error(h, "1e9 0.7 e_fit constant 0.5", "normal extended_hertz NU (Poisson ratio) = 0.7 is outside");
  expect_error(h, "1e9 0.3 e_fit constant 0.5 tc_fit constant 1e-3", "normal extended_hertz takes no tc_fit (its "
                                                                     "contact time follows from Hertz)");
  expect_error(h, "1e9 0.3 e_fit power 0.1 -2", "restitution fit exponent p = -2 is outside the allowed range [0, inf)");
}

TEST(LawInput, CundallStrackForms) {
  const auto& s = tdem::cundall_strack::stiffness_description;
  law::Reading r = read(s, "600 25 0.5 limit_force yes");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 3);
  EXPECT_EQ(r.v[0], 600.0);
  EXPECT_EQ(r.v[2], 0.5);
  Words w("600 25");
  r = law::read(s, 2, w.p.data(), host_keyword, " (with normal lsd stiffness)");
  EXPECT_EQ(r.error, "tangential cundall_strack (with normal lsd stiffness) needs 3 values (KT GAMMAT MU), got 2");
  expect_error(s, "0 25 0.5", "tangential cundall_strack KT = 0 must be > 0");
  expect_error(s, "600 25 -0.5", "tangential cundall_strack MU = -0.5 must be >= 0");
  const auto& k = tdem::cundall_strack::ratio_description;
  r = read(k, "0.8 0.5");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.v[0], 0.8);
  Words w2("0.8");
  r = law::read(k, 1, w2.p.data(), host_keyword, " (with normal hertz)");
  EXPECT_EQ(r.error, "tangential cundall_strack (with normal hertz) needs 2 values (KAPPA MU), got 1");
}

TEST(LawInput, UnitsReadAsBefore) {
  // a law without groups reads as the count and range checks of its description say
  const auto& wb = tdem::walton_braun::description;
  law::Reading r = read(wb, "1e5 2e5 tangential");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.next, 2);
  EXPECT_EQ(r.v[2], 0.0);  // S falls back to 0
  expect_error(wb, "1e5 2e5 3 4", "normal walton_braun needs 2 or 3 values (KL KUL [S]), got 4");
  expect_error(wb, "1e5 5e4", "normal walton_braun KUL (unloading stiffness) = 50000 is outside the allowed range "
                              "[KL, inf) = [100000, inf)");
}

TEST(LawInput, OneListNamesEveryTangentialLaw) {
  std::string names;
  for (const law::Description* d : law::all_tangential_laws) {
    names += std::string(names.empty() ? "" : ", ") + d->name;
    EXPECT_STREQ(d->kind, "tangential");
  }
  EXPECT_EQ(names, "cundall_strack, haff_werner, linear_spring, walton_braun, mindlin_deresiewicz, mindlin_no_slip, "
                   "di_renzo");
  EXPECT_STREQ(tdem::cundall_strack::ratio_description.name, "cundall_strack");  // its second form
}

TEST(LawInput, OneListNamesEveryNormalLaw) {
  std::string names;
  for (const law::Description* d : law::all_normal_laws) names += std::string(names.empty() ? "" : ", ") + d->name;
  std::string units;
  for (const law::Description* d : law::normal_laws) units += std::string(", ") + d->name;
  EXPECT_EQ(names, "lsd, hertz" + units + ", extended_linear, extended_hertz, continuous_potential");
  for (const law::Description* d : law::all_normal_laws) {
    EXPECT_LE(law::all_values(*d), law::MAX_INPUT_VALUES) << d->name;
    EXPECT_STREQ(d->kind, "normal");
    for (int g = 1; g < d->group_count; ++g) {  // required groups come first
      if (d->groups[g].required) {
        EXPECT_TRUE(d->groups[g - 1].required) << d->name;
      }
    }
  }
}
