// Issue 4 check: a hemisphere that a constant torch rotation cannot build (a joint limit is exceeded)
// becomes buildable with the layer-wise optimisation, on the bundled KUKA KR 16-2 cell as read from
// resources/cells/kuka_kr16_2_table.cell (its own straight torch, axis limits, cable-twist limit),
// with the part placed 150 mm to the side of and 50 mm below the cell's own placement.
//
// Why a constant spin fails here: the torch spin of the plan's tool frames (tool_frame.h: x along
// the travel) is held, so the torch turns once about its axis per revolution and A6 winds up by a
// turn per layer, past its +-350 deg after the first revolution or two. With this straight torch the
// wrist centre, and so A1-A5, do not depend on the spin at all: only the spin can fix it, and the
// optimiser has to find one that swings back and forth within each layer instead of winding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "motion_fixtures.h"
#include "spira/base/progress.h"
#include "spira/motion/motion_solver.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "support/test_support.h"

namespace spira {
namespace {

// The largest excess of any robot axis over the cell file's limits (deg, <= 0 when within).
double worstExcessDeg(const RobotCell& cell, const JointTrajectory& joints, std::string& axis)
{
  double worst = -1e9;
  for (const JointPoint& p : joints.points)
    for (size_t j = 0; j < 6; ++j) {
      const CellAxis& a = cell.record().robotAxes[j];
      const double excess = std::max(a.minDeg - p.robotDeg[j], p.robotDeg[j] - a.maxDeg);
      if (excess > worst) {
        worst = excess;
        axis = "A" + std::to_string(j + 1);
      }
    }
  return worst;
}

TEST(MotionBundledCell, HemisphereNeedsTheOptimisationOnTheKukaCell)
{
  const RobotCell cell(readCellFile(test::sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell"));
  ASSERT_TRUE(cell.canSolve()) << cell.ikRefusal();
  // R 150 mm, from the equator to 50 deg from the pole in 6 revolutions: the torch tilts 90 -> 50 deg.
  const Trajectory path = test::domeSpiral(150, 50, 6, 360);
  const Transform placement = cell.record().T_mount_part * test::translation(0, 150, -50);
  const JointPathSetup setup = cell.seededSetup(path, placement);
  MotionParams params;
  params.cableTwistLimitDeg = cell.record().cableTwistLimitDeg;
  ASSERT_EQ(params.cableTwistLimitDeg, 120.0);
  params.optimiseSpin = false;
  params.constantSpin = ConstantSpin::RelativeToTravel;
  NullProgress progress;

  const MotionResult constant = solveMotion(cell.ik(), cell.convention(), path, setup, params, progress);
  EXPECT_TRUE(constant.report.unreachable.empty());     // every pose is reached...
  EXPECT_FALSE(constant.report.outsideLimits.empty());  // ...but not within the joint limits
  EXPECT_FALSE(constant.report.reachable);
  EXPECT_EQ(constant.report.minLimitMarginAxis, "A6");
  std::string axis;
  EXPECT_GT(worstExcessDeg(cell, constant.joints, axis), 5.0);  // independent of the report
  EXPECT_EQ(axis, "A6");
  // The spin really is constant in the tool frame: every point's spin is the first one's.
  for (double s : constant.spinRad) ASSERT_EQ(s, constant.spinRad.front());

  params.optimiseSpin = true;
  const MotionResult optimised = solveMotion(cell.ik(), cell.convention(), path, setup, params, progress);
  EXPECT_TRUE(optimised.report.optimised);
  EXPECT_TRUE(optimised.report.reachable);
  EXPECT_TRUE(optimised.report.unreachable.empty());
  EXPECT_TRUE(optimised.report.outsideLimits.empty());
  EXPECT_TRUE(optimised.report.withinCableTwistLimit) << optimised.report.maxCableTwistDeg;
  EXPECT_LT(worstExcessDeg(cell, optimised.joints, axis), -params.limitMarginDeg + 1e-3) << axis;
  double twist = 0.0;
  for (const JointPoint& p : optimised.joints.points)
    twist = std::max(twist, std::abs(p.robotDeg[3] + p.robotDeg[5]));
  EXPECT_LE(twist, 120.0 + 1e-9);
  // A1-A5 are the same in both plans (the straight torch's wrist centre ignores the spin); the
  // optimiser only chose the spin.
  for (size_t i = 0; i < path.size(); i += 97)
    for (size_t j = 0; j < 5; ++j) {
      const double gap = optimised.joints.points[i].robotDeg[j] - constant.joints.points[i].robotDeg[j];
      EXPECT_NEAR(std::remainder(gap, 360.0), 0.0, 1e-6) << "A" << j + 1 << " point " << i;
    }
  EXPECT_LT(optimised.report.objectiveResult, optimised.report.objectiveConstant);
}

}  // namespace
}  // namespace spira
