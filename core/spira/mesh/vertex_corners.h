#pragma once

#include <cstdint>
#include <vector>

#include "spira/mesh/big_vector.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The corners around each vertex. Corner c = 3 * f + k is vertex faces[f][k] of face f; the
// corners of vertex v are corners[offset[v] .. offset[v + 1]), in increasing order.
// Edge tables, fans and duplicate checks are all built per vertex from this one table.
struct VertexCorners {
  std::vector<int> offset;  // vertexCount + 1 entries
  BigVector<int> corners;
};

// Faces with a repeated vertex index are always left out; so are faces whose `useFace` entry is 0
// when `useFace` is given. Built with a parallel, stable counting sort. Face indices must be valid.
VertexCorners buildVertexCorners(const TriangleMesh& mesh,
                                 const std::vector<std::uint8_t>* useFace = nullptr);

inline bool hasRepeatedIndex(const Face& f)
{
  return f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
}

}  // namespace spira
