#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/segment_distance.h"
#include "spira/collision/convex_shape.h"

namespace spira::bvh_detail {

// A query shape's bounding capsule (ConvexShape::boundingCapsule) and the cheap distance bounds the
// hierarchies prune with before any GJK. Every bound here is at most the true distance: the shape
// lies inside its capsule, so a node or primitive proven farther than a margin (or than the nearest
// distance found so far) could never have been within it, and a query's answer does not change,
// only its cost. A small slack keeps rounding in the closed forms on the safe side.
struct CapsuleBound {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  double radius = 0.0;
  bool valid = false;

  explicit CapsuleBound(const ConvexShape& shape) { valid = shape.boundingCapsule(a, b, radius); }
};

constexpr double kBoundSlack = 1e-6;  // mm

// Distance between segments [p0, p1] and [q0, q1] (Ericson, Real-Time Collision Detection 5.1.9).
inline double segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1)
{
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 1e-30 && e <= 1e-30) return r.norm();
  if (a <= 1e-30) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-30) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return (p0 + s * d1 - (q0 + t * d2)).norm();
}

// Lower bounds of the distance (mm) from everything in the capsule to a box, to a capsule [q0, q1]
// of radius r and to a sphere, in closed form (no GJK); -infinity without a capsule. They are exact
// only up to rounding: compare them with kBoundSlack to spare.
inline double boxLowerBound(const CapsuleBound& c, const BoundingBox& box)
{
  if (!c.valid) return -std::numeric_limits<double>::infinity();
  return pointSegmentDistance(box.center(), c.a, c.b) - 0.5 * box.size().norm() - c.radius;
}

inline double capsuleLowerBound(const CapsuleBound& c, const Vec3& q0, const Vec3& q1, double r)
{
  if (!c.valid) return -std::numeric_limits<double>::infinity();
  return segmentDistance(c.a, c.b, q0, q1) - c.radius - r;
}

inline double sphereLowerBound(const CapsuleBound& c, const Vec3& center, double r)
{
  if (!c.valid) return -std::numeric_limits<double>::infinity();
  return pointSegmentDistance(center, c.a, c.b) - r - c.radius;
}

// The box is farther than `margin` from everything in the capsule (box centre to the axis, less the
// box's half diagonal and the radius).
inline bool boxBeyond(const CapsuleBound& c, const BoundingBox& box, double margin)
{
  return boxLowerBound(c, box) > margin + kBoundSlack;
}

}  // namespace spira::bvh_detail
