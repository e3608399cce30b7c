#pragma once

#include "spira/collision/resolve_settings.h"
#include "spira/collision/torch_collision_checker.h"

namespace spira {

// The tilt magnitude that clears point i when the torch turns about t in direction `sign` (+1 or -1),
// searched from `fromMagnitude` (where the point collides) upwards: increments of the search step
// find the first clear angle, bisection narrows it to the tolerance, and the safety angle is added
// (capped at the maximum tilt). If the angle with safety collides again (clearance is not monotonic
// in the tilt) the scan goes on from there; if no angle with safety is found, the smallest clear
// angle without it is returned. +infinity when nothing up to the maximum tilt clears.
double clearingTilt(const TorchCollisionChecker& checker, size_t i, int sign, double fromMagnitude,
                    const ResolveSettings& settings);

}  // namespace spira
