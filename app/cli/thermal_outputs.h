#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "spira/thermal/thermal_replan.h"
#include "spira/thermal/thermal_study.h"

namespace spira::cli {

// thermal_points.csv: per trajectory point its peak and interpass temperatures, time above
// melting, weighted Bond number, risk flag, the deposit below at the torch's arrival and the pool.
std::string thermalPointsCsv(const ThermalStudy& study);
// probes.csv: t, then one column per probe node.
std::string thermalProbesCsv(const ThermalResult& result);
// thermal.json: the settings, the energy balance, the extremes, the risk count, sizes and times.
nlohmann::json thermalJson(const ThermalStudy& study, const ThermalStudySettings& settings);
// What re-planning adds to thermal.json and to the re-planned report.json.
// `final` is the re-planned path's study (the outcome's, moved out of it).
nlohmann::json replanJson(const ThermalReplanOutcome& outcome, const ThermalReplanSettings& replan,
                          const ThermalStudy& final);
// The console's account of a re-planning: what each remedy changed and what it cost.
void printReplan(const ThermalReplanOutcome& outcome, const ThermalReplanSettings& replan, double seconds);
// The plan's report.json updated for the re-planned path: build time, speed ranges, "thermal_replan".
nlohmann::json replannedReport(nlohmann::json report, const ThermalReplanOutcome& outcome,
                               const ThermalReplanSettings& replan, const ThermalStudy& final);

}  // namespace spira::cli
