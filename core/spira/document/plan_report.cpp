#include "spira/document/plan_report.h"

#include "spira/base/error.h"
#include "spira/document/json_read.h"

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
    s.depositSummary = text(check, "summary", "", what + " (deposit_check)", kReplanHint);
  }
  return s;
}

}  // namespace spira
