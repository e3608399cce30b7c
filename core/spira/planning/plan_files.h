#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/planning/planner.h"

namespace spira {

// The trajectory as CSV, one row per point, header
//   index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc
// (mm; unit vectors n, t, b; deposit height mm; TS mm/s; WFS m/min; arc 1 while depositing).
// Numbers are written in the shortest form that reads back to the same double.
std::string trajectoryCsv(const Trajectory& trajectory);

// The plan report (report.json): the summary keys of the CLI contract plus details.
nlohmann::json planReportJson(const PlanOutput& plan, const std::string& strategy);

// Writes DIR/trajectory.csv and DIR/report.json, each atomically.
void writePlanFiles(const PlanOutput& plan, const std::string& strategy, const std::filesystem::path& dir);

}  // namespace spira
