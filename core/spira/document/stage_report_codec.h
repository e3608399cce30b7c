#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/document/stage_reports.h"

namespace spira {

// The JSON form of a stage report: report.json and the project file. Reading takes what a report
// holds and leaves the rest at its default (a report written by an earlier version lacks the
// newer keys); a member of the wrong type is an InputError naming `what` and the key, with `hint`.
// Defined for FieldStageReport, GeneratricesStageReport, SpiralStageReport, ProcessStageReport,
// ThermalStageReport, MotionStageReport, KinematicsStageReport and ExportStageResult.
template <class Report>
nlohmann::json reportToJson(const Report& report);
template <class Report>
Report reportFromJson(const nlohmann::json& j, const std::string& what, const std::string& hint);

// Equal when they write the same JSON (a NaN equals a NaN).
template <class Report>
bool sameReport(const Report& a, const Report& b);

}  // namespace spira
