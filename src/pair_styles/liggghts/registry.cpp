// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the one registration table of the tdem LIGGGHTS styles.
//
// How a law gets into `pair_style gran` / `fix wall/gran` (LIGGGHTS 3.8.0):
//  1. ContactModels::Factory maps keyword values to model ids (`model NAME`, `tangential NAME`);
//     the id goes into 6 bits of a hash (normal | tangential<<6 | cohesion<<12 | rolling<<18 |
//     surface<<24).
//  2. PairStyles::Factory and Walls::Factory map ("gran", hash) to a creator of
//     Granular<ContactModel<GranStyle<...>>>, a class template compiled here with the laws
//     inlined (no virtual call per contact). Restart files store the hash, so read_restart
//     finds the same creator.
//  3. The "gran" variant selector turns the keywords into the hash. tdem wraps it to give
//     errors that name the unknown model and list what is allowed. The LAMMPS constructor
//     installs LIGGGHTS's selector, so the wrapper is installed by attach(), after it.
#include "tdem_liggghts.h"

#include <cstdint>
#include <cstring>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "contact_models.h"
#include "granular_pair_style.h"
#include "granular_wall.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include "register_combo.h"
#include "tdem_liggghts_ids.h"

namespace tdem {
namespace liggghts {
namespace {

using namespace LIGGGHTS::ContactModels;

LAMMPS_NS::LAMMPS* g_lmp = nullptr;

std::set<int64_t>& compiled() {
  static std::set<int64_t> s;
  return s;
}

// id -> name of every model LIGGGHTS and tdem know, per kind.
struct Names {
  std::map<int, std::string> normal, tangential, cohesion, rolling, surface;
};

const Names& names() {
  static const Names n = [] {
    Names r;
    r.normal[NORMAL_OFF] = "off";
#define NORMAL_MODEL(identifier, str, constant) r.normal[constant] = #str;
#include "style_normal_model.h"
#undef NORMAL_MODEL
    r.tangential[TANGENTIAL_OFF] = "off";
#define TANGENTIAL_MODEL(identifier, str, constant) r.tangential[constant] = #str;
#include "style_tangential_model.h"
#undef TANGENTIAL_MODEL
    r.cohesion[COHESION_OFF] = "off";
#define COHESION_MODEL(identifier, str, constant) r.cohesion[constant] = #str;
#include "style_cohesion_model.h"
#undef COHESION_MODEL
    r.rolling[ROLLING_OFF] = "off";
#define ROLLING_MODEL(identifier, str, constant) r.rolling[constant] = #str;
#include "style_rolling_model.h"
#undef ROLLING_MODEL
#define SURFACE_MODEL(identifier, str, constant) r.surface[constant] = #str;
#include "style_surface_model.h"
#undef SURFACE_MODEL
    r.normal[TDEM_LSD] = kNormalLsdName;
    r.normal[TDEM_HERTZ] = kNormalHertzName;
#define TDEM_UNIT_NAME(constant, id, ns) r.normal[constant] = unit_model<tdem::ns::Law>();
    TDEM_LIGGGHTS_UNITS(TDEM_UNIT_NAME)
#undef TDEM_UNIT_NAME
    r.normal[TDEM_CONTINUOUS_POTENTIAL] = kNormalContinuousPotentialName;
    r.normal[TDEM_EXTENDED_LINEAR] = kNormalExtendedLinearName;
    r.normal[TDEM_EXTENDED_HERTZ] = kNormalExtendedHertzName;
    r.tangential[TDEM_CUNDALL_STRACK] = kTangentialCundallStrackName;
    r.tangential[TDEM_HAFF_WERNER] = kTangentialHaffWernerName;
    r.tangential[TDEM_LINEAR_SPRING] = kTangentialLinearSpringName;
    r.tangential[TDEM_WALTON_BRAUN_T] = kTangentialWaltonBraunName;
    r.tangential[TDEM_MINDLIN_DERESIEWICZ] = kTangentialMindlinDeresiewiczName;
    r.tangential[TDEM_MINDLIN_NO_SLIP] = kTangentialMindlinNoSlipName;
    r.tangential[TDEM_DI_RENZO] = kTangentialDiRenzoName;
    r.surface[TDEM_CLUMP_SURFACE] = kSurfaceClumpName;
    r.rolling[TDEM_SDS] = kRollingSdsName;
    return r;
  }();
  return n;
}

std::string join(const std::map<int, std::string>& m) {
  std::string s;
  for (const auto& kv : m) s += (s.empty() ? "" : ", ") + kv.second;
  return s;
}

std::string name_of(const std::map<int, std::string>& m, int id) {
  auto it = m.find(id);
  return it == m.end() ? "#" + std::to_string(id) : it->second;
}

std::string describe(int64_t hash) {
  const Names& n = names();
  auto part = [&](int shift) { return static_cast<int>((hash >> shift) & 63); };
  return "model " + name_of(n.normal, part(0)) + " tangential " + name_of(n.tangential, part(6)) +
         " cohesion " + name_of(n.cohesion, part(12)) + " rolling_friction " +
         name_of(n.rolling, part(18)) + " surface " + name_of(n.surface, part(24)) +
         ((hash & kGridCorrectionBit) ? " grid_correction on" : "");
}

// `grid_correction on` among the arguments after the models: the variant with the correction
// compiled in (tdem_liggghts_grid.h). The keyword and its value are left for the settings, which
// check the value.
bool grid_correction_on(int narg, char** args) {
  for (int k = 0; k + 1 < narg && args[k] && args[k + 1]; ++k)
    if (std::strcmp(args[k], "grid_correction") == 0 && std::strcmp(args[k + 1], "on") == 0) return true;
  return false;
}

// Does LIGGGHTS's own selector accept this probe? (It never modifies its tables.)
bool accepted(std::vector<std::string> words, const LAMMPS_NS::Custom_contact_models& ccm) {
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(&w[0]);
  argv.push_back(nullptr);
  int narg = static_cast<int>(words.size());
  char** args = argv.data();
  return Factory::select(narg, args, ccm) != -1;
}

[[noreturn]] void fail(const std::string& msg) {
  g_lmp->error->all(FLERR, msg.c_str());
  throw std::runtime_error(msg);  // not reached: error->all exits
}

// Called when LIGGGHTS's selector rejected the keywords: name the culprit if it is a model name.
void diagnose(int narg, char** args, const LAMMPS_NS::Custom_contact_models& ccm) {
  struct Kind {
    const char* keyword;
    const char* what;
    const std::map<int, std::string>* names;
  };
  const Names& n = names();
  const Kind kinds[] = {{"model", "normal", &n.normal},
                        {"tangential", "tangential", &n.tangential},
                        {"cohesion", "cohesion", &n.cohesion},
                        {"rolling_friction", "rolling friction", &n.rolling},
                        {"surface", "surface", &n.surface}};
  int pos = 0;
  for (const Kind& k : kinds) {
    if (pos + 1 >= narg || !args[pos] || std::strcmp(args[pos], k.keyword) != 0) continue;
    const std::string value = args[pos + 1];
    if (value != "custom") {
      std::vector<std::string> probe;
      if (std::strcmp(k.keyword, "model") == 0)
        probe = {"model", value, "tangential", "history"};
      else
        probe = {"model", "hooke", k.keyword, value};
      if (!accepted(probe, ccm))
        fail(std::string("gran contact model: keyword '") + k.keyword + "' has unknown " + k.what +
             " model '" + value + "'; allowed: " + join(*k.names));
    }
    pos += 2;
  }
}

int64_t select_variant(int& narg, char**& args, LAMMPS_NS::Custom_contact_models ccm) {
  const int narg0 = narg;
  char** const args0 = args;
  int64_t hash = Factory::select(narg, args, ccm);
  if (!g_lmp) return hash;
  if (hash == -1) {
    diagnose(narg0, args0, ccm);
    return hash;  // LIGGGHTS reports the remaining cases (all models off, keyword order)
  }
  const int normal = static_cast<int>(hash & 63), tangential = static_cast<int>((hash >> 6) & 63);
  const int rolling = static_cast<int>((hash >> 18) & 63), surface = static_cast<int>((hash >> 24) & 63);
  if (grid_correction_on(narg, args)) {
    if (!combos::tdem_contact_model(normal, surface))
      fail("grid_correction on: the time-grid correction works with the tdem normal models and the default "
           "surface only (given: " + describe(hash) + ")");
    hash |= kGridCorrectionBit;
  }
  // a tdem model in any slot (tdem ids are TDEM_FIRST_ID and up, stock ids below)
  if ((normal >= TDEM_FIRST_ID || tangential >= TDEM_FIRST_ID || surface >= TDEM_FIRST_ID ||
       rolling >= TDEM_FIRST_ID) &&
      !compiled().count(hash)) {
    std::string list;
    for (int64_t h : compiled()) list += "\n  " + describe(h);
    fail("gran contact model: the combination '" + describe(hash) +
         "' is not compiled into tdem-liggghts; compiled tdem combinations:" + list);
  }
  return hash;
}

}  // namespace

namespace detail {
void note_compiled(int64_t hash) { compiled().insert(hash); }
}  // namespace detail

// The list of combinations (combos.h), part by part.
template <int... K>
void register_parts(std::integer_sequence<int, K...>) {
  (detail::register_part<K>(), ...);
}

void register_styles() {
  static bool done = false;
  if (done) return;
  done = true;
  Factory& models = Factory::instance();
  models.addNormalModel(kNormalLsdName, TDEM_LSD);
  models.addNormalModel(kNormalHertzName, TDEM_HERTZ);
#define TDEM_UNIT_MODEL(constant, id, ns) models.addNormalModel(unit_model<tdem::ns::Law>(), constant);
  TDEM_LIGGGHTS_UNITS(TDEM_UNIT_MODEL)
#undef TDEM_UNIT_MODEL
  models.addNormalModel(kNormalContinuousPotentialName, TDEM_CONTINUOUS_POTENTIAL);
  models.addNormalModel(kNormalExtendedLinearName, TDEM_EXTENDED_LINEAR);
  models.addNormalModel(kNormalExtendedHertzName, TDEM_EXTENDED_HERTZ);
  models.addTangentialModel(kTangentialCundallStrackName, TDEM_CUNDALL_STRACK);
  models.addTangentialModel(kTangentialHaffWernerName, TDEM_HAFF_WERNER);
  models.addTangentialModel(kTangentialLinearSpringName, TDEM_LINEAR_SPRING);
  models.addTangentialModel(kTangentialWaltonBraunName, TDEM_WALTON_BRAUN_T);
  models.addTangentialModel(kTangentialMindlinDeresiewiczName, TDEM_MINDLIN_DERESIEWICZ);
  models.addTangentialModel(kTangentialMindlinNoSlipName, TDEM_MINDLIN_NO_SLIP);
  models.addTangentialModel(kTangentialDiRenzoName, TDEM_DI_RENZO);
  models.addSurfaceModel(kSurfaceClumpName, TDEM_CLUMP_SURFACE);
  models.addRollingModel(kRollingSdsName, TDEM_SDS);
  register_parts(std::make_integer_sequence<int, TDEM_LIGGGHTS_PARTS>());
}

std::string style_listing() {
  std::vector<std::string>& fixes = listed_styles();
  fixes.clear();
  register_fixes(nullptr);  // with no instance: only the names are recorded
#ifdef TDEM_LIG_MODULE_GRATE
  register_grate(nullptr);
#endif
#ifdef TDEM_LIG_MODULE_MIXING
  register_mixing(nullptr);
#endif
#ifdef TDEM_LIG_MODULE_TIMESTEP
  register_timestep(nullptr);
#endif
#ifdef TDEM_LIG_MODULE_CLUMP
  register_clump(nullptr);
#endif
  const Names& n = names();
  // a titled block of names, wrapped at 80 columns as LIGGGHTS's own lists
  auto block = [](const std::string& title, const std::vector<std::string>& items) {
    std::string out = "\n* " + title + ":\n", line;
    for (const std::string& s : items) {
      if (!line.empty() && line.size() + s.size() + 2 > 80) {
        out += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : "  ") + s;
    }
    return out + line + "\n";
  };
  auto tdem_of = [](const std::map<int, std::string>& m) {
    std::vector<std::string> v;
    for (const auto& kv : m)
      if (kv.second.compare(0, 5, "tdem/") == 0) v.push_back(kv.second);
    return v;
  };
  std::vector<std::string> f, c;
  for (const std::string& s : fixes) {
    if (s.compare(0, 4, "fix ") == 0) f.push_back(s.substr(4));
    else c.push_back(s.substr(8));
  }
  fixes.clear();
  return "\n* tdem: tdem-liggghts adds these to the lists above (one page per model and style in docs/liggghts/)\n" +
         block("Contact models (tdem), pair_style gran / fix wall/gran model", tdem_of(n.normal)) +
         block("Tangential models (tdem), tangential", tdem_of(n.tangential)) +
         block("Surface models (tdem), surface", tdem_of(n.surface)) +
         block("Rolling friction models (tdem), rolling_friction", tdem_of(n.rolling)) +
         block("Fix styles (tdem)", f) + block("Compute styles (tdem)", c);
}

void attach(LAMMPS_NS::LAMMPS* lmp) {
  g_lmp = lmp;
  if (!lmp) return;
  // fix tdem/integrate (src/integrators/liggghts): LIGGGHTS's fix styles live in the instance
  register_fixes(lmp);
#ifdef TDEM_LIG_MODULE_GRATE
  register_grate(lmp);
#endif
#ifdef TDEM_LIG_MODULE_MIXING
  register_mixing(lmp);
#endif
#ifdef TDEM_LIG_MODULE_TIMESTEP
  register_timestep(lmp);
#endif
#ifdef TDEM_LIG_MODULE_CLUMP
  register_clump(lmp);
#endif
  // The LAMMPS constructor (re)installs LIGGGHTS's own "gran" selector, so the wrapper goes in
  // afterwards. LIGGGHTS prints a collision warning on std::cerr when a selector is replaced;
  // replacing it is intended here, so that warning is silenced.
  std::streambuf* saved = std::cerr.rdbuf(nullptr);
  LIGGGHTS::PairStyles::Factory::instance().addVariantSelector("gran", &select_variant);
  LIGGGHTS::Walls::Factory::instance().addVariantSelector("gran", &select_variant);
  std::cerr.rdbuf(saved);
  std::cerr.clear();
}

}  // namespace liggghts
}  // namespace tdem
