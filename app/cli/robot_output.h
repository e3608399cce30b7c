#pragma once

#include <iosfwd>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "spira/document/plan_report.h"
#include "spira/pipeline/export_job.h"
#include "spira/planning/planner.h"

namespace spira::cli {

// The exporter of a --export/--format value: "krl", "fanuc_tp" or a full id ("export.krl").
// Throws UsageError listing the formats for anything else.
const ExporterPlugin& exporterFor(const PluginRegistry& registry, const std::string& format);

// The header block of an exported program: part, cell, date and the plan's key figures.
std::map<std::string, std::string> programHeader(const std::string& partFile, const std::string& cellFile,
                                                 const PlanReportSummary& plan);

void printMotionSummary(const MotionStageReport& motion, std::ostream& out);
void printExportSummary(const ExportOutcome& exported, std::ostream& out);

}  // namespace spira::cli
