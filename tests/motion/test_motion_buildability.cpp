// Chalvin (2020) section 3.3 and 4.1 (validation case V28): a hemisphere that no constant spin
// can build becomes buildable with the layer-wise optimisation. On the KUKA KR 16-2 placement of
// resources/cells/kuka_kr16_2_table.cell (part frame at (1100, 0, 400) mm).
#include <gtest/gtest.h>

#include <string>

#include "motion_fixtures.h"
#include "spira/base/units.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/motion/motion_solver.h"

namespace spira {
namespace {

bool buildable(const MotionReport& r)
{
  return r.reachable && r.withinCableTwistLimit;
}

// A torch with a 36 deg gooseneck, as the CMT torch of Chalvin's Eq. 4.9: its tip 86 mm off the
// flange axis and 406 mm out, its axis tilted 36 deg from the flange axis.
Transform gooseneck()
{
  Transform t = Transform::Identity();
  t.linear() = Eigen::AngleAxisd(degToRad(-36.0), Vec3::UnitY()).toRotationMatrix();
  t.translation() = Vec3(-86, 0, 406);
  return t;
}

TEST(MotionBuildability, GooseneckHemisphereNeedsTheOptimisation)
{
  test::KukaCell cell;
  cell.setup.flangeTcp = gooseneck();
  // R 80 mm, 4 revolutions from the equator to 40 deg from the pole: the torch tilts up to 50 deg.
  const Trajectory path = test::domeSpiral(80, 40, 4, 360);
  MotionParams params;
  params.cableTwistLimitDeg = 120;
  params.optimiseSpin = false;
  NullProgress progress;
  // The thesis tried R_Z = 0, 90, 180, 270 deg: each fails here too, on A5 or on the cable twist.
  for (double spinDeg : {0.0, 90.0, 180.0, 270.0}) {
    cell.setup.spinRad = degToRad(spinDeg);
    cell.seedAt(path);
    const MotionResult r = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
    EXPECT_FALSE(buildable(r.report)) << spinDeg << " deg";
    const bool twistFails = !r.report.withinCableTwistLimit;
    const bool limitFails = !r.report.outsideLimits.empty();
    EXPECT_TRUE(twistFails || limitFails) << spinDeg << " deg";
  }
  cell.setup.spinRad = 0.0;
  cell.seedAt(path);
  params.optimiseSpin = true;
  const MotionResult r = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  EXPECT_TRUE(r.report.optimised);
  EXPECT_TRUE(r.report.unreachable.empty());
  EXPECT_TRUE(r.report.outsideLimits.empty());
  EXPECT_TRUE(r.report.withinCableTwistLimit) << r.report.maxCableTwistDeg;
  EXPECT_LE(r.report.maxCableTwistDeg, 120.0);
  EXPECT_GE(r.report.minLimitMarginDeg, params.limitMarginDeg - 1e-3) << r.report.minLimitMarginAxis;
  EXPECT_GE(r.report.minDexterity, params.dexterityFloor);
  EXPECT_TRUE(buildable(r.report));
  // Only the hinges' own slack (0.01 deg inside each bound, spin_cost.h) may be touched.
  EXPECT_LT(r.report.penaltyResult, 1e-3);
  EXPECT_GT(r.report.penaltyConstant, 0.0);
}

TEST(MotionBuildability, TravelRelativeSpinIsWhatTheKinematicsSolve)
{
  test::KukaCell cell;
  cell.setup.spinRad = 0.4;
  const Trajectory path = test::domeSpiral(150, 50, 2, 180);
  cell.seedAt(path);
  MotionParams params;
  params.optimiseSpin = false;
  params.constantSpin = ConstantSpin::RelativeToTravel;
  NullProgress progress;
  const MotionResult r = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  const JointTrajectory reference =
      solveJointTrajectory(cell.ik, cell.convention, path, cell.setup, progress);
  ASSERT_EQ(r.joints.size(), reference.size());
  for (size_t i = 0; i < path.size(); ++i) {
    for (size_t j = 0; j < 6; ++j)
      ASSERT_NEAR(r.joints.points[i].robotDeg[j], reference.points[i].robotDeg[j], 1e-9);
    EXPECT_EQ(r.joints.points[i].reachable, reference.points[i].reachable);
    EXPECT_EQ(r.joints.points[i].kukaStatus, reference.points[i].kukaStatus);
    EXPECT_EQ(r.joints.points[i].kukaTurn, reference.points[i].kukaTurn);
    EXPECT_DOUBLE_EQ(r.spinRad[i], 0.4);
  }
}

TEST(MotionBuildability, StraightTorchHemisphereWindsUpWithoutTheOptimisation)
{
  // The cell's own torch: the spin that follows the travel (solveJointTrajectory's) turns A6 a
  // full turn every revolution, past the cable twist limit within the first one; the optimised
  // spin builds the same hemisphere.
  test::KukaCell cell;
  const Trajectory path = test::domeSpiral(150, 50, 6, 360);
  cell.seedAt(path);
  MotionParams params;
  params.cableTwistLimitDeg = 120;
  params.optimiseSpin = false;
  params.constantSpin = ConstantSpin::RelativeToTravel;
  NullProgress progress;
  const MotionResult travel = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  EXPECT_FALSE(travel.report.withinCableTwistLimit);
  EXPECT_FALSE(travel.report.outsideLimits.empty());
  EXPECT_EQ(travel.report.minLimitMarginAxis, "A6");
  params.optimiseSpin = true;
  const MotionResult optimised = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  EXPECT_TRUE(buildable(optimised.report));
  EXPECT_LT(optimised.report.objectiveResult, travel.report.objectiveResult);
}

}  // namespace
}  // namespace spira
