#pragma once

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A convex solid known by its support mapping, the form GJK needs: every collision primitive
// (segment core of a capsule, triangle, box, torch) is one, so a single distance routine serves
// them all. Coordinates are in whatever frame the caller uses consistently (mm).
class ConvexShape {
 public:
  virtual ~ConvexShape() = default;
  // A point of the shape farthest along `direction` (any one when several tie; `direction` need
  // not be unit and may be zero).
  virtual Vec3 support(const Vec3& direction) const = 0;
  // A point of the shape, ideally central: GJK starts from it.
  virtual Vec3 anyPoint() const = 0;
  // An axis-aligned box holding the shape (the broad phase).
  virtual BoundingBox bounds() const = 0;
  // A capsule (segment [a, b] inflated by `radius`) holding the shape, when the shape has a tight
  // one: the hierarchies then reject far nodes and primitives without GJK (a long tilted torch has
  // a loose axis-aligned box but a tight capsule). False: none, only bounds() is used.
  virtual bool boundingCapsule(Vec3& /*a*/, Vec3& /*b*/, double& /*radius*/) const { return false; }
};

}  // namespace spira
