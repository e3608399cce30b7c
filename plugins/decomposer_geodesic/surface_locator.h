#pragma once

#include <memory>

#include "spira/contour/surface_point.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::geodesic {

// The closest point of a mesh to any point in space (an AABB tree over the faces), for many
// queries: the coverage check and the projection of fill-in generatrices. Queries are
// thread-safe.
class SurfaceLocator {
 public:
  explicit SurfaceLocator(const TriangleMesh& mesh);
  ~SurfaceLocator();
  SurfaceLocator(const SurfaceLocator&) = delete;
  SurfaceLocator& operator=(const SurfaceLocator&) = delete;

  SurfacePoint closest(const Vec3& q) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spira::geodesic
