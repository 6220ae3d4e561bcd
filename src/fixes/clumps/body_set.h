// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the bodies of fix tdem/clump, shared by the LAMMPS and the LIGGGHTS fix. Everything a fix
// does with its bodies that needs no engine type lives here; the fixes keep what is the engine's
// own (atom creation, regions, error calls, restart hooks, the pair and wall styles they serve).
//
// Design ("global bodies", as LAMMPS fix rigid): every rank keeps the state {x, v, q, L} of every
// body. Per half step each rank writes force and torque (about the com) of its owned spheres into
// per-sphere slots; a body whose spheres one rank owns entirely is summed there in template order
// (6 doubles), a body split over ranks contributes its 6 nsph slot values, summed after the
// reduction in template order. Every slot has one non-zero contributor, so the sums are bitwise the
// same on any number of ranks. Every rank advances every body identically (rigid_body.h) and sets
// x, v, omega of its owned spheres.
//
// The per-atom body and sphere indices (owned and ghost) are kept here (body_index(),
// sphere_index()), refreshed by map_atoms() after every exchange.
//
// Errors are std::runtime_error whose text starts with the fix's `where`; the hosts pass it to
// their error->all.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "contact/input_checks.h"
#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/host_bodies.h"
#include "fixes/clumps/rigid_body.h"
#include "fixes/clumps/template.h"

namespace tdem {
namespace clumps {

// %.10g of x (messages).
inline std::string num10(double x) { return checks::number(x, 10); }

// One sphere of a clump inserted by BodySet::insert: the host creates it where it is owned.
struct NewSphere {
  std::int64_t tag, mol;
  int sphere;  // index in the template
  Vec3 x;      // centre (unwrapped)
  Vec3 v;      // velocity
};

class BodySet {
 public:
  // Row of a body in restart records: mol, x3, v3, q4, L3 (then force3, torque3 with_force).
  static constexpr int kRow = 14, kRowForce = 20;
  // Row of an atom of form_bodies(): tag, mol, xu3, v3, omega3, radius.
  static constexpr int kFormRow = 12;

  explicit BodySet(std::string where = "fix tdem/clump") : where_(std::move(where)) {}

  void configure(const Template& t, Rotation scheme) {
    tmpl_ = t;
    body_ = Body::from(t);
    scheme_ = scheme;
    nsph_ = static_cast<int>(t.body.size());
    smass_ = sphere_masses(t);  // the body mass shared by r^3; exactly M for one sphere
  }
  // com and inverse inertia (space frame) per body for the local_mass correction (LAMMPS styles)
  void keep_local_mass(bool on) { local_mass_ = on; }

  const Template& tmpl() const { return tmpl_; }
  const std::string& where() const { return where_; }
  const Body& body() const { return body_; }
  Rotation scheme() const { return scheme_; }
  int nsph() const { return nsph_; }
  const std::vector<double>& sphere_mass() const { return smass_; }
  std::size_t size() const { return st_.size(); }
  const State& state(std::size_t b) const { return st_[b]; }
  std::int64_t mol(std::size_t b) const { return mol_[b]; }
  const std::vector<std::int64_t>& mols() const { return mol_; }
  bool has_tag(std::int64_t tag) const { return slot_.count(tag) != 0; }

  // per body: mass (as fix rigid's masstotal), force and torque of the last sum (6), com (3) and
  // inverse inertia in the space frame (9, row-major; local_mass only)
  double* masses() { return mass_.data(); }
  double* forces() { return fsum_.data(); }
  const double* forces() const { return fsum_.data(); }
  double* com() { return com_.data(); }
  double* inverse_inertia() { return binv_.data(); }
  // per atom (owned and ghost): body index or -1, sphere index in the template or -1
  int* body_index() { return bidx_.data(); }
  int* sphere_index() { return sidx_.data(); }
  const int* body_index() const { return bidx_.data(); }
  const int* sphere_index() const { return sidx_.data(); }
  std::size_t atom_capacity() const { return bidx_.size(); }

  void clear() {
    st_.clear(), mol_.clear(), tags_.clear(), mass_.clear(), fsum_.clear(), rot_.clear(), omg_.clear();
    slot_.clear();
  }

  template <class TagT>
  int add(std::int64_t mol, const State& s, const TagT* tags) {
    const int b = static_cast<int>(st_.size());
    st_.push_back(s);
    mol_.push_back(mol);
    mass_.push_back(body_.mass);
    fsum_.resize(6 * st_.size(), 0.0);
    rot_.push_back(rotation_matrix(s.q));
    omg_.push_back(angular_velocity(s, body_));
    for (int k = 0; k < nsph_; k++) {
      tags_.push_back(static_cast<std::int64_t>(tags[k]));
      slot_[static_cast<std::int64_t>(tags[k])] = b * nsph_ + k;
    }
    return b;
  }

  // ---------------------------------------------------------------- atoms
  // Body and sphere index of the nall atoms (owned first), radius and mass of the clump spheres
  // from the template, and the layout of the force reduction. Returns the number of clump spheres
  // owned by all ranks together (size() * nsph() unless spheres were lost).
  template <class TagT>
  std::int64_t map_atoms(int nall, int nlocal, int nmax, const TagT* tag, double* radius, double* rmass,
                         MPI_Comm world) {
    if (static_cast<std::size_t>(std::max(nmax, nall)) > bidx_.size()) {
      bidx_.resize(std::max(nmax, nall));
      sidx_.resize(std::max(nmax, nall));
    }
    const std::int64_t nmine =
        map_clump_atoms(nall, nlocal, tag, slot_, nsph_, tmpl_, smass_, bidx_.data(), sidx_.data(), radius, rmass);
    std::int64_t all = 0;
    MPI_Allreduce(&nmine, &all, 1, MPI_INT64_T, MPI_SUM, world);
    // bodies owned by one rank entirely are reduced as 6 sums, split bodies as their 6 nsph slots
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    const std::size_t nb = st_.size();
    std::vector<int> cnt(nb, 0), mx(nb, 0);
    for (int i = 0; i < nlocal; i++)
      if (bidx_[i] >= 0) cnt[bidx_[i]]++;
    if (nprocs > 1 && nb > 0)
      MPI_Allreduce(cnt.data(), mx.data(), static_cast<int>(nb), MPI_INT, MPI_MAX, world);
    else
      mx = cnt;
    red_off_.assign(nb + 1, 0);
    split_.assign(nb, 0);
    for (std::size_t b = 0; b < nb; b++) {
      split_[b] = mx[b] < nsph_ ? 1 : 0;
      red_off_[b + 1] = red_off_[b] + (split_[b] ? 6 * nsph_ : 6);
    }
    return all;
  }
  std::string lost_message(std::int64_t found) const {
    return where_ + ": " + std::to_string(found) + " clump spheres found, " + std::to_string(st_.size()) +
           " bodies need " + std::to_string(static_cast<std::int64_t>(st_.size()) * nsph_) +
           " (clump spheres lost or deleted)";
  }

  // rotation matrix and angular velocity of every body (and com, inverse inertia for local_mass)
  void refresh_kinematics() {
    for (std::size_t b = 0; b < st_.size(); b++) {
      rot_[b] = rotation_matrix(st_[b].q);
      omg_[b] = omega_of(b);
    }
    if (!local_mass_) return;
    com_.resize(3 * st_.size());
    binv_.resize(9 * st_.size());
    for (std::size_t b = 0; b < st_.size(); b++) {
      const Mat3& R = rot_[b];
      for (int i = 0; i < 3; i++) {
        com_[3 * b + i] = st_[b].x[i];
        for (int j = 0; j < 3; j++) {
          double s = 0.0;
          for (int k = 0; k < 3; k++) s += R[i][k] * R[j][k] / body_.inertia[k];
          binv_[9 * b + 3 * i + j] = s;
        }
      }
    }
  }

  // forces() <- force and torque about the com of every body, from the owned spheres' f, torque
  void sum_forces(int nlocal, double* const* f, double* const* t, MPI_Comm world) {
    const std::size_t nb = st_.size(), nslot = nb * nsph_;
    if (slotf_.size() != 6 * nslot) slotf_.assign(6 * nslot, 0.0);
    else std::fill(slotf_.begin(), slotf_.end(), 0.0);
    for (int i = 0; i < nlocal; i++) {
      const int b = bidx_[i];
      if (b < 0) continue;
      const Vec3 r = offset(b, sidx_[i]);
      double* fs = &slotf_[6 * (static_cast<std::size_t>(b) * nsph_ + sidx_[i])];
      fs[0] = f[i][0];
      fs[1] = f[i][1];
      fs[2] = f[i][2];
      fs[3] = r[1] * f[i][2] - r[2] * f[i][1] + t[i][0];
      fs[4] = r[2] * f[i][0] - r[0] * f[i][2] + t[i][1];
      fs[5] = r[0] * f[i][1] - r[1] * f[i][0] + t[i][2];
    }
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    if (nprocs == 1) {
      for (std::size_t b = 0; b < nb; b++) body_sum(&slotf_[6 * b * nsph_], &fsum_[6 * b]);
      return;
    }
    red_.assign(red_off_[nb], 0.0);
    for (std::size_t b = 0; b < nb; b++) {
      const double* fs = &slotf_[6 * b * nsph_];
      double* out = &red_[red_off_[b]];
      if (split_[b]) std::copy(fs, fs + 6 * nsph_, out);
      else body_sum(fs, out);  // zero on the ranks that do not own the body
    }
    MPI_Allreduce(MPI_IN_PLACE, red_.data(), static_cast<int>(red_.size()), MPI_DOUBLE, MPI_SUM, world);
    for (std::size_t b = 0; b < nb; b++) {
      const double* in = &red_[red_off_[b]];
      if (split_[b]) body_sum(in, &fsum_[6 * b]);
      else std::copy(in, in + 6, &fsum_[6 * b]);
    }
  }

  // Owned spheres from their bodies: x (if positions; box(i, int[3]) gives the periodic image of
  // atom i, prd the box lengths), v, omega.
  template <class Box>
  void set_spheres(int nlocal, double** x, double** v, double** omega, const double prd[3], Box box,
                   bool positions) const {
    for (int i = 0; i < nlocal; i++) {
      const int b = bidx_[i];
      if (b < 0) continue;
      const Vec3 r = offset(b, sidx_[i]);
      if (positions) {
        int img[3];
        box(i, img);
        for (int k = 0; k < 3; k++) x[i][k] = st_[b].x[k] + r[k] - img[k] * prd[k];
      }
      const Vec3& w = omg_[b];
      v[i][0] = st_[b].v[0] + w[1] * r[2] - w[2] * r[1];
      v[i][1] = st_[b].v[1] + w[2] * r[0] - w[0] * r[2];
      v[i][2] = st_[b].v[2] + w[0] * r[1] - w[1] * r[0];
      omega[i][0] = w[0];
      omega[i][1] = w[1];
      omega[i][2] = w[2];
    }
  }

  // The two half steps of every body with the forces of the last sum_forces() times c (ftm2v).
  void initial_integrate(double h, double c) {
    for (std::size_t b = 0; b < st_.size(); b++) {
      const double* fb = &fsum_[6 * b];
      clumps::initial_integrate(st_[b], body_, Vec3{c * fb[0], c * fb[1], c * fb[2]},
                                Vec3{c * fb[3], c * fb[4], c * fb[5]}, h, scheme_);
    }
    refresh_kinematics();
  }
  void final_integrate(double h, double c) {
    for (std::size_t b = 0; b < st_.size(); b++) {
      const double* fb = &fsum_[6 * b];
      clumps::final_integrate(st_[b], body_, Vec3{c * fb[0], c * fb[1], c * fb[2]},
                              Vec3{c * fb[3], c * fb[4], c * fb[5]}, h);
      omg_[b] = omega_of(b);  // q and x are unchanged: rotation, com and inertia stay valid
    }
  }

  // ---------------------------------------------------------------- output (the fixes' scalar,
  // vector and array; mvv2e converts mass velocity^2 to energy)
  double kinetic_energy(double mvv2e) const {
    double e = 0.0;
    for (const auto& s : st_) e += clumps::kinetic_energy(s, body_);
    return e * mvv2e;
  }
  // [0] bodies, [1-3] total momentum, [4-6] sum of the bodies' angular momenta about their com,
  // [7] translational, [8] rotational kinetic energy
  double vector(int n, double mvv2e) const {
    if (n == 0) return static_cast<double>(st_.size());
    double out = 0.0;
    for (const auto& s : st_) {
      if (n >= 1 && n <= 3) out += body_.mass * s.v[n - 1];
      else if (n >= 4 && n <= 6) out += s.L[n - 4];
      else if (n == 7) out += 0.5 * body_.mass * dot(s.v, s.v) * mvv2e;
      else if (n == 8) out += rotational_energy(s, body_) * mvv2e;
    }
    return out;
  }
  // row per body: mol, x y z, vx vy vz, qw qx qy qz, Lx Ly Lz, wx wy wz
  static constexpr int kArrayColumns = 17;
  double array(int i, int j) const {
    if (i < 0 || i >= static_cast<int>(st_.size())) return 0.0;
    const State& s = st_[i];
    if (j == 0) return static_cast<double>(mol_[i]);
    if (j <= 3) return s.x[j - 1];
    if (j <= 6) return s.v[j - 4];
    if (j == 7) return s.q.w;
    if (j == 8) return s.q.x;
    if (j == 9) return s.q.y;
    if (j == 10) return s.q.z;
    if (j <= 13) return s.L[j - 11];
    if (j <= 16) return angular_velocity(s, body_)[j - 14];
    return 0.0;
  }

  // 1/M + (r x n).I^-1 (r x n) of body b seen at its sphere k (r: sphere centre - com)
  double inverse_side_mass(int b, int k, const double* n) const {
    const Vec3 r = offset(b, k);
    const Vec3 rn = {r[1] * n[2] - r[2] * n[1], r[2] * n[0] - r[0] * n[2], r[0] * n[1] - r[1] * n[0]};
    const Vec3 w = mul_t(rot_[b], rn);  // body frame: the principal inertia is diagonal
    return 1.0 / body_.mass + w[0] * w[0] / body_.inertia[0] + w[1] * w[1] / body_.inertia[1] +
           w[2] * w[2] / body_.inertia[2];
  }

  double memory_usage() const {
    return static_cast<double>(bidx_.size()) * 2 * sizeof(int) +
           static_cast<double>(st_.size()) * (sizeof(State) + sizeof(Mat3) + sizeof(Vec3) + 20 * sizeof(double)) +
           static_cast<double>(tags_.size()) * (sizeof(std::int64_t) + 6 * sizeof(double) + 32);
  }

  // ---------------------------------------------------------------- restart
  // Per body: kRow (or kRowForce) doubles, then its nsph sphere tags.
  void pack(std::vector<double>& buf, bool with_force) const {
    for (std::size_t b = 0; b < st_.size(); b++) {
      const State& s = st_[b];
      const double row[kRow] = {static_cast<double>(mol_[b]), s.x[0], s.x[1], s.x[2], s.v[0], s.v[1], s.v[2],
                                s.q.w, s.q.x, s.q.y, s.q.z, s.L[0], s.L[1], s.L[2]};
      buf.insert(buf.end(), row, row + kRow);
      if (with_force) buf.insert(buf.end(), &fsum_[6 * b], &fsum_[6 * b] + 6);
      for (int k = 0; k < nsph_; k++) buf.push_back(static_cast<double>(tags_[b * nsph_ + k]));
    }
  }
  // The bodies of a record written by pack() (nb bodies of ns spheres), replacing these.
  void unpack(const double* p, int nb, int ns, bool with_force) {
    if (ns != nsph_)
      throw std::runtime_error(where_ + ": the restart file has clumps of " + std::to_string(ns) +
                               " spheres, template " + tmpl_.name + " has " + std::to_string(nsph_));
    clear();
    const int w = with_force ? kRowForce : kRow;
    std::vector<std::int64_t> tags(nsph_);
    for (int b = 0; b < nb; b++) {
      State s;
      s.x = {p[1], p[2], p[3]};
      s.v = {p[4], p[5], p[6]};
      s.q = {p[7], p[8], p[9], p[10]};
      s.L = {p[11], p[12], p[13]};
      for (int k = 0; k < nsph_; k++) tags[k] = static_cast<std::int64_t>(p[w + k]);
      add(static_cast<std::int64_t>(p[0]), s, tags.data());
      if (with_force) std::copy(p + kRow, p + kRowForce, &fsum_[6 * b]);
      p += w + nsph_;
    }
  }

  // ---------------------------------------------------------------- making bodies
  // Bodies from the rows (kFormRow doubles each, of every rank) of the group's atoms that are not
  // clump spheres yet: one body per molecule, its spheres in ID order = template order, placed by
  // the best fit of the template. Returns the number of bodies formed.
  int form(const std::vector<double>& rows, const std::string& group) {
    std::map<std::int64_t, std::vector<const double*>> mols;
    for (std::size_t k = 0; k < rows.size() / kFormRow; k++)
      mols[static_cast<std::int64_t>(rows[kFormRow * k + 1])].push_back(&rows[kFormRow * k]);
    for (const std::int64_t m : mol_)
      if (mols.count(m)) fail("molecule " + std::to_string(m) + " is already a body; its spheres must not change");
    int nnew = 0;
    std::vector<std::int64_t> tags(nsph_);
    std::vector<Vec3> p(nsph_), vel(nsph_), om(nsph_);
    for (auto& kv : mols) {
      auto& v = kv.second;
      const std::string m = std::to_string(kv.first);
      std::sort(v.begin(), v.end(), [](const double* a, const double* b) { return a[0] < b[0]; });
      if (static_cast<int>(v.size()) != nsph_)
        fail("molecule " + m + " has " + std::to_string(v.size()) + " spheres in group " + group + ", template " +
             tmpl_.name + " has " + std::to_string(nsph_));
      for (int k = 0; k < nsph_; k++) {
        tags[k] = static_cast<std::int64_t>(v[k][0]);
        const double r = tmpl_.body[k].r;
        if (std::fabs(v[k][11] - r) > 1e-6 * r)
          fail("atom " + std::to_string(tags[k]) + " (molecule " + m + ") has radius " + num10(v[k][11]) +
               " but sphere " + std::to_string(k + 1) + " of template " + tmpl_.name + " has radius " + num10(r));
        p[k] = {v[k][2], v[k][3], v[k][4]};
        vel[k] = {v[k][5], v[k][6], v[k][7]};
        om[k] = {v[k][8], v[k][9], v[k][10]};
      }
      // orientation (Horn's quaternion) and velocities (least squares)
      BodyFit fit;
      try {
        fit = fit_body(tmpl_, body_, p, vel, om);
      } catch (const std::exception& e) {
        fail("molecule " + m + ": " + e.what());
      }
      const double allowed = 1e-6 * tmpl_.bounding_radius;
      if (fit.residual > allowed)
        fail("the spheres of molecule " + m + " (atom IDs " + std::to_string(tags[0]) +
             "..., in ID order) are not a rigid copy of template " + tmpl_.name + ": largest distance " +
             num10(fit.residual) + " from the best fit (allowed " + num10(allowed) + ")");
      add(kv.first, fit.state, tags.data());
      nnew++;
    }
    return nnew;
  }
  std::string formed_message(int nnew, const std::string& group) const {
    return where_ + ": " + std::to_string(nnew) + " bodies formed from the molecules of group " + group + " (" +
           std::to_string(st_.size()) + " bodies in all)\n";
  }

  // n clumps placed without overlap (in: region, existing spheres, seed; place_clumps of
  // host_bodies.h), moving with velocity vel, as bodies with molecule IDs maxmol + 1 ... and
  // sphere tags maxtag + 1 ...; returns their spheres for the host to create.
  std::vector<NewSphere> insert(const PlacementInput& in, const Vec3& vel, std::int64_t maxtag, std::int64_t maxmol,
                                const std::string& region) {
    for (const std::int64_t m : mol_) maxmol = std::max(maxmol, m);
    const PlacementResult res = place_clumps(tmpl_, in);
    if (!res.complete)
      fail("insert: placed only " + std::to_string(res.bodies.size()) + " of " + std::to_string(in.n) +
           " clumps in region " + region + ": " + std::to_string(in.max_failures) +
           " random attempts in a row found no free place (region too small or too full); use a larger region "
           "or a smaller N");
    attempts_ = res.attempts, first_mol_ = maxmol + 1, first_tag_ = maxtag + 1;
    std::vector<NewSphere> out;
    std::vector<std::int64_t> tags(nsph_);
    for (int b = 0; b < in.n; b++) {
      const std::int64_t mol = maxmol + 1 + b;
      for (int k = 0; k < nsph_; k++) tags[k] = maxtag + 1 + static_cast<std::int64_t>(b) * nsph_ + k;
      State s = res.bodies[b];
      s.v = vel;
      s.L = {0, 0, 0};
      add(mol, s, tags.data());
      for (int k = 0; k < nsph_; k++) out.push_back({tags[k], mol, k, res.spheres[std::size_t(b) * nsph_ + k], vel});
    }
    return out;
  }
  std::string inserted_message(int n, std::int64_t created, const std::string& region) const {
    return where_ + ": inserted " + std::to_string(n) + " clumps (" + std::to_string(created) + " spheres) in region " +
           region + " after " + std::to_string(attempts_) + " attempts; molecule IDs " + std::to_string(first_mol_) +
           "-" + std::to_string(first_mol_ + n - 1) + ", atom IDs " + std::to_string(first_tag_) + "-" +
           std::to_string(first_tag_ + created - 1) + "\n";
  }

  std::string template_message(Correction c) const {
    return where_ + ": template " + tmpl_.name + " (" + std::to_string(nsph_) + " spheres): mass " +
           num10(tmpl_.mp.mass) + ", principal inertia " + num10(tmpl_.mp.principal[0]) + " " +
           num10(tmpl_.mp.principal[1]) + " " + num10(tmpl_.mp.principal[2]) + ", bounding radius " +
           num10(tmpl_.bounding_radius) + ", rotation " + to_string(scheme_) + ", multiple-contact correction " +
           to_string(c) + "\n";
  }

 private:
  std::string where_;
  Template tmpl_;
  Body body_;
  Rotation scheme_ = Rotation::splitting;
  int nsph_ = 0;
  std::vector<double> smass_;
  bool local_mass_ = false;
  // bodies
  std::vector<State> st_;
  std::vector<std::int64_t> mol_, tags_;  // molecule ID per body, nsph sphere tags per body
  std::vector<double> mass_, fsum_, com_, binv_;
  std::vector<Mat3> rot_;
  std::vector<Vec3> omg_;
  std::unordered_map<std::int64_t, int> slot_;  // tag -> body * nsph + sphere
  // force reduction
  std::vector<double> slotf_, red_;
  std::vector<std::size_t> red_off_;
  std::vector<char> split_;
  // per atom
  std::vector<int> bidx_, sidx_;
  // the last insert (for its message)
  long long attempts_ = 0;
  std::int64_t first_mol_ = 0, first_tag_ = 0;

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(where_ + ": " + what); }

  Vec3 offset(int b, int k) const { return mul(rot_[b], tmpl_.body[k].x); }
  // omega = Lambda I^-1 Lambda^T L with the cached rotation matrix
  Vec3 omega_of(std::size_t b) const {
    const Vec3 pi = mul_t(rot_[b], st_[b].L);
    return mul(rot_[b], Vec3{pi[0] / body_.inertia[0], pi[1] / body_.inertia[1], pi[2] / body_.inertia[2]});
  }
  void body_sum(const double* fs, double* fb) const {
    for (int c = 0; c < 6; c++) fb[c] = fs[c];
    for (int k = 1; k < nsph_; k++)
      for (int c = 0; c < 6; c++) fb[c] += fs[6 * k + c];
  }
};

}  // namespace clumps
}  // namespace tdem
