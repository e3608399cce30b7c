#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "real/vec3.h"

namespace spira::test::real {

// Segments binned on a uniform grid by their bounding boxes, so a ball query looks at a few
// cells instead of the whole path. Segments are added one by one (material grows as the path
// is read) and are identified by the caller's ids.
class SegmentGrid {
 public:
  explicit SegmentGrid(double cell) : cell_(cell) {}

  void add(size_t id, const V3& a, const V3& c);

  // Calls f(id) once for every segment whose box touches the cube of half-size `radius` around p.
  template <class F>
  void query(const V3& p, double radius, F&& f)
  {
    ++stamp_;
    const auto lo = cellOf(p - V3(radius, radius, radius));
    const auto hi = cellOf(p + V3(radius, radius, radius));
    for (long x = lo[0]; x <= hi[0]; ++x)
      for (long y = lo[1]; y <= hi[1]; ++y)
        for (long z = lo[2]; z <= hi[2]; ++z) {
          const auto it = cells_.find(key(x, y, z));
          if (it == cells_.end()) continue;
          for (const size_t id : it->second) {
            if (seen_[id] == stamp_) continue;
            seen_[id] = stamp_;
            f(id);
          }
        }
  }

 private:
  using Cell = std::array<long, 3>;
  Cell cellOf(const V3& p) const
  {
    return {static_cast<long>(std::floor(p.x / cell_)), static_cast<long>(std::floor(p.y / cell_)),
            static_cast<long>(std::floor(p.z / cell_))};
  }
  static std::int64_t key(long x, long y, long z)
  {
    // 21 bits a coordinate: a ±10^6-cell range, far more than any part needs.
    const auto k = [](long v) { return static_cast<std::int64_t>(v + (1L << 20)) & ((1LL << 21) - 1); };
    return (k(x) << 42) | (k(y) << 21) | k(z);
  }

  double cell_;
  std::unordered_map<std::int64_t, std::vector<size_t>> cells_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
};

}  // namespace spira::test::real
