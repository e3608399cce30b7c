#include "spira/skeleton/capped_surface.h"

namespace spira {

CappedSurface capBoundaryLoops(const TriangleMesh& mesh, const std::vector<BoundaryLoop>& loops)
{
  CappedSurface out;
  out.mesh = mesh;
  for (const BoundaryLoop& loop : loops) {
    const size_t n = loop.vertices.size();
    if (!loop.closed || n < 3) continue;
    Vec3 centre = Vec3::Zero();
    for (int v : loop.vertices) centre += mesh.vertices[v];
    centre /= static_cast<double>(n);
    const int c = static_cast<int>(out.mesh.vertices.size());
    out.mesh.vertices.push_back(centre);
    // The part's faces run each boundary edge v_i -> v_(i+1); the cap runs it the other way.
    for (size_t i = 0; i < n; ++i)
      out.mesh.faces.push_back({loop.vertices[(i + 1) % n], loop.vertices[i], c});
    ++out.capsAdded;
  }
  return out;
}

}  // namespace spira
