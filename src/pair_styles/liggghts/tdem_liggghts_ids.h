// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: model ids of the tdem contact laws inside LIGGGHTS's contact-model factories.
//
// LIGGGHTS packs (normal, tangential, cohesion, rolling, surface) ids into one hash, 6 bits
// each (Utils::generate_gran_hashcode), so every id must be < 64. The stock ids of
// LIGGGHTS 3.8.0 are: normal 0-12 (NORMAL_OFF = 9), tangential 0-4, cohesion 0-8,
// rolling 0-6, surface 0-5. tdem takes ids from 40 upwards so that they never meet a stock id;
// the hash (and with it a restart file) of a tdem model is stable as long as these stay put.
#pragma once

#include <cstdint>

// The normal laws that are units (src/contact/law_unit.h, listed in src/contact/laws.h), one line
// each: X(constant, model id, namespace of the law). The model is `model tdem/<name>` with the
// name of the law's description; normal_model_tdem_history.h defines it from the unit.
#define TDEM_LIGGGHTS_UNITS(X)           \
  X(TDEM_WALTON_BRAUN, 42, walton_braun) \
  X(TDEM_THORNTON, 43, thornton)         \
  X(TDEM_POWER_LAW, 45, power_law)       \
  X(TDEM_LUDING, 48, luding)

namespace LIGGGHTS {
namespace ContactModels {

static const int TDEM_FIRST_ID = 40;        // the smallest tdem id of every model kind

#define TDEM_LIGGGHTS_UNIT_ID(constant, id, ns) static const int constant = id;
TDEM_LIGGGHTS_UNITS(TDEM_LIGGGHTS_UNIT_ID)
#undef TDEM_LIGGGHTS_UNIT_ID

static const int TDEM_LSD = 40;             // model tdem/lsd
static const int TDEM_CUNDALL_STRACK = 40;  // tangential tdem/cundall_strack
static const int TDEM_HERTZ = 41;           // model tdem/hertz
static const int TDEM_CONTINUOUS_POTENTIAL = 44;  // model tdem/continuous_potential
static const int TDEM_EXTENDED_LINEAR = 46;       // model tdem/extended_linear
static const int TDEM_EXTENDED_HERTZ = 47;        // model tdem/extended_hertz
// tangential laws of issue 4 (tangential ids 41 upwards, after tdem/cundall_strack = 40)
static const int TDEM_HAFF_WERNER = 41;           // tangential tdem/haff_werner
static const int TDEM_LINEAR_SPRING = 42;         // tangential tdem/linear_spring
static const int TDEM_WALTON_BRAUN_T = 43;        // tangential tdem/walton_braun
static const int TDEM_MINDLIN_DERESIEWICZ = 44;   // tangential tdem/mindlin_deresiewicz
static const int TDEM_MINDLIN_NO_SLIP = 45;       // tangential tdem/mindlin_no_slip
static const int TDEM_DI_RENZO = 46;              // tangential tdem/di_renzo
// surface models (stock 0-5)
static const int TDEM_CLUMP_SURFACE = 40;         // surface tdem/clump (clump multiple-contact correction)
static const int TDEM_SDS = 40;                   // rolling_friction tdem/sds

}  // namespace ContactModels
}  // namespace LIGGGHTS

namespace tdem {
namespace liggghts {
inline constexpr const char* kNormalLsdName = "tdem/lsd";
inline constexpr const char* kTangentialCundallStrackName = "tdem/cundall_strack";
inline constexpr const char* kNormalHertzName = "tdem/hertz";
inline constexpr const char* kNormalContinuousPotentialName = "tdem/continuous_potential";
inline constexpr const char* kNormalExtendedLinearName = "tdem/extended_linear";
inline constexpr const char* kNormalExtendedHertzName = "tdem/extended_hertz";
inline constexpr const char* kTangentialHaffWernerName = "tdem/haff_werner";
inline constexpr const char* kTangentialLinearSpringName = "tdem/linear_spring";
inline constexpr const char* kTangentialWaltonBraunName = "tdem/walton_braun";
inline constexpr const char* kTangentialMindlinDeresiewiczName = "tdem/mindlin_deresiewicz";
inline constexpr const char* kTangentialMindlinNoSlipName = "tdem/mindlin_no_slip";
inline constexpr const char* kTangentialDiRenzoName = "tdem/di_renzo";
inline constexpr const char* kSurfaceClumpName = "tdem/clump";
inline constexpr const char* kRollingSdsName = "tdem/sds";
// The hash bit of a combination's variant with `grid_correction on` (tdem_liggghts_grid.h; bits
// 0-29 hold the five model ids, 6 bits each); the selector (registry.cpp) sets it.
inline constexpr int64_t kGridCorrectionBit = int64_t(1) << 30;
}  // namespace liggghts
}  // namespace tdem
