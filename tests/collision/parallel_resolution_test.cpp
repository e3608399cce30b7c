// The torch collision check and resolution run their points on all cores (read-only hierarchies,
// each point's deposit the path before it). The answer must not depend on the threads: one thread
// and many give the same hits, tilts and trajectory, bit for bit.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>

#include "collision/mesh_builders.h"
#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"

namespace spira {
namespace {

// A spiral over a sphere of radius r from the equator up to `polarEndDeg` from the pole: near the
// top the layers are small circles and the 20 mm torch body reaches over the deposit on the far
// side, so many points conflict with the deposit (and a post beside the equator adds obstacle hits).
Trajectory domeSpiral(double r, double polarEndDeg, int turns, int perTurn)
{
  Trajectory plan;
  const int n = turns * perTurn;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / perTurn;
    const double polar = degToRad(90.0 - (90.0 - polarEndDeg) * k / n);
    TrajectoryPoint p;
    p.normal = Vec3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    p.position = r * p.normal + Vec3(0, 0, 1);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    p.revolution = k / perTurn;
    plan.points.push_back(p);
  }
  return plan;
}

CollisionResolution resolveOn(int threads, const Trajectory& plan, const TorchCollisionChecker& checker)
{
  tbb::task_arena arena(threads);
  CollisionResolution res;
  NullProgress progress;
  arena.execute([&] { res = resolveTorchCollisions(plan, checker, ResolveSettings(), progress); });
  return res;
}

bool bitIdentical(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(ParallelResolution, OneThreadAndManyGiveBitIdenticalResults)
{
  const Trajectory plan = domeSpiral(40.0, 15.0, 12, 360);
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  scene.addObstacle("post", test::boxMesh(Vec3(54, -6, 0), Vec3(70, 6, 60)));
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);

  const CollisionResolution serial = resolveOn(1, plan, checker);
  // Enough conflicts of both kinds that the parallel blocks (2048 points) really split the work.
  size_t deposit = 0, obstacle = 0;
  for (const unsigned h : serial.hits) {
    deposit += (h & kCollisionDeposit) ? 1 : 0;
    obstacle += (h & kCollisionObstacle) ? 1 : 0;
  }
  ASSERT_GT(deposit, 300u);
  ASSERT_GT(obstacle, 20u);
  size_t tilted = 0;
  for (const double t : serial.tiltRad) tilted += t != 0.0 ? 1 : 0;
  ASSERT_GT(tilted, deposit);  // ramps tilt neighbours too

  for (const int threads : {2, 4, 8}) {
    const CollisionResolution parallel = resolveOn(threads, plan, checker);
    EXPECT_EQ(parallel.hits, serial.hits) << threads;
    EXPECT_EQ(parallel.unresolved, serial.unresolved) << threads;
    EXPECT_TRUE(bitIdentical(parallel.tiltRad, serial.tiltRad)) << threads;
    ASSERT_EQ(parallel.trajectory.size(), serial.trajectory.size());
    EXPECT_EQ(parallel.trajectory.points, serial.trajectory.points) << threads;
    EXPECT_TRUE(bitIdentical(parallel.trajectory.extra.at("torch_tilt"), serial.tiltRad)) << threads;
  }
}

}  // namespace
}  // namespace spira
