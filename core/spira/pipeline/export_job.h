#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

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
  // The plan's positioner tolerance (deg, PlanReportSummary::positionerToleranceDeg): the targets keep
  // the build direction as close to the vertical as the plan did. None: the process default.
  std::optional<double> positionerToleranceDeg;
  // Per planned point, whether the plan left it in collision (torch or robot links, as
  // solvePlanMotion found); empty when unknown. The program's targets standing for such points
  // are flagged "in collision" (refused unless the exporter's `force` is set). Needs a cell.
  std::vector<bool> plannedCollision;
  std::map<std::string, std::string> header;
};

struct ExportOutcome {
  ExportResult result;
  PrepReport prep;
  size_t robotTargets = 0;  // points written
  size_t unreachableTargets = 0;
  size_t subPaths = 1;  // sub-paths of the plan: one arc start and stop each
  size_t dwells = 0;    // dwells of the plan (path/dwell.h): each one lift, one wait, one more arc start
  double seconds = 0.0;
};

// Prepares the planned trajectory (smoothing and decimation under the job's tolerances), solves the
// prepared points on the cell when there is one, and writes the program with the exporter (all
// files or none). A plan with several sub-paths (the `path` channel of a multi-branch part) is
// prepared and solved sub-path by sub-path and written with one arc start and stop each and a
// retract, travel and approach between them at job.prep.travelClearance above the plan, arc off.
// A dwell (path/dwell.h) cuts its sub-path in two pieces prepared on their own; between them the
// torch lifts job.prep.travelClearance along its axis, waits there with the arc off (the program
// point carries the wait in the dwell channel) and comes back to the same point to strike again. A
// dwell at a sub-path's first or last point waits on the travel's approach or retract instead.
// With job.prep.leadWireFeed the wire-feed setpoints are led by the feeder's lag (the
// kWfsCommandChannel / kWfsLeadChannel channels of export_path.h). Throws InputError for unknown
// exporters or bad parameters; an exporter refuses unreachable or colliding targets unless its
// `force` parameter is set (InfeasibleError).
ExportOutcome exportTrajectory(const PluginRegistry& registry, const Trajectory& planned,
                               const ExportJob& job, const std::filesystem::path& outDir, Progress& progress);

}  // namespace spira
