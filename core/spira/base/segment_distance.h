#pragma once

#include <algorithm>

#include "spira/base/transform.h"

namespace spira {

// The distance from p to the segment [a, b] (to a itself when the segment has no length).
inline double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace spira
