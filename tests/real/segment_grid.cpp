#include "real/segment_grid.h"

#include <algorithm>

namespace spira::test::real {

void SegmentGrid::add(size_t id, const V3& a, const V3& c)
{
  if (seen_.size() <= id) seen_.resize(id + 1, 0);
  const V3 lo(std::min(a.x, c.x), std::min(a.y, c.y), std::min(a.z, c.z));
  const V3 hi(std::max(a.x, c.x), std::max(a.y, c.y), std::max(a.z, c.z));
  const auto l = cellOf(lo);
  const auto h = cellOf(hi);
  for (long x = l[0]; x <= h[0]; ++x)
    for (long y = l[1]; y <= h[1]; ++y)
      for (long z = l[2]; z <= h[2]; ++z) cells_[key(x, y, z)].push_back(id);
}

}  // namespace spira::test::real
