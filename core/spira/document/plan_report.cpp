#include "spira/document/plan_report.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/document/results.h"
#include "spira/document/stage_report_codec.h"
#include "spira/io/json_read.h"

namespace spira {
namespace {

constexpr const char* kReplanHint = "plan the part again with spira-cli plan";

}  // namespace

nlohmann::json parsePlanReport(const std::string& text, const std::string& what)
{
  nlohmann::json report = json_read::parse(text, what, kReplanHint);
  if (!report.is_object())
    throw InputError(what + ": expected a JSON object, found " + json_read::describe(report), kReplanHint);
  return report;
}

namespace {

void takeDepositCheck(PlanReportSummary& s, const DepositCheckRecord& check)
{
  s.depositSummary = check.summary;
  s.depositChecked = true;
  s.depositHeightMin = check.heightMin;
  s.depositHeightMax = check.heightMax;
  s.flagged = check.flagged;
  s.uncoveredFraction = check.coverage ? check.coverage->uncoveredFraction : 0.0;
  s.flaggedPoints.clear();
  for (const DepositFlagRecord& f : check.flaggedPoints)
    s.flaggedPoints.push_back({static_cast<std::size_t>(std::max<std::int64_t>(0, f.point)), f.kind,
                               std::isfinite(f.height) ? std::optional<double>(f.height) : std::nullopt});
}

}  // namespace

PlanReportSummary summaryOf(const SpiralStageReport& r, const ProcessStageReport* process,
                            const MotionStageReport* motion)
{
  PlanReportSummary s;
  if (motion) {
    s.cell = motion->cell;
    s.positionerToleranceDeg = motion->positionerToleranceDeg;
  }
  s.partType = r.partType;
  s.revolutions = r.revolutions;
  s.heightMin = r.heightMin;
  s.heightMax = r.heightMax;
  s.pathLength = r.pathLength;
  s.feasible = r.feasible;
  takeDepositCheck(s, r.depositCheck);
  s.points = r.points;
  s.collapsedRevolutions = r.collapsedRevolutions;
  s.closed = r.closurePoint.has_value();
  s.rampHeightMin = r.rampHeightMin;
  s.rampHeightMax = r.rampHeightMax;
  if (r.hMax > 0.0) s.window = PlanWindow{r.h, r.hMin, r.hMax, r.heightTolerance};
  if (r.solid)
    s.solidWall = SolidWallSummary{r.solid->wallThickness.median, r.solid->wallThickness.thinnest,
                                   r.solid->wallThickness.thickest};
  if (process) s.buildTime = r.buildTime;
  if (r.deltaMin && r.deltaMax && r.maxKinkDeg && r.arcStarts)
    s.layers =
        PlanReportSummary::Layers{r.layers,    *r.arcStarts,  *r.deltaMin,
                                  *r.deltaMax, *r.maxKinkDeg, r.layerOutput.value_or("spiral") == "spiral"};
  return s;
}

PlanReportSummary summarisePlanReport(const nlohmann::json& r, const std::string& what)
{
  using namespace json_read;
  if (!r.is_object()) return {};
  const auto spiral = reportFromJson<SpiralStageReport>(r, what, kReplanHint);
  const auto motion = reportFromJson<MotionStageReport>(r, what, kReplanHint);
  std::optional<ProcessStageReport> process;
  if (r.contains("process"))
    process = reportFromJson<ProcessStageReport>(r["process"], what + " (process)", kReplanHint);
  PlanReportSummary s = summaryOf(spiral, process ? &*process : nullptr, &motion);
  s.depositChecked = r.contains("deposit_check");
  s.part = text(r, "part", "", what, kReplanHint);
  s.cellFile = text(r, "cell_file", "", what, kReplanHint);
  if (!r.contains("h_max")) s.window.reset();
  return s;
}

nlohmann::json mergedPlanReport(const Results& results)
{
  const StageReports& reports = results.reports;
  if (!reports.spiral) return nlohmann::json::object();
  nlohmann::json report = reportToJson(*reports.spiral);
  if (reports.process) report["process"] = reportToJson(*reports.process);
  if (reports.thermal) report["thermal"] = reportToJson(*reports.thermal);
  if (reports.thermal && reports.thermal->depositCheck) {
    report["deposit_check"] = reportToJson(*reports.thermal->depositCheck);
    report["feasible"] = reports.spiral->feasible && reports.thermal->depositCheck->feasible;
  }
  if (const auto& kinematics = reports.kinematics) {
    const nlohmann::json motion = reportToJson(kinematics->motion);
    for (const auto& [key, value] : motion.items()) report[key] = value;
    nlohmann::json& timings = report["timings_s"];
    timings["kinematics"] = kinematics->seconds;
    if (timings.contains("total")) timings["total"] = timings["total"].get<double>() + kinematics->seconds;
  }
  return report;
}

std::optional<PlanReportSummary> planSummaryOf(const Results& results)
{
  const StageReports& reports = results.reports;
  if (!reports.spiral) return std::nullopt;
  PlanReportSummary s = summaryOf(*reports.spiral, reports.process.get(),
                                  reports.kinematics ? &reports.kinematics->motion : nullptr);
  if (reports.thermal && reports.thermal->depositCheck) {
    s.feasible = s.feasible && reports.thermal->depositCheck->feasible;
    takeDepositCheck(s, *reports.thermal->depositCheck);
  }
  return s;
}

std::optional<PlanWindow> planWindow(const Results& results)
{
  const std::optional<PlanReportSummary> s = planSummaryOf(results);
  return s ? s->window : std::nullopt;
}

}  // namespace spira
