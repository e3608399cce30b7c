#include "spira/path/trajectory.h"

namespace spira {

bool TrajectoryPoint::operator==(const TrajectoryPoint& o) const
{
  return position == o.position && normal == o.normal && tangent == o.tangent && build == o.build &&
         path == o.path && revolution == o.revolution && generatrix == o.generatrix && height == o.height &&
         travelSpeed == o.travelSpeed && wireFeed == o.wireFeed && arcOn == o.arcOn;
}

double Trajectory::length() const
{
  double len = 0.0;
  for (size_t i = 1; i < points.size(); ++i) len += (points[i].position - points[i - 1].position).norm();
  return len;
}

}  // namespace spira
