#pragma once

#include <map>
#include <string>

#include "spira/path/process_model.h"
#include "spira/path/spiral_settings.h"
#include "spira/plugin/parameter.h"

namespace spira {

// Parameter schemas of the planner's own settings sections (settings_sections.h). Each key is
// bound to the settings field it fills: the GUI builds its panels from them, the CLI its flags
// (--h, --h-min, --process ...) and the project file stores values by these keys.
const ParamSchema& spiralSchema();
const ParamSchema& processSchema();

// The planner's settings as a plan uses them: read, validated and with every "0 = automatic"
// value resolved (h_min and h_max from h and the modulation range, the closing ring from the bead
// width). Empty sections give SpiralSettings{} and ProcessSettings{}.
struct PlanSections {
  SpiralSettings spiral;
  ProcessSettings process;
};

// Reads the spiral and process sections of `params` (values by section name, as PlanSettings and
// PlanRequest store them; missing sections take the defaults). Throws InputError naming the key
// for a value out of range, and when values contradict each other (h_min >= h_max, h outside
// [h_min, h_max], limits crossed, unreadable calibration file).
PlanSections readPlanSections(const std::map<std::string, ParamSet>& params);

// The process section alone, read and validated as readPlanSections does.
ProcessSettings processSettingsFrom(const ParamSet& values);

// The bead width (mm) of process `values`, its default when absent or out of range: for views,
// which must not throw on settings a file made inconsistent, nor read the calibration table.
double beadWidthOf(const ParamSet& values);

}  // namespace spira
