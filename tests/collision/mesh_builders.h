#pragma once

#include "spira/mesh/triangle_mesh.h"

namespace spira::test {

// A closed box mesh (12 outward triangles) with corners lo and hi: an obstacle, a clamp, a post.
inline TriangleMesh boxMesh(const Vec3& lo, const Vec3& hi)
{
  TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

}  // namespace spira::test
