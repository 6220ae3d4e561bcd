// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: per-type-pair material properties for the tdem contact laws in LIGGGHTS, read from
// `fix property/global NAME peratomtypepair N v11 v12 ... vNN` through LIGGGHTS's property
// registry, with range checks whose messages name the property, the type pair, the value
// and the allowed range.
#pragma once

#include <vector>

#include "property_registry.h"

#include "contact/law_parameters.h"

namespace tdem {
namespace liggghts {

// Registry names (the prefix keeps them apart from stock registry entries of the same
// fix property/global, which may apply other checks).
inline constexpr const char* kPropRestitution = "tdem_coefficientRestitution";  // (0, 1]
inline constexpr const char* kPropContactTime = "tdem_contactTime";             // > 0
inline constexpr const char* kPropStiffnessRatio = "tdem_tangentialStiffnessRatio";  // >= 0
inline constexpr const char* kPropTangentialDampingRatio = "tdem_tangentialDampingRatio";  // >= 0
inline constexpr const char* kPropDampingCoefficient = "tdem_dampingCoefficient";  // >= 0
inline constexpr const char* kPropDampingExponent = "tdem_dampingExponent";        // >= 0
inline constexpr const char* kPropPotentialEnergy = "tdem_potentialEnergy";        // > 0
inline constexpr const char* kPropPotentialExponent = "tdem_potentialExponent";    // > 0
inline constexpr const char* kPropRollingStiffness = "tdem_rollingStiffness";    // > 0
inline constexpr const char* kPropRollingDamping = "tdem_rollingDamping";        // >= 0
inline constexpr const char* kPropRollingFriction = "tdem_coefficientRollingFriction";  // >= 0
// fit coefficients: finite here; the ranges depend on the fit form (checked by the model)
inline constexpr const char* kPropRestitutionFit[3] = {"tdem_restitutionFitC0", "tdem_restitutionFitC1",
                                                       "tdem_restitutionFitC2"};
inline constexpr const char* kPropContactTimeFit[2] = {"tdem_contactTimeFitC0", "tdem_contactTimeFitC1"};
// scalars (fix property/global NAME scalar V), optional
inline constexpr const char* kPropImpactVelocityMin = "tdem_impactVelocityMin";  // > 0
inline constexpr const char* kPropImpactVelocityMax = "tdem_impactVelocityMax";  // > 0

MatrixProperty* create_restitution(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_contact_time(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_stiffness_ratio(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_tangential_damping_ratio(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_damping_coefficient(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_damping_exponent(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_potential_energy(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_potential_exponent(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_rolling_stiffness(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_rolling_damping(PropertyRegistry& registry, const char* caller, bool);
MatrixProperty* create_rolling_friction(PropertyRegistry& registry, const char* caller, bool);
extern const MatrixPropertyCreator create_restitution_fit[3];
extern const MatrixPropertyCreator create_contact_time_fit[2];
ScalarProperty* create_impact_velocity_min(PropertyRegistry& registry, const char* caller, bool);
ScalarProperty* create_impact_velocity_max(PropertyRegistry& registry, const char* caller, bool);

// The per-type-pair property `fix_name` of parameter p of a unit law (src/contact/law_unit.h),
// checked against p's bound (Bound::at_least: finite here; check_at_least compares the values).
MatrixProperty* create_parameter(PropertyRegistry& registry, const char* fix_name, const char* caller,
                                 const tdem::law::Parameter& p);
// error->all unless v >= ref (a Bound::at_least parameter `fix_name` against `ref_name`).
void check_at_least(LAMMPS_NS::LAMMPS* lmp, const char* caller, const char* fix_name, int i, int j, double v,
                    const char* ref_name, double ref);

// Is there a `fix property/global <fix_name> scalar ...`? (Optional scalar properties.)
bool has_scalar_property(LAMMPS_NS::LAMMPS* lmp, const char* fix_name, const char* caller);

// The atom types whose rows LIGGGHTS fills in the tables of a PropertyRegistry: the largest type
// present in atoms, insertions and walls (Properties::max_type), not the create_box count. A table
// connected in this init has exactly these rows; a type that appears later (create_atoms, set type,
// fix pour) comes with a new init and new tables. Read no table beyond this.
inline int table_types(PropertyRegistry& registry) { return registry.max_type(); }

// error->all unless the range check holds for every type pair 1..ntypes of a connected matrix.
// kind: 0 -> value > 0, 1 -> value >= 0. `fix_name` is the fix property/global name.
void check_matrix(LAMMPS_NS::LAMMPS* lmp, double** m, int ntypes, const char* fix_name,
                  const char* caller, int kind);

// A warning (rank 0, once per message and process) for every type pair whose value is outside
// its usual range: `unusual` is one of tdem::usual (src/contact/usual_ranges.h).
void warn_unusual(LAMMPS_NS::LAMMPS* lmp, double** m, int ntypes, const char* fix_name, const char* caller,
                  std::string (*unusual)(double));

// A dense (ntypes+1)^2 table of per-type-pair values, indexed by LIGGGHTS atom types.
template <class V>
class PairTable {
 public:
  void resize(int ntypes) {
    stride_ = ntypes + 1;
    v_.assign(static_cast<size_t>(stride_) * stride_, V{});
  }
  V& operator()(int i, int j) { return v_[static_cast<size_t>(i) * stride_ + j]; }
  const V& operator()(int i, int j) const { return v_[static_cast<size_t>(i) * stride_ + j]; }

 private:
  int stride_ = 0;
  std::vector<V> v_;
};

}  // namespace liggghts
}  // namespace tdem
