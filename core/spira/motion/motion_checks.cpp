#include "spira/motion/motion_checks.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"

namespace spira {

namespace {

// The axes of one point, robot first, then the positioner's.
struct AxisValues {
  double deg[8];
  const AxisLimit* limit[8];
  size_t count;
};

AxisValues axesOf(const JointTrajectory& joints, const JointPoint& p)
{
  AxisValues v{};
  for (size_t j = 0; j < 6; ++j) {
    v.deg[j] = p.robotDeg[j];
    v.limit[j] = &joints.robotLimits[j];
  }
  v.count = 6;
  if (joints.hasPositioner)
    for (size_t j = 0; j < 2; ++j, ++v.count) {
      v.deg[v.count] = p.externalDeg[j];
      v.limit[v.count] = &joints.externalLimits[j];
    }
  return v;
}

}  // namespace

void checkMotion(const Trajectory& path, const JointTrajectory& joints, const std::vector<bool>& reached,
                 double cableTwistLimitDeg, MotionReport& report)
{
  const size_t n = joints.size();
  if (path.size() != n || reached.size() != n)
    throw InternalError("motion check: path, joints and reach flags differ in size (" +
                        std::to_string(path.size()) + ", " + std::to_string(n) + ", " +
                        std::to_string(reached.size()) + ")");
  report.unreachable.clear();
  report.outsideLimits.clear();
  report.speedRatio.assign(n, 0.0);
  report.axisSpeeds.clear();
  if (n > 0) {
    const AxisValues first = axesOf(joints, joints.points.front());
    for (size_t j = 0; j < first.count; ++j)
      report.axisSpeeds.push_back({first.limit[j]->name, 0.0, MotionReport::kNone});
  }
  for (size_t i = 0; i < n; ++i) {
    const JointPoint& p = joints.points[i];
    if (!reached[i]) {
      report.unreachable.push_back(i);
      continue;
    }
    const AxisValues v = axesOf(joints, p);
    double pointMargin = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < v.count; ++j) {
      const double margin = std::min(v.deg[j] - v.limit[j]->minDeg, v.limit[j]->maxDeg - v.deg[j]);
      pointMargin = std::min(pointMargin, margin);
      if (margin < report.minLimitMarginDeg) {
        report.minLimitMarginDeg = margin;
        report.minLimitMarginAxis = v.limit[j]->name;
        report.minLimitMarginPoint = i;
      }
    }
    if (pointMargin < 0.0) report.outsideLimits.push_back(i);
    if (p.dexterity < report.minDexterity || report.minDexterityPoint == MotionReport::kNone) {
      report.minDexterity = p.dexterity;
      report.minDexterityPoint = i;
    }
    const double twist = std::abs(p.robotDeg[3] + p.robotDeg[5]);
    if (twist > report.maxCableTwistDeg || report.maxCableTwistPoint == MotionReport::kNone) {
      report.maxCableTwistDeg = twist;
      report.maxCableTwistPoint = i;
    }

    if (i == 0 || !reached[i - 1]) continue;
    const double speed = path.points[i].travelSpeed;
    if (!(speed > 0.0) || !std::isfinite(speed)) {
      ++report.segmentsWithoutSpeed;
      continue;
    }
    const double dt = (path.points[i].position - path.points[i - 1].position).norm() / speed;
    const AxisValues before = axesOf(joints, joints.points[i - 1]);
    for (size_t j = 0; j < v.count; ++j) {
      const double maxSpeed = v.limit[j]->maxSpeedDegPerS;
      if (!(maxSpeed > 0.0) || !std::isfinite(maxSpeed)) continue;
      const double move = std::abs(v.deg[j] - before.deg[j]);
      // A turn on the spot (zero-length segment) needs infinite speed at the planned feed.
      const double ratio =
          dt > 0.0 ? move / dt / maxSpeed : (move > 1e-9 ? std::numeric_limits<double>::infinity() : 0.0);
      report.speedRatio[i] = std::max(report.speedRatio[i], ratio);
      MotionReport::AxisSpeed& axis = report.axisSpeeds[j];
      if (ratio > axis.maxRatio) {
        axis.maxRatio = ratio;
        axis.point = i;
      }
      if (ratio > report.maxSpeedRatio) {
        report.maxSpeedRatio = ratio;
        report.maxSpeedRatioAxis = v.limit[j]->name;
        report.maxSpeedRatioPoint = i;
      }
    }
  }
  report.withinCableTwistLimit = cableTwistLimitDeg <= 0.0 || report.maxCableTwistDeg <= cableTwistLimitDeg;
  report.reachable = report.unreachable.empty() && report.outsideLimits.empty();
}

}  // namespace spira
