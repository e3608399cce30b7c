#pragma once

#include "spira/base/transform.h"

namespace spira {

// Whether two triangles share a point (crossing, touching or overlapping in a common plane).
// Exact up to a relative tolerance of 1e-12 of the triangles' size; a degenerate (zero-area)
// triangle is handled as the segment or point it is.
bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2);

}  // namespace spira
