#pragma once

#include <ctime>
#include <map>
#include <string>

#include "spira/document/plan_report.h"

namespace spira {

// The header comment every robot program carries, as the exporters print it: the part, the cell
// (empty: "none", the targets are torch poses in the part frame), the date (UTC) and the plan in
// one line. The CLI and the desktop app both write programs with it.
std::map<std::string, std::string> programHeader(const std::string& part, const std::string& cell,
                                                 const PlanReportSummary& plan, std::time_t when);

}  // namespace spira
