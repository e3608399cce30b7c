#include <gtest/gtest.h>

#include <cmath>

#include "collision/mesh_builders.h"
#include "collision/plan_builders.h"
#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"

namespace spira {
namespace {

using test::boxMesh;

TEST(HelixPlan, ACleanCylinderSpiralHasNoCollisionsAndIsLeftUnchanged)
{
  const Trajectory plan = test::helixPlan(50.0, 1.0, 20, 180);
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  scene.addObstacle("table", boxMesh(Vec3(-300, -300, -30), Vec3(300, 300, -10)));
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);
  NullProgress progress;
  const CollisionResolution res = resolveTorchCollisions(plan, checker, ResolveSettings(), progress);
  EXPECT_EQ(res.collisionCount(), 0u);
  EXPECT_TRUE(res.unresolved.empty());
  for (const double t : res.tiltRad) EXPECT_EQ(t, 0.0);
  EXPECT_EQ(res.trajectory.points, plan.points);
  // The torch keeps at least its clearance everywhere; on the first point only the substrate is
  // near: the nozzle rim is 1 + 15 mm above it (b is tilted by the helix lead only).
  for (size_t i = 0; i < plan.size(); i += 97) EXPECT_GT(checker.clearance(i), TorchParams().clearance);
  EXPECT_NEAR(checker.clearance(0), checker.torchAt(0).heightAbove(Vec3::Zero(), Vec3::UnitZ()), 1e-9);
  EXPECT_NEAR(checker.clearance(0), 16.0, 0.1);
}

TEST(HelixPlan, AnObstacleBesideTheWallIsDetectedAndAvoidedByTiltingInwards)
{
  const Trajectory plan = test::helixPlan(50.0, 1.0, 6, 180);
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  // A post outside the wall at +X: the torch body (radius 20, from 46 mm up) sweeps into it.
  scene.addObstacle("clamp", boxMesh(Vec3(64, -6, 0), Vec3(80, 6, 70)));
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);
  ResolveSettings settings;
  NullProgress progress;
  const CollisionResolution res = resolveTorchCollisions(plan, checker, settings, progress);
  ASSERT_GT(res.collisionCount(), 0u);
  for (size_t i = 0; i < plan.size(); ++i) {
    if (res.hits[i] == 0) continue;
    EXPECT_EQ(res.hits[i], unsigned(kCollisionObstacle));
    // Only points near the post collide (the torch reaches 20 mm sideways).
    EXPECT_GT(plan.points[i].position.x(), 40.0);
    // Tilting inwards (towards -n, a negative tilt) moves the torch away from the post.
    EXPECT_LT(res.tiltRad[i], 0.0);
  }
  EXPECT_TRUE(res.unresolved.empty());
  for (size_t i = 0; i < plan.size(); ++i) {
    EXPECT_FALSE(checker.collides(i, res.tiltRad[i])) << i;
    if (i + 1 < plan.size()) {
      EXPECT_LE(std::abs(res.tiltRad[i + 1] - res.tiltRad[i]), settings.maxTiltChangeRad + 1e-12);
    }
  }
}

}  // namespace
}  // namespace spira
