#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// The point with its torch turned by `angleRad` about the travel direction t, right-handed about t:
//   b' = cos(angle) b + sin(angle) (t x b) = cos(angle) b + sin(angle) n,   n' = t x b',
// so (n', t, b') stays orthonormal with b' = n' x t (t and b are first made exactly orthonormal).
// A positive angle swings the torch axis towards +n (for an outward normal: away from the part's
// inside). Position and every other channel are kept;
// angle 0 returns the point unchanged. A point whose t is zero or along b is returned unchanged.
TrajectoryPoint tiltAboutTangent(const TrajectoryPoint& point, double angleRad);

}  // namespace spira
