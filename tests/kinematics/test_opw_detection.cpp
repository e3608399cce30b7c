#include <gtest/gtest.h>

#include "robot_files.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/opw_detection.h"

namespace spira {
namespace {

using test::robotUrdf;

void expectOffsetsDeg(const OpwParameters& p, const std::array<double, 6>& deg)
{
  for (size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(wrapToPi(p.offsets[i] - degToRad(deg[i])), 0.0, 1e-12) << "offset " << i;
}

TEST(OpwDetection, KukaParametersMatchTheReadme)
{
  // README: a1=260, a2=+35, b=0, c1=675, c2=680, c3=670, c4=158, signs [-1,1,1,-1,1,-1],
  // offsets [0,-90,0,0,0,0] (derived there from the URDF and checked against KDL).
  const OpwDetection d =
      detectOpw(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  ASSERT_TRUE(d.ok) << d.reason;
  const OpwParameters& p = d.model.parameters();
  EXPECT_NEAR(p.a1, 260, 1e-9);
  EXPECT_NEAR(p.a2, 35, 1e-9);
  EXPECT_NEAR(p.b, 0, 1e-9);
  EXPECT_NEAR(p.c1, 675, 1e-9);
  EXPECT_NEAR(p.c2, 680, 1e-9);
  EXPECT_NEAR(p.c3, 670, 1e-9);
  EXPECT_NEAR(p.c4, 158, 1e-9);
  EXPECT_EQ(p.signs, (std::array<int, 6>{{-1, 1, 1, -1, 1, -1}}));
  expectOffsetsDeg(p, {{0, -90, 0, 0, 0, 0}});
  EXPECT_LT(d.maxPositionError, 1e-9);
  EXPECT_LT(d.maxOrientationError, 1e-12);
}

TEST(OpwDetection, FanucParametersMatchTheUpstreamOpwFile)
{
  // README (fanuc_m20ia_support/config/opw_parameters_m20ia.yaml): a1=150, a2=-250, b=0, c1=525,
  // c2=790, c3=835, c4=100, signs [1,1,-1,-1,-1,-1], offsets [0,0,-90,0,0,180].
  const OpwDetection d =
      detectOpw(KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base_link", "tool0"));
  ASSERT_TRUE(d.ok) << d.reason;
  const OpwParameters& p = d.model.parameters();
  EXPECT_NEAR(p.a1, 150, 1e-9);
  EXPECT_NEAR(p.a2, -250, 1e-9);
  EXPECT_NEAR(p.b, 0, 1e-9);
  EXPECT_NEAR(p.c1, 525, 1e-9);
  EXPECT_NEAR(p.c2, 790, 1e-9);
  EXPECT_NEAR(p.c3, 835, 1e-9);
  EXPECT_NEAR(p.c4, 100, 1e-9);
  EXPECT_EQ(p.signs, (std::array<int, 6>{{1, 1, -1, -1, -1, -1}}));
  expectOffsetsDeg(p, {{0, 0, -90, 0, 0, 180}});
  // tool0 is OPW-compatible: its offset is absorbed by joint 6, no residual tip transform.
  EXPECT_NEAR((d.model.flangeTip().matrix() - Eigen::Matrix4d::Identity()).norm(), 0.0, 1e-12);
}

TEST(OpwDetection, ChainFromTheFlangeKeepsATipRotation)
{
  // The KUKA flange frame has X (not Z) out of the flange: that is not a turn about the flange
  // axis, so it goes to T_flange_tip, and the model still equals the chain.
  const OpwDetection d =
      detectOpw(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "flange"));
  ASSERT_TRUE(d.ok) << d.reason;
  EXPECT_GT((d.model.flangeTip().linear() - Mat3::Identity()).norm(), 1.0);
  EXPECT_LT(d.maxPositionError, 1e-9);
  // ... and the IK of that chain lands on the flange frame.
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "flange"));
  JointVector q;
  q << 0.3, -1.2, 1.4, 0.5, 0.8, -0.6;
  const std::optional<IkSolution> s = ik.solve(ik.forward(q), ik.configurationOf(q), JointVector::Zero());
  ASSERT_TRUE(s);
  EXPECT_LT((s->q - q).norm(), 1e-9);
}

TEST(ArmConfiguration, LabelsAndIndicesRoundTrip)
{
  int count = 0;
  for (const ArmConfiguration& c : ArmConfiguration::all()) {
    EXPECT_EQ(ArmConfiguration::parse(c.label()), c);
    EXPECT_EQ(ArmConfiguration::fromIndex(c.index()), c);
    EXPECT_EQ(c.index(), count++);
  }
  EXPECT_EQ(ArmConfiguration{}.label(), "front/up/noflip");
  EXPECT_THROW(ArmConfiguration::parse("front/up"), InputError);
}

// A KUKA-like arm whose A5 axis sits 40 mm off the A4 axis: no spherical wrist.
const char* kOffsetWristUrdf = R"(<?xml version="1.0"?>
<robot name="offset_wrist">
  <link name="base_link"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="l4"/>
  <link name="l5"/><link name="l6"/><link name="tool0"/>
  <joint name="j1" type="revolute"><origin xyz="0 0 0.675"/><parent link="base_link"/><child link="l1"/>
    <axis xyz="0 0 -1"/><limit lower="-3" upper="3" effort="0" velocity="2"/></joint>
  <joint name="j2" type="revolute"><origin xyz="0.26 0 0"/><parent link="l1"/><child link="l2"/>
    <axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="0" velocity="2"/></joint>
  <joint name="j3" type="revolute"><origin xyz="0.68 0 0"/><parent link="l2"/><child link="l3"/>
    <axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="0" velocity="2"/></joint>
  <joint name="j4" type="revolute"><origin xyz="0.67 0 -0.035"/><parent link="l3"/><child link="l4"/>
    <axis xyz="-1 0 0"/><limit lower="-3" upper="3" effort="0" velocity="2"/></joint>
  <joint name="j5" type="revolute"><origin xyz="0 0 0.04"/><parent link="l4"/><child link="l5"/>
    <axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="0" velocity="2"/></joint>
  <joint name="j6" type="revolute"><origin xyz="0.1 0 0"/><parent link="l5"/><child link="l6"/>
    <axis xyz="-1 0 0"/><limit lower="-3" upper="3" effort="0" velocity="2"/></joint>
  <joint name="j6_tool0" type="fixed"><origin xyz="0.1 0 0" rpy="0 1.5707963267948966 0"/>
    <parent link="l6"/><child link="tool0"/></joint>
</robot>)";

TEST(OpwDetection, RefusesAWristWhoseAxesDoNotMeet)
{
  const KinematicChain chain = KinematicChain::fromUrdfString(kOffsetWristUrdf, "base_link", "tool0");
  const OpwDetection d = detectOpw(chain);
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.reason.find("spherical wrist"), std::string::npos) << d.reason;
  try {
    ArmIk ik(chain);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("not a 6R arm with a spherical wrist"), std::string::npos) << what;
    EXPECT_FALSE(e.hint().empty());
  }
}

TEST(OpwDetection, RefusesChainsWithoutSixJointsOrWithSkewAxes)
{
  const KinematicChain five = KinematicChain::fromUrdfString(kOffsetWristUrdf, "base_link", "l5");
  const OpwDetection d5 = detectOpw(five);
  EXPECT_FALSE(d5.ok);
  EXPECT_NE(d5.reason.find("5 revolute joints"), std::string::npos) << d5.reason;

  // Axis 3 tilted: joints 2 and 3 are no longer parallel.
  std::string skew = kOffsetWristUrdf;
  const std::string axis3 =
      "<origin xyz=\"0.68 0 0\"/><parent link=\"l2\"/><child link=\"l3\"/>\n    <axis xyz=\"0 1 0\"/>";
  const size_t at = skew.find(axis3);
  ASSERT_NE(at, std::string::npos);
  skew.replace(
      at, axis3.size(),
      "<origin xyz=\"0.68 0 0\"/><parent link=\"l2\"/><child link=\"l3\"/>\n    <axis xyz=\"0 1 0.2\"/>");
  const OpwDetection ds = detectOpw(KinematicChain::fromUrdfString(skew, "base_link", "tool0"));
  EXPECT_FALSE(ds.ok);
  EXPECT_NE(ds.reason.find("not parallel"), std::string::npos) << ds.reason;
}

}  // namespace
}  // namespace spira
