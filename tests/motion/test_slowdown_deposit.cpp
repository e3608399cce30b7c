// The deposit a controller lays when it slows down where an axis cannot keep up
// (slowdown_deposit.h), with numbers worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/motion/slowdown_deposit.h"

namespace spira {
namespace {

Trajectory fourPoints(double height, double travelSpeed, double wireFeed)
{
  Trajectory t;
  for (int i = 0; i < 4; ++i) {
    TrajectoryPoint p;
    p.position = Vec3(i, 0, 0);
    p.height = height;
    p.travelSpeed = travelSpeed;
    p.wireFeed = wireFeed;
    t.points.push_back(p);
  }
  return t;
}

TEST(SlowdownDeposit, MassConservationThickensTheBeadByTheSlowdownFactor)
{
  const Trajectory path = fourPoints(2.0, 2.9, 38.3);
  ProcessSettings process;
  const DepositWindow window{1.8, 2.2, 0.01};
  const SlowdownReport r = slowdownDeposit(path, {0.0, 0.8, 1.05, 1.2}, process, window);
  EXPECT_EQ(r.model, "mass_conservation");
  ASSERT_EQ(r.points.size(), 2u);  // points at or below 100 % are not slowed
  EXPECT_EQ(r.points[0].point, 2u);
  EXPECT_NEAR(r.points[0].slowedHeight, 2.1, 1e-12);  // 2 mm x 1.05
  EXPECT_TRUE(r.points[0].fits);
  EXPECT_NEAR(r.points[1].slowedHeight, 2.4, 1e-12);  // 2 mm x 1.2: past 2.2 + 0.01
  EXPECT_FALSE(r.points[1].fits);
  EXPECT_EQ(r.outsideWindow, 1u);
  EXPECT_FALSE(r.fits());
  EXPECT_DOUBLE_EQ(r.maxFactor, 1.2);
  EXPECT_EQ(r.maxSlowedHeightPoint, 3u);
  // Mass conservation itself: h = pi d^2 WFS / (4 W TS) at the slowed speed.
  EXPECT_NEAR(r.points[1].slowedHeight / 2.0,
              massConservationHeight(1.0, 5.2, 38.3, 2.9 / 1.2) / massConservationHeight(1.0, 5.2, 38.3, 2.9),
              1e-12);
}

TEST(SlowdownDeposit, CalibrationReadsTheTableAtTheSlowedSpeed)
{
  ProcessSettings process;
  process.model = HeightModel::Calibration;
  process.calibration = CalibrationTable({1.8, 2.0, 2.2}, {3.2, 2.9, 2.6});
  process.wireFeed = 40.0;  // the table's wire feed
  // Planned at half the table's wire feed and half its speed: the table's 2.0 mm bead (2.9 mm/s).
  const Trajectory path = fourPoints(2.0, 1.45, 20.0);
  const SlowdownReport r = slowdownDeposit(path, {0.0, 2.9 / 2.75, 2.9 / 2.5, 1.0}, process, {1.8, 2.2, 0.0});
  EXPECT_EQ(r.model, "calibration");
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_NEAR(r.points[0].slowedHeight, 2.1, 1e-12);  // 2.75 mm/s at the table's feed: halfway 2.0 .. 2.2
  EXPECT_TRUE(r.points[0].fits);
  // 2.5 mm/s is slower than the slowest bead measured: thicker than anything in the table.
  EXPECT_TRUE(std::isinf(r.points[1].slowedHeight));
  EXPECT_FALSE(r.points[1].fits);
}

}  // namespace
}  // namespace spira
