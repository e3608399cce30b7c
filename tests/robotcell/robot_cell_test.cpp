#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/document/cell_file.h"
#include "spira/path/tool_frame.h"
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
