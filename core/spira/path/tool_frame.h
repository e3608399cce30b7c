#pragma once

#include "spira/base/transform.h"
#include "spira/path/trajectory.h"

namespace spira {

// The TCP frame at a path point, expressed in the part frame (T_part_tcp):
//   z = -b   the torch axis, pointing from the torch towards the deposit (approach direction);
//   x = t rotated by `spinRad` about z   (spin 0: x along the travel direction);
//   y = z cross x.
// The torch is symmetric about its axis, so `spinRad` is the free (redundant) rotation that the
// kinematics optimise; everything else is fixed by the plan. Degenerate channels (t parallel to b)
// fall back to the surface normal for x.
Transform toolFrame(const TrajectoryPoint& point, double spinRad = 0.0);

}  // namespace spira
