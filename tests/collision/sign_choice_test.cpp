#include <gtest/gtest.h>

#include <cmath>

#include "collision/mesh_builders.h"
#include "collision/plan_builders.h"
#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"
#include "spira/collision/tilt_search.h"

namespace spira {
namespace {

using test::boxMesh;

// A straight pass along +X under two overhead bars, the first slightly to +Y and the second slightly
// to -Y: each alone is cleared fastest by leaning away from its offset, i.e. in opposite directions,
// but they are too close for the torch to swing from one lean to the other at 1 deg per point.
TEST(SignChoice, NeighbouringConflictsPullingOppositeWaysShareOneLean)
{
  Trajectory plan;
  for (int k = 0; k <= 100; ++k) plan.points.push_back(test::wallPoint(k, 0, 1, true));
  CollisionScene scene;
  scene.addObstacle("bar +y", boxMesh(Vec3(25, -1, 150), Vec3(40, 7, 160)));
  scene.addObstacle("bar -y", boxMesh(Vec3(52, -7, 150), Vec3(67, 1, 160)));
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);
  ResolveSettings settings;

  // The premise: under the first bar leaning towards -Y (n = -Y, a positive tilt) clears with the
  // smaller angle, under the second the other way round.
  const double a1 = clearingTilt(checker, 32, 1, 0.0, settings),
               b1 = clearingTilt(checker, 32, -1, 0.0, settings);
  const double a2 = clearingTilt(checker, 60, 1, 0.0, settings),
               b2 = clearingTilt(checker, 60, -1, 0.0, settings);
  ASSERT_TRUE(checker.collides(32) && checker.collides(60));
  ASSERT_LT(a1, b1);
  ASSERT_LT(b2, a2);

  NullProgress progress;
  const CollisionResolution res = resolveTorchCollisions(plan, checker, settings, progress);
  EXPECT_TRUE(res.unresolved.empty());
  int positive = 0, negative = 0;
  for (size_t i = 0; i < plan.size(); ++i) {
    positive += res.tiltRad[i] > 0.0;
    negative += res.tiltRad[i] < 0.0;
    EXPECT_FALSE(checker.collides(i, res.tiltRad[i])) << i;
    if (i + 1 < plan.size()) {
      EXPECT_LE(std::abs(res.tiltRad[i + 1] - res.tiltRad[i]), settings.maxTiltChangeRad + 1e-12) << i;
    }
  }
  EXPECT_TRUE(positive == 0 || negative == 0) << positive << " leaning one way, " << negative << " the other";
  EXPECT_GT(positive + negative, 40);
  // The shared lean is the one whose largest tilt is smaller.
  const int sign = positive > 0 ? 1 : -1;
  double maxTilt = 0.0;
  for (const double t : res.tiltRad) maxTilt = std::max(maxTilt, std::abs(t));
  EXPECT_NEAR(maxTilt, sign > 0 ? std::max(a1, a2) : std::max(b1, b2), 3.0 * settings.toleranceRad);
}

TEST(SignChoice, CancellingStopsTheCheck)
{
  const Trajectory plan = test::helixPlan(50.0, 1.0, 5, 180);
  const TorchCollisionChecker checker(plan, TorchParams());
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(resolveTorchCollisions(plan, checker, ResolveSettings(), progress), Cancelled);
}

}  // namespace
}  // namespace spira
