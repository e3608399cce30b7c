#pragma once

#include <cstddef>
#include <limits>

#include "spira/base/transform.h"

namespace spira {

// The answer of a nearest-primitive query against a hierarchy.
struct NearestHit {
  static constexpr size_t npos = static_cast<size_t>(-1);
  double distance = std::numeric_limits<double>::infinity();  // mm, 0 when touching or overlapping
  size_t primitive = npos;  // the nearest primitive's index; npos when none lies within the search radius
  Vec3 pointOnShape = Vec3::Zero();
  Vec3 pointOnPrimitive = Vec3::Zero();
  bool found() const { return primitive != npos; }
};

}  // namespace spira
