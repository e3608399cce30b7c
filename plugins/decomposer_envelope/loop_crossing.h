#pragma once

#include <optional>
#include <vector>

#include "projection_axis.h"
#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A point on a free edge with its interpolated unit normal.
struct EdgePoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();
};

// Angles are measured about the axis point at each point's own height, counter-clockwise seen
// from above, from +X. The half-plane of angle theta holds the points p with
// p_xy - axis.at(p.z) along (cos theta, sin theta).

// Where the loop crosses the half-plane of angle `theta`: the outermost crossing (the one an
// envelope point at that angle meets first) when the loop crosses it more than once; nullopt
// when it never does. `vertexNormals` are the mesh's (TriangleMesh::vertexNormals()).
std::optional<EdgePoint> loopCrossing(const TriangleMesh& mesh, const std::vector<Vec3>& vertexNormals,
                                      const BoundaryLoop& loop, const ProjectionAxis& axis, double theta);

// How many times the loop turns about the axis (positive counter-clockwise seen from above).
int loopWinding(const TriangleMesh& mesh, const BoundaryLoop& loop, const ProjectionAxis& axis);

}  // namespace spira
