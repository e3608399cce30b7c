#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A bounding-volume hierarchy of axis-aligned boxes over primitives known only by their boxes and
// an integer key. The key lets a query ignore primitives with key >= some end without rebuilding
// (the growing deposit: one tree over the whole path, each query sees only what was laid so far);
// every node keeps the smallest key below it so whole subtrees drop out at once.
class BvhTree {
 public:
  struct Node {
    BoundingBox box;
    uint32_t first = 0;   // leaf: first slot in order(); inner node: index of the right child
    uint32_t count = 0;   // primitives of a leaf; 0 for an inner node (its left child is the next node)
    uint32_t minKey = 0;  // smallest primitive key below this node
    bool leaf() const { return count > 0; }
  };

  BvhTree() = default;
  // `boxes[i]` bounds primitive i; `keys` is empty (key = index) or one per primitive.
  BvhTree(const std::vector<BoundingBox>& boxes, const std::vector<uint32_t>& keys, int leafSize = 4);

  bool empty() const { return nodes_.empty(); }
  const std::vector<Node>& nodes() const { return nodes_; }
  // Primitive indices in leaf order.
  const std::vector<uint32_t>& order() const { return order_; }
  const BoundingBox& bounds() const { return nodes_.front().box; }

  // Depth-first search: opens the nodes `enter(node)` accepts and calls `visit(primitive)` for the
  // primitives of opened leaves; stops and returns true as soon as `visit` returns true.
  template <class Enter, class Visit>
  bool search(Enter&& enter, Visit&& visit) const;

  // Branch and bound for a nearest primitive: `bound(node)` is a lower bound of the distance of
  // anything below the node; `visit(primitive, best)` may lower `best`. Nearer children go first.
  template <class Bound, class Visit>
  void nearest(Bound&& bound, Visit&& visit, double& best) const;

 private:
  uint32_t build(uint32_t begin, uint32_t end, const std::vector<BoundingBox>& boxes,
                 const std::vector<Vec3>& centers, const std::vector<uint32_t>& keys, int leafSize);

  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;
};

template <class Enter, class Visit>
bool BvhTree::search(Enter&& enter, Visit&& visit) const
{
  if (nodes_.empty()) return false;
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!enter(node)) continue;
    if (node.leaf()) {
      for (uint32_t k = node.first; k < node.first + node.count; ++k)
        if (visit(order_[k])) return true;
    } else {
      stack[top++] = node.first;
      stack[top++] = static_cast<uint32_t>(&node - nodes_.data()) + 1;
    }
  }
  return false;
}

template <class Bound, class Visit>
void BvhTree::nearest(Bound&& bound, Visit&& visit, double& best) const
{
  if (nodes_.empty()) return;
  std::pair<uint32_t, double> stack[128];
  int top = 0;
  const double rootBound = bound(nodes_[0]);
  if (rootBound < best) stack[top++] = {0, rootBound};
  while (top > 0) {
    const auto [index, lower] = stack[--top];
    if (lower >= best) continue;
    const Node& node = nodes_[index];
    if (node.leaf()) {
      for (uint32_t k = node.first; k < node.first + node.count; ++k) visit(order_[k], best);
      continue;
    }
    const uint32_t left = index + 1, right = node.first;
    const double bl = bound(nodes_[left]), br = bound(nodes_[right]);
    // Push the farther child first so the nearer one is searched first and tightens `best`.
    if (bl <= br) {
      if (br < best) stack[top++] = {right, br};
      if (bl < best) stack[top++] = {left, bl};
    } else {
      if (bl < best) stack[top++] = {left, bl};
      if (br < best) stack[top++] = {right, br};
    }
  }
}

}  // namespace spira
