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
};

}  // namespace spira
