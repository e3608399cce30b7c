#include "spira/verify/segment_grid.h"

#include <algorithm>
#include <cmath>

namespace spira {
namespace {

// 21 bits per axis: cells of 1 mm cover +/- 1 km, far beyond any part.
constexpr int64_t kAxisBits = 21;
constexpr int64_t kAxisOffset = int64_t{1} << (kAxisBits - 1);

int64_t cellIndex(double v, double cell)
{
  const double i = std::floor(v / cell);
  return static_cast<int64_t>(std::clamp(i, -double(kAxisOffset), double(kAxisOffset - 1)));
}

}  // namespace

SegmentGrid::SegmentGrid(const std::vector<Vec3>& points, std::vector<size_t> from, double cell,
                         double margin)
    : cell_(cell), from_(std::move(from))
{
  for (size_t s = 0; s < from_.size(); ++s) {
    const Vec3& a = points[from_[s]];
    const Vec3& c = points[from_[s] + 1];
    const Vec3 lo = a.cwiseMin(c).array() - margin;
    const Vec3 hi = a.cwiseMax(c).array() + margin;
    for (int64_t x = cellIndex(lo.x(), cell_); x <= cellIndex(hi.x(), cell_); ++x)
      for (int64_t y = cellIndex(lo.y(), cell_); y <= cellIndex(hi.y(), cell_); ++y)
        for (int64_t z = cellIndex(lo.z(), cell_); z <= cellIndex(hi.z(), cell_); ++z)
          entries_.emplace_back(key(x, y, z), static_cast<uint32_t>(s));
  }
  std::sort(entries_.begin(), entries_.end());
}

int64_t SegmentGrid::key(int64_t x, int64_t y, int64_t z) const
{
  return ((x + kAxisOffset) << (2 * kAxisBits)) | ((y + kAxisOffset) << kAxisBits) | (z + kAxisOffset);
}

void SegmentGrid::collect(const Vec3& lo, const Vec3& hi, std::vector<uint32_t>& out) const
{
  for (int64_t x = cellIndex(lo.x(), cell_); x <= cellIndex(hi.x(), cell_); ++x)
    for (int64_t y = cellIndex(lo.y(), cell_); y <= cellIndex(hi.y(), cell_); ++y)
      for (int64_t z = cellIndex(lo.z(), cell_); z <= cellIndex(hi.z(), cell_); ++z) {
        const int64_t k = key(x, y, z);
        auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(k, uint32_t{0}));
        for (; it != entries_.end() && it->first == k; ++it) out.push_back(it->second);
      }
}

double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& c)
{
  const Vec3 d = c - a;
  const double len2 = d.squaredNorm();
  const double u = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + u * d - p).norm();
}

}  // namespace spira
