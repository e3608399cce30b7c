#pragma once

#include <vector>

#include "spira/contour/surface_point.h"
#include "spira/field/mesh_adjacency.h"
#include "spira/mesh/edge_table.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::geodesic {

// The part mesh with the connectivity the geodesic decomposer walks: the face across each
// half-edge, the faces around each vertex, and the vertex normals. Built once per decomposition
// and shared read-only by all threads.
class GeodesicMesh {
 public:
  explicit GeodesicMesh(const TriangleMesh& mesh);

  const TriangleMesh& mesh() const { return mesh_; }
  const MeshAdjacency& adjacency() const { return adjacency_; }
  const std::vector<Vec3>& vertexNormals() const { return vertexNormals_; }
  double meanEdgeLength() const { return meanEdge_; }

  // The face across half-edge h = 3 f + k (from corner k to corner k + 1 of face f), -1 on a free edge.
  int faceAcross(int h) const;
  // The face holding the edge (a, b), -1 if none; meant for free edges, which have one face.
  int faceWithEdge(int a, int b) const;
  // Corners (3 * face + k) around vertex v.
  const int* cornersBegin(int v) const
  {
    return adjacency_.corners.data() + adjacency_.cornerStart[size_t(v)];
  }
  const int* cornersEnd(int v) const
  {
    return adjacency_.corners.data() + adjacency_.cornerStart[size_t(v) + 1];
  }
  bool onBoundary(int v) const { return adjacency_.onBoundary[size_t(v)] != 0; }

  // The surface point of face f at barycentric weights `bary` of its corners.
  SurfacePoint pointOn(int f, const Vec3& bary) const;
  // The unit normal at a combination of vertices (P1 interpolation of the vertex normals).
  Vec3 normalAt(const int* vertices, const Vec3& weights, int count) const;

 private:
  const TriangleMesh& mesh_;
  EdgeTable edges_;
  MeshAdjacency adjacency_;
  std::vector<Vec3> vertexNormals_;
  double meanEdge_ = 0.0;
};

}  // namespace spira::geodesic
