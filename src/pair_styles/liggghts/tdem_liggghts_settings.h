// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: keyword settings with a fixed list of words (e.g. `parameters stiffness|restitution`)
// for LIGGGHTS contact models.
//
// LIGGGHTS's Settings class only lets a model register on/off, yes/no and number keywords; its
// EnumSetting exists but Settings::registerSetting is private. register_enum() adds an
// EnumSetting to a Settings object (see tdem_liggghts_settings.cpp for how) whose error
// message also lists the allowed words.
#pragma once

#include <string>
#include <vector>

#include "contact/law_parameters.h"
#include "settings.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tdem {
namespace liggghts {

// Registers keyword `name` of the model `owner` (e.g. "model tdem/lsd") taking one of `words`; `target` receives the index of the chosen
// word (default_index if the keyword is not given).
//
// LIGGGHTS hands a setting only the argument pointer, not the count, and its command argument
// arrays are not terminated: a keyword given last without its value would read a stale pointer
// of an earlier command. `lmp` lets the setting find the end of the command's arguments
// (Input::arg / Input::narg) and report the value as missing instead.
void register_enum(LAMMPS_NS::LAMMPS* lmp, Settings& settings, const std::string& owner, const std::string& name,
                   int& target, const std::vector<std::string>& words, int default_index);

// The words of a keyword group's choices (src/contact/law_parameters.h), in their order: the
// LIGGGHTS setting that chooses among them takes the same words as the law's input line.
inline std::vector<std::string> choice_words(const law::Group& g) {
  std::vector<std::string> w;
  for (int c = 0; c < g.choice_count; ++c) w.push_back(g.choices[c].word);
  return w;
}

// Registers an on/off keyword like Settings::registerOnOff (and shared with models that use
// registerOnOff for the same keyword), with an error message that lists the allowed values.
void register_on_off(LAMMPS_NS::LAMMPS* lmp, Settings& settings, const std::string& owner, const std::string& name,
                     bool& target, bool default_value);

}  // namespace liggghts
}  // namespace tdem
