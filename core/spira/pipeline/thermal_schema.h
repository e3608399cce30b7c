#pragma once

#include "spira/plugin/parameter.h"
#include "spira/plugin/settings_section.h"

namespace spira {

// The "thermal" section of the plan settings: whether a plan simulates the heat of its build (off by
// default), the material and arc power, the model's resolution, and the interpass limit with the
// remedies re-planning may use (thermal.md). The GUI's Thermal tab is built from the schema; the
// values are read by thermalStageSettingsFrom() (thermal_stage.h).
const ParamSchema& thermalSchema();
const SettingsSection& thermalSection();

// Whether `values` switch the stage on (not validated: a plan without it never reads the rest).
bool thermalStageEnabled(const ParamSet& values);

}  // namespace spira
