#include "spira/collision/bvh_tree.h"

#include <algorithm>
#include <numeric>

#include "spira/base/error.h"
#include "spira/collision/box_ops.h"

namespace spira {

BvhTree::BvhTree(const std::vector<BoundingBox>& boxes, const std::vector<uint32_t>& keys, int leafSize)
{
  if (!keys.empty() && keys.size() != boxes.size())
    throw InternalError("BvhTree: " + std::to_string(keys.size()) + " keys for " +
                        std::to_string(boxes.size()) + " primitives");
  if (boxes.size() >= std::numeric_limits<uint32_t>::max())
    throw InputError("too many collision primitives (" + std::to_string(boxes.size()) + ")",
                     "split the path or the mesh");
  if (boxes.empty()) return;
  std::vector<Vec3> centers(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centers[i] = boxes[i].center();
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * boxes.size() / std::max(1, leafSize) + 1);
  build(0, static_cast<uint32_t>(boxes.size()), boxes, centers, keys, std::max(1, leafSize));
}

uint32_t BvhTree::build(uint32_t begin, uint32_t end, const std::vector<BoundingBox>& boxes,
                        const std::vector<Vec3>& centers, const std::vector<uint32_t>& keys, int leafSize)
{
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  BoundingBox box, centerBox;
  uint32_t minKey = std::numeric_limits<uint32_t>::max();
  for (uint32_t k = begin; k < end; ++k) {
    const uint32_t p = order_[k];
    box = merged(box, boxes[p]);
    centerBox.extend(centers[p]);
    minKey = std::min(minKey, keys.empty() ? p : keys[p]);
  }
  nodes_[index].box = box;
  nodes_[index].minKey = minKey;
  if (end - begin <= static_cast<uint32_t>(leafSize)) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Median split on the widest axis of the centres: balanced, so the depth stays near log2(n).
  int axis = 0;
  centerBox.size().maxCoeff(&axis);
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centers[a][axis] < centers[b][axis]; });
  build(begin, mid, boxes, centers, keys, leafSize);
  const uint32_t right = build(mid, end, boxes, centers, keys, leafSize);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

}  // namespace spira
