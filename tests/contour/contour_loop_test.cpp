#include <cmath>

#include <gtest/gtest.h>

#include "contour_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/contour/contour_loop.h"
#include "spira/contour/surface_point.h"
#include "spira/mesh/corner_normals.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira {
namespace {

double wrap(double s, double total)
{
  s = std::fmod(s, total);
  return s < 0 ? s + total : s;
}

TEST(ContourLoop, ResampledLoopHasExactlyNPointsEquallySpacedInArcLength)
{
  const double R = 25, H = 40;
  const int N = 72;
  const TriangleMesh mesh = makeOpenCylinder(R, H, N, 10);
  const IsoContour c = extractIsoContour(mesh, test::heightField(mesh), 17.3).contours.at(0);
  const double L = c.length();
  for (size_t n : {3u, 100u, 360u, 1001u}) {
    const ResampledLoop r = resampleLoop(mesh, c, n, 0.0);
    ASSERT_EQ(r.points.size(), n);
    EXPECT_DOUBLE_EQ(r.length, L);
    EXPECT_NEAR((r.points[0].position - c.points[0].position).norm(), 0.0, 1e-12);
    for (size_t k = 0; k < n; ++k) {
      const SurfacePoint& p = r.points[k];
      // On the contour (same height, on the polygon) and in its face.
      EXPECT_NEAR(p.position.z(), 17.3, 1e-9);
      EXPECT_LT(test::distanceToPolygon(p.position, R, N), 1e-9);
      const Face& f = mesh.faces[p.face];
      const Vec3 x =
          p.bary[0] * mesh.vertices[f[0]] + p.bary[1] * mesh.vertices[f[1]] + p.bary[2] * mesh.vertices[f[2]];
      EXPECT_LT((x - p.position).norm(), 1e-9);
      EXPECT_GE(p.bary.minCoeff(), -1e-12);
      // Arc length from the start grows by exactly L / n per point.
      const double s = nearestArcParameter(c, p.position);
      EXPECT_NEAR(wrap(s - L * k / n + 1e-9, L), 1e-9, 1e-8) << "n " << n << " k " << k;
    }
  }
  EXPECT_THROW(resampleLoop(mesh, c, 2), InputError);
}

TEST(ContourLoop, PhaseContinuesThePreviousContour)
{
  const double R = 25, H = 40;
  const TriangleMesh mesh = makeOpenCylinder(R, H, 64, 10);
  const auto levels = extractIsoContours(mesh, test::heightField(mesh), {5.5, 12.1, 30.7});
  // Start the first contour at an arbitrary point, then let each continue the previous.
  ResampledLoop prev = resampleLoop(mesh, levels[0].contours[0], 180, 7.77);
  const Vec3 start = prev.points[0].position;
  for (size_t k = 1; k < levels.size(); ++k) {
    const ResampledLoop r = resampleLoopContinuing(mesh, levels[k].contours[0], 180, prev.points[0].position);
    // Same polygon at another height: every point sits straight above its predecessor.
    for (size_t i = 0; i < r.points.size(); ++i) {
      const Vec3 d = r.points[i].position - prev.points[i].position;
      EXPECT_LT(std::hypot(d.x(), d.y()), 1e-9);
    }
    EXPECT_EQ(nearestIndex(r.points, Vec3(start.x(), start.y(), r.points[0].position.z())), 0u);
    prev = r;
  }
}

TEST(ContourLoop, LengthAndVectorArea)
{
  // Unit square in the plane z = 5, counter-clockwise seen from above.
  const std::vector<Vec3> sq{Vec3(0, 0, 5), Vec3(1, 0, 5), Vec3(1, 1, 5), Vec3(0, 1, 5)};
  EXPECT_DOUBLE_EQ(polylineLength(sq, true), 4.0);
  EXPECT_DOUBLE_EQ(polylineLength(sq, false), 3.0);
  EXPECT_LT((vectorArea(sq) - Vec3(0, 0, 1)).norm(), 1e-15);
  const std::vector<Vec3> rev(sq.rbegin(), sq.rend());
  EXPECT_LT((vectorArea(rev) - Vec3(0, 0, -1)).norm(), 1e-15);
  // Far from the origin, the same.
  std::vector<Vec3> far = sq;
  for (auto& p : far) p += Vec3(1e6, -2e6, 3e5);
  EXPECT_LT((vectorArea(far) - Vec3(0, 0, 1)).norm(), 1e-9);
}

TEST(ContourLoop, OpenContourCannotBeResampled)
{
  const TriangleMesh mesh = test::flatFork();
  std::vector<double> y;
  for (const auto& v : mesh.vertices) y.push_back(v.y());
  const IsoContour c = extractIsoContour(mesh, y, 2.5).contours.at(0);
  EXPECT_THROW(resampleLoop(mesh, c, 10), InputError);
  EXPECT_THROW(nearestArcParameter(c, Vec3::Zero()), InputError);
}

TEST(SurfacePoint, ClosestPointAndNormals)
{
  const double R = 10;
  const TriangleMesh mesh = makeOpenCylinder(R, 20, 32, 4);
  const std::vector<Vec3> vn = cornerNormals(mesh);
  // A point outside, level with a vertex at angle 0: the closest surface point is that vertex.
  const SurfacePoint p = closestSurfacePoint(mesh, Vec3(R + 3, 0, 10));
  EXPECT_LT((p.position - Vec3(R, 0, 10)).norm(), 1e-12);
  EXPECT_LT((surfaceNormalAt(mesh, vn, p) - Vec3(1, 0, 0)).norm(), 1e-9);
  // Between vertices: on the face plane, normal close to radial.
  const double a = 2 * kPi / 64;  // half a segment
  const SurfacePoint q = closestSurfacePoint(mesh, Vec3((R + 1) * std::cos(a), (R + 1) * std::sin(a), 7));
  EXPECT_NEAR(q.position.z(), 7, 1e-9);
  EXPECT_NEAR(std::hypot(q.position.x(), q.position.y()), R * std::cos(kPi / 32), 1e-9);
  const Vec3 n = surfaceNormalAt(mesh, vn, q);
  EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  EXPECT_NEAR(n.dot(Vec3(std::cos(a), std::sin(a), 0)), 1.0, 1e-9);
  std::vector<double> z;
  for (const auto& v : mesh.vertices) z.push_back(v.z());
  EXPECT_NEAR(interpolateAt(mesh, q, z), 7.0, 1e-9);
}

}  // namespace
}  // namespace spira
