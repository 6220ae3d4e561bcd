// SPDX-License-Identifier: GPL-2.0-or-later
#include "tdem_liggghts_settings.h"

#include <map>
#include <sstream>

#include "input.h"
#include "lammps.h"

namespace {

// Settings keeps its keyword table in a private member and has no public way to add an
// EnumSetting. An explicit template instantiation may name a private member (C++17
// [temp.explicit]/12), which is used here, once in the program, to obtain a pointer to that
// member. The table type is spelled exactly as in settings.h.
using SettingTable = std::map<std::string, Setting*>;
struct SettingTableTag {
  using type = SettingTable Settings::*;
  friend type member(SettingTableTag);
};
template <class Tag, typename Tag::type M>
struct Grant {
  friend typename Tag::type member(Tag) { return M; }
};
template struct Grant<SettingTableTag, &Settings::settings>;

// True if the keyword at args[0] has no value after it: args[1] is null, or args lies in the
// argument array of the command being read and args[0] is its last element. Arrays built by
// other code (restart, fixes that create fixes) are null-terminated or complete.
bool value_missing(LAMMPS_NS::LAMMPS* lmp, char** args) {
  if (args[1] == nullptr) return true;
  const LAMMPS_NS::Input* in = lmp ? lmp->input : nullptr;
  if (!in || !in->arg || in->narg <= 0) return false;
  if (args < in->arg || args >= in->arg + in->narg) return false;
  return args + 1 >= in->arg + in->narg;
}

class WordSetting : public EnumSetting<int> {
 public:
  WordSetting(LAMMPS_NS::LAMMPS* lmp, const std::string& owner, const std::string& name,
              const std::vector<std::string>& words, int default_index)
      : EnumSetting<int>(name), lmp_(lmp), owner_(owner), words_(words) {
    for (size_t i = 0; i < words.size(); ++i) addOption(words[i], static_cast<int>(i));
    setDefault(words.at(default_index));
  }
  int parseArguments(char** args) override {
    if (name != args[0]) return 0;
    if (value_missing(lmp_, args)) {
      error_message = owner_ + ": keyword '" + name + "' needs a value; allowed: " + allowed();
      return -1;
    }
    const int consumed = EnumSetting<int>::parseArguments(args);
    if (consumed < 0)
      error_message = owner_ + ": keyword '" + name + "': value '" + std::string(args[1]) +
                      "' is not allowed; allowed values: " + allowed();
    return consumed;
  }

 private:
  std::string allowed() const {
    std::string s;
    for (size_t i = 0; i < words_.size(); ++i) s += (i ? " | " : "") + words_[i];
    return s;
  }
  LAMMPS_NS::LAMMPS* lmp_;
  std::string owner_;
  std::vector<std::string> words_;
};

// An on/off keyword that lists the allowed values in its error message. It is an OnOffSetting,
// so a LIGGGHTS model that registers the same keyword with Settings::registerOnOff shares it.
class OnOffWords : public OnOffSetting {
 public:
  OnOffWords(LAMMPS_NS::LAMMPS* lmp, const std::string& owner, const std::string& name, bool default_value)
      : OnOffSetting(name, default_value), lmp_(lmp), owner_(owner) {}
  int parseArguments(char** args) override {
    if (name != args[0]) return 0;
    if (value_missing(lmp_, args)) {
      error_message = owner_ + ": keyword '" + name + "' needs a value; allowed: off | on";
      return -1;
    }
    const int consumed = OnOffSetting::parseArguments(args);
    if (consumed < 0)
      error_message = owner_ + ": keyword '" + name + "': value '" + std::string(args[1]) +
                      "' is not allowed; allowed values: off | on";
    return consumed;
  }

 private:
  LAMMPS_NS::LAMMPS* lmp_;
  std::string owner_;
};

}  // namespace

namespace tdem {
namespace liggghts {

void register_enum(LAMMPS_NS::LAMMPS* lmp, Settings& settings, const std::string& owner, const std::string& name,
                   int& target, const std::vector<std::string>& words, int default_index) {
  SettingTable& table = settings.*member(SettingTableTag{});
  auto it = table.find(name);
  if (it == table.end()) it = table.emplace(name, new WordSetting(lmp, owner, name, words, default_index)).first;
  if (auto* s = dynamic_cast<WordSetting*>(it->second)) s->registerTarget(target);
}

void register_on_off(LAMMPS_NS::LAMMPS* lmp, Settings& settings, const std::string& owner, const std::string& name,
                     bool& target, bool default_value) {
  SettingTable& table = settings.*member(SettingTableTag{});
  if (table.find(name) == table.end()) table.emplace(name, new OnOffWords(lmp, owner, name, default_value));
  settings.registerOnOff(name, target, default_value);
}

}  // namespace liggghts
}  // namespace tdem
