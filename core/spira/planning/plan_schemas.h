#pragma once

#include "spira/path/process_model.h"
#include "spira/path/spiral_settings.h"
#include "spira/plugin/parameter.h"

namespace spira {

// Parameter schemas of the planner's own settings sections (PlanSettings::kSpiralSection and
// kProcessSection). Declared once here, like a plugin's: the GUI builds its panels, the CLI its
// flags (--h, --h-min, --process ...) and the project file stores values by these keys.
const ParamSchema& spiralSchema();
const ParamSchema& processSchema();

// Settings from values (completed with defaults). Throws InputError when they contradict each
// other (h_min >= h_max, h outside [h_min, h_max], limits crossed, unreadable calibration file).
SpiralSettings spiralSettingsFrom(const ParamSet& values);
ProcessSettings processSettingsFrom(const ParamSet& values);

// The bead width (mm) of process `values`, its default when absent or out of range: for views,
// which must not throw on settings a file made inconsistent, nor read the calibration table.
double beadWidthOf(const ParamSet& values);

}  // namespace spira
