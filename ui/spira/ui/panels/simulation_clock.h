#pragma once

#include <cstddef>
#include <vector>

namespace spira {
struct Trajectory;
}

namespace spira::ui {

// The time line of a planned path: point i is reached at time(i) (s) when the torch runs each
// segment at the travel speed of its end point (the process channel), or at `fallbackSpeed`
// (mm/s) where the path has no speed. A dwell (path/dwell.h) holds the torch at its point for its wait
// before the next segment. Simulation playback maps wall-clock time through it.
class SimulationClock {
 public:
  explicit SimulationClock(const Trajectory& path, double fallbackSpeed = 8.0);
  SimulationClock() = default;

  size_t size() const { return times_.size(); }
  double duration() const { return times_.empty() ? 0.0 : times_.back(); }
  double time(size_t i) const { return times_.at(i); }
  // The last point reached at time t (clamped to the path).
  size_t indexAt(double t) const;

 private:
  std::vector<double> times_;
};

}  // namespace spira::ui
