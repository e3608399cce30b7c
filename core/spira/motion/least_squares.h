#pragma once

#include <functional>

#include <Eigen/Core>

namespace spira {

// Residuals r(x) of a small nonlinear least-squares problem: minimise |r(x)|^2. The function
// resizes r as it likes (the same size on every call).
using ResidualFunction = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& r)>;

struct LeastSquaresOptions {
  int maxIterations = 40;            // accepted steps
  double relativeTolerance = 1e-10;  // stop when a step lowers the cost by less than this fraction
  double stepTolerance = 1e-10;      // ... or moves x by less than this (same units as x)
  double differenceStep = 1e-6;      // forward-difference step, times max(1, |x_i|)
};

struct LeastSquaresResult {
  Eigen::VectorXd x;
  double cost = 0.0;  // |r(x)|^2
  int iterations = 0;
  int evaluations = 0;
};

// Levenberg-Marquardt with a forward-difference Jacobian, for problems of a few variables whose
// residuals are costly (each one an inverse kinematics solve). Every accepted step lowers the
// cost, so the result is never worse than the start: cost(result.x) <= cost(x0).
LeastSquaresResult minimiseLeastSquares(const ResidualFunction& f, const Eigen::VectorXd& x0,
                                        const LeastSquaresOptions& options);

}  // namespace spira
