#pragma once

#include "spira/collision/convex_shape.h"

namespace spira {

// The small convex primitives the bounding-volume hierarchies hold. A capsule is a SegmentShape
// plus a radius: its distances are the segment's minus the radius, which keeps GJK exact.

class SegmentShape final : public ConvexShape {
 public:
  SegmentShape(const Vec3& a, const Vec3& b) : a_(a), b_(b) {}
  Vec3 support(const Vec3& d) const override { return d.dot(b_ - a_) > 0.0 ? b_ : a_; }
  Vec3 anyPoint() const override { return 0.5 * (a_ + b_); }
  BoundingBox bounds() const override;

 private:
  Vec3 a_, b_;
};

class TriangleShape final : public ConvexShape {
 public:
  TriangleShape(const Vec3& a, const Vec3& b, const Vec3& c) : v_{a, b, c} {}
  Vec3 support(const Vec3& d) const override;
  Vec3 anyPoint() const override { return (v_[0] + v_[1] + v_[2]) / 3.0; }
  BoundingBox bounds() const override;
  const Vec3& vertex(int k) const { return v_[k]; }

 private:
  Vec3 v_[3];
};

// A solid axis-aligned box; the hierarchies use it to bound whole subtrees exactly.
class BoxShape final : public ConvexShape {
 public:
  explicit BoxShape(const BoundingBox& box) : box_(box) {}
  Vec3 support(const Vec3& d) const override
  {
    return Vec3(d.x() > 0.0 ? box_.max.x() : box_.min.x(), d.y() > 0.0 ? box_.max.y() : box_.min.y(),
                d.z() > 0.0 ? box_.max.z() : box_.min.z());
  }
  Vec3 anyPoint() const override { return 0.5 * (box_.min + box_.max); }
  BoundingBox bounds() const override { return box_; }

 private:
  BoundingBox box_;
};

}  // namespace spira
