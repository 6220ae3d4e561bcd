// SPDX-License-Identifier: GPL-2.0-or-later
#include "tdem_liggghts_properties.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "contact/usual_ranges.h"

#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "lammps.h"
#include "modify.h"

namespace tdem {
namespace liggghts {
namespace {

enum class Range { positive, non_negative, restitution, finite };

const char* describe(Range r) {
  switch (r) {
    case Range::positive: return "> 0";
    case Range::non_negative: return ">= 0";
    case Range::restitution: return "in (0, 1]";
    case Range::finite: return "finite";
  }
  return "";
}

bool ok(Range r, double v) {
  if (!std::isfinite(v)) return false;
  switch (r) {
    case Range::positive: return v > 0.0;
    case Range::non_negative: return v >= 0.0;
    case Range::restitution: return tdem::checks::restitution_ok(v);
    case Range::finite: return true;
  }
  return false;
}

// Shortest of %.15g / %.17g that reads back as v (so 0.3 prints as 0.3).
std::string format_value(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  if (std::strtod(buf, nullptr) != v) std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void fail(LAMMPS_NS::LAMMPS* lmp, const char* fix_name, const char* caller, int i, int j, double v,
          Range r) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: fix property/global %s has value %s for atom types %d %d; allowed: %s %s",
                caller, fix_name, format_value(v).c_str(), i, j, fix_name, describe(r));
  lmp->error->all(FLERR, buf);
}

MatrixProperty* create_checked(PropertyRegistry& registry, const char* fix_name, const char* caller,
                               Range r) {
  LAMMPS_NS::LAMMPS* lmp = registry.getLAMMPS();
  const int n = registry.max_type();
  LAMMPS_NS::FixPropertyGlobal* fix =
      registry.getGlobalProperty(fix_name, "property/global", "peratomtypepair", n, n, caller);
  MatrixProperty* m = new MatrixProperty(n + 1, n + 1);
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= n; ++j) {
      const double v = fix->compute_array(i - 1, j - 1);
      if (!ok(r, v)) {
        delete m;
        fail(lmp, fix_name, caller, i, j, v, r);
      }
      m->data[i][j] = v;
    }
  return m;
}

ScalarProperty* create_checked_scalar(PropertyRegistry& registry, const char* fix_name, const char* caller,
                                      Range r) {
  LAMMPS_NS::FixPropertyGlobal* fix = registry.getGlobalProperty(fix_name, "property/global", "scalar", 0, 0, caller);
  const double v = fix->compute_scalar();
  if (!ok(r, v)) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s: fix property/global %s has value %s; allowed: %s %s", caller, fix_name,
                  format_value(v).c_str(), fix_name, describe(r));
    registry.getLAMMPS()->error->all(FLERR, buf);
  }
  ScalarProperty* p = new ScalarProperty();
  p->data = v;
  return p;
}

template <int I>
MatrixProperty* create_restitution_fit_i(PropertyRegistry& registry, const char* caller, bool) {
  static const char* names[3] = {"restitutionFitC0", "restitutionFitC1", "restitutionFitC2"};
  return create_checked(registry, names[I], caller, Range::finite);
}
template <int I>
MatrixProperty* create_contact_time_fit_i(PropertyRegistry& registry, const char* caller, bool) {
  static const char* names[2] = {"contactTimeFitC0", "contactTimeFitC1"};
  return create_checked(registry, names[I], caller, Range::finite);
}

}  // namespace

const MatrixPropertyCreator create_restitution_fit[3] = {&create_restitution_fit_i<0>, &create_restitution_fit_i<1>,
                                                         &create_restitution_fit_i<2>};
const MatrixPropertyCreator create_contact_time_fit[2] = {&create_contact_time_fit_i<0>,
                                                          &create_contact_time_fit_i<1>};

MatrixProperty* create_rolling_stiffness(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "rollingStiffness", caller, Range::positive);
}
MatrixProperty* create_rolling_damping(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "rollingDamping", caller, Range::non_negative);
}
MatrixProperty* create_rolling_friction(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "coefficientRollingFriction", caller, Range::non_negative);
}
ScalarProperty* create_impact_velocity_min(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked_scalar(registry, "impactVelocityMin", caller, Range::positive);
}
ScalarProperty* create_impact_velocity_max(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked_scalar(registry, "impactVelocityMax", caller, Range::positive);
}

MatrixProperty* create_parameter(PropertyRegistry& registry, const char* fix_name, const char* caller,
                                 const tdem::law::Parameter& p) {
  using tdem::law::Bound;
  const Range r = p.bound == Bound::positive       ? Range::positive
                  : p.bound == Bound::non_negative ? Range::non_negative
                  : p.bound == Bound::restitution  ? Range::restitution
                                                   : Range::finite;
  return create_checked(registry, fix_name, caller, r);
}

void check_at_least(LAMMPS_NS::LAMMPS* lmp, const char* caller, const char* fix_name, int i, int j, double v,
                    const char* ref_name, double ref) {
  if (v >= ref) return;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: fix property/global %s has value %s for atom types %d %d; allowed: %s >= %s (%s)", caller,
                fix_name, format_value(v).c_str(), i, j, fix_name, ref_name, format_value(ref).c_str());
  lmp->error->all(FLERR, buf);
}

bool has_scalar_property(LAMMPS_NS::LAMMPS* lmp, const char* fix_name, const char* caller) {
  return lmp->modify->find_fix_property(fix_name, "property/global", "scalar", 0, 0, caller, false) != nullptr;
}

MatrixProperty* create_restitution(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "coefficientRestitution", caller, Range::restitution);
}
MatrixProperty* create_contact_time(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "contactTime", caller, Range::positive);
}
MatrixProperty* create_stiffness_ratio(PropertyRegistry& registry, const char* caller, bool) {
  MatrixProperty* m = create_checked(registry, "tangentialStiffnessRatio", caller, Range::non_negative);
  warn_unusual(registry.getLAMMPS(), m->data, registry.max_type(), "tangentialStiffnessRatio", caller,
               &tdem::usual::stiffness_ratio);
  return m;
}

MatrixProperty* create_tangential_damping_ratio(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "tangentialDampingRatio", caller, Range::non_negative);
}
MatrixProperty* create_damping_coefficient(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "dampingCoefficient", caller, Range::non_negative);
}
MatrixProperty* create_damping_exponent(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "dampingExponent", caller, Range::non_negative);
}
MatrixProperty* create_potential_energy(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "potentialEnergy", caller, Range::positive);
}
MatrixProperty* create_potential_exponent(PropertyRegistry& registry, const char* caller, bool) {
  return create_checked(registry, "potentialExponent", caller, Range::positive);
}

void warn_unusual(LAMMPS_NS::LAMMPS* lmp, double** m, int ntypes, const char* fix_name, const char* caller,
                  std::string (*unusual)(double)) {
  // LIGGGHTS connects the tables at every init (every run): warn once per message
  static std::set<std::string> said;
  if (lmp->comm->me != 0) return;
  for (int i = 1; i <= ntypes; ++i)
    for (int j = i; j <= ntypes; ++j) {
      const std::string text = unusual(m[i][j]);
      if (text.empty()) continue;
      const std::string msg = std::string(caller) + ": fix property/global " + fix_name + " for atom types " +
                              std::to_string(i) + " " + std::to_string(j) + ": " + text;
      if (said.insert(msg).second) lmp->error->warning(FLERR, msg.c_str());
    }
}

void check_matrix(LAMMPS_NS::LAMMPS* lmp, double** m, int ntypes, const char* fix_name,
                  const char* caller, int kind) {
  const Range r = kind == 0 ? Range::positive : Range::non_negative;
  for (int i = 1; i <= ntypes; ++i)
    for (int j = 1; j <= ntypes; ++j)
      if (!ok(r, m[i][j])) fail(lmp, fix_name, caller, i, j, m[i][j], r);
}

}  // namespace liggghts
}  // namespace tdem
