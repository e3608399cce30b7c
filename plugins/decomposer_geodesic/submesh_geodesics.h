#pragma once

#include <array>
#include <memory>
#include <vector>

#include "spira/contour/surface_point.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::geodesic {

// A point of an exact shortest path and the mesh vertices whose P1 weights give it: one vertex
// (the path passes through it), two (it crosses an edge) or three (the end points, inside a face).
// Unused slots hold vertex -1 and weight 0.
struct PathPoint {
  Vec3 position = Vec3::Zero();
  std::array<int, 3> vertices{-1, -1, -1};
  Vec3 weights = Vec3::Zero();
};

struct ExactPath {
  std::vector<PathPoint> points;     // from the source to the query point
  std::vector<int> throughVertices;  // mesh vertices the path passes through (where it may bend)
  double length = -1.0;              // mm; negative when the query point is not reachable
  bool reached() const { return length >= 0.0; }
};

// Exact shortest paths from one source point over a sub-mesh of a part (CGAL's
// Surface_mesh_shortest_path: Xin & Wang's improvement of the Chen & Han algorithm, the one the
// thesis uses, 000_dbb97c2716e10cc3.txt §3.3.2.2). Paths are exact on the sub-mesh: where the sub-mesh was
// cut out of a larger mesh, a path that passes through a vertex of the cut may be longer than on the whole
// mesh, which the caller checks with `throughVertices`.
//
// Vertices whose angle sum is 2 pi to 1e-6 (every vertex of a developable part: a cylinder, a
// cone) are taken as flat, not as saddles: a geodesic goes straight through them, and CGAL's own
// test, which counts them as saddles and spawns a pseudo-source at each, makes the search about
// 15 times slower on such parts.
//
// The tree is built in the constructor (the long part: roughly 20 microseconds per face); the
// queries are cheap. One object per thread: the queries are not synchronised.
class SubmeshGeodesics {
 public:
  // The sub-mesh of `mesh` made of `faces` (face ids of `mesh`, the source's face among them).
  SubmeshGeodesics(const TriangleMesh& mesh, const std::vector<int>& faces, const SurfacePoint& source);
  ~SubmeshGeodesics();
  SubmeshGeodesics(const SubmeshGeodesics&) = delete;
  SubmeshGeodesics& operator=(const SubmeshGeodesics&) = delete;

  // False when `faces` do not form a manifold surface (they meet at a vertex through several
  // separate fans): the tree is not built, and `nonManifoldVertices()` lists where; adding the
  // faces around those vertices repairs the selection.
  bool ok() const;
  const std::vector<int>& nonManifoldVertices() const;
  size_t faceCount() const;

  // Exact distance (mm) from the source to `p` (a point of a sub-mesh face) or to vertex `v` of
  // `mesh`; negative when not reachable or not in the sub-mesh.
  double distance(const SurfacePoint& p) const;
  double distanceToVertex(int v) const;
  // The shortest path from the source to `p`.
  ExactPath pathTo(const SurfacePoint& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spira::geodesic
