#include "spira/thermal/thermal_substrate.h"

#include <algorithm>
#include <limits>

namespace spira {

double substratePlaneOf(const Trajectory& t)
{
  double z = std::numeric_limits<double>::infinity();
  for (const TrajectoryPoint& p : t.points) {
    if (p.revolution != t.points.front().revolution || p.path != t.points.front().path) break;
    z = std::min(z, (p.position - p.height * p.build).z());
  }
  return z;
}

}  // namespace spira
