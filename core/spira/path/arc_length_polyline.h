#pragma once

#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// A polyline with per-point unit normals, read by arc length from its first point. Positions are
// interpolated linearly, normals linearly then renormalised, so samples stay on the polyline.
class ArcLengthPolyline {
 public:
  struct Sample {
    Vec3 position;
    Vec3 normal;
  };

  // `normals` has one unit vector per point of `points`; both must outlive this object.
  ArcLengthPolyline(const Polyline& points, const std::vector<Vec3>& normals);

  double length() const { return cumulative_.back(); }
  // The sample at arc length s, clamped to [0, length()].
  Sample at(double s) const;
  // Same, for increasing s along one sweep: `cursor` (start it at 0) remembers the segment reached,
  // so a sweep of m samples costs O(m + points) instead of O(m log points).
  Sample at(double s, size_t& cursor) const;

 private:
  Sample interpolate(size_t k, double s) const;  // on segment [k-1, k]

  const Polyline* points_;
  const std::vector<Vec3>* normals_;
  std::vector<double> cumulative_;  // arc length at each point
};

}  // namespace spira
