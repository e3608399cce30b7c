#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Nearest-point queries on a fixed point set through a uniform grid of cubic cells, stored
// densely (at most about 8 cells per point: the cell grows when the requested one would need
// more). Built in O(n); a query near the points costs a few cell look-ups, one far away falls
// back to a linear scan. Ties go to the lowest index, so results do not depend on the cell size.
class PointGrid {
 public:
  // `cellSize` (mm) > 0; about the spacing of the points (or the query distance) works best.
  PointGrid(std::vector<Vec3> points, double cellSize);
  size_t nearest(const Vec3& q) const;
  const std::vector<Vec3>& points() const { return points_; }
  double cellSize() const { return cell_; }

 private:
  Eigen::Vector3i cellOf(const Vec3& p) const;
  size_t bruteForce(const Vec3& q) const;

  std::vector<Vec3> points_;
  double cell_ = 1.0;
  Vec3 origin_;
  Eigen::Vector3i extent_;      // cells per axis
  std::vector<int> cellStart_;  // points of cell i: order_[cellStart_[i] .. cellStart_[i + 1])
  std::vector<int> order_;
};

}  // namespace spira
