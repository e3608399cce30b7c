#include "spira/document/plan_report.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/document/results.h"
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

PlanReportSummary summarisePlanReport(const nlohmann::json& r, const std::string& what)
{
  using namespace json_read;
  PlanReportSummary s;
  if (!r.is_object()) return s;
  s.part = text(r, "part", "", what, kReplanHint);
  s.cellFile = text(r, "cell_file", "", what, kReplanHint);
  s.cell = text(r, "cell", "", what, kReplanHint);
  s.partType = text(r, "part_type", "", what, kReplanHint);
  s.revolutions = wholeNumber(r, "n_revolutions", 0, what, kReplanHint);
  s.heightMin = number(r, "height_min", 0.0, what, kReplanHint);
  s.heightMax = number(r, "height_max", 0.0, what, kReplanHint);
  s.pathLength = number(r, "path_length", 0.0, what, kReplanHint);
  if (r.contains("feasible")) s.feasible = flag(r, "feasible", what, kReplanHint);
  if (r.contains("deposit_check")) {
    const nlohmann::json& check = r["deposit_check"];
    if (!check.is_object())
      throw InputError(what + ": 'deposit_check' should be an object, found " + describe(check), kReplanHint);
    const std::string where = what + " (deposit_check)";
    s.depositSummary = text(check, "summary", "", where, kReplanHint);
    s.depositChecked = true;
    s.depositHeightMin = number(check, "height_min", 0.0, where, kReplanHint);
    s.depositHeightMax = number(check, "height_max", 0.0, where, kReplanHint);
    s.flagged = wholeNumber(check, "flagged", 0, where, kReplanHint);
    if (check.contains("coverage"))
      s.uncoveredFraction = number(check["coverage"], "uncovered_fraction", 0.0, where, kReplanHint);
    if (check.contains("flagged_points") && check["flagged_points"].is_array())
      for (const nlohmann::json& f : check["flagged_points"]) {
        DepositFlagSummary flag;
        flag.point =
            static_cast<std::size_t>(std::max<std::int64_t>(0, wholeNumber(f, "point", where, kReplanHint)));
        flag.kind = text(f, "kind", "", where, kReplanHint);
        if (f.contains("height") && f["height"].is_number()) flag.height = f["height"].get<double>();
        s.flaggedPoints.push_back(std::move(flag));
      }
  }
  s.points = wholeNumber(r, "n_points", 0, what, kReplanHint);
  s.collapsedRevolutions = wholeNumber(r, "collapsed_revolutions", 0, what, kReplanHint);
  s.closed = r.contains("closure_point") && !r["closure_point"].is_null();
  s.rampHeightMin = number(r, "ramp_height_min", 0.0, what, kReplanHint);
  s.rampHeightMax = number(r, "ramp_height_max", 0.0, what, kReplanHint);
  if (r.contains("h_min") && r.contains("h_max"))
    s.window = PlanWindow{number(r, "h", 0.0, what, kReplanHint), number(r, "h_min", what, kReplanHint),
                          number(r, "h_max", what, kReplanHint),
                          number(r, "height_tolerance_mm", 0.0, what, kReplanHint)};
  if (r.contains("solid") && r["solid"].is_object() && r["solid"].contains("wall_thickness_mm")) {
    const nlohmann::json& wall = r["solid"]["wall_thickness_mm"];
    const std::string where = what + " (solid)";
    s.solidWall = SolidWallSummary{number(wall, "median", 0.0, where, kReplanHint),
                                   number(wall, "thinnest", 0.0, where, kReplanHint),
                                   number(wall, "thickest", 0.0, where, kReplanHint)};
  }
  if (r.contains("process") && r["process"].is_object() && r["process"].contains("build_time_s"))
    s.buildTime = number(r["process"], "build_time_s", what + " (process)", kReplanHint);
  return s;
}

nlohmann::json mergedPlanReport(const Results& results)
{
  const auto& spiral = results.report(Stage::Spiral);
  if (!spiral || !spiral->is_object()) return nlohmann::json::object();
  nlohmann::json report = *spiral;
  if (const auto& process = results.report(Stage::Process)) report["process"] = *process;
  if (const auto& motion = results.report(Stage::Kinematics); motion && motion->is_object())
    for (const auto& [key, value] : motion->items()) report[key] = value;
  return report;
}

std::optional<PlanReportSummary> planSummaryOf(const Results& results)
{
  if (!results.report(Stage::Spiral)) return std::nullopt;
  try {
    return summarisePlanReport(mergedPlanReport(results), "the plan's report");
  } catch (const InputError&) {
    return std::nullopt;
  }
}

std::optional<PlanWindow> planWindow(const Results& results)
{
  const std::optional<PlanReportSummary> s = planSummaryOf(results);
  return s ? s->window : std::nullopt;
}

}  // namespace spira
