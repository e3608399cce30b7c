#pragma once

#include <cstdint>
#include <vector>

#include "spira/mesh/big_vector.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The undirected edges of a triangle mesh and the half-edges that use each one.
//
// Half-edge h = 3 * f + k runs from faces[f][k] to faces[f][(k + 1) % 3]. Edges are numbered in
// (lower vertex, higher vertex) order; the half-edges of edge e are
// halfEdges[edgeStart[e] .. edgeStart[e + 1]), in increasing half-edge (and so face) order.
// Built by a parallel radix/counting sort on the lower vertex (vertex_sort.h): O(V + F), no hashing.
struct EdgeTable {
  BigVector<int> halfEdges;
  BigVector<int> edgeStart;       // edgeCount() + 1 entries
  BigVector<int> edgeOfHalfEdge;  // 3 * faceCount entries; -1 for left-out faces

  size_t edgeCount() const { return edgeStart.empty() ? 0 : edgeStart.size() - 1; }
  int faceCountOf(size_t e) const { return edgeStart[e + 1] - edgeStart[e]; }
  int firstHalfEdge(size_t e) const { return halfEdges[edgeStart[e]]; }
};

inline int halfEdgeFrom(const TriangleMesh& m, int h)
{
  return m.faces[h / 3][h % 3];
}
inline int halfEdgeTo(const TriangleMesh& m, int h)
{
  return m.faces[h / 3][(h % 3 + 1) % 3];
}

// `useFace`, when given, has one entry per face; faces with 0 are left out. Faces with a repeated
// vertex index are always left out. Face indices must be valid (validateMesh checks them first).
EdgeTable buildEdgeTable(const TriangleMesh& mesh, const std::vector<std::uint8_t>* useFace = nullptr);

}  // namespace spira
