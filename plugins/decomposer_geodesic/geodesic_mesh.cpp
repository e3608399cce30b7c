#include "geodesic_mesh.h"

namespace spira::geodesic {

GeodesicMesh::GeodesicMesh(const TriangleMesh& mesh)
    : mesh_(mesh),
      edges_(buildEdgeTable(mesh)),
      adjacency_(buildMeshAdjacency(mesh)),
      vertexNormals_(mesh.vertexNormals()),
      meanEdge_(mesh.meanEdgeLength())
{
}

int GeodesicMesh::faceAcross(int h) const
{
  const int e = edges_.edgeOfHalfEdge[size_t(h)];
  if (e < 0 || edges_.faceCountOf(size_t(e)) != 2) return -1;
  const int first = edges_.halfEdges[size_t(edges_.edgeStart[size_t(e)])];
  const int other = first == h ? edges_.halfEdges[size_t(edges_.edgeStart[size_t(e)]) + 1] : first;
  return other / 3;
}

int GeodesicMesh::faceWithEdge(int a, int b) const
{
  for (const int* c = cornersBegin(a); c != cornersEnd(a); ++c) {
    const Face& f = mesh_.faces[size_t(*c / 3)];
    const int k = *c % 3;
    if (f[size_t((k + 1) % 3)] == b || f[size_t((k + 2) % 3)] == b) return *c / 3;
  }
  return -1;
}

SurfacePoint GeodesicMesh::pointOn(int f, const Vec3& bary) const
{
  const Face& fc = mesh_.faces[size_t(f)];
  SurfacePoint p;
  p.face = f;
  p.bary = bary;
  p.position = bary[0] * mesh_.vertices[size_t(fc[0])] + bary[1] * mesh_.vertices[size_t(fc[1])] +
               bary[2] * mesh_.vertices[size_t(fc[2])];
  return p;
}

Vec3 GeodesicMesh::normalAt(const int* vertices, const Vec3& weights, int count) const
{
  Vec3 n = Vec3::Zero();
  for (int i = 0; i < count; ++i)
    if (vertices[i] >= 0) n += weights[i] * vertexNormals_[size_t(vertices[i])];
  const double len = n.norm();
  if (len > 1e-12) return n / len;
  // Opposite normals cancel (a knife edge): any of them is as good.
  for (int i = 0; i < count; ++i)
    if (vertices[i] >= 0 && weights[i] > 0) return vertexNormals_[size_t(vertices[i])];
  return Vec3::UnitZ();
}

}  // namespace spira::geodesic
