#pragma once

#include <array>
#include <optional>
#include <vector>

#include "spira/collision/bvh_tree.h"
#include "spira/contour/surface_point.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Nearest ray-triangle hits against a mesh, through a bounding-volume hierarchy (the thesis
// loops over every triangle per ray, 000_dbb97c2716e10cc3.txt §3.3.2.1 step 2; the hierarchy makes a ray cost
// about log n). It copies the triangles it needs, so the mesh may go away. Reentrant: queries are const.
class RayCaster {
 public:
  explicit RayCaster(const TriangleMesh& mesh);

  // The first face the ray origin + t * direction meets for t in [0, tMax] (direction need not
  // be unit; t is in its units), as a point on the surface with its face and barycentric weights
  // (SurfacePoint's convention). Hits on a shared edge count for either face: a ray never slips
  // between two triangles. nullopt when the ray meets nothing.
  std::optional<SurfacePoint> nearest(const Vec3& origin, const Vec3& direction, double tMax) const;

 private:
  std::vector<std::array<Vec3, 3>> triangles_;  // by face index
  BvhTree tree_;
};

}  // namespace spira
