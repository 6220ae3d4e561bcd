// SPDX-License-Identifier: GPL-2.0-or-later
// The bodies of fix tdem/clump that both engines share (src/fixes/clumps/body_set.h), on one MPI
// rank: sphere placement and velocities against the rigid-body formulas written out here, the
// force and torque sums against a direct sum, restart records, forming bodies from sphere rows
// (and the errors), insertion without overlap.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "fixes/clumps/clump_host.h"

using namespace tdem::clumps;

namespace {

Template tetra() { return make_template("t", shape_tetra(0.002, 0.003), 2500.0); }

State some_state() {
  State s;
  s.x = {0.01, -0.02, 0.03};
  s.v = {0.5, -0.25, 1.0};
  s.q = qnormalise(Quat{0.9, 0.2, -0.3, 0.1});
  s.L = {1e-9, -2e-9, 3e-9};
  return s;
}

// n atoms: the spheres of the bodies of `set` (tags 1..), as a host would hold them
struct Atoms {
  std::vector<long> tag;
  std::vector<double> radius, rmass;
  std::vector<double> xs, vs, ws, fs, ts;
  std::vector<double*> x, v, w, f, t;
  explicit Atoms(int n) : tag(n), radius(n), rmass(n), xs(3 * n), vs(3 * n), ws(3 * n), fs(3 * n), ts(3 * n) {
    for (int i = 0; i < n; ++i) {
      tag[i] = i + 1;
      x.push_back(&xs[3 * i]), v.push_back(&vs[3 * i]), w.push_back(&ws[3 * i]);
      f.push_back(&fs[3 * i]), t.push_back(&ts[3 * i]);
    }
  }
  int n() const { return static_cast<int>(tag.size()); }
};

const auto no_image = [](int, int* box) { box[0] = box[1] = box[2] = 0; };
const double kPrd[3] = {1.0, 1.0, 1.0};

}  // namespace

TEST(ClumpBodySet, SpheresFollowTheRigidMotion) {
  BodySet set("fix c tdem/clump");
  set.configure(tetra(), Rotation::splitting);
  const State s = some_state();
  const long tags[4] = {1, 2, 3, 4};
  set.add(7, s, tags);
  Atoms a(5);  // atom 5 is no clump sphere
  ASSERT_EQ(set.map_atoms(a.n(), a.n(), a.n(), a.tag.data(), a.radius.data(), a.rmass.data(), MPI_COMM_WORLD), 4);
  EXPECT_EQ(set.body_index()[4], -1);
  set.refresh_kinematics();
  set.set_spheres(a.n(), a.x.data(), a.v.data(), a.w.data(), kPrd, no_image, true);
  const Mat3 R = rotation_matrix(s.q);
  const Vec3 w = angular_velocity(s, set.body());
  double msum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Vec3 r = mul(R, set.tmpl().body[k].x);
    const Vec3 wr = cross(w, r);
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(a.x[k][d], s.x[d] + r[d], 1e-15);
      EXPECT_NEAR(a.v[k][d], s.v[d] + wr[d], 1e-15);
      EXPECT_EQ(a.w[k][d], w[d]);
    }
    EXPECT_EQ(a.radius[k], 0.002);
    msum += a.rmass[k];
  }
  EXPECT_NEAR(msum, set.body().mass, 1e-15 * set.body().mass);
}

TEST(ClumpBodySet, ForceAndTorqueSumsAndTheHalfSteps) {
  BodySet set;
  set.configure(tetra(), Rotation::splitting);
  const State s = some_state();
  const long tags[4] = {1, 2, 3, 4};
  set.add(1, s, tags);
  Atoms a(4);
  set.map_atoms(4, 4, 4, a.tag.data(), a.radius.data(), a.rmass.data(), MPI_COMM_WORLD);
  set.refresh_kinematics();
  set.set_spheres(4, a.x.data(), a.v.data(), a.w.data(), kPrd, no_image, true);
  Vec3 F{0, 0, 0}, T{0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    for (int d = 0; d < 3; ++d) a.f[i][d] = 1e-3 * (i + 1) * (d == 0 ? 1.0 : d == 1 ? -2.0 : 0.5), a.t[i][d] = 1e-7 * (d - i);
    const Vec3 fi{a.f[i][0], a.f[i][1], a.f[i][2]}, ti{a.t[i][0], a.t[i][1], a.t[i][2]};
    const Vec3 r = sub(Vec3{a.x[i][0], a.x[i][1], a.x[i][2]}, s.x);  // about the com
    F = add(F, fi);
    T = add(T, add(cross(r, fi), ti));
  }
  set.sum_forces(4, a.f.data(), a.t.data(), MPI_COMM_WORLD);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(set.forces()[d], F[d], 1e-18);
    EXPECT_NEAR(set.forces()[3 + d], T[d], 1e-18);
  }
  // the two half steps are those of rigid_body.h with these sums
  State ref = s;
  initial_integrate(ref, set.body(), Vec3{set.forces()[0], set.forces()[1], set.forces()[2]},
                    Vec3{set.forces()[3], set.forces()[4], set.forces()[5]}, 1e-5, Rotation::splitting);
  set.initial_integrate(1e-5, 1.0);
  EXPECT_EQ(set.state(0).x[2], ref.x[2]);
  EXPECT_EQ(set.state(0).q.w, ref.q.w);
  EXPECT_EQ(set.state(0).L[1], ref.L[1]);
  // scalar and vector output
  EXPECT_DOUBLE_EQ(set.kinetic_energy(1.0), kinetic_energy(set.state(0), set.body()));
  EXPECT_EQ(set.vector(0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(set.vector(1, 1.0), set.body().mass * set.state(0).v[0]);
  EXPECT_EQ(set.array(0, 0), 1.0);
}

TEST(ClumpBodySet, RestartRecordsRoundTripBitwise) {
  for (bool with_force : {false, true}) {
    BodySet a, b;
    a.configure(tetra(), Rotation::splitting);
    b.configure(tetra(), Rotation::splitting);
    const long t1[4] = {1, 2, 3, 4}, t2[4] = {9, 8, 7, 6};
    a.add(3, some_state(), t1);
    State s2 = some_state();
    s2.x[0] = -0.3;
    a.add(5, s2, t2);
    a.forces()[7] = 1.25;  // body 1, force y
    std::vector<double> buf;
    a.pack(buf, with_force);
    EXPECT_EQ(buf.size(), 2u * ((with_force ? BodySet::kRowForce : BodySet::kRow) + 4));
    b.unpack(buf.data(), 2, 4, with_force);
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b.mol(1), 5);
    EXPECT_EQ(b.state(1).x[0], -0.3);
    EXPECT_EQ(b.state(0).q.z, a.state(0).q.z);
    EXPECT_TRUE(b.has_tag(6) && b.has_tag(4) && !b.has_tag(5));
    EXPECT_EQ(b.forces()[7], with_force ? 1.25 : 0.0);
    EXPECT_THROW(b.unpack(buf.data(), 2, 3, with_force), std::runtime_error);  // 3 spheres: another template
  }
}

TEST(ClumpBodySet, FormsBodiesFromSphereRowsAndNamesWhatIsWrong) {
  BodySet set("fix c tdem/clump");
  set.configure(tetra(), Rotation::splitting);
  const State s = some_state();
  // the rows of the spheres of a rigid copy (tags 11..14, molecule 4), listed out of ID order
  std::vector<double> rows;
  const Mat3 R = rotation_matrix(s.q);
  const Vec3 w = angular_velocity(s, set.body());
  for (int k : {2, 0, 3, 1}) {
    const Vec3 r = mul(R, set.tmpl().body[k].x), x = add(s.x, r), v = add(s.v, cross(w, r));
    const double row[BodySet::kFormRow] = {11.0 + k, 4.0, x[0], x[1], x[2], v[0], v[1], v[2], w[0], w[1], w[2], 0.002};
    rows.insert(rows.end(), row, row + BodySet::kFormRow);
  }
  ASSERT_EQ(set.form(rows, "all"), 1);
  EXPECT_EQ(set.mol(0), 4);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(set.state(0).x[d], s.x[d], 1e-15);
    EXPECT_NEAR(set.state(0).v[d], s.v[d], 1e-12);
    EXPECT_NEAR(set.state(0).L[d], s.L[d], 1e-18);
  }
  EXPECT_TRUE(set.has_tag(11) && set.has_tag(14));
  // the same molecule again, a wrong radius, a missing sphere
  auto message = [&](std::vector<double> r) {
    BodySet fresh("fix c tdem/clump");
    fresh.configure(tetra(), Rotation::splitting);
    try {
      fresh.form(r, "all");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  try {
    set.form(rows, "all");
    ADD_FAILURE() << "a body formed twice";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("molecule 4 is already a body"), std::string::npos) << e.what();
  }
  std::vector<double> bad = rows;
  bad[11] = 0.003;
  EXPECT_NE(message(bad).find("has radius 0.003 but sphere 3 of template t has radius 0.002"), std::string::npos)
      << message(bad);
  bad = rows;
  bad.resize(3 * BodySet::kFormRow);
  EXPECT_NE(message(bad).find("molecule 4 has 3 spheres in group all, template t has 4"), std::string::npos);
  bad = rows;
  bad[2] += 1e-4;  // a sphere moved: no rigid copy
  EXPECT_NE(message(bad).find("are not a rigid copy of template t"), std::string::npos);
}

TEST(ClumpBodySet, InsertsWithoutOverlapAndNumbersAfterTheLargestIds) {
  BodySet set("fix c tdem/clump");
  set.configure(tetra(), Rotation::splitting);
  PlacementInput in;
  in.n = 20;
  in.seed = 5;
  in.lo = {0.0, 0.0, 0.0};
  in.hi = {0.05, 0.05, 0.05};
  in.inside = [&](const Vec3& p, double r) {
    return sphere_inside([&](double x, double y, double z) { return x >= 0 && y >= 0 && z >= 0 && x <= 0.05 && y <= 0.05 && z <= 0.05; }, p, r);
  };
  in.delta = [](const Vec3& a, const Vec3& b) { return sub(a, b); };
  const auto spheres = set.insert(in, Vec3{0, 0, -1}, 100, 7, "box");
  ASSERT_EQ(spheres.size(), 80u);
  EXPECT_EQ(spheres.front().tag, 101);
  EXPECT_EQ(spheres.front().mol, 8);
  EXPECT_EQ(spheres.back().tag, 180);
  EXPECT_EQ(spheres.back().mol, 27);
  for (std::size_t i = 0; i < spheres.size(); ++i)
    for (std::size_t j = i + 1; j < spheres.size(); ++j)
      if (spheres[i].mol != spheres[j].mol) {
        EXPECT_GE(norm(sub(spheres[i].x, spheres[j].x)), 0.004 - 1e-15);
      }
  EXPECT_NE(set.inserted_message(20, 80, "box").find("molecule IDs 8-27, atom IDs 101-180"), std::string::npos);
  in.n = 100000;
  in.max_failures = 200;
  EXPECT_THROW(set.insert(in, Vec3{0, 0, 0}, 0, 0, "box"), std::runtime_error);
}

// MPI on one rank. Open MPI 4.1 singletons that start at the same time race on their shared
// session directory under TMPDIR (tests/host/mpi_env.py): each process takes a private one. The
// test listing of the build (gtest_discover_tests) needs no MPI.
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
  char dir[] = "/tmp/tdem-unit-mpi-XXXXXX";
  const bool own_tmp = mkdtemp(dir) != nullptr;
  if (own_tmp) setenv("TMPDIR", dir, 1);
  MPI_Init(&argc, &argv);
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  if (own_tmp) std::filesystem::remove_all(dir);
  return rc;
}
