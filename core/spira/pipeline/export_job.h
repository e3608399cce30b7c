#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "spira/base/progress.h"
#include "spira/plugin/exporter.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/prep/prepare_trajectory.h"
#include "spira/robotcell/robot_cell.h"

namespace spira {

// One robot-program export: which exporter, its parameters, the path preparation, the cell (null:
// Cartesian targets in the part frame) and the header block's entries.
struct ExportJob {
  std::string exporterId;  // e.g. "export.krl"
  ParamSet exporterParams;
  PrepParams prep;
  const RobotCell* cell = nullptr;
  bool optimiseSpin = true;  // layer-wise torch spin on the prepared points (plan_motion.h)
  std::map<std::string, std::string> header;
};

struct ExportOutcome {
  ExportResult result;
  PrepReport prep;
  size_t robotTargets = 0;  // points written
  size_t unreachableTargets = 0;
  double seconds = 0.0;
};

// Prepares the planned trajectory (smoothing and decimation under the job's tolerances), solves the
// prepared points on the cell when there is one, and writes the program with the exporter (all
// files or none). Throws InputError for unknown exporters or bad parameters; an exporter refuses
// unreachable or colliding targets unless its `force` parameter is set.
ExportOutcome exportTrajectory(const PluginRegistry& registry, const Trajectory& planned,
                               const ExportJob& job, const std::filesystem::path& outDir, Progress& progress);

}  // namespace spira
