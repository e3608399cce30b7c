#include "spira/motion/spin_cost.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"

namespace spira {

namespace {

constexpr double kReachPositionTol = 1e-6;     // mm, as path_tracker.cpp
constexpr double kReachOrientationTol = 1e-8;  // rad

}  // namespace

SpinCost::SpinCost(const ArmIk& ik, const ControllerConvention& convention, const MotionFrames& frames,
                   const Transform& flangeTcp, const ArmConfiguration& configuration,
                   const MotionParams& params)
    : ik_(ik),
      convention_(convention),
      frames_(frames),
      tcpFlange_(flangeTcp.inverse()),
      configuration_(configuration),
      params_(params)
{
  for (size_t j = 0; j < 6; ++j) {
    const AxisLimit& l = convention.axisLimits()[j];
    const double range = l.maxDeg - l.minDeg;
    if (!(range > 0.0) || !std::isfinite(range))
      throw InputError("axis " + l.name + " has no finite range (" + std::to_string(l.minDeg) + " .. " +
                           std::to_string(l.maxDeg) + " deg)",
                       "give every robot axis finite limits in the cell or URDF");
    weights_[j] = 1.0 / range;
    mid_[j] = 0.5 * (l.maxDeg + l.minDeg);
    halfRange_[j] = 0.5 * range;
  }
}

Transform SpinCost::baseTcp(size_t index, double toolSpin) const
{
  return frames_.baseTcp0[index] * spinAboutTorch(toolSpin);
}

SolvedPose SpinCost::solve(size_t index, double chartSpin, const JointVector& near) const
{
  SolvedPose pose;
  const Transform target = baseTcp(index, frames_.chartOffset[index] + chartSpin) * tcpFlange_;
  const std::optional<IkSolution> s = ik_.solve(target, configuration_, near);
  pose.reached = s && s->positionError < kReachPositionTol && s->orientationError < kReachOrientationTol;
  pose.q = pose.reached ? s->q : near;
  pose.dexterity = pose.reached ? s->dexterity : 0.0;
  pose.deg = convention_.toControllerDeg(pose.q);
  return pose;
}

void SpinCost::residuals(const SolvedPose* previous, double segments, const SolvedPose& pose, double share,
                         double* out) const
{
  for (size_t j = 0; j < 6; ++j)
    out[kObjective + j] =
        previous ? std::sqrt(weights_[j] / segments) * (pose.deg[j] - previous->deg[j]) : 0.0;
  const double mu = std::sqrt(kPenaltyWeight);
  std::fill(out + kPenalty, out + kResidualsPerPoint, 0.0);
  if (!pose.reached) {
    out[kPenalty + 8] = kUnreachableResidual;
    return;
  }
  const auto& limits = convention_.axisLimits();
  const double twist = pose.deg[3] + pose.deg[5];
  const double limit = params_.cableTwistLimitDeg;
  for (size_t j = 0; j < 6; ++j) {
    const double distance = std::min(pose.deg[j] - limits[j].minDeg, limits[j].maxDeg - pose.deg[j]);
    out[kPenalty + j] = mu * std::max(0.0, params_.limitMarginDeg + kSlackDeg - distance);
  }
  out[kPenalty + 6] =
      mu * kDexterityDegrees * std::max(0.0, params_.dexterityFloor + kSlackDexterity - pose.dexterity);
  out[kPenalty + 7] = limit > 0.0 ? mu * std::max(0.0, std::abs(twist) - (limit - kSlackDeg)) : 0.0;
  const double c = std::sqrt(params_.centringWeight * share);
  if (c > 0.0) {
    for (size_t j = 0; j < 6; ++j) out[kCentring + j] = c * (pose.deg[j] - mid_[j]) / halfRange_[j];
    out[kCentring + 6] = limit > 0.0 ? c * twist / limit : 0.0;
  }
}

double SpinCost::objective(const SolvedPose& a, const SolvedPose& b) const
{
  double sum = 0.0;
  for (size_t j = 0; j < 6; ++j) sum += weights_[j] * (b.deg[j] - a.deg[j]) * (b.deg[j] - a.deg[j]);
  return sum;
}

double SpinCost::penalty(const SolvedPose& pose) const
{
  double r[kResidualsPerPoint];
  residuals(nullptr, 1.0, pose, 0.0, r);
  double sum = 0.0;
  for (int i = kPenalty; i < kCentring; ++i) sum += r[i] * r[i];
  return sum;
}

}  // namespace spira
