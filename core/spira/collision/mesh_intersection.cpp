#include "spira/collision/mesh_intersection.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/collision/box_ops.h"
#include "spira/collision/gjk.h"
#include "spira/collision/triangle_intersection.h"

namespace spira {

namespace {

bool pairWithin(const TriangleShape& ta, const TriangleShape& tb, double margin)
{
  if (margin <= 0.0)
    return trianglesIntersect(ta.vertex(0), ta.vertex(1), ta.vertex(2), tb.vertex(0), tb.vertex(1),
                              tb.vertex(2));
  return gjkWithin(ta, tb, margin);
}

TriangleShape carried(const TriangleShape& t, const Transform& T)
{
  return TriangleShape(T * t.vertex(0), T * t.vertex(1), T * t.vertex(2));
}

// Simultaneous descent of both trees in b's frame; `onPair(fa, fb)` returns true to stop.
template <class OnPair>
bool dualSearch(const TriangleBvh& a, const Transform& T_b_a, const TriangleBvh& b, double margin,
                OnPair onPair)
{
  const auto& na = a.tree().nodes();
  const auto& nb = b.tree().nodes();
  if (na.empty() || nb.empty()) return false;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 0u}};
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const auto& nodeA = na[ia];
    const auto& nodeB = nb[ib];
    if (!boxesOverlap(transformedBox(nodeA.box, T_b_a), inflated(nodeB.box, margin))) continue;
    if (nodeA.leaf() && nodeB.leaf()) {
      for (uint32_t i = nodeA.first; i < nodeA.first + nodeA.count; ++i) {
        const uint32_t fa = a.tree().order()[i];
        const TriangleShape ta = carried(a.triangle(fa), T_b_a);
        for (uint32_t j = nodeB.first; j < nodeB.first + nodeB.count; ++j) {
          const uint32_t fb = b.tree().order()[j];
          if (pairWithin(ta, b.triangle(fb), margin) && onPair(fa, fb)) return true;
        }
      }
      continue;
    }
    // Open the bigger box: it is the one that can still be split usefully.
    const bool splitA = nodeB.leaf() || (!nodeA.leaf() && nodeA.box.diagonal() >= nodeB.box.diagonal());
    if (splitA) {
      stack.push_back({nodeA.first, ib});
      stack.push_back({ia + 1, ib});
    } else {
      stack.push_back({ia, nodeB.first});
      stack.push_back({ia, ib + 1});
    }
  }
  return false;
}

}  // namespace

bool meshesIntersect(const TriangleBvh& a, const Transform& T_world_a, const TriangleBvh& b,
                     const Transform& T_world_b, double margin)
{
  const Transform T_b_a = T_world_b.inverse() * T_world_a;
  return dualSearch(a, T_b_a, b, margin, [](uint32_t, uint32_t) { return true; });
}

bool meshIntersects(const TriangleMesh& meshA, const Transform& T_b_a, const TriangleBvh& b, double margin)
{
  const BoundingBox reach = inflated(b.bounds(), margin);
  for (const Face& f : meshA.faces) {
    for (const int v : f)
      if (v < 0 || static_cast<size_t>(v) >= meshA.vertices.size())
        throw InputError("collision mesh face refers to vertex " + std::to_string(v) + " of " +
                             std::to_string(meshA.vertices.size()),
                         "repair or re-export the link mesh");
    const TriangleShape t(T_b_a * meshA.vertices[f[0]], T_b_a * meshA.vertices[f[1]],
                          T_b_a * meshA.vertices[f[2]]);
    const BoundingBox box = t.bounds();
    if (!boxesOverlap(box, reach)) continue;
    const BoundingBox tReach = inflated(box, margin);
    const bool hit =
        b.tree().search([&](const BvhTree::Node& node) { return boxesOverlap(tReach, node.box); },
                        [&](uint32_t fb) { return pairWithin(t, b.triangle(fb), margin); });
    if (hit) return true;
  }
  return false;
}

std::vector<std::pair<size_t, size_t>> intersectingFaces(const TriangleBvh& a, const Transform& T_world_a,
                                                         const TriangleBvh& b, const Transform& T_world_b,
                                                         double margin, size_t maxPairs)
{
  const Transform T_b_a = T_world_b.inverse() * T_world_a;
  std::vector<std::pair<size_t, size_t>> pairs;
  dualSearch(a, T_b_a, b, margin, [&](uint32_t fa, uint32_t fb) {
    pairs.emplace_back(fa, fb);
    return pairs.size() >= maxPairs;
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace spira
