#pragma once

#include <cstdint>
#include <vector>

#include "spira/mesh/big_vector.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/mesh/vertex_corners.h"

namespace spira {

// How the faces around each vertex group into fans. Two faces at a vertex v belong to the same
// fan when they share an edge at v, directly or through other faces of the fan. A manifold
// vertex has one fan; a bow-tie vertex (two cones of faces touching at their tips) has two.
struct VertexFans {
  // Per corner 3 * f + k (vertex faces[f][k] of face f): the smallest corner id of its fan,
  // -1 for left-out faces and faces with a repeated vertex index.
  BigVector<int> fanOfCorner;
  // Per vertex: number of fans (0 for vertices no counted face uses).
  std::vector<int> fanCount;
};

// `useFace`, when given, has one entry per face; faces with 0 are left out, as are faces with a
// repeated vertex index. Face indices must be valid.
VertexFans computeVertexFans(const TriangleMesh& mesh, const std::vector<std::uint8_t>* useFace = nullptr);
// The same from a corner table built earlier (on the same faces or more: `useFace` filters them).
VertexFans computeVertexFans(const TriangleMesh& mesh, const VertexCorners& corners,
                             const std::vector<std::uint8_t>* useFace = nullptr);

}  // namespace spira
