// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the arguments of `fix ID group tdem/clump ...`, the same in LAMMPS and LIGGGHTS
// (docs/lammps/fix_tdem_clump.md, docs/liggghts/fix_tdem_clump.md), parsed and turned into a template without a
// host. Errors are std::invalid_argument whose text starts with the fix's `where` ("fix c
// tdem/clump") and names the keyword, the value and what is allowed; the hosts pass it to their
// error->all.
#pragma once

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/multi_contact/multi_contact.h"
#include "fixes/clumps/host_bodies.h"
#include "fixes/clumps/rigid_body.h"
#include "fixes/clumps/template.h"

namespace tdem {
namespace clumps {

inline const char* clump_syntax() {
  return "fix ID group tdem/clump template NAME (file PATH | shape SHAPE r d [n]) [density RHO] "
         "[integration columns|voxel|monte_carlo] [resolution N] [rotation splitting|explicit|richardson] "
         "[insert N region REGID seed S [type T] [vel vx vy vz]] [bodies molecule] "
         "[correction none|count|overlap|local_mass] [vtk N prefix]";
}

struct ClumpArgs {
  std::string name;                 // template NAME
  std::string kind;                 // "file" or "shape"
  std::string path, shape;          // file PATH | shape SHAPE r d [n]
  double r = 0.0, d = 0.0, rho = -1.0;
  int n = 2, resolution = 64;
  Integration integration = Integration::columns;
  Rotation scheme = Rotation::splitting;
  int ninsert = 0, insert_type = 1;  // insert N region REGID seed S [type T] [vel vx vy vz]
  std::string insert_region;
  long long insert_seed = 0;
  double insert_vel[3] = {0.0, 0.0, 0.0};
  bool bodies_molecule = false;      // bodies molecule (implied without insert)
  Correction correction = Correction::none;
  int vtk_every = 0;                 // vtk N prefix: bodies as prefix_STEP.vtu every N steps, prefix.pvd
  std::string vtk_prefix;
};

// a[0..] are the words after "fix ID group tdem/clump"; ntypes bounds `insert type`.
inline ClumpArgs parse_clump_args(const std::vector<std::string>& a, const std::string& where, int ntypes) {
  const int narg = static_cast<int>(a.size());
  const std::string syntax = clump_syntax();
  auto fail = [&](const std::string& what) { throw std::invalid_argument(where + ": " + what); };
  auto need = [&](int iarg, int n, const std::string& key, const std::string& what) {
    if (iarg + n >= narg) fail("keyword '" + key + "' needs " + what + "; syntax: " + syntax);
  };
  auto number = [&](const std::string& s, const std::string& key) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || !std::isfinite(v))
      fail("keyword '" + key + "': value '" + s + "' is not a number");
    return v;
  };
  auto integer = [&](const std::string& s, const std::string& key, long long lo, long long hi) {
    const double v = number(s, key);
    if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi))
      fail("keyword '" + key + "': value '" + s + "' is not an integer in [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]");
    return static_cast<long long>(v);
  };
  // an unknown word: names the keyword and the word as "keyword 'K': K 'V' is unknown; allowed: ..."
  auto unknown = [&](const std::string& key, const std::string& v, const std::string& allowed) {
    fail("keyword '" + key + "': " + key + " '" + v + "' is unknown; allowed: " + allowed);
  };
  ClumpArgs c;
  int iarg = 0;
  while (iarg < narg) {
    const std::string key = a[iarg];
    if (key == "template") {
      need(iarg, 1, key, "a name");
      c.name = a[iarg + 1];
      iarg += 2;
    } else if (key == "file") {
      need(iarg, 1, key, "a path");
      c.kind = "file";
      c.path = a[iarg + 1];
      iarg += 2;
    } else if (key == "shape") {
      need(iarg, 3, key, "SHAPE r d [n]");
      c.kind = "shape";
      c.shape = a[iarg + 1];
      if (c.shape != "single" && c.shape != "dimer" && c.shape != "rod" && c.shape != "tetra" &&
          c.shape != "square4" && c.shape != "cube8")
        unknown(key, c.shape, "single, dimer, rod, tetra, square4, cube8");
      c.r = number(a[iarg + 2], "shape r");
      c.d = number(a[iarg + 3], "shape d");
      if (!(c.r > 0.0)) fail("keyword 'shape': radius r = " + a[iarg + 2] + " is outside (0, inf)");
      if (!(c.d >= 0.0)) fail("keyword 'shape': distance d = " + a[iarg + 3] + " is outside [0, inf)");
      iarg += 4;
      if (c.shape == "rod") {
        need(iarg - 1, 1, "shape rod", "the number of spheres n");
        c.n = static_cast<int>(integer(a[iarg], "shape rod n", 1, 1000));
        iarg += 1;
      }
    } else if (key == "density") {
      need(iarg, 1, key, "a value");
      c.rho = number(a[iarg + 1], key);
      if (!(c.rho > 0.0)) fail("keyword 'density': value " + a[iarg + 1] + " is outside (0, inf)");
      iarg += 2;
    } else if (key == "integration") {
      need(iarg, 1, key, "a value (columns, voxel, monte_carlo)");
      const std::string v = a[iarg + 1];
      if (v == "columns") c.integration = Integration::columns;
      else if (v == "voxel") c.integration = Integration::voxel;
      else if (v == "monte_carlo") c.integration = Integration::monte_carlo;
      else unknown(key, v, "columns, voxel, monte_carlo");
      iarg += 2;
    } else if (key == "resolution") {
      need(iarg, 1, key, "a value");
      c.resolution = static_cast<int>(integer(a[iarg + 1], key, 4, 4096));
      iarg += 2;
    } else if (key == "rotation") {
      need(iarg, 1, key, "a value (splitting, explicit, richardson)");
      const std::string v = a[iarg + 1];
      if (v == "splitting") c.scheme = Rotation::splitting;
      else if (v == "explicit") c.scheme = Rotation::explicit_rodrigues;
      else if (v == "richardson") c.scheme = Rotation::richardson;
      else unknown(key, v, "splitting, explicit, richardson");
      iarg += 2;
    } else if (key == "insert") {
      need(iarg, 5, key, "N region REGID seed S");
      c.ninsert = static_cast<int>(integer(a[iarg + 1], "insert N", 1, 100000000));
      if (a[iarg + 2] != "region") fail("keyword 'insert': expected 'region' after N, got '" + a[iarg + 2] + "'");
      c.insert_region = a[iarg + 3];
      if (a[iarg + 4] != "seed")
        fail("keyword 'insert': expected 'seed' after the region, got '" + a[iarg + 4] + "'");
      c.insert_seed = integer(a[iarg + 5], "insert seed", 1, 2147483647);
      iarg += 6;
      while (iarg < narg) {
        if (a[iarg] == "type") {
          need(iarg, 1, "insert type", "a value");
          c.insert_type = static_cast<int>(integer(a[iarg + 1], "insert type", 1, ntypes));
          iarg += 2;
        } else if (a[iarg] == "vel") {
          need(iarg, 3, "insert vel", "vx vy vz");
          for (int k = 0; k < 3; k++) c.insert_vel[k] = number(a[iarg + 1 + k], "insert vel");
          iarg += 4;
        } else {
          break;
        }
      }
    } else if (key == "bodies") {
      need(iarg, 1, key, "a value (molecule)");
      if (a[iarg + 1] != "molecule") unknown(key, a[iarg + 1], "molecule");
      c.bodies_molecule = true;
      iarg += 2;
    } else if (key == "correction") {
      need(iarg, 1, key, "a value (none, count, overlap, local_mass)");
      const std::string v = a[iarg + 1];
      if (v != "none" && v != "count" && v != "overlap" && v != "local_mass")
        unknown(key, v, "none, count, overlap, local_mass");
      c.correction = correction_from_string(v);
      iarg += 2;
    } else if (key == "vtk") {
      need(iarg, 2, key, "N prefix (steps between VTK files, file prefix)");
      c.vtk_every = static_cast<int>(integer(a[iarg + 1], key, 1, 2147483647LL));
      c.vtk_prefix = a[iarg + 2];
      iarg += 3;
    } else {
      fail("unknown keyword '" + key +
           "'; allowed: template, file, shape, density, integration, resolution, rotation, insert, bodies, "
           "correction, vtk; syntax: " + syntax);
    }
  }
  if (c.name.empty()) fail("missing keyword 'template NAME'; syntax: " + syntax);
  if (c.kind.empty()) fail("missing 'file PATH' or 'shape SHAPE r d [n]'; syntax: " + syntax);
  if (c.kind == "shape" && c.rho < 0.0)
    fail("missing keyword 'density RHO' (needed for the mass of shape " + c.shape + ")");
  if (c.kind == "shape" && c.shape != "single" && !(c.d > 0.0))
    fail("keyword 'shape': distance d = 0 is outside (0, inf) for shape " + c.shape);
  if (c.ninsert == 0) c.bodies_molecule = true;
  return c;
}

// The template of the arguments (read from the file, or built-in shape), with exact mass
// properties where its spheres are disjoint; errors as "<where>: template: ...".
inline Template clump_template(const ClumpArgs& c, const std::string& where) {
  Template t;
  try {
    if (c.kind == "file")
      t = read_template_file(c.path, c.rho > 0.0 ? c.rho : 0.0);
    else
      t = make_template(c.shape, builtin_shape(c.shape, c.r, c.d, c.n), c.rho, c.resolution, c.integration);
    exact_if_disjoint(t);  // the union of disjoint spheres is their sum: exact mass properties
  } catch (const std::exception& e) {
    throw std::invalid_argument(where + ": template: " + std::string(e.what()));
  }
  t.name = c.name;
  return t;
}

}  // namespace clumps
}  // namespace tdem
