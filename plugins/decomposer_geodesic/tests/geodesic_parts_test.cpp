// The pieces of the geodesic decomposer on meshes whose answers are known exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposer_geodesic/base_ring.h"
#include "decomposer_geodesic/corridor.h"
#include "decomposer_geodesic/generatrix_solver.h"
#include "decomposer_geodesic/submesh_geodesics.h"
#include "decomposer_geodesic/surface_locator.h"
#include "geodesic_shapes.h"
#include "spira/base/units.h"
#include "spira/contour/surface_point.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {
namespace {

using namespace spira::geodesic;

// A flat square grid in z = 0: cells x cells squares of `size` mm, each split in two.
TriangleMesh flatGrid(int cells, double size)
{
  TriangleMesh m;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) m.vertices.emplace_back(i * size, j * size, 0.0);
  auto id = [&](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

std::vector<int> allFaces(const TriangleMesh& m)
{
  std::vector<int> f(m.faceCount());
  for (size_t i = 0; i < f.size(); ++i) f[i] = int(i);
  return f;
}

TEST(SubmeshGeodesics, FlatGridDistancesAreEuclideanAndPathsStraight)
{
  const TriangleMesh grid = flatGrid(20, 5.0);
  const Vec3 source(23.3, 41.7, 0.0);
  const SubmeshGeodesics geo(grid, allFaces(grid), closestSurfacePoint(grid, source));
  ASSERT_TRUE(geo.ok());
  for (int v : {0, 20, 220, 440, 137})
    EXPECT_NEAR(geo.distanceToVertex(v), (grid.vertices[size_t(v)] - source).norm(), 1e-9);
  const Vec3 target(91.2, 3.4, 0.0);
  const ExactPath path = geo.pathTo(closestSurfacePoint(grid, target));
  ASSERT_TRUE(path.reached());
  EXPECT_NEAR(path.length, (target - source).norm(), 1e-9);
  ASSERT_GE(path.points.size(), 2u);
  EXPECT_LT((path.points.front().position - source).norm(), 1e-9);
  EXPECT_LT((path.points.back().position - target).norm(), 1e-9);
  const Vec3 dir = (target - source).normalized();
  for (const PathPoint& p : path.points) {
    EXPECT_LT((p.position - source).cross(dir).norm(), 1e-9) << "off the straight line";
    Vec3 fromWeights = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      if (p.vertices[size_t(k)] >= 0)
        fromWeights += p.weights[k] * grid.vertices[size_t(p.vertices[size_t(k)])];
    EXPECT_LT((fromWeights - p.position).norm(), 1e-9);
  }
}

// On a cylinder (every vertex flat), distances equal the unrolled plane's, and a band around the
// straight path gives the same answer as the whole mesh.
TEST(SubmeshGeodesics, CylinderMatchesTheDevelopmentAndBandsMatchTheWholeMesh)
{
  const double R = 20.0;
  const TriangleMesh tube = makeOpenCylinder(R, 40.0, 64, 20);
  // From the first base vertex to the top vertex 8 segments round: on the unrolled 64-gon prism,
  // 8 chords across and 40 mm up.
  const Vec3 a(R, 0.0, 0.0);
  const Vec3 b(R * std::cos(kPi / 4.0), R * std::sin(kPi / 4.0), 40.0);
  const SurfacePoint sa = closestSurfacePoint(tube, a), sb = closestSurfacePoint(tube, b);
  const SubmeshGeodesics whole(tube, allFaces(tube), sa);
  const double polygonArc = 8.0 * 2.0 * R * std::sin(kPi / 64);
  EXPECT_NEAR(whole.distance(sb), std::hypot(40.0, polygonArc), 1e-9);

  const GeodesicMesh gm(tube);
  Corridor band(gm);
  const ExactPath path = whole.pathTo(sb);
  std::vector<int> seed;
  for (const PathPoint& p : path.points) seed.push_back(closestSurfacePoint(tube, p.position).face);
  band.build(seed, 1);
  EXPECT_LT(band.faces().size(), tube.faceCount() / 4);
  const SubmeshGeodesics narrow(tube, band.faces(), sa);
  ASSERT_TRUE(narrow.ok());
  EXPECT_NEAR(narrow.distance(sb), whole.distance(sb), 1e-9);
}

TEST(Corridor, ClosesPinchedFansAndKnowsWhereItWasCut)
{
  const TriangleMesh grid = flatGrid(6, 1.0);
  const GeodesicMesh gm(grid);
  // Faces touching vertex (3,3) = 24 only through that vertex: south-west and north-east cells.
  const int centre = 3 * 7 + 3;
  std::vector<int> seed;
  for (const int* c = gm.cornersBegin(centre); c != gm.cornersEnd(centre); ++c) {
    const Face& f = grid.faces[size_t(*c / 3)];
    Vec3 mid =
        (grid.vertices[size_t(f[0])] + grid.vertices[size_t(f[1])] + grid.vertices[size_t(f[2])]) / 3.0;
    if ((mid.x() < 3 && mid.y() < 3) || (mid.x() > 3 && mid.y() > 3)) seed.push_back(*c / 3);
  }
  ASSERT_EQ(seed.size(), 4u);  // two faces south-west of the centre, two north-east
  Corridor band(gm);
  band.build(seed, 0);
  EXPECT_EQ(band.faces().size(), 6u) << "the whole star of the pinched vertex";
  EXPECT_FALSE(band.isCut(centre));
  for (int v : band.vertices()) {
    if (v != centre) {
      EXPECT_TRUE(band.isCut(v)) << v;
    }
  }
  band.buildWholeMesh();
  EXPECT_EQ(band.faces().size(), grid.faceCount());
  EXPECT_FALSE(band.isCut(centre));
}

// The guide only chooses where to look: a guide that leads nowhere (a field that falls towards the
// base) or astray (one that drifts sideways) costs wider bands, never a wrong generatrix.
TEST(GeneratrixSolver, AMisleadingGuideStillGivesTheExactGeodesic)
{
  const double R = 20.0, H = 40.0;
  const Part part = makePart(makeOpenCylinder(R, H, 64, 20));
  const GeodesicMesh gm(part.mesh);
  GeodesicTarget target;
  target.upper = &part.report.boundaryLoops[1];
  target.upperIndex.assign(part.mesh.vertexCount(), -1);
  target.upperVertex.assign(part.mesh.vertexCount(), 0);
  for (size_t i = 0; i < target.upper->vertices.size(); ++i) {
    target.upperIndex[size_t(target.upper->vertices[i])] = int(i);
    target.upperVertex[size_t(target.upper->vertices[i])] = 1;
  }
  const BaseRing ring(gm, part.report.boundaryLoops[0]);
  const BasePoint base = *ring.at(0.3);
  std::vector<double> downhill, sideways;
  for (const Vec3& v : part.mesh.vertices) {
    downhill.push_back(v.z());                    // lowest on the base: the trace cannot leave it
    sideways.push_back(H - v.z() + 0.6 * v.y());  // drifts round the tube on the way up
  }
  Corridor band(gm);
  NullProgress progress;
  for (const auto* guide : {&downhill, &sideways}) {
    const GeneratrixSolver solver(gm, *guide, target);
    const SolvedGeneratrix s = solver.solve(base.point, band, progress);
    EXPECT_NEAR(s.path.length, H, 1e-7);
    EXPECT_NEAR(s.end.position.z(), H, 1e-9);
    EXPECT_NEAR(angleOf(s.end.position), 0.3, 1e-6);
    EXPECT_TRUE(s.rings > 1 || s.rings < 0) << "the first band cannot have held the answer";
  }
}

TEST(BaseRing, ConstantAnglesAroundTheCentroidInTheLoopsDirection)
{
  // An off-centre circle: the axis goes through its centroid, not the origin.
  TriangleMesh tube = makeOpenCylinder(25.0, 10.0, 90, 2);
  for (Vec3& v : tube.vertices) v += Vec3(7.0, -3.0, 0.0);
  const Part part = makePart(tube);
  const GeodesicMesh gm(part.mesh);
  const BaseRing ring(gm, part.report.boundaryLoops[0]);
  EXPECT_LT((ring.centroid() - Vec3(7.0, -3.0, 0.0)).head<2>().norm(), 1e-9);
  EXPECT_TRUE(ring.counterClockwise());
  size_t ambiguous = 7;
  const std::vector<BasePoint> points = ring.discretise(24, &ambiguous);
  EXPECT_EQ(ambiguous, 0u);
  ASSERT_EQ(points.size(), 24u);
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 d = points[i].point.position - ring.centroid();
    EXPECT_NEAR(angleOf(d), 2.0 * kPi * double(i) / 24.0, 1e-9);
    EXPECT_NEAR(points[i].point.position.z(), 0.0, 1e-12);
    EXPECT_NEAR(d.head<2>().norm(), 25.0, 25.0 * (1.0 - std::cos(kPi / 90.0)) + 1e-9);
    EXPECT_NEAR(points[i].point.bary.sum(), 1.0, 1e-12);
  }
  EXPECT_NEAR(ring.midAngle(0.1, 0.3), 0.2, 1e-12);
  EXPECT_NEAR(ring.midAngle(6.2, 0.1), 6.2 + 0.5 * (0.1 + 2.0 * kPi - 6.2), 1e-12);
}

TEST(SurfaceLocator, FindsTheClosestPointOnTheSurface)
{
  const TriangleMesh tube = makeOpenCylinder(10.0, 20.0, 256, 10);
  const SurfaceLocator locator(tube);
  for (const Vec3& q : {Vec3(3.0, 1.0, 5.0), Vec3(-15.0, 2.0, 11.0), Vec3(0.0, -9.0, 19.0)}) {
    const SurfacePoint p = locator.closest(q);
    // Same answer as the brute-force search over all faces.
    const SurfacePoint brute = closestSurfacePoint(tube, q);
    EXPECT_NEAR((p.position - q).norm(), (brute.position - q).norm(), 1e-9);
    EXPECT_LT((p.position - brute.position).norm(), 1e-6);
    // And on the cylinder: within the 256-gon's chordal error of radius 10, at the query's height.
    EXPECT_NEAR(p.position.head<2>().norm(), 10.0, 10.0 * (1.0 - std::cos(kPi / 256)) + 1e-9);
    EXPECT_NEAR(p.position.z(), q.z(), 1e-9);
    EXPECT_NEAR(p.bary.sum(), 1.0, 1e-12);
    const Face& f = tube.faces[size_t(p.face)];
    const Vec3 x = p.bary[0] * tube.vertices[size_t(f[0])] + p.bary[1] * tube.vertices[size_t(f[1])] +
                   p.bary[2] * tube.vertices[size_t(f[2])];
    EXPECT_LT((x - p.position).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace spira::test
