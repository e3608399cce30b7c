#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "spira/collision/basic_shapes.h"
#include "spira/collision/box_ops.h"
#include "spira/collision/bvh_tree.h"
#include "spira/collision/capsule_bound.h"
#include "spira/collision/gjk.h"
#include "spira/collision/nearest_hit.h"

namespace spira::bvh_detail {

// The three queries every hierarchy answers against a convex shape, shared by the triangle and
// capsule trees. Primitives are reached through `inflation(p)` (the capsule radius, 0 for a
// triangle) and `core(p)` (the convex core, a SegmentShape or TriangleShape); node boxes already
// contain the inflation. Only primitives with key < keyEnd take part.

// Inner nodes are also tested exactly (GJK against the node box): a tilted torch's own box is
// loose, and the exact test prunes most of what the loose one lets through. The shape's bounding
// capsule (capsule_bound.h) first rejects, without GJK, nodes that are clearly beyond the margin.
inline bool nodeWithin(const BvhTree::Node& node, const ConvexShape& shape, const CapsuleBound& capsule,
                       const BoundingBox& reach, double margin, uint32_t keyEnd)
{
  if (node.minKey >= keyEnd || !boxesOverlap(reach, node.box) || boxBeyond(capsule, node.box, margin))
    return false;
  return node.leaf() || gjkWithin(shape, BoxShape(node.box), margin);
}

// `lower(p, capsule)` is a closed-form lower bound of the distance from the shape's bounding capsule
// to primitive p with its inflation (capsule_bound.h; -infinity where it cannot tell): cheaper than
// GJK, it proves p farther than a margin, or unable to beat a nearest distance found so far.
// `hint`, when given, names a primitive to try before the search (kNoHint: none) and receives the
// one found: a caller asking about nearly the same shape again (the torch at a slightly different
// tilt) usually hits the same primitive and skips the search. The answer does not depend on it.
constexpr uint32_t kNoHint = std::numeric_limits<uint32_t>::max();

template <class Keys, class Inflation, class Core, class Lower>
bool anyWithin(const BvhTree& tree, const ConvexShape& shape, double margin, uint32_t keyEnd, Keys key,
               Inflation inflation, Core core, Lower lower, uint32_t* hint = nullptr)
{
  const BoundingBox reach = inflated(shape.bounds(), margin);
  const CapsuleBound capsule(shape);
  const auto within = [&](uint32_t p) {
    if (key(p) >= keyEnd || lower(p, capsule) > margin + kBoundSlack) return false;
    return gjkWithin(shape, core(p), margin + inflation(p));
  };
  if (hint && *hint < tree.order().size() && within(*hint)) return true;
  return tree.search(
      [&](const BvhTree::Node& node) { return nodeWithin(node, shape, capsule, reach, margin, keyEnd); },
      [&](uint32_t p) {
        if (!within(p)) return false;
        if (hint) *hint = p;
        return true;
      });
}

template <class Keys, class Inflation, class Core, class Lower>
std::vector<size_t> allWithin(const BvhTree& tree, const ConvexShape& shape, double margin, uint32_t keyEnd,
                              Keys key, Inflation inflation, Core core, Lower lower)
{
  const BoundingBox reach = inflated(shape.bounds(), margin);
  const CapsuleBound capsule(shape);
  std::vector<size_t> hits;
  tree.search(
      [&](const BvhTree::Node& node) { return nodeWithin(node, shape, capsule, reach, margin, keyEnd); },
      [&](uint32_t p) {
        if (key(p) < keyEnd && !(lower(p, capsule) > margin + kBoundSlack) &&
            gjkWithin(shape, core(p), margin + inflation(p)))
          hits.push_back(p);
        return false;
      });
  std::sort(hits.begin(), hits.end());
  return hits;
}

// Below this fraction of the best distance a box gap counts as loose (see nearestTo; 0.8 was the
// fastest of 0.5..1 on upright and tilted torches over the helix benchmark).
constexpr double kExactBoundBelow = 0.8;

// Branch and bound; `slack` (mm) prunes candidates that could beat the best by less than it, so
// near-ties (a flat nozzle over many nearly equidistant beads) need fewer exact distances.
// The bounding capsule drops, before any GJK, nodes and primitives whose capsule lower bound already
// rules them out: GJK's distance is an upper bound of the exact one, so each of them would have been
// rejected after its GJK anyway, and dropping them changes neither the order of the accepted hits
// nor the answer, only the cost. The capsule only prunes; it never reorders the search (the box gap
// still ranks the children), so the answer stays the same bit for bit.

template <class Keys, class Inflation, class Core, class Lower>
NearestHit nearestTo(const BvhTree& tree, const ConvexShape& shape, double maxDistance, uint32_t keyEnd,
                     double slack, Keys key, Inflation inflation, Core core, Lower lower)
{
  NearestHit hit;
  const BoundingBox shapeBox = shape.bounds();
  const CapsuleBound capsule(shape);
  // A lower bound at or above this cannot give a hit that survives `d + slack >= best`.
  const auto ruledOut = [&](double lowerBound, double bestSoFar) {
    return lowerBound - kBoundSlack + slack >= bestSoFar;
  };
  const double tolerance = std::max(1e-7, 0.1 * slack);
  double best = maxDistance;
  const auto bound = [&](const BvhTree::Node& node) {
    if (node.minKey >= keyEnd) return std::numeric_limits<double>::infinity();
    // The box gap is cheap and, for an upright torch over the part, nearly exact. When it is far below
    // the best distance (a tilted torch's box swallows whole regions), an exact GJK bound against
    // the node box prunes the subtree instead of opening it.
    const double cheap = boxDistance(shapeBox, node.box) + slack;
    if (cheap >= best) return cheap;
    if (ruledOut(boxLowerBound(capsule, node.box), best)) return std::numeric_limits<double>::infinity();
    if (node.leaf() || cheap > kExactBoundBelow * best) return cheap;
    return gjkDistance(shape, BoxShape(node.box), tolerance, best).distance + slack;
  };
  const auto visit = [&](uint32_t p, double& bestSoFar) {
    if (key(p) >= keyEnd || ruledOut(lower(p, capsule), bestSoFar)) return;
    const double r = inflation(p);
    const GjkResult g = gjkDistance(shape, core(p), tolerance, bestSoFar - slack + r);
    const double d = std::max(0.0, g.distance - r);
    if (g.exceeded || d + slack >= bestSoFar) return;
    bestSoFar = d;
    hit.distance = d;
    hit.primitive = p;
    hit.pointOnShape = g.pointA;
    const Vec3 toShape = g.pointA - g.pointB;
    const double gap = toShape.norm();
    hit.pointOnPrimitive = gap > 0.0 ? Vec3(g.pointB + std::min(r, gap) / gap * toShape) : g.pointB;
  };
  tree.nearest(bound, visit, best);
  return hit;
}

}  // namespace spira::bvh_detail
