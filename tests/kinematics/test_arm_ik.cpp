#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>

#include "robot_files.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/arm_ik.h"

namespace spira {
namespace {

using test::positionGap;
using test::robotUrdf;
using test::rotationGap;

class ArmIkRoundTrip : public ::testing::TestWithParam<const char*> {};

JointVector randomWithinLimits(const KinematicChain& c, std::mt19937& rng)
{
  JointVector q;
  for (int i = 0; i < 6; ++i) {
    const ChainJoint& j = c.joint(static_cast<size_t>(i));
    q[i] = std::uniform_real_distribution<double>(j.lower, j.upper)(rng);
  }
  return q;
}

double jointGapModulo2Pi(const JointVector& a, const JointVector& b)
{
  double g = 0.0;
  for (int i = 0; i < 6; ++i) g = std::max(g, std::abs(wrapToPi(a[i] - b[i])));
  return g;
}

// 10,000 random poses reachable in each of the 8 configurations (joint vectors drawn within the
// limits, kept when they fall in that configuration): the IK of that configuration returns the
// drawn joints and its forward kinematics lands on the pose.
TEST_P(ArmIkRoundTrip, TenThousandPosesPerConfiguration)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf(GetParam()), "base_link", "tool0"));
  std::mt19937 rng(2024);
  double worstPosition = 0.0, worstOrientation = 0.0, worstJoint = 0.0;
  for (const ArmConfiguration& c : ArmConfiguration::all()) {
    int accepted = 0, nearSingular = 0;
    while (accepted < 10000) {
      const JointVector q = randomWithinLimits(ik.chain(), rng);
      if (ik.configurationOf(q) != c) continue;
      ++accepted;
      const Transform target = ik.forward(q);
      const std::optional<IkSolution> s = ik.solve(target, c, randomWithinLimits(ik.chain(), rng));
      ASSERT_TRUE(s) << c.label();
      const Transform reached = ik.forward(s->q);
      worstPosition = std::max(worstPosition, positionGap(reached, target));
      worstOrientation = std::max(worstOrientation, rotationGap(reached, target));
      ASSERT_EQ(ik.configurationOf(s->q), c) << c.label();
      // Away from singularities the configuration pins the joints down (modulo 2 pi).
      if (ik.dexterity(q) < 1e-3) {
        ++nearSingular;
        continue;
      }
      worstJoint = std::max(worstJoint, jointGapModulo2Pi(s->q, q));
    }
    EXPECT_LT(nearSingular, 100) << c.label();
  }
  EXPECT_LT(worstPosition, 1e-6);     // mm
  EXPECT_LT(worstOrientation, 1e-8);  // rad
  EXPECT_LT(radToDeg(worstJoint), 1e-7);
  char text[96];
  std::snprintf(text, sizeof text, "%.3g mm, %.3g rad, %.3g deg", worstPosition, worstOrientation,
                radToDeg(worstJoint));
  RecordProperty("worst_errors", text);
}

// solveAll: every solution reaches the pose, carries its own configuration label, and the drawn
// joint vector is among them.
TEST_P(ArmIkRoundTrip, SolveAllReturnsEveryBranchAndTheDrawnOne)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf(GetParam()), "base_link", "tool0"));
  std::mt19937 rng(99);
  std::array<int, 8> seen{};
  for (int k = 0; k < 2000; ++k) {
    const JointVector q = randomWithinLimits(ik.chain(), rng);
    const Transform target = ik.forward(q);
    const std::vector<IkSolution> all = ik.solveAll(target);
    ASSERT_FALSE(all.empty());
    bool found = false;
    for (const IkSolution& s : all) {
      ASSERT_LT(s.positionError, 1e-9);
      ASSERT_LT(positionGap(ik.forward(s.q), target), 1e-6);
      ASSERT_LT(rotationGap(ik.forward(s.q), target), 1e-8);
      ASSERT_EQ(ik.configurationOf(s.q), s.configuration);
      ASSERT_EQ(s.withinLimits, ik.chain().limitMargin(s.q) >= 0.0);
      ++seen[static_cast<size_t>(s.configuration.index())];
      if (jointGapModulo2Pi(s.q, q) < 1e-7) found = true;
    }
    if (ik.dexterity(q) > 1e-3) {
      ASSERT_TRUE(found) << "pose " << k;
    }
  }
  for (int i = 0; i < 8; ++i)
    EXPECT_GT(seen[static_cast<size_t>(i)], 0) << ArmConfiguration::fromIndex(i).label();
}

INSTANTIATE_TEST_SUITE_P(BundledArms, ArmIkRoundTrip, ::testing::Values("kuka_kr16_2", "fanuc_m20ia"));

TEST(ArmIk, OffersJoint4And6OneTurnAwayWhenWithinLimits)
{
  // KUKA A4 and A6 range +-350 deg: a wrist at A4 = 20, A6 = -30 can also be A4 = 20 - 360 and
  // A6 = -30 + 360; A1 (+-185) has no second turn at 10 deg.
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  JointVector q;
  q << degToRad(10), degToRad(-80), degToRad(70), degToRad(20), degToRad(40), degToRad(-30);
  const std::vector<IkSolution> all = ik.solveAll(ik.forward(q));
  int same = 0;
  bool turned4 = false, turned6 = false, both = false;
  for (const IkSolution& s : all) {
    if (jointGapModulo2Pi(s.q, q) > 1e-9) continue;
    ++same;
    const double a4 = radToDeg(s.q[3]), a6 = radToDeg(s.q[5]);
    EXPECT_NEAR(radToDeg(s.q[0]), 10.0, 1e-9);
    turned4 |= std::abs(a4 + 340.0) < 1e-7 && std::abs(a6 + 30.0) < 1e-7;
    turned6 |= std::abs(a4 - 20.0) < 1e-7 && std::abs(a6 - 330.0) < 1e-7;
    both |= std::abs(a4 + 340.0) < 1e-7 && std::abs(a6 - 330.0) < 1e-7;
    EXPECT_TRUE(s.withinLimits);
  }
  EXPECT_EQ(same, 4);
  EXPECT_TRUE(turned4 && turned6 && both);
}

TEST(ArmIk, FlagsSolutionsOutsideTheLimitsButStillReturnsThem)
{
  // KUKA A5 is limited to +-130 deg; the flipped wrist of a pose with A5 = 120 has A5 = -120,
  // but a pose with the wrist bent to A5 = 140 (outside) still comes back, flagged.
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  JointVector q;
  q << 0.0, degToRad(-70), degToRad(60), degToRad(10), degToRad(140), degToRad(5);
  bool sawOutside = false;
  for (const IkSolution& s : ik.solveAll(ik.forward(q)))
    if (jointGapModulo2Pi(s.q, q) < 1e-9) {
      sawOutside = true;
      EXPECT_FALSE(s.withinLimits);
      EXPECT_NEAR(radToDeg(s.limitMargin), -10.0, 1e-7);
    }
  EXPECT_TRUE(sawOutside);
}

TEST(ArmIk, OutOfReachGivesNoSolution)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  Transform far = Transform::Identity();
  far.translation() = Vec3(3000, 0, 500);
  EXPECT_TRUE(ik.solveAll(far).empty());
  EXPECT_FALSE(ik.solve(far, ArmConfiguration{}, JointVector::Zero()));
  Transform bad = far;
  bad.translation().x() = std::nan("");
  EXPECT_THROW(ik.solveAll(bad), InputError);
}

TEST(ArmIk, RefinementReachesTheChainWhenTheModelIsOnlyClose)
{
  // The KR 16 with axis 3 turned 5e-7 rad about the vertical: within the detection's tolerance, so
  // the OPW closed form is up to ~1e-3 mm off the chain, and the Newton steps on the chain itself
  // must close that gap.
  std::string text;
  {
    std::ifstream in(robotUrdf("kuka_kr16_2"));
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string exact = "xyz=\"0.68 0 0\" rpy=\"0 0 0\"";
  const size_t at = text.find(exact);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, exact.size(), "xyz=\"0.68 0 0\" rpy=\"0 0 5e-7\"");
  const ArmIk ik(KinematicChain::fromUrdfString(text, "base_link", "tool0"));
  std::mt19937 rng(5);
  double modelGap = 0.0;
  for (int k = 0; k < 200; ++k) {
    const JointVector q = randomWithinLimits(ik.chain(), rng);
    const Transform target = ik.forward(q);
    modelGap = std::max(modelGap, positionGap(ik.model().forward(q), target));
    const std::optional<IkSolution> s = ik.solve(target, ik.configurationOf(q), q);
    ASSERT_TRUE(s);
    EXPECT_LT(s->positionError, 1e-9);
    EXPECT_LT(s->orientationError, 1e-12);
    EXPECT_LT(positionGap(ik.forward(s->q), target), 1e-9);
  }
  EXPECT_GT(modelGap, 1e-5);  // the closed form alone would not have been enough
}

}  // namespace
}  // namespace spira
