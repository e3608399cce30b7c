#include "loop_crossing.h"

#include <cmath>

#include "spira/base/units.h"

namespace spira {

namespace {

Eigen::Vector2d offset(const ProjectionAxis& axis, const Vec3& p)
{
  return Eigen::Vector2d(p.x(), p.y()) - axis.at(p.z());
}

// Signed distance of p from the plane of the half-plane (positive on the counter-clockwise side).
double side(const ProjectionAxis& axis, const Vec3& p, const Eigen::Vector2d& across)
{
  return across.dot(offset(axis, p));
}

}  // namespace

std::optional<EdgePoint> loopCrossing(const TriangleMesh& mesh, const std::vector<Vec3>& vertexNormals,
                                      const BoundaryLoop& loop, const ProjectionAxis& axis, double theta)
{
  const Eigen::Vector2d along(std::cos(theta), std::sin(theta)), across(-std::sin(theta), std::cos(theta));
  const size_t n = loop.vertices.size();
  std::optional<EdgePoint> best;
  double bestReach = -1.0;
  for (size_t i = 0; i < n; ++i) {
    const int ia = loop.vertices[i], ib = loop.vertices[(i + 1) % n];
    const Vec3 &a = mesh.vertices[ia], &b = mesh.vertices[ib];
    double sa = side(axis, a, across), sb = side(axis, b, across);
    if ((sa < 0) == (sb < 0)) continue;
    // The axis point moves with z, so the side is not quite linear along the edge: regula falsi
    // (Illinois variant) pins the crossing down; on a vertical axis the first step is exact.
    double lo = 0.0, hi = 1.0, t = sa / (sa - sb);
    int kept = 0;
    for (int it = 0; it < 60; ++it) {
      t = (lo * sb - hi * sa) / (sb - sa);
      const double st = side(axis, a + t * (b - a), across);
      if (st == 0.0 || axis.isVertical()) break;
      if ((st < 0) == (sa < 0)) {
        lo = t;
        sa = st;
        if (kept == -1) sb *= 0.5;
        kept = -1;
      } else {
        hi = t;
        sb = st;
        if (kept == 1) sa *= 0.5;
        kept = 1;
      }
      if (hi - lo < 1e-12) break;
    }
    const Vec3 p = a + t * (b - a);
    const double reach = along.dot(offset(axis, p));
    if (reach <= 0 || reach <= bestReach)
      continue;  // the opposite half-plane, or hidden behind a farther crossing
    bestReach = reach;
    EdgePoint e;
    e.position = p;
    const Vec3 nrm = (1 - t) * vertexNormals[ia] + t * vertexNormals[ib];
    e.normal = nrm.norm() > 0 ? Vec3(nrm.normalized()) : Vec3(p - axis.pointAt(p.z())).normalized();
    best = e;
  }
  return best;
}

int loopWinding(const TriangleMesh& mesh, const BoundaryLoop& loop, const ProjectionAxis& axis)
{
  double turned = 0.0;
  const size_t n = loop.vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = offset(axis, mesh.vertices[loop.vertices[i]]);
    const Eigen::Vector2d b = offset(axis, mesh.vertices[loop.vertices[(i + 1) % n]]);
    turned += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  return static_cast<int>(std::lround(turned / (2 * kPi)));
}

}  // namespace spira
