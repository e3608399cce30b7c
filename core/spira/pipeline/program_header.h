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

// When a program is written: now, or SOURCE_DATE_EPOCH (seconds since 1970-01-01 UTC, the
// reproducible-builds convention) when set, so that the same plan gives byte-identical programs.
// Throws InputError for a SOURCE_DATE_EPOCH that is not a whole number of seconds.
std::time_t programTime();

}  // namespace spira
