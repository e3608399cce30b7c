#pragma once

#include <set>
#include <vector>

#include "spira/mesh/mesh_report.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::test {

// Three corners per triangle, as an STL file stores them.
inline std::vector<Vec3> soupOf(const TriangleMesh& m)
{
  std::vector<Vec3> corners;
  corners.reserve(3 * m.faceCount());
  for (const Face& f : m.faces)
    for (int v : f) corners.push_back(m.vertices[v]);
  return corners;
}

// Signed volume by the divergence theorem: positive when the faces point outwards.
inline double signedVolume(const TriangleMesh& m)
{
  double v = 0.0;
  for (const Face& f : m.faces) v += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]])) / 6.0;
  return v;
}

// Both meshes in one, without welding.
inline TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh m = a;
  const int offset = static_cast<int>(a.vertexCount());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Face f : b.faces) m.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return m;
}

inline std::set<MeshIssueKind> issueKinds(const MeshReport& r)
{
  std::set<MeshIssueKind> kinds;
  for (const MeshIssue& i : r.issues) kinds.insert(i.kind);
  return kinds;
}

inline Vec3 centroidOf(const TriangleMesh& m, int f)
{
  const Face& t = m.faces[f];
  return (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
}

}  // namespace spira::test
