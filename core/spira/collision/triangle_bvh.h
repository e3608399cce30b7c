#pragma once

#include <array>
#include <limits>
#include <vector>

#include "spira/collision/basic_shapes.h"
#include "spira/collision/bvh_tree.h"
#include "spira/collision/nearest_hit.h"

namespace spira {

// A bounding-volume hierarchy over the triangles of a mesh (the substrate, the table, a positioner,
// a robot link), in the mesh's own frame. Primitive indices are face indices. It copies the
// triangles it needs, so the mesh may go away. Triangles are surfaces: a shape wholly inside a
// closed mesh touches no triangle and is not reported.
class TriangleBvh {
 public:
  explicit TriangleBvh(const TriangleMesh& mesh);

  size_t size() const { return triangles_.size(); }
  TriangleShape triangle(size_t face) const
  {
    const auto& t = triangles_[face];
    return TriangleShape(t[0], t[1], t[2]);
  }
  const BvhTree& tree() const { return tree_; }
  BoundingBox bounds() const { return tree_.empty() ? BoundingBox() : tree_.bounds(); }

  // Whether some triangle comes within `margin` mm of the shape.
  bool intersects(const ConvexShape& shape, double margin = 0.0) const;
  // The nearest triangle no farther than `maxDistance` mm. With `slack` > 0 the answer may be up to
  // `slack` mm farther than the true nearest (near-ties are not all resolved exactly: much faster).
  NearestHit nearest(const ConvexShape& shape, double maxDistance = std::numeric_limits<double>::infinity(),
                     double slack = 0.0) const;
  // Every face within `margin` mm, sorted.
  std::vector<size_t> within(const ConvexShape& shape, double margin) const;

 private:
  std::vector<std::array<Vec3, 3>> triangles_;  // by face index
  BvhTree tree_;
};

}  // namespace spira
