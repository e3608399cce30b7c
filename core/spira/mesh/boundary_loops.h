#pragma once

#include <vector>

#include "spira/mesh/edge_table.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/mesh/vertex_fans.h"

namespace spira {

// A closed chain of boundary edges, vertices in order (first vertex not repeated at the end).
// The loop runs so that the mesh lies on its left when seen from outside (the direction the
// faces' boundary edges run). For an outward-facing open cylinder around +Z that is
// counter-clockwise seen from above at the base (z = 0) and clockwise at the rim.
struct BoundaryLoop {
  std::vector<int> vertices;
  double length = 0.0;  // mm, including the closing edge when the loop is closed
  double zMin = 0.0, zMax = 0.0;
  // False when the chain could not be closed: that only happens where boundary edges meet at a
  // non-manifold edge or run against each other (inconsistent orientation), which validation
  // reports separately.
  bool closed = true;
};

// Chains the edges that have exactly one face into loops, sorted by zMin ascending.
// At a vertex where several boundary edges meet (a bow-tie), the chain continues along the edge
// of the same fan of faces, so every loop follows one sheet; it never loops forever: every step
// uses up one boundary edge.
std::vector<BoundaryLoop> extractBoundaryLoops(const TriangleMesh& mesh, const EdgeTable& edges,
                                               const VertexFans& fans);

// Centroid of a closed polygon: its edges' midpoints weighted by their lengths, so uneven vertex
// spacing does not pull it sideways (the vertices' mean when it has no length).
Vec3 polygonCentroid(const std::vector<Vec3>& points);

// The centroid of the loop's polygon.
Vec3 loopCentroid(const TriangleMesh& mesh, const BoundaryLoop& loop);

}  // namespace spira
