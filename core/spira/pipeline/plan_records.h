#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/document/stage_reports.h"
#include "spira/planning/planner.h"

namespace spira {

// The stage reports of a plan, from the planner's output; `strategy` is the decomposer's id (short
// or full), written by its one name.
FieldStageReport fieldStageReport(const PlanOutput& plan);
GeneratricesStageReport generatricesStageReport(const PlanOutput& plan);
SpiralStageReport spiralStageReport(const PlanOutput& plan, const std::string& strategy);
ProcessStageReport processStageReport(const ProcessReport& process);
// report.json's deposit_check: the verdict and its first flags.
DepositCheckRecord depositCheckRecord(const DepositCheckReport& check);

// The plan's report in report.json's layout without a document (the spiral's, the process's under
// "process"): what the planning tests compare.
nlohmann::json planReportJson(const PlanOutput& plan, const std::string& strategy);

}  // namespace spira
