// The rotary axis wound into its range by whole turns (positioner_path.h), on axis values made
// in code with numbers worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/units.h"
#include "spira/motion/positioner_path.h"

namespace spira {
namespace {

// A positioner chain whose axes have the given limits (deg).
KinematicChain chainWithLimits(double e1Lo, double e1Hi, double e2Lo, double e2Hi)
{
  std::vector<ChainJoint> joints(2);
  joints[0].name = "e1";
  joints[0].axis = Vec3::UnitY();
  joints[0].lower = degToRad(e1Lo);
  joints[0].upper = degToRad(e1Hi);
  joints[1].name = "e2";
  joints[1].lower = degToRad(e2Lo);
  joints[1].upper = degToRad(e2Hi);
  return KinematicChain("base", "table", joints, Transform::Identity());
}

// E2 from `start` deg turning `turns` times (negative: clockwise), E1 at 10 deg.
std::vector<Eigen::Vector2d> spiralAxes(double start, double turns)
{
  std::vector<Eigen::Vector2d> axes;
  for (int i = 0; i <= 1000; ++i)
    axes.emplace_back(degToRad(10.0), degToRad(start + 360.0 * turns * i / 1000.0));
  return axes;
}

TEST(PositionerWinding, AnAxisAlreadyInsideItsRangeIsLeftAlone)
{
  std::vector<Eigen::Vector2d> axes = spiralAxes(-87.0, -90.0);  // down to -32,487 deg
  const std::vector<Eigen::Vector2d> before = axes;
  const std::array<int, 2> turns = windToFit(axes, std::vector<bool>(axes.size(), true),
                                             chainWithLimits(-135, 135, -36000, 36000), degToRad(2));
  EXPECT_EQ(turns[0], 0);
  EXPECT_EQ(turns[1], 0);
  EXPECT_EQ(axes, before);
}

TEST(PositionerWinding, ASpiralTooLongFromZeroIsWoundFromTheOtherEnd)
{
  // The vase of issue 14: -87 .. -39,147 deg on a +-36,000 deg axis. The fewest whole turns that
  // fit: 9 (3,153 .. -35,907 deg); 8 would leave it at -36,267.
  std::vector<Eigen::Vector2d> axes = spiralAxes(-87.0, -108.5);
  const std::array<int, 2> turns = windToFit(axes, std::vector<bool>(axes.size(), true),
                                             chainWithLimits(-135, 135, -36000, 36000), degToRad(2));
  EXPECT_EQ(turns[0], 0);  // the tilt has no room for a turn
  EXPECT_EQ(turns[1], 9);
  EXPECT_NEAR(radToDeg(axes.front()[1]), -87.0 + 3240.0, 1e-9);
  EXPECT_NEAR(radToDeg(axes.back()[1]), -39147.0 + 3240.0, 1e-9);
  EXPECT_NEAR(radToDeg(axes.front()[0]), 10.0, 1e-12);
  // Counter-clockwise the same spiral winds up from the low end.
  axes = spiralAxes(87.0, 108.5);
  EXPECT_EQ(windToFit(axes, std::vector<bool>(axes.size(), true), chainWithLimits(-135, 135, -36000, 36000),
                      degToRad(2))[1],
            -9);
  EXPECT_GE(radToDeg(axes.front()[1]), -36000.0 + 2.0);
  EXPECT_LE(radToDeg(axes.back()[1]), 36000.0 - 2.0);
}

TEST(PositionerWinding, MarginIsDroppedBeforeTheRangeAndUnreachedPointsDoNotCount)
{
  // 719 deg of travel on a +-360 deg axis fits only without the 2 deg margin.
  std::vector<Eigen::Vector2d> axes = spiralAxes(-359.0, 719.0 / 360.0);
  std::vector<bool> reached(axes.size(), true);
  axes.back()[1] = degToRad(5000.0);  // a point the positioner did not reach
  reached.back() = false;
  const std::array<int, 2> turns =
      windToFit(axes, reached, chainWithLimits(-135, 135, -360, 360), degToRad(2));
  EXPECT_EQ(turns[1], 0);  // -359 .. 360 fits as it is
  // Too long for the axis: centred between the limits, the overshoot shared by both ends.
  axes = spiralAxes(0.0, 3.0);
  windToFit(axes, std::vector<bool>(axes.size(), true), chainWithLimits(-135, 135, -360, 360), 0.0);
  EXPECT_NEAR(radToDeg(axes.front()[1]), -720.0, 1e-9);
  EXPECT_NEAR(radToDeg(axes.back()[1]), 360.0, 1e-9);
}

}  // namespace
}  // namespace spira
