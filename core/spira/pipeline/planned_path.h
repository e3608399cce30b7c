#pragma once

#include <memory>
#include <vector>

#include "spira/document/results.h"

namespace spira {

// The path a planned document hands to export: the kinematics stage's when the plan was solved on
// a cell (its torch tilts clear collisions, so the program must follow it), else the thermal stage's
// re-planned path when it re-planned, else the process stage's.
struct PlannedPath {
  std::shared_ptr<const Trajectory> trajectory;  // null: not planned
  // Per point of `trajectory`: the kinematics stage left it in collision (the program flags it
  // and refuses it unless forced). Empty without that stage.
  std::vector<bool> collision;
};

PlannedPath plannedPathOf(const Results& results);

// The path with its process channels that the views draw and number their points on: the thermal
// stage's re-planned path when it re-planned, else the process stage's (null: not planned).
std::shared_ptr<const Trajectory> processPathOf(const Results& results);

}  // namespace spira
