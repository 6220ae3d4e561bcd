// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the bodies of fix tdem/clump, shared by the LAMMPS and the LIGGGHTS fix. Everything a fix
// does with its bodies that needs no engine type lives here; the fixes keep what is the engine's
// own (atom creation, regions, error calls, restart hooks, the pair and wall styles they serve).
//
// Design ("local bodies", issue 20): a rank keeps the bodies of which it owns at least one sphere
// (active) and, for their mass, those of which it sees ghost spheres only. Every clump sphere
// carries its body's molecule ID (the body key, the same on every rank) and sphere index; the state
// {x, v, q, L} and the last force sum travel with the spheres when they change rank (exchange and
// restart records of kState doubles). A rank that owns a sphere of a body sees all of its spheres
// (owned or ghost) when the ghost cutoff is at least reach(), the largest distance between two
// sphere centres of the template. Per half step each rank writes force and torque (about the com)
// of its owned spheres, the ghosts get theirs by forward communication, and every rank holding a
// body sums its nsph spheres in template order and advances it: the same operations on the same
// numbers wherever the body is held, so the bodies are bitwise the same on any number of ranks,
// and the work and memory of a rank follow the spheres it holds. The output (scalar, vector,
// array) counts each body once, on the rank owning its sphere 0, with exact sums.
//
// The per-atom body index, sphere index and key (owned and ghost) are kept here (body_index(),
// sphere_index(), body_key()), refreshed by map_atoms() after every exchange.
//
// Errors are std::runtime_error whose text starts with the fix's `where`; the hosts pass it to
// their error->all.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
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

// One sphere of a clump inserted by BodySet::insert: the host creates it where it is owned and
// gives it its body with set_atom().
struct NewSphere {
  std::int64_t tag, mol;
  int sphere;  // index in the template
  Vec3 x;      // centre (unwrapped)
  Vec3 v;      // velocity
  State body;  // the state of its body
};

// A body formed from a molecule (BodySet::form): molecule ID, state, sphere tags in template order.
struct NewBody {
  std::int64_t mol;
  State state;
  std::vector<std::int64_t> tags;
};

class BodySet {
 public:
  // Per-atom state a sphere carries between ranks and in restart files: x3 v3 q4 L3 of its body
  // and the body's force and torque of the last sum (6).
  static constexpr int kState = 19;
  // Exchange record of a clump sphere: body key (molecule ID), sphere index, state; of another
  // atom: -1 alone.
  static constexpr int kExchange = 2 + kState;
  // Row of a body in the restart records of the global-bodies version (read for old files):
  // mol, x3, v3, q4, L3 (then force3, torque3 with_force).
  static constexpr int kRow = 14, kRowForce = 20;
  // Row of an atom of form_bodies(): tag, mol, xu3, v3, omega3, radius.
  static constexpr int kFormRow = 12;
  // What a forward communication carries (pack_forward / unpack_forward), doubles per atom.
  enum class Comm { keys, force, pose };
  static constexpr int comm_size(Comm c) { return c == Comm::keys ? 2 : c == Comm::force ? 6 : 7; }
  static constexpr int kCommMax = 7;

  explicit BodySet(std::string where = "fix tdem/clump") : where_(std::move(where)) {}

  void configure(const Template& t, Rotation scheme) {
    tmpl_ = t;
    body_ = Body::from(t);
    scheme_ = scheme;
    nsph_ = static_cast<int>(t.body.size());
    smass_ = sphere_masses(t);  // the body mass shared by r^3; exactly M for one sphere
    reach_ = 0.0;
    for (const auto& a : t.body)
      for (const auto& b : t.body) reach_ = std::max(reach_, norm(sub(a.x, b.x)));
  }
  // com and inverse inertia (space frame) per body for the local_mass correction
  void keep_local_mass(bool on) { local_mass_ = on; }

  const Template& tmpl() const { return tmpl_; }
  const std::string& where() const { return where_; }
  const Body& body() const { return body_; }
  Rotation scheme() const { return scheme_; }
  int nsph() const { return nsph_; }
  const std::vector<double>& sphere_mass() const { return smass_; }
  // The largest distance between two sphere centres of the template: a rank that owns a sphere of
  // a body sees all its spheres when the ghost cutoff is at least this.
  double reach() const { return reach_; }
  // bodies on all ranks together
  std::int64_t size() const { return nbody_; }
  void set_size(std::int64_t n) { nbody_ = n, version_++; }
  // bodies this rank knows (with an owned sphere: active; only ghost spheres: for their mass)
  std::size_t local_size() const { return st_.size(); }
  bool active(std::size_t b) const { return act_[b] != 0; }
  // is local body b reported here (output, once over the ranks: by the owner of its sphere 0)?
  bool reported(std::size_t b) const { return out_[b] != 0; }
  // advanced by every collective change of the bodies (output caches)
  std::uint64_t version() const { return version_; }
  const State& state(std::size_t b) const { return st_[b]; }
  std::int64_t mol(std::size_t b) const { return key_b_[b]; }
  // is owned atom i a clump sphere?
  bool is_sphere(int i) const { return key_[i] >= 0; }

  // per local body: mass (as fix rigid's masstotal), force and torque of the last sum (6), com (3)
  // and inverse inertia in the space frame (9, row-major; local_mass only)
  double* masses() { return mass_.data(); }
  double* forces() { return fsum_.data(); }
  const double* forces() const { return fsum_.data(); }
  double* com() { return com_.data(); }
  double* inverse_inertia() { return binv_.data(); }
  // per atom (owned and ghost): local body index or -1, sphere index in the template or -1, body
  // key (molecule ID, the same on every rank) or -1
  int* body_index() { return bidx_.data(); }
  int* sphere_index() { return sidx_.data(); }
  const int* body_index() const { return bidx_.data(); }
  const int* sphere_index() const { return sidx_.data(); }
  std::int64_t* body_key() { return key_.data(); }
  const std::int64_t* body_key() const { return key_.data(); }

  // ---------------------------------------------------------------- per-atom arrays (the hosts'
  // grow_arrays, copy_arrays, pack/unpack_exchange, pack/unpack_restart call these)
  void grow(int nmax) {
    const std::size_t n = static_cast<std::size_t>(std::max(nmax, 1));
    if (n <= key_.size()) return;
    key_.resize(n, -1), sidx_.resize(n, -1), bidx_.resize(n, -1);
    pst_.resize(n * kState, 0.0), fs6_.resize(n * 6, 0.0), off_.resize(n * 3, 0.0);
  }
  void copy_atom(int i, int j) {  // atom i to slot j
    key_[j] = key_[i], sidx_[j] = sidx_[i], bidx_[j] = bidx_[i];
    if (bidx_[i] == kInAtom) std::copy(&pst_[kState * i], &pst_[kState * i] + kState, &pst_[kState * j]);
  }
  int pack_exchange(int i, double* buf) const {
    buf[0] = static_cast<double>(key_[i]);
    if (key_[i] < 0) return 1;
    buf[1] = sidx_[i];
    state_of(i, buf + 2);
    return kExchange;
  }
  int unpack_exchange(int n, const double* buf) {
    key_[n] = static_cast<std::int64_t>(buf[0]);
    if (key_[n] < 0) {
      sidx_[n] = bidx_[n] = -1;
      return 1;
    }
    sidx_[n] = static_cast<int>(buf[1]);
    bidx_[n] = kInAtom;
    std::copy(buf + 2, buf + 2 + kState, &pst_[kState * n]);
    return kExchange;
  }
  // restart: the exchange record behind its length (the engines' convention)
  int pack_restart(int i, double* buf) const {
    const int n = 1 + pack_exchange(i, buf + 1);
    buf[0] = n;
    return n;
  }
  void unpack_restart(int n, const double* rec) { unpack_exchange(n, rec + 1); }
  static constexpr int kRestartMax = 1 + kExchange;

  // Owned atom i becomes sphere k of the body `key` in state s (insert, form, old restart files).
  void set_atom(int i, std::int64_t key, int k, const State& s, const double* f6 = nullptr) {
    key_[i] = key, sidx_[i] = k, bidx_[i] = kInAtom;
    double* p = &pst_[kState * i];
    put_state(s, p);
    for (int c = 0; c < 6; c++) p[13 + c] = f6 ? f6[c] : 0.0;
  }

  // ---------------------------------------------------------------- forward communication
  void set_comm(Comm c) { comm_ = c; }
  Comm comm() const { return comm_; }
  int pack_forward(int n, const int* list, double* buf) const {
    int m = 0;
    for (int ii = 0; ii < n; ii++) {
      const int j = list[ii];
      if (comm_ == Comm::keys) {
        buf[m++] = static_cast<double>(key_[j]);
        buf[m++] = sidx_[j];
      } else if (comm_ == Comm::force) {
        for (int c = 0; c < 6; c++) buf[m++] = fs6_[6 * j + c];
      } else {
        // a body with an owned sphere here: its state; else (a ghost sent on, in a later swap)
        // the pose the ghost received
        const int b = bidx_[j];
        if (b >= 0 && act_[b]) {
          const State& s = st_[b];
          const double pose[7] = {s.x[0], s.x[1], s.x[2], s.q.w, s.q.x, s.q.y, s.q.z};
          for (int c = 0; c < 7; c++) buf[m++] = pose[c];
        } else {
          for (int c = 0; c < 7; c++) buf[m++] = pst_[kState * static_cast<std::size_t>(j) + c];
        }
      }
    }
    return m;
  }
  void unpack_forward(int n, int first, const double* buf) {
    int m = 0;
    for (int j = first; j < first + n; j++) {
      if (comm_ == Comm::keys) {
        key_[j] = static_cast<std::int64_t>(buf[m++]);
        sidx_[j] = static_cast<int>(buf[m++]);
      } else if (comm_ == Comm::force) {
        for (int c = 0; c < 6; c++) fs6_[6 * j + c] = buf[m++];
      } else {
        for (int c = 0; c < 7; c++) pst_[kState * j + c] = buf[m++];  // ghosts: com, q
      }
    }
  }

  // ---------------------------------------------------------------- the local bodies
  // After every exchange and border update (the hosts' setup_pre_neighbor and pre_neighbor): the
  // bodies of the owned spheres, from the previous local bodies or from the state the spheres
  // carried in; forward(Comm) runs the host's forward communication of this set (the keys of
  // the ghost atoms); per-atom body and sphere index of owned and ghost atoms; the atom of every
  // sphere of every body with an owned sphere; radius and mass of the clump spheres from the
  // template. Returns the clump spheres owned by all ranks together and, in missing, the smallest
  // key of a body with an owned sphere some of whose spheres this rank does not see (-1: none).
  template <class TagT, class Forward>
  std::int64_t map_atoms(int nlocal, int nghost, const TagT* tag, double* radius, double* rmass, MPI_Comm world,
                         Forward forward, std::int64_t& missing) {
    const int nall = nlocal + nghost;
    grow(nall);
    nlocal_ = nlocal;
    if (!pending_.empty()) adopt_pending(nlocal, tag);
    std::vector<State> old_st;
    std::vector<double> old_f;
    old_st.swap(st_), old_f.swap(fsum_);
    key_b_.clear(), act_.clear(), index_.clear();
    std::int64_t nmine = 0;
    for (int i = 0; i < nlocal; i++) {
      if (key_[i] < 0) {
        bidx_[i] = -1;
        continue;
      }
      nmine++;
      auto it = index_.find(key_[i]);
      if (it == index_.end()) {
        const int b = new_body(key_[i], true);
        if (bidx_[i] >= 0) {
          st_[b] = old_st[bidx_[i]];
          std::copy(&old_f[6 * bidx_[i]], &old_f[6 * bidx_[i]] + 6, &fsum_[6 * b]);
        } else {
          get_state(&pst_[kState * i], st_[b]);
          std::copy(&pst_[kState * i + 13], &pst_[kState * i + 19], &fsum_[6 * b]);
        }
        it = index_.emplace(key_[i], b).first;
      }
      bidx_[i] = it->second;
    }
    comm_ = Comm::keys;
    forward(Comm::keys);
    for (int j = nlocal; j < nall; j++) {
      if (key_[j] < 0) {
        bidx_[j] = sidx_[j] = -1;
        continue;
      }
      auto it = index_.find(key_[j]);
      if (it == index_.end()) it = index_.emplace(key_[j], new_body(key_[j], false)).first;
      bidx_[j] = it->second;
    }
    const std::size_t nb = st_.size();
    atoms_.assign(nb * nsph_, -1);
    for (int i = 0; i < nall; i++) {
      if (bidx_[i] < 0) continue;
      int& a = atoms_[static_cast<std::size_t>(bidx_[i]) * nsph_ + sidx_[i]];
      if (a < 0) a = i;  // owned atoms come first: a body's own spheres are its owned copies
      radius[i] = tmpl_.body[sidx_[i]].r;
      rmass[i] = smass_[sidx_[i]];
    }
    std::int64_t miss = std::numeric_limits<std::int64_t>::max();
    out_.assign(nb, 0);
    for (std::size_t b = 0; b < nb; b++) {
      if (!act_[b]) continue;
      for (int k = 0; k < nsph_; k++)
        if (atoms_[b * nsph_ + k] < 0) miss = std::min(miss, key_b_[b]);
      out_[b] = atoms_[b * nsph_] >= 0 && atoms_[b * nsph_] < nlocal;  // the owner of sphere 0 reports it
    }
    std::int64_t all[2] = {nmine, -miss}, red[2] = {0, 0};
    MPI_Allreduce(&all[0], &red[0], 1, MPI_INT64_T, MPI_SUM, world);
    MPI_Allreduce(&all[1], &red[1], 1, MPI_INT64_T, MPI_MAX, world);
    missing = -red[1] == std::numeric_limits<std::int64_t>::max() ? -1 : -red[1];
    rot_.assign(nb, Mat3{});
    omg_.assign(nb, Vec3{});
    version_++;
    refresh_kinematics(forward);  // the same rotation and omega as before the exchange, bitwise
    return red[0];
  }
  std::string lost_message(std::int64_t found) const {
    return where_ + ": " + std::to_string(found) + " clump spheres found, " + std::to_string(nbody_) +
           " bodies need " + std::to_string(nbody_ * nsph_) + " (clump spheres lost or deleted)";
  }
  std::string reach_message(std::int64_t key, double cutghost) const {
    return where_ + ": a rank owns a sphere of the body of molecule " + std::to_string(key) +
           " but does not see all its spheres: the ghost cutoff " + num10(cutghost) +
           " is shorter than the largest distance between two spheres of template " + tmpl_.name + ", " +
           num10(reach_) + " (set comm_modify cutoff to at least that)";
  }

  // Rotation matrix and angular velocity of the bodies with an owned sphere; for local_mass com and
  // inverse inertia of every local body (a body seen only through ghosts gets its pose by
  // forward(Comm::pose)).
  template <class Forward>
  void refresh_kinematics(Forward forward) {
    const std::size_t nb = st_.size();
    for (std::size_t b = 0; b < nb; b++) {
      if (!act_[b]) continue;
      rot_[b] = rotation_matrix(st_[b].q);
      omg_[b] = omega_of(b);
    }
    // the offset Lambda r_hat of every owned sphere, for set_spheres and sum_forces until the
    // orientation changes again
    for (int i = 0; i < nlocal_; i++)
      if (bidx_[i] >= 0) {
        const Vec3 r = offset(bidx_[i], sidx_[i]);
        std::copy(r.begin(), r.end(), &off_[3 * static_cast<std::size_t>(i)]);
      }
    if (!local_mass_) return;
    comm_ = Comm::pose;
    forward(Comm::pose);
    com_.resize(3 * nb);
    binv_.resize(9 * nb);
    for (std::size_t b = 0; b < nb; b++) {
      if (!act_[b]) {  // the pose some ghost sphere of it brought
        int a = -1;
        for (int k = 0; k < nsph_ && a < 0; k++) a = atoms_[b * nsph_ + k];
        const double* p = &pst_[kState * a];
        st_[b].x = {p[0], p[1], p[2]};
        st_[b].q = {p[3], p[4], p[5], p[6]};
        rot_[b] = rotation_matrix(st_[b].q);
      }
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

  // forces() <- force and torque about the com of every body with an owned sphere: each owned
  // sphere's (f, r x f + torque), the ghosts' by forward(Comm::force), summed in template order
  // (the same operations on every rank that holds the body, so the sums do not depend on the
  // number of ranks).
  template <class Forward>
  void sum_forces(int nlocal, double* const* f, double* const* t, Forward forward) {
    for (int i = 0; i < nlocal; i++) {
      if (bidx_[i] < 0) continue;
      const double* r = &off_[3 * static_cast<std::size_t>(i)];
      double* fs = &fs6_[6 * static_cast<std::size_t>(i)];
      fs[0] = f[i][0];
      fs[1] = f[i][1];
      fs[2] = f[i][2];
      fs[3] = r[1] * f[i][2] - r[2] * f[i][1] + t[i][0];
      fs[4] = r[2] * f[i][0] - r[0] * f[i][2] + t[i][1];
      fs[5] = r[0] * f[i][1] - r[1] * f[i][0] + t[i][2];
    }
    comm_ = Comm::force;
    forward(Comm::force);
    for (std::size_t b = 0; b < st_.size(); b++) {
      if (!act_[b]) continue;
      const int* a = &atoms_[b * nsph_];
      double* fb = &fsum_[6 * b];
      for (int c = 0; c < 6; c++) fb[c] = fs6_[6 * static_cast<std::size_t>(a[0]) + c];
      for (int k = 1; k < nsph_; k++)
        for (int c = 0; c < 6; c++) fb[c] += fs6_[6 * static_cast<std::size_t>(a[k]) + c];
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
      const double* r = &off_[3 * static_cast<std::size_t>(i)];
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

  // The two half steps of the bodies with an owned sphere with the forces of the last
  // sum_forces() times c (ftm2v).
  template <class Forward>
  void initial_integrate(double h, double c, Forward forward) {
    for (std::size_t b = 0; b < st_.size(); b++) {
      if (!act_[b]) continue;
      const double* fb = &fsum_[6 * b];
      clumps::initial_integrate(st_[b], body_, Vec3{c * fb[0], c * fb[1], c * fb[2]},
                                Vec3{c * fb[3], c * fb[4], c * fb[5]}, h, scheme_);
    }
    version_++;
    refresh_kinematics(forward);
  }
  void final_integrate(double h, double c) {
    for (std::size_t b = 0; b < st_.size(); b++) {
      if (!act_[b]) continue;
      const double* fb = &fsum_[6 * b];
      clumps::final_integrate(st_[b], body_, Vec3{c * fb[0], c * fb[1], c * fb[2]},
                              Vec3{c * fb[3], c * fb[4], c * fb[5]}, h);
      omg_[b] = omega_of(b);  // q and x are unchanged: rotation, com and inertia stay valid
    }
    version_++;
  }

  // 1/M + (r x n).I^-1 (r x n) of local body b seen at its sphere k (r: sphere centre - com)
  double inverse_side_mass(int b, int k, const double* n) const {
    const Vec3 r = offset(b, k);
    const Vec3 rn = {r[1] * n[2] - r[2] * n[1], r[2] * n[0] - r[0] * n[2], r[0] * n[1] - r[1] * n[0]};
    const Vec3 w = mul_t(rot_[b], rn);  // body frame: the principal inertia is diagonal
    return 1.0 / body_.mass + w[0] * w[0] / body_.inertia[0] + w[1] * w[1] / body_.inertia[1] +
           w[2] * w[2] / body_.inertia[2];
  }

  double memory_usage() const {
    const double per_atom = sizeof(std::int64_t) + 2 * sizeof(int) + (kState + 9) * sizeof(double);
    const double per_body = sizeof(State) + sizeof(Mat3) + sizeof(Vec3) + 20 * sizeof(double) +
                            nsph_ * sizeof(int) + sizeof(std::int64_t) + 2 + 48;
    return static_cast<double>(key_.size()) * per_atom + static_cast<double>(st_.size()) * per_body +
           0.0;
  }

  // ---------------------------------------------------------------- restart
  // The global record of this version holds only counts and flags (the bodies travel with their
  // spheres' per-atom records). Records of the global-bodies version (every body: kRow or
  // kRowForce doubles, then its nsph sphere tags) are read into a list that the next map_atoms()
  // gives to the owned spheres.
  void unpack_global_bodies(const double* p, int nb, int ns, bool with_force) {
    if (ns != nsph_)
      throw std::runtime_error(where_ + ": the restart file has clumps of " + std::to_string(ns) +
                               " spheres, template " + tmpl_.name + " has " + std::to_string(nsph_));
    pending_.clear();
    const int w = with_force ? kRowForce : kRow;
    for (int b = 0; b < nb; b++) {
      Pending e;
      e.mol = static_cast<std::int64_t>(p[0]);
      e.s.x = {p[1], p[2], p[3]};
      e.s.v = {p[4], p[5], p[6]};
      e.s.q = {p[7], p[8], p[9], p[10]};
      e.s.L = {p[11], p[12], p[13]};
      for (int c = 0; c < 6; c++) e.f[c] = with_force ? p[kRow + c] : 0.0;
      for (int k = 0; k < nsph_; k++) {
        e.k = k;
        pending_[static_cast<std::int64_t>(p[w + k])] = e;
      }
      p += w + nsph_;
    }
    set_size(nb);
  }
  // Owned atoms (tags of the first nlocal) that are spheres of `bodies` become so.
  template <class TagT>
  void adopt(const std::vector<NewBody>& bodies, int nlocal, const TagT* tag) {
    std::unordered_map<std::int64_t, std::pair<int, int>> where;
    for (std::size_t b = 0; b < bodies.size(); b++)
      for (int k = 0; k < nsph_; k++) where[bodies[b].tags[k]] = {static_cast<int>(b), k};
    for (int i = 0; i < nlocal; i++) {
      const auto it = where.find(static_cast<std::int64_t>(tag[i]));
      if (it != where.end()) set_atom(i, bodies[it->second.first].mol, it->second.second, bodies[it->second.first].state);
    }
  }
  std::string template_message(Correction c) const {
    return where_ + ": template " + tmpl_.name + " (" + std::to_string(nsph_) + " spheres): mass " +
           num10(tmpl_.mp.mass) + ", principal inertia " + num10(tmpl_.mp.principal[0]) + " " +
           num10(tmpl_.mp.principal[1]) + " " + num10(tmpl_.mp.principal[2]) + ", bounding radius " +
           num10(tmpl_.bounding_radius) + ", rotation " + to_string(scheme_) + ", multiple-contact correction " +
           to_string(c) + "\n";
  }

 private:
  static constexpr int kInAtom = -2;  // bidx_ of an owned sphere whose body state is in pst_
  struct Pending {
    std::int64_t mol = 0;
    int k = 0;
    State s;
    double f[6] = {0, 0, 0, 0, 0, 0};
  };

  std::string where_;
  Template tmpl_;
  Body body_;
  Rotation scheme_ = Rotation::splitting;
  int nsph_ = 0;
  double reach_ = 0.0;
  std::vector<double> smass_;
  bool local_mass_ = false;
  std::int64_t nbody_ = 0;      // on all ranks
  std::uint64_t version_ = 0;   // advanced by every collective change of the bodies (output caches)
  Comm comm_ = Comm::keys;
  // local bodies
  std::vector<State> st_;
  std::vector<std::int64_t> key_b_;
  std::vector<char> act_, out_;
  std::vector<int> atoms_;  // nsph atom indices per body (owned copy first), -1 if not seen
  std::vector<double> mass_, fsum_, com_, binv_;
  std::vector<Mat3> rot_;
  std::vector<Vec3> omg_;
  std::unordered_map<std::int64_t, int> index_;  // key -> local body
  // per atom
  std::vector<std::int64_t> key_;
  std::vector<int> bidx_, sidx_;
  std::vector<double> pst_, fs6_, off_;  // carried state, force and torque, offset Lambda r_hat
  int nlocal_ = 0;                        // owned atoms at the last map_atoms
  // old restart files: tag -> body
  std::unordered_map<std::int64_t, Pending> pending_;

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(where_ + ": " + what); }

  int new_body(std::int64_t key, bool active) {
    const int b = static_cast<int>(st_.size());
    st_.push_back(State{});
    key_b_.push_back(key);
    act_.push_back(active ? 1 : 0);
    mass_.resize(st_.size(), body_.mass);
    fsum_.resize(6 * st_.size(), 0.0);
    return b;
  }
  static void put_state(const State& s, double* p) {
    const double row[13] = {s.x[0], s.x[1], s.x[2], s.v[0], s.v[1], s.v[2], s.q.w, s.q.x, s.q.y, s.q.z,
                            s.L[0], s.L[1], s.L[2]};
    std::copy(row, row + 13, p);
  }
  static void get_state(const double* p, State& s) {
    s.x = {p[0], p[1], p[2]};
    s.v = {p[3], p[4], p[5]};
    s.q = {p[6], p[7], p[8], p[9]};
    s.L = {p[10], p[11], p[12]};
  }
  // the carried state of owned atom i: from its local body, or what it brought along
  void state_of(int i, double* p) const {
    if (bidx_[i] >= 0) {
      put_state(st_[bidx_[i]], p);
      std::copy(&fsum_[6 * bidx_[i]], &fsum_[6 * bidx_[i]] + 6, p + 13);
    } else {
      std::copy(&pst_[kState * i], &pst_[kState * i] + kState, p);
    }
  }
  template <class TagT>
  void adopt_pending(int nlocal, const TagT* tag) {
    for (int i = 0; i < nlocal; i++) {
      const auto it = pending_.find(static_cast<std::int64_t>(tag[i]));
      if (it != pending_.end()) set_atom(i, it->second.mol, it->second.k, it->second.s, it->second.f);
    }
    pending_.clear();
  }

  Vec3 offset(int b, int k) const { return mul(rot_[b], tmpl_.body[k].x); }
  // omega = Lambda I^-1 Lambda^T L with the cached rotation matrix
  Vec3 omega_of(std::size_t b) const {
    const Vec3 pi = mul_t(rot_[b], st_[b].L);
    return mul(rot_[b], Vec3{pi[0] / body_.inertia[0], pi[1] / body_.inertia[1], pi[2] / body_.inertia[2]});
  }

};

}  // namespace clumps
}  // namespace tdem
