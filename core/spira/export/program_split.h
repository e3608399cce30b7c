#pragma once

#include <cstddef>
#include <vector>

namespace spira {

// A half-open range [begin, end) of indices.
struct IndexRange {
  size_t begin = 0;
  size_t end = 0;
  size_t size() const { return end - begin; }
  bool operator==(const IndexRange& o) const { return begin == o.begin && end == o.end; }
};

// Cuts [0, count) into the fewest consecutive ranges of at most `maxPerPart` indices, sized as
// evenly as possible (sizes differ by at most one, larger ones first), so no sub-program is left
// with a handful of points. count 0 gives no range; maxPerPart 0 is treated as 1.
std::vector<IndexRange> splitEvenly(size_t count, size_t maxPerPart);

}  // namespace spira
