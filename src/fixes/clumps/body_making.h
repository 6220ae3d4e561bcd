// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: making the bodies of fix tdem/clump (both engines): from molecules (best fit of the template
// to each molecule's spheres) and by random insertion without overlap. Both run once, when the
// bodies are made, on the rows or spheres of every rank (the hosts gather them), and give every
// rank the same bodies; the hosts then hand each body to the spheres they own (BodySet::adopt,
// BodySet::set_atom), and the bodies are local from then on (body_set.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixes/clumps/body_set.h"

namespace tdem {
namespace clumps {

// Bodies from the rows (kFormRow doubles each, of every rank) of the group's atoms that are not
// clump spheres yet: one body per molecule, its spheres in ID order = template order, placed by
// the best fit of the template. `existing`: the molecule IDs of the bodies of every rank. The
// hosts give the bodies to their owned spheres with adopt().
inline std::vector<NewBody> form_bodies(BodySet& set, const std::vector<double>& rows, const std::string& group,
                                        const std::vector<std::int64_t>& existing) {
  const int nsph_ = set.nsph(), kFormRow = BodySet::kFormRow;
  const Template& tmpl_ = set.tmpl();
  const auto fail = [&](const std::string& what) { throw std::runtime_error(set.where() + ": " + what); };
  std::map<std::int64_t, std::vector<const double*>> mols;
  for (std::size_t k = 0; k < rows.size() / kFormRow; k++)
    mols[static_cast<std::int64_t>(rows[kFormRow * k + 1])].push_back(&rows[kFormRow * k]);
  for (const std::int64_t m : existing)
    if (mols.count(m)) fail("molecule " + std::to_string(m) + " is already a body; its spheres must not change");
  std::vector<NewBody> out;
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
      fit = fit_body(tmpl_, set.body(), p, vel, om);
    } catch (const std::exception& e) {
      fail("molecule " + m + ": " + e.what());
    }
    const double allowed = 1e-6 * tmpl_.bounding_radius;
    if (fit.residual > allowed)
      fail("the spheres of molecule " + m + " (atom IDs " + std::to_string(tags[0]) +
           "..., in ID order) are not a rigid copy of template " + tmpl_.name + ": largest distance " +
           num10(fit.residual) + " from the best fit (allowed " + num10(allowed) + ")");
    out.push_back({kv.first, fit.state, tags});
  }
  set.set_size(set.size() + static_cast<std::int64_t>(out.size()));
  return out;
}
inline std::string formed_message(const BodySet& set, int nnew, const std::string& group) {
  return set.where() + ": " + std::to_string(nnew) + " bodies formed from the molecules of group " + group + " (" +
         std::to_string(set.size()) + " bodies in all)\n";
}

// n clumps placed without overlap (in: region, existing spheres, seed; place_clumps of
// host_bodies.h), moving with velocity vel, as bodies with molecule IDs maxmol + 1 ... (maxmol:
// the largest of every rank) and sphere tags maxtag + 1 ...; returns their spheres for the host
// to create where it owns them (with set_atom()).
struct Inserted {
  std::vector<NewSphere> spheres;
  long long attempts = 0;
  std::int64_t first_mol = 0, first_tag = 0;
};
inline Inserted insert_bodies(BodySet& set, const PlacementInput& in, const Vec3& vel, std::int64_t maxtag,
                              std::int64_t maxmol, const std::string& region) {
  const int nsph_ = set.nsph();
  const auto fail = [&](const std::string& what) { throw std::runtime_error(set.where() + ": " + what); };
  const PlacementResult res = place_clumps(set.tmpl(), in);
  if (!res.complete)
    fail("insert: placed only " + std::to_string(res.bodies.size()) + " of " + std::to_string(in.n) +
         " clumps in region " + region + ": " + std::to_string(in.max_failures) +
         " random attempts in a row found no free place (region too small or too full); use a larger region "
         "or a smaller N");
  Inserted out;
  out.attempts = res.attempts, out.first_mol = maxmol + 1, out.first_tag = maxtag + 1;
  std::vector<std::int64_t> tags(nsph_);
  for (int b = 0; b < in.n; b++) {
    const std::int64_t mol = maxmol + 1 + b;
    for (int k = 0; k < nsph_; k++) tags[k] = maxtag + 1 + static_cast<std::int64_t>(b) * nsph_ + k;
    State s = res.bodies[b];
    s.v = vel;
    s.L = {0, 0, 0};
    for (int k = 0; k < nsph_; k++)
      out.spheres.push_back({tags[k], mol, k, res.spheres[std::size_t(b) * nsph_ + k], vel, s});
  }
  set.set_size(set.size() + in.n);
  return out;
}
inline std::string inserted_message(const BodySet& set, const Inserted& r, int n, std::int64_t created,
                                    const std::string& region) {
  return set.where() + ": inserted " + std::to_string(n) + " clumps (" + std::to_string(created) +
         " spheres) in region " + region + " after " + std::to_string(r.attempts) + " attempts; molecule IDs " +
         std::to_string(r.first_mol) + "-" + std::to_string(r.first_mol + n - 1) + ", atom IDs " +
         std::to_string(r.first_tag) + "-" + std::to_string(r.first_tag + created - 1) + "\n";
}

}  // namespace clumps
}  // namespace tdem
