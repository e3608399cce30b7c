#pragma once

#include "spira/plugin/parameter.h"
#include "spira/plugin/settings_section.h"
#include "spira/prep/prep_params.h"

namespace spira {

// The prep section of the plan settings: path preparation before a robot program is written
// (smoothing, decimation under chord and attribute tolerances, point spacing). See prep_params.h.
const ParamSchema& prepSchema();
const SettingsSection& prepSection();
// Throws InputError for values outside the schema or a minimum spacing above the maximum.
PrepParams prepParamsFrom(const ParamSet& values);

}  // namespace spira
