#pragma once

#include <string_view>

#include "spira/plugin/parameter.h"

namespace spira {

// A settings section of the plan that is not a plugin's: the name it is stored under (project
// files, presets, report.json, CLI flag targets) and its schema. The sections themselves are
// declared where their schema is: spiralSection() and processSection() (planning/
// settings_sections.h), prepSection() (pipeline/prep_schema.h), thermalSection()
// (pipeline/thermal_schema.h).
struct SettingsSection {
  std::string_view name;
  const ParamSchema& schema;
};

// The section names, for the areas that store sections without reading them (the document).
inline constexpr char kSpiralSectionName[] = "spiral";
inline constexpr char kProcessSectionName[] = "process";
inline constexpr char kPrepSectionName[] = "prep";
inline constexpr char kThermalSectionName[] = "thermal";

}  // namespace spira
