#include <gtest/gtest.h>

#include <cmath>

#include "robot_files.h"
#include "spira/base/units.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/kinematics/kuka_status_turn.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

using test::positionGap;
using test::robotUrdf;
using test::rotationGap;

Transform translation(double x, double y, double z)
{
  Transform t = Transform::Identity();
  t.translation() = Vec3(x, y, z);
  return t;
}

// A spiral on a vertical cylinder (radius r, pitch per turn) in the part frame: n outward,
// t along the travel, b = n x t up.
Trajectory cylinderSpiral(double r, double pitch, double turns, int perTurn)
{
  Trajectory path;
  const int n = static_cast<int>(turns * perTurn);
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * kPi * k / perTurn;
    TrajectoryPoint p;
    p.position = Vec3(r * std::cos(a), r * std::sin(a), pitch * a / (2 * kPi));
    p.normal = Vec3(std::cos(a), std::sin(a), 0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    path.points.push_back(p);
  }
  return path;
}

// A spiral over a hemisphere from the equator to 20 deg from the pole: the build direction
// b = n x t tilts inwards, so a positioner has to turn the part to keep it vertical.
Trajectory domeSpiral(double r, int perTurn, double turns)
{
  Trajectory path;
  const int n = static_cast<int>(turns * perTurn);
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * kPi * k / perTurn;
    const double polar = degToRad(90 - 70.0 * k / n);
    TrajectoryPoint p;
    p.normal = Vec3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    p.position = r * p.normal;
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    path.points.push_back(p);
  }
  return path;
}

TEST(JointPathSolver, KukaCellFillsControllerDegreesAndStatusTurn)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  const ControllerConvention kc(Controller::KukaKrc4, ik.chain());
  // The torch x follows the travel, so the tool turns once per turn of the spiral: A6 winds up,
  // within +-350 deg: keep the path under a turn.
  const Trajectory path = cylinderSpiral(120, 3, 0.9, 180);
  JointPathSetup setup;
  setup.cellName = "kr16 test cell";
  setup.basePart = translation(1150, 0, 250);
  setup.flangeTcp = translation(0, 0, 300);
  setup.spinRad = 0.3;
  const Transform firstTip =
      setup.basePart * toolFrame(path.points[0], setup.spinRad) * setup.flangeTcp.inverse();
  setup.seed = ik.solve(firstTip, ArmConfiguration{}, JointVector::Zero())->q;
  NullProgress progress;
  const JointTrajectory jt = solveJointTrajectory(ik, kc, path, setup, progress);
  EXPECT_EQ(jt.controller, "kuka_krc4");
  EXPECT_EQ(jt.cellName, "kr16 test cell");
  EXPECT_FALSE(jt.hasPositioner);
  EXPECT_EQ(jt.robotLimits[0].name, "A1");
  ASSERT_EQ(jt.size(), path.size());
  for (size_t i = 0; i < jt.size(); ++i) {
    const JointPoint& p = jt.points[i];
    ASSERT_TRUE(p.reachable) << i;
    const Transform expected = setup.basePart * toolFrame(path.points[i], setup.spinRad);
    EXPECT_LT(positionGap(p.baseTcp, expected), 1e-12);
    // The printed axes drive the arm onto the TCP frame.
    const JointVector q = kc.fromControllerDeg(p.robotDeg);
    const Transform tcp = ik.forward(q) * setup.flangeTcp;
    ASSERT_LT(positionGap(tcp, expected), 1e-9);
    ASSERT_LT(rotationGap(tcp, expected), 1e-12);
    const KukaStatusTurn st = kukaStatusTurn(ik.model(), q);
    EXPECT_EQ(p.kukaStatus, st.status);
    EXPECT_EQ(p.kukaTurn, st.turn);
    EXPECT_EQ(p.kukaStatus & 7, 2);  // basic area, elbow up, A5 > 0: the seed's configuration
    EXPECT_GT(p.dexterity, 0.0);
    for (size_t j = 0; i > 0 && j < 6; ++j)
      EXPECT_LT(std::abs(p.robotDeg[j] - jt.points[i - 1].robotDeg[j]), 5.0);
  }
}

TEST(JointPathSolver, FanucWithPositionerKeepsTheBuildDirectionVertical)
{
  ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base", "tool0"));
  const ControllerConvention fc(Controller::FanucR30ib, ik.chain());
  const TiltRotatePositioner positioner(
      KinematicChain::fromUrdfFile(robotUrdf("positioner_2axis"), "base_link", "table_top"));
  const Trajectory path = domeSpiral(60, 240, 1.4);
  JointPathSetup setup;
  setup.positioner = &positioner;
  setup.basePositioner = translation(1000, 0, -525);  // on the floor, 1 m in front of J1
  setup.tablePart = translation(0, 0, 10);
  setup.flangeTcp = translation(0, 0, 350);
  // The table turns against the spiral, 1.4 turns in all. The first build direction is vertical
  // (any E2 would do); starting from E2 = 180 deg the tilt goes negative and E2 stays in +-360.
  setup.positionerSeed = Eigen::Vector2d(0.0, kPi);
  // Torch straight down over the table centre at the first point.
  Transform firstTcp = Transform::Identity();
  firstTcp.linear() = Eigen::AngleAxisd(kPi, Vec3::UnitX()).toRotationMatrix();
  firstTcp.translation() = Vec3(1000, 0, 400);
  setup.seed = ik.solve(firstTcp * setup.flangeTcp.inverse(), ArmConfiguration{}, JointVector::Zero())->q;
  NullProgress progress;
  const JointTrajectory jt = solveJointTrajectory(ik, fc, path, setup, progress);
  EXPECT_EQ(jt.controller, "fanuc_r30ib");
  EXPECT_TRUE(jt.hasPositioner);
  EXPECT_EQ(jt.externalLimits[0].name, "E1");
  EXPECT_NEAR(jt.externalLimits[0].maxDeg, 135.0, 1e-9);
  ASSERT_EQ(jt.size(), path.size());
  double worstVertical = 0.0;
  for (size_t i = 0; i < jt.size(); ++i) {
    const JointPoint& p = jt.points[i];
    ASSERT_TRUE(p.reachable) << i;
    const TiltRotatePositioner::Axes e(degToRad(p.externalDeg[0]), degToRad(p.externalDeg[1]));
    const Transform basePart = setup.basePositioner * positioner.forward(e) * setup.tablePart;
    // Flat position: the build direction is vertical and the torch points straight down.
    worstVertical =
        std::max(worstVertical, (basePart.linear() * path.points[i].build - Vec3::UnitZ()).norm());
    EXPECT_LT((p.baseTcp.linear().col(2) - Vec3(0, 0, -1)).norm(), 1e-9);
    const Transform expected = basePart * toolFrame(path.points[i]);
    EXPECT_LT(positionGap(p.baseTcp, expected), 1e-9);
    const JointVector q = fc.fromControllerDeg(p.robotDeg);
    const Transform tcp = ik.forward(q) * setup.flangeTcp;
    ASSERT_LT(positionGap(tcp, expected), 1e-9);
    ASSERT_LT(rotationGap(tcp, expected), 1e-12);
    EXPECT_EQ(p.fanucConfig.substr(0, 5), "N U T");
  }
  EXPECT_LT(worstVertical, 1e-9);
  // The dome's build direction tilts up to 70 deg inwards: the positioner tilts as much.
  double maxTilt = 0.0;
  for (const JointPoint& p : jt.points) maxTilt = std::max(maxTilt, std::abs(p.externalDeg[0]));
  EXPECT_NEAR(maxTilt, 70.0, 1e-6);
  EXPECT_NEAR(jt.points.front().externalDeg[1], 180.0, 1e-9);
  EXPECT_NEAR(jt.points.back().externalDeg[1], 180.0 - 1.4 * 360.0, 1e-6);
  EXPECT_LT(jt.points.back().externalDeg[0], -69.0);
}

}  // namespace
}  // namespace spira
