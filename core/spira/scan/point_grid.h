#pragma once

#include <cstdint>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// Points bucketed in a uniform grid of cubic cells, each cell's points stored together: what lies
// near a line is found among a million points by visiting a few cells instead of every point.
class PointGrid {
 public:
  // `cell` mm. A grid that would need far more cells than points (a stray point metres away) gets
  // larger cells: the queries stay exact, only slower.
  PointGrid(const std::vector<Vec3>& points, double cell);

  // Appends to `out` the indices of the points that may lie within `radius` of the line through
  // `origin` along `axis` (a unit vector), at any distance along it: every point that does, each
  // once, and some that do not (the caller applies its own test). In no particular order.
  void nearLine(const Vec3& origin, const Vec3& axis, double radius, std::vector<std::uint32_t>& out) const;

  double cell() const { return cell_; }

 private:
  Vec3 min_ = Vec3::Zero();
  double cell_ = 1.0;
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<std::uint32_t> start_;  // per cell (x fastest), its first entry in order_; one more at the end
  std::vector<std::uint32_t> order_;  // point indices, cell by cell
};

}  // namespace spira
