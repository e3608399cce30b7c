#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "spira/collision/basic_shapes.h"
#include "spira/collision/bvh_tree.h"
#include "spira/collision/nearest_hit.h"

namespace spira {

// A capsule: every point within `radius` of the segment [a, b] (a deposited bead segment).
struct Capsule {
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
  double radius = 0.0;
};

// A bounding-volume hierarchy over capsules, each with an integer key (the path segment it was laid
// on). Every query takes `keyEnd` and sees only capsules with key < keyEnd, so one static tree over a
// whole plan answers "what had been deposited before point i" for every i without a rebuild.
class CapsuleBvh {
 public:
  static constexpr uint32_t kAll = std::numeric_limits<uint32_t>::max();

  CapsuleBvh() = default;
  // `keys` is empty (key = index) or one per capsule.
  explicit CapsuleBvh(std::vector<Capsule> capsules, std::vector<uint32_t> keys = {});

  size_t size() const { return capsules_.size(); }
  const Capsule& capsule(size_t i) const { return capsules_[i]; }
  uint32_t key(size_t i) const { return keys_.empty() ? static_cast<uint32_t>(i) : keys_[i]; }
  const BvhTree& tree() const { return tree_; }

  // Whether a visible capsule comes within `margin` mm of the shape. `hint` (optional, start it at
  // kAll) is a capsule to try first and receives the one found; repeated queries about nearly the
  // same shape pass the same hint to skip most of the search. The answer never depends on it.
  bool intersects(const ConvexShape& shape, double margin = 0.0, uint32_t keyEnd = kAll,
                  uint32_t* hint = nullptr) const;
  // The nearest visible capsule no farther than `maxDistance` mm (surface to surface). With `slack` > 0
  // the answer may be up to `slack` mm farther than the true nearest (much faster on near-ties).
  NearestHit nearest(const ConvexShape& shape, uint32_t keyEnd = kAll,
                     double maxDistance = std::numeric_limits<double>::infinity(), double slack = 0.0) const;
  // Every visible capsule within `margin` mm, as sorted capsule indices.
  std::vector<size_t> within(const ConvexShape& shape, double margin, uint32_t keyEnd = kAll) const;

 private:
  std::vector<Capsule> capsules_;
  std::vector<uint32_t> keys_;
  BvhTree tree_;
};

}  // namespace spira
