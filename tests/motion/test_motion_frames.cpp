#include <gtest/gtest.h>

#include <cmath>

#include "motion_fixtures.h"
#include "spira/base/units.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/motion/motion_frames.h"
#include "spira/motion/motion_layers.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

double rotationGap(const Mat3& a, const Mat3& b)
{
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

TEST(MotionFrames, SpinAboutTheTorchReproducesToolFrame)
{
  test::KukaCell cell;
  const Trajectory path = test::domeSpiral(90, 30, 2, 48);
  NullProgress progress;
  const MotionFrames frames = buildMotionFrames(path, cell.setup, MotionParams{}, progress);
  ASSERT_EQ(frames.baseTcp0.size(), path.size());
  for (size_t i = 0; i < path.size(); i += 7)
    for (double spin : {-2.0, 0.3, 4.0}) {
      const Transform expected = cell.setup.basePart * toolFrame(path.points[i], spin);
      const Transform got = frames.baseTcp0[i] * spinAboutTorch(spin);
      EXPECT_LT((got.translation() - expected.translation()).norm(), 1e-12);
      EXPECT_LT(rotationGap(got.linear(), expected.linear()), 1e-12);
    }
}

TEST(MotionFrames, ChartHoldsAVerticalTorchFixedInTheRobotFrame)
{
  test::KukaCell cell;
  const Trajectory path = test::stackedCircles(100, 2, 90, 0, 2);
  NullProgress progress;
  const MotionFrames frames = buildMotionFrames(path, cell.setup, MotionParams{}, progress);
  EXPECT_LT((frames.referenceAxis - Vec3(0, 0, -1)).norm(), 1e-12);
  const double c = 0.7;
  const Vec3 x0 = (frames.baseTcp0[0] * spinAboutTorch(frames.chartOffset[0] + c)).linear().col(0);
  for (size_t i = 1; i < path.size(); ++i) {
    const Vec3 x = (frames.baseTcp0[i] * spinAboutTorch(frames.chartOffset[i] + c)).linear().col(0);
    ASSERT_LT((x - x0).norm(), 1e-12) << i;
    // Unwrapped: the travel direction turns once a circle (clockwise about the torch axis, which
    // points down), so the offset grows by 2 pi a layer.
    if (i >= 90) {
      EXPECT_NEAR(frames.chartOffset[i] - frames.chartOffset[i - 90], 2 * kPi, 1e-9);
    }
  }
}

TEST(MotionFrames, ChartOfATiltedTorchIsTheSmallestTurnFromTheReference)
{
  test::KukaCell cell;
  const Trajectory path = test::domeSpiral(80, 40, 3, 60);
  NullProgress progress;
  const MotionFrames frames = buildMotionFrames(path, cell.setup, MotionParams{}, progress);
  // The frame at chart value c, built independently: the reference frame (z = reference axis,
  // x = base X projected off it), turned by c about its z, then by Eigen's shortest-arc rotation.
  const Vec3 zr = frames.referenceAxis;
  const Vec3 xr = (Vec3::UnitX() - Vec3::UnitX().dot(zr) * zr).normalized();
  Mat3 reference;
  reference << xr, zr.cross(xr), zr;
  const double c = -1.1;
  for (size_t i = 0; i < path.size(); ++i) {
    const Mat3 got = (frames.baseTcp0[i] * spinAboutTorch(frames.chartOffset[i] + c)).linear();
    const Vec3 z = got.col(2);
    const Mat3 swing = Eigen::Quaterniond::FromTwoVectors(zr, z).toRotationMatrix();
    const Mat3 expected = swing * reference * Eigen::AngleAxisd(c, Vec3::UnitZ()).toRotationMatrix();
    ASSERT_LT(rotationGap(got, expected), 1e-9) << i;
  }
}

TEST(MotionFrames, TurntableFollowsAPointWhoseBuildDirectionIsAlongItsAxis)
{
  test::FanucPositionerCell cell;
  const Trajectory path = test::stackedCircles(80, 2, 72, 10, 2);
  NullProgress progress;
  MotionParams params;
  const MotionFrames follow = buildMotionFrames(path, cell.setup, params, progress);
  for (size_t i = 0; i < path.size(); ++i) {
    EXPECT_TRUE(follow.positionerReached[i]);
    EXPECT_NEAR(follow.external[i][0], 0.0, 1e-12);
    // The table turns against the travel: 5 deg a point, continuously over both layers.
    EXPECT_NEAR(radToDeg(follow.external[i][1]), -5.0 * static_cast<double>(i), 1e-9) << i;
    // ...so the deposition point stays where the first one was (up to the layer height).
    const Vec3 world = follow.baseTcp0[i].translation();
    const Vec3 first = follow.baseTcp0[0].translation() + Vec3(0, 0, path.points[i].position.z() - 10);
    EXPECT_LT((world - first).norm(), 1e-9) << i;
  }
  // Off: the rotation is held, as solveJointTrajectory does.
  params.turntableFollowsPoint = false;
  const MotionFrames held = buildMotionFrames(path, cell.setup, params, progress);
  cell.seedAt(path);
  const JointTrajectory reference =
      solveJointTrajectory(cell.ik, cell.convention, path, cell.setup, progress);
  for (size_t i = 0; i < path.size(); ++i) {
    EXPECT_NEAR(radToDeg(held.external[i][1]), reference.points[i].externalDeg[1], 1e-9);
    EXPECT_NEAR(radToDeg(held.external[i][0]), reference.points[i].externalDeg[0], 1e-9);
  }
}

TEST(MotionFrames, TiltedBuildDirectionsPlaceThePartAsTheKinematicsDo)
{
  test::FanucPositionerCell cell;
  cell.setup.positionerSeed = Eigen::Vector2d(0.0, kPi);
  const Trajectory path = test::domeSpiral(60, 30, 2, 90);
  NullProgress progress;
  const MotionFrames frames = buildMotionFrames(path, cell.setup, MotionParams{}, progress);
  cell.seedAt(path);
  const JointTrajectory reference =
      solveJointTrajectory(cell.ik, cell.convention, path, cell.setup, progress);
  for (size_t i = 0; i < path.size(); ++i) {
    ASSERT_NEAR(radToDeg(frames.external[i][0]), reference.points[i].externalDeg[0], 1e-9) << i;
    ASSERT_NEAR(radToDeg(frames.external[i][1]), reference.points[i].externalDeg[1], 1e-9) << i;
    EXPECT_LT((frames.baseTcp0[i].translation() - reference.points[i].baseTcp.translation()).norm(), 1e-9);
  }
}

TEST(MotionLayers, SplitsByRevolutionWithTheSpinAbscissa)
{
  const Trajectory path = test::stackedCircles(50, 3, 40, 0, 1);
  MotionParams params;
  const std::vector<MotionLayer> layers = splitLayers(path, params);
  ASSERT_EQ(layers.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(layers[k].first, 40 * k);
    EXPECT_EQ(layers[k].count, 40u);
    EXPECT_EQ(layers[k].revolution, static_cast<int>(k));
    EXPECT_EQ(layers[k].hasNext, k < 2);
    EXPECT_NEAR(layers[k].x[10], 0.25, 1e-15);
    EXPECT_EQ(layers[k].xNext, 1.0);
  }
  // The polar angle about the circles' axis gives the same abscissa for evenly spaced points.
  params.variable = SpinVariable::PolarAngle;
  const std::vector<MotionLayer> polar = splitLayers(path, params);
  for (size_t k = 0; k < 3; ++k) {
    for (size_t m = 0; m < 40; ++m) EXPECT_NEAR(polar[k].x[m], static_cast<double>(m) / 40.0, 1e-12);
    if (k < 2) {
      EXPECT_NEAR(polar[k].xNext, 1.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace spira
