// SPDX-License-Identifier: GPL-2.0-or-later
// Multi-sphere clump core (src/fixes/clumps/): template mass properties against closed forms (single
// sphere, non-overlapping spheres by the parallel-axis theorem, two overlapping spheres as a solid
// of revolution / lens volume), convergence with resolution, principal axes, the text format;
// rigid-body rotation schemes on the torque-free asymmetric top (energy and angular momentum over
// 1e5 steps, Dzhanibekov flip period against the elliptic-integral closed form, isotropic body);
// the N-parallel-contact closed forms and flat-face drops of N = 1, 2, 4, 8 sphere clumps on a
// wall integrated with rigid_body.h, with and without the multiple-contact correction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/multi_contact/contact_tally.h"
#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/rigid_body.h"
#include "fixes/clumps/template.h"

using namespace tdem::clumps;
using tdem::ContactEnd;

namespace {

double rel(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

double frob(const Mat3& a) {
  double s = 0;
  for (auto& r : a)
    for (double v : r) s += v * v;
  return std::sqrt(s);
}
Mat3 msub(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = a[i][j] - b[i][j];
  return c;
}
Mat3 madd(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = a[i][j] + b[i][j];
  return c;
}

// Closed form of a set of NON-overlapping spheres: mass, com and inertia about the com from the
// solid-sphere inertia and the parallel-axis theorem.
MassProperties spheres_closed_form(const std::vector<Sphere>& s, double rho) {
  MassProperties mp;
  Vec3 first{};
  for (const auto& sp : s) {
    const double m = rho * 4.0 / 3.0 * M_PI * sp.r * sp.r * sp.r;
    mp.mass += m;
    first = add(first, scale(m, sp.x));
  }
  mp.com = scale(1.0 / mp.mass, first);
  for (const auto& sp : s) {
    const double m = rho * 4.0 / 3.0 * M_PI * sp.r * sp.r * sp.r;
    Mat3 own{};
    for (int i = 0; i < 3; ++i) own[i][i] = 0.4 * m * sp.r * sp.r;
    mp.inertia = madd(mp.inertia, madd(own, point_inertia(m, sub(sp.x, mp.com))));
  }
  mp.volume = mp.mass / rho;
  return mp;
}

// Two equal spheres (radius R, centres +-d/2 on x) as a solid of revolution about x: the union's
// radius at |x| is a(u)^2 = R^2 - u^2 with u = |x| - d/2 in [-d/2, R]. Integrals of polynomials of
// degree <= 4 in u, evaluated exactly by 3-point Gauss-Legendre.
struct UnionClosedForm {
  double volume, Ixx, Iyy;  // Ixx: about the axis; Iyy: transverse, through the com (origin)
};
UnionClosedForm two_spheres_closed_form(double R, double d, double rho) {
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const double lo = -0.5 * d, hi = R, half = 0.5 * (hi - lo), midp = 0.5 * (hi + lo);
  double V = 0, Ix = 0, Iy = 0;
  for (int k = 0; k < 3; ++k) {
    const double u = midp + half * g[k], a2 = R * R - u * u, x = u + 0.5 * d;
    V += w[k] * half * M_PI * a2;
    Ix += w[k] * half * 0.5 * M_PI * a2 * a2;
    Iy += w[k] * half * M_PI * a2 * (0.25 * a2 + x * x);
  }
  return {2 * V, 2 * rho * Ix, 2 * rho * Iy};
}

}  // namespace

// ======================================================================== templates
TEST(ClumpTemplate, JacobiReconstructsSymmetricMatrix) {
  const Mat3 a{Vec3{4.0, -1.2, 0.3}, Vec3{-1.2, 2.5, 0.7}, Vec3{0.3, 0.7, 1.1}};
  Vec3 l;
  Mat3 v;
  jacobi_eigen(a, l, v);
  EXPECT_LE(l[0], l[1]);
  EXPECT_LE(l[1], l[2]);
  EXPECT_NEAR(det(v), 1.0, 1e-14);
  EXPECT_LT(frob(msub(mul(transpose(v), v), identity())), 1e-14);
  Mat3 D{};
  for (int i = 0; i < 3; ++i) D[i][i] = l[i];
  EXPECT_LT(frob(msub(mul(mul(v, D), transpose(v)), a)), 1e-13);
  // Trace and determinant are invariants.
  EXPECT_NEAR(l[0] + l[1] + l[2], 7.6, 1e-13);
  EXPECT_NEAR(l[0] * l[1] * l[2], det(a), 1e-13);
}

TEST(ClumpTemplate, SingleSphereClosedForm) {
  const double r = 0.5e-3, rho = 2500.0;
  const double m = rho * 4.0 / 3.0 * M_PI * r * r * r, I = 0.4 * m * r * r;
  const Template t = make_template("single", shape_single(r), rho, 128);
  EXPECT_LT(rel(t.mp.mass, m), 2e-3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(t.mp.com[k], 0.0, 1e-15);
    EXPECT_LT(rel(t.mp.principal[k], I), 3e-3);
  }
  std::printf("[ clumps ] single sphere res 128: mass rel err %.2e, I rel err %.2e\n", rel(t.mp.mass, m),
              rel(t.mp.principal[0], I));
}

TEST(ClumpTemplate, NonOverlappingSpheresParallelAxis) {
  // Asymmetric set, different radii, far from the origin.
  const std::vector<Sphere> s = {{Vec3{10.0, -5.0, 3.0}, 0.5},
                                 {Vec3{11.3, -5.2, 3.4}, 0.7},
                                 {Vec3{10.2, -3.9, 2.6}, 0.4},
                                 {Vec3{9.1, -5.6, 3.9}, 0.3}};
  const double rho = 1000.0;
  const MassProperties ref = spheres_closed_form(s, rho);
  const Template t = make_template("asym", s, rho, 160);
  EXPECT_LT(rel(t.mp.mass, ref.mass), 1.5e-3);
  EXPECT_LT(norm(sub(t.mp.com, ref.com)), 5e-4);
  const double err = frob(msub(t.mp.inertia, ref.inertia)) / frob(ref.inertia);
  EXPECT_LT(err, 2e-3);
  // Principal moments against the eigenvalues of the closed-form tensor.
  Vec3 l;
  Mat3 v;
  jacobi_eigen(ref.inertia, l, v);
  for (int k = 0; k < 3; ++k) EXPECT_LT(rel(t.mp.principal[k], l[k]), 2.5e-3) << k;
  // Monte-Carlo: deterministic and within a few standard errors.
  const Template m1 = make_template("asym", s, rho, 96, Integration::monte_carlo);
  const Template m2 = make_template("asym", s, rho, 96, Integration::monte_carlo);
  EXPECT_EQ(m1.mp.mass, m2.mp.mass);
  EXPECT_LT(rel(m1.mp.mass, ref.mass), 1.5e-2);
  EXPECT_LT(frob(msub(m1.mp.inertia, ref.inertia)) / frob(ref.inertia), 3e-2);
  std::printf("[ clumps ] 4 separate spheres: columns 160 mass %.2e inertia %.2e; MC 96^3 mass %.2e inertia %.2e\n",
              rel(t.mp.mass, ref.mass), err, rel(m1.mp.mass, ref.mass),
              frob(msub(m1.mp.inertia, ref.inertia)) / frob(ref.inertia));
}

TEST(ClumpTemplate, RodOfSeparateSpheresExact) {
  // Rod of 3 spheres r = 1, gap: I_xx = 3 (2/5 m r^2), I_yy = I_zz = 3 (2/5 m r^2) + 2 m d^2.
  const double r = 1.0, d = 2.5, rho = 1.0, m = 4.0 / 3.0 * M_PI;
  const Template t = make_template("rod", shape_rod(3, r, d), rho, 192);
  EXPECT_LT(rel(t.mp.principal[0], 1.2 * m), 5e-3);
  EXPECT_LT(rel(t.mp.principal[1], 1.2 * m + 2 * m * d * d), 3e-3);
  EXPECT_LT(rel(t.mp.principal[2], 1.2 * m + 2 * m * d * d), 3e-3);
  // Principal axis 1 is the rod axis.
  EXPECT_NEAR(std::fabs(t.mp.axes[0][0]), 1.0, 1e-12);
}

TEST(ClumpTemplate, TwoOverlappingSpheresUnionClosedForm) {
  const double R = 1.0, d = 1.2, rho = 1.0, Vs = 4.0 / 3.0 * M_PI;
  const UnionClosedForm cf = two_spheres_closed_form(R, d, rho);
  // Lens volume check of the closed form itself: V = 2 (4/3 pi R^3) - pi (4R + d)(2R - d)^2/12.
  const double lens = M_PI * (4 * R + d) * (2 * R - d) * (2 * R - d) / 12.0;
  EXPECT_NEAR(cf.volume, 2 * Vs - lens, 1e-12);
  for (Integration method : {Integration::columns, Integration::voxel}) {
    std::vector<double> errs;
    for (int res : {24, 48, 96, 192}) {
      const Template t = make_template("dimer", shape_rod(2, R, d), rho, res, method);
      const double e = std::max({rel(t.mp.mass, rho * cf.volume), rel(t.mp.principal[0], cf.Ixx),
                                 rel(t.mp.principal[1], cf.Iyy), rel(t.mp.principal[2], cf.Iyy)});
      errs.push_back(e);
      std::printf("[ clumps ] overlapping dimer %-7s res %3d: max rel err (V, Ixx, Iyy, Izz) %.3e\n",
                  to_string(method), res, e);
      // The sum of sphere masses double-counts the lens: the union is below it by the lens.
      EXPECT_LT(t.mp.mass, rho * (2 * Vs - 0.5 * lens)) << res;
    }
    if (method == Integration::columns) {
      EXPECT_LT(errs[0], 3e-2);
      EXPECT_LT(errs.back(), 5e-4);
      // Convergence: every doubling of the resolution reduces the error, by at least a factor 2
      // per doubling on average (second order would be 4).
      for (std::size_t i = 1; i < errs.size(); ++i) EXPECT_LT(errs[i], errs[i - 1]) << i;
      EXPECT_LT(errs.back(), errs.front() / 8.0);
    } else {
      // Voxel counting: erratic but bounded and small at the finest grid.
      EXPECT_LT(errs.back(), 2e-3);
      EXPECT_LT(errs.back(), errs.front() / 4.0);
    }
  }
}

TEST(ClumpTemplate, BodyFrameRoundTripAndBuiltins) {
  for (const char* name : {"single", "dimer", "rod", "tetra", "square4", "cube8"}) {
    const Template t = make_template(name, builtin_shape(name, 0.6, 1.0, 3), 1.0, 48);
    // Placing the body in the template orientation at its com reproduces the input spheres.
    const State s = place(t, t.mp.com);
    const auto p = sphere_positions(s, t);
    ASSERT_EQ(p.size(), t.spheres.size());
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_LT(norm(sub(p[i], t.spheres[i].x)), 1e-13) << name;
    // Body-frame inertia is diagonal: A^T I A = diag(principal).
    const Mat3 D = mul(mul(transpose(t.mp.axes), t.mp.inertia), t.mp.axes);
    EXPECT_LT(std::fabs(D[0][1]) + std::fabs(D[0][2]) + std::fabs(D[1][2]), 1e-12 * t.mp.principal[2]) << name;
  }
  EXPECT_EQ(builtin_shape("rod", 1, 1, 5).size(), 5u);
  EXPECT_EQ(builtin_shape("cube8", 1, 1).size(), 8u);
  const auto tet = shape_tetra(0.3, 1.7);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) EXPECT_NEAR(norm(sub(tet[i].x, tet[j].x)), 1.7, 1e-14);
  // Regular tetra-sphere and cube8: isotropic inertia (cubic symmetry).
  const Template tt = make_template("tetra", tet, 1.0, 64);
  EXPECT_LT(rel(tt.mp.principal[0], tt.mp.principal[2]), 1e-3);
  EXPECT_THROW(builtin_shape("hexagon", 1, 1), std::invalid_argument);
}

TEST(ClumpTemplate, TextFormat) {
  const std::string text =
      "# a dimer\n"
      "sphere 0 0 0 1.0\n"
      "sphere 1.2 0 0 1.0   # second\n"
      "\n"
      "resolution 96\n"
      "density 2.0\n";
  const Template t = parse_template_string(text, "dimer", 0.0);
  const UnionClosedForm cf = two_spheres_closed_form(1.0, 1.2, 2.0);
  EXPECT_EQ(t.size(), 2u);
  EXPECT_LT(rel(t.mp.mass, 2.0 * cf.volume), 3e-3);
  EXPECT_NEAR(t.mp.com[0], 0.6, 1e-12);
  // Explicit mass properties.
  const Template e = parse_template_string(
      "sphere 0 0 0 1\nsphere 2 0 0 1\nmass 3.0\ncom 1 0 0\ninertia 1 4 4 0 0 0\n", "explicit", 0.0);
  EXPECT_EQ(e.mp.mass, 3.0);
  EXPECT_EQ(e.mp.principal[0], 1.0);
  EXPECT_EQ(e.mp.principal[2], 4.0);
  EXPECT_NEAR(e.body[0].x[0] * e.body[1].x[0], -1.0, 1e-15);
  // Bad input names the keyword and the value.
  auto msg = [](const std::string& s) {
    try {
      parse_template_string(s, "bad", 1.0);
    } catch (const std::exception& ex) {
      return std::string(ex.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(msg("sphere 0 0 0 -1\n").find("radius -1"), std::string::npos) << msg("sphere 0 0 0 -1\n");
  EXPECT_NE(msg("sphere 0 0 x 1\n").find("'x'"), std::string::npos);
  EXPECT_NE(msg("sphere 0 0 0\n").find("needs 4"), std::string::npos);
  EXPECT_NE(msg("sphere 0 0 0 1\ncolor red\n").find("unknown keyword 'color'"), std::string::npos);
  EXPECT_NE(msg("sphere 0 0 0 1\nintegration exact\n").find("'exact'"), std::string::npos);
  EXPECT_NE(msg("sphere 0 0 0 1\nmass 2\n").find("all of 'mass', 'com' and 'inertia'"), std::string::npos);
  EXPECT_NE(msg("density 2\n").find("no 'sphere'"), std::string::npos);
  EXPECT_NE(msg("sphere 0 0 0 1\nresolution 2.5\n").find("resolution"), std::string::npos);
  EXPECT_NE(msg("sphere 0 0 0 1\nmass 1\ncom 0 0 0\ninertia 1 1 5 0 0 0\n").find("triangle"), std::string::npos);
  EXPECT_THROW(parse_template_string("sphere 0 0 0 1\n", "nodensity", 0.0), std::invalid_argument);
  EXPECT_THROW(read_template_file("/nonexistent/clump.txt", 1.0), std::invalid_argument);
}

// ======================================================================== rigid body
namespace {

struct TopRun {
  double max_rel_energy = 0, max_rel_energy_first_half = 0, final_rel_energy = 0;
  double max_norm_dev = 0;  // | |Lambda^T L| - |L| | / |L|
  bool L_unchanged = true;
};

TopRun run_free_top(Rotation scheme, const Vec3& inertia, const Vec3& pi0, double h, long steps) {
  const Body b{1.0, inertia};
  State s;
  s.q = qnormalise(Quat{0.9, 0.1, -0.3, 0.2});  // arbitrary orientation
  s.L = mul(rotation_matrix(s.q), pi0);
  const Vec3 L0 = s.L;
  const double E0 = rotational_energy(s, b), Lnorm = norm(L0);
  TopRun r;
  const Vec3 zero{0, 0, 0};
  for (long n = 1; n <= steps; ++n) {
    initial_integrate(s, b, zero, zero, h, scheme);
    final_integrate(s, b, zero, zero, h);
    const double e = std::fabs(rotational_energy(s, b) - E0) / E0;
    r.max_rel_energy = std::max(r.max_rel_energy, e);
    if (n <= steps / 2) r.max_rel_energy_first_half = r.max_rel_energy;
    r.max_norm_dev = std::max(r.max_norm_dev, std::fabs(norm(body_angular_momentum(s)) - Lnorm) / Lnorm);
  }
  r.final_rel_energy = (rotational_energy(s, b) - E0) / E0;
  r.L_unchanged = (s.L == L0);
  return r;
}

}  // namespace

TEST(ClumpRigidBody, TorqueFreeAsymmetricTopSymplecticVsExplicit) {
  const Vec3 I{1.0, 2.0, 3.0};
  struct Case {
    const char* name;
    Vec3 omega;
  } cases[] = {{"intermediate", {0.05, 1.0, 0.05}}, {"near-max", {0.1, 0.1, 1.0}}, {"near-min", {1.0, 0.1, 0.1}}};
  for (const auto& c : cases) {
    const Vec3 pi0{I[0] * c.omega[0], I[1] * c.omega[1], I[2] * c.omega[2]};
    const double h = 0.01;  // |omega| h ~ 0.01
    const long steps = 100000;
    const TopRun sp = run_free_top(Rotation::splitting, I, pi0, h, steps);
    const TopRun ex = run_free_top(Rotation::explicit_rodrigues, I, pi0, h, steps);
    const TopRun ri = run_free_top(Rotation::richardson, I, pi0, h, steps);
    std::printf("[ clumps ] free top %-12s 1e5 steps h=%.3g: splitting max|dE/E| %.2e (first half %.2e) final %.2e;"
                " explicit final %.2e; richardson final %.2e; | |pi|-|L| |/|L| %.1e\n",
                c.name, h, sp.max_rel_energy, sp.max_rel_energy_first_half, sp.final_rel_energy,
                ex.final_rel_energy, ri.final_rel_energy, sp.max_norm_dev);
    // Angular momentum: space-frame L untouched by torque-free steps; its body-frame image keeps
    // the norm to round-off (unit quaternion).
    EXPECT_TRUE(sp.L_unchanged) << c.name;
    EXPECT_LT(sp.max_norm_dev, 1e-12) << c.name;
    // Symplectic splitting: energy error bounded (O(h^2)) and not growing: the whole run's maximum
    // is reached within the first half already (up to 10 %).
    EXPECT_LT(sp.max_rel_energy, 2e-4) << c.name;
    EXPECT_LE(sp.max_rel_energy, 1.1 * sp.max_rel_energy_first_half + 1e-12) << c.name;
    // The explicit incremental rotation drifts: its final energy error exceeds the splitting's
    // bound by far.
    EXPECT_GT(std::fabs(ex.final_rel_energy), 20.0 * sp.max_rel_energy) << c.name;
  }
}

namespace {
double agm_K(double k2) {  // complete elliptic integral of the first kind K(k), k2 = k^2
  double a = 1.0, g = std::sqrt(1.0 - k2);
  for (int i = 0; i < 60 && std::fabs(a - g) > 1e-16 * a; ++i) {
    const double an = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = an;
  }
  return M_PI / (2.0 * a);
}
// Time between sign changes of the intermediate-axis momentum pi_2 (Landau & Lifshitz, Mechanics
// section 37): 2 K(k)/lambda with lambda = sqrt((I3 - I2)(L^2 - 2 E I1)/(I1 I2 I3)),
// k^2 = (I2 - I1)(2 E I3 - L^2)/((I3 - I2)(L^2 - 2 E I1)) for L^2 > 2 E I2; indices 1 and 3 swapped
// otherwise.
double flip_half_period(Vec3 I, double E, double L2) {
  if (L2 < 2 * E * I[1]) std::swap(I[0], I[2]);
  const double lam = std::sqrt((I[2] - I[1]) * (L2 - 2 * E * I[0]) / (I[0] * I[1] * I[2]));
  const double k2 = (I[1] - I[0]) * (2 * E * I[2] - L2) / ((I[2] - I[1]) * (L2 - 2 * E * I[0]));
  return 2.0 * agm_K(k2) / lam;
}
}  // namespace

TEST(ClumpRigidBody, DzhanibekovFlipPeriodClosedForm) {
  const Vec3 I{1.0, 2.0, 3.0};
  const Body b{1.0, I};
  for (const Vec3 omega : {Vec3{0.05, 1.0, 0.05}, Vec3{0.15, 1.0, 0.02}}) {
    State s;
    s.q = qnormalise(Quat{0.3, -0.5, 0.1, 0.8});
    s.L = mul(rotation_matrix(s.q), Vec3{I[0] * omega[0], I[1] * omega[1], I[2] * omega[2]});
    const double E = rotational_energy(s, b), L2 = dot(s.L, s.L);
    const double expected = flip_half_period(I, E, L2);
    for (Rotation scheme : {Rotation::splitting, Rotation::richardson}) {
      State st = s;
      const double h = 0.002;
      const Vec3 zero{0, 0, 0};
      double prev = body_angular_momentum(st)[1], t = 0;
      std::vector<double> crossings;
      for (long n = 0; n < 100000; ++n) {
        initial_integrate(st, b, zero, zero, h, scheme);
        final_integrate(st, b, zero, zero, h);
        t += h;
        const double cur = body_angular_momentum(st)[1];
        if ((prev < 0) != (cur < 0)) crossings.push_back(t - h * cur / (cur - prev));
        prev = cur;
      }
      ASSERT_GE(crossings.size(), 4u);
      const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
      std::printf("[ clumps ] flip half-period, L^2 %s 2 E I2: closed form %.8f, %s %.8f (rel %.1e, %zu flips)\n",
                  L2 > 2 * E * I[1] ? ">" : "<", expected, to_string(scheme), measured, rel(measured, expected),
                  crossings.size());
      EXPECT_LT(rel(measured, expected), 1e-4) << to_string(scheme);
    }
  }
}

TEST(ClumpRigidBody, IsotropicBodyRotatesAtConstantOmega) {
  const Body b{2.0, Vec3{0.7, 0.7, 0.7}};
  const Vec3 omega{0.3, -1.1, 0.8};
  for (Rotation scheme : {Rotation::explicit_rodrigues, Rotation::splitting, Rotation::richardson}) {
    State s;
    s.q = qnormalise(Quat{0.5, 0.5, -0.1, 0.3});
    const Quat q0 = s.q;
    set_angular_velocity(s, b, omega);
    const double h = 1e-3;
    const long steps = 20000;
    const Vec3 zero{0, 0, 0};
    double dev = 0;
    for (long n = 0; n < steps; ++n) {
      initial_integrate(s, b, zero, zero, h, scheme);
      final_integrate(s, b, zero, zero, h);
      dev = std::max(dev, norm(sub(angular_velocity(s, b), omega)));
    }
    EXPECT_LT(dev, 1e-14) << to_string(scheme);
    // Orientation against the exact rotation about the fixed axis omega by |omega| t: exact for the
    // incremental rotation (it IS the exact flow here); second order for the other two (halving h
    // reduces the error fourfold).
    const Quat exact = qmul(quat_from_rotation_vector(scale(h * steps, omega)), q0);
    const double err = frob(msub(rotation_matrix(s.q), rotation_matrix(exact)));
    State s2;
    s2.q = q0;
    set_angular_velocity(s2, b, omega);
    for (long n = 0; n < 2 * steps; ++n) {
      initial_integrate(s2, b, zero, zero, 0.5 * h, scheme);
      final_integrate(s2, b, zero, zero, 0.5 * h);
    }
    const double err2 = frob(msub(rotation_matrix(s2.q), rotation_matrix(exact)));
    std::printf("[ clumps ] isotropic body %-10s: max |omega - omega0| %.1e, orientation error at t = 20: "
                "h %.2e, h/2 %.2e\n", to_string(scheme), dev, err, err2);
    if (scheme == Rotation::explicit_rodrigues) {
      EXPECT_LT(err, 1e-12);
    } else {
      EXPECT_LT(err, 1e-5) << to_string(scheme);
      EXPECT_NEAR(err / err2, 4.0, 0.2) << to_string(scheme);
    }
  }
}

TEST(ClumpRigidBody, PointVelocityAndGyroscopicTerm) {
  const Template t = make_template("rod", shape_rod(3, 0.5, 0.8), 1000.0, 48);
  const Body b = Body::from(t);
  State s = place(t, Vec3{1, 2, 3}, qnormalise(Quat{0.8, 0.2, 0.4, -0.1}));
  s.v = {0.1, -0.2, 0.3};
  set_angular_velocity(s, b, Vec3{2.0, -1.0, 0.5});
  // Velocity of a body point against a central difference of its position under exact rotation.
  const Vec3 r_hat = t.body[2].x;
  const Vec3 xp = body_point(s, r_hat);
  const Vec3 w = angular_velocity(s, b);
  const double dt = 1e-6;
  State a = s, c = s;
  a.x = add(s.x, scale(dt, s.v));
  a.q = qmul(quat_from_rotation_vector(scale(dt, w)), s.q);
  c.x = add(s.x, scale(-dt, s.v));
  c.q = qmul(quat_from_rotation_vector(scale(-dt, w)), s.q);
  const Vec3 fd = scale(0.5 / dt, sub(body_point(a, r_hat), body_point(c, r_hat)));
  EXPECT_LT(norm(sub(fd, point_velocity(s, b, xp))), 1e-8);
  // Euler's equations: for torque-free motion d(omega_body)/dt = I^-1 (pi x omega_body); check the
  // integrated body-frame omega change over a small step against it (the gyroscopic term).
  const Mat3 R0 = rotation_matrix(s.q);
  const Vec3 wb0 = mul_t(R0, w), pi0 = mul_t(R0, s.L);
  State n = s;
  const double h = 1e-5;
  const Vec3 zero{0, 0, 0};
  initial_integrate(n, b, zero, zero, h, Rotation::splitting);
  final_integrate(n, b, zero, zero, h);
  const Vec3 wb1 = mul_t(rotation_matrix(n.q), angular_velocity(n, b));
  const Vec3 g = cross(pi0, wb0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR((wb1[k] - wb0[k]) / h, g[k] / b.inertia[k], 1e-4 * norm(w) * norm(w));
}

// The sub-rotations' sin/cos of small angles (Taylor polynomials) agree with the library's to one
// rounding of the value, over the whole small-angle range and across its edge; larger angles are the
// library's own; the inverse inertia of a stock fix's principal moments and axes.
TEST(ClumpRigidBody, SmallAngleSinCosAsAccurateAsTheLibrary) {
  double worst_s = 0.0, worst_c = 0.0;
  for (int k = -20000; k <= 20000; ++k) {
    const double x = 0.0100003 * k / 20000.0 * (1.0 + 1e-7 * (k % 7));
    double s, c;
    detail::small_angle_sincos(x, s, c);
    if (x != 0.0) worst_s = std::max(worst_s, std::fabs(s - std::sin(x)) / std::fabs(std::sin(x)));
    worst_c = std::max(worst_c, std::fabs(c - std::cos(x)));
  }
  EXPECT_LE(worst_s, 2.3e-16);  // one unit in the last place (2^-52) and the library's own half
  EXPECT_LE(worst_c, 1.2e-16);
  double s, c;
  detail::small_angle_sincos(0.3, s, c);
  EXPECT_EQ(s, std::sin(0.3));
  EXPECT_EQ(c, std::cos(0.3));
  detail::small_angle_sincos(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
}

TEST(ClumpRigidBody, InverseInertiaFromPrincipalAxes) {
  const Quat q = qnormalise(Quat{0.9, 0.2, -0.3, 0.25});
  const Mat3 R = rotation_matrix(q);
  const Vec3 I{2.0, 3.0, 5.0};
  const Mat3 inv = inverse_inertia_space(R, I);
  // R^T inv R = diag(1/I)
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double v = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) v += R[i][a] * inv[i][j] * R[j][b];
      EXPECT_NEAR(v, a == b ? 1.0 / I[a] : 0.0, 1e-15) << a << b;
    }
  // a zero moment (an axis the fix does not turn about) adds nothing along that axis
  const Mat3 rod = inverse_inertia_space(R, Vec3{0.0, 3.0, 3.0});
  for (int i = 0; i < 3; ++i) {
    double v = 0.0;
    for (int j = 0; j < 3; ++j) v += rod[i][j] * R[j][0];
    EXPECT_NEAR(v, 0.0, 1e-16);
  }
}

TEST(ClumpRigidBody, SchemeNames) {
  EXPECT_EQ(rotation_from_string("splitting"), Rotation::splitting);
  EXPECT_EQ(rotation_from_string("explicit"), Rotation::explicit_rodrigues);
  EXPECT_EQ(rotation_from_string("richardson"), Rotation::richardson);
  try {
    rotation_from_string("verlet");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'verlet'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("explicit, splitting, richardson"), std::string::npos);
  }
  EXPECT_THROW(correction_from_string("half"), std::invalid_argument);
}

// ======================================================================== multiple contacts
TEST(ClumpMultiContact, ClosedFormsOfNParallelContacts) {
  // physics_reference 6.4: e = 0.8 -> 0.729 (N = 2), 0.638 (N = 4); t_c x 0.71, x 0.50.
  const double e1 = 0.8, t1 = 1e-4;
  const double beta = tdem::lsd::damping_ratio_from_restitution(e1, ContactEnd::zero_overlap);
  const double w0 = M_PI / (t1 * std::sqrt(1 - beta * beta));
  EXPECT_NEAR(n_contacts_restitution_zero_overlap(beta, 1), e1, 1e-14);
  EXPECT_NEAR(n_contacts_time_zero_overlap(beta, w0, 1), t1, 1e-18);
  EXPECT_NEAR(n_contacts_restitution_zero_overlap(beta, 2), 0.729, 5e-4);
  EXPECT_NEAR(n_contacts_restitution_zero_overlap(beta, 4), 0.638, 5e-4);
  EXPECT_NEAR(n_contacts_time_zero_overlap(beta, w0, 2) / t1, 0.71, 5e-3);
  EXPECT_NEAR(n_contacts_time_zero_overlap(beta, w0, 4) / t1, 0.50, 5e-3);
  for (int n : {1, 2, 4, 8}) {
    const NContactOutcome o = n_contacts_outcome(e1, t1, n, ContactEnd::zero_overlap);
    EXPECT_NEAR(o.e, n_contacts_restitution_zero_overlap(beta, n), 1e-13) << n;
    EXPECT_NEAR(o.tc / t1, n_contacts_time_zero_overlap(beta, w0, n) / t1, 1e-12) << n;
    const NContactOutcome f = n_contacts_outcome(e1, t1, n, ContactEnd::zero_force);
    if (n == 1) {
      EXPECT_NEAR(f.e, e1, 1e-12);
      EXPECT_NEAR(f.tc, t1, 1e-15);
    } else {
      EXPECT_LT(f.e, e1);
      EXPECT_LT(f.tc, t1);
    }
  }
  EXPECT_THROW(n_contacts_outcome(0.8, 1e-4, 0, ContactEnd::zero_overlap), std::domain_error);
  EXPECT_EQ(correction_factor(Correction::count, 4, 1e-6, 4e-6), 0.25);
  EXPECT_EQ(correction_factor(Correction::overlap_share, 4, 1e-6, 4e-6), 0.25);
  EXPECT_EQ(correction_factor(Correction::overlap_share, 2, 0.0, 4e-6), 0.0);
  EXPECT_EQ(correction_factor(Correction::none, 4, 1e-6, 4e-6), 1.0);
}

namespace {

struct DropOutcome {
  double e = 0, tc = 0, max_step_force_jump = 0, max_force = 0;
  double max_spin = 0;
  double e_point = 0;  // normal velocity of the first-touching sphere's lowest point, after / -before
};

// A clump dropped on the wall z = 0 with LSD per sphere-wall contact (zero-overlap end), per-contact
// coefficients rates.at(m) with m the body mass M (or, with Correction::local_mass, the locally
// reduced mass of the contact, re-evaluated every step), velocity Verlet + rotation scheme of
// rigid_body.h. Initial state: touching (lowest sphere at zero overlap), com velocity (0, 0, -v0).
DropOutcome drop(const Template& t, const Quat& orient, double v0, const tdem::lsd::MassRates<double>& rates,
                 Correction corr, double h) {
  const Body b = Body::from(t);
  State s = place(t, Vec3{0, 0, 0}, orient);
  double zmin = INFINITY;
  std::size_t i0 = 0;
  for (std::size_t i = 0; i < t.body.size(); ++i) {
    const double zi = sphere_positions(s, t)[i][2] - t.body[i].r;
    if (zi < zmin) {
      zmin = zi;
      i0 = i;
    }
  }
  s.x[2] = -zmin;  // lowest sphere just touches
  s.v = {0, 0, -v0};
  auto forces = [&](const State& st, Vec3& F, Vec3& T, bool first) {
    F = {0, 0, 0};
    T = {0, 0, 0};
    const auto p = sphere_positions(st, t);
    std::vector<double> xi(p.size()), xid(p.size());
    std::vector<bool> on(p.size(), false);
    int nc = 0;
    double xsum = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      xi[i] = t.body[i].r - p[i][2];
      const Vec3 cp{p[i][0], p[i][1], 0.0};
      xid[i] = -point_velocity(st, b, cp)[2];
      // In contact with positive overlap; at t = 0 also at exactly zero overlap while approaching.
      on[i] = xi[i] > 0 || (first && std::fabs(xi[i]) < 1e-15 * t.body[i].r && xid[i] > 0);
      if (on[i]) {
        ++nc;
        xsum += std::max(0.0, xi[i]);
      }
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!on[i]) continue;
      const double sfac = (first && corr == Correction::overlap_share && xsum == 0) ? 1.0 / nc
                                                                                     : correction_factor(corr, nc, xi[i], xsum);
      const Vec3 cp{p[i][0], p[i][1], 0.0};
      const double meff = corr == Correction::local_mass
                              ? local_reduced_mass(b.mass, inverse_inertia_space(st, b), sub(cp, st.x), Vec3{0, 0, 1})
                              : b.mass;
      const auto c = rates.at(meff);
      const double f = sfac * (c.k * xi[i] + c.gamma * xid[i]);
      const Vec3 Fi{0, 0, f};
      F = add(F, Fi);
      T = add(T, cross(sub(cp, st.x), Fi));
    }
    return nc;
  };
  Vec3 F, T;
  forces(s, F, T, true);
  DropOutcome out;
  double t_now = 0;
  double prev_f = F[2];
  auto deepest = [&](const State& st) {
    const auto p = sphere_positions(st, t);
    double m = -INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i) m = std::max(m, t.body[i].r - p[i][2]);
    return m;
  };
  double prev_deep = 0;
  for (long n = 0; n < 10000000; ++n) {
    initial_integrate(s, b, F, T, h, Rotation::splitting);
    const int nc = forces(s, F, T, false);
    final_integrate(s, b, F, T, h);
    t_now += h;
    // Force changes while the body stays in contact (the final separation excluded).
    if (nc > 0) out.max_step_force_jump = std::max(out.max_step_force_jump, std::fabs(F[2] - prev_f));
    out.max_force = std::max(out.max_force, std::fabs(F[2]));
    out.max_spin = std::max(out.max_spin, norm(angular_velocity(s, b)));
    prev_f = F[2];
    const double deep = deepest(s);
    if (nc == 0 && n > 2) {
      out.tc = t_now - h * (-deep) / (prev_deep - deep);  // linear interpolation of the last zero
      out.e = s.v[2] / v0;
      const Vec3 p0 = sphere_positions(s, t)[i0];
      out.e_point = point_velocity(s, b, Vec3{p0[0], p0[1], 0.0})[2] / v0;
      return out;
    }
    prev_deep = deep;
  }
  return out;
}

}  // namespace

TEST(ClumpMultiContact, FlatFaceDropsMatchNContactClosedFormAndCorrection) {
  const double r = 1e-3, rho = 2500.0, v0 = 1.0, e1 = 0.8, t1 = 1e-4;
  struct Shape {
    int n;
    Template t;
  };
  // Flat faces of N spheres in the xy plane: single, dimer, 2x2 square, 4x2 plate.
  std::vector<Shape> shapes = {{1, make_template("single", shape_single(r), rho, 48)},
                               {2, make_template("dimer", shape_rod(2, r, 1.8 * r), rho, 48)},
                               {4, make_template("square4", shape_square4(r, 1.8 * r), rho, 48)},
                               {8, make_template("plate8", shape_grid(4, 2, 1, r, 1.8 * r), rho, 48)}};
  const double beta = tdem::lsd::damping_ratio_from_restitution(e1, ContactEnd::zero_overlap);
  const double w0 = M_PI / (t1 * std::sqrt(1 - beta * beta));
  for (const auto& sh : shapes) {
    // The plate lies in the template's xy plane; the body frame puts the largest moment first or
    // last, so drop with the TEMPLATE orientation (q_template = 1): all spheres at the same height.
    ASSERT_EQ(static_cast<int>(sh.t.size()), sh.n);
    const auto c = tdem::lsd::rates_from_restitution_and_time(e1, t1, ContactEnd::zero_overlap);
    const double eN = n_contacts_restitution_zero_overlap(beta, sh.n);
    const double tN = n_contacts_time_zero_overlap(beta, w0, sh.n);
    const double h = tN / 5000.0;
    const DropOutcome none = drop(sh.t, Quat{}, v0, c, Correction::none, h);
    const DropOutcome cnt = drop(sh.t, Quat{}, v0, c, Correction::count, t1 / 5000.0);
    const DropOutcome ovl = drop(sh.t, Quat{}, v0, c, Correction::overlap_share, t1 / 5000.0);
    std::printf("[ clumps ] flat drop N=%d: none e %.6f (closed %.6f, rel %.1e) t_c %.6e (closed %.6e, rel %.1e);"
                " count e %.6f t_c %.6e (rel %.1e, %.1e); overlap e %.6f t_c %.6e; max spin %.1e rad/s\n",
                sh.n, none.e, eN, rel(none.e, eN), none.tc, tN, rel(none.tc, tN), cnt.e, cnt.tc, rel(cnt.e, e1),
                rel(cnt.tc, t1), ovl.e, ovl.tc, none.max_spin);
    EXPECT_LT(rel(none.e, eN), 1e-3) << sh.n;
    EXPECT_LT(rel(none.tc, tN), 1e-3) << sh.n;
    EXPECT_LT(rel(cnt.e, e1), 1e-3) << sh.n;
    EXPECT_LT(rel(cnt.tc, t1), 1e-3) << sh.n;
    EXPECT_LT(rel(ovl.e, e1), 1e-3) << sh.n;
    EXPECT_LT(rel(ovl.tc, t1), 1e-3) << sh.n;
    // Symmetric flat impact: no rotation beyond round-off.
    EXPECT_LT(none.max_spin * r, 1e-9 * v0) << sh.n;
  }
}

TEST(ClumpMultiContact, OverlapShareIsContinuousWhereCountJumps) {
  // Slightly tilted dimer: one sphere touches first, the second joins during the contact.
  const double r = 1e-3, rho = 2500.0, v0 = 1.0;
  const Template t = make_template("dimer", shape_rod(2, r, 1.8 * r), rho, 48);
  const auto c = tdem::lsd::rates_from_restitution_and_time(0.8, 1e-4, ContactEnd::zero_overlap);
  const Quat tilt = quat_from_rotation_vector(Vec3{0, 0.005, 0});  // about y: the x-ends at different heights
  const double h = 1e-4 / 5000.0;
  const DropOutcome cnt = drop(t, tilt, v0, c, Correction::count, h);
  const DropOutcome ovl = drop(t, tilt, v0, c, Correction::overlap_share, h);
  const DropOutcome none = drop(t, tilt, v0, c, Correction::none, h);
  std::printf("[ clumps ] tilted dimer: largest force change in one step / peak force: none %.2e, count %.2e, "
              "overlap %.2e; e none %.4f count %.4f overlap %.4f\n",
              none.max_step_force_jump / none.max_force, cnt.max_step_force_jump / cnt.max_force,
              ovl.max_step_force_jump / ovl.max_force, none.e, cnt.e, ovl.e);
  // While in contact: overlap sharing changes the force by O(h/t_c) per step only; without a
  // correction the second sphere brings its damping force gamma xi_dot at once; count in addition
  // halves the first contact's force when the second opens.
  EXPECT_GT(cnt.max_step_force_jump, 5.0 * ovl.max_step_force_jump);
  EXPECT_GT(none.max_step_force_jump, 5.0 * ovl.max_step_force_jump);
  EXPECT_LT(ovl.max_step_force_jump, 1e-2 * ovl.max_force);
}

TEST(ClumpMultiContact, LocalReducedMassMatchesImpulseResponse) {
  const double r = 1e-3, d = 1.8e-3;
  const Template t = make_template("dimer", shape_rod(2, r, d), 2500.0, 64);
  const Body b = Body::from(t);
  const State s0 = place(t, Vec3{0, 0, r}, Quat{});
  const Vec3 n{0, 0, 1};
  // Contact point under sphere 2 (at +d/2 on x): r = (d/2, 0, -r); (r x n) = (0, -d/2, 0), so
  // 1/m_loc = 1/M + (d/2)^2 / I_yy (I_yy: transverse moment of the dimer).
  const Vec3 cp{0.5 * d, 0, 0};
  const Vec3 rr = sub(cp, s0.x);
  const double m_loc = local_reduced_mass(b.mass, inverse_inertia_space(s0, b), rr, n);
  const double Iyy = t.mp.principal[1];
  EXPECT_NEAR(1.0 / m_loc, 1.0 / b.mass + 0.25 * d * d / Iyy, 1e-10 / b.mass);
  EXPECT_LT(m_loc, b.mass);
  // Independent: apply a normal impulse J at the contact point; the point's normal velocity changes
  // by J / m_loc.
  State s = s0;
  const double J = 1e-6;
  apply_impulse(s, b, scale(J, n), cp);
  const double dvn = dot(point_velocity(s, b, cp), n) - dot(point_velocity(s0, b, cp), n);
  EXPECT_LT(rel(dvn, J / m_loc), 1e-12);
  // Two bodies: inverse masses add; a point on the line of the com gives back the reduced mass.
  const Mat3 Ii = inverse_inertia_space(s0, b);
  EXPECT_NEAR(local_reduced_mass(b.mass, Ii, Vec3{0, 0, -r}, b.mass, Ii, Vec3{0, 0, r}, n), 0.5 * b.mass,
              1e-14 * b.mass);
}

// Single-contact (tilted) impact: a dimer tilted by 0.5 rad hits with its lower sphere only. Over a
// short contact the geometry hardly changes, so rigid-body impact theory with the locally reduced
// mass m_loc applies: the contact point rebounds with the restitution of the LSD law for mass
// m_loc, and the centre of mass with v' = -v0 + (1 + e_pt) m_loc v0 / M.
TEST(ClumpMultiContact, TiltedSingleContactAgainstRigidBodyImpactTheory) {
  const double r = 1e-3, d = 1.8e-3, v0 = 1.0, e1 = 0.8, t1 = 1e-6, theta = 0.5;
  const Template t = make_template("dimer", shape_rod(2, r, d), 2500.0, 64);
  const double M = t.mp.mass;
  const double rx = 0.5 * d * std::cos(theta);  // lever arm of the contact point
  const double m_loc = 1.0 / (1.0 / M + rx * rx / t.mp.principal[1]);
  const auto rates = tdem::lsd::rates_from_restitution_and_time(e1, t1, ContactEnd::zero_overlap);
  const Quat tilt = quat_from_rotation_vector(Vec3{0, theta, 0});
  const double h = t1 / 5000.0;
  // Body-mass parameters (no correction): the contact point sees the law with mass m_loc.
  const DropOutcome none = drop(t, tilt, v0, rates, Correction::none, h);
  const auto cM = rates.at(M);
  const double e_pt = tdem::lsd::restitution(cM, m_loc, ContactEnd::zero_overlap);
  const double t_pt = tdem::lsd::contact_time(cM, m_loc, ContactEnd::zero_overlap);
  // Local-mass parameters: the contact point recovers e1 and t1.
  const DropOutcome loc = drop(t, tilt, v0, rates, Correction::local_mass, h);
  std::printf("[ clumps ] tilted dimer single contact, m_loc/M = %.4f: none e_pt %.5f (theory %.5f) t_c %.4e (%.4e)"
              " e_cm %.5f (%.5f); local_mass e_pt %.5f (%.5f) t_c %.4e (%.4e) e_cm %.5f (%.5f)\n",
              m_loc / M, none.e_point, e_pt, none.tc, t_pt, none.e, -1 + (1 + e_pt) * m_loc / M, loc.e_point, e1,
              loc.tc, t1, loc.e, -1 + (1 + e1) * m_loc / M);
  EXPECT_LT(m_loc / M, 0.7);
  EXPECT_LT(rel(none.e_point, e_pt), 2e-3);
  EXPECT_LT(rel(none.tc, t_pt), 2e-3);
  EXPECT_LT(std::fabs(none.e - (-1 + (1 + e_pt) * m_loc / M)), 2e-3);
  EXPECT_LT(rel(loc.e_point, e1), 2e-3);
  EXPECT_LT(rel(loc.tc, t1), 2e-3);
  EXPECT_LT(std::fabs(loc.e - (-1 + (1 + e1) * m_loc / M)), 2e-3);
}

// ContactTally (contact_tally.h): the per-step body-pair sums the host styles use.
TEST(ClumpContactTally, CountAndOverlapShareFactors) {
  ContactTally t(1e-3);
  // body 0 against wall -7: three contacts of unequal overlap; body 1 against free sphere -5: one
  const double xi[3] = {1e-6, 3e-6, 2.5e-6};
  for (double v : xi) t.add(0, -7, v);
  t.add(-5, 1, 4e-6);
  ASSERT_EQ(t.contacts(), 4u);
  ASSERT_EQ(t.pairs(), 2u);
  double share = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(t.count_of(k), 3);
    EXPECT_EQ(t.factor(Correction::count, k, xi[k]), 1.0 / 3.0);
    share += t.factor(Correction::overlap_share, k, xi[k]);
  }
  EXPECT_NEAR(share, 1.0, 1e-15);
  EXPECT_NEAR(t.overlap_sum_of(0), 6.5e-6, 1e-20);
  // a single contact keeps its force exactly; the other corrections leave every contact alone
  EXPECT_EQ(t.factor(Correction::count, 3, 4e-6), 1.0);
  EXPECT_EQ(t.factor(Correction::overlap_share, 3, 4e-6), 1.0);
  EXPECT_EQ(t.factor(Correction::none, 0, xi[0]), 1.0);
  EXPECT_EQ(t.factor(Correction::local_mass, 0, xi[0]), 1.0);
  // the pair key does not depend on the order of the sides
  t.add(-7, 0, 0.5e-6);
  EXPECT_EQ(t.count_of(4), 4);
  EXPECT_EQ(t.count_of(0), 4);
  t.clear();
  EXPECT_EQ(t.contacts(), 0u);
  EXPECT_EQ(t.pairs(), 0u);
}

TEST(ClumpContactTally, SumIsIndependentOfOrderAndOfTheSplitOverRanks) {
  // 40 contacts of 5 body pairs with overlaps whose double sums depend on the order
  std::vector<double> xi;
  std::vector<std::int64_t> a;
  for (int k = 0; k < 40; ++k) {
    xi.push_back(1e-7 * (1.0 + 0.37 * k + 1e-9 * k * k) * (k % 3 == 0 ? 1e3 : 1.0));
    a.push_back(k % 5);
  }
  ContactTally fwd(2e-3), bwd(2e-3);
  for (int k = 0; k < 40; ++k) fwd.add(a[k], -1, xi[k]);
  for (int k = 39; k >= 0; --k) bwd.add(a[k], -1, xi[k]);
  for (int k = 0; k < 40; ++k) {
    const std::size_t kb = 39 - k;
    EXPECT_EQ(fwd.overlap_sum_of(k), bwd.overlap_sum_of(kb));  // bitwise
    EXPECT_EQ(fwd.factor(Correction::overlap_share, k, xi[k]),
              bwd.factor(Correction::overlap_share, kb, xi[k]));
  }
  // "two ranks": even contacts here, odd ones there; pack, merge the other block, compare
  ContactTally r0(2e-3), r1(2e-3);
  for (int k = 0; k < 40; ++k) (k % 2 ? r1 : r0).add(a[k], -1, xi[k]);
  r0.add(99, 98, 1e-6);  // a pair only rank 0 has
  std::vector<std::int64_t> b0, b1;
  r0.pack(b0);
  r1.pack(b1);
  r0.merge_packed(b1.data(), b1.size() / ContactTally::pack_width);
  r1.merge_packed(b0.data(), b0.size() / ContactTally::pack_width);
  std::size_t k0 = 0, k1 = 0;
  for (int k = 0; k < 40; ++k) {
    const ContactTally& r = (k % 2) ? r1 : r0;
    const std::size_t kr = (k % 2) ? k1++ : k0++;
    EXPECT_EQ(r.count_of(kr), 8);
    EXPECT_EQ(r.overlap_sum_of(kr), fwd.overlap_sum_of(k));
    EXPECT_EQ(r.factor(Correction::overlap_share, kr, xi[k]), fwd.factor(Correction::overlap_share, k, xi[k]));
  }
  EXPECT_EQ(r0.count_of(k0), 1);  // the pair only rank 0 has keeps its own count
  EXPECT_EQ(r1.pairs(), 5u);      // pairs of the other rank are not added
}

TEST(ClumpContactTally, OverlapShareForceIsContinuousWhenASecondContactCloses) {
  // the linear force sum_i s_i k xi_i of a body pair before and just after a second contact
  // closes (xi2 = 0 -> 1e-15 m): continuous with overlap_share, a jump of k xi1 / 2 with count
  const double k = 1e5, xi1 = 2e-5;
  auto force = [&](Correction c, double xi2) {
    ContactTally t(1e-3);
    t.add(3, -1, xi1);
    if (xi2 > 0.0) t.add(3, -1, xi2);
    double f = t.factor(c, 0, xi1) * k * xi1;
    if (xi2 > 0.0) f += t.factor(c, 1, xi2) * k * xi2;
    return f;
  };
  EXPECT_NEAR(force(Correction::overlap_share, 1e-15), force(Correction::overlap_share, 0.0), 1e-9 * k * xi1);
  EXPECT_NEAR(force(Correction::count, 1e-15), 0.5 * k * xi1, 1e-9 * k * xi1);
  EXPECT_NEAR(force(Correction::count, 0.0), k * xi1, 1e-12 * k * xi1);
}

TEST(ClumpContactTally, LookupByTheSidesGivesTheFactorOfTheContactOrder) {
  ContactTally t(1e-3);
  t.add(2, 5, 1e-6);
  t.add(5, 2, 3e-6);
  t.add(2, -9, 2e-6);
  EXPECT_EQ(t.find(5, 2), t.find(2, 5));
  EXPECT_EQ(t.find(7, 5), -1);
  EXPECT_EQ(t.pair_factor(Correction::overlap_share, t.find(2, 5), 3e-6),
            t.factor(Correction::overlap_share, 1, 3e-6));
  EXPECT_EQ(t.pair_factor(Correction::count, t.find(2, 5), 1e-6), 0.5);
  EXPECT_EQ(t.pair_factor(Correction::count, t.find(-9, 2), 2e-6), 1.0);
  EXPECT_EQ(t.pair_factor(Correction::count, -1, 2e-6), 1.0);
}

TEST(ClumpContactTally, UncountedCopyKeepsItsPlaceAndReceivesTheOtherRanksCount) {
  // newton off: rank 0 counts a contact of pair (1, 2) that rank 1 also sees (uncounted there);
  // rank 1 counts another contact of the same pair
  ContactTally r0(1e-3), r1(1e-3);
  r0.add(1, 2, 2e-6);
  r1.add(2, 1, 2e-6, false);  // rank 0's contact, seen here too
  r1.add(1, 2, 1e-6);
  EXPECT_EQ(r1.contacts(), 2u);  // both keep their place in the contact order
  EXPECT_EQ(r1.count_of(0), 1);  // before the merge: only its own contact
  std::vector<std::int64_t> b0, b1;
  r0.pack(b0);
  r1.pack(b1);
  r0.merge_packed(b1.data(), b1.size() / ContactTally::pack_width);
  r1.merge_packed(b0.data(), b0.size() / ContactTally::pack_width);
  for (const ContactTally* r : {&r0, &r1}) {
    EXPECT_EQ(r->count_of(0), 2);
    EXPECT_NEAR(r->overlap_sum_of(0), 3e-6, 1e-20);
  }
  EXPECT_EQ(r1.factor(Correction::overlap_share, 0, 2e-6), r0.factor(Correction::overlap_share, 0, 2e-6));
  // a pair seen only as an uncounted copy has no count of its own
  ContactTally t(1e-3);
  t.add(5, 6, 1e-6, false);
  EXPECT_EQ(t.count_of(0), 0);
  EXPECT_EQ(t.pair_factor(Correction::count, t.find(5, 6), 1e-6), 1.0);
}
