#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/transform.h"
#include "spira/base/units.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/path/tool_frame.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "support/test_support.h"

namespace spira {
namespace {

CellRecord bundled(const char* name)
{
  return readCellFile(test::sourceDir() / "resources" / "cells" / name);
}

// Two revolutions of a helix on an R = 30 mm wall, building up +Z of the part frame.
Trajectory helix(int perRev = 72, double radius = 30.0)
{
  Trajectory t;
  for (int k = 0; k < 2 * perRev; ++k) {
    const double a = 2.0 * kPi * k / perRev;
    TrajectoryPoint p;
    p.position = Vec3(radius * std::cos(a), radius * std::sin(a), 2.0 + 2.0 * k / perRev);
    p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0.0);
    p.build = p.normal.cross(p.tangent);
    p.revolution = k / perRev;
    p.generatrix = k % perRev;
    p.travelSpeed = 8.0;
    t.points.push_back(p);
  }
  return t;
}

double rotationError(const Transform& a, const Transform& b)
{
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

TEST(RobotCell, KukaTableCellSolvesAPartAndTheToolLandsOnEveryPoint)
{
  const RobotCell cell(bundled("kuka_kr16_2_table.cell"));
  ASSERT_TRUE(cell.canSolve()) << cell.ikRefusal();
  EXPECT_TRUE(cell.worldBase().isApprox(Transform::Identity()));
  EXPECT_EQ(cell.convention().axisLimits()[1].minDeg, -155.0);
  const Trajectory path = helix();
  NullProgress progress;
  JointPathSetup setup = cell.setup();
  const auto first =
      cell.ik().solveAll(setup.basePart * toolFrame(path.points[0]) * setup.flangeTcp.inverse());
  ASSERT_FALSE(first.empty());
  setup.seed = first.front().q;
  setup.configuration = first.front().configuration;
  const JointTrajectory joints = solveJointTrajectory(cell.ik(), cell.convention(), path, setup, progress);
  ASSERT_EQ(joints.size(), path.size());
  const Transform worldPart = cell.record().T_mount_part;
  for (size_t i = 0; i < path.size(); ++i) {
    const JointPoint& j = joints.points[i];
    const Transform reached = cell.worldBase() *
                              cell.arm().forward(cell.convention().fromControllerDeg(j.robotDeg)) *
                              setup.flangeTcp;
    const Transform wanted = worldPart * toolFrame(path.points[i]);
    EXPECT_LT((reached.translation() - wanted.translation()).norm(), 1e-6) << i;
    EXPECT_LT(rotationError(reached, wanted), 1e-8) << i;
  }
}

TEST(RobotCell, FanucPositionerCellHoldsTheBuildDirectionVerticalInTheWorld)
{
  const RobotCell cell(bundled("fanuc_m20ia_positioner.cell"));
  ASSERT_TRUE(cell.canSolve()) << cell.ikRefusal();
  // FANUC World ("base") is 525 mm above the robot's foot.
  EXPECT_LT((cell.worldBase().translation() - Vec3(0, 0, 525)).norm(), 1e-9);
  ASSERT_NE(cell.positioner(), nullptr);
  EXPECT_LT((cell.basePositioner().translation() - Vec3(1100, 0, -525)).norm(), 1e-9);

  // A leaning wall: the build direction tilts 20 degrees from the table normal.
  Trajectory path = helix();
  for (auto& p : path.points) {
    p.build = (p.build + std::tan(degToRad(20.0)) * p.normal).normalized();
    p.normal = p.tangent.cross(p.build);
  }
  NullProgress progress;
  JointPathSetup setup = cell.setup();
  const JointTrajectory joints = solveJointTrajectory(cell.ik(), cell.convention(), path, setup, progress);
  ASSERT_EQ(joints.size(), path.size());
  EXPECT_TRUE(joints.hasPositioner);
  const Transform worldPositioner = cell.worldBase() * cell.basePositioner();
  for (size_t i = 0; i < path.size(); i += 7) {
    const JointPoint& j = joints.points[i];
    const Eigen::Vector2d e(degToRad(j.externalDeg[0]), degToRad(j.externalDeg[1]));
    const Transform worldPart = worldPositioner * cell.positioner()->forward(e) * cell.record().T_mount_part;
    const Vec3 buildInWorld = worldPart.linear() * path.points[i].build;
    EXPECT_LT((buildInWorld - Vec3::UnitZ()).norm(), 1e-9) << i;
    if (!j.reachable) continue;
    const Transform reached = cell.worldBase() *
                              cell.arm().forward(cell.convention().fromControllerDeg(j.robotDeg)) *
                              setup.flangeTcp;
    EXPECT_LT((reached.translation() - (worldPart * toolFrame(path.points[i])).translation()).norm(), 1e-6)
        << i;
  }
}

// A part stored lying on its side and placed upright (T_world_part turns it 90 degrees about X):
// exports solve its part-frame path on cellForPlacement(cell, T_world_part), the planner's
// kinematics stage solves the upright (build-frame) path on the plain cell. Both must give the
// same motion, on the fixed table and on the positioner.
TEST(RobotCell, APlacementTurnsThePartOnItsMountAsInTheWorld)
{
  const Transform T_world_part = transformFromXyzRpy(Vec3(12.0, -7.0, 3.0), Vec3(degToRad(90.0), 0.0, 0.4));
  const Mat3 R = T_world_part.linear();
  const Trajectory upright = helix();
  Trajectory lying = upright;
  for (TrajectoryPoint& p : lying.points) {
    p.position = R.transpose() * p.position;
    p.normal = R.transpose() * p.normal;
    p.tangent = R.transpose() * p.tangent;
    p.build = R.transpose() * p.build;
  }
  for (const char* name : {"kuka_kr16_2_table.cell", "fanuc_m20ia_positioner.cell"}) {
    const RobotCell plain(bundled(name));
    const RobotCell placed(cellForPlacement(bundled(name), T_world_part));
    // Only the mount pose changes, and only by the placement's turn.
    EXPECT_TRUE(
        placed.record().T_mount_part.translation().isApprox(plain.record().T_mount_part.translation()));
    NullProgress progress;
    const JointTrajectory a =
        solveJointTrajectory(plain.ik(), plain.convention(), upright, plain.seededSetup(upright), progress);
    const JointTrajectory b =
        solveJointTrajectory(placed.ik(), placed.convention(), lying, placed.seededSetup(lying), progress);
    ASSERT_EQ(a.size(), b.size());
    size_t reachable = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a.points[i].reachable, b.points[i].reachable) << name << " " << i;
      reachable += a.points[i].reachable ? 1 : 0;
      for (size_t k = 0; k < 6; ++k)
        EXPECT_NEAR(a.points[i].robotDeg[k], b.points[i].robotDeg[k], 1e-7) << name << " point " << i;
      for (size_t k = 0; k < 2; ++k)
        EXPECT_NEAR(a.points[i].externalDeg[k], b.points[i].externalDeg[k], 1e-7) << name << " point " << i;
    }
    EXPECT_GT(reachable, size_t{20}) << name;  // a comparison of motions, not of failures
  }
}

TEST(RobotCell, AxisMappingsThatDoNotMatchTheChainAreRefused)
{
  CellRecord c = bundled("kuka_kr16_2_table.cell");
  c.robotAxes[2].urdfJoint = "joint_a4";
  EXPECT_THROW(RobotCell{c}, InputError);
  c = bundled("kuka_kr16_2_table.cell");
  c.robotAxes[3].sign = -1;
  EXPECT_THROW(RobotCell{c}, InputError);
  c = bundled("kuka_kr16_2_table.cell");
  c.robotAxes.pop_back();
  EXPECT_THROW(RobotCell{c}, InputError);
  c = bundled("kuka_kr16_2_table.cell");
  c.robotTipLink = "no_such_link";
  EXPECT_THROW(RobotCell{c}, InputError);
  c = bundled("kuka_kr16_2_table.cell");
  c.robotUrdf = "/nonexistent/robot.urdf";
  EXPECT_THROW(RobotCell{c}, Error);
}

}  // namespace
}  // namespace spira
