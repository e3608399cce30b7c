#include "spira/motion/least_squares.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace spira {

namespace {

constexpr double kInitialDamping = 1e-3;
constexpr double kMaxDamping = 1e12;
// Trial steps per iteration: after this many rejections (damping up 4^n times) the start is a
// minimum for all practical purposes, and each trial costs a full set of residuals.
constexpr int kMaxRejections = 10;

}  // namespace

LeastSquaresResult minimiseLeastSquares(const ResidualFunction& f, const Eigen::VectorXd& x0,
                                        const LeastSquaresOptions& options)
{
  LeastSquaresResult out;
  out.x = x0;
  Eigen::VectorXd r, rTrial;
  f(out.x, r);
  ++out.evaluations;
  out.cost = r.squaredNorm();
  const Eigen::Index n = x0.size();
  if (n == 0 || !std::isfinite(out.cost)) return out;

  Eigen::MatrixXd jac(r.size(), n);
  double damping = kInitialDamping;
  while (out.iterations < options.maxIterations) {
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::VectorXd xi = out.x;
      const double h = options.differenceStep * std::max(1.0, std::abs(xi[i]));
      xi[i] += h;
      f(xi, rTrial);
      ++out.evaluations;
      jac.col(i) = (rTrial - r) / h;
    }
    const Eigen::MatrixXd jtj = jac.transpose() * jac;
    const Eigen::VectorXd gradient = jac.transpose() * r;
    if (gradient.norm() <= 1e-300) break;
    bool accepted = false;
    bool converged = false;
    for (int rejections = 0; rejections < kMaxRejections && damping < kMaxDamping; ++rejections) {
      // Marquardt's scaling (by diag(J^T J)) keeps the step meaningful for unequal variables.
      Eigen::MatrixXd a = jtj;
      for (Eigen::Index i = 0; i < n; ++i) a(i, i) += damping * std::max(jtj(i, i), 1e-12);
      const Eigen::VectorXd step = a.ldlt().solve(-gradient);
      if (!step.allFinite()) {
        damping *= 10.0;
        continue;
      }
      const Eigen::VectorXd trial = out.x + step;
      f(trial, rTrial);
      ++out.evaluations;
      const double cost = rTrial.squaredNorm();
      if (std::isfinite(cost) && cost < out.cost) {
        const double gain = (out.cost - cost) / std::max(out.cost, 1e-300);
        converged = gain < options.relativeTolerance || step.norm() < options.stepTolerance;
        out.x = trial;
        out.cost = cost;
        r.swap(rTrial);
        damping = std::max(damping / 3.0, 1e-12);
        accepted = true;
        break;
      }
      if (step.norm() < options.stepTolerance) break;
      damping *= 4.0;
    }
    if (!accepted) break;
    ++out.iterations;
    if (converged) break;
  }
  return out;
}

}  // namespace spira
