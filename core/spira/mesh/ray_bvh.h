#pragma once

#include <limits>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The first face a ray meets.
struct RayHit {
  int face = -1;  // -1: none within the range
  double distance = std::numeric_limits<double>::infinity();
};

// A bounding-volume hierarchy over a mesh's faces for first-hit ray queries. Kept apart from the
// collision area's BVH (which answers distance queries on convex shapes): a wall-thickness ray
// needs only boxes and triangles, and the mesh area must not depend on collision.
// The mesh must outlive the tree; queries are const and may run in parallel.
class RayBvh {
 public:
  explicit RayBvh(const TriangleMesh& mesh);

  // First face hit by origin + t * direction for minDistance < t <= maxDistance, leaving out
  // `skipFace` (the face the ray starts on). Faces are hit from either side; edges count as inside
  // so a ray through a shared edge is never lost between its two faces.
  RayHit firstHit(const Vec3& origin, const Vec3& direction, double minDistance, double maxDistance,
                  int skipFace = -1) const;

 private:
  struct Node {
    BoundingBox box;
    int first = 0, count = 0;  // leaf: faces order_[first .. first + count); inner: count == 0
    int right = 0;             // inner: the right child (the left one follows the node)
  };
  int build(int first, int count, std::vector<Vec3>& centroids);

  const TriangleMesh& mesh_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace spira
