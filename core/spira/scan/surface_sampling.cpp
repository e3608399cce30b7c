#include <algorithm>
#include <cmath>
#include <random>

#include "spira/base/error.h"
#include "spira/scan/scan_alignment.h"

namespace spira {

PointCloud sampleSurface(const TriangleMesh& mesh, double spacing)
{
  if (!(spacing > 0.0))
    throw InputError("a sampling spacing of " + std::to_string(spacing) + " mm", "give it above 0");
  PointCloud out;
  // A fixed seed: the same part gives the same samples, so alignments repeat exactly.
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell = spacing * spacing;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const Vec3& a = mesh.vertices[size_t(mesh.faces[f][0])];
    const Vec3& b = mesh.vertices[size_t(mesh.faces[f][1])];
    const Vec3& c = mesh.vertices[size_t(mesh.faces[f][2])];
    const Vec3 scaled = (b - a).cross(c - a);
    const double area = 0.5 * scaled.norm();
    if (!(area > 0.0)) continue;
    const Vec3 normal = scaled.normalized();
    const double expected = area / cell;
    size_t n = size_t(std::floor(expected));
    if (unit(random) < expected - double(n)) ++n;
    out.points.push_back((a + b + c) / 3.0);
    out.normals.push_back(normal);
    for (size_t k = 1; k < n; ++k) {
      double u = unit(random), v = unit(random);
      if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
      out.points.push_back(a + u * (b - a) + v * (c - a));
      out.normals.push_back(normal);
    }
  }
  return out;
}

}  // namespace spira
