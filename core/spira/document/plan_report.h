#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace spira {

// What export takes from a plan's report (a plan folder's report.json, or the stage reports a
// project stores): the names and figures for the program header and the plan's verdict. Every
// member is optional in the report; one of the wrong type is an InputError naming the report
// (`what`) and the key.
struct PlanReportSummary {
  std::string part;      // "part": the planned file, empty when absent
  std::string cellFile;  // "cell_file": the cell the plan was made for, empty without one
  std::string cell;      // "cell": the cell's name, empty when absent
  std::string partType;  // "part_type"
  std::int64_t revolutions = 0;
  double heightMin = 0.0, heightMax = 0.0, pathLength = 0.0;  // mm
  std::optional<bool> feasible;
  std::string depositSummary;  // "deposit_check"."summary"
};

// Parses a report's text; it must be a JSON object. Throws InputError naming `what` and, for a
// syntax error, the line and column.
nlohmann::json parsePlanReport(const std::string& text, const std::string& what);

PlanReportSummary summarisePlanReport(const nlohmann::json& report, const std::string& what);

}  // namespace spira
