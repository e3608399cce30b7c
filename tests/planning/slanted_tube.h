#pragma once

#include <cmath>

#include "spira/base/units.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::test {

// An open wall of radius `radius` on z = 0 whose top edge is slanted, z = height + slant cos(a):
// vertical generatrices from height - slant to height + slant long.
inline TriangleMesh slantedTube(double radius, double height, double slant, int segments, int rings)
{
  TriangleMesh m;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * kPi * i / segments;
      const double top = height + slant * std::cos(a);
      m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), top * j / rings);
    }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const int i1 = (i + 1) % segments;
      const int a = j * segments + i, b = j * segments + i1, c = (j + 1) * segments + i1,
                d = (j + 1) * segments + i;
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  return m;
}

}  // namespace spira::test
