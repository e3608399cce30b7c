#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/collision/resolve_settings.h"
#include "spira/collision/torch_collision_checker.h"

namespace spira {

// The outcome of torch collision checking and resolution on a plan.
struct CollisionResolution {
  std::vector<unsigned> hits;      // per point: CollisionKind bits of the planned (untilted) torch
  std::vector<double> tiltRad;     // per point: final tilt about t (0 where untouched)
  std::vector<size_t> unresolved;  // points still colliding with their final tilt, ascending
  // The plan with n and b turned by tiltRad about t (t, position and all other channels kept), plus
  // the per-point channel extra["torch_tilt"] (rad).
  Trajectory trajectory;
  size_t collisionCount() const;  // points whose planned torch collides
};

// Detects every point whose planned torch collides and tilts it about t by the smallest clearing
// angle plus the safety angle (both signs searched, the smaller kept). The tilts are then ramped in
// and out so that consecutive points never differ by more than maxTiltChangeRad; ramped neighbours
// are checked again (a ramp may push a clear point into something) and fixed in further passes.
// Tilt signs are compared by the way they lean the torch: where the travel reverses (t and n flip,
// b stays) the same lean is the opposite tilt about t, and the ramp follows the lean. Conflicts
// that pull opposite ways within one ramp all get the lean that clears the most of them.
// `plan` must be the trajectory `checker` was built from (its extra channels are carried over).
CollisionResolution resolveTorchCollisions(const Trajectory& plan, const TorchCollisionChecker& checker,
                                           const ResolveSettings& settings, Progress& progress);

}  // namespace spira
