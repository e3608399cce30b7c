#pragma once

#include <string>
#include <vector>

#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/base/transform.h"
#include "spira/export/export_path.h"

namespace spira {

// What the RAPID writer needs besides the path; every value already checked against the schema and
// every name already a valid RAPID data name (rapid_names.h).
struct RapidSettings {
  std::string moduleName;   // valid; parts add _001, _002...
  size_t maxPoints = 5000;  // robtargets per module
  std::string toolName = "tSpiraTorch";
  std::string wobjName = "wobjSpira";
  std::string seamName = "smSpira";
  std::string weldPrefix = "wdSpira";           // welddata wdSpira1, wdSpira2...
  std::string speedPrefix = "vSpira";           // speeddata vSpira1..., vSpiraTravel, vSpiraApproach
  Transform flangeTcp = Transform::Identity();  // the torch: tooldata tframe
  double toolMass = 3.0;                        // kg, tooldata tload
  int zone = 1;                                 // zN between arc points
  double approachSpeed = 20.0;                  // mm/s
  double travelSpeed = 200.0;                   // mm/s, MoveJ to the approach and between sub-paths
  bool wireFeed = false;                        // welddata carries the WFS channel (analog modes)
  int schedule = 1;                             // arcdata sched (the power source's program)
  double voltage = 0.0;                         // arcdata voltage, V (0: the schedule's)
};

struct RapidOutput {
  std::vector<OutputFile> files;
  size_t weldDataCount = 0;
  double worstSpeedError = 0.0;  // largest relative difference of a written weld speed from the plan's
};

// Writes one module <name>.mod, or past maxPoints a main module calling part modules in order plus
// the program file <name>.pgf listing them. `header` is the comment block the modules open with.
RapidOutput writeRapidProgram(const ExportPath& path, const RapidSettings& settings,
                              const std::vector<std::string>& header, Progress& progress);

}  // namespace spira
