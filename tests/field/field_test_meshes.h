#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira::test {

// Surfaces of revolution about +Z built ring by ring with nearly equilateral triangles (the
// ring vertex count follows the radius), so the accuracy tests measure the method and not
// slivers. Faces are counter-clockwise seen from outside.
struct RingMesh {
  TriangleMesh mesh;
  std::vector<int> lower;  // the bottom ring (z = 0), in order
  std::vector<int> upper;  // the top ring (empty if the top is closed at a pole)
  int pole = -1;           // the top vertex of a closed dome
};

// Open tube of radius r from z = 0 to z = height, mean edge length about `edge`.
RingMesh tubeMesh(double r, double height, double edge);
// Open truncated cone: radius r0 at z = 0, r1 at z = height.
RingMesh coneMesh(double r0, double r1, double height, double edge);
// Hemisphere of radius r centred on the origin, open at z = 0, pole at (0, 0, r).
RingMesh domeMesh(double r, double edge);

// A flat, irregular square [-half, half]^2 in the plane z = 0: a triangular lattice of step
// `edge` whose interior vertices are moved by up to `jitter` * edge in random directions (fixed
// seed). No symmetry for a method to lean on.
TriangleMesh jitteredPlane(double half, double edge, double jitter, unsigned seed);
// domeMesh(r, edge) with every vertex but the rim and the pole moved by up to `jitter` * edge in
// each coordinate and put back on the sphere (fixed seed): irregular triangles on the same surface.
RingMesh jitteredDome(double r, double edge, double jitter, unsigned seed);

struct ErrorStats {
  double mean = 0.0, max = 0.0;
  int count = 0;
};

// Relative error against an exact distance on the vertices farther than `minDistance` from the
// sources (the heat method smooths the distance within a few edges of its sources).
template <typename Exact>
ErrorStats relativeError(const TriangleMesh& mesh, const std::vector<double>& phi, double minDistance,
                         Exact exact)
{
  ErrorStats s;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const double d = exact(mesh.vertices[v]);
    if (d <= minDistance) continue;
    const double e = std::abs(phi[v] - d) / d;
    s.mean += e;
    s.max = std::max(s.max, e);
    ++s.count;
  }
  if (s.count) s.mean /= s.count;
  return s;
}

}  // namespace spira::test
