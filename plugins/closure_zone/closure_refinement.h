#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"
#include "spira/plugin/closure_finder.h"

namespace spira::closure_zone {

// Refines the maximum of a per-vertex field beyond the mesh vertices: a quadratic is fitted by
// least squares to the field over the two rings around `peakVertex` (in the tangent plane of
// the vertex normal), and its stationary point, when it is a maximum inside the faces touching the one-ring,
// is lifted back onto the face that contains it. Falls back to the vertex itself otherwise, so the result is
// never worse than the best vertex. The closure result at a mesh vertex itself (face = one face around it).
ClosureResult atVertex(const TriangleMesh& mesh, const std::vector<double>& field, int vertex);

ClosureResult refineMaximum(const TriangleMesh& mesh, const std::vector<double>& field, int peakVertex);

}  // namespace spira::closure_zone
