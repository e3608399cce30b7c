#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "motion_fixtures.h"
#include "spira/base/units.h"
#include "spira/motion/motion_solver.h"
#include "spira/motion/spin_optimiser.h"

namespace spira {
namespace {

struct Case {
  std::string name;
  std::function<MotionResult(const MotionParams&)> solve;
};

std::vector<Case> cases()
{
  std::vector<Case> out;
  for (double y : {-250.0, 0.0, 300.0})
    for (bool gooseneck : {false, true})
      out.push_back({"kuka dome y " + std::to_string(y) + (gooseneck ? " gooseneck" : " straight"),
                     [y, gooseneck](const MotionParams& p) {
                       test::KukaCell cell;
                       cell.setup.basePart = test::translation(1100, y, 400);
                       if (gooseneck) {
                         cell.setup.flangeTcp.linear() =
                             Eigen::AngleAxisd(degToRad(-36.0), Vec3::UnitY()).toRotationMatrix();
                         cell.setup.flangeTcp.translation() = Vec3(-86, 0, 406);
                       }
                       const Trajectory path = test::domeSpiral(100, 45, 3, 120);
                       cell.seedAt(path);
                       NullProgress progress;
                       return solveMotion(cell.ik, cell.convention, path, cell.setup, p, progress);
                     }});
  out.push_back({"kuka cylinder", [](const MotionParams& p) {
                   test::KukaCell cell;
                   const Trajectory path = test::stackedCircles(120, 3, 120, 0, 2);
                   cell.seedAt(path);
                   NullProgress progress;
                   return solveMotion(cell.ik, cell.convention, path, cell.setup, p, progress);
                 }});
  out.push_back({"fanuc positioner dome", [](const MotionParams& p) {
                   test::FanucPositionerCell cell;
                   cell.setup.positionerSeed = Eigen::Vector2d(0.0, kPi);
                   const Trajectory path = test::domeSpiral(60, 30, 3, 120);
                   cell.seedAt(path);
                   NullProgress progress;
                   return solveMotion(cell.ik, cell.convention, path, cell.setup, p, progress);
                 }});
  return out;
}

TEST(MotionObjective, OptimisedPlanNeverCostsMoreThanTheConstantSpin)
{
  for (const Case& c : cases())
    for (int degree : {1, 3}) {
      MotionParams params;
      params.degree = degree;
      params.cableTwistLimitDeg = 120;
      const MotionResult r = c.solve(params);
      const MotionReport& m = r.report;
      SCOPED_TRACE(c.name + ", degree " + std::to_string(degree));
      EXPECT_LE(m.objectiveResult + m.penaltyResult, (m.objectiveConstant + m.penaltyConstant) * (1 + 1e-12));
      if (m.penaltyConstant == 0.0) {
        EXPECT_LE(m.objectiveResult, m.objectiveConstant * (1 + 1e-12));
      }
      // The layers' objectives add up to the plan's.
      double sum = 0.0;
      for (const LayerSpin& l : m.layers) sum += l.objective;
      EXPECT_NEAR(sum, m.objectiveResult, 1e-9 * std::max(1.0, sum));
      if (!m.optimised) continue;
      // Continuity: every layer starts with the spin the previous one ends with.
      for (size_t k = 0; k + 1 < m.layers.size(); ++k) {
        ASSERT_EQ(m.layers[k].coefficients.size(), static_cast<size_t>(degree) + 1);
        EXPECT_DOUBLE_EQ(m.layers[k + 1].coefficients[0],
                         evaluateSpinPolynomial(m.layers[k].coefficients, 1.0));
      }
    }
}

TEST(MotionObjective, ConstantSpinInTheRobotFrameIsOneChartValue)
{
  for (const Case& c : cases()) {
    MotionParams params;
    params.optimiseSpin = false;
    const MotionResult r = c.solve(params);
    SCOPED_TRACE(c.name);
    EXPECT_FALSE(r.report.optimised);
    EXPECT_EQ(r.report.objectiveResult, r.report.objectiveConstant);
    EXPECT_EQ(r.report.posesSolved, 0);
    const double value = r.report.layers.front().coefficients.at(0);
    for (const LayerSpin& l : r.report.layers) {
      ASSERT_EQ(l.coefficients.size(), 1u);
      EXPECT_EQ(l.coefficients[0], value);
    }
    EXPECT_DOUBLE_EQ(r.spinRad.front(), 0.0);  // the setup's spin at the first point
  }
}

TEST(MotionObjective, PolarAngleAbscissaMatchesThePointIndexOnEvenCircles)
{
  // Evenly spaced points on circles about the part's z axis: the polar angle over a turn is the
  // point index over the layer's count, so both abscissae give the same plan.
  test::KukaCell cell;
  const Trajectory path = test::stackedCircles(120, 3, 120, 0, 2);
  cell.seedAt(path);
  NullProgress progress;
  MotionParams params;
  params.cableTwistLimitDeg = 120;
  const MotionResult byIndex = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  params.variable = SpinVariable::PolarAngle;
  const MotionResult byAngle = solveMotion(cell.ik, cell.convention, path, cell.setup, params, progress);
  EXPECT_NEAR(byAngle.report.objectiveResult, byIndex.report.objectiveResult,
              1e-6 * byIndex.report.objectiveResult);
  for (size_t i = 0; i < path.size(); ++i) EXPECT_NEAR(byAngle.spinRad[i], byIndex.spinRad[i], 1e-5) << i;
}

}  // namespace
}  // namespace spira
