#include "spira/contour/surface_point.h"

#include <limits>

namespace spira {

namespace {

// Closest point of triangle (a, b, c) to p, as barycentric weights (Ericson, Real-Time
// Collision Detection, 5.1.5): the Voronoi regions of the corners, then the edges, then inside.
Vec3 closestBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return Vec3(1, 0, 0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return Vec3(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return Vec3(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return Vec3(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return Vec3(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return Vec3(0, 1 - w, w);
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) return Vec3(1, 0, 0);  // zero-area face: any corner is as close as the face
  const double v = vb / denom, w = vc / denom;
  return Vec3(1 - v - w, v, w);
}

}  // namespace

double interpolateAt(const TriangleMesh& mesh, const SurfacePoint& p, const std::vector<double>& values)
{
  const Face& f = mesh.faces[p.face];
  return p.bary[0] * values[f[0]] + p.bary[1] * values[f[1]] + p.bary[2] * values[f[2]];
}

Vec3 interpolateAt(const TriangleMesh& mesh, const SurfacePoint& p, const std::vector<Vec3>& values)
{
  const Face& f = mesh.faces[p.face];
  return p.bary[0] * values[f[0]] + p.bary[1] * values[f[1]] + p.bary[2] * values[f[2]];
}

Vec3 surfaceNormalAt(const TriangleMesh& mesh, const std::vector<Vec3>& cornerNormals, const SurfacePoint& p)
{
  const size_t c = 3 * static_cast<size_t>(p.face);
  const Vec3 n =
      p.bary[0] * cornerNormals[c] + p.bary[1] * cornerNormals[c + 1] + p.bary[2] * cornerNormals[c + 2];
  const double len = n.norm();
  if (len > 1e-9) return n / len;
  return mesh.faceNormal(p.face);
}

SurfacePoint closestPointOnFace(const TriangleMesh& mesh, int face, const Vec3& q)
{
  const Face& fc = mesh.faces[size_t(face)];
  const Vec3 w = closestBarycentric(q, mesh.vertices[size_t(fc[0])], mesh.vertices[size_t(fc[1])],
                                    mesh.vertices[size_t(fc[2])]);
  return {w[0] * mesh.vertices[size_t(fc[0])] + w[1] * mesh.vertices[size_t(fc[1])] +
              w[2] * mesh.vertices[size_t(fc[2])],
          face, w};
}

SurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Vec3& q)
{
  SurfacePoint best;
  double bestD2 = std::numeric_limits<double>::infinity();
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& fc = mesh.faces[f];
    const Vec3& a = mesh.vertices[fc[0]];
    const Vec3& b = mesh.vertices[fc[1]];
    const Vec3& c = mesh.vertices[fc[2]];
    const Vec3 w = closestBarycentric(q, a, b, c);
    const Vec3 x = w[0] * a + w[1] * b + w[2] * c;
    const double d2 = (x - q).squaredNorm();
    if (d2 < bestD2) {
      bestD2 = d2;
      best.position = x;
      best.face = static_cast<int>(f);
      best.bary = w;
    }
  }
  return best;
}

}  // namespace spira
