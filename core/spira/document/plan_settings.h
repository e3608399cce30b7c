#pragma once

#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/plugin/parameter.h"
#include "spira/plugin/settings_section.h"
#include "spira/plugin/strategy_name.h"

namespace spira {

// What the user chose for planning: the strategies and every parameter value, stored by
// section. A section is a plugin id ("decomposer.isovalue", "export.krl") or one of the
// built-in sections below. Values are stored as the user set them; missing keys take the
// schema default when read through ParamSet::withDefaults.
struct PlanSettings {
  static constexpr const char* kProcessSection = kProcessSectionName;  // process window (speeds, heights)
  static constexpr const char* kSpiralSection = kSpiralSectionName;    // spiral construction
  static constexpr const char* kThermalSection = kThermalSectionName;  // the optional thermal stage
  static constexpr const char* kDefaultDecomposer = kDefaultDecomposerId;
  static constexpr const char* kDefaultClosureFinder = kDefaultClosureFinderId;

  std::string decomposerId = kDefaultDecomposer;
  std::string closureFinderId = kDefaultClosureFinder;
  std::map<std::string, ParamSet> params;

  // The stored values of `section` (empty when none are stored).
  ParamSet section(const std::string& name) const;

  // Sections stored empty compare equal to absent ones.
  bool operator==(const PlanSettings& o) const;
  bool operator!=(const PlanSettings& o) const { return !(*this == o); }
};

nlohmann::json planSettingsToJson(const PlanSettings& s);
PlanSettings planSettingsFromJson(const nlohmann::json& j);  // throws InputError

}  // namespace spira
