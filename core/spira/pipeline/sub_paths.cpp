#include "spira/pipeline/sub_paths.h"

#include <algorithm>

namespace spira {
namespace {

void mergeReport(MotionReport& total, const MotionReport& part, size_t offset, bool first)
{
  const auto shift = [offset](size_t i) { return i == MotionReport::kNone ? i : i + offset; };
  total.reachable = total.reachable && part.reachable;
  for (size_t i : part.unreachable) total.unreachable.push_back(i + offset);
  for (size_t i : part.outsideLimits) total.outsideLimits.push_back(i + offset);
  if (first || part.minLimitMarginDeg < total.minLimitMarginDeg) {
    total.minLimitMarginDeg = part.minLimitMarginDeg;
    total.minLimitMarginAxis = part.minLimitMarginAxis;
    total.minLimitMarginPoint = shift(part.minLimitMarginPoint);
  }
  if (first || part.minDexterity < total.minDexterity) {
    total.minDexterity = part.minDexterity;
    total.minDexterityPoint = shift(part.minDexterityPoint);
  }
  if (first || part.maxSpeedRatio > total.maxSpeedRatio) {
    total.maxSpeedRatio = part.maxSpeedRatio;
    total.maxSpeedRatioAxis = part.maxSpeedRatioAxis;
    total.maxSpeedRatioPoint = shift(part.maxSpeedRatioPoint);
  }
  total.segmentsWithoutSpeed += part.segmentsWithoutSpeed;
  total.speedRatio.insert(total.speedRatio.end(), part.speedRatio.begin(), part.speedRatio.end());
  for (const MotionReport::AxisSpeed& axis : part.axisSpeeds) {
    auto it = std::find_if(total.axisSpeeds.begin(), total.axisSpeeds.end(),
                           [&axis](const MotionReport::AxisSpeed& a) { return a.axis == axis.axis; });
    if (it == total.axisSpeeds.end())
      it = total.axisSpeeds.insert(total.axisSpeeds.end(), {axis.axis, 0.0, MotionReport::kNone});
    if (axis.maxRatio > it->maxRatio) {
      it->maxRatio = axis.maxRatio;
      it->point = shift(axis.point);
    }
  }
  if (first || part.maxCableTwistDeg > total.maxCableTwistDeg) {
    total.maxCableTwistDeg = part.maxCableTwistDeg;
    total.maxCableTwistPoint = shift(part.maxCableTwistPoint);
  }
  total.withinCableTwistLimit = total.withinCableTwistLimit && part.withinCableTwistLimit;
  total.objectiveConstant += part.objectiveConstant;
  total.penaltyConstant += part.penaltyConstant;
  total.objectiveResult += part.objectiveResult;
  total.penaltyResult += part.penaltyResult;
  total.optimised = total.optimised || part.optimised;
  total.posesSolved += part.posesSolved;
  for (LayerSpin layer : part.layers) {
    layer.firstPoint += offset;
    total.layers.push_back(std::move(layer));
  }
}

}  // namespace

std::vector<SubPathRange> subPathRanges(const Trajectory& t)
{
  std::vector<SubPathRange> out;
  for (size_t i = 0; i < t.size(); ++i)
    if (out.empty() || t.points[i].path != out.back().path)
      out.push_back(SubPathRange{t.points[i].path, i, i + 1});
    else
      out.back().end = i + 1;
  return out;
}

Trajectory subTrajectory(const Trajectory& t, const SubPathRange& range)
{
  Trajectory out;
  const auto b = static_cast<std::ptrdiff_t>(range.begin), e = static_cast<std::ptrdiff_t>(range.end);
  out.points.assign(t.points.begin() + b, t.points.begin() + e);
  for (const auto& [name, values] : t.extra) out.extra[name].assign(values.begin() + b, values.begin() + e);
  return out;
}

void appendTrajectory(Trajectory& whole, const Trajectory& part)
{
  const size_t before = whole.size();
  whole.points.insert(whole.points.end(), part.points.begin(), part.points.end());
  for (const auto& [name, values] : part.extra) {
    std::vector<double>& channel = whole.extra[name];
    channel.resize(before, 0.0);
    channel.insert(channel.end(), values.begin(), values.end());
  }
  for (auto& [name, channel] : whole.extra) channel.resize(whole.size(), 0.0);
}

MotionResult solveSubPaths(const RobotCell& cell, const Trajectory& path, const MotionParams& params,
                           Progress& progress, std::vector<JointPathSetup>* setups)
{
  const std::vector<SubPathRange> ranges = subPathRanges(path);
  if (ranges.size() <= 1) {
    const JointPathSetup setup = cell.seededSetup(path);
    if (setups) *setups = {setup};
    return solveMotion(cell.ik(), cell.convention(), path, setup, params, progress);
  }
  MotionResult out;
  if (setups) setups->clear();
  const double total = static_cast<double>(path.size());
  for (size_t r = 0; r < ranges.size(); ++r) {
    const SubPathRange& range = ranges[r];
    const Trajectory piece = subTrajectory(path, range);
    SubProgress sub(progress, static_cast<double>(range.begin) / total,
                    static_cast<double>(range.end) / total, "sub-path " + std::to_string(range.path));
    const JointPathSetup setup = cell.seededSetup(piece);
    if (setups) setups->push_back(setup);
    MotionResult solved = solveMotion(cell.ik(), cell.convention(), piece, setup, params, sub);
    if (r == 0) {
      out.joints = solved.joints;
      out.joints.points.clear();
    }
    out.joints.points.insert(out.joints.points.end(), solved.joints.points.begin(),
                             solved.joints.points.end());
    out.spinRad.insert(out.spinRad.end(), solved.spinRad.begin(), solved.spinRad.end());
    mergeReport(out.report, solved.report, range.begin, r == 0);
  }
  return out;
}

}  // namespace spira
