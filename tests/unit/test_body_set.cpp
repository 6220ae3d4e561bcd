// SPDX-License-Identifier: GPL-2.0-or-later
// The bodies of fix tdem/clump that both engines share (src/fixes/clumps/body_set.h), on one MPI
// rank: sphere placement and velocities against the rigid-body formulas written out here, the
// force and torque sums against a direct sum, a body split over two "ranks" against the body held
// whole (bitwise), exchange and restart records (and those of the global-bodies version), forming
// bodies from sphere rows (and the errors), insertion without overlap.
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

// n atoms of one "rank" (the first nlocal owned, the rest ghosts)
const auto no_comm = [](BodySet::Comm) {};

// A set with one tetra body (key 7) whose 4 spheres are atoms 0..3 of a; atom 4 is no clump sphere.
void one_body(BodySet& set, Atoms& a, const State& s) {
  set.configure(tetra(), Rotation::splitting);
  set.grow(a.n());
  for (int k = 0; k < 4; ++k) set.set_atom(k, 7, k, s);
  set.set_size(1);
  std::int64_t missing = 0;
  ASSERT_EQ(set.map_atoms(a.n(), 0, a.tag.data(), a.radius.data(), a.rmass.data(), MPI_COMM_WORLD, no_comm, missing), 4);
  EXPECT_EQ(missing, -1);
}

}  // namespace

TEST(ClumpBodySet, SpheresFollowTheRigidMotion) {
  BodySet set("fix c tdem/clump");
  const State s = some_state();
  Atoms a(5);  // atom 5 is no clump sphere
  one_body(set, a, s);
  EXPECT_EQ(set.body_index()[4], -1);
  EXPECT_EQ(set.body_key()[2], 7);
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
  // the ghost cutoff a rank needs: the largest distance between two sphere centres (tetra edge)
  EXPECT_NEAR(set.reach(), 0.003, 1e-15);
}

TEST(ClumpBodySet, ForceAndTorqueSumsAndTheHalfSteps) {
  BodySet set;
  const State s = some_state();
  Atoms a(4);
  one_body(set, a, s);
  set.set_spheres(4, a.x.data(), a.v.data(), a.w.data(), kPrd, no_image, true);
  Vec3 F{0, 0, 0}, T{0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    for (int d = 0; d < 3; ++d) a.f[i][d] = 1e-3 * (i + 1) * (d == 0 ? 1.0 : d == 1 ? -2.0 : 0.5), a.t[i][d] = 1e-7 * (d - i);
    const Vec3 fi{a.f[i][0], a.f[i][1], a.f[i][2]}, ti{a.t[i][0], a.t[i][1], a.t[i][2]};
    const Vec3 r = sub(Vec3{a.x[i][0], a.x[i][1], a.x[i][2]}, s.x);  // about the com
    F = add(F, fi);
    T = add(T, add(cross(r, fi), ti));
  }
  set.sum_forces(4, a.f.data(), a.t.data(), no_comm);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(set.forces()[d], F[d], 1e-18);
    EXPECT_NEAR(set.forces()[3 + d], T[d], 1e-18);
  }
  // the two half steps are those of rigid_body.h with these sums
  State ref = s;
  initial_integrate(ref, set.body(), Vec3{set.forces()[0], set.forces()[1], set.forces()[2]},
                    Vec3{set.forces()[3], set.forces()[4], set.forces()[5]}, 1e-5, Rotation::splitting);
  set.initial_integrate(1e-5, 1.0, no_comm);
  EXPECT_EQ(set.state(0).x[2], ref.x[2]);
  EXPECT_EQ(set.state(0).q.w, ref.q.w);
  EXPECT_EQ(set.state(0).L[1], ref.L[1]);
  // scalar, vector and array output
  BodyOutput out;
  EXPECT_EQ(out.kinetic_energy(set, 1.0, MPI_COMM_WORLD), kinetic_energy(set.state(0), set.body()));
  EXPECT_EQ(out.vector(set, 0, 1.0, MPI_COMM_WORLD), 1.0);
  EXPECT_EQ(out.vector(set, 1, 1.0, MPI_COMM_WORLD), set.body().mass * set.state(0).v[0]);
  EXPECT_EQ(out.array(set, 0, 0, MPI_COMM_WORLD), 7.0);
  EXPECT_EQ(out.array(set, 0, 3, MPI_COMM_WORLD), set.state(0).x[2]);
}

// One body split over two "ranks" (two sets in this process; the forward communication copies the
// owner's values into the other set's ghosts): force sums, half steps and every carried value are
// bitwise those of the body held whole by one set, and the output counts it once.
TEST(ClumpBodySet, ABodySplitOverTwoRanksIsBitwiseTheBodyHeldWhole) {
  const State s = some_state();
  BodySet whole;
  Atoms w(4);
  one_body(whole, w, s);
  whole.set_spheres(4, w.x.data(), w.v.data(), w.w.data(), kPrd, no_image, true);
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d) w.f[i][d] = 1e-3 * std::sin(1.0 + i + 3 * d), w.t[i][d] = 1e-7 * std::cos(2.0 * i + d);
  // rank A owns spheres 0, 1 (atoms 0, 1) and sees 2, 3 as ghosts (atoms 2, 3); rank B the reverse
  BodySet A, B;
  Atoms ra(4), rb(4);
  for (BodySet* set : {&A, &B}) set->configure(tetra(), Rotation::splitting), set->grow(4), set->set_size(1);
  A.set_atom(0, 7, 0, s), A.set_atom(1, 7, 1, s);
  B.set_atom(0, 7, 2, s), B.set_atom(1, 7, 3, s);
  for (int i = 0; i < 2; ++i)
    for (int d = 0; d < 3; ++d) {
      ra.f[i][d] = w.f[i][d], ra.t[i][d] = w.t[i][d];
      rb.f[i][d] = w.f[i + 2][d], rb.t[i][d] = w.t[i + 2][d];
    }
  ra.tag = {1, 2, 3, 4}, rb.tag = {3, 4, 1, 2};
  const int owned[2] = {0, 1};
  auto comm_into = [&](BodySet& from, BodySet& to) {
    return [&](BodySet::Comm c) {
      from.set_comm(c);
      std::vector<double> buf(2 * BodySet::kCommMax);
      EXPECT_EQ(from.pack_forward(2, owned, buf.data()), 2 * BodySet::comm_size(c));
      to.unpack_forward(2, 2, buf.data());
    };
  };
  // each set's map_atoms asks for the keys of its ghosts: the other set packs its owned atoms
  std::int64_t missing = 0;
  ASSERT_EQ(A.map_atoms(2, 2, ra.tag.data(), ra.radius.data(), ra.rmass.data(), MPI_COMM_WORLD, comm_into(B, A), missing), 2);
  EXPECT_EQ(missing, -1);
  ASSERT_EQ(B.map_atoms(2, 2, rb.tag.data(), rb.radius.data(), rb.rmass.data(), MPI_COMM_WORLD, comm_into(A, B), missing), 2);
  EXPECT_EQ(missing, -1);
  // a rank that does not see sphere 3 names the body
  BodySet C;
  Atoms rc(3);
  C.configure(tetra(), Rotation::splitting), C.grow(3), C.set_size(1);
  C.set_atom(0, 7, 0, s), C.set_atom(1, 7, 1, s), C.set_atom(2, 7, 2, s);
  C.map_atoms(3, 0, rc.tag.data(), rc.radius.data(), rc.rmass.data(), MPI_COMM_WORLD, no_comm, missing);
  EXPECT_EQ(missing, 7);
  EXPECT_NE(C.reach_message(7, 0.002).find("molecule 7 but does not see all its spheres"), std::string::npos);

  whole.sum_forces(4, w.f.data(), w.t.data(), no_comm);
  B.sum_forces(2, rb.f.data(), rb.t.data(), no_comm);          // B's own spheres (its ghosts not yet)
  A.sum_forces(2, ra.f.data(), ra.t.data(), comm_into(B, A));  // A's own, B's by communication
  B.sum_forces(2, rb.f.data(), rb.t.data(), comm_into(A, B));  // B again, now with A's
  for (int c = 0; c < 6; ++c) {
    EXPECT_EQ(A.forces()[c], whole.forces()[c]) << c;
    EXPECT_EQ(B.forces()[c], whole.forces()[c]) << c;
  }
  for (BodySet* set : {&whole, &A, &B}) set->initial_integrate(1e-5, 1.0, no_comm), set->final_integrate(1e-5, 1.0);
  EXPECT_EQ(A.state(0).q.x, whole.state(0).q.x);
  EXPECT_EQ(B.state(0).L[2], whole.state(0).L[2]);
  EXPECT_EQ(B.state(0).x[0], whole.state(0).x[0]);
  // the body is reported by the owner of its sphere 0 only
  EXPECT_TRUE(A.reported(0));
  EXPECT_FALSE(B.reported(0));
  // the exchange record of a sphere carries the body: a third set receiving it holds the same body
  std::vector<double> rec(BodySet::kExchange);
  ASSERT_EQ(B.pack_exchange(1, rec.data()), BodySet::kExchange);
  BodySet D;
  Atoms rd(1);
  rd.tag = {4};
  D.configure(tetra(), Rotation::splitting), D.grow(1), D.set_size(1);
  ASSERT_EQ(D.unpack_exchange(0, rec.data()), BodySet::kExchange);
  EXPECT_EQ(D.body_key()[0], 7);
  EXPECT_EQ(D.sphere_index()[0], 3);
}

TEST(ClumpBodySet, ExchangeAndRestartRecordsRoundTripBitwise) {
  BodySet a;
  const State s = some_state();
  Atoms at(5);
  one_body(a, at, s);
  a.forces()[4] = 1.25;  // torque y of the body: carried with the spheres
  a.initial_integrate(1e-5, 1.0, no_comm);
  std::vector<double> rec(BodySet::kRestartMax);
  EXPECT_EQ(a.pack_restart(4, rec.data()), 2);  // no clump sphere: its length and -1
  const int n = a.pack_restart(2, rec.data());
  ASSERT_EQ(n, BodySet::kRestartMax);
  EXPECT_EQ(rec[0], n);
  BodySet b;
  b.configure(tetra(), Rotation::splitting);
  b.grow(1);
  b.unpack_restart(0, rec.data());
  b.set_size(1);
  Atoms bt(1);
  bt.tag = {3};
  std::int64_t missing = 0;
  b.map_atoms(1, 0, bt.tag.data(), bt.radius.data(), bt.rmass.data(), MPI_COMM_WORLD, no_comm, missing);
  EXPECT_EQ(missing, 7);  // one sphere of four: the others are not here
  EXPECT_EQ(b.state(0).q.z, a.state(0).q.z);
  EXPECT_EQ(b.state(0).x[1], a.state(0).x[1]);
  EXPECT_EQ(b.forces()[4], 1.25);
  // a record of the global-bodies version: the bodies reach their spheres at the next map_atoms
  BodySet c("fix c tdem/clump");
  c.configure(tetra(), Rotation::splitting);
  const double old[BodySet::kRowForce + 4] = {9, s.x[0], s.x[1], s.x[2], s.v[0], s.v[1], s.v[2], s.q.w, s.q.x, s.q.y,
                                              s.q.z, s.L[0], s.L[1], s.L[2], 0, 0, 0, 0, 2.5, 0, 1, 2, 3, 4};
  c.unpack_global_bodies(old, 1, 4, true);
  EXPECT_EQ(c.size(), 1);
  Atoms ct(4);
  c.grow(4);
  EXPECT_EQ(c.map_atoms(4, 0, ct.tag.data(), ct.radius.data(), ct.rmass.data(), MPI_COMM_WORLD, no_comm, missing), 4);
  EXPECT_EQ(missing, -1);
  EXPECT_EQ(c.body_key()[3], 9);
  EXPECT_EQ(c.state(0).L[2], s.L[2]);
  EXPECT_EQ(c.forces()[4], 2.5);
  EXPECT_THROW(c.unpack_global_bodies(old, 1, 3, true), std::runtime_error);  // 3 spheres: another template
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
  const std::vector<NewBody> made = form_bodies(set, rows, "all", {});
  ASSERT_EQ(made.size(), 1u);
  EXPECT_EQ(made[0].mol, 4);
  EXPECT_EQ(set.size(), 1);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(made[0].state.x[d], s.x[d], 1e-15);
    EXPECT_NEAR(made[0].state.v[d], s.v[d], 1e-12);
    EXPECT_NEAR(made[0].state.L[d], s.L[d], 1e-18);
  }
  EXPECT_EQ(made[0].tags, (std::vector<std::int64_t>{11, 12, 13, 14}));
  // adopt: the owned atoms with these tags become its spheres
  std::vector<long> tags = {14, 5, 11};
  set.grow(3);
  set.adopt(made, 3, tags.data());
  EXPECT_TRUE(set.is_sphere(0) && !set.is_sphere(1) && set.is_sphere(2));
  EXPECT_EQ(set.sphere_index()[0], 3);
  // the same molecule again, a wrong radius, a missing sphere
  auto message = [&](std::vector<double> r) {
    BodySet fresh("fix c tdem/clump");
    fresh.configure(tetra(), Rotation::splitting);
    try {
      form_bodies(fresh, r, "all", {});
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  try {
    form_bodies(set, rows, "all", {4});
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
  const Inserted ins = insert_bodies(set, in, Vec3{0, 0, -1}, 100, 7, "box");
  const auto& spheres = ins.spheres;
  EXPECT_EQ(set.size(), 20);
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
  EXPECT_NE(inserted_message(set, ins, 20, 80, "box").find("molecule IDs 8-27, atom IDs 101-180"), std::string::npos);
  in.n = 100000;
  in.max_failures = 200;
  EXPECT_THROW(insert_bodies(set, in, Vec3{0, 0, 0}, 0, 0, "box"), std::runtime_error);
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
