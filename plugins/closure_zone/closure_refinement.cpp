#include "closure_refinement.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <Eigen/Dense>

namespace spira::closure_zone {
namespace {

// Faces with at least one vertex in `vertices` (one pass over the mesh: called twice per search).
std::vector<int> facesAround(const TriangleMesh& mesh, const std::set<int>& vertices)
{
  std::vector<int> out;
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f])
      if (vertices.count(v)) {
        out.push_back(static_cast<int>(f));
        break;
      }
  return out;
}

ClosureResult atVertexInRing(const TriangleMesh& mesh, const std::vector<double>& field, int v,
                             const std::vector<int>& ring)
{
  ClosureResult r;
  r.point = mesh.vertices[static_cast<size_t>(v)];
  r.distance = field[static_cast<size_t>(v)];
  for (int f : ring) {
    const Face& face = mesh.faces[static_cast<size_t>(f)];
    for (int k = 0; k < 3; ++k)
      if (face[static_cast<size_t>(k)] == v) {
        r.face = f;
        r.barycentric = Vec3::Zero();
        r.barycentric[k] = 1.0;
        return r;
      }
  }
  return r;
}

// Barycentric coordinates of the 2D point q in the 2D triangle (a, b, c).
Vec3 barycentric2d(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   const Eigen::Vector2d& c)
{
  const Eigen::Vector2d v0 = b - a, v1 = c - a, v2 = q - a;
  const double den = v0.x() * v1.y() - v1.x() * v0.y();
  if (std::abs(den) < 1e-300) return Vec3::Constant(-1.0);
  const double wb = (v2.x() * v1.y() - v1.x() * v2.y()) / den;
  const double wc = (v0.x() * v2.y() - v2.x() * v0.y()) / den;
  return Vec3(1.0 - wb - wc, wb, wc);
}

}  // namespace

ClosureResult atVertex(const TriangleMesh& mesh, const std::vector<double>& field, int vertex)
{
  return atVertexInRing(mesh, field, vertex, facesAround(mesh, {vertex}));
}

ClosureResult refineMaximum(const TriangleMesh& mesh, const std::vector<double>& field, int peakVertex)
{
  const std::set<int> ring0 = {peakVertex};
  const std::vector<int> ring1Faces = facesAround(mesh, ring0);
  std::set<int> ring1 = ring0;
  for (int f : ring1Faces)
    for (int v : mesh.faces[static_cast<size_t>(f)]) ring1.insert(v);
  const std::vector<int> ring2Faces = facesAround(mesh, ring1);
  std::set<int> ring2 = ring1;
  for (int f : ring2Faces)
    for (int v : mesh.faces[static_cast<size_t>(f)]) ring2.insert(v);

  const ClosureResult fallback = atVertexInRing(mesh, field, peakVertex, ring1Faces);
  if (ring2.size() < 6) return fallback;

  // Tangent frame at the peak from the area-weighted normal of its one-ring.
  Vec3 n = Vec3::Zero();
  for (int f : ring1Faces) n += mesh.faceNormalScaled(static_cast<size_t>(f));
  if (n.norm() == 0.0) return fallback;
  n.normalize();
  const Vec3 e1 = n.unitOrthogonal();
  const Vec3 e2 = n.cross(e1);
  const Vec3 origin = mesh.vertices[static_cast<size_t>(peakVertex)];
  auto project = [&](int v) {
    const Vec3 d = mesh.vertices[static_cast<size_t>(v)] - origin;
    return Eigen::Vector2d(d.dot(e1), d.dot(e2));
  };

  // Least-squares quadratic phi(x, y) = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2.
  Eigen::MatrixXd A(static_cast<Eigen::Index>(ring2.size()), 6);
  Eigen::VectorXd b(static_cast<Eigen::Index>(ring2.size()));
  Eigen::Index row = 0;
  double scale = 0.0;
  for (int v : ring2) scale = std::max(scale, project(v).norm());
  if (scale == 0.0) return fallback;
  for (int v : ring2) {
    if (!std::isfinite(field[static_cast<size_t>(v)])) return fallback;
    const Eigen::Vector2d p = project(v) / scale;
    A.row(row) << 1.0, p.x(), p.y(), p.x() * p.x(), p.x() * p.y(), p.y() * p.y();
    b(row) = field[static_cast<size_t>(v)];
    ++row;
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  Eigen::Matrix2d H;
  H << 2.0 * c(3), c(4), c(4), 2.0 * c(5);
  if (!(H.determinant() > 0.0 && H(0, 0) < 0.0)) return fallback;  // not a maximum
  const Eigen::Vector2d peak2 = H.ldlt().solve(-Eigen::Vector2d(c(1), c(2)));
  const Eigen::Vector2d peakMm = peak2 * scale;

  for (int f : ring2Faces) {
    const Face& face = mesh.faces[static_cast<size_t>(f)];
    const Vec3 w = barycentric2d(peakMm, project(face[0]), project(face[1]), project(face[2]));
    if (w.minCoeff() < -1e-12) continue;
    ClosureResult r;
    r.face = f;
    r.barycentric = w.cwiseMax(0.0) / w.cwiseMax(0.0).sum();
    r.point = r.barycentric[0] * mesh.vertices[static_cast<size_t>(face[0])] +
              r.barycentric[1] * mesh.vertices[static_cast<size_t>(face[1])] +
              r.barycentric[2] * mesh.vertices[static_cast<size_t>(face[2])];
    const double fitted = c(0) + c(1) * peak2.x() + c(2) * peak2.y() + c(3) * peak2.x() * peak2.x() +
                          c(4) * peak2.x() * peak2.y() + c(5) * peak2.y() * peak2.y();
    // Never report less than the best vertex: the fit smooths, it must not lower the maximum.
    r.distance = std::max(fitted, fallback.distance);
    return r;
  }
  return fallback;
}

}  // namespace spira::closure_zone
