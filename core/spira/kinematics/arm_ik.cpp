#include "spira/kinematics/arm_ik.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "spira/base/error.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/dexterity.h"
#include "spira/kinematics/opw_detection.h"

namespace spira {

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Axes = Eigen::Matrix<double, 3, 6>;

constexpr double kPositionTol = 1e-10;     // mm: stop refining below this
constexpr double kOrientationTol = 1e-13;  // rad
constexpr int kMaxNewtonSteps = 12;

// Rotation vector of R (axis * angle), exact enough near the identity where Newton works.
Vec3 rotationVector(const Mat3& r)
{
  const Eigen::AngleAxisd aa(r);
  return aa.axis() * aa.angle();
}

Matrix6 jacobianAt(const Axes& points, const Axes& axes, const Vec3& p)
{
  Matrix6 j;
  for (int i = 0; i < 6; ++i) {
    j.col(i).head<3>() = axes.col(i).cross(p - points.col(i));
    j.col(i).tail<3>() = axes.col(i);
  }
  return j;
}

}  // namespace

ArmIk::ArmIk(KinematicChain chain) : chain_(std::move(chain))
{
  const OpwDetection d = detectOpw(chain_);
  if (!d.ok)
    throw InputError(
        "cannot solve the inverse kinematics of the chain " + chain_.baseLink() + " -> " + chain_.tipLink() +
            ": not a 6R arm with a spherical wrist and an ortho-parallel base (" + d.reason + ")",
        "use a 6-axis industrial arm (axes 2 and 3 parallel, axes 4-6 meeting in one point) and "
        "choose the chain from its foot to its flange or tool0 link");
  model_ = d.model;
}

void ArmIk::setAxisMargins(AxisMargins margins)
{
  axisMargins_ = std::move(margins);
}

JointVector ArmIk::axisMargins(const JointVector& q) const
{
  if (axisMargins_) return axisMargins_(q);
  JointVector m;
  for (int i = 0; i < 6; ++i) {
    const ChainJoint& j = chain_.joint(static_cast<size_t>(i));
    m[i] = std::min(q[i] - j.lower, j.upper - q[i]);
  }
  return m;
}

Vec3 ArmIk::wristCentre(const JointVector& q) const
{
  return chain_.forward(q) * model_.wristCentreInTip();
}

double ArmIk::dexterity(const JointVector& q) const
{
  Axes points, axes;
  const Transform tip = chain_.forward(q, points, axes);
  return armDexterity(jacobianAt(points, axes, tip * model_.wristCentreInTip()));
}

bool ArmIk::refine(const Transform& target, JointVector& q) const
{
  IkSolution s;
  s.q = q;
  const bool converged = refineAndMeasure(target, s);
  q = s.q;
  return converged;
}

bool ArmIk::refineAndMeasure(const Transform& target, IkSolution& s) const
{
  Axes points, axes;
  bool converged = false;
  Transform t;
  for (int step = 0;; ++step) {
    t = chain_.forward(s.q, points, axes);
    Vector6 e;
    e.head<3>() = target.translation() - t.translation();
    e.tail<3>() = rotationVector(target.linear() * t.linear().transpose());
    s.positionError = e.head<3>().norm();
    s.orientationError = e.tail<3>().norm();
    converged = s.positionError < kPositionTol && s.orientationError < kOrientationTol;
    if (converged || step == kMaxNewtonSteps) break;
    // SVD so that a step at (or next to) a singularity stays bounded.
    const Eigen::JacobiSVD<Matrix6> svd(jacobianAt(points, axes, t.translation()),
                                        Eigen::ComputeFullU | Eigen::ComputeFullV);
    s.q += svd.solve(e);
  }
  s.dexterity = armDexterity(jacobianAt(points, axes, t * model_.wristCentreInTip()));
  s.limitMargin = limitMargin(s.q);
  s.withinLimits = s.limitMargin >= 0.0;
  return converged;
}

bool ArmIk::solveBranch(const Transform& baseTip, const ArmConfiguration& configuration, double theta4Hint,
                        JointVector& q) const
{
  JointVector theta;
  const Transform opwFlange = model_.baseOpwInverse_ * baseTip * model_.flangeTipInverse_;
  if (!model_.solve(opwFlange, configuration, theta4Hint, theta)) return false;
  q = model_.fromOpw(theta);
  return true;
}

std::optional<IkSolution> ArmIk::solve(const Transform& baseTip, const ArmConfiguration& configuration,
                                       const JointVector& near) const
{
  if (!baseTip.matrix().allFinite() || !near.allFinite())
    throw InputError("a target pose or reference joint vector holds NaN or infinity",
                     "check the path poses given to the inverse kinematics");
  IkSolution s;
  if (!solveBranch(baseTip, configuration, model_.toOpw(near)[3], s.q)) return std::nullopt;
  for (int i = 0; i < 6; ++i) s.q[i] = nearestBranch(s.q[i], near[i]);
  s.configuration = configuration;
  refineAndMeasure(baseTip, s);
  return s;
}

std::vector<IkSolution> ArmIk::solveAll(const Transform& baseTip) const
{
  if (!baseTip.matrix().allFinite())
    throw InputError("the target pose holds NaN or infinity",
                     "check the pose given to the inverse kinematics");
  std::vector<IkSolution> out;
  for (const ArmConfiguration& c : ArmConfiguration::all()) {
    IkSolution s;
    if (!solveBranch(baseTip, c, 0.0, s.q)) continue;
    // Joint by joint, so that an axis limited relative to an earlier one sees its final value.
    for (int i = 0; i < 6; ++i) {
      s.q[i] = wrapToPi(s.q[i]);
      double best = axisMargins(s.q)[i];
      const double base = s.q[i];
      for (double shift : {2.0 * kPi, -2.0 * kPi}) {
        JointVector shifted = s.q;
        shifted[i] = base + shift;
        const double m = axisMargins(shifted)[i];
        if (m > best && best < 0.0) {
          best = m;
          s.q[i] = shifted[i];
        }
      }
    }
    s.configuration = c;
    refineAndMeasure(baseTip, s);
    out.push_back(s);

    // Joints 1, 4 and 6 often turn more than one revolution: offer every in-limit turn.
    std::vector<JointVector> variants{s.q};
    for (int i : {0, 3, 5}) {
      const size_t count = variants.size();
      for (size_t v = 0; v < count; ++v)
        for (double shift : {-2.0 * kPi, 2.0 * kPi}) {
          JointVector q = variants[v];
          q[i] += shift;
          if (axisMargins(q)[i] >= 0.0) variants.push_back(q);
        }
    }
    for (size_t v = 1; v < variants.size(); ++v) {
      IkSolution shifted = s;
      shifted.q = variants[v];
      shifted.limitMargin = limitMargin(shifted.q);
      shifted.withinLimits = shifted.limitMargin >= 0.0;
      out.push_back(shifted);
    }
  }
  return out;
}

}  // namespace spira
