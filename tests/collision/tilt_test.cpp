#include <gtest/gtest.h>

#include <cmath>

#include "collision/plan_builders.h"
#include "spira/base/units.h"
#include "spira/collision/tilt_about_tangent.h"
#include "spira/collision/tilt_ramp.h"

namespace spira {
namespace {

TEST(TiltAboutTangent, TurnsNAndBAboutTKeepingAnOrthonormalFrame)
{
  const TrajectoryPoint p = test::helixPlan(50.0, 1.0, 1, 36).points[5];
  for (const double deg : {-40.0, -3.0, 7.5, 30.0}) {
    const double a = degToRad(deg);
    const TrajectoryPoint q = tiltAboutTangent(p, a);
    EXPECT_NEAR(q.build.norm(), 1.0, 1e-14);
    EXPECT_NEAR(q.normal.norm(), 1.0, 1e-14);
    EXPECT_NEAR(q.normal.dot(q.tangent), 0.0, 1e-14);
    EXPECT_NEAR(q.build.dot(q.tangent), 0.0, 1e-14);
    EXPECT_NEAR((q.normal.cross(q.tangent) - q.build).norm(), 0.0, 1e-14);
    EXPECT_NEAR((q.tangent - p.tangent).norm(), 0.0, 1e-14);
    EXPECT_EQ(q.position, p.position);
    // b' = cos a b + sin a n: the angle to b is |a|, and a positive angle leans towards +n.
    EXPECT_NEAR(q.build.dot(p.build), std::cos(a), 1e-14);
    EXPECT_NEAR(q.build.dot(p.normal), std::sin(a), 1e-14);
  }
  EXPECT_EQ(tiltAboutTangent(p, 0.0), p);
}

TEST(TiltRamp, RampsInAndOutAtTheAllowedRateAndMergesNeighbours)
{
  const std::vector<double> e = rampEnvelope({0, 0, 5, 0, 0, 0, 0, 0, 3, 0}, 2.0);
  const std::vector<double> expected = {1, 3, 5, 3, 1, 0, 0, 1, 3, 1};
  ASSERT_EQ(e.size(), expected.size());
  for (size_t i = 0; i < e.size(); ++i) EXPECT_DOUBLE_EQ(e[i], expected[i]) << i;
  // Close requirements merge: the lower one lies under the higher one's ramp.
  const std::vector<double> m = rampEnvelope({0, 6, 0, 3, 0}, 2.0);
  const std::vector<double> mergedExpected = {4, 6, 4, 3, 1};
  for (size_t i = 0; i < m.size(); ++i) EXPECT_DOUBLE_EQ(m[i], mergedExpected[i]) << i;
}

}  // namespace
}  // namespace spira
