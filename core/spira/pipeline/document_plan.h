#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "spira/document/document.h"
#include "spira/document/plan_report.h"
#include "spira/planning/plan_advice.h"
#include "spira/planning/planner.h"

namespace spira {

class PluginRegistry;
class Progress;

// One stage of a plan as the progress display shows it: the part of the job's [0, 1] progress it
// covers. The spans mirror the SubProgress ranges planPart() hands its stages.
struct PlanStageSpan {
  const char* label;
  double begin, end;
};
constexpr int kPlanStageCount = 7;
constexpr int kThermalPlanStage = 5;  // the optional thermal stage's span, skipped when it is off
const std::array<PlanStageSpan, kPlanStageCount>& planStageSpans();
// The stage index whose span holds `fraction` (the last one from its begin on).
int planStageAt(double fraction);

// Choices a plan takes beyond the document: the CLI's flags; the desktop app plans with the defaults.
struct PlanDocumentOptions {
  bool midSurfaceOfSolid = true;  // false: a watertight solid is refused (`--no-mid-surface`)
  bool resolveCollisions = true;  // false: torch collisions are kept and reported (`--keep-collisions`)
};

// What planning a document hands back: the staged results (field, generatrices,
// spiral, process and, with a cell, kinematics, each with its report) and what the user should read about it.
struct DocumentPlan {
  Results results;
  std::vector<std::string> warnings;
  bool feasible = false;  // the deposit check's verdict on the path
  // No cell, or the robot follows the path: reached, free of collisions, within its axis speeds.
  bool motionOk = true;
  std::string summary;         // one line: revolutions, points, heights, build time
  std::string depositSummary;  // the deposit check's verdict in one sentence
  // An infeasible plan: the change Spira planned and found feasible, or what it tried.
  std::optional<PlanAdvice> advice;
  // The plan folder's report.json: the plan's report with the advice, the cell's motion and the
  // stage timings, as `spira-cli plan` writes it.
  nlohmann::json report;
  // The planner's output but the field, the generatrices and the trajectory, which moved into `results`.
  PlanOutput output;
  size_t windowViolations = 0;
  size_t limitViolations = 0;
  double seconds = 0.0;
};

// Plans the part of `snapshot` with its settings, as the GUI (on a worker thread) and
// `spira-cli plan PROJECT` do; touches no Document. Throws InputError when there is no part, and
// whatever planPart() throws.
DocumentPlan planDocument(const DocumentState& snapshot, const PluginRegistry& registry, Progress& progress,
                          const PlanDocumentOptions& options = {});

// What in `settings` would stop a plan before it starts: values that contradict each other (only a
// file can bring them: the panels refuse them) or a calibration table that cannot be read. Shown
// when a project opens, so the user learns it before planning.
struct SettingsProblem {
  std::string what, hint;
};
std::vector<SettingsProblem> settingsProblems(const PlanSettings& settings);

// Stores the results of a plan made on `snapshot` into `doc`, keeping only the stages that the
// edits made since (while it ran) left valid. Returns the first stage dropped, or nullopt when
// all were stored.
std::optional<Stage> storePlanResults(Document& doc, const DocumentState& snapshot, const Results& computed);

}  // namespace spira
