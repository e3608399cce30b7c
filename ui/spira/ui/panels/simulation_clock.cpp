#include "spira/ui/panels/simulation_clock.h"

#include <algorithm>

#include "spira/path/dwell.h"
#include "spira/path/trajectory.h"

namespace spira::ui {

SimulationClock::SimulationClock(const Trajectory& path, double fallbackSpeed)
{
  times_.reserve(path.size());
  double t = 0.0;
  for (size_t i = 0; i < path.size(); ++i) {
    if (i > 0) {
      const TrajectoryPoint& p = path.points[i];
      const double speed = p.travelSpeed > 0.0 ? p.travelSpeed : fallbackSpeed;
      t += dwellAt(path, i - 1) + (p.position - path.points[i - 1].position).norm() / speed;
    }
    times_.push_back(t);
  }
}

size_t SimulationClock::indexAt(double t) const
{
  if (times_.empty()) return 0;
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  return it == times_.begin() ? 0 : static_cast<size_t>(it - times_.begin()) - 1;
}

}  // namespace spira::ui
