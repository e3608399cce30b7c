// The geodesic decomposer on open parts whose geodesics are known in closed form: surfaces that
// unroll into the plane (cylinder, cone), where a geodesic is a straight line of the development.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposer_geodesic/geodesic_decomposition.h"
#include "decomposer_geodesic/submesh_geodesics.h"
#include "geodesic_shapes.h"
#include "spira/base/units.h"
#include "spira/contour/surface_point.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {
namespace {

using geodesic::decomposeByGeodesics;
using geodesic::GeodesicDecomposition;
using geodesic::GeodesicOptions;

GeodesicDecomposition decompose(const Part& part, size_t n, int fillRounds = 6)
{
  GeodesicOptions options;
  options.pointsPerRevolution = n;
  options.fillRounds = fillRounds;
  NullProgress progress;
  const DecomposeInput in = part.input();
  return decomposeByGeodesics(part.mesh, in.lower, in.upper ? &*in.upper : nullptr, std::nullopt, nullptr,
                              options, progress);
}

// Unrolled cone: a point at radius r and angle a lies at slant distance rho = r / sin(h) from the
// apex and development angle a sin(h), h being the half-angle (sin h = (r0 - r1) / slant).
double coneDistance(const Vec3& p, const Vec3& q, double sinHalf)
{
  const double rp = std::hypot(p.x(), p.y()) / sinHalf, rq = std::hypot(q.x(), q.y()) / sinHalf;
  double da = std::remainder(angleOf(p) - angleOf(q), 2.0 * kPi) * sinHalf;
  return std::sqrt(rp * rp + rq * rq - 2.0 * rp * rq * std::cos(da));
}

TEST(GeodesicOpen, CylinderGeneratricesClimbStraightUpFromConstantAngles)
{
  const double R = 30.0, H = 60.0;
  const size_t n = 36;
  const Part part = makePart(makeOpenCylinder(R, H, 128, 40));
  const GeodesicDecomposition d = decompose(part, n);
  const Generatrices& g = d.generatrices;
  ASSERT_EQ(g.lines.size(), n) << "no fill-in is needed: neighbours are 5 degrees apart";
  EXPECT_FALSE(g.hasClosurePoint);
  EXPECT_EQ(d.stats.fillIns, 0u);
  EXPECT_EQ(d.stats.wholeMesh, 0u);
  ASSERT_EQ(g.normals.size(), n);
  for (size_t i = 0; i < n; ++i) {
    SCOPED_TRACE(i);
    const auto& line = g.lines[i];
    ASSERT_EQ(line.size(), g.lines[0].size());
    ASSERT_EQ(g.normals[i].size(), line.size());
    // Constant angle, counter-clockwise seen from above (the lower loop's direction).
    EXPECT_NEAR(angleOf(line.front()), 2.0 * kPi * double(i) / double(n), 1e-9);
    EXPECT_NEAR(line.front().z(), 0.0, 1e-9);
    EXPECT_NEAR(line.back().z(), H, 1e-9);
    EXPECT_NEAR(polylineLength(line), H, 0.002 * H);
    EXPECT_NEAR(d.exactLengths[i], H, 0.002 * H);
    EXPECT_NEAR(angleOf(line.back()), angleOf(line.front()), 1e-3);
    for (size_t k = 0; k < line.size(); ++k) {
      const Vec3 radial = Vec3(line[k].x(), line[k].y(), 0.0).normalized();
      EXPECT_NEAR(g.normals[i][k].norm(), 1.0, 1e-9);
      EXPECT_GT(g.normals[i][k].dot(radial), 0.999);
    }
  }
}

TEST(GeodesicOpen, TruncatedConeGeneratricesAreSlantLines)
{
  const double r0 = 40.0, r1 = 25.0, H = 50.0;
  const double slant = std::hypot(H, r0 - r1);
  const Part part = makePart(makeOpenCone(r0, r1, H, 128, 40));
  const GeodesicDecomposition d = decompose(part, 48);
  ASSERT_EQ(d.generatrices.lines.size(), 48u);
  for (size_t i = 0; i < d.generatrices.lines.size(); ++i) {
    SCOPED_TRACE(i);
    const auto& line = d.generatrices.lines[i];
    EXPECT_NEAR(polylineLength(line), slant, 0.002 * slant);
    EXPECT_NEAR(line.back().z(), H, 1e-9);
    // The exact distance between the generatrix's own ends, on the developed cone.
    const double exact = coneDistance(line.front(), line.back(), (r0 - r1) / slant);
    EXPECT_NEAR(polylineLength(line), exact, 0.005 * exact);
  }
}

// A cylinder cut by a wavy top edge z = H + a cos(alpha): the nearest point of the top edge is
// not straight above, so Eq. 3.7 really is a minimum. Unrolled (s = R alpha, z), the surface is a
// plane strip and the distance from (s0, 0) to the top edge is min over s of the plane distance.
TEST(GeodesicOpen, WavyTopEdgeEndsAtTheNearestPointOfTheUpperEdge)
{
  const double R = 30.0, H = 60.0, a = 15.0;
  auto top = [&](double alpha) { return H + a * std::cos(alpha); };
  const Part part = makePart(makeTube([&](double, double) { return R; }, top, 128, 40));
  ASSERT_EQ(part.report.partClass, PartClass::Open);
  // Geodesics only: where the ends spread, the coverage check would add fill-ins between them.
  const GeodesicDecomposition d = decompose(part, 36, 0);
  ASSERT_EQ(d.generatrices.lines.size(), 36u);
  double largestShift = 0.0;
  for (size_t i = 0; i < 36; ++i) {
    SCOPED_TRACE(i);
    const auto& line = d.generatrices.lines[i];
    const double s0 = R * angleOf(line.front());
    double nearest = 1e300;
    for (int k = -200000; k <= 200000; ++k) {
      const double s = s0 + kPi * R * k / 200000.0;
      nearest = std::min(nearest, std::hypot(s - s0, top(s / R)));
    }
    EXPECT_NEAR(polylineLength(line), nearest, 0.005 * nearest);
    EXPECT_NEAR(d.exactLengths[i], nearest, 0.005 * nearest);
    // The end lies on the upper edge.
    EXPECT_NEAR(line.back().z(), top(angleOf(line.back())), 0.05);
    largestShift = std::max(largestShift,
                            std::abs(std::remainder(angleOf(line.back()) - angleOf(line.front()), 2 * kPi)));
  }
  // Where the edge slopes, the nearest point lies well to the side (about 0.2 rad at 90 degrees).
  EXPECT_GT(largestShift, 0.1);
}

// Independent check with another exact computation: the CGAL distance from the generatrix's END,
// on the whole mesh, back to its base point equals the generatrix length.
TEST(GeodesicOpen, LengthsEqualTheExactDistanceMeasuredFromTheOtherEnd)
{
  const Bump shape{30.0, 5.0, 30.0, 0.5, 14.0};
  auto top = [&](double alpha) { return 60.0 + 8.0 * std::sin(2.0 * alpha); };
  const Part part = makePart(makeTube([&](double al, double z) { return shape.radius(al, z); }, top, 96, 36));
  const GeodesicDecomposition d = decompose(part, 24);
  // Eq. 3.8-3.9: the fill-ins closed every gap between neighbours to under the tolerance.
  EXPECT_LE(d.stats.coverageError, GeodesicOptions().coverageTolerance);
  std::vector<int> all(part.mesh.faceCount());
  for (size_t f = 0; f < all.size(); ++f) all[f] = int(f);
  for (size_t i = 0; i < d.generatrices.lines.size(); i += 6) {
    if (d.fillIn[i]) continue;
    SCOPED_TRACE(i);
    const auto& line = d.generatrices.lines[i];
    const geodesic::SubmeshGeodesics fromEnd(part.mesh, all, closestSurfacePoint(part.mesh, line.back()));
    ASSERT_TRUE(fromEnd.ok());
    const double back = fromEnd.distance(closestSurfacePoint(part.mesh, line.front()));
    EXPECT_NEAR(polylineLength(line), back, 0.005 * back);
    EXPECT_NEAR(d.exactLengths[i], back, 1e-5 * back);
  }
}

}  // namespace
}  // namespace spira::test
