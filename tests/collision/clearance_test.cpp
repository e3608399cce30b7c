// The clearance (nearest-distance) queries prune nodes, bead segments and triangles by the torch's
// bounding capsule before GJK. Pruning may only save work: every answer must equal the exhaustive
// minimum of the exact GJK distance over all elements, on scenes dense enough that most elements
// are pruned.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "plan_builders.h"
#include "spira/collision/basic_shapes.h"
#include "spira/collision/capsule_bvh.h"
#include "spira/collision/collision_scene.h"
#include "spira/collision/gjk.h"
#include "spira/collision/tilt_about_tangent.h"
#include "spira/collision/torch_collision_checker.h"
#include "spira/collision/triangle_bvh.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Rng {
  std::mt19937 gen;
  explicit Rng(unsigned seed) : gen(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
  Vec3 point(double a, double b) { return Vec3(uniform(a, b), uniform(a, b), uniform(a, b)); }
};

// Triangles of 2..10 mm scattered in the ring r in [rIn, rOut], z in [z0, z1] around the Z axis.
TriangleMesh ringSoup(Rng& rng, int count, double rIn, double rOut, double z0, double z1)
{
  TriangleMesh mesh;
  for (int f = 0; f < count; ++f) {
    const double phi = rng.uniform(0.0, 2.0 * kPi), r = rng.uniform(rIn, rOut);
    const Vec3 c(r * std::cos(phi), r * std::sin(phi), rng.uniform(z0, z1));
    const int base = static_cast<int>(mesh.vertices.size());
    for (int k = 0; k < 3; ++k) mesh.vertices.push_back(c + rng.point(-5.0, 5.0));
    mesh.faces.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

// The torch at a random point of the cube [-reach, reach]^3, built in a random direction and tilted
// up to 1 rad about the travel direction.
TorchSolid randomTorch(Rng& rng, const TorchParams& params, double reach)
{
  TrajectoryPoint p;
  p.position = rng.point(-reach, reach);
  p.build = rng.point(-1.0, 1.0).normalized();
  p.tangent = p.build.unitOrthogonal();
  p.normal = p.tangent.cross(p.build);
  return TorchSolid(params, toolFrame(tiltAboutTangent(p, rng.uniform(-1.0, 1.0))));
}

double exhaustiveTriangles(const ConvexShape& shape, const TriangleMesh& mesh)
{
  double best = kInf;
  for (const auto& f : mesh.faces) {
    const TriangleShape t(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
    best = std::min(best, gjkDistance(shape, t).distance);
  }
  return best;
}

double exhaustiveCapsules(const ConvexShape& shape, const CapsuleBvh& bvh, uint32_t keyEnd)
{
  double best = kInf;
  for (size_t i = 0; i < bvh.size(); ++i) {
    if (bvh.key(i) >= keyEnd) continue;
    const Capsule& c = bvh.capsule(i);
    best = std::min(best, std::max(0.0, gjkDistance(shape, SegmentShape(c.a, c.b)).distance - c.radius));
  }
  return best;
}

double planeGap(const ConvexShape& shape, const Vec3& point, const Vec3& normal)
{
  return std::max(0.0, normal.dot(shape.support(-normal) - point));
}

// A helix wall of 432 points (431 bead segments), a substrate plane under it and 320 obstacle
// triangles around it: the torch at every 5th point, tilted up to 0.6 rad either way, against the
// deposit laid before it (sliding window), the plane and the obstacles.
TEST(ClearancePruning, CheckerClearanceEqualsExhaustiveMinimumOverEveryElement)
{
  Rng rng(11);
  const Trajectory plan = test::helixPlan(30.0, 1.5, 6, 72);
  const TriangleMesh clutter = ringSoup(rng, 320, 58.0, 110.0, 0.0, 50.0);
  CollisionScene scene;
  scene.setSubstratePlane(Vec3(0.0, 0.0, -4.0), Vec3::UnitZ());
  scene.addObstacle("clutter", clutter);
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);
  ASSERT_GE(checker.deposit().capsules().size(), 400u);

  int nearestDeposit = 0, nearestObstacle = 0, nearestPlane = 0, touching = 0;
  for (size_t i = 0; i < checker.size(); i += 5) {
    const double tilt = rng.uniform(-0.6, 0.6);
    const TorchSolid torch = checker.torchAt(i, tilt);
    const double deposit =
        exhaustiveCapsules(torch, checker.deposit().capsules(), checker.deposit().visibleEnd(i));
    const double obstacle = exhaustiveTriangles(torch, clutter);
    const double plane = planeGap(torch, Vec3(0.0, 0.0, -4.0), Vec3::UnitZ());
    const double exact = std::min({deposit, obstacle, plane});
    ASSERT_TRUE(std::isfinite(exact));
    EXPECT_NEAR(checker.clearance(i, tilt, kInf, 0.0), exact, 1e-9) << "point " << i << ", tilt " << tilt;
    // The default search radius caps the answer; the default slack may only overstate it by the slack.
    EXPECT_NEAR(checker.clearance(i, tilt, 100.0, 0.0), std::min(exact, 100.0), 1e-9) << "point " << i;
    const double loose = checker.clearance(i, tilt);
    EXPECT_GE(loose, std::min(exact, 100.0) - 1e-9) << "point " << i;
    EXPECT_LE(loose, std::min(exact, 100.0) + 1e-3 + 1e-9) << "point " << i;
    if (exact == 0.0) ++touching;
    if (exact > 0.0 && exact == deposit) ++nearestDeposit;
    if (exact > 0.0 && exact == obstacle) ++nearestObstacle;
    if (exact > 0.0 && exact == plane) ++nearestPlane;
  }
  // Every kind of element was the nearest somewhere, and most poses are clear of everything.
  EXPECT_GT(nearestDeposit, 5);
  EXPECT_GT(nearestObstacle, 5);
  EXPECT_GT(nearestPlane, 0);
  EXPECT_LT(touching, 40);
}

// Capsules and triangles packed around the torch (many nearly equidistant candidates, the case the
// capsule prunes most), random tilted poses and key cut-offs.
TEST(ClearancePruning, NearestCapsuleAndTriangleEqualExhaustiveMinimumOnDenseScenes)
{
  Rng rng(12);
  std::vector<Capsule> caps;
  for (int i = 0; i < 600; ++i) {
    const Vec3 a = rng.point(-60.0, 60.0);
    caps.push_back({a, a + rng.point(-4.0, 4.0), rng.uniform(0.5, 2.5)});
  }
  const CapsuleBvh capsules(caps);
  const TriangleMesh soup = ringSoup(rng, 500, 0.0, 70.0, -60.0, 60.0);
  const TriangleBvh triangles(soup);
  int clear = 0;
  for (int q = 0; q < 60; ++q) {
    const TorchSolid torch = randomTorch(rng, TorchParams(), 70.0);
    const uint32_t keyEnd = static_cast<uint32_t>(rng.uniform(0.0, 700.0));
    const double capsuleExact = exhaustiveCapsules(torch, capsules, keyEnd);
    const double triangleExact = exhaustiveTriangles(torch, soup);
    const NearestHit c = capsules.nearest(torch, keyEnd);
    ASSERT_EQ(c.found(), std::isfinite(capsuleExact)) << "query " << q;
    if (c.found()) {
      EXPECT_NEAR(c.distance, capsuleExact, 1e-9) << "query " << q;
      EXPECT_LT(capsules.key(c.primitive), keyEnd);
    }
    const NearestHit t = triangles.nearest(torch);
    ASSERT_TRUE(t.found());
    EXPECT_NEAR(t.distance, triangleExact, 1e-9) << "query " << q;
    // A search radius just above the answer still finds it; one below it finds nothing.
    EXPECT_NEAR(triangles.nearest(torch, triangleExact + 0.01).distance, triangleExact, 1e-9);
    if (triangleExact > 0.0) {
      EXPECT_FALSE(triangles.nearest(torch, 0.5 * triangleExact).found());
    }
    if (triangleExact > 0.0 && capsuleExact > 0.0) ++clear;
  }
  EXPECT_GT(clear, 10);
}

// GJK's distance bounds (and so every clearance above) hold only if the torch's support point lies
// on the torch. A direction along the torch axis, the gap under a flat tip face, leaves only rounding
// noise as the radial part: the point must still be a rim point of the nozzle tip (or of the top).
TEST(ClearancePruning, TorchSupportAlongItsAxisIsARimPoint)
{
  Rng rng(14);
  const TorchParams params;
  for (int q = 0; q < 200; ++q) {
    const TorchSolid torch = randomTorch(rng, params, 100.0);
    const double scale = rng.uniform(0.01, 100.0);
    for (const double sign : {-1.0, 1.0}) {
      const Vec3 x = torch.support(sign * scale * torch.axis());
      const double axial = (x - torch.tcp()).dot(torch.axis());
      const double radial = ((x - torch.tcp()) - axial * torch.axis()).norm();
      if (sign < 0.0) {
        EXPECT_NEAR(axial, params.standoff, 1e-9) << "query " << q;
        EXPECT_NEAR(radial, params.nozzleRadius, 1e-9) << "query " << q;
      } else {
        EXPECT_NEAR(axial, params.standoff + params.coneLength + params.bodyLength, 1e-9) << "query " << q;
        EXPECT_NEAR(radial, params.bodyRadius, 1e-9) << "query " << q;
      }
    }
  }
}

// A query shape without a bounding capsule (a box) takes the unpruned path and must agree too.
TEST(ClearancePruning, ShapesWithoutABoundingCapsuleStillGetTheExactMinimum)
{
  Rng rng(13);
  const TriangleMesh soup = ringSoup(rng, 400, 0.0, 80.0, -40.0, 40.0);
  CollisionScene scene;
  scene.setSubstrateMesh(soup);
  for (int q = 0; q < 30; ++q) {
    BoundingBox box;
    box.extend(rng.point(-90.0, 90.0));
    box.extend(box.min + rng.point(1.0, 15.0));
    const BoxShape shape(box);
    Vec3 a, b;
    double r = 0.0;
    ASSERT_FALSE(shape.boundingCapsule(a, b, r));
    EXPECT_NEAR(scene.clearance(shape), exhaustiveTriangles(shape, soup), 1e-9) << "query " << q;
  }
}

}  // namespace
}  // namespace spira
