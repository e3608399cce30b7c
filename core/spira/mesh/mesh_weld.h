#pragma once

#include <cstddef>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Default welding tolerance, relative to the bounding-box diagonal.
constexpr double kDefaultWeldTolerance = 1e-7;

struct WeldStats {
  size_t inputVertices = 0;
  size_t outputVertices = 0;
  size_t removedUnreferenced = 0;
  double tolerance = 0.0;  // absolute, mm
};

// Merges vertices closer than `relativeTolerance` * bounding-box diagonal (the diagonal taken at most
// 1e4 median edge lengths, so one stray far vertex cannot weld whole triangles), transitively, and
// drops vertices no face uses. Faces keep their order and orientation; faces that become
// degenerate are kept (validation reports them), so nothing is silently thrown away.
TriangleMesh weldVertices(const TriangleMesh& mesh, double relativeTolerance = kDefaultWeldTolerance,
                          WeldStats* stats = nullptr);

// Same, starting from a triangle soup: corners[3*i + k] is corner k of triangle i.
TriangleMesh weldTriangleSoup(const std::vector<Vec3>& corners,
                              double relativeTolerance = kDefaultWeldTolerance, WeldStats* stats = nullptr);

}  // namespace spira
