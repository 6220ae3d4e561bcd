// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: model ids of the tdem contact laws inside LIGGGHTS's contact-model factories.
//
// LIGGGHTS packs (normal, tangential, cohesion, rolling, surface) ids into one hash, 6 bits
// each (Utils::generate_gran_hashcode), so every id must be < 64. The stock ids of
// LIGGGHTS 3.8.0 are: normal 0-12 (NORMAL_OFF = 9), tangential 0-4, cohesion 0-8,
// rolling 0-6, surface 0-5. tdem takes ids from 40 upwards so that they never meet a stock id;
// the hash (and with it a restart file) of a tdem model is stable as long as these stay put.
#pragma once

namespace LIGGGHTS {
namespace ContactModels {

static const int TDEM_LSD = 40;             // model tdem/lsd
static const int TDEM_CUNDALL_STRACK = 40;  // tangential tdem/cundall_strack
static const int TDEM_HERTZ = 41;           // model tdem/hertz
static const int TDEM_WALTON_BRAUN = 42;    // model tdem/walton_braun
static const int TDEM_THORNTON = 43;        // model tdem/thornton
static const int TDEM_CONTINUOUS_POTENTIAL = 44;  // model tdem/continuous_potential
static const int TDEM_POWER_LAW = 45;             // model tdem/power_law
static const int TDEM_EXTENDED_LINEAR = 46;       // model tdem/extended_linear
static const int TDEM_EXTENDED_HERTZ = 47;        // model tdem/extended_hertz

}  // namespace ContactModels
}  // namespace LIGGGHTS

namespace tdem {
namespace liggghts {
inline constexpr const char* kNormalLsdName = "tdem/lsd";
inline constexpr const char* kTangentialCundallStrackName = "tdem/cundall_strack";
inline constexpr const char* kNormalHertzName = "tdem/hertz";
inline constexpr const char* kNormalWaltonBraunName = "tdem/walton_braun";
inline constexpr const char* kNormalThorntonName = "tdem/thornton";
inline constexpr const char* kNormalContinuousPotentialName = "tdem/continuous_potential";
inline constexpr const char* kNormalPowerLawName = "tdem/power_law";
inline constexpr const char* kNormalExtendedLinearName = "tdem/extended_linear";
inline constexpr const char* kNormalExtendedHertzName = "tdem/extended_hertz";
}  // namespace liggghts
}  // namespace tdem
