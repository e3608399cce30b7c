#pragma once

#include <string>

#include "spira/path/joint_trajectory.h"

namespace spira {

// The joint trajectory as CSV, one row per path point (same index as trajectory.csv), header
//   index,q1,q2,q3,q4,q5,q6,e1,e2,config,reachable,dexterity,collision
// Robot joints in degrees in the CONTROLLER's convention; e1/e2 the positioner axes in degrees,
// empty without a positioner; config "S<bits> T<bits>" (KUKA) or the FANUC CONFIG string in
// quotes; reachable and collision 1/0; dexterity the singular-value ratio (0 at a singularity).
std::string jointsCsv(const JointTrajectory& joints);

}  // namespace spira
