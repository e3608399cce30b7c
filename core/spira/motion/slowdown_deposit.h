#pragma once

#include <limits>
#include <string>
#include <vector>

#include "spira/path/process_model.h"
#include "spira/path/trajectory.h"

namespace spira {

// The deposit-height window a thickened deposit is checked against (mm): heights within
// [hMin - tolerance, hMax + tolerance] fit, as in checkFeasibility (feasibility.h).
struct DepositWindow {
  double hMin = 0.0;
  double hMax = std::numeric_limits<double>::infinity();
  double tolerance = 0.0;
  bool fits(double height) const { return height >= hMin - tolerance && height <= hMax + tolerance; }
};

// One point the controller slows down at.
struct SlowedPoint {
  size_t point = 0;
  double factor = 1.0;         // planned travel speed / slowed travel speed (> 1)
  double plannedHeight = 0.0;  // mm, the height channel
  double slowedHeight = 0.0;   // mm, the deposit at the slowed travel speed and the planned wire feed
  bool fits = true;            // slowedHeight inside the window
};

// What slowing the travel where the joints cannot keep up does to the deposit.
struct SlowdownReport {
  // "mass_conservation": h = pi d^2 WFS / (4 W TS), so at a constant wire feed the height grows
  // by the slowdown factor; "calibration": the measured height -> travel speed table, read at the
  // travel speed the planned point's WFS / TS ratio stands for, divided by the factor.
  std::string model;
  std::vector<SlowedPoint> points;  // every slowed point, in path order
  size_t outsideWindow = 0;         // slowed points whose thicker deposit leaves the window
  double maxFactor = 1.0;
  size_t maxFactorPoint = 0;
  double maxSlowedHeight = 0.0;  // mm, over the slowed points
  size_t maxSlowedHeightPoint = 0;
  bool fits() const { return outsideWindow == 0; }
};

// A controller that cannot run every axis of a move at the planned speed slows the whole move
// until the fastest axis runs at its limit: the segment into point i then runs at its travel
// speed divided by speedRatio[i] (motion_report.h: the largest |dA/dt| / max speed of its axes).
// The wire feed keeps its setpoint, so the bead there thickens; this derives how much from the
// process model of `process` and checks the thicker deposit against `window`. `speedRatio`:
// one value per point of `path`; values up to 1 leave the point alone.
SlowdownReport slowdownDeposit(const Trajectory& path, const std::vector<double>& speedRatio,
                               const ProcessSettings& process, const DepositWindow& window);

}  // namespace spira
