#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "document_test_data.h"
#include "spira/base/error.h"
#include "spira/document/project_file.h"

namespace spira {
namespace {

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(KinematicsResult, ChecksComeFromThePointsAndTheAxisLimits)
{
  const KinematicsResult k = test::sampleKinematics(7);
  ASSERT_EQ(k.checks.size(), 7u);
  ASSERT_EQ(k.axes.size(), 8u);  // six robot axes and the positioner's two
  EXPECT_EQ(k.axes[6].name, "E1");
  EXPECT_FALSE(k.checks[2].reachable);
  EXPECT_TRUE(k.checks[1].reachable);
  EXPECT_TRUE(k.checks[5].collision);
  EXPECT_EQ(k.collisionCount(), 1u);
  EXPECT_FALSE(k.allReachable());
  EXPECT_EQ(k.checks[3].dexterity, 1.0 / 6.0);
  double expected = std::numeric_limits<double>::infinity();
  const std::vector<double> v = axisValuesDeg(k, 0);
  ASSERT_EQ(v.size(), 8u);
  for (size_t a = 0; a < 8; ++a)
    expected = std::min({expected, v[a] - k.axes[a].minDeg, k.axes[a].maxDeg - v[a]});
  EXPECT_EQ(k.checks[0].limitMarginDeg, expected);
  // E1 = -20/3 lies 128.33 deg from -135; J6 = -15 lies 150 from its min -165 and 150.5 from 165.5.
  EXPECT_NEAR(k.checks[0].limitMarginDeg, 135.0 - 20.0 / 3.0, 1e-9);
  // Point 6: E2 = 6000.1, J1..J6 about 0.6 - 3k: still E1 closest.
  EXPECT_NEAR(k.checks[6].limitMarginDeg, 135.0 - 20.0 / 3.0, 1e-9);
}

TEST(KinematicsResult, RobotOnlyResultHasSixAxes)
{
  JointTrajectory j;
  j.robotLimits[4] = AxisLimit{"A5", -120.0, 120.0, 300.0};
  JointPoint p;
  p.robotDeg = {0, 0, 0, 0, 119.5, 0};
  j.points.push_back(p);
  const KinematicsResult k = makeKinematicsResult(j, test::sampleTrajectory(1));
  ASSERT_EQ(k.axes.size(), 6u);
  EXPECT_DOUBLE_EQ(k.checks[0].limitMarginDeg, 0.5);
  EXPECT_EQ(axisValuesDeg(k, 0).size(), 6u);
}

TEST(KinematicsResult, ProjectRoundTripIsBitForBit)
{
  const DocumentState s = test::fullState();
  const DocumentState back = decodeProject(encodeProject(s));
  ASSERT_TRUE(back.results.kinematics);
  const KinematicsResult& a = *s.results.kinematics;
  const KinematicsResult& b = *back.results.kinematics;
  EXPECT_EQ(a, b);
  ASSERT_EQ(b.size(), 7u);
  EXPECT_TRUE(std::signbit(b.joints.points[0].robotDeg[1]));
  EXPECT_EQ(b.joints.points[4].dexterity, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(b.joints.points[5].fanucConfig, "F D B, -1, 0, 1");
  EXPECT_EQ(b.joints.points[1].fanucConfig, "N U T, 0, 0, 0");
  EXPECT_EQ(b.joints.points[6].kukaTurn, 57);
  EXPECT_TRUE(b.joints.hasPositioner);
  EXPECT_EQ(b.joints.externalLimits[1].name, "E2");
  for (size_t i = 0; i < a.size(); ++i)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        EXPECT_TRUE(
            sameBits(a.joints.points[i].baseTcp.matrix()(r, c), b.joints.points[i].baseTcp.matrix()(r, c)));
  EXPECT_EQ(b.path, a.path);
  // A changed value is seen by ==.
  KinematicsResult c = b;
  c.joints.points[3].baseTcp.translation().x() += 1e-9;
  EXPECT_NE(c, a);
}

TEST(KinematicsResult, DamagedJointsAreAnInputError)
{
  DocumentState s = test::fullState();
  nlohmann::json j = resultsToJson(s.results);
  j["kinematics"]["joints"]["count"] = 8;  // blobs hold 7
  EXPECT_THROW(resultsFromJson(j), InputError);
  j = resultsToJson(s.results);
  j["kinematics"]["joints"]["fanuc_configs"] = nlohmann::json::array({"only one"});
  EXPECT_THROW(resultsFromJson(j), InputError);
}

TEST(KinematicsResult, SchemaOneKinematicsPayloadIsDropped)
{
  DocumentState s = test::fullState();
  nlohmann::json j = resultsToJson(s.results);
  j["schema"] = 1;
  j["kinematics"] = {{"payload", {{"reachable", true}}}};
  const Results r = resultsFromJson(j);
  EXPECT_FALSE(r.kinematics);
  EXPECT_TRUE(r.process);
}

}  // namespace
}  // namespace spira
