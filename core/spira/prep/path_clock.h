#pragma once

#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// Time along a trajectory from its per-point travel speed, the speed varying linearly with path
// length between points, so an interval of length L takes L ln(v1 / v0) / (v1 - v0) seconds. Converts
// between the time the robot reaches a place and the path length travelled, which is how a time
// advance becomes a path-synchronised trigger distance.
class PathClock {
 public:
  // Throws InputError when a travel speed is not positive.
  explicit PathClock(const Trajectory& path);

  const std::vector<double>& times() const { return time_; }  // s, 0 at the first point
  const std::vector<double>& arcs() const { return arc_; }    // mm, 0 at the first point
  // Path length travelled at time t, clamped to [0, length].
  double arcAtTime(double t) const;

 private:
  std::vector<double> time_, arc_, speed_;
};

}  // namespace spira
