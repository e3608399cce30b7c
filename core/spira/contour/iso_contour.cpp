#include "spira/contour/iso_contour.h"

#include <algorithm>
#include <string>

#include "spira/base/error.h"

namespace spira {

double IsoContour::length() const
{
  double len = 0.0;
  const size_t m = points.size();
  for (size_t i = 0; i < segmentFaces.size(); ++i)
    len += (points[(i + 1) % m].position - points[i].position).norm();
  return len;
}

std::vector<Vec3> IsoContour::positions() const
{
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(p.position);
  return out;
}

Vec3 IsoContour::barycentricIn(const TriangleMesh& mesh, size_t i, int face) const
{
  const ContourPoint& p = points[i];
  const Face& f = mesh.faces[face];
  Vec3 w = Vec3::Zero();
  auto add = [&](int v, double weight) {
    for (int k = 0; k < 3; ++k) {
      if (f[k] == v) {
        w[k] += weight;
        return;
      }
    }
    throw InternalError("contour point " + std::to_string(i) + " does not lie on face " +
                        std::to_string(face));
  };
  add(p.v0, 1.0 - p.t);
  if (!p.onVertex()) add(p.v1, p.t);
  return w;
}

SurfacePoint IsoContour::surfacePoint(const TriangleMesh& mesh, size_t i) const
{
  const size_t face = i < segmentFaces.size() ? i : segmentFaces.size() - 1;
  SurfacePoint sp;
  sp.position = points[i].position;
  sp.face = segmentFaces[face];
  sp.bary = barycentricIn(mesh, i, sp.face);
  return sp;
}

void IsoContour::reverse()
{
  // Segment i (points[i] -> points[i+1]) becomes the segment leaving the mirrored point of
  // points[i+1]; for a loop the reversed order starts at the same point so that index 0 is kept.
  const size_t m = points.size();
  if (closed) {
    std::vector<ContourPoint> p(m);
    std::vector<int> f(m);
    for (size_t j = 0; j < m; ++j) {
      p[j] = points[(m - j) % m];
      f[j] = segmentFaces[(2 * m - j - 1) % m];
    }
    points.swap(p);
    segmentFaces.swap(f);
  } else {
    std::reverse(points.begin(), points.end());
    std::reverse(segmentFaces.begin(), segmentFaces.end());
  }
}

IsoContour contourFromBoundaryLoop(const TriangleMesh& mesh, const std::vector<int>& loopVertices,
                                   double level, bool meshOnLeft)
{
  const size_t m = loopVertices.size();
  if (m < 3)
    throw InputError("the boundary loop has " + std::to_string(m) + " vertices; a free edge needs at least 3",
                     "repair the mesh so that its free edges are closed loops");
  std::vector<int> posInLoop(mesh.vertexCount(), -1);
  for (size_t i = 0; i < m; ++i) {
    const int v = loopVertices[i];
    if (v < 0 || static_cast<size_t>(v) >= mesh.vertexCount())
      throw InputError("boundary loop vertex " + std::to_string(v) + " is not a mesh vertex",
                       "pass the loops validateMesh extracted from this mesh");
    posInLoop[v] = static_cast<int>(i);
  }
  // Face of loop edge i (loop[i] -> loop[i+1]) and whether the face runs the edge the same way.
  std::vector<int> edgeFace(m, -1);
  size_t alongFaces = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = posInLoop[mesh.faces[f][k]], b = posInLoop[mesh.faces[f][(k + 1) % 3]];
      if (a < 0 || b < 0) continue;
      if (static_cast<size_t>(b) == (a + 1) % m) {
        edgeFace[a] = static_cast<int>(f);
        ++alongFaces;
      } else if (static_cast<size_t>(a) == (b + 1) % m) {
        edgeFace[b] = static_cast<int>(f);
      }
    }
  }
  IsoContour c;
  c.level = level;
  c.closed = true;
  c.points.resize(m);
  c.segmentFaces = edgeFace;
  for (size_t i = 0; i < m; ++i) {
    if (edgeFace[i] < 0)
      throw InputError("boundary loop vertices " + std::to_string(loopVertices[i]) + " and " +
                           std::to_string(loopVertices[(i + 1) % m]) + " share no face",
                       "pass the loops validateMesh extracted from this mesh");
    const int v = loopVertices[i];
    c.points[i] = ContourPoint{mesh.vertices[v], v, v, 0.0};
  }
  // Boundary faces all run the loop's edges one way on a consistently oriented mesh; the
  // majority decides when they do not.
  const bool runsWithFaces = 2 * alongFaces >= m;
  if (runsWithFaces != meshOnLeft) c.reverse();
  return c;
}

}  // namespace spira
