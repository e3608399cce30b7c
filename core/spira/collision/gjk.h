#pragma once

#include <limits>

#include "spira/collision/convex_shape.h"

namespace spira {

// Distance between two convex shapes by the Gilbert-Johnson-Keerthi algorithm. Overlapping or
// touching shapes have distance 0 (there is no penetration depth: the collision resolver only
// needs the yes/no answer, then searches an angle).
struct GjkResult {
  double distance = 0.0;       // mm, 0 when the shapes touch or overlap
  Vec3 pointA = Vec3::Zero();  // closest point on a (witness)
  Vec3 pointB = Vec3::Zero();  // closest point on b
  bool intersecting = false;
  // Stopped early because the distance was proven to exceed `stopAbove`: `distance` is then that
  // proven lower bound and the witnesses are approximate.
  bool exceeded = false;
};

// Exact for polytopes; for curved shapes (the torch) within `tolerance` mm. A finite `stopAbove`
// lets branch-and-bound searches give up on a pair as soon as it cannot beat their best distance.
GjkResult gjkDistance(const ConvexShape& a, const ConvexShape& b, double tolerance = 1e-7,
                      double stopAbove = std::numeric_limits<double>::infinity());

// Whether the shapes come within `margin` mm of each other (touching counts at margin 0). It stops
// as soon as an upper or lower distance bound decides, so it costs a fraction of gjkDistance.
bool gjkWithin(const ConvexShape& a, const ConvexShape& b, double margin);

}  // namespace spira
