#include "spira/collision/capsule_bvh.h"

#include <cmath>

#include "spira/base/error.h"
#include "spira/collision/box_ops.h"
#include "spira/collision/bvh_queries.h"

namespace spira {

namespace {

// The distance from the query shape's bounding capsule to capsule p is at least this.
auto lowerBound(const std::vector<Capsule>& capsules)
{
  return [&capsules](uint32_t p, const bvh_detail::CapsuleBound& bound) {
    const Capsule& c = capsules[p];
    return bvh_detail::capsuleLowerBound(bound, c.a, c.b, c.radius);
  };
}

}  // namespace

CapsuleBvh::CapsuleBvh(std::vector<Capsule> capsules, std::vector<uint32_t> keys)
    : capsules_(std::move(capsules)), keys_(std::move(keys))
{
  if (!keys_.empty() && keys_.size() != capsules_.size())
    throw InternalError("CapsuleBvh: " + std::to_string(keys_.size()) + " keys for " +
                        std::to_string(capsules_.size()) + " capsules");
  std::vector<BoundingBox> boxes;
  boxes.reserve(capsules_.size());
  for (size_t i = 0; i < capsules_.size(); ++i) {
    const Capsule& c = capsules_[i];
    if (!c.a.allFinite() || !c.b.allFinite() || !(c.radius >= 0.0) || !std::isfinite(c.radius))
      throw InputError("deposit segment " + std::to_string(i) + " has a non-finite point or a bad radius",
                       "check the trajectory positions and the bead width");
    BoundingBox box;
    box.extend(c.a);
    box.extend(c.b);
    boxes.push_back(inflated(box, c.radius));
  }
  tree_ = BvhTree(boxes, keys_);
}

bool CapsuleBvh::intersects(const ConvexShape& shape, double margin, uint32_t keyEnd, uint32_t* hint) const
{
  return bvh_detail::anyWithin(
      tree_, shape, margin, keyEnd, [&](uint32_t p) { return key(p); },
      [&](uint32_t p) { return capsules_[p].radius; },
      [&](uint32_t p) { return SegmentShape(capsules_[p].a, capsules_[p].b); }, lowerBound(capsules_), hint);
}

NearestHit CapsuleBvh::nearest(const ConvexShape& shape, uint32_t keyEnd, double maxDistance,
                               double slack) const
{
  return bvh_detail::nearestTo(
      tree_, shape, maxDistance, keyEnd, slack, [&](uint32_t p) { return key(p); },
      [&](uint32_t p) { return capsules_[p].radius; },
      [&](uint32_t p) { return SegmentShape(capsules_[p].a, capsules_[p].b); }, lowerBound(capsules_));
}

std::vector<size_t> CapsuleBvh::within(const ConvexShape& shape, double margin, uint32_t keyEnd) const
{
  return bvh_detail::allWithin(
      tree_, shape, margin, keyEnd, [&](uint32_t p) { return key(p); },
      [&](uint32_t p) { return capsules_[p].radius; },
      [&](uint32_t p) { return SegmentShape(capsules_[p].a, capsules_[p].b); }, lowerBound(capsules_));
}

}  // namespace spira
