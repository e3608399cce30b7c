#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/planning/plan_advice.h"
#include "spira/planning/planner.h"

namespace spira {

// The trajectory as CSV, one row per point, header
//   index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path
// (mm; unit vectors n, t, b; deposit height mm; TS mm/s; WFS m/min; arc 1 while depositing; path:
// the sub-path, 0 for a mono-branch part, numbered in build order on a multi-branch one, where the
// arc stops at the end of each sub-path and starts again at the next). A plan with a dwell
// (path/dwell.h) has one more column, dwell_s: the wait at the point, s, 0 where the torch does not stop.
// Numbers are written in the shortest form that reads back to the same double.
std::string trajectoryCsv(const Trajectory& trajectory);

// report.json's "advice" of an infeasible plan.
nlohmann::json adviceJson(const PlanAdvice& advice);

}  // namespace spira
