#include "spira/collision/triangle_intersection.h"

#include <algorithm>
#include <cmath>

#include "spira/collision/basic_shapes.h"
#include "spira/collision/gjk.h"

namespace spira {

namespace {

using Vec2 = Eigen::Vector2d;

double cross2(const Vec2& a, const Vec2& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

// Whether the segment p-q, whose signed distances to the triangle's plane are dp and dq, meets the
// triangle (boundary included). Segments lying in the plane are left to the other edges.
bool edgeMeetsTriangle(const Vec3& p, const Vec3& q, double dp, double dq, const Vec3* t,
                       const Vec3& unitNormal, double eps)
{
  if ((dp > 0.0 && dq > 0.0) || (dp < 0.0 && dq < 0.0) || (dp == 0.0 && dq == 0.0)) return false;
  const Vec3 x = p + dp / (dp - dq) * (q - p);
  for (int k = 0; k < 3; ++k) {
    const Vec3& a = t[k];
    const Vec3& b = t[(k + 1) % 3];
    if (unitNormal.dot((b - a).cross(x - a)) < -eps * (b - a).norm()) return false;
  }
  return true;
}

bool segments2dMeet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s, double eps)
{
  const double d1 = cross2(q - p, r - p), d2 = cross2(q - p, s - p);
  const double d3 = cross2(s - r, p - r), d4 = cross2(s - r, q - r);
  const double e1 = eps * (q - p).norm(), e2 = eps * (s - r).norm();
  if ((d1 > e1 && d2 > e1) || (d1 < -e1 && d2 < -e1)) return false;
  if ((d3 > e2 && d4 > e2) || (d3 < -e2 && d4 < -e2)) return false;
  // Collinear segments: they meet when their projections on the common line overlap.
  if (std::abs(d1) <= e1 && std::abs(d2) <= e1) {
    const Vec2 dir = q - p;
    const double a = 0.0, b = dir.squaredNorm();
    const double c = dir.dot(r - p), d = dir.dot(s - p);
    return std::max(a, std::min(c, d)) <= std::min(b, std::max(c, d)) + eps * std::sqrt(b);
  }
  return true;
}

bool inside2d(const Vec2& x, const Vec2* t, double eps)
{
  const double area = cross2(t[1] - t[0], t[2] - t[0]);
  const double sign = area >= 0.0 ? 1.0 : -1.0;
  for (int k = 0; k < 3; ++k) {
    const Vec2 e = t[(k + 1) % 3] - t[k];
    if (sign * cross2(e, x - t[k]) < -eps * e.norm()) return false;
  }
  return true;
}

bool coplanarOverlap(const Vec3* a, const Vec3* b, const Vec3& normal, double eps)
{
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  Vec2 a2[3], b2[3];
  for (int k = 0; k < 3; ++k) {
    a2[k] = Vec2(a[k][u], a[k][v]);
    b2[k] = Vec2(b[k][u], b[k][v]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments2dMeet(a2[i], a2[(i + 1) % 3], b2[j], b2[(j + 1) % 3], eps)) return true;
  return inside2d(a2[0], b2, eps) || inside2d(b2[0], a2, eps);
}

}  // namespace

bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2)
{
  const Vec3 a[3] = {a0, a1, a2};
  const Vec3 b[3] = {b0, b1, b2};
  double scale = 0.0;
  for (int k = 0; k < 3; ++k)
    scale = std::max({scale, (a[k] - a[(k + 1) % 3]).norm(), (b[k] - b[(k + 1) % 3]).norm()});
  const double eps = 1e-12 * std::max(scale, 1e-300);
  const Vec3 na = (a1 - a0).cross(a2 - a0), nb = (b1 - b0).cross(b2 - b0);
  // A sliver has no reliable plane: GJK treats it as the segment or point it is.
  if (na.norm() <= 1e-9 * scale * scale || nb.norm() <= 1e-9 * scale * scale)
    return gjkWithin(TriangleShape(a0, a1, a2), TriangleShape(b0, b1, b2), 0.0);
  const Vec3 ua = na.normalized(), ub = nb.normalized();
  double db[3], da[3];
  for (int k = 0; k < 3; ++k) {
    db[k] = ua.dot(b[k] - a0);
    da[k] = ub.dot(a[k] - b0);
    if (std::abs(db[k]) <= eps) db[k] = 0.0;
    if (std::abs(da[k]) <= eps) da[k] = 0.0;
  }
  const auto oneSide = [](const double* d) {
    return (d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0) || (d[0] < 0.0 && d[1] < 0.0 && d[2] < 0.0);
  };
  if (oneSide(db) || oneSide(da)) return false;
  if (db[0] == 0.0 && db[1] == 0.0 && db[2] == 0.0) return coplanarOverlap(a, b, ua, eps);
  // Crossing triangles meet along a segment whose ends lie on edges of one or the other.
  for (int k = 0; k < 3; ++k) {
    if (edgeMeetsTriangle(a[k], a[(k + 1) % 3], da[k], da[(k + 1) % 3], b, ub, eps)) return true;
    if (edgeMeetsTriangle(b[k], b[(k + 1) % 3], db[k], db[(k + 1) % 3], a, ua, eps)) return true;
  }
  return false;
}

}  // namespace spira
