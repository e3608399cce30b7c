#pragma once

#include <string>
#include <vector>

#include "spira/path/process_model.h"
#include "spira/path/trajectory.h"
#include "spira/scan/built_wall.h"

namespace spira {

// Re-planning the rest of a build from the measured top of the wall (between-layer correction). The
// measured shortfall of each generatrix is made up by laying its next revolutions thicker (or thinner,
// for a wall that grew too tall) by the same amount each, over the fewest revolutions that keep every
// bead inside [hMin, hMax]; the torch follows the wall as it stands, its positions lowered by what is
// still missing, so the path starts at the measured edge and ends on the planned top.
struct ResumeSettings {
  double hMin = 0.0, hMax = 0.0;  // the process window, mm
  ProcessSettings process;        // the speeds of the new heights
};

struct ResumeReport {
  size_t at = 0;  // the first point of the continuation: the arc restarts there
  size_t edgePoints = 0, unmeasured = 0;
  double shortfallMin = 0.0, shortfallMax = 0.0, shortfallMean = 0.0;  // measured, mm
  int revolutionsMax = 0;    // the most revolutions a generatrix takes to make its shortfall up
  double leftoverMax = 0.0;  // mm the window cannot make up by the end (0: the top is reached)
  size_t leftoverPoint = 0;  // where (a point of the continuation's last revolution), if any
  double heightMin = 0.0, heightMax = 0.0;  // the continuation's deposits
  bool reachesTop() const { return leftoverMax <= 1e-9; }
  std::string summary() const;
};

struct Resumed {
  Trajectory continuation;  // the plan's points from `at` on, heights, positions and speeds re-planned
  ResumeReport report;
};

// The process a plan was laid with, as its channels show it: one wire feed throughout (synergic) or
// else one travel speed; the re-planned heights keep it.
ProcessSettings processOfPlan(const Trajectory& plan, double beadWidth);

// Throws InputError for an index outside the plan, a window that does not hold the plan, or a plan
// whose remaining points lie on generatrices the edge does not have.
Resumed resumeFromEdge(const Trajectory& plan, size_t at, const MeasuredEdge& edge,
                       const ResumeSettings& settings);

}  // namespace spira
