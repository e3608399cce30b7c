#pragma once

#include <algorithm>

#include "spira/base/transform.h"

namespace spira {

// The point of the segment [a, b] nearest to p (a itself when the segment has no length).
inline Vec3 closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// The distance from p to the segment [a, b].
inline double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  return (closestPointOnSegment(p, a, b) - p).norm();
}

}  // namespace spira
