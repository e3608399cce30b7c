#pragma once

#include <vector>

#include <Eigen/Core>

#include "spira/path/trajectory.h"

namespace spira {

// What the envelope points are projected towards: one point per height (thesis 000_dbb97c2716e10cc3.txt
// §3.3.2.1 step 2, "a skeleton point S_i at the same altitude as P_i"). Either a vertical line or a chain of
// points rising in z (a monotone skeleton). Beyond the chain's ends (the skeleton stops short of
// the free edges) it goes on along the direction of its last stretch, when that stretch rises
// steeply enough to say where the axis goes; otherwise it stays at the end point's x, y.
class ProjectionAxis {
 public:
  // The vertical line through `point`.
  static ProjectionAxis vertical(const Vec3& point);
  // The straight line through two points at different heights, extended both ways.
  static ProjectionAxis line(const Vec3& a, const Vec3& b);
  // A chain of at least two points rising in z. Small falls (skeleton noise) are flattened: each
  // point's z is raised to the highest z before it. Throws InputError for fewer than two points or
  // a chain with no rise at all.
  static ProjectionAxis chain(const Polyline& points);

  // x, y of the axis point at height z.
  Eigen::Vector2d at(double z) const;
  Vec3 pointAt(double z) const
  {
    const Eigen::Vector2d p = at(z);
    return Vec3(p.x(), p.y(), z);
  }
  // The points that define the axis (two for a line), z rising.
  const Polyline& points() const { return points_; }
  bool isVertical() const { return vertical_; }

 private:
  Polyline points_;
  Vec3 below_ = Vec3::Zero(), above_ = Vec3::Zero();  // xy change per mm of z beyond each end (z = 0)
  bool vertical_ = false;
};

}  // namespace spira
