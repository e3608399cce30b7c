#include <gtest/gtest.h>

#include "collision/plan_builders.h"
#include "spira/base/error.h"
#include "spira/collision/collision_scene.h"
#include "spira/collision/torch_collision_checker.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

TEST(CollisionScene, SubstratePlaneAndMeshAgreeOnAFlatFloor)
{
  const TorchParams torch;
  CollisionScene plane, mesh;
  plane.setSubstratePlane(Vec3(0, 0, -5), Vec3(0, 0, 2));
  // A flat square floor at z = -5 made of two triangles.
  TriangleMesh floor;
  floor.vertices = {Vec3(-500, -500, 0), Vec3(500, -500, 0), Vec3(500, 500, 0), Vec3(-500, 500, 0)};
  floor.faces = {{0, 1, 2}, {0, 2, 3}};
  Transform down = Transform::Identity();
  down.translation() = Vec3(0, 0, -5);
  mesh.setSubstrateMesh(floor, down);
  for (const double tcpZ : {-20.0, -18.5, -17.0, -10.0}) {
    // Nozzle tip 15 mm above the TCP: the torch is (tcpZ + 15) - (-5) above the floor.
    const TrajectoryPoint p = test::wallPoint(0, 0, tcpZ, true);
    const TorchSolid solid(torch, toolFrame(p));
    const double height = tcpZ + 20.0;
    EXPECT_NEAR(plane.clearance(solid), std::max(0.0, height), 1e-9);
    EXPECT_NEAR(mesh.clearance(solid), std::max(0.0, height), 1e-6);
    const unsigned expected = height <= torch.clearance ? kCollisionSubstrate : kCollisionNone;
    EXPECT_EQ(plane.hits(solid, torch.clearance), expected) << tcpZ;
    EXPECT_EQ(mesh.hits(solid, torch.clearance), expected) << tcpZ;
  }
  EXPECT_THROW(plane.setSubstratePlane(Vec3::Zero(), Vec3::Zero()), InputError);
}

TEST(CollisionScene, NamesTheObstacleHitAndReportsEveryKindAtOnce)
{
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  Transform far = Transform::Identity();
  far.translation() = Vec3(500, 0, 0);
  scene.addObstacle("far column", makeOpenCylinder(10.0, 300.0, 32, 4), far);
  Transform near = Transform::Identity();
  near.translation() = Vec3(25, 0, 0);
  scene.addObstacle("positioner", makeOpenCylinder(10.0, 300.0, 32, 4), near);
  // The torch body (radius 20) reaches x = 20; the column's surface starts at x = 15.
  Trajectory plan;
  plan.points.push_back(test::wallPoint(0, 0, -14, true));  // nozzle tip 1 mm above the floor
  plan.points.push_back(test::wallPoint(1, 0, -14, true));
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);
  const TorchSolid solid = checker.torchAt(0);
  EXPECT_EQ(scene.obstacleHit(solid, 2.0), 1);
  EXPECT_EQ(scene.obstacleName(1), "positioner");
  EXPECT_EQ(checker.hits(0), unsigned(kCollisionSubstrate | kCollisionObstacle));
  EXPECT_TRUE(checker.collides(0));
  EXPECT_EQ(checker.clearance(0), 0.0);
}

}  // namespace
}  // namespace spira
