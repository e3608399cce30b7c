#include <gtest/gtest.h>

#include <cmath>

#include "motion_fixtures.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/motion/motion_checks.h"
#include "spira/motion/motion_solver.h"

namespace spira {
namespace {

TEST(MotionChecks, SpeedRatioOfAHandMadeTrajectory)
{
  Trajectory path;
  for (double x : {0.0, 10.0, 30.0}) {
    TrajectoryPoint p;
    p.position = Vec3(x, 0, 0);
    path.points.push_back(p);
  }
  path.points[1].travelSpeed = 5.0;   // 10 mm at 5 mm/s: 2 s
  path.points[2].travelSpeed = 10.0;  // 20 mm at 10 mm/s: 2 s
  JointTrajectory jt;
  jt.hasPositioner = true;
  for (size_t j = 0; j < 6; ++j) jt.robotLimits[j] = {"A" + std::to_string(j + 1), -180, 180, 100};
  jt.externalLimits = {AxisLimit{"E1", -90, 90, 50}, AxisLimit{"E2", -1000, 1000, 120}};
  jt.points.resize(3);
  jt.points[1].robotDeg[0] = 10;      // 5 deg/s of 100: 0.05
  jt.points[2].robotDeg[0] = 50;      // 20 deg/s: 0.2
  jt.points[1].externalDeg[1] = 100;  // 50 deg/s of 120: 0.4167
  jt.points[2].externalDeg[1] = 100;
  jt.points[2].robotDeg[3] = 170;  // A4 170 deg: 10 deg from its limit
  jt.points[1].robotDeg[3] = -60;  // -60 -> 170 in 2 s: 115 deg/s of 100: 1.15
  MotionReport r;
  checkMotion(path, jt, {true, true, true}, 0.0, r);
  EXPECT_NEAR(r.maxSpeedRatio, 115.0 / 100.0, 1e-12);
  EXPECT_EQ(r.maxSpeedRatioAxis, "A4");
  EXPECT_EQ(r.maxSpeedRatioPoint, 2u);
  EXPECT_EQ(r.segmentsWithoutSpeed, 0u);
  EXPECT_NEAR(r.minLimitMarginDeg, 10.0, 1e-12);
  EXPECT_EQ(r.minLimitMarginAxis, "A4");
  EXPECT_EQ(r.minLimitMarginPoint, 2u);
  EXPECT_NEAR(r.maxCableTwistDeg, 170.0, 1e-12);
  EXPECT_TRUE(r.withinCableTwistLimit);  // no limit given
  EXPECT_TRUE(r.reachable);

  // Without A4's jump the positioner is the fastest; a point without travel speed is skipped.
  jt.points[0].robotDeg[3] = 170;
  jt.points[1].robotDeg[3] = 170;
  path.points[2].travelSpeed = 0.0;
  MotionReport r2;
  checkMotion(path, jt, {true, true, true}, 120.0, r2);
  EXPECT_NEAR(r2.maxSpeedRatio, 50.0 / 120.0, 1e-12);
  EXPECT_EQ(r2.maxSpeedRatioAxis, "E2");
  EXPECT_EQ(r2.maxSpeedRatioPoint, 1u);
  EXPECT_EQ(r2.segmentsWithoutSpeed, 1u);
  EXPECT_FALSE(r2.withinCableTwistLimit);
}

TEST(MotionChecks, TurntableSpeedRatioIsTheTableTurnOverTheChordTime)
{
  // A circle of radius 80 mm in 360 points at 10 mm/s on the positioner: each chord
  // 2 r sin(0.5 deg) takes chord / 10 s while the table turns 1 deg; the robot stands still.
  test::FanucPositionerCell cell;
  const Trajectory path = test::stackedCircles(80, 2, 360, 0, 2, 10.0);
  cell.seedAt(path);
  NullProgress progress;
  const MotionResult r = solveMotion(cell.ik, cell.convention, path, cell.setup, MotionParams{}, progress);
  const double chord = 2 * 80 * std::sin(degToRad(0.5));
  const double expected = (1.0 / (chord / 10.0)) / 120.0;
  // The step from one layer to the next climbs 2 mm as well; every other segment is a chord.
  EXPECT_NEAR(r.report.maxSpeedRatio, expected, 1e-9 * expected);
  EXPECT_EQ(r.report.maxSpeedRatioAxis, "E2");
  EXPECT_NEAR(expected, 0.05968, 1e-5);  // 7.16 deg/s of 120
}

TEST(MotionChecks, UnreachablePointsAreListedByIndexNeverClipped)
{
  // A straight run away from the KUKA at 300 mm height, torch straight down. The wrist centre is
  // 350 + 158 mm above the TCP, and the arm reaches it while its distance from the axis of A2
  // (260 mm out from A1, 675 mm up) is at most 680 + sqrt(670^2 + 35^2) mm.
  test::KukaCell cell;
  cell.setup.basePart = Transform::Identity();
  Trajectory path;
  const double reach = 680.0 + std::sqrt(670.0 * 670.0 + 35.0 * 35.0);
  std::vector<size_t> expected;
  for (int k = 0; k < 100; ++k) {
    TrajectoryPoint p;
    p.position = Vec3(1000.0 + 8.0 * k + 3.0, 0, 300);
    p.normal = Vec3(0, -1, 0);
    p.tangent = Vec3(1, 0, 0);
    p.build = p.normal.cross(p.tangent);  // +Z
    p.travelSpeed = 10.0;
    path.points.push_back(p);
    const double d = std::hypot(p.position.x() - 260.0, 300.0 + 508.0 - 675.0);
    if (d > reach) expected.push_back(static_cast<size_t>(k));
  }
  ASSERT_GT(expected.size(), 10u);
  ASSERT_LT(expected.size(), 90u);
  cell.seedAt(path);
  for (bool optimise : {false, true}) {
    MotionParams params;
    params.optimiseSpin = optimise;
    NullProgress progress;
    const MotionResult r = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
    ASSERT_EQ(r.joints.size(), path.size());
    EXPECT_EQ(r.report.unreachable, expected);
    EXPECT_FALSE(r.report.reachable);
    for (size_t i = 0; i < path.size(); ++i) {
      const bool out = std::find(expected.begin(), expected.end(), i) != expected.end();
      EXPECT_EQ(r.joints.points[i].reachable, !out) << i;
    }
  }
}

TEST(MotionSolver, ReportsProgressAndStopsWhenCancelled)
{
  test::KukaCell cell;
  const Trajectory path = test::domeSpiral(100, 50, 3, 120);
  cell.seedAt(path);
  std::vector<double> fractions;
  CallbackProgress progress([&](double f, std::string_view) { fractions.push_back(f); });
  solveMotion(cell.ik, cell.convention, path, cell.setup, MotionParams{}, progress);
  ASSERT_GT(fractions.size(), 3u);
  for (size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1] - 1e-12);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);

  CallbackProgress* self = nullptr;
  CallbackProgress cancelling([&](double f, std::string_view) {
    if (f > 0.2) self->cancel();
  });
  self = &cancelling;
  EXPECT_THROW(solveMotion(cell.ik, cell.convention, path, cell.setup, MotionParams{}, cancelling),
               Cancelled);
}

TEST(MotionSolver, RejectsBadParametersAndInput)
{
  test::KukaCell cell;
  const Trajectory path = test::stackedCircles(100, 1, 36, 0, 1);
  cell.seedAt(path);
  NullProgress progress;
  auto solveWith = [&](const MotionParams& p) {
    solveMotion(cell.ik, cell.convention, path, cell.setup, p, progress);
  };
  MotionParams p;
  p.degree = 7;
  EXPECT_THROW(solveWith(p), InputError);
  p = MotionParams{};
  p.limitMarginDeg = -1;
  EXPECT_THROW(solveWith(p), InputError);
  p = MotionParams{};
  p.searchSamples = 2;
  EXPECT_THROW(solveWith(p), InputError);
  p = MotionParams{};
  p.dexterityFloor = 1.5;
  EXPECT_THROW(solveWith(p), InputError);
  EXPECT_THROW(solveMotion(cell.ik, cell.convention, Trajectory{}, cell.setup, MotionParams{}, progress),
               InputError);
  Trajectory broken = path;
  broken.points[3].position.x() = std::nan("");
  EXPECT_THROW(solveMotion(cell.ik, cell.convention, broken, cell.setup, MotionParams{}, progress),
               InputError);
}

}  // namespace
}  // namespace spira
