// Chalvin (2020) section 4.1.3 and validation case V27: on an axisymmetric part whose axis is
// coaxial with a rotating axis, the layer-wise optimisation holds the other axes still within a
// layer and turns that axis linearly. In a torch-carried cell that axis is the positioner's
// rotation (the table turns the part under the torch); the thesis' part-carried cell had J6.
// These tests use the thesis' objective alone (Eq. 4.3, centring off): the default centring term
// would also, slowly, bring J6 towards mid-range.
#include <gtest/gtest.h>

#include <cmath>

#include "motion_fixtures.h"
#include "spira/base/units.h"
#include "spira/motion/motion_solver.h"
#include "spira/motion/spin_optimiser.h"

namespace spira {
namespace {

double stdDev(const std::vector<double>& v)
{
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double sum = 0.0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(v.size()));
}

// Largest deviation of E2 from the straight line through a layer's first point with slope `perPoint`.
double linearGap(const JointTrajectory& jt, size_t first, size_t count, double perPoint)
{
  double worst = 0.0;
  for (size_t m = 0; m < count; ++m)
    worst = std::max(worst, std::abs(jt.points[first + m].externalDeg[1] -
                                     (jt.points[first].externalDeg[1] + perPoint * static_cast<double>(m))));
  return worst;
}

TEST(MotionAxisymmetric, TurntableCylinderHoldsTheRobotStillAndTurnsTheTableLinearly)
{
  test::FanucPositionerCell cell;
  const int perLayer = 360;
  const Trajectory path = test::stackedCircles(80, 5, perLayer, 0, 2);
  cell.seedAt(path);
  MotionParams params;
  params.cableTwistLimitDeg = 120;
  params.centringWeight = 0.0;
  NullProgress progress;
  const MotionResult r = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  ASSERT_TRUE(r.report.reachable);
  EXPECT_TRUE(r.report.withinCableTwistLimit);
  EXPECT_TRUE(r.report.optimised);
  EXPECT_LE(r.report.objectiveResult, r.report.objectiveConstant);
  ASSERT_EQ(r.report.layers.size(), 5u);
  for (const LayerSpin& layer : r.report.layers) {
    for (size_t j = 0; j < 6; ++j) {
      std::vector<double> axis;
      for (size_t m = 0; m < layer.pointCount; ++m)
        axis.push_back(r.joints.points[layer.firstPoint + m].robotDeg[j]);
      EXPECT_LT(stdDev(axis), 1e-3) << "J" << j + 1 << " layer " << layer.revolution;
    }
    for (size_t m = 0; m < layer.pointCount; ++m)
      EXPECT_NEAR(r.joints.points[layer.firstPoint + m].externalDeg[0], 0.0, 1e-9);
    EXPECT_LT(linearGap(r.joints, layer.firstPoint, layer.pointCount, -360.0 / perLayer), 1e-9);
  }
}

TEST(MotionAxisymmetric, OptimiserStartedFarOffFindsTheStillRobot)
{
  test::FanucPositionerCell cell;
  const Trajectory path = test::stackedCircles(80, 3, 360, 0, 2);
  cell.seedAt(path);
  MotionParams params;
  params.cableTwistLimitDeg = 120;
  params.centringWeight = 0.0;
  NullProgress progress;
  const MotionFrames frames = buildMotionFrames(path, cell.setup, params, progress);
  const SpinCost cost(cell.ik, cell.convention, frames, cell.setup.flangeTcp, ArmConfiguration{}, params);
  const SpinOptimiser optimiser(cost, params);
  const std::vector<MotionLayer> layers = splitLayers(path, params);
  // The middle layer, its start held, from a cubic that swings the torch by a radian or more.
  const JointVector entry = cost.solve(layers[1].first - 1, 0.2, cell.setup.seed).q;
  const LayerSpinSolution s = optimiser.optimiseLayer(layers[1], {0.2, 1.5, -2.0, 1.0}, true, entry);
  ASSERT_EQ(s.coefficients.size(), 4u);
  EXPECT_DOUBLE_EQ(s.coefficients[0], 0.2);
  for (size_t i = 1; i < 4; ++i) EXPECT_LT(std::abs(s.coefficients[i]), 1e-5) << i;
  ASSERT_EQ(s.poses.size(), 360u);
  for (size_t j = 0; j < 6; ++j) {
    std::vector<double> axis;
    for (const SolvedPose& p : s.poses) axis.push_back(p.deg[j]);
    EXPECT_LT(stdDev(axis), 1e-3) << "J" << j + 1;
  }
  // Within the layer nothing moves; what is left is the 2 mm climb into the next layer.
  double within = 0.0;
  for (size_t i = 1; i < s.poses.size(); ++i) within += cost.objective(s.poses[i - 1], s.poses[i]);
  EXPECT_LT(within, 1e-9);
  EXPECT_LT(s.objective, 1e-3);
  EXPECT_EQ(s.penalty, 0.0);
}

TEST(MotionAxisymmetric, StraightTorchSpinTurnsOnlyTheLastAxis)
{
  // The cell's torch lies on the A6 axis, so its spin is a turn of A6 alone: whatever the spin,
  // A1-A5 are the same. The travel-relative spin winds A6 a turn per layer; the optimiser keeps
  // A6 nearly still instead.
  test::KukaCell cell;
  const Trajectory path = test::stackedCircles(100, 3, 360, 0, 2);
  cell.seedAt(path);
  MotionParams params;
  params.cableTwistLimitDeg = 120;
  NullProgress progress;
  const MotionResult optimised = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  params.optimiseSpin = false;
  params.constantSpin = ConstantSpin::RelativeToTravel;
  const MotionResult travel = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  ASSERT_TRUE(optimised.report.reachable);
  ASSERT_TRUE(optimised.report.withinCableTwistLimit);
  for (size_t i = 0; i < path.size(); ++i)
    for (size_t j = 0; j < 5; ++j)
      ASSERT_NEAR(optimised.joints.points[i].robotDeg[j], travel.joints.points[i].robotDeg[j], 1e-6)
          << i << " A" << j + 1;
  for (const LayerSpin& layer : optimised.report.layers) {
    const size_t last = layer.firstPoint + layer.pointCount - 1;
    EXPECT_GT(
        std::abs(travel.joints.points[last].robotDeg[5] - travel.joints.points[layer.firstPoint].robotDeg[5]),
        340.0);
    double lo = 1e9, hi = -1e9;
    for (size_t m = layer.firstPoint; m <= last; ++m) {
      lo = std::min(lo, optimised.joints.points[m].robotDeg[5]);
      hi = std::max(hi, optimised.joints.points[m].robotDeg[5]);
    }
    EXPECT_LT(hi - lo, 5.0) << "layer " << layer.revolution;
  }
  EXPECT_FALSE(travel.report.withinCableTwistLimit && travel.report.reachable);
}

}  // namespace
}  // namespace spira
