#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "robot_files.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/fanuc_config.h"
#include "spira/kinematics/kuka_status_turn.h"

namespace spira {
namespace {

using test::robotUrdf;

ArmIk kuka()
{
  return ArmIk(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
}

ArmIk fanuc()
{
  return ArmIk(KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base", "tool0"));
}

JointVector deg(double a, double b, double c, double d, double e, double f)
{
  JointVector q;
  q << degToRad(a), degToRad(b), degToRad(c), degToRad(d), degToRad(e), degToRad(f);
  return q;
}

// FANUC WPR of a rotation: R = Rz(R) Ry(P) Rx(W), in degrees (004_bd0df31205c0c3c0.txt Appendix B, FANUC's
// naming).
Vec3 fanucWpr(const Mat3& r)
{
  return Vec3(radToDeg(std::atan2(r(2, 1), r(2, 2))),
              radToDeg(std::atan2(-r(2, 0), std::hypot(r(0, 0), r(1, 0)))),
              radToDeg(std::atan2(r(1, 0), r(0, 0))));
}

TEST(ControllerConvention, KukaAxesAreTheUrdfJointsInDegrees)
{
  const ArmIk ik = kuka();
  const ControllerConvention kc(Controller::KukaKrc4, ik.chain());
  EXPECT_EQ(kc.id(), "kuka_krc4");
  const std::array<double, 6> a = kc.toControllerDeg(deg(10, -90, 90, -20, 30, 400));
  const std::array<double, 6> expected{{10, -90, 90, -20, 30, 400}};
  for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(a[i], expected[i], 1e-12);
  EXPECT_NEAR((kc.fromControllerDeg(a) - deg(10, -90, 90, -20, 30, 400)).norm(), 0.0, 1e-15);
  EXPECT_EQ(kc.axisLimits()[1].name, "A2");
  EXPECT_NEAR(kc.axisLimits()[1].minDeg, -155.0, 1e-9);
  EXPECT_NEAR(kc.axisLimits()[1].maxDeg, 35.0, 1e-9);
  EXPECT_NEAR(kc.axisLimits()[5].maxSpeedDegPerS, 615.0, 1e-9);
}

TEST(ControllerConvention, FanucJ3IsCoupledToJ2)
{
  const ArmIk ik = fanuc();
  const ControllerConvention fc(Controller::FanucR30ib, ik.chain());
  EXPECT_EQ(ControllerConvention::parse("fanuc_r30ib"), Controller::FanucR30ib);
  EXPECT_EQ(ControllerConvention::parse("abb_irc5"), Controller::AbbIrc5);
  EXPECT_THROW(ControllerConvention::parse("staubli_cs9"), InputError);
  // README: TP (0, 30, 0, 0, 0, 0) = URDF (0, 30, 30, 0, 0, 0).
  const std::array<double, 6> tp = fc.toControllerDeg(deg(0, 30, 30, 0, 0, 0));
  EXPECT_NEAR(tp[1], 30.0, 1e-12);
  EXPECT_NEAR(tp[2], 0.0, 1e-12);
  EXPECT_NEAR((fc.fromControllerDeg({{0, 30, 0, 0, 0, 0}}) - deg(0, 30, 30, 0, 0, 0)).norm(), 0.0, 1e-15);
  // github.com/ros-industrial/fanuc_experimental issue 17: joint_3 = -0.0352, joint_2 = 0.5467 rad
  // showed TP J3 = -33.342 deg.
  JointVector q = JointVector::Zero();
  q[1] = 0.5467;
  q[2] = -0.0352;
  EXPECT_NEAR(fc.toControllerDeg(q)[2], -33.342, 0.005);
  // The J3 range (-185..273.12) applies to TP J3: J2 = 100, J3 = 200 is inside although the URDF
  // angle q3 = 300 deg is outside the URDF box.
  const JointVector inside = fc.fromControllerDeg({{0, 100, 200, 0, 0, 0}});
  EXPECT_LT(ik.chain().limitMargin(inside), 0.0);
  EXPECT_GT(fc.limitMargin(inside), 0.0);
  EXPECT_NEAR(radToDeg(fc.limitMargin(fc.fromControllerDeg({{0, 0, 280, 0, 0, 0}}))), 273.12 - 280, 1e-3);
}

// The three check poses of the clean model of test_fanuc_spec_model.cpp (after 004_bd0df31205c0c3c0.txt App.
// C.1) of the ArcMate 120iC in pendant joints, FANUC World (= base).
TEST(ControllerConvention, FanucSpecPosesInPendantJoints)
{
  const ArmIk ik = fanuc();
  const ControllerConvention fc(Controller::FanucR30ib, ik.chain());
  struct Case {
    std::array<double, 6> j;
    Vec3 xyz, wpr;
  };
  const Case cases[] = {
      {{{0, 0, 0, 0, -90, 0}}, {985, 0, 940}, {180, 0, 0}},
      {{{30, 10, -20, 40, -60, 90}}, {1051.151, 542.603, 647.893}, {175.414, 37.159, 136.013}}};
  for (const Case& c : cases) {
    const Transform t = ik.forward(fc.fromControllerDeg(c.j));
    EXPECT_NEAR((t.translation() - c.xyz).norm(), 0.0, 1e-3);
    const Vec3 wpr = fanucWpr(t.linear());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(wrapToPi(degToRad(wpr[i] - c.wpr[i])), 0.0, degToRad(1e-3)) << i;
  }
  // V19, J = 0: (1085, 0, 1040), W 180, P -90 (R then undefined with W).
  const Transform zero = ik.forward(JointVector::Zero());
  EXPECT_NEAR((zero.translation() - Vec3(1085, 0, 1040)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(fanucWpr(zero.linear())[1], -90.0, 1e-6);
}

TEST(KukaStatusTurn, KnownPoses)
{
  const ArmIk ik = kuka();
  // HOME: wrist in front, A3 = 90 >= phi, A5 = 0 -> S 'B010'; A2 < 0 -> T 'B000010'.
  KukaStatusTurn st = kukaStatusTurn(ik.model(), deg(0, -90, 90, 0, 0, 0));
  EXPECT_EQ(st.status, 2);
  EXPECT_EQ(st.turn, 2);
  // Overhead: A2 = -150 leans the upper arm back, A3 = 60 turns the forearm up, so the wrist
  // centre is at x = 260 - 680 cos 30 + 35 = -293.9 mm; A5 = -30 < 0.
  st = kukaStatusTurn(ik.model(), deg(0, -150, 60, 0, -30, 0));
  EXPECT_NEAR(ik.wristCentre(deg(0, -150, 60, 0, -30, 0)).x(), 260 - 680 * std::cos(degToRad(30)) + 35, 1e-9);
  EXPECT_EQ(st.status, 7);
  EXPECT_EQ(st.turn, 2 | 16);
  // Bit 1 changes where the arm is stretched: A3 = -atan(35/670) = -2.9904 deg on the KR 16.
  const double phi = -radToDeg(std::atan2(35.0, 670.0));
  EXPECT_NEAR(radToDeg(ik.model().stretchedJoint3()), phi, 1e-12);
  EXPECT_EQ(kukaStatusTurn(ik.model(), deg(0, -60, phi + 0.01, 0, 20, 0)).status & 2, 2);
  EXPECT_EQ(kukaStatusTurn(ik.model(), deg(0, -60, phi - 0.01, 0, 20, 0)).status & 2, 0);
  // T lists the negative axes, A1 first.
  EXPECT_EQ(kukaStatusTurn(ik.model(), deg(-1, 1, -1, 1, -1, 1)).turn, 1 | 4 | 16);
}

TEST(KukaStatusTurn, AgreesWithTheArmConfigurationAndRoundTrips)
{
  const ArmIk ik = kuka();
  std::mt19937 rng(3);
  int resolved = 0;
  for (int k = 0; k < 3000; ++k) {
    JointVector q;
    for (int i = 0; i < 6; ++i) {
      const ChainJoint& j = ik.chain().joint(static_cast<size_t>(i));
      q[i] = std::uniform_real_distribution<double>(j.lower, j.upper)(rng);
    }
    const KukaStatusTurn st = kukaStatusTurn(ik.model(), q);
    const ArmConfiguration c = ik.configurationOf(q);
    ASSERT_EQ((st.status & 1) != 0, !c.front);
    ASSERT_EQ((st.status & 2) != 0, c.up);
    ASSERT_EQ((st.status & 4) != 0, !c.noFlip);
    if (ik.dexterity(q) < 1e-3) continue;
    // Pose + S + T name exactly one in-limit joint vector: the one we started from.
    const std::optional<JointVector> back = kukaJointsFrom(ik, ik.forward(q), st.status, st.turn);
    ASSERT_TRUE(back);
    ASSERT_LT(((*back) - q).cwiseAbs().maxCoeff(), 1e-9);
    ++resolved;
  }
  EXPECT_GT(resolved, 2900);
}

TEST(FanucConfig, FormatAndParse)
{
  FanucConfig c;
  EXPECT_EQ(c.format(), "N U T, 0, 0, 0");
  c.flip = true;
  c.up = false;
  c.front = false;
  c.turns = {1, -1, 0};
  EXPECT_EQ(c.format(), "F D B, 1, -1, 0");
  EXPECT_EQ(FanucConfig::parse("F D B, 1, -1, 0"), c);
  EXPECT_EQ(FanucConfig::parse("FDB,1,-1,0"), c);
  EXPECT_EQ(FanucConfig::parse(c.format()), c);
  EXPECT_THROW(FanucConfig::parse("N U X, 0, 0, 0"), InputError);
  EXPECT_THROW(FanucConfig::parse("N U T, 0, 0"), InputError);
  EXPECT_THROW(FanucConfig::parse("N U T, 0, a, 0"), InputError);
}

TEST(FanucConfig, TurnNumbers)
{
  EXPECT_EQ(fanucTurnNumber(0.0), 0);
  EXPECT_EQ(fanucTurnNumber(179.9), 0);
  EXPECT_EQ(fanucTurnNumber(-179.9), 0);
  EXPECT_EQ(fanucTurnNumber(180.0), 1);
  EXPECT_EQ(fanucTurnNumber(539.0), 1);
  EXPECT_EQ(fanucTurnNumber(540.0), 2);
  EXPECT_EQ(fanucTurnNumber(-180.0), -1);
  EXPECT_EQ(fanucTurnNumber(-270.0), -1);
}

TEST(FanucConfig, KnownPosesAndRoundTrip)
{
  ArmIk ik = fanuc();
  const ControllerConvention fc(Controller::FanucR30ib, ik.chain());
  fc.applyTo(ik);
  // The usual pose, flange tilted down (J5 = -90): N U T.
  EXPECT_EQ(fanucConfig(ik.model(), fc.fromControllerDeg({{0, 0, 0, 0, -90, 0}})).format(), "N U T, 0, 0, 0");
  EXPECT_EQ(fanucConfig(ik.model(), fc.fromControllerDeg({{-20, 10, -10, 190, 30, -200}})).format(),
            "F U T, 0, 1, -1");
  JointPoint p;
  fc.describe(ik.model(), fc.fromControllerDeg({{0, 0, 0, 0, -90, 0}}), p);
  EXPECT_EQ(p.fanucConfig, "N U T, 0, 0, 0");
  EXPECT_NEAR(p.robotDeg[4], -90.0, 1e-12);

  std::mt19937 rng(4);
  int resolved = 0, tried = 0;
  while (tried < 3000) {
    std::array<double, 6> j;
    for (size_t i = 0; i < 6; ++i)
      j[i] =
          std::uniform_real_distribution<double>(fc.axisLimits()[i].minDeg, fc.axisLimits()[i].maxDeg)(rng);
    j[2] = std::uniform_real_distribution<double>(-180.0, 180.0)(rng);  // the CONFIG leaves J3's turn open
    const JointVector q = fc.fromControllerDeg(j);
    if (ik.dexterity(q) < 1e-3) continue;
    ++tried;
    const FanucConfig c = fanucConfig(ik.model(), q);
    EXPECT_EQ(FanucConfig::parse(c.format()), c);
    const ArmConfiguration a = ik.configurationOf(q);
    ASSERT_EQ(c.front, a.front);
    ASSERT_EQ(c.up, a.up);
    ASSERT_EQ(c.flip, !a.noFlip);
    const std::optional<JointVector> back = fanucJointsFrom(ik, ik.forward(q), c);
    ASSERT_TRUE(back) << c.format();
    for (int i = 0; i < 6; ++i)
      ASSERT_NEAR((*back)[i], q[i], 1e-9) << "joint " << i + 1 << " of " << c.format();
    ++resolved;
  }
  EXPECT_EQ(resolved, tried);

  // J3 = 200 and J3 = -160 are the same arm; the CONFIG resolves to -160.
  const JointVector j3 = fc.fromControllerDeg({{10, 20, 200, 30, -40, 50}});
  const std::optional<JointVector> back = fanucJointsFrom(ik, ik.forward(j3), fanucConfig(ik.model(), j3));
  ASSERT_TRUE(back);
  EXPECT_NEAR(fc.toControllerDeg(*back)[2], -160.0, 1e-9);
}

}  // namespace
}  // namespace spira
