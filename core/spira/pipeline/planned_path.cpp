#include "spira/pipeline/planned_path.h"

namespace spira {

PlannedPath plannedPathOf(const Results& results)
{
  PlannedPath p;
  if (!results.kinematics) {
    p.trajectory =
        results.thermal && results.thermal->replanned ? results.thermal->replanned : results.process;
    return p;
  }
  p.trajectory = std::shared_ptr<const Trajectory>(results.kinematics, &results.kinematics->path);
  p.collision.reserve(results.kinematics->checks.size());
  for (const KinematicsCheck& c : results.kinematics->checks) p.collision.push_back(c.collision);
  return p;
}

std::shared_ptr<const Trajectory> processPathOf(const Results& results)
{
  return results.thermal && results.thermal->replanned ? results.thermal->replanned : results.process;
}

}  // namespace spira
