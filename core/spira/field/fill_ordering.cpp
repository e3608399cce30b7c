#include "spira/field/fill_ordering.h"

#include <algorithm>
#include <atomic>
#include <memory>

#include <tbb/parallel_invoke.h>

namespace spira {
namespace {

constexpr int kLeafSize = 32;          // below this, fill inside a part is negligible
constexpr int kParallelGrain = 20000;  // smaller parts are not worth a task

class Dissection {
 public:
  Dissection(const std::vector<Vec3>& points, const MeshAdjacency& adjacency)
      : points_(points), adj_(adjacency), tag_(new std::atomic<int>[points.size()])
  {
    for (size_t v = 0; v < points.size(); ++v) tag_[v].store(0, std::memory_order_relaxed);
  }

  // Orders the vertices in part[0..n) into out[0..n); `part` is used as scratch space.
  void order(int* part, int n, int* out)
  {
    if (n <= kLeafSize) {
      std::copy(part, part + n, out);
      return;
    }
    Vec3 lo = points_[part[0]], hi = lo;
    for (int k = 1; k < n; ++k) {
      lo = lo.cwiseMin(points_[part[k]]);
      hi = hi.cwiseMax(points_[part[k]]);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int half = n / 2;
    std::nth_element(part, part + half, part + n,
                     [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
    const int left = nextTag_.fetch_add(2), right = left + 1;
    for (int k = 0; k < half; ++k) tag_[part[k]].store(left, std::memory_order_relaxed);
    for (int k = half; k < n; ++k) tag_[part[k]].store(right, std::memory_order_relaxed);

    // The smaller of the two one-sided separators (vertices of one side touching the other).
    const int leftTouching = countTouching(part, half, right);
    const int rightTouching = countTouching(part + half, n - half, left);
    const bool cutLeft = leftTouching <= rightTouching;
    int* side = cutLeft ? part : part + half;
    const int sideSize = cutLeft ? half : n - half;
    const int otherTag = cutLeft ? right : left;
    std::vector<int> separator;
    separator.reserve(cutLeft ? leftTouching : rightTouching);
    int kept = 0;
    for (int k = 0; k < sideSize; ++k) {
      const int v = side[k];
      if (touches(v, otherTag))
        separator.push_back(v);
      else
        side[kept++] = v;
    }
    // Compact: [left part][right part] at the front of `part`, separator at the end of `out`.
    int nLeft = half, nRight = n - half;
    if (cutLeft) {
      nLeft = kept;
      std::copy(part + half, part + n, part + nLeft);
    } else {
      nRight = kept;
    }
    const int ns = int(separator.size());
    std::copy(separator.begin(), separator.end(), out + n - ns);
    for (int v : separator)
      tag_[v].store(0, std::memory_order_relaxed);  // separator vertices belong to no part below

    if (n > kParallelGrain) {
      tbb::parallel_invoke([&] { order(part, nLeft, out); },
                           [&] { order(part + nLeft, nRight, out + nLeft); });
    } else {
      order(part, nLeft, out);
      order(part + nLeft, nRight, out + nLeft);
    }
  }

 private:
  bool touches(int v, int tag) const
  {
    for (int e = adj_.neighborStart[v]; e < adj_.neighborStart[v + 1]; ++e)
      if (tag_[adj_.neighbors[e]].load(std::memory_order_relaxed) == tag) return true;
    return false;
  }
  int countTouching(const int* part, int n, int otherTag) const
  {
    int count = 0;
    for (int k = 0; k < n; ++k) count += touches(part[k], otherTag) ? 1 : 0;
    return count;
  }

  const std::vector<Vec3>& points_;
  const MeshAdjacency& adj_;
  // Part label of each vertex. Sibling parts are ordered concurrently and read each other's
  // labels along their common border; labels are unique, so a stale read is harmless, and the
  // atomics make it defined.
  std::unique_ptr<std::atomic<int>[]> tag_;
  std::atomic<int> nextTag_{1};
};

}  // namespace

std::vector<int> geometricNestedDissection(const std::vector<Vec3>& points, const MeshAdjacency& adjacency)
{
  const int n = int(points.size());
  std::vector<int> part(n), order(n);
  for (int v = 0; v < n; ++v) part[v] = v;
  Dissection d(points, adjacency);
  d.order(part.data(), n, order.data());
  return order;
}

}  // namespace spira
