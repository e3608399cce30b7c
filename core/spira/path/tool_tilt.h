#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// The source's tilted tool axis (Chalvin, Eq. 2.30-2.32), in its closed form
//   T = (tan(lead) t + tan(side) n + b) / sqrt(1 + tan^2(lead) + tan^2(side)):
// `lead` (theta_n) leans the torch towards the travel direction in the advance plane (t, b), `side`
// (theta_t) towards the surface normal in the normal plane (n, b). Both zero give b. Radians, |angle| < 90
// deg.
Vec3 tiltedToolAxis(const Vec3& t, const Vec3& n, const Vec3& b, double leadRad, double sideRad);

struct TorchTilt {
  double leadRad = 0.0;
  double sideRad = 0.0;
  bool any() const { return leadRad != 0.0 || sideRad != 0.0; }
};

// The channels that keep the build direction b of a path whose torch axis was tilted: a positioner
// holds b, not the torch, vertical, so that each bead is laid flat whatever the torch's angle.
inline constexpr const char* kUpChannels[3] = {"up_x", "up_y", "up_z"};

// The path with every point's torch axis (its `build`) turned by the tilt law, its normal made
// perpendicular again (n = t x T), the tangent and position kept; the untilted b goes into the up
// channels (unless the path already has them). Zero tilt returns the path unchanged.
Trajectory withTorchTilt(const Trajectory& path, const TorchTilt& tilt);

// The build direction a positioner keeps vertical at point i: the up channels where the path has
// them, else the point's build direction (also where they hold zero: the travel moves an exporter
// lays between sub-paths, where no bead is laid).
Vec3 upDirection(const Trajectory& path, size_t i);

}  // namespace spira
