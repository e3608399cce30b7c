#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "spira/document/stage_reports.h"

namespace spira {

struct Results;

// The process window a plan was made with (mm).
struct PlanWindow {
  double h = 0.0, hMin = 0.0, hMax = 0.0, tolerance = 0.0;
  bool outside(double height) const { return height < hMin - tolerance || height > hMax + tolerance; }
};

// A point the deposit check rejected (report.json's deposit_check.flagged_points).
struct DepositFlagSummary {
  std::size_t point = 0;
  std::string kind;              // "below_deposit", "thin", "thick", "jump", "unsupported"
  std::optional<double> height;  // mm: what lies below it, or the jump's length; none: nothing below
};

// The wall of a thin-walled solid planned on its mid-surface (mm).
struct SolidWallSummary {
  double median = 0.0, thinnest = 0.0, thickest = 0.0;
};

// What export and the views take from a plan's reports (a plan folder's report.json, or the stage
// reports a document holds): the names and figures for the program header and the plan's verdict.
struct PlanReportSummary {
  std::string part;      // "part": the planned file, empty when absent
  std::string cellFile;  // "cell_file": the cell the plan was made for, empty without one
  std::string cell;      // "cell": the cell's name, empty when absent
  std::string partType;  // "part_type"
  std::int64_t revolutions = 0;
  double heightMin = 0.0, heightMax = 0.0, pathLength = 0.0;  // mm
  std::optional<bool> feasible;
  std::string depositSummary;  // "deposit_check"."summary"

  std::int64_t points = 0;                          // "n_points"
  std::int64_t collapsedRevolutions = 0;            // folded into the closure point, not laid
  bool closed = false;                              // ends on a closure point
  double rampHeightMin = 0.0, rampHeightMax = 0.0;  // 0: no start-up or closing ramp
  std::optional<PlanWindow> window;                 // the stage reports a project stores carry it
  std::optional<SolidWallSummary> solidWall;
  // The deposit check: heights measured on what lies below, the uncovered share of the surface.
  bool depositChecked = false;
  double depositHeightMin = 0.0, depositHeightMax = 0.0, uncoveredFraction = 0.0;
  std::int64_t flagged = 0;                       // points it rejects
  std::vector<DepositFlagSummary> flaggedPoints;  // the first 1000 of them
  std::optional<double> buildTime;                // s: "process"."build_time_s"
  // The positioner's tolerance the motion was solved with (deg): a program's targets are solved with it.
  std::optional<double> positionerToleranceDeg;
  // Laid in layers (constant distance): the layers, their distances to the one below (mm), the
  // sharpest kink (deg) and the arcs.
  struct Layers {
    std::int64_t count = 0, arcStarts = 0;
    double deltaMin = 0.0, deltaMax = 0.0, maxKinkDeg = 0.0;
    bool spiral = true;
  };
  std::optional<Layers> layers;
};

// Parses a report's text; it must be a JSON object. Throws InputError naming `what` and, for a
// syntax error, the line and column.
nlohmann::json parsePlanReport(const std::string& text, const std::string& what);

// The summary of a plan folder's report.json (the stage reports merged, with the keys the CLI
// adds). Throws InputError naming `what` and the key of a member of the wrong type.
PlanReportSummary summarisePlanReport(const nlohmann::json& report, const std::string& what);

// The summary of the stage reports: the spiral's, with the process's and the motion's when present.
PlanReportSummary summaryOf(const SpiralStageReport& spiral, const ProcessStageReport* process,
                            const MotionStageReport* motion);

// The stage reports of a planned document in report.json's layout: the spiral's at the top, the
// process's under "process", the robot motion's at the top and its wall time under
// timings_s "kinematics". Empty without a spiral report.
nlohmann::json mergedPlanReport(const Results& results);

// The summary of a planned document's reports; nullopt without a spiral report.
std::optional<PlanReportSummary> planSummaryOf(const Results& results);

// The process window of a planned document; nullopt without one.
std::optional<PlanWindow> planWindow(const Results& results);

}  // namespace spira
