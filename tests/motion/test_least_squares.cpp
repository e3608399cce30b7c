#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "spira/motion/least_squares.h"

namespace spira {
namespace {

TEST(LeastSquares, LinearProblemMatchesTheNormalEquations)
{
  Eigen::MatrixXd a(5, 3);
  a << 1, 2, 0, 0, 1, 3, 2, 0, 1, 1, 1, 1, 4, -1, 2;
  Eigen::VectorXd b(5);
  b << 1, -2, 0.5, 3, 7;
  const ResidualFunction f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) { r = a * x - b; };
  const LeastSquaresResult result = minimiseLeastSquares(f, Eigen::VectorXd::Zero(3), LeastSquaresOptions{});
  const Eigen::VectorXd exact = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  EXPECT_LT((result.x - exact).norm(), 1e-7);
  EXPECT_NEAR(result.cost, (a * exact - b).squaredNorm(), 1e-10);
}

TEST(LeastSquares, RosenbrockValleyConvergesToItsMinimum)
{
  const ResidualFunction f = [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    r.resize(2);
    r << 10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0];
  };
  LeastSquaresOptions options;
  options.maxIterations = 200;
  const LeastSquaresResult result = minimiseLeastSquares(f, Eigen::Vector2d(-1.2, 1.0), options);
  EXPECT_NEAR(result.x[0], 1.0, 1e-6);
  EXPECT_NEAR(result.x[1], 1.0, 1e-6);
  EXPECT_LT(result.cost, 1e-12);
}

TEST(LeastSquares, NeverEndsAboveItsStartEvenAgainstAWall)
{
  // A quadratic bowl centred at 2 behind a wall at 1 (residual 1e4 beyond it): the minimum of the
  // reachable side is the wall, and no accepted step may cross it.
  const ResidualFunction f = [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    r.resize(2);
    r << x[0] - 2.0, x[0] > 1.0 ? 1e4 : 0.0;
  };
  const LeastSquaresResult result =
      minimiseLeastSquares(f, Eigen::VectorXd::Constant(1, -3.0), LeastSquaresOptions{});
  EXPECT_LE(result.x[0], 1.0);
  EXPECT_GT(result.x[0], 0.5);
  EXPECT_LT(result.cost, 25.0);  // the start's cost
}

}  // namespace
}  // namespace spira
