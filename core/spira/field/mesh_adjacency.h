#pragma once

#include <vector>

#include "spira/field/symmetric_sparse_matrix.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Vertex-to-face and vertex-to-vertex connectivity of a triangle mesh, as flat arrays (CSR), so
// the field solvers can walk a million-face mesh in parallel without per-vertex allocations.
// Faces that repeat a vertex carry no area or edges and are left out.
struct MeshAdjacency {
  // Corners around vertex v: corners[cornerStart[v] .. cornerStart[v+1]), each 3 * face + k
  // where mesh.faces[face][k] == v.
  std::vector<int> cornerStart, corners;
  // Vertices joined to v by an edge, sorted: neighbors[neighborStart[v] .. neighborStart[v+1]).
  std::vector<int> neighborStart, neighbors;
  // 1 if the vertex lies on an edge used by exactly one face (a free edge).
  std::vector<char> onBoundary;
  // Connected component of each vertex (0-based); an isolated vertex is its own component.
  std::vector<int> component;
  int componentCount = 0;

  int vertexCount() const { return int(onBoundary.size()); }
  // The pattern of the lower triangle of any vertex-by-vertex operator on this mesh (values 0).
  SymmetricSparseMatrix lowerPattern() const;
};

// Throws InputError if a face refers to a vertex that does not exist.
MeshAdjacency buildMeshAdjacency(const TriangleMesh& mesh);

}  // namespace spira
