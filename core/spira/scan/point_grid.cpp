#include "spira/scan/point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/error.h"

namespace spira {
namespace {

// Per axis, so a scan that is long and thin does not make a line query walk a million cells.
constexpr double kMaxCellsPerAxis = 4096.0;

}  // namespace

PointGrid::PointGrid(const std::vector<Vec3>& points, double cell)
{
  if (points.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InputError("a scan of " + std::to_string(points.size()) + " points",
                     "thin it below 4 billion points (scan-compare --voxel)");
  if (!(cell > 0.0)) throw InternalError("a point grid's cell must be positive");
  if (points.empty()) return;
  Vec3 max = points.front();
  min_ = points.front();
  for (const Vec3& p : points) min_ = min_.cwiseMin(p), max = max.cwiseMax(p);
  const Vec3 extent = max - min_;
  if (!std::isfinite(extent.maxCoeff()))
    throw InputError("the scan holds a point at infinity", "remove it from the scan");
  // Room for a few cells per point at most: empty cells cost memory and time to step over.
  const double limit = std::max(4096.0, 2.0 * double(points.size()));
  cell_ = std::max(cell, extent.maxCoeff() / kMaxCellsPerAxis);
  const auto cellsAt = [&](double c) {
    return (std::floor(extent.x() / c) + 1) * (std::floor(extent.y() / c) + 1) *
           (std::floor(extent.z() / c) + 1);
  };
  while (cellsAt(cell_) > limit) cell_ *= std::max(1.01, std::cbrt(cellsAt(cell_) / limit));
  for (int k = 0; k < 3; ++k) dims_[k] = int(std::floor(extent[k] / cell_)) + 1;
  const size_t cells = size_t(dims_.x()) * size_t(dims_.y()) * size_t(dims_.z());
  std::vector<std::uint32_t> of(points.size());
  start_.assign(cells + 1, 0);
  for (size_t i = 0; i < points.size(); ++i) {
    size_t id = 0;
    for (int k = 3; k-- > 0;) {
      const int c = std::min(dims_[k] - 1, int(std::floor((points[i][k] - min_[k]) / cell_)));
      id = id * size_t(dims_[k]) + size_t(std::max(0, c));
    }
    of[i] = std::uint32_t(id);
    ++start_[id + 1];
  }
  for (size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  order_.resize(points.size());
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (size_t i = 0; i < points.size(); ++i) order_[next[of[i]]++] = std::uint32_t(i);
}

void PointGrid::nearLine(const Vec3& origin, const Vec3& axis, double radius,
                         std::vector<std::uint32_t>& out) const
{
  if (order_.empty()) return;
  // A little more than asked: a point exactly at `radius` must not be lost to rounding.
  const double r = radius * (1.0 + 1e-9) + 1e-9;
  const Vec3 lo = min_ - Vec3::Constant(r);
  const Vec3 hi = min_ + cell_ * dims_.cast<double>() + Vec3::Constant(r);
  // The stretch of the line whose points lie within r of the grid, per axis: every point within r of
  // the line has its foot on the line there.
  double s0 = -std::numeric_limits<double>::infinity(), s1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (axis[k] == 0.0) {
      if (origin[k] < lo[k] || origin[k] > hi[k]) return;
      continue;
    }
    double a = (lo[k] - origin[k]) / axis[k], b = (hi[k] - origin[k]) / axis[k];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a), s1 = std::min(s1, b);
  }
  if (!(s0 <= s1)) return;
  // Samples one cell apart along it: each foot lies within half a cell of one, so each point within
  // r of the line lies within `reach` of a sample in every axis.
  const double reach = std::sqrt(r * r + 0.25 * cell_ * cell_) * (1.0 + 1e-9) + 1e-9;
  const size_t samples = size_t(std::ceil((s1 - s0) / cell_)) + 1;
  std::vector<std::uint32_t> cells;
  for (size_t j = 0; j < samples; ++j) {
    const Vec3 c = origin + (s0 + double(j) * cell_) * axis;
    Eigen::Vector3i from, to;
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
      from[k] = std::max(0, int(std::floor((c[k] - reach - min_[k]) / cell_)));
      to[k] = std::min(dims_[k] - 1, int(std::floor((c[k] + reach - min_[k]) / cell_)));
      inside = inside && from[k] <= to[k];
    }
    if (!inside) continue;
    for (int z = from.z(); z <= to.z(); ++z)
      for (int y = from.y(); y <= to.y(); ++y)
        for (int x = from.x(); x <= to.x(); ++x)
          cells.push_back(
              std::uint32_t((size_t(z) * size_t(dims_.y()) + size_t(y)) * size_t(dims_.x()) + size_t(x)));
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  for (std::uint32_t c : cells)
    out.insert(out.end(), order_.begin() + start_[c], order_.begin() + start_[c + 1]);
}

}  // namespace spira
