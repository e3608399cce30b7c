#include "spira/document/kinematics_result.h"

#include <algorithm>
#include <limits>

namespace spira {
namespace {

bool sameLimit(const AxisLimit& a, const AxisLimit& b)
{
  return a.name == b.name && a.minDeg == b.minDeg && a.maxDeg == b.maxDeg &&
         a.maxSpeedDegPerS == b.maxSpeedDegPerS;
}

bool samePoint(const JointPoint& a, const JointPoint& b)
{
  return a.robotDeg == b.robotDeg && a.externalDeg == b.externalDeg &&
         a.baseTcp.matrix() == b.baseTcp.matrix() && a.kukaStatus == b.kukaStatus &&
         a.kukaTurn == b.kukaTurn && a.fanucConfig == b.fanucConfig && a.abbConf == b.abbConf &&
         a.reachable == b.reachable && a.dexterity == b.dexterity && a.collision == b.collision;
}

bool sameJoints(const JointTrajectory& a, const JointTrajectory& b)
{
  if (a.controller != b.controller || a.cellName != b.cellName || a.hasPositioner != b.hasPositioner ||
      a.points.size() != b.points.size())
    return false;
  // Only ABB trajectories keep their tool in the project (results_codec.cpp).
  if (a.controller == "abb_irc5" && a.flangeTcp.matrix() != b.flangeTcp.matrix()) return false;
  for (size_t k = 0; k < a.robotLimits.size(); ++k)
    if (!sameLimit(a.robotLimits[k], b.robotLimits[k])) return false;
  for (size_t k = 0; k < a.externalLimits.size(); ++k)
    if (!sameLimit(a.externalLimits[k], b.externalLimits[k])) return false;
  for (size_t i = 0; i < a.points.size(); ++i)
    if (!samePoint(a.points[i], b.points[i])) return false;
  return true;
}

}  // namespace

bool KinematicsCheck::operator==(const KinematicsCheck& o) const
{
  return reachable == o.reachable && dexterity == o.dexterity && limitMarginDeg == o.limitMarginDeg &&
         collision == o.collision;
}

bool KinematicsResult::allReachable() const
{
  return std::all_of(checks.begin(), checks.end(), [](const KinematicsCheck& c) { return c.reachable; });
}

size_t KinematicsResult::collisionCount() const
{
  return static_cast<size_t>(
      std::count_if(checks.begin(), checks.end(), [](const KinematicsCheck& c) { return c.collision; }));
}

bool KinematicsResult::operator==(const KinematicsResult& o) const
{
  if (!sameJoints(joints, o.joints) || !(path == o.path) || checks != o.checks ||
      axes.size() != o.axes.size())
    return false;
  for (size_t k = 0; k < axes.size(); ++k)
    if (!sameLimit(axes[k], o.axes[k])) return false;
  return true;
}

std::vector<double> axisValuesDeg(const KinematicsResult& r, size_t i)
{
  const JointPoint& p = r.joints.points.at(i);
  std::vector<double> v(p.robotDeg.begin(), p.robotDeg.end());
  for (size_t k = 6; k < r.axes.size(); ++k) v.push_back(p.externalDeg[k - 6]);
  return v;
}

KinematicsResult makeKinematicsResult(JointTrajectory joints, Trajectory path)
{
  KinematicsResult r;
  r.axes.assign(joints.robotLimits.begin(), joints.robotLimits.end());
  if (joints.hasPositioner)
    r.axes.insert(r.axes.end(), joints.externalLimits.begin(), joints.externalLimits.end());
  r.checks.reserve(joints.size());
  r.joints = std::move(joints);
  for (size_t i = 0; i < r.joints.size(); ++i) {
    const JointPoint& p = r.joints.points[i];
    const std::vector<double> values = axisValuesDeg(r, i);
    double margin = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < values.size(); ++k)
      margin = std::min({margin, values[k] - r.axes[k].minDeg, r.axes[k].maxDeg - values[k]});
    r.checks.push_back(KinematicsCheck{p.reachable, p.dexterity, margin, p.collision});
  }
  r.path = std::move(path);
  return r;
}

}  // namespace spira
