#pragma once

#include <filesystem>
#include <string>

#include "spira/document/plan_report.h"
#include "spira/path/trajectory.h"

namespace spira::cli {

// A plan folder ('spira-cli plan -o DIR') read back for a scan of its build: resume and scan-compare.
struct PlanFolder {
  Trajectory trajectory;
  PlanReportSummary report;
  // report.json's dropped_mm: the plan moved the part this far along z (--drop, --level-base), so its
  // points lie that far from the part as its file holds it.
  double droppedMm = 0.0;
  bool levelledBase = false;  // --level-base cut the part's base off before planning
};

// Throws InputError for a folder that is not a complete plan.
PlanFolder readPlanFolder(const std::filesystem::path& dir);

// --at INDEX: the number of the plan's points deposited (1 .. the plan's size). UsageError when
// missing or not a whole number, InputError when outside the plan.
size_t atFlag(const std::string& text, const Trajectory& plan);

double beadWidthFlag(const std::string& text);

}  // namespace spira::cli
