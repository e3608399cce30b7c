#include "spira/contour/point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/error.h"

namespace spira {

PointGrid::PointGrid(std::vector<Vec3> points, double cellSize) : points_(std::move(points))
{
  if (points_.empty()) throw InternalError("PointGrid needs at least one point");
  BoundingBox box;
  for (const auto& p : points_) box.extend(p);
  origin_ = box.min;
  const double maxCells = 8.0 * static_cast<double>(points_.size()) + 64.0;
  cell_ = std::max({cellSize, box.size().maxCoeff() / maxCells, 1e-9});
  auto cellsAlong = [&](int a) { return std::floor(box.size()[a] / cell_) + 1.0; };
  while (cellsAlong(0) * cellsAlong(1) * cellsAlong(2) > maxCells) cell_ *= 1.5;
  for (int a = 0; a < 3; ++a) extent_[a] = static_cast<int>(cellsAlong(a));

  // Counting sort of the points by cell.
  const size_t cells = static_cast<size_t>(extent_.prod());
  cellStart_.assign(cells + 1, 0);
  std::vector<int> cellOfPoint(points_.size());
  for (size_t i = 0; i < points_.size(); ++i) {
    const Eigen::Vector3i c = cellOf(points_[i]).cwiseMax(0).cwiseMin(extent_ - Eigen::Vector3i::Ones());
    cellOfPoint[i] = (c.z() * extent_.y() + c.y()) * extent_.x() + c.x();
    ++cellStart_[cellOfPoint[i] + 1];
  }
  for (size_t i = 0; i < cells; ++i) cellStart_[i + 1] += cellStart_[i];
  order_.resize(points_.size());
  std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (size_t i = 0; i < points_.size(); ++i) order_[fill[cellOfPoint[i]]++] = static_cast<int>(i);
}

Eigen::Vector3i PointGrid::cellOf(const Vec3& p) const
{
  // Far-away queries are clamped a little outside the grid: the ring search then hands them to
  // the linear scan.
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) {
    const double x = std::floor((p[a] - origin_[a]) / cell_);
    c[a] = static_cast<int>(std::clamp(x, -1e6, 1e6 + extent_[a]));
  }
  return c;
}

size_t PointGrid::bruteForce(const Vec3& q) const
{
  size_t best = 0;
  double bestD2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < points_.size(); ++i) {
    const double d2 = (points_[i] - q).squaredNorm();
    if (d2 < bestD2) {
      bestD2 = d2;
      best = i;
    }
  }
  return best;
}

size_t PointGrid::nearest(const Vec3& q) const
{
  const Eigen::Vector3i c = cellOf(q);
  double bestD2 = std::numeric_limits<double>::infinity();
  int best = -1;
  auto visit = [&](int x, int y, int z) {
    if (x < 0 || y < 0 || z < 0 || x >= extent_.x() || y >= extent_.y() || z >= extent_.z()) return;
    const int cell = (z * extent_.y() + y) * extent_.x() + x;
    for (int j = cellStart_[cell]; j < cellStart_[cell + 1]; ++j) {
      const int i = order_[j];
      const double d2 = (points_[i] - q).squaredNorm();
      if (d2 < bestD2 || (d2 == bestD2 && i < best)) {
        bestD2 = d2;
        best = i;
      }
    }
  };
  // Rings beyond this one hold no cell of the grid.
  int maxRing = 0;
  for (int a = 0; a < 3; ++a)
    maxRing = std::max({maxRing, std::abs(c[a]), std::abs(c[a] - (extent_[a] - 1))});
  for (int r = 0; r <= maxRing; ++r) {
    // The shell of cells at Chebyshev distance exactly r; a scan is cheaper past some size.
    if (static_cast<double>(r) * r * 24.0 > 4.0 * static_cast<double>(points_.size())) return bruteForce(q);
    for (int dx = -r; dx <= r; ++dx) {
      for (int dy = -r; dy <= r; ++dy) {
        const bool rim = std::abs(dx) == r || std::abs(dy) == r;
        for (int dz = -r; dz <= r; dz += (rim || r == 0) ? 1 : 2 * r)
          visit(c.x() + dx, c.y() + dy, c.z() + dz);
      }
    }
    // Any point not seen yet lies at least r cells away from the query's cell.
    if (best >= 0 && std::sqrt(bestD2) <= r * cell_) break;
  }
  return best >= 0 ? static_cast<size_t>(best) : bruteForce(q);
}

}  // namespace spira
