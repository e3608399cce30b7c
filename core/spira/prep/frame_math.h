#pragma once

#include <Eigen/Geometry>

#include "spira/base/transform.h"
#include "spira/path/trajectory.h"

namespace spira {

// The point's (n, t, b) frame made orthonormal and right-handed (b = n x t) after its vectors were
// interpolated. b, the torch axis, is kept as it is (normalised); t is projected onto the plane
// normal to b; n = t x b. Degenerate input (t along b) falls back to n for the travel direction.
void orthonormaliseFrame(TrajectoryPoint& point);

// The rotation whose columns are n, t, b (the point's frame must be orthonormal), as a quaternion:
// what the robot interpolates between two programmed poses (slerp).
Eigen::Quaterniond frameQuaternion(const TrajectoryPoint& point);

}  // namespace spira
