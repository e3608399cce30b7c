#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "robot_files.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/kinematic_chain.h"

namespace spira {
namespace {

using test::handFanucM20ia;
using test::handKukaKr16;
using test::positionGap;
using test::robotUrdf;
using test::rotationGap;

JointVector deg(double a, double b, double c, double d, double e, double f)
{
  JointVector q;
  q << degToRad(a), degToRad(b), degToRad(c), degToRad(d), degToRad(e), degToRad(f);
  return q;
}

TEST(KinematicChain, ReadsTheKukaChainWithNamesAxesAndLimits)
{
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0");
  ASSERT_EQ(c.size(), 6u);
  EXPECT_EQ(c.joint(0).name, "joint_a1");
  EXPECT_EQ(c.joint(5).name, "joint_a6");
  EXPECT_NEAR((c.joint(0).axis - Vec3(0, 0, -1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.joint(3).origin.translation() - Vec3(670, 0, -35)).norm(), 0.0, 1e-9);
  // README limits: A2 -155..+35 deg, A5 +-130 deg, A6 speed 615 deg/s.
  EXPECT_NEAR(radToDeg(c.joint(1).lower), -155.0, 1e-9);
  EXPECT_NEAR(radToDeg(c.joint(1).upper), 35.0, 1e-9);
  EXPECT_NEAR(radToDeg(c.joint(4).upper), 130.0, 1e-9);
  EXPECT_NEAR(radToDeg(c.joint(5).maxVelocity), 615.0, 1e-9);
}

TEST(KinematicChain, KukaForwardKinematicsEqualsTheHandComposedChain)
{
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-kPi, kPi);
  for (int k = 0; k < 500; ++k) {
    JointVector q;
    for (int i = 0; i < 6; ++i) q[i] = u(rng);
    const Transform a = c.forward(q), b = handKukaKr16(q);
    ASSERT_LT(positionGap(a, b), 1e-9);
    ASSERT_LT(rotationGap(a, b), 1e-12);
  }
}

TEST(KinematicChain, FanucForwardKinematicsEqualsTheHandComposedChain)
{
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base_link", "tool0");
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-kPi, kPi);
  for (int k = 0; k < 500; ++k) {
    JointVector q;
    for (int i = 0; i < 6; ++i) q[i] = u(rng);
    const Transform a = c.forward(q), b = handFanucM20ia(q);
    ASSERT_LT(positionGap(a, b), 1e-9);
    ASSERT_LT(rotationGap(a, b), 1e-12);
  }
}

TEST(KinematicChain, KukaReadmeCheckValues)
{
  const KinematicChain flange = KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "flange");
  // HOME {0, -90, 90, 0, 0, 0}: flange at (1088, 0, 1320) with the identity orientation.
  const Transform home = flange.forward(deg(0, -90, 90, 0, 0, 0));
  EXPECT_NEAR((home.translation() - Vec3(1088, 0, 1320)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(rotationGap(home, Transform::Identity()), 0.0, 1e-12);
  EXPECT_NEAR((flange.forward(JointVector::Zero()).translation() - Vec3(1768, 0, 640)).norm(), 0.0, 1e-9);
  // A1 = +30 deg turns the arm clockwise seen from above: flange Y = -1088 sin 30 = -544.
  EXPECT_NEAR(flange.forward(deg(30, -90, 90, 0, 0, 0)).translation().y(), -544.0, 1e-9);
  // tool0 at HOME: Z forward, X down ($POS_ACT A 0, B 90, C 0).
  const KinematicChain tool0 = KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0");
  const Mat3 r = tool0.forward(deg(0, -90, 90, 0, 0, 0)).linear();
  EXPECT_NEAR((r.col(2) - Vec3::UnitX()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((r.col(0) - Vec3(0, 0, -1)).norm(), 0.0, 1e-12);
}

TEST(KinematicChain, FanucReadmeCheckValuesFromTheBaseFrame)
{
  // "base" is a fixed child of base_link (525 mm up), not an ancestor of tool0: the chain goes
  // up to base_link and down again.
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base", "tool0");
  ASSERT_EQ(c.size(), 6u);
  const Transform zero = c.forward(JointVector::Zero());
  EXPECT_NEAR((zero.translation() - Vec3(1085, 0, 1040)).norm(), 0.0, 1e-9);
  // WPR (180, -90, 0): R = Rz(0) Ry(-90) Rx(180); quaternion (w 0, x 0.7071, y 0, z 0.7071).
  const Mat3 expected =
      (Eigen::AngleAxisd(-kPi / 2, Vec3::UnitY()) * Eigen::AngleAxisd(kPi, Vec3::UnitX())).toRotationMatrix();
  EXPECT_NEAR((zero.linear() - expected).norm(), 0.0, 1e-12);
  const Eigen::Quaterniond quat(zero.linear());
  EXPECT_NEAR(std::abs(quat.x()), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(std::abs(quat.z()), std::sqrt(0.5), 1e-12);
  // TP (0, 30, 0, 0, 0, 0) = URDF (0, 30, 30, 0, 0, 0): flange level at (1480, 0, 934.16).
  const KinematicChain flange = KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base", "flange");
  const Transform tp = flange.forward(deg(0, 30, 30, 0, 0, 0));
  EXPECT_NEAR(tp.translation().x(), 1480.0, 1e-9);
  EXPECT_NEAR(tp.translation().y(), 0.0, 1e-9);
  EXPECT_NEAR(tp.translation().z(), 934.16, 0.005);  // 790 cos 30 + 250 = 934.1620
  EXPECT_NEAR(rotationGap(tp, Transform::Identity()), 0.0, 1e-12);
  // base_link -> flange at all-zero: (1085, 0, 1565).
  const KinematicChain foot = KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base_link", "flange");
  EXPECT_NEAR((foot.forward(JointVector::Zero()).translation() - Vec3(1085, 0, 1565)).norm(), 0.0, 1e-9);
}

TEST(KinematicChain, RejectsTextThatIsNotUrdf)
{
  try {
    KinematicChain::fromUrdfString("<robot name='x'><link name='a'/><joint", "a", "b");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not valid URDF"), std::string::npos) << e.what();
    EXPECT_FALSE(e.hint().empty());
  }
}

TEST(KinematicChain, MissingFileIsAnIoError)
{
  EXPECT_THROW(KinematicChain::fromUrdfFile("/nonexistent/robot.urdf", "a", "b"), IoError);
}

TEST(KinematicChain, NamesAMissingLinkAndListsTheLinks)
{
  try {
    KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool_9");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no link named 'tool_9'"), std::string::npos) << what;
    EXPECT_NE(e.hint().find("tool0"), std::string::npos) << e.hint();
  }
}

const char* kPrismaticUrdf = R"(<?xml version="1.0"?>
<robot name="slider">
  <link name="base"/><link name="carriage"/><link name="arm"/>
  <joint name="rail" type="prismatic">
    <parent link="base"/><child link="carriage"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="2" effort="0" velocity="1"/>
  </joint>
  <joint name="turn" type="revolute">
    <origin xyz="0 0 0.5" rpy="0 0 0"/>
    <parent link="carriage"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="0" velocity="1"/>
  </joint>
</robot>)";

TEST(KinematicChain, RefusesAPrismaticJointInTheChain)
{
  try {
    KinematicChain::fromUrdfString(kPrismaticUrdf, "base", "arm");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'rail'"), std::string::npos) << what;
    EXPECT_NE(what.find("prismatic"), std::string::npos) << what;
  }
  // The revolute part alone is fine, in mm.
  const KinematicChain c = KinematicChain::fromUrdfString(kPrismaticUrdf, "carriage", "arm");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c.forward(Eigen::VectorXd::Constant(1, 0.3)).translation().z(), 500.0, 1e-12);
}

TEST(KinematicChain, RefusesNanAndWrongCounts)
{
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0");
  JointVector q = JointVector::Zero();
  q[3] = std::nan("");
  EXPECT_THROW(c.forward(q), InputError);
  EXPECT_THROW(c.forward(Eigen::VectorXd::Zero(5)), InputError);
  EXPECT_THROW(c.limitMargin(q), InputError);
}

TEST(KinematicChain, LimitMarginIsTheDistanceToTheNearestLimit)
{
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0");
  // A2 = -90 sits 55 deg from -155 and 125 deg from +35; A5 = 120 is 10 deg from +130.
  EXPECT_NEAR(radToDeg(c.limitMargin(deg(0, -90, 90, 0, 120, 0))), 10.0, 1e-9);
  EXPECT_NEAR(radToDeg(c.limitMargin(deg(0, -90, 90, 0, 140, 0))), -10.0, 1e-9);
}

}  // namespace
}  // namespace spira
