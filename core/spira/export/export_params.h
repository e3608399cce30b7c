#pragma once

#include <cstdint>
#include <string>

#include "spira/export/export_path.h"
#include "spira/plugin/parameter.h"

namespace spira {

// Schema entries the robot-program exporters share, so each is worded once. Every exporter
// puts them in its own schema (keys are per plugin); the controller-specific ones it declares
// itself.
ParamDef programNameParam(const std::string& defaultName, const std::string& rulesText);
ParamDef maxPointsParam(std::int64_t defaultCount, std::int64_t maxCount, const std::string& why);
ParamDef approachDistanceParam();
ParamDef approachSpeedParam(double maxSpeed);
ParamDef jointSpeedParam();
ParamDef processCommandParam();
ParamDef wfsOffsetParam(double lo, double hi, const std::string& outputText);
ParamDef wfsGainParam(double defaultGain, double lo, double hi, const std::string& outputText);
ParamDef wfsDeadbandParam();
ParamDef forceParam();
// An integer entry (no unit) for an exporter's own controller settings: output numbers, frame and
// job indices.
ParamDef intParam(std::string key, std::int64_t value, double lo, double hi, std::string label,
                  std::string tooltip, std::string category);

// The shared settings read from `values` (already completed with the schema's defaults).
PathOptions readPathOptions(const ParamSet& values, const ParamSchema& schema, const std::string& controller);

// The analog value for a wire feed: offset + gain * WFS, WFS in m/min as the schema shows it.
double wfsAnalogValue(double wfsMmPerS, double offset, double gainPerMPerMin);

const char* processCommandName(ProcessCommand c);  // "speed", "speed_analog", "analog"

}  // namespace spira
