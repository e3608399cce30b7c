#include "spira/collision/basic_shapes.h"

namespace spira {

BoundingBox SegmentShape::bounds() const
{
  BoundingBox box;
  box.extend(a_);
  box.extend(b_);
  return box;
}

Vec3 TriangleShape::support(const Vec3& d) const
{
  const double d0 = d.dot(v_[0]), d1 = d.dot(v_[1]), d2 = d.dot(v_[2]);
  if (d0 >= d1 && d0 >= d2) return v_[0];
  return d1 >= d2 ? v_[1] : v_[2];
}

BoundingBox TriangleShape::bounds() const
{
  BoundingBox box;
  for (const Vec3& v : v_) box.extend(v);
  return box;
}

}  // namespace spira
